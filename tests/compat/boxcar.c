/*
  boxcar.c -- a four-wheeled box car on contacts made by hand (after Karma 1.2's BoxCar example).

  z is up and the ground is the plane z = 0. A box chassis carries four wheels on car-wheel joints
  (chassis first, wheel second; steering axis z, hinge axis y); the rear wheels' steering is
  locked and the front wheels' steering motor holds them straight. Each tick every wheel touching
  the ground gets a contact (wheel, world) with normal (0, 0, 1), two-dimensional friction and its
  primary direction along the wheel's rolling direction; the rear wheels are driven by a torque
  about their hinge axes, taken back from the chassis. Checked: the car settles on its wheels
  (upright, chassis above the wheels, no wheel sinking into the ground) and drives forward along
  x when the torque is applied.
*/
#include <math.h>
#include "Mdt.h"
#include "compat_check.h"

#define WHEEL_RADIUS 0.35
#define WHEEL_X 0.8
#define WHEEL_Y 0.7
#define WHEEL_Z (-0.1)
#define CHASSIS_MASS 4
#define WHEEL_MASS 0.5

typedef struct Car
{
    MdtWorld *world;
    MdtBodyID body[5];                 /* 0-3 wheels (rear left, rear right, front left, front right), 4 chassis */
    MdtCarWheelID wheel_joint[4];
    MdtContactID wheel_ground_contact[4];
    MeReal drive_torque;
} Car;

void CarInit(Car *c, MdtWorld *w, MeReal height)
{
    MeMatrix3 I;
    int k;

    c->world = w;
    c->drive_torque = 0;
    c->body[4] = MdtBodyCreate(w);
    MdtBodySetMass(c->body[4], CHASSIS_MASS);
    MdtMakeInertiaTensorBox(CHASSIS_MASS, 2, 1, (MeReal)0.4, I);
    MdtBodySetInertiaTensor(c->body[4], I);
    MdtBodySetPosition(c->body[4], 0, 0, height - (MeReal)WHEEL_Z);

    MdtMakeInertiaTensorSphere(WHEEL_MASS, WHEEL_RADIUS, I);
    for (k = 0; k < 4; k++)
    {
        MeReal x = k < 2 ? -(MeReal)WHEEL_X : (MeReal)WHEEL_X;
        MeReal y = (k % 2) == 0 ? (MeReal)WHEEL_Y : -(MeReal)WHEEL_Y;
        MdtCarWheelID j;

        c->body[k] = MdtBodyCreate(w);
        MdtBodySetMass(c->body[k], WHEEL_MASS);
        MdtBodySetInertiaTensor(c->body[k], I);
        MdtBodySetPosition(c->body[k], x, y, height);

        j = c->wheel_joint[k] = MdtCarWheelCreate(w);
        MdtCarWheelSetBodies(j, c->body[4], c->body[k]);
        MdtCarWheelSetPosition(j, x, y, height);
        MdtCarWheelSetSteeringAndHingeAxes(j, 0, 0, 1, 0, 1, 0);
        if (k < 2)
            MdtCarWheelSetSteeringLock(j, 1);
        MdtCarWheelSetSuspension(j, 1000, 30, (MeReal)0.001, -(MeReal)0.1, (MeReal)0.1, 0);

        c->wheel_ground_contact[k] = MdtContactCreate(w);
    }
    for (k = 0; k < 5; k++)
        MdtBodyEnable(c->body[k]);
    for (k = 0; k < 4; k++)
        MdtCarWheelEnable(c->wheel_joint[k]);
}

