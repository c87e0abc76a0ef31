/*
  pendulums.c -- many pendulums swing with their own periods (after Karma 1.2's ManyPendulums
  example).

  A row of pendulums of different lengths hangs from ball-and-socket joints on the static
  environment; each bob is a small ball. They are let go from a small angle together. Checked:
  each one's period, measured over several swings, against the compound pendulum's
  2 pi sqrt((L^2 + k^2) / (g L)) (k the bob's radius of gyration), with the large-amplitude
  correction; and that each keeps its length.
*/
#include <math.h>
#include <Mdt.h>
#include <MeMemory.h>
#include "compat_check.h"

#define N 8
#define GRAVITY 9.8
#define BOB 0.05
#define AMPLITUDE 0.1

int MEAPI_CDECL main(int argc, const char **argv)
{
    MdtWorld *world;
    MdtBodyID *bob;
    MdtBSJointID *joint;
    MeReal *length, *firstCrossing, *lastCrossing, *lastX, *stretch;
    int *crossings;
    MeMatrix3 I;
    MeReal step = (MeReal)0.002;
    int i, n;

    (void)argc;
    (void)argv;

    bob = (MdtBodyID *)MeMemoryAPI.create(N * sizeof(MdtBodyID));
    joint = (MdtBSJointID *)MeMemoryAPI.create(N * sizeof(MdtBSJointID));
    length = (MeReal *)MeMemoryAPI.create(5 * N * sizeof(MeReal));
    firstCrossing = length + N;
    lastCrossing = length + 2 * N;
    lastX = length + 3 * N;
    stretch = length + 4 * N;
    crossings = (int *)MeMemoryAPI.createZeroed(N * sizeof(int));

    world = MdtWorldCreate(N, N, 1, 1);
    MdtWorldSetAutoDisable(world, 0);
    MdtWorldSetGravity(world, 0, -(MeReal)GRAVITY, 0);

    MdtMakeInertiaTensorSphere(1, BOB, I);
    for (i = 0; i < N; i++)
    {
        MeReal x = (MeReal)i;

        length[i] = (MeReal)0.5 + (MeReal)0.5 * i;
        bob[i] = MdtBodyCreate(world);
        MdtBodySetInertiaTensor(bob[i], I);
        MdtBodySetPosition(bob[i], x + length[i] * MeSin(AMPLITUDE), 10 - length[i] * MeCos(AMPLITUDE), 0);
        MdtBodyEnable(bob[i]);

        joint[i] = MdtBSJointCreate(world);
        MdtBSJointSetBodies(joint[i], bob[i], 0);
        MdtBSJointSetPosition(joint[i], x, 10, 0);
        MdtBSJointEnable(joint[i]);
        lastX[i] = length[i] * MeSin(AMPLITUDE);
        stretch[i] = 0;
    }

    /* Upward zero crossings of each bob's x offset, interpolated within the step. */
    for (n = 1; n <= (int)(20 / step); n++)
    {
        MdtWorldStep(world, step);
        for (i = 0; i < N; i++)
        {
            MeVector3 p;
            MeReal x, d;

            MdtBodyGetPosition(bob[i], p);
            x = p[0] - (MeReal)i;
            if (lastX[i] < 0 && x >= 0)
            {
                MeReal t = (n - 1 + lastX[i] / (lastX[i] - x)) * step;
                if (crossings[i]++ == 0)
                    firstCrossing[i] = t;
                lastCrossing[i] = t;
            }
            lastX[i] = x;
            d = MeFabs(MeSqrt(x * x + (p[1] - 10) * (p[1] - 10) + p[2] * p[2]) - length[i]);
            if (d > stretch[i])
                stretch[i] = d;
        }
    }

    for (i = 0; i < N; i++)
    {
        char what[80];
        double L = length[i], k2 = 0.4 * BOB * BOB;
        double analytic = 2 * ME_PI * sqrt((L * L + k2) / (GRAVITY * L)) * (1 + AMPLITUDE * AMPLITUDE / 16);
        double measured = crossings[i] > 1 ? (lastCrossing[i] - firstCrossing[i]) / (crossings[i] - 1) : 0;

        sprintf(what, "period of the %.1f m pendulum (s)", L);
        compatNear(what, measured, analytic, 0.005 * analytic);
        sprintf(what, "the %.1f m pendulum keeps its length", L);
        compatCheck(stretch[i] < (MeReal)0.002 * length[i], what);
    }

    MdtWorldDestroy(world);
    MeMemoryAPI.destroy(bob);
    MeMemoryAPI.destroy(joint);
    MeMemoryAPI.destroy(length);
    MeMemoryAPI.destroy(crossings);
    return compatExit("pendulums");
}
