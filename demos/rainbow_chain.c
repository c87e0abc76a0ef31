/* rainbow_chain.c -- a chain of twenty balls linked by ball and socket joints, its first ball held
 * up by a joint to the world, released horizontal: it swings down and drapes onto the ground. */
#include <stdlib.h>

#include "demo.h"

#define LINKS 20
#define RADIUS ME_R(0.15)
#define SPACING ME_R(0.32)

typedef struct Chain {
    MdtBodyID ball[LINKS];
    MdtBSJointID joint[LINKS];
    MeReal worstGap;
} Chain;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 14; /* 14 kg balls */
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    Chain *s = calloc(1, sizeof *s);
    demo->data = s;
    McdGeometryID ball = McdSphereCreate(MstUniverseGetFramework(demo->universe), RADIUS);
    MdtBodyID previous = NULL;
    McdModelID previousModel = NULL;
    for (int i = 0; i < LINKS; i++) {
        MeReal x = (MeReal)i * SPACING;
        McdModelID m = DemoAddModel(demo, ball, 1000, x, 4, 0);
        if (!m)
            return MEFALSE;
        McdModelSetSortKey(m, i + 1);
        s->ball[i] = McdModelGetBody(m);
        s->joint[i] = MdtBSJointCreate(demo->world);
        MdtBSJointSetBodies(s->joint[i], s->ball[i], previous);
        MdtBSJointSetPosition(s->joint[i], x - SPACING / 2 * (i > 0), 4, 0);
        MdtBSJointEnable(s->joint[i]);
        /* Neighbours touch along the chain: leave their collisions to the joints. */
        if (previousModel)
            DemoDisablePair(demo, m, previousModel);
        previous = s->ball[i];
        previousModel = m;
    }
    demo->named[0] = s->ball[LINKS - 1];
    demo->names[0] = "free end";
    demo->namedCount = 1;
    return METRUE;
}

static void afterStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    Chain *s = demo->data;
    for (int i = 1; i < LINKS; i++) {
        MeVector3 a, b;
        MdtConstraintBodyGetPosition(MdtBSJointQuaConstraint(s->joint[i]), 0, a);
        MdtConstraintBodyGetPosition(MdtBSJointQuaConstraint(s->joint[i]), 1, b);
        MeReal gap = MeVector3Distance(a, b);
        if (gap > s->worstGap)
            s->worstGap = gap;
    }
}

static void report(const DemoInstance *demo, FILE *out)
{
    const Chain *s = demo->data;
    fprintf(out, "  %d links; largest joint separation during the run %.2e m (%.3f %% of a link)\n", LINKS,
            (double)s->worstGap, (double)(100 * s->worstGap / SPACING));
}

const DemoScene DemoSceneRainbowChain = {"rainbowchain", "a chain of twenty balls swings down onto the ground", 600,
                                         ME_R(1.0) / 60, create, NULL, afterStep, report};
