/* box_on_ground.c -- step 2 of the guide's tutorial: collision. A universe joins a collision space to
 * the world; a box is dropped on a ground plane, lands, comes to rest and falls asleep. */
#include <stdio.h>
#include <karma/karma.h>

/* McdPlaneCreate's plane faces local +z. Its transform's rows are the plane's axes in the world:
 * turning local z to world +y (-90 degrees about x) makes it the ground of a y-up world. */
static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};

int main(void)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes; /* pools for 100 bodies, 100 models... */
    sizes.massScale = 10;                             /* our box weighs 10 kg: tell the world */
    MstUniverseID universe = MstUniverseCreate(&sizes);
    MdtWorldID world = MstUniverseGetWorld(universe);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MdtWorldSetGravity(world, 0, -9.81, 0);

    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);

    /* A 0.5 m cube of density 80 kg/m^3 (10 kg): a model for collision with an enabled body. */
    McdModelID box = MstModelAndBodyCreate(universe, McdBoxCreate(collision, 0.5, 0.5, 0.5), 80);
    MdtBodyID body = McdModelGetBody(box);
    MdtBodySetPosition(body, 0, 2, 0);

    for (int step = 1; step <= 180; step++) {
        MstUniverseStep(universe, 1.0 / 60);
        if (step % 30 == 0) {
            MeVector3 p;
            MdtBodyGetPosition(body, p);
            printf("t = %.1f s: box centre at height %.2f m, %s\n", step / 60.0, (double)p[1],
                   MdtBodyIsEnabled(body) ? "awake" : "asleep");
        }
    }
    printf("mass %.1f kg; the box rests with its centre half its size (0.25 m) above the ground\n",
           (double)MdtBodyGetMass(body));
    MstUniverseDestroy(universe);
    return 0;
}
