/* hinge.c -- hinges with limits and motors: a door swung by its motor against hard stops at ±90°
 * (bouncing with restitution 0.3), and a paddle wheel driven at 3 rad/s by a motor whose torque cap
 * is too small to lift a weight hung on it, so it stalls at the cap. */
#include <stdlib.h>

#include "demo.h"

#define DOOR_STOP ME_R(1.5707963)
#define PADDLE_SPEED ME_R(3.0)
#define PADDLE_TORQUE ME_R(40.0) /* N·m: the weight needs 20 kg · 9.81 · 0.4 m = 78.5 N·m */

typedef struct HingeDemo {
    MdtHingeID door, paddle;
    MeReal doorMin, doorMax, paddleSpeedMax, paddleTorque;
} HingeDemo;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 20;
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    HingeDemo *s = calloc(1, sizeof *s);
    demo->data = s;
    MdtWorldSetAutoDisable(demo->world, MEFALSE);
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    /* The door: 1 m wide, 2 m high (y), hinged at its left edge about y, above the ground. */
    McdModelID door = DemoAddModel(demo, McdBoxCreate(fw, 1, 2, ME_R(0.05)), 400, ME_R(0.5), ME_R(1.05), 0);
    if (!door)
        return MEFALSE;
    s->door = MdtHingeCreate(demo->world);
    MdtHingeSetBodies(s->door, McdModelGetBody(door), NULL);
    MdtHingeSetPosition(s->door, 0, ME_R(1.05), 0);
    MdtHingeSetAxis(s->door, 0, 1, 0);
    MdtLimitID l = MdtHingeGetLimit(s->door);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(l), -DOOR_STOP);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(l), DOOR_STOP);
    MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(l), ME_R(0.3));
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(l), ME_R(0.3));
    MdtLimitActivateLimits(l, METRUE);
    MdtLimitSetLimitedForceMotor(l, 2, 200);
    MdtHingeEnable(s->door);
    /* The paddle: a bar on a horizontal axle (along z) at (4, 2, 0), a 20 kg weight bolted 0.4 m out. */
    McdModelID paddle = DemoAddModel(demo, McdBoxCreate(fw, ME_R(0.8), ME_R(0.1), ME_R(0.1)), 250, ME_R(4.4), 2, 0);
    if (!paddle)
        return MEFALSE;
    MdtBodyID pb = McdModelGetBody(paddle);
    MdtBodySetMass(pb, 20);
    MeVector3 com = {ME_R(0.0), 0, 0};
    MdtBodySetCenterOfMassRelativePosition(pb, com);
    s->paddle = MdtHingeCreate(demo->world);
    MdtHingeSetBodies(s->paddle, pb, NULL);
    MdtHingeSetPosition(s->paddle, 4, 2, 0);
    MdtHingeSetAxis(s->paddle, 0, 0, 1);
    MdtLimitSetLimitedForceMotor(MdtHingeGetLimit(s->paddle), PADDLE_SPEED, PADDLE_TORQUE);
    MdtHingeEnable(s->paddle);
    demo->named[0] = McdModelGetBody(door);
    demo->names[0] = "door";
    demo->named[1] = pb;
    demo->names[1] = "paddle";
    demo->namedCount = 2;
    return METRUE;
}

static void beforeStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    HingeDemo *s = demo->data;
    /* Reverse the door's motor every 2.5 s. */
    int phase = (int)(demo->time / ME_R(2.5));
    MdtLimitSetLimitedForceMotor(MdtHingeGetLimit(s->door), phase % 2 ? -2 : 2, 200);
}

static void afterStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    HingeDemo *s = demo->data;
    MeReal a = MdtLimitGetPosition(MdtHingeGetLimit(s->door));
    if (a < s->doorMin)
        s->doorMin = a;
    if (a > s->doorMax)
        s->doorMax = a;
    MeReal w = MdtLimitGetVelocity(MdtHingeGetLimit(s->paddle));
    if (w > s->paddleSpeedMax)
        s->paddleSpeedMax = w;
    MeVector3 t;
    MdtHingeGetTorque(s->paddle, 0, t);
    s->paddleTorque = MeFabs(t[1]);
}

static void report(const DemoInstance *demo, FILE *out)
{
    const HingeDemo *s = demo->data;
    fprintf(out, "  door angle stayed in [%.4f, %.4f] rad (stops at ±%.4f)\n", (double)s->doorMin,
            (double)s->doorMax, (double)DOOR_STOP);
    fprintf(out, "  paddle: top speed %.3f rad/s (motor target %.1f), axle torque now %.2f N·m (cap %.1f): it "
                 "cannot lift the weight over\n",
            (double)s->paddleSpeedMax, (double)PADDLE_SPEED, (double)s->paddleTorque, (double)PADDLE_TORQUE);
}

const DemoScene DemoSceneHinge = {"hinge", "a motor-driven door against hard stops; a paddle whose motor stalls", 600,
                                  ME_R(1.0) / 60, create, beforeStep, afterStep, report};
