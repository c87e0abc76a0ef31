/* mdt_scenes.c -- the dynamics benchmark scenes and their quality figures (see mdt_scenes.h). */
#include "mdt_scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static BenchMdtScene *newScene(const char *name, int bodies, int joints, int supports)
{
    BenchMdtScene *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    snprintf(s->name, sizeof s->name, "%s", name);
    s->bodies = calloc((size_t)(bodies > 0 ? bodies : 1), sizeof *s->bodies);
    s->joints = calloc((size_t)(joints > 0 ? joints : 1), sizeof *s->joints);
    s->supports = calloc((size_t)(supports > 0 ? supports : 1), sizeof *s->supports);
    if (!s->bodies || !s->joints || !s->supports) {
        BenchMdtSceneDestroy(s);
        return NULL;
    }
    s->gravity[1] = -9.81; /* y up */
    s->step = 1.0 / 60.0;
    s->friction = 0.6;
    return s;
}

/* Size: a box's half-extents, mass and position, flat, one box to a line in the scene builders. */
static void setBox(BenchMdtBody *b, double hx, double hy, double hz, double mass, double x, double y, double z)
{
    b->half[0] = hx;
    b->half[1] = hy;
    b->half[2] = hz;
    b->mass = mass;
    b->pos[0] = x;
    b->pos[1] = y;
    b->pos[2] = z;
}

/* A ball joint at a world anchor; the local anchors follow from the initial (unrotated) poses. */
/* Size: the joint's slot, its two bodies and its anchor's coordinates, one joint to a line. */
static void setJoint(BenchMdtScene *s, int j, int b0, int b1, double x, double y, double z)
{
    BenchMdtJoint *jt = &s->joints[j];
    const double a[3] = {x, y, z};
    jt->body[0] = b0;
    jt->body[1] = b1;
    for (int k = 0; k < 3; k++) {
        jt->anchor[k] = a[k];
        jt->local[0][k] = a[k] - s->bodies[b0].pos[k];
        jt->local[1][k] = b1 >= 0 ? a[k] - s->bodies[b1].pos[k] : a[k];
    }
}

BenchMdtScene *BenchMdtSceneChain(int links)
{
    if (links < 1)
        return NULL;
    BenchMdtScene *s = newScene("chain", links, links, 0);
    if (!s)
        return NULL;
    snprintf(s->description, sizeof s->description,
             "%d links (1 m, 1 kg) on ball joints falling from horizontal, hung from the world", links);
    s->bodyCount = s->jointCount = links;
    for (int i = 0; i < links; i++) {
        setBox(&s->bodies[i], 0.05, 0.05, 0.5, 1, 0, 0, i + 0.5);
        setJoint(s, i, i, i - 1, 0, 0, i);
    }
    s->steps = 600;
    s->quality = BENCH_MDT_Q_JOINT_GAP;
    s->qualityName = "max joint gap (m)";
    return s;
}

BenchMdtScene *BenchMdtSceneColumn(int boxes)
{
    if (boxes < 1)
        return NULL;
    BenchMdtScene *s = newScene("column", boxes, 0, boxes);
    if (!s)
        return NULL;
    snprintf(s->description, sizeof s->description, "%d unit boxes (1 kg) stacked on the ground", boxes);
    s->bodyCount = s->supportCount = boxes;
    for (int i = 0; i < boxes; i++) {
        setBox(&s->bodies[i], 0.5, 0.5, 0.5, 1, 0, 0.5 + i, 0);
        s->supports[i].upper = i;
        s->supports[i].lower = i - 1;
    }
    s->steps = 1200;
    s->quality = BENCH_MDT_Q_TOP_DRIFT;
    s->qualityName = "top drift (m)";
    return s;
}

BenchMdtScene *BenchMdtSceneWall(int wide, int high)
{
    if (wide < 1 || high < 1)
        return NULL;
    const int n = wide * high;
    BenchMdtScene *s = newScene("wall", n, 0, 2 * n);
    if (!s)
        return NULL;
    snprintf(s->description, sizeof s->description,
             "running-bond wall of %d x %d bricks (1 x 0.5 x 0.5 m, 1 kg), odd rows shifted 0.25 m", wide, high);
    s->bodyCount = n;
    const double hx = 0.25, hy = 0.25, hz = 0.5; /* half depth, height, length: the wall runs along z */
    for (int r = 0; r < high; r++)
        for (int i = 0; i < wide; i++)
            setBox(&s->bodies[r * wide + i], hx, hy, hz, 1, 0, hy + 2 * hy * r, i + (r % 2 ? 0.25 : 0));
    /* Supports: the ground for row 0, else every brick of the row below that the brick overlaps. */
    int m = 0;
    for (int r = 0; r < high; r++)
        for (int i = 0; i < wide; i++) {
            const int b = r * wide + i;
            if (r == 0) {
                s->supports[m].upper = b;
                s->supports[m++].lower = -1;
                continue;
            }
            for (int j = 0; j < wide; j++) {
                const int c = (r - 1) * wide + j;
                double lo = fmax(s->bodies[b].pos[2] - hz, s->bodies[c].pos[2] - hz);
                double hi = fmin(s->bodies[b].pos[2] + hz, s->bodies[c].pos[2] + hz);
                if (hi - lo > 1e-9) {
                    s->supports[m].upper = b;
                    s->supports[m++].lower = c;
                }
            }
        }
    s->supportCount = m;
    s->steps = 600;
    s->quality = BENCH_MDT_Q_MAX_DRIFT;
    s->qualityName = "max drift (m)";
    return s;
}

