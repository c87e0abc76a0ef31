/* seesaws.c -- step 4 of the guide's tutorial: collision, a joint and materials together. Two seesaws
 * (planks on hinges) side by side; a box is dropped on the right end of each. The plank tips until its
 * end meets the ground. The rubber box grips the slope and stays; the ice box slides off. */
#include <math.h>
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

/* A 3 m plank on a hinge 0.5 m above the ground at (0, 0.5, z), turning about z; returns its hinge. */
static MdtHingeID seesaw(MstUniverseID universe, MeReal z)
{
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    McdModelID plank = MstModelAndBodyCreate(universe, McdBoxCreate(collision, 3, 0.1, 0.5), 200);
    MdtBodySetPosition(McdModelGetBody(plank), 0, 0.5, z);
    MdtHingeID hinge = MdtHingeCreate(MstUniverseGetWorld(universe));
    MdtHingeSetBodies(hinge, McdModelGetBody(plank), NULL);
    MdtHingeSetPosition(hinge, 0, 0.5, z);
    MdtHingeSetAxis(hinge, 0, 0, 1);
    MdtHingeEnable(hinge);
    return hinge;
}

/* A 0.4 m box of `material`, dropped from 1.5 m onto the right end of the plank at z. */
static MdtBodyID dropBox(MstUniverseID universe, MstMaterialID material, MeReal z)
{
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    McdModelID box = MstModelAndBodyCreate(universe, McdBoxCreate(collision, 0.4, 0.4, 0.4), 500);
    McdModelSetMaterial(box, (int)material);
    MdtBodySetPosition(McdModelGetBody(box), 1.2, 1.5, z);
    return McdModelGetBody(box);
}

int main(void)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 30; /* planks and boxes weigh about 30 kg */
    MstUniverseID universe = MstUniverseCreate(&sizes);
    MstBridgeID bridge = MstUniverseGetBridge(universe);
    MdtWorldSetGravity(MstUniverseGetWorld(universe), 0, -9.81, 0);
    MstFixedModelCreate(universe, McdPlaneCreate(MstUniverseGetFramework(universe)), groundTM);

    /* Materials: the ground and planks keep the default material 0; each box gets one of its own.
     * Each pair of materials has its contact parameters: Coulomb friction with mu = 0.9 or 0.05. */
    MstMaterialID rubber = MstBridgeGetNewMaterial(bridge), ice = MstBridgeGetNewMaterial(bridge);
    const MstMaterialID materials[2] = {rubber, ice};
    const MeReal mu[2] = {0.9, 0.05};
    for (int i = 0; i < 2; i++) {
        MdtContactParamsID p = MstBridgeGetContactParams(bridge, MstBridgeGetDefaultMaterial(), materials[i]);
        MdtContactParamsSetType(p, MdtContactTypeFriction2D);
        MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
        MdtContactParamsSetFrictionCoeffecient(p, mu[i]);
    }

    MdtHingeID hinges[2] = {seesaw(universe, -1), seesaw(universe, 1)};
    MdtBodyID boxes[2] = {dropBox(universe, rubber, -1), dropBox(universe, ice, 1)};
    for (int step = 0; step < 5 * 60; step++)
        MstUniverseStep(universe, 1.0 / 60);

    const char *names[2] = {"rubber", "ice"};
    for (int i = 0; i < 2; i++) {
        MeReal angle = MdtLimitGetPosition(MdtHingeGetLimit(hinges[i]));
        MeVector3 p;
        MdtBodyGetPosition(boxes[i], p);
        printf("%-6s (mu %.2f): plank tipped %.1f degrees (tan %.2f); the box %s\n", names[i], (double)mu[i],
               fabs((double)angle) * 180 / 3.14159265358979, tan(fabs((double)angle)),
               p[1] > (MeReal)0.3 ? "stays on the plank" : "slid off onto the ground");
    }
    MstUniverseDestroy(universe);
    return 0;
}
