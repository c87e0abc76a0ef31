/* chain.c -- how-to "Ragdolls": the ragdoll's parts in small. Four links joined end to end by
 * ball-and-socket joints, each with a cone limit of 30 degrees, fall across a post. The chain drapes
 * over it: each joint bends to its limit and no further, and the joints hold the links together. */
#include <math.h>
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */
static MeMatrix4 postTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0.5, 0, 1}};   /* a 1 m post */

enum { LINKS = 4 };
static const MeReal half = 0.3; /* each link is 0.6 m long along its x axis */

/* The world point at `along` metres on link's x axis from its centre (the transform's rows are its axes). */
static void pointOn(MdtBodyID link, MeReal along, MeVector3 out)
{
    MeMatrix4 tm;
    MdtBodyGetTransform(link, tm);
    for (int k = 0; k < 3; k++)
        out[k] = tm[3][k] + along * tm[0][k];
}

int main(void)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID universe = MstUniverseCreate(&sizes);
    MdtWorldID world = MstUniverseGetWorld(universe);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MstBridgeID bridge = MstUniverseGetBridge(universe);
    MdtWorldSetGravity(world, 0, -9.81, 0);
    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);
    MstFixedModelCreate(universe, McdBoxCreate(collision, 0.4, 1, 1), postTM);
    const MstMaterialID material = MstBridgeGetDefaultMaterial();
    MdtContactParamsID p = MstBridgeGetContactParams(bridge, material, material);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, 0.8);

    /* Four 1 kg links in a row along x, 1.5 m up, centred over the post. */
    McdModelID models[LINKS];
    MdtBodyID links[LINKS];
    for (int i = 0; i < LINKS; i++) {
        McdGeometryID shape = McdBoxCreate(collision, 2 * half, 0.2, 0.2);
        models[i] = MstModelAndBodyCreate(universe, shape, (MeReal)(1 / 0.024)); /* 1 kg: 0.024 m^3 */
        links[i] = McdModelGetBody(models[i]);
        MdtBodySetPosition(links[i], (2 * i - LINKS + 1) * half, 1.5, 0);
    }
    /* Joint i joins link i to link i + 1 where they meet. A cone limit keeps the angle between their
     * x axes (the limit's default axes) under 30 degrees. Joined links overlap at the joint: they must
     * not collide with each other. */
    MdtConeLimitID cones[LINKS - 1];
    for (int i = 0; i < LINKS - 1; i++) {
        MdtBSJointID joint = MdtBSJointCreate(world);
        MdtBSJointSetBodies(joint, links[i], links[i + 1]);
        MdtBSJointSetPosition(joint, (2 * i - LINKS + 2) * half, 1.5, 0);
        MdtBSJointEnable(joint);
        cones[i] = MdtConeLimitCreate(world);
        MdtConeLimitSetBodies(cones[i], links[i], links[i + 1]);
        MdtConeLimitSetConeHalfAngle(cones[i], 30 * ME_PI / 180);
        MdtConeLimitEnable(cones[i]);
        McdSpaceDisablePair(models[i], models[i + 1]);
    }

    for (int step = 0; step < 5 * 60; step++)
        MstUniverseStep(universe, 1.0 / 60);

    for (int i = 0; i < LINKS - 1; i++) {
        MeVector3 a, b;
        pointOn(links[i], half, a);
        pointOn(links[i + 1], -half, b);
        double gap2 = 0;
        for (int k = 0; k < 3; k++)
            gap2 += (double)((a[k] - b[k]) * (a[k] - b[k]));
        const double degrees = (double)MdtConeLimitGetAngle(cones[i]) * 180 / 3.14159265358979;
        printf("joint %d: bent %.0f degrees (limit 30), the links' ends %s 1 mm apart\n", i + 1, degrees,
               sqrt(gap2) < 0.001 ? "less than" : "more than");
    }
    MeVector3 end;
    MdtBodyGetPosition(links[0], end);
    printf("the end links hang at %.2f m, above the ground: the limits hold the chain up\n", (double)end[1]);
    MstUniverseDestroy(universe);
    return 0;
}