/* Ground contacts, steering and drive for this step. */
void CarUpdate(Car *c)
{
    int k;

    for (k = 0; k < 4; k++)
    {
        MdtContactID contact = c->wheel_ground_contact[k];
        MeVector3 p, haxis;

        MdtCarWheelGetHingeAxis(c->wheel_joint[k], haxis);
        if (MdtContactIsEnabled(contact))
            MdtContactDisable(contact);
        MdtBodyGetPosition(c->body[k], p);
        if (p[2] <= WHEEL_RADIUS)
        {
            MdtContactParamsID params;
            MeReal a[3], norm;

            MdtContactSetBodies(contact, c->body[k], 0);
            MdtContactSetPosition(contact, p[0], p[1], p[2] - (MeReal)WHEEL_RADIUS);
            MdtContactSetNormal(contact, 0, 0, 1);
            MdtContactSetPenetration(contact, (MeReal)WHEEL_RADIUS - p[2]);
            /* The rolling direction: normal x hinge axis. */
            a[0] = -haxis[1];
            a[1] = haxis[0];
            a[2] = 0;
            norm = MeRecipSqrt(a[0] * a[0] + a[1] * a[1]);
            MdtContactSetDirection(contact, a[0] * norm, a[1] * norm, 0);
            params = MdtContactGetParams(contact);
            MdtContactParamsSetType(params, MdtContactTypeFriction2D);
            MdtContactParamsSetFriction(params, 20);
            MdtContactParamsSetSoftness(params, (MeReal)0.0001);
            MdtContactEnable(contact);
        }

        if (k < 2)
        {
            MeReal t = c->drive_torque;
            MdtBodyAddTorque(c->body[k], t * haxis[0], t * haxis[1], t * haxis[2]);
            MdtBodyAddTorque(c->body[4], -t * haxis[0], -t * haxis[1], -t * haxis[2]);
        }
        else
        {
            MeReal theta = MdtCarWheelGetSteeringAngle(c->wheel_joint[k]);
            MdtCarWheelSetSteeringLimitedForceMotor(c->wheel_joint[k], -5 * theta, 100);
        }
    }
}

Car car;
MeReal lowestWheel = 1;

void MEAPI tick(MeReal step)
{
    int k;

    MeProfileStartSection("Car", 0);
    CarUpdate(&car);
    MeProfileEndSection("Car");
    MdtWorldStep(car.world, step);
    for (k = 0; k < 4; k++)
    {
        MeVector3 p;
        MdtBodyGetPosition(car.body[k], p);
        if (p[2] < lowestWheel)
            lowestWheel = p[2];
    }
}

int MEAPI_CDECL main(int argc, const char *(argv[]))
{
    MdtWorldID world;
    MeMatrix3 R;
    MeVector3 start, p, wheel;
    MeReal step = (MeReal)0.01;
    int i;

    (void)argc;
    (void)argv;

    world = MdtWorldCreate(5, 8, 1, 1);
    MdtWorldSetAutoDisable(world, 0);
    MdtWorldSetGravity(world, 0, 0, -(MeReal)9.8);
    CarInit(&car, world, (MeReal)(WHEEL_RADIUS + 0.15));

    for (i = 0; i < (int)(2 / step); i++)
        tick(step);
    MdtBodyGetPosition(car.body[4], start);
    MdtBodyGetOrientation(car.body[4], R);
    MdtBodyGetPosition(car.body[0], wheel);
    printf("BoxCar at rest: chassis at (%g, %g, %g), rear left wheel at height %g\n",
           (double)start[0], (double)start[1], (double)start[2], (double)wheel[2]);
    compatNear("wheel height at rest (m)", wheel[2], WHEEL_RADIUS, 0.03);
    compatCheck(start[2] > wheel[2], "the chassis stands above its wheels");
    compatCheck(R[2][2] > (MeReal)0.99, "the car stands upright");
    compatCheck(lowestWheel > (MeReal)(0.8 * WHEEL_RADIUS), "no wheel sinks into the ground");

    car.drive_torque = 3;
    for (i = 0; i < (int)(3 / step); i++)
        tick(step);
    MdtBodyGetPosition(car.body[4], p);
    MdtBodyGetOrientation(car.body[4], R);
    printf("BoxCar after 3 s of drive: chassis at (%g, %g, %g)\n", (double)p[0], (double)p[1], (double)p[2]);
    compatCheck(p[0] - start[0] > 1, "the car drives forward (more than 1 m along x in 3 s)");
    compatNear("sideways drift (m)", p[1] - start[1], 0, 0.2);
    compatCheck(R[2][2] > (MeReal)0.95, "the car stays upright");
    compatCheck(lowestWheel > (MeReal)(0.8 * WHEEL_RADIUS), "no wheel sinks into the ground while driving");

    MdtWorldDestroy(world);
    return compatExit("boxcar");
}
