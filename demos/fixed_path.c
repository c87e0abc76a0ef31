/* fixed_path.c -- a pendulum whose pivot is carried round a circle by a fixed path joint (the
 * application sets the anchor's position and velocity every step), as in Karma's FixedPath example.
 * Driven near its natural frequency, the swing grows; the report shows the rod length held. */
#include <stdlib.h>

#include "demo.h"

#define LENGTH ME_R(1.0)
#define RADIUS ME_R(0.15)   /* of the pivot's circle */
#define OMEGA ME_R(2.8)     /* rad/s; the pendulum's own is √(g/L) = 3.13 */

typedef struct FixedPathDemo {
    MdtFixedPathID path;
    MdtBodyID bob;
    MeReal worstLengthError, widestSwing;
} FixedPathDemo;

static void pivotAt(MeReal t, MeVector3 p, MeVector3 v)
{
    MeVector3Set(p, RADIUS * MeCos(OMEGA * t), 2, -RADIUS * MeSin(OMEGA * t)); /* a horizontal circle 2 m up */
    MeVector3Set(v, -RADIUS * OMEGA * MeSin(OMEGA * t), 0, -RADIUS * OMEGA * MeCos(OMEGA * t));
}

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 4;
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    FixedPathDemo *s = calloc(1, sizeof *s);
    demo->data = s;
    MdtWorldSetAutoDisable(demo->world, MEFALSE);
    McdModelID m = DemoAddModel(demo, McdSphereCreate(MstUniverseGetFramework(demo->universe), ME_R(0.1)), 955,
                                RADIUS, 2 - LENGTH, 0);
    if (!m)
        return MEFALSE;
    s->bob = McdModelGetBody(m);
    s->path = MdtFixedPathCreate(demo->world);
    MdtConstraintSetBodies(MdtFixedPathQuaConstraint(s->path), s->bob, NULL);
    MdtFixedPathSetPosition(s->path, 0, RADIUS, 2, 0); /* world point now: the rod's top on the bob */
    MeVector3 p, v;
    pivotAt(0, p, v);
    MdtFixedPathSetPosition(s->path, 1, p[0], p[1], p[2]);
    MdtFixedPathSetVelocity(s->path, 1, v[0], v[1], v[2]);
    MdtConstraintEnable(MdtFixedPathQuaConstraint(s->path));
    demo->named[0] = s->bob;
    demo->names[0] = "bob";
    demo->namedCount = 1;
    return METRUE;
}

static void beforeStep(DemoInstance *demo, MeReal h)
{
    FixedPathDemo *s = demo->data;
    MeVector3 p, v;
    pivotAt(demo->time + h, p, v); /* where the anchor must be at the end of the step */
    MdtFixedPathSetPosition(s->path, 1, p[0], p[1], p[2]);
    MdtFixedPathSetVelocity(s->path, 1, v[0], v[1], v[2]);
}

static void afterStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    FixedPathDemo *s = demo->data;
    MeVector3 p, v, b;
    pivotAt(demo->time, p, v);
    MdtBodyGetPosition(s->bob, b);
    MeReal r = MeVector3Distance(p, b);
    if (MeFabs(r - LENGTH) > s->worstLengthError)
        s->worstLengthError = MeFabs(r - LENGTH);
    MeReal swing = MeSqrt((b[0] - p[0]) * (b[0] - p[0]) + (b[2] - p[2]) * (b[2] - p[2])); /* horizontal */
    if (swing > s->widestSwing)
        s->widestSwing = swing;
}

static void report(const DemoInstance *demo, FILE *out)
{
    const FixedPathDemo *s = demo->data;
    fprintf(out, "  pivot on a %.2f m circle at %.1f rad/s; the bob swung out to %.3f m from below the pivot\n",
            (double)RADIUS, (double)OMEGA, (double)s->widestSwing);
    fprintf(out, "  rod length held to %.2e m (%.3f %%)\n", (double)s->worstLengthError,
            (double)(100 * s->worstLengthError / LENGTH));
}

const DemoScene DemoSceneFixedPath = {"fixedpath", "a pendulum whose pivot is driven round a circle", 600,
                                      ME_R(1.0) / 60, create, beforeStep, afterStep, report};
