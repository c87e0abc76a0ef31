/* cradle.c -- Newton's cradle: five steel balls hung in a row on hinges, a hair apart, frictionless
 * (more than their contact tolerances, so each impact is its own two-body collision, as the ideal
 * cradle assumes), frictionless and perfectly elastic; the first is lifted and let go. The report gives each ball's speed right
 * after the first impact: momentum and energy pass down the row to the last ball. */
#include <stdlib.h>

#include "demo.h"

#define BALLS 5
#define RADIUS ME_R(0.1)
#define GAP ME_R(0.002)
#define LENGTH ME_R(1.0)
#define LIFT ME_R(0.5) /* rad */

typedef struct Cradle {
    MdtBodyID ball[BALLS];
    MeReal impactSpeed;  /* first ball's top speed before the last ball moves */
    MeReal lastBallPeak; /* largest speed of the last ball in the first swing */
    MeReal firstAfter;   /* first ball's speed when the last reaches its peak */
    MeBool hit;
} Cradle;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 33; /* 33 kg steel balls */
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), -1))
        return MEFALSE;
    Cradle *s = calloc(1, sizeof *s);
    demo->data = s;
    MdtWorldSetAutoDisable(demo->world, MEFALSE);
    MdtContactParamsSetRestitution(MstBridgeGetContactParams(MstUniverseGetBridge(demo->universe), 0, 0), 1);
    McdGeometryID ball = McdSphereCreate(MstUniverseGetFramework(demo->universe), RADIUS);
    for (int i = 0; i < BALLS; i++) {
        MeReal x = (MeReal)i * (2 * RADIUS + GAP);
        MeReal bx = x, by = 2 - LENGTH; /* hung 1 m below hinges 2 m up */
        if (i == 0) {
            bx = x - LENGTH * MeSin(LIFT);
            by = 2 - LENGTH * MeCos(LIFT);
        }
        McdModelID m = DemoAddModel(demo, ball, 7850, bx, by, 0);
        if (!m)
            return MEFALSE;
        McdModelSetSortKey(m, i + 1);
        /* Contacts reported early (within the tolerance) would join the balls into one impact. */
        McdModelSetContactTolerance(m, GAP / 4);
        s->ball[i] = McdModelGetBody(m);
        MdtHingeID j = MdtHingeCreate(demo->world);
        MdtHingeSetBodies(j, s->ball[i], NULL);
        MdtHingeSetPosition(j, x, 2, 0);
        MdtHingeSetAxis(j, 0, 0, 1);
        MdtHingeEnable(j);
        demo->named[i] = s->ball[i];
        demo->names[i] = "ball";
    }
    demo->namedCount = BALLS;
    return METRUE;
}

static void afterStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    Cradle *s = demo->data;
    MeVector3 v0, v4;
    MdtBodyGetLinearVelocity(s->ball[0], v0);
    MdtBodyGetLinearVelocity(s->ball[BALLS - 1], v4);
    if (!s->hit && MeVector3Magnitude(v4) > ME_R(0.01))
        s->hit = METRUE;
    if (!s->hit && MeVector3Magnitude(v0) > s->impactSpeed)
        s->impactSpeed = MeVector3Magnitude(v0);
    else if (demo->time < ME_R(1.5) && MeVector3Magnitude(v4) > s->lastBallPeak) {
        s->lastBallPeak = MeVector3Magnitude(v4);
        s->firstAfter = MeVector3Magnitude(v0);
    }
}

static void report(const DemoInstance *demo, FILE *out)
{
    const Cradle *s = demo->data;
    fprintf(out, "  first ball hits at %.3f m/s; the last ball leaves at up to %.3f m/s (%.1f %%), the first "
                 "keeps %.3f m/s\n",
            (double)s->impactSpeed, (double)s->lastBallPeak, (double)(100 * s->lastBallPeak / s->impactSpeed),
            (double)s->firstAfter);
}

const DemoScene DemoSceneCradle = {"cradle", "Newton's cradle: five hinged balls, the first lifted and let go", 600,
                                   ME_R(1.0) / 60, create, NULL, afterStep, report};
