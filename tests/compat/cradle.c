/*
  cradle.c -- Newton's cradle on contacts made by hand (after Karma 1.2's Cradle example and the
  Karma 1.2 User Guide's account of it).

  Five balls hang from ball-and-socket joints on the static environment, in a row along x with a
  small gap. The first is pulled aside and let go; every tick each pair of balls is tested and, if
  they overlap, a frictionless contact with restitution 1 is made with the bodies (b1, b2) and the
  normal from b2's centre toward b1's. The guide: the momentum and energy of the first ball are
  passed along the row, the last ball swings out and the first stops. Checked: the last ball
  leaves with nearly the first one's speed and rises to nearly its height, the first and middle
  balls are left almost at rest, no ball passes into another, and no energy is created.
*/
#include <math.h>
#include <Mdt.h>
#include <MeMath.h>
#include "compat_check.h"

#define N_PENDULUMS 5
#define N_CONTACTS 10
#define RADIUS 1
#define LENGTH 5
#define GAP 0.1
#define RELEASE_ANGLE (ME_PI / 3)

MdtWorldID world;
MdtBodyID ball[N_PENDULUMS];
MdtBSJointID bs[N_PENDULUMS];
MdtContactID contact[N_CONTACTS];
int contactsUsed = 0;
MeReal closest = 2 * RADIUS;
MeReal step = (MeReal)0.002;

/* A contact between two balls that overlap, normal from b2 toward b1. */
void sphereSphereCheck(MdtBodyID b1, MdtBodyID b2)
{
    MeVector3 p1, p2, normal;
    MeReal distance;
    MdtContactID c;
    MdtContactParamsID params;
    int i;

    MdtBodyGetPosition(b1, p1);
    MdtBodyGetPosition(b2, p2);
    for (i = 0; i < 3; i++)
        normal[i] = p1[i] - p2[i];
    distance = MeSqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    if (distance < closest)
        closest = distance;
    if (distance >= 2 * RADIUS || contactsUsed == N_CONTACTS)
        return;
    for (i = 0; i < 3; i++)
        normal[i] /= distance;

    c = contact[contactsUsed++];
    MdtContactReset(c);
    MdtContactSetBodies(c, b1, b2);
    MdtContactSetPosition(c, (p1[0] + p2[0]) / 2, (p1[1] + p2[1]) / 2, (p1[2] + p2[2]) / 2);
    MdtContactSetNormal(c, normal[0], normal[1], normal[2]);
    MdtContactSetPenetration(c, 2 * RADIUS - distance);
    params = MdtContactGetParams(c);
    MdtContactParamsSetType(params, MdtContactTypeFrictionZero);
    MdtContactParamsSetRestitution(params, 1);
    MdtContactEnable(c);
}

void MEAPI tick(void)
{
    int i, j;

    MeProfileStartSection("Collision", 1);
    for (i = 0; i < contactsUsed; i++)
        MdtContactDisable(contact[i]);
    contactsUsed = 0;
    for (i = 0; i < N_PENDULUMS; i++)
        for (j = i + 1; j < N_PENDULUMS; j++)
            sphereSphereCheck(ball[i], ball[j]);

    MeProfileStartSection("Dynamics", 0);
    MdtWorldStep(world, step);
    MeProfileEndSection("Dynamics");
}

