/*
  gyroscope.c -- a spinning top precesses (after Karma 1.2's Gyroscope example).

  A flywheel (a disc) spins fast about its axle, which lies horizontally along x; one end of the
  axle is held by a ball-and-socket joint to the static environment, the disc's centre is a
  distance D from it, and gravity pulls down (y). Instead of falling, the axle turns slowly about
  the vertical: the precession rate is m g D / (Is w) for spin w and polar moment of inertia Is.
  The body is given non-spherical inertia and the Coriolis force (Karma does not use the full
  tensor otherwise), and starts with the precession speed so that it nutates little. Checked: the
  measured precession rate against the analytic one, and the axle staying nearly level.
*/
#include <math.h>
#include "Mdt.h"
#include "MeMath.h"
#include "compat_check.h"

#define MASS 1
#define RADIUS 0.5
#define DISTANCE 1
#define SPIN 60
#define GRAVITY 9.8

int MEAPI_CDECL main(int argc, const char *(argv[]))
{
    MdtWorldID world;
    MdtBodyID wheel;
    MdtBSJointID pivot;
    MeMatrix3 I;
    MeReal polar = (MeReal)(MASS * RADIUS * RADIUS / 2);
    MeReal diametral = (MeReal)(MASS * RADIUS * RADIUS / 4);
    MeReal rate = (MeReal)(MASS * GRAVITY * DISTANCE) / (polar * SPIN);
    MeReal step = (MeReal)0.001, seconds = 2, turned = 0, previous = 0, sag = 0;
    int i;

    (void)argc;
    (void)argv;

    world = MdtWorldCreate(1, 1, 1, 1);
    MdtWorldSetAutoDisable(world, 0);
    MdtWorldSetGravity(world, 0, -(MeReal)GRAVITY, 0);

    wheel = MdtBodyCreate(world);
    MdtBodySetMass(wheel, MASS);
    I[0][0] = polar;     I[0][1] = 0;         I[0][2] = 0;
    I[1][0] = 0;         I[1][1] = diametral; I[1][2] = 0;
    I[2][0] = 0;         I[2][1] = 0;         I[2][2] = diametral;
    MdtBodySetInertiaTensor(wheel, I);
    MdtBodyEnableNonSphericalInertia(wheel);
    MdtBodyEnableCoriolisForce(wheel);
    MdtBodySetPosition(wheel, DISTANCE, 0, 0);
    MdtBodySetAngularVelocity(wheel, SPIN, rate, 0);
    MdtBodySetLinearVelocity(wheel, 0, 0, -rate * DISTANCE);
    MdtBodyEnable(wheel);

    pivot = MdtBSJointCreate(world);
    MdtBSJointSetBodies(pivot, wheel, 0);
    MdtBSJointSetPosition(pivot, 0, 0, 0);
    MdtBSJointEnable(pivot);

    /* Angle of the axle about the vertical, unwrapped as it turns. */
    for (i = 0; i < (int)(seconds / step); i++)
    {
        MeVector3 p;
        MeReal azimuth, change;

        MeProfileStartSection("Dynamics", 0);
        MdtWorldStep(world, step);
        MeProfileEndSection("Dynamics");
        MdtBodyGetPosition(wheel, p);
        azimuth = MeAtan2(-p[2], p[0]);
        change = azimuth - previous;
        if (change > ME_PI)
            change -= 2 * ME_PI;
        if (change < -ME_PI)
            change += 2 * ME_PI;
        turned += change;
        previous = azimuth;
        if (-p[1] > sag)
            sag = -p[1];
    }

    printf("Gyroscope: turned %g rad in %g s; analytic rate %g rad/s; lowest centre %g m\n",
           (double)turned, (double)seconds, (double)rate, (double)-sag);
    compatNear("precession rate (rad/s)", turned / seconds, rate, 0.05 * rate);
    compatNear("how far the axle dips (m)", sag, 0, 0.1 * DISTANCE);

    MdtBSJointDestroy(pivot);
    MdtWorldDestroy(world);
    return compatExit("gyroscope");
}
