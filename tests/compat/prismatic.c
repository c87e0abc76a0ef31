/*
  prismatic.c -- a slider on a prismatic joint with limits and a motor (after Karma 1.2's
  Prismatic example).

  A body slides on a vertical prismatic joint to the static environment. It falls freely along
  the axis, a side push does not move it off the axis, the lower limit stops it, and the joint's
  motor then drives it up at a set speed to the upper limit. Checked against free fall, the
  limits and the motor's speed.
*/
#include <math.h>
#include <Mdt.h>
#include "compat_check.h"

#define LOWER (-2)
#define UPPER 1
#define SPEED 1

MdtWorld *world;
MdtBodyID body;
MdtPrismaticID prism;
MeReal step = (MeReal)0.01;
MeReal sideways = 0, lowest = 0;

void MEAPI run(MeReal seconds, MeReal push)
{
    int i;

    for (i = 0; i < (int)(seconds / step); i++)
    {
        MeVector3 p;

        MdtBodyAddForce(body, push, 0, push);
        MdtWorldStep(world, step);
        MdtBodyGetPosition(body, p);
        if (MeFabs(p[0]) + MeFabs(p[2]) > sideways)
            sideways = MeFabs(p[0]) + MeFabs(p[2]);
        if (p[1] - 5 < lowest)
            lowest = p[1] - 5;
    }
}

MeReal height(void)
{
    MeVector3 p;
    MdtBodyGetPosition(body, p);
    return p[1] - 5;
}

int MEAPI_CDECL main(int argc, const char **argv)
{
    MdtLimitID limit;
    MeVector3 v;
    MeVector4 q;

    (void)argc;
    (void)argv;

    world = MdtWorldCreate(1, 1, 1, 1);
    MdtWorldSetAutoDisable(world, 0);
    MdtWorldSetGravity(world, 0, -(MeReal)9.8, 0);

    body = MdtBodyCreate(world);
    MdtBodySetPosition(body, 0, 5, 0);
    MdtBodyEnable(body);

    prism = MdtPrismaticCreate(world);
    MdtPrismaticSetBodies(prism, body, 0);
    MdtPrismaticSetAxis(prism, 0, 1, 0);
    limit = MdtPrismaticGetLimit(prism);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(limit), LOWER);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(limit), UPPER);
    MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(limit), 0);
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(limit), 0);
    MdtLimitActivateLimits(limit, 1);
    MdtPrismaticEnable(prism);

    run((MeReal)0.5, 20);
    compatNear("fall along the axis in 0.5 s (m)", height(), -0.5 * 9.8 * 0.25, 0.03);
    compatNear("the limit's measured position (m)", MdtLimitGetPosition(limit), height(), 0.01);

    run(2, 20);
    MdtBodyGetLinearVelocity(body, v);
    compatNear("resting on the lower limit (m)", height(), LOWER, 0.02);
    compatNear("speed on the lower limit (m/s)", v[1], 0, 0.02);
    compatCheck(lowest > LOWER - (MeReal)0.05, "the slider never goes past the lower limit");

    MdtLimitSetLimitedForceMotor(limit, SPEED, 100);
    MdtLimitActivateMotor(limit, 1);
    run(1, 0);
    MdtBodyGetLinearVelocity(body, v);
    compatNear("speed under the motor (m/s)", v[1], SPEED, 0.02);

    run(3, 0);
    compatNear("held at the upper limit (m)", height(), UPPER, 0.02);
    compatNear("distance pushed off the axis (m)", sideways, 0, 0.01);
    MdtBodyGetQuaternion(body, q);
    compatNear("rotation (quaternion w)", q[0], 1, 0.001);

    MdtWorldDestroy(world);
    return compatExit("prismatic");
}