/* Kinetic plus potential energy of the row (unit masses, heights from the balls' rest height). */
MeReal energy(void)
{
    MeReal e = 0;
    int i;

    for (i = 0; i < N_PENDULUMS; i++)
    {
        MeVector3 p, v;
        MdtBodyGetPosition(ball[i], p);
        MdtBodyGetLinearVelocity(ball[i], v);
        e += (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / 2 + (MeReal)9.8 * (p[1] - LENGTH);
    }
    return e;
}

MeReal speed(MdtBodyID b)
{
    MeVector3 v;
    MdtBodyGetLinearVelocity(b, v);
    return MeSqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

int MEAPI_CDECL main(int argc, const char *(argv[]))
{
    MeReal spacing = 2 * RADIUS + (MeReal)GAP;
    MeReal offset = (N_PENDULUMS - 1) * spacing / 2;
    MeReal startEnergy, impactSpeed = 0, lastMaxSpeed = 0, lastMaxRise = 0;
    MeReal firstSpeedAfter = 0, middleSpeedAfter = 0, maxEnergy;
    MeMatrix3 I;
    int i, n, impactStep = -1;

    (void)argc;
    (void)argv;

    world = MdtWorldCreate(N_PENDULUMS, N_PENDULUMS + N_CONTACTS, 1, 1);
    MdtWorldSetGravity(world, 0, -(MeReal)9.8, 0);
    MdtWorldSetAutoDisable(world, 0);

    MdtMakeInertiaTensorSphere(1, RADIUS, I);
    for (i = 0; i < N_PENDULUMS; i++)
    {
        ball[i] = MdtBodyCreate(world);
        MdtBodySetInertiaTensor(ball[i], I);
        MdtBodySetPosition(ball[i], i * spacing - offset, LENGTH, 0);
    }
    /* The first ball pulled aside on its string. */
    MdtBodySetPosition(ball[0], -offset - LENGTH * MeSin(RELEASE_ANGLE),
                       2 * LENGTH - LENGTH * MeCos(RELEASE_ANGLE), 0);

    for (i = 0; i < N_PENDULUMS; i++)
    {
        bs[i] = MdtBSJointCreate(world);
        MdtBSJointSetBodies(bs[i], ball[i], 0);
        MdtBSJointSetPosition(bs[i], i * spacing - offset, 2 * LENGTH, 0);
    }
    for (i = 0; i < N_CONTACTS; i++)
        contact[i] = MdtContactCreate(world);
    for (i = 0; i < N_PENDULUMS; i++)
    {
        MdtBodyEnable(ball[i]);
        MdtBSJointEnable(bs[i]);
    }

    startEnergy = maxEnergy = energy();
    for (n = 0; n < (int)(3 / step); n++)
    {
        MeReal before = speed(ball[0]);
        MeVector3 p;

        tick();
        if (impactStep < 0 && contactsUsed > 0)
        {
            impactStep = n;
            impactSpeed = before;
        }
        if (energy() > maxEnergy)
            maxEnergy = energy();
        if (impactStep < 0)
            continue;
        if (n - impactStep < (int)(0.5 / step) && speed(ball[N_PENDULUMS - 1]) > lastMaxSpeed)
            lastMaxSpeed = speed(ball[N_PENDULUMS - 1]);
        MdtBodyGetPosition(ball[N_PENDULUMS - 1], p);
        if (p[1] - LENGTH > lastMaxRise)
            lastMaxRise = p[1] - LENGTH;
        if (n - impactStep == (int)(0.3 / step))
        {
            firstSpeedAfter = speed(ball[0]);
            for (i = 1; i < N_PENDULUMS - 1; i++)
                if (speed(ball[i]) > middleSpeedAfter)
                    middleSpeedAfter = speed(ball[i]);
        }
    }

    printf("Cradle: impact %g m/s, last ball's top speed %g m/s and rise %g m; first ball %g m/s, "
           "middle %g m/s 0.3 s later; closest centres %g\n", (double)impactSpeed,
           (double)lastMaxSpeed, (double)lastMaxRise, (double)firstSpeedAfter,
           (double)middleSpeedAfter, (double)closest);
    compatCheck(impactStep >= 0, "the first ball reaches the row");
    compatNear("impact speed (m/s)", impactSpeed, sqrt(2 * 9.8 * LENGTH * (1 - cos(ME_PI / 3))), 0.2);
    compatCheck(lastMaxSpeed > (MeReal)0.9 * impactSpeed,
                "the last ball leaves with at least 90% of the impact speed");
    compatCheck(lastMaxRise > (MeReal)0.85 * LENGTH * (1 - MeCos(RELEASE_ANGLE)),
                "the last ball rises to at least 85% of the first ball's drop");
    compatCheck(firstSpeedAfter < (MeReal)0.15 * impactSpeed, "the first ball is left almost at rest");
    compatCheck(middleSpeedAfter < (MeReal)0.15 * impactSpeed, "the middle balls are left almost at rest");
    compatCheck(closest > 2 * RADIUS - (MeReal)0.1, "no ball passes into another");
    compatCheck(maxEnergy < (MeReal)1.02 * startEnergy + (MeReal)0.01, "no energy is created");

    MdtWorldDestroy(world);
    return compatExit("cradle");
}
