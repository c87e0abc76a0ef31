/* prismatic.c -- a cart on a prismatic rail driven back and forth by its motor between two hard
 * stops, and a lift: a platform on a vertical prismatic joint, pushed up by its motor, carrying a box
 * that rests on it through contacts. */
#include <stdlib.h>

#include "demo.h"

#define RAIL_STOP ME_R(2.0)
#define LIFT_TOP ME_R(1.5)

typedef struct PrismaticDemo {
    MdtPrismaticID rail, lift;
    MdtBodyID cargo;
    MeReal cartMin, cartMax;
} PrismaticDemo;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 20;
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    PrismaticDemo *s = calloc(1, sizeof *s);
    demo->data = s;
    MdtWorldSetAutoDisable(demo->world, MEFALSE);
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    McdModelID cart = DemoAddModel(demo, McdBoxCreate(fw, ME_R(0.6), ME_R(0.3), ME_R(0.4)), 200, 0, 1, 2);
    if (!cart)
        return MEFALSE;
    s->rail = MdtPrismaticCreate(demo->world);
    MdtPrismaticSetBodies(s->rail, McdModelGetBody(cart), NULL);
    MdtPrismaticSetAxis(s->rail, 1, 0, 0);
    MdtLimitID l = MdtPrismaticGetLimit(s->rail);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(l), -RAIL_STOP);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(l), RAIL_STOP);
    MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(l), ME_R(0.5));
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(l), ME_R(0.5));
    MdtLimitActivateLimits(l, METRUE);
    MdtPrismaticEnable(s->rail);
    /* The lift: a 1 × 0.1 × 1 m platform on a vertical axis (y), its cargo a box resting on it. */
    McdModelID platform = DemoAddModel(demo, McdBoxCreate(fw, 1, ME_R(0.1), 1), 500, 0, ME_R(0.3), -2);
    McdModelID cargo = DemoAddModel(demo, McdBoxCreate(fw, ME_R(0.4), ME_R(0.4), ME_R(0.4)), 300, 0, ME_R(0.55), -2);
    if (!platform || !cargo)
        return MEFALSE;
    s->cargo = McdModelGetBody(cargo);
    s->lift = MdtPrismaticCreate(demo->world);
    MdtPrismaticSetBodies(s->lift, McdModelGetBody(platform), NULL);
    MdtPrismaticSetAxis(s->lift, 0, 1, 0);
    MdtLimitID ll = MdtPrismaticGetLimit(s->lift);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(ll), 0);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(ll), LIFT_TOP);
    MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(ll), 0);
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(ll), 0);
    MdtLimitActivateLimits(ll, METRUE);
    MdtLimitSetLimitedForceMotor(ll, ME_R(0.5), 2000);
    MdtPrismaticEnable(s->lift);
    demo->named[0] = McdModelGetBody(cart);
    demo->names[0] = "cart";
    demo->named[1] = McdModelGetBody(platform);
    demo->names[1] = "platform";
    demo->named[2] = s->cargo;
    demo->names[2] = "cargo";
    demo->namedCount = 3;
    return METRUE;
}

static void beforeStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    PrismaticDemo *s = demo->data;
    int phase = (int)(demo->time / ME_R(3.0));
    MdtLimitSetLimitedForceMotor(MdtPrismaticGetLimit(s->rail), phase % 2 ? -3 : 3, 400);
}

static void afterStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    PrismaticDemo *s = demo->data;
    MeReal x = MdtLimitGetPosition(MdtPrismaticGetLimit(s->rail));
    if (x < s->cartMin)
        s->cartMin = x;
    if (x > s->cartMax)
        s->cartMax = x;
}

static void report(const DemoInstance *demo, FILE *out)
{
    const PrismaticDemo *s = demo->data;
    MeVector3 p;
    MdtBodyGetPosition(s->cargo, p);
    fprintf(out, "  cart stayed in [%.4f, %.4f] m (stops at ±%.1f)\n", (double)s->cartMin, (double)s->cartMax,
            (double)RAIL_STOP);
    fprintf(out, "  lift at %.4f m (top stop %.1f); cargo resting on it at height %.3f m\n",
            (double)MdtLimitGetPosition(MdtPrismaticGetLimit(s->lift)), (double)LIFT_TOP, (double)p[1]);
}

const DemoScene DemoScenePrismatic = {"prismatic", "a motor-driven cart between hard stops; a lift carrying a box",
                                      600, ME_R(1.0) / 60, create, beforeStep, afterStep, report};
