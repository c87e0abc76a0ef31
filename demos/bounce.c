/* bounce.c -- a ball dropped on the ground bounces with the restitution of its material; each
 * apex is e² of the one before. */
#include <stdlib.h>

#include "demo.h"

#define RESTITUTION ME_R(0.8)
#define DROP_HEIGHT ME_R(3.0)
#define MAX_APEXES 8

typedef struct Bounce {
    MeReal lastY, lastVy; /* height and vertical speed (y is up) */
    int apexCount;
    MeReal apex[MAX_APEXES];
} Bounce;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 65; /* typical body mass, kg: the world's softness scales with it */
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), 0))
        return MEFALSE;
    Bounce *s = calloc(1, sizeof *s);
    demo->data = s;
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(demo->universe), 0, 0);
    MdtContactParamsSetRestitution(p, RESTITUTION);
    McdModelID ball = DemoAddModel(demo, McdSphereCreate(fw, 0.25f), 1000, 0, DROP_HEIGHT + ME_R(0.25), 0);
    if (!ball)
        return MEFALSE;
    demo->named[0] = McdModelGetBody(ball);
    demo->names[0] = "ball";
    demo->namedCount = 1;
    MdtWorldSetAutoDisable(demo->world, MEFALSE);
    s->lastY = DROP_HEIGHT;
    return METRUE;
}

static void afterStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    Bounce *s = demo->data;
    MeVector3 p, v;
    MdtBodyGetPosition(demo->named[0], p);
    MdtBodyGetLinearVelocity(demo->named[0], v);
    if (s->lastVy > 0 && v[1] <= 0 && s->apexCount < MAX_APEXES)
        s->apex[s->apexCount++] = p[1] - ME_R(0.25);
    s->lastVy = v[1];
}

static void report(const DemoInstance *demo, FILE *out)
{
    const Bounce *s = demo->data;
    MeReal previous = DROP_HEIGHT;
    for (int i = 0; i < s->apexCount; i++) {
        fprintf(out, "  apex %d: %.3f m, ratio %.3f (e^2 = %.3f)\n", i + 1, (double)s->apex[i],
                (double)(s->apex[i] / previous), (double)(RESTITUTION * RESTITUTION));
        previous = s->apex[i];
    }
}

const DemoScene DemoSceneBounce = {"bounce", "a ball bounces on the ground; each apex is e^2 of the last", 600,
                                   ME_R(1.0) / 60, create, NULL, afterStep, report};
