/* karma_pendulum.c -- the pendulum of the joint tests (karma_pendulum.h). Plain C on the public API. */
#include "karma_pendulum.h"

#include <math.h>

#include <karma/Mdt.h>

#define KARMA_PENDULUM_G 9.81
#define KARMA_PENDULUM_INERTIA 1e-3

static void holdBob(MdtWorldID w, MdtBodyID bob, KarmaPendulumJoint joint)
{
    if (joint == KARMA_PENDULUM_BALL) {
        MdtBSJointID j = MdtBSJointCreate(w);
        MdtBSJointSetBodies(j, bob, NULL);
        MdtBSJointSetPosition(j, 0, 0, 0);
        MdtBSJointEnable(j);
    } else {
        MdtHingeID j = MdtHingeCreate(w);
        MdtHingeSetBodies(j, bob, NULL);
        MdtHingeSetPosition(j, 0, 0, 0);
        MdtHingeSetAxis(j, 0, 1, 0);
        MdtHingeEnable(j);
    }
}

KarmaPendulum karma_pendulum_swing(KarmaPendulumJoint joint, double h, double L, double theta0)
{
    KarmaPendulum out = {NAN, 0, 0};
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-KARMA_PENDULUM_G);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID bob = MdtBodyCreate(w);
    MdtBodySetSphericalInertiaTensor(bob, (MeReal)KARMA_PENDULUM_INERTIA);
    MdtBodySetPosition(bob, (MeReal)(L * sin(theta0)), 0, (MeReal)(-L * cos(theta0)));
    MdtBodyEnable(bob);
    holdBob(w, bob, joint);
    /* The times the bob crosses the vertical, interpolated linearly between steps. */
    double lastX = L * sin(theta0), t = 0, crossings[8];
    int n = 0;
    while (n < 8 && t < 60) {
        MdtWorldStep(w, (MeReal)h);
        t += h;
        MeVector3 p;
        MeMatrix3 R;
        MdtBodyGetPosition(bob, p);
        MdtBodyGetOrientation(bob, R); /* row 1: the bob's y axis */
        double r = sqrt((double)p[0] * p[0] + (double)p[1] * p[1] + (double)p[2] * p[2]);
        out.lengthDrift = fmax(out.lengthDrift, fabs(r - L));
        out.axisDrift = fmax(out.axisDrift, fmax(fabs((double)p[1]), fmax(fabs((double)R[1][0]), fabs((double)R[1][2]))));
        if ((lastX > 0) != (p[0] > 0))
            crossings[n++] = t - h * (double)p[0] / ((double)p[0] - lastX);
        lastX = (double)p[0];
    }
    MdtWorldDestroy(w);
    if (n == 8)
        out.period = (crossings[7] - crossings[1]) / 3; /* three full periods */
    return out;
}

double karma_pendulum_expected_period(double L, double theta0)
{
    const double pi = 3.14159265358979323846;
    return 2 * pi * sqrt((L * L + KARMA_PENDULUM_INERTIA) / (KARMA_PENDULUM_G * L)) * (1 + theta0 * theta0 / 16);
}