BenchMdtScene *BenchMdtSceneCreate(const char *name)
{
    if (!strcmp(name, "chain"))
        return BenchMdtSceneChain(100);
    if (!strcmp(name, "column"))
        return BenchMdtSceneColumn(20);
    if (!strcmp(name, "wall"))
        return BenchMdtSceneWall(20, 10);
    return NULL;
}

void BenchMdtSceneDestroy(BenchMdtScene *s)
{
    if (!s)
        return;
    free(s->bodies);
    free(s->joints);
    free(s->supports);
    free(s);
}

/* ---- quality ------------------------------------------------------------------------------ */
static void rotate(double out[3], const double q[4], const double v[3])
{
    /* out = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z) */
    const double u[3] = {q[1], q[2], q[3]};
    double t[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (int k = 0; k < 3; k++)
        t[k] *= 2;
    out[0] = v[0] + q[0] * t[0] + (u[1] * t[2] - u[2] * t[1]);
    out[1] = v[1] + q[0] * t[1] + (u[2] * t[0] - u[0] * t[2]);
    out[2] = v[2] + q[0] * t[2] + (u[0] * t[1] - u[1] * t[0]);
}

static double jointGap(const BenchMdtScene *s, const double (*pos)[3], const double (*quat)[4])
{
    double worst = 0;
    for (int j = 0; j < s->jointCount; j++) {
        const BenchMdtJoint *jt = &s->joints[j];
        double p[2][3];
        for (int h = 0; h < 2; h++) {
            int b = jt->body[h];
            if (b < 0) {
                memcpy(p[h], jt->local[h], sizeof p[h]);
                continue;
            }
            rotate(p[h], quat[b], jt->local[h]);
            for (int k = 0; k < 3; k++)
                p[h][k] += pos[b][k];
        }
        double d = sqrt((p[0][0] - p[1][0]) * (p[0][0] - p[1][0]) + (p[0][1] - p[1][1]) * (p[0][1] - p[1][1]) +
                        (p[0][2] - p[1][2]) * (p[0][2] - p[1][2]));
        worst = d > worst || d != d ? d : worst;
    }
    return worst;
}

static double drift(const BenchMdtScene *s, const double (*pos)[3], int b)
{
    const double *p0 = s->bodies[b].pos;
    return sqrt((pos[b][0] - p0[0]) * (pos[b][0] - p0[0]) + (pos[b][1] - p0[1]) * (pos[b][1] - p0[1]) +
                (pos[b][2] - p0[2]) * (pos[b][2] - p0[2]));
}

void BenchMdtQualityInit(const BenchMdtScene *scene, BenchMdtQualityState *q)
{
    (void)scene;
    q->value = 0;
    q->nonFinite = 0;
}

void BenchMdtQualityObserve(const BenchMdtScene *s, BenchMdtQualityState *q, const double (*pos)[3],
                            const double (*quat)[4])
{
    for (int b = 0; b < s->bodyCount; b++)
        for (int k = 0; k < 3; k++)
            q->nonFinite |= !isfinite(pos[b][k]);
    if (s->quality == BENCH_MDT_Q_JOINT_GAP)
        q->value = fmax(q->value, jointGap(s, pos, quat));
}

void BenchMdtQualityFinish(const BenchMdtScene *s, BenchMdtQualityState *q, const double (*pos)[3],
                           const double (*quat)[4])
{
    (void)quat;
    if (s->quality == BENCH_MDT_Q_TOP_DRIFT)
        q->value = drift(s, pos, s->bodyCount - 1);
    else if (s->quality == BENCH_MDT_Q_MAX_DRIFT)
        for (int b = 0; b < s->bodyCount; b++)
            q->value = fmax(q->value, drift(s, pos, b));
    if (q->nonFinite)
        q->value = NAN;
}
