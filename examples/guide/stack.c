/* stack.c -- how-to "Stack boxes that stand": ten 1 kg boxes in a column on the ground, at the world's
 * default settings, with friction. After 10 s the column still stands and has gone to sleep. */
#include <math.h>
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

int main(void)
{
    enum { BOXES = 10 };
    const MeReal size = 0.5;
    MstUniverseSizes sizes = MstUniverseDefaultSizes; /* massScale 1: our boxes weigh 1 kg */
    MstUniverseID universe = MstUniverseCreate(&sizes);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MstBridgeID bridge = MstUniverseGetBridge(universe);
    MdtWorldSetGravity(MstUniverseGetWorld(universe), 0, -9.81, 0);
    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);

    /* Everything has the default material: give its contacts Coulomb friction, mu = 0.6. */
    const MstMaterialID material = MstBridgeGetDefaultMaterial();
    MdtContactParamsID p = MstBridgeGetContactParams(bridge, material, material);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, 0.6);

    /* The column: box i over box i - 1, 1 mm apart so that they start untouched, and stacked as a
     * hand would, not quite straight: every other box is 2 cm off to the side. */
    MdtBodyID boxes[BOXES];
    for (int i = 0; i < BOXES; i++) {
        McdModelID box = MstModelAndBodyCreate(universe, McdBoxCreate(collision, size, size, size), 8);
        boxes[i] = McdModelGetBody(box);
        MdtBodySetPosition(boxes[i], i % 2 ? (MeReal)0.02 : 0, size / 2 + i * (size + (MeReal)0.001), 0);
    }
    MeVector3 start;
    MdtBodyGetPosition(boxes[BOXES - 1], start);

    for (int step = 0; step < 10 * 60; step++)
        MstUniverseStep(universe, 1.0 / 60);

    int awake = 0;
    for (int i = 0; i < BOXES; i++)
        awake += MdtBodyIsEnabled(boxes[i]) ? 1 : 0;
    MeVector3 top;
    MdtBodyGetPosition(boxes[BOXES - 1], top);
    const double dx = (double)(top[0] - start[0]), dz = (double)(top[2] - start[2]), drift = sqrt(dx * dx + dz * dz);
    printf("after 10 s: top box at height %.2f m (a standing column: %.2f m), %d of %d boxes awake\n",
           (double)top[1], (double)(size / 2 + (BOXES - 1) * size), awake, BOXES);
    printf("the top box drifted sideways %.1f mm\n", 1000 * drift);
    MstUniverseDestroy(universe);
    return 0;
}
