/*
  bounce.c -- a ball dropped on the ground bounces, with contacts made by hand (after Karma 1.2's
  Bounce tutorial and the Karma 1.2 User Guide's description of it).

  The ball is body 0 of its contact and the world (static environment) body 1, given as 0; y is up
  and the ground is the plane y = 0, so the contact normal is (0, 1, 0): the direction in which
  body 0 is pushed. Each tick the last contact is destroyed and a new one made while the ball
  touches the ground. The checks: the ball never sinks through the ground, it leaves the ground
  with the restitution times its impact speed, it rises to restitution squared times its drop
  height, and it comes to rest on the ground.
*/
#include <math.h>
#include "Mdt.h"
#include "compat_check.h"

#define RADIUS 1
#define DROP_HEIGHT 10
#define RESTITUTION 0.6

MdtWorldID world;
MdtBodyID ball;
MdtContactID contact = 0;
MeReal step = (MeReal)0.005;

/* Make the ball's contact with the ground for this step, if it touches it. */
void MEAPI tick(void)
{
    MeVector3 pos;
    MeReal penetration;

    if (contact)
    {
        MdtContactDisable(contact);
        MdtContactDestroy(contact);
        contact = 0;
    }

    MdtBodyGetPosition(ball, pos);
    penetration = RADIUS - pos[1];
    if (penetration > 0)
    {
        MdtContactParamsID params;

        contact = MdtContactCreate(world);
        MdtContactSetBodies(contact, ball, 0);
        MdtContactSetPosition(contact, pos[0], pos[1] - RADIUS, pos[2]);
        MdtContactSetNormal(contact, 0, 1, 0);
        MdtContactSetPenetration(contact, penetration);

        params = MdtContactGetParams(contact);
        MdtContactParamsSetType(params, MdtContactTypeFriction2D);
        MdtContactParamsSetFriction(params, (MeReal)5.0);
        MdtContactParamsSetRestitution(params, (MeReal)RESTITUTION);
        MdtContactEnable(contact);
    }

    MeProfileStartSection("Dynamics", 0);
    MdtWorldStep(world, step);
    MeProfileEndSection("Dynamics");
}

int MEAPI_CDECL main(int argc, const char *(argv[]))
{
    MeMatrix3 I;
    MeVector3 pos, vel;
    MeReal lowest = DROP_HEIGHT;
    MeReal impactSpeed = 0, leavingSpeed = 0, apex = 0;
    int bounces = 0, touching = 0, i;

    (void)argc;
    (void)argv;

    world = MdtWorldCreate(1, 1, 1, 1);
    MdtWorldSetGravity(world, 0, -(MeReal)9.8, 0);

    ball = MdtBodyCreate(world);
    MdtBodySetMass(ball, 1);
    MdtMakeInertiaTensorSphere(1, RADIUS, I);
    MdtBodySetInertiaTensor(ball, I);
    MdtBodySetPosition(ball, 0, DROP_HEIGHT, 0);
    MdtBodySetQuaternion(ball, 1, 0, 0, 0);
    MdtBodyEnable(ball);

    for (i = 0; i < (int)(20 / step); i++)
    {
        MdtBodyGetLinearVelocity(ball, vel);
        tick();
        MdtBodyGetPosition(ball, pos);
        if (pos[1] < lowest)
            lowest = pos[1];

        /* The first bounce: speed at impact, speed on leaving, height of the next apex. */
        if (contact && !touching && bounces == 0)
            impactSpeed = -vel[1];
        if (contact)
            touching = 1;
        if (!contact && touching)
        {
            touching = 0;
            if (bounces++ == 0)
            {
                MdtBodyGetLinearVelocity(ball, vel);
                leavingSpeed = vel[1];
            }
        }
        if (bounces == 1 && pos[1] > apex)
            apex = pos[1];
    }

    printf("Bounce: lowest centre %g, impact %g m/s, leaving %g m/s, apex %g m, %d bounces\n",
           (double)lowest, (double)impactSpeed, (double)leavingSpeed, (double)apex, bounces);
    compatCheck(lowest > (MeReal)(0.9 * RADIUS), "the ball never sinks through the ground");
    compatNear("impact speed (m/s)", impactSpeed, sqrt(2 * 9.8 * (DROP_HEIGHT - RADIUS)), 0.2);
    compatNear("leaving speed / impact speed (the restitution)", leavingSpeed / impactSpeed,
               RESTITUTION, 0.06);
    compatNear("height of the first apex above the ground", apex - RADIUS,
               RESTITUTION * RESTITUTION * (DROP_HEIGHT - RADIUS), 0.4);
    compatCheck(bounces >= 3, "the ball bounces more than once");

    MdtBodyGetPosition(ball, pos);
    MdtBodyGetLinearVelocity(ball, vel);
    compatNear("height at rest after 20 s", pos[1], RADIUS, 0.05);
    compatNear("vertical speed at rest", vel[1], 0, 0.2);

    MdtWorldDestroy(world);
    return compatExit("bounce");
}
