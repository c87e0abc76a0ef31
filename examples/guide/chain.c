/* chain.c -- how-to "Ragdolls": the ragdoll's parts in small. Four links joined end to end by
 * ball-and-socket joints fall across a post. With a cone limit of 30 degrees on each joint, the chain
 * drapes over the post with each joint bent to its limit and no further; without limits it folds
 * further and hangs lower. Either way the joints hold the links together. */
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

/* Drops the chain on the post with cone limits of `limitDegrees` (180: no limit) and prints how it
 * hangs after 5 s. */
static void drape(double limitDegrees)
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
     * x axes (the limit's default axes) under its half-angle. Joined links overlap at the joint: they
     * must not collide with each other. */
    MdtConeLimitID cones[LINKS - 1];
    for (int i = 0; i < LINKS - 1; i++) {
        MdtBSJointID joint = MdtBSJointCreate(world);
        MdtBSJointSetBodies(joint, links[i], links[i + 1]);
        MdtBSJointSetPosition(joint, (2 * i - LINKS + 2) * half, 1.5, 0);
        MdtBSJointEnable(joint);
        cones[i] = MdtConeLimitCreate(world);
        MdtConeLimitSetBodies(cones[i], links[i], links[i + 1]);
        MdtConeLimitSetConeHalfAngle(cones[i], (MeReal)(limitDegrees * 3.14159265358979 / 180));
        MdtConeLimitEnable(cones[i]);
        McdSpaceDisablePair(models[i], models[i + 1]);
    }

    for (int step = 0; step < 5 * 60; step++)
        MstUniverseStep(universe, 1.0 / 60);

    double largestGap = 0;
    printf("%s: joints bent", limitDegrees < 180 ? "cone limits of 30 degrees" : "no limits");
    for (int i = 0; i < LINKS - 1; i++) {
        MeVector3 a, b;
        pointOn(links[i], half, a);
        pointOn(links[i + 1], -half, b);
        double gap2 = 0;
        for (int k = 0; k < 3; k++)
            gap2 += (double)((a[k] - b[k]) * (a[k] - b[k]));
        largestGap = fmax(largestGap, sqrt(gap2));
        printf("%s %.0f", i ? "," : "", (double)MdtConeLimitGetAngle(cones[i]) * 180 / 3.14159265358979);
    }
    MeVector3 end;
    MdtBodyGetPosition(links[0], end);
    printf(" degrees; end links' centres %.2f m up; joints open %s 1 mm\n", (double)end[1],
           largestGap < 0.001 ? "less than" : "more than");
    MstUniverseDestroy(universe);
}

int main(void)
{
    drape(30);
    drape(180);
    return 0;
}
