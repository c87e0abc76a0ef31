/* many_pendulums.c -- a pendulum wave: twelve balls sharing one sphere geometry, each on a ball and
 * socket joint to the world, with lengths chosen so that in 30 s the pendulums make 20, 21, ... 31
 * swings. Released together, they drift in and out of phase; the report compares each period with
 * the small-angle 2π√(L/g). */
#include <math.h>
#include <stdlib.h>

#include "demo.h"

#define COUNT 12
#define G ME_R(9.81)
#define CYCLE ME_R(30.0)   /* seconds for the whole pattern to repeat */
#define FIRST_SWINGS 20
#define AMPLITUDE ME_R(0.12) /* rad */

typedef struct Pendulums {
    MdtBodyID bob[COUNT];
    MeReal length[COUNT];
    MeReal lastX[COUNT];
    int crossings[COUNT];
    MeReal firstCrossing[COUNT], lastCrossing[COUNT];
} Pendulums;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 4; /* 4 kg balls */
    if (!DemoUniverseCreate(demo, &sizes, G, -1))
        return MEFALSE;
    Pendulums *s = calloc(1, sizeof *s);
    demo->data = s;
    MdtWorldSetAutoDisable(demo->world, MEFALSE);
    McdGeometryID ball = McdSphereCreate(MstUniverseGetFramework(demo->universe), ME_R(0.1));
    for (int i = 0; i < COUNT; i++) {
        MeReal period = CYCLE / (MeReal)(FIRST_SWINGS + i);
        MeReal L = G * period * period / (4 * ME_PI * ME_PI);
        MeReal z = (MeReal)i * ME_R(0.25); /* side by side along z; pivots 3 m up */
        McdModelID m = DemoAddModel(demo, ball, 955, L * MeSin(AMPLITUDE), 3 - L * MeCos(AMPLITUDE), z);
        if (!m)
            return MEFALSE;
        MdtBodyID b = McdModelGetBody(m);
        MdtBSJointID j = MdtBSJointCreate(demo->world);
        MdtBSJointSetBodies(j, b, NULL);
        MdtBSJointSetPosition(j, 0, 3, z);
        MdtBSJointEnable(j);
        s->bob[i] = b;
        s->length[i] = L;
        s->lastX[i] = L * MeSin(AMPLITUDE);
        if (i < DEMO_MAX_NAMED_BODIES) {
            demo->named[demo->namedCount] = b;
            demo->names[demo->namedCount++] = "bob";
        }
    }
    return METRUE;
}

static void afterStep(DemoInstance *demo, MeReal h)
{
    Pendulums *s = demo->data;
    for (int i = 0; i < COUNT; i++) {
        MeVector3 p;
        MdtBodyGetPosition(s->bob[i], p);
        if ((s->lastX[i] > 0) != (p[0] > 0)) {
            MeReal t = demo->time - h * p[0] / (p[0] - s->lastX[i]);
            if (s->crossings[i] == 0)
                s->firstCrossing[i] = t;
            s->lastCrossing[i] = t;
            s->crossings[i]++;
        }
        s->lastX[i] = p[0];
    }
}

static void report(const DemoInstance *demo, FILE *out)
{
    const Pendulums *s = demo->data;
    for (int i = 0; i < COUNT; i++) {
        if (s->crossings[i] < 3)
            continue;
        MeReal measured = 2 * (s->lastCrossing[i] - s->firstCrossing[i]) / (MeReal)(s->crossings[i] - 1);
        /* Small-angle period, corrected for the amplitude and the ball's own inertia (2/5 r²). */
        double L = (double)s->length[i], r = 0.1;
        double expected = 2 * 3.14159265358979 * sqrt((L * L + 0.4 * r * r) / (9.81 * L)) *
                          (1 + (double)(AMPLITUDE * AMPLITUDE) / 16);
        fprintf(out, "  L = %.4f m: period %.4f s, pendulum theory %.4f s (%+.2f %%)\n", L, (double)measured,
                expected, 100 * ((double)measured / expected - 1));
    }
}

const DemoScene DemoSceneManyPendulums = {"manypendulums", "a pendulum wave of twelve ball-and-socket pendulums",
                                          1800, ME_R(1.0) / 60, create, NULL, afterStep, report};
