/*
  hinge.c -- a body on a motorised hinge with limits (after Karma 1.2's Hinge example).

  A box hangs on a hinge to the static environment whose axis, x, passes through its centre. The
  hinge's motor drives it at a set speed with a bounded torque; hard limits at -90 and +90
  degrees stop it. Checked: the motor brings the box to the set speed, the upper limit stops it
  and holds it there, reversing the motor takes it to the lower limit, the limit's measured angle
  agrees with the body's orientation, and the joint holds the box's centre where it was against
  gravity.
*/
#include <math.h>
#include "Mdt.h"
#include "compat_check.h"

#define SPEED 2
#define MAX_TORQUE 50
#define LIMIT (ME_PI / 2)

MdtWorldID world;
MdtBodyID body;
MdtHingeID hinge;
MeReal step = (MeReal)0.01;
MeReal drift = 0;
MeReal farthest = 0;

/* The box's angle about x, from its quaternion (w, x, y, z). */
MeReal bodyAngle(void)
{
    MeVector4 q;
    MdtBodyGetQuaternion(body, q);
    return 2 * MeAtan2(q[1], q[0]);
}

void MEAPI run(MeReal seconds)
{
    int i;

    for (i = 0; i < (int)(seconds / step); i++)
    {
        MeVector3 p;
        MeReal a;

        MeProfileStartSection("Dynamics", 0);
        MdtWorldStep(world, step);
        MeProfileEndSection("Dynamics");

        MdtBodyGetPosition(body, p);
        if (MeFabs(p[1]) + MeFabs(p[2]) + MeFabs(p[0] + 5) > drift)
            drift = MeFabs(p[1]) + MeFabs(p[2]) + MeFabs(p[0] + 5);
        a = MeFabs(bodyAngle());
        if (a > farthest)
            farthest = a;
    }
}

int MEAPI_CDECL main(int argc, const char **argv)
{
    MdtLimitID limit;
    MeMatrix3 I;
    MeVector3 w;
    int k;

    (void)argc;
    (void)argv;

    world = MdtWorldCreate(1, 1, 1, 1);
    MdtWorldSetAutoDisable(world, 0);
    MdtWorldSetGravity(world, 0, -(MeReal)9.8, 0);

    body = MdtBodyCreate(world);
    MdtMakeInertiaTensorBox(1, 4, 2, 4, I);
    MdtBodySetInertiaTensor(body, I);
    MdtBodySetPosition(body, -5, 0, 0);
    MdtBodySetQuaternion(body, 1, 0, 0, 0);
    MdtBodyEnable(body);

    hinge = MdtHingeCreate(world);
    MdtHingeSetBodies(hinge, body, 0);
    MdtHingeSetPosition(hinge, 0, 0, 0);
    MdtHingeSetAxis(hinge, 1, 0, 0);

    /* Hard stops (infinite stiffness) that do not bounce, at -LIMIT and +LIMIT. */
    limit = MdtHingeGetLimit(hinge);
    for (k = 0; k < 2; k++)
    {
        MdtSingleLimitID stop = k ? MdtLimitGetUpperLimit(limit) : MdtLimitGetLowerLimit(limit);
        MdtSingleLimitSetStop(stop, k ? LIMIT : -LIMIT);
        MdtSingleLimitSetStiffness(stop, MEINFINITY);
        MdtSingleLimitSetRestitution(stop, 0);
    }
    MdtLimitActivateLimits(limit, 1);
    MdtLimitSetLimitedForceMotor(limit, SPEED, MAX_TORQUE);
    MdtLimitActivateMotor(limit, 1);
    MdtHingeEnable(hinge);

    run((MeReal)0.4);
    MdtBodyGetAngularVelocity(body, w);
    compatNear("speed under the motor (rad/s)", w[0], SPEED, 0.05);
    /* The motor's torque takes SPEED * Ixx / MAX_TORQUE seconds to bring the box to speed. */
    compatNear("angle after 0.4 s (rad)", bodyAngle(), SPEED * (0.4 - 0.5 * SPEED * I[0][0] / MAX_TORQUE), 0.02);

    run(3);
    MdtBodyGetAngularVelocity(body, w);
    compatNear("angle held at the upper limit (rad)", bodyAngle(), LIMIT, 0.03);
    compatNear("the limit's measured angle (rad)", MdtLimitGetPosition(limit), bodyAngle(), 0.01);
    compatNear("speed at the limit (rad/s)", w[0], 0, 0.02);
    compatCheck(farthest < LIMIT + (MeReal)0.05, "the box never goes past the upper limit");

    MdtLimitSetLimitedForceMotor(limit, -SPEED, MAX_TORQUE);
    MdtLimitActivateMotor(limit, 1);
    run(3);
    compatNear("angle held at the lower limit (rad)", bodyAngle(), -LIMIT, 0.03);
    compatNear("the limit's measured angle (rad)", MdtLimitGetPosition(limit), -LIMIT, 0.03);
    compatCheck(farthest < LIMIT + (MeReal)0.05, "the box never goes past either limit");
    compatNear("distance the joint let the centre move (m)", drift, 0, 0.01);

    MdtHingeDestroy(hinge);
    MdtWorldDestroy(world);
    return compatExit("hinge");
}
