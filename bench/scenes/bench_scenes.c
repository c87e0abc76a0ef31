/* bench_scenes.c -- builders for the benchmark scenes and the quality figures they report.
 *
 * y is up (docs/decisions.md K30). The scenes were first written z-up; each is that scene with its
 * axes relabelled, (x, y, z) -> (y, z, x) (bench/scenes/README.md): heights moved from z to y, the
 * old x to z and the old y to x, and box half-extents are permuted alike. The peers choose friction
 * directions from the normal's components in a cyclic pattern, so this relabelling keeps their
 * choices too; a turn about x would not (the figures moved, see the README).
 *
 * Everything an engine needs to build a scene is in the BenchScene data; everything a scene reports
 * is computed here from body poses, so Karma, ODE and Bullet are measured by the same code. */
#include "bench_scenes.h"
#include "bench_scenes_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double kPi = 3.14159265358979323846;

/* ---- quaternions (w, x, y, z) ----------------------------------------------------------------- */

void BenchQuatMultiply(double out[4], const double q[4], const double p[4])
{
    double r[4];
    r[0] = q[0] * p[0] - q[1] * p[1] - q[2] * p[2] - q[3] * p[3];
    r[1] = q[0] * p[1] + q[1] * p[0] + q[2] * p[3] - q[3] * p[2];
    r[2] = q[0] * p[2] - q[1] * p[3] + q[2] * p[0] + q[3] * p[1];
    r[3] = q[0] * p[3] + q[1] * p[2] - q[2] * p[1] + q[3] * p[0];
    memcpy(out, r, sizeof r);
}

void BenchQuatRotate(double out[3], const double q[4], const double v[3])
{
    /* v + 2w (u × v) + 2 u × (u × v), u = vector part */
    const double *u = q + 1;
    double t[3] = {2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]),
                   2 * (u[0] * v[1] - u[1] * v[0])};
    double r[3] = {v[0] + q[0] * t[0] + (u[1] * t[2] - u[2] * t[1]),
                   v[1] + q[0] * t[1] + (u[2] * t[0] - u[0] * t[2]),
                   v[2] + q[0] * t[2] + (u[0] * t[1] - u[1] * t[0])};
    memcpy(out, r, sizeof r);
}

void BenchQuatRotateInverse(double out[3], const double q[4], const double v[3])
{
    const double c[4] = {q[0], -q[1], -q[2], -q[3]};
    BenchQuatRotate(out, c, v);
}

void BenchQuatFromAxisAngle(double out[4], const double axis[3], double angle)
{
    double s = sin(0.5 * angle);
    out[0] = cos(0.5 * angle);
    out[1] = axis[0] * s;
    out[2] = axis[1] * s;
    out[3] = axis[2] * s;
}

/* ---- mass properties ---------------------------------------------------------------------------- */

void BenchBodyInertia(const BenchBody *b, double inertia[3])
{
    double m = b->mass, r = b->size[0];
    switch (b->shape) {
    case BENCH_SPHERE:
        inertia[0] = inertia[1] = inertia[2] = 0.4 * m * r * r;
        break;
    case BENCH_CAPSULE: {
        /* cylinder of length 2h plus two hemispheres; a hemisphere's centroid is 3r/8 from its flat
         * face, so the pair contributes ms (2r²/5 + h² + 3hr/4) about a transverse axis */
        double h = b->size[1];
        double cyl = kPi * r * r * 2 * h, caps = 4.0 / 3.0 * kPi * r * r * r;
        double mc = m * cyl / (cyl + caps), ms = m * caps / (cyl + caps);
        inertia[0] = inertia[1] = mc * (r * r / 4 + h * h / 3) + ms * (0.4 * r * r + h * h + 0.75 * h * r);
        inertia[2] = mc * r * r / 2 + ms * 0.4 * r * r;
        break;
    }
    case BENCH_BOX:
    default: {
        const double *e = b->size; /* half-extents */
        inertia[0] = m * (e[1] * e[1] + e[2] * e[2]) / 3;
        inertia[1] = m * (e[0] * e[0] + e[2] * e[2]) / 3;
        inertia[2] = m * (e[0] * e[0] + e[1] * e[1]) / 3;
        break;
    }
    }
}

/* ---- building ---------------------------------------------------------------------------------- */

const double kIdentity[4] = {1, 0, 0, 0};
const double kAxisY[3] = {0, 1, 0};
const double kAxisZ[3] = {0, 0, 1};
/* A standing capsule: its local z axis turned onto world y (-90 degrees about x). */
static const double kStandUp[4] = {0.70710678118654752440, -0.70710678118654752440, 0, 0};

/* A new scene called `prefix` when count == standard (the scene of issue 5), else prefix + count. */
BenchScene *scene_new(const char *prefix, int count, int standard, int maxBodies, int maxJoints)
{
    BenchScene *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->bodies = calloc((size_t)(maxBodies > 0 ? maxBodies : 1), sizeof *s->bodies);
    s->joints = calloc((size_t)(maxJoints > 0 ? maxJoints : 1), sizeof *s->joints);
    if (!s->bodies || !s->joints) {
        BenchSceneDestroy(s);
        return NULL;
    }
    if (count == standard)
        snprintf(s->name, sizeof s->name, "%s", prefix);
    else
        snprintf(s->name, sizeof s->name, "%s%d", prefix, count);
    s->hasGround = 1;
    s->gravity[1] = BENCH_GRAVITY_Y;
    s->step = BENCH_STEP;
    s->friction = BENCH_FRICTION;
    s->steps = 600;
    s->fallDistance = -1;
    return s;
}

/* Size: a body's fields, flat, as the scene builders write them one body to a line. */
int add_body(BenchScene *s, BenchShape shape, double a, double b, double c, double mass,
                    const double pos[3], const double quat[4], int fixed)
{
    BenchBody *body = &s->bodies[s->bodyCount];
    body->shape = shape;
    body->size[0] = a;
    body->size[1] = b;
    body->size[2] = c;
    body->mass = mass;
    memcpy(body->pos, pos, sizeof body->pos);
    memcpy(body->quat, quat, sizeof body->quat);
    body->fixed = fixed;
    return s->bodyCount++;
}

/* Size: a joint's fields, flat, as the scene builders write them one joint to a line. */
void add_joint(BenchScene *s, BenchJointType type, int b0, int b1, const double anchor[3],
                      const double axis[3], double lo, double hi)
{
    BenchJoint *j = &s->joints[s->jointCount++];
    j->type = type;
    j->body[0] = b0;
    j->body[1] = b1;
    memcpy(j->anchor, anchor, sizeof j->anchor);
    if (axis)
        memcpy(j->axis, axis, sizeof j->axis);
    j->limited = type == BENCH_HINGE && lo <= hi;
    j->lo = lo;
    j->hi = hi;
}

/* Local anchors from the initial poses, and the dynamic body count. */
void scene_finish(BenchScene *s)
{
    s->dynamicCount = 0;
    for (int i = 0; i < s->bodyCount; i++)
        s->dynamicCount += !s->bodies[i].fixed;
    for (int k = 0; k < s->jointCount; k++) {
        BenchJoint *j = &s->joints[k];
        for (int side = 0; side < 2; side++) {
            if (j->body[side] < 0) {
                memcpy(j->local[side], j->anchor, sizeof j->local[side]);
                continue;
            }
            const BenchBody *b = &s->bodies[j->body[side]];
            double d[3] = {j->anchor[0] - b->pos[0], j->anchor[1] - b->pos[1], j->anchor[2] - b->pos[2]};
            BenchQuatRotateInverse(j->local[side], b->quat, d);
        }
    }
}

/* Deterministic jitter: a 64-bit LCG (Knuth's MMIX constants), uniform in [-1, 1). */
double jitter(unsigned long long *state)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 4503599627370496.0 - 1.0; /* 2^52: 53 bits → [0, 2) */
}

BenchScene *BenchScenePyramid(int base)
{
    if (base < 1)
        return NULL;
    int count = base * (base + 1) / 2;
    BenchScene *s = scene_new("pyramid", base, -1, count, 0);
    if (!s)
        return NULL;
    const double pitch = 1.05; /* unit boxes with 0.05 m gaps between neighbours of a row */
    for (int row = 0; row < base; row++) { /* rows along z, one box deep along x */
        int n = base - row;
        for (int i = 0; i < n; i++) {
            double p[3] = {0, 0.5 + row, (i - 0.5 * (n - 1)) * pitch};
            add_body(s, BENCH_BOX, 0.5, 0.5, 0.5, 1.0, p, kIdentity, 0);
        }
    }
    snprintf(s->description, sizeof s->description,
             "2-D pyramid of %d unit boxes (base %d), one box deep, resting on the ground for 10 s", count,
             base);
    s->quality = BENCH_Q_MAX_DRIFT;
    s->qualityName = "max_drift_m";
    s->fallDistance = BENCH_FALL_DISTANCE;
    scene_finish(s);
    return s;
}

BenchScene *BenchScenePile(int spheres, int boxes)
{
    if (spheres < 0 || boxes < 0 || spheres + boxes < 1)
        return NULL;
    int count = spheres + boxes;
    BenchScene *s = scene_new("pile", spheres == boxes ? spheres : count, 500, count + 4, 0);
    if (!s)
        return NULL;
    /* Container: inner 16 m x 16 m (x and z), walls 1 m thick and 12 m high standing on the ground:
     * the walls across z first, then those across x. */
    const double inner = 8.0, wallHalfHeight = 6.0;
    const double wz[3] = {0, wallHalfHeight, inner + 0.5}, wx[3] = {inner + 0.5, wallHalfHeight, 0};
    const double wzn[3] = {0, wallHalfHeight, -wz[2]}, wxn[3] = {-wx[0], wallHalfHeight, 0};
    add_body(s, BENCH_BOX, inner + 1.0, wallHalfHeight, 0.5, 0, wz, kIdentity, 1);
    add_body(s, BENCH_BOX, inner + 1.0, wallHalfHeight, 0.5, 0, wzn, kIdentity, 1);
    add_body(s, BENCH_BOX, 0.5, wallHalfHeight, inner, 0, wx, kIdentity, 1);
    add_body(s, BENCH_BOX, 0.5, wallHalfHeight, inner, 0, wxn, kIdentity, 1);
    /* Bodies on a 12 x 12 grid per layer (z, x), 1.3 m apart, jittered by ±0.02 m; boxes turned by
     * up to ±0.25 rad about y (their footprint then stays under 1.22 m: no initial overlap). Spheres
     * and boxes alternate while both remain. The jitter is drawn in the order z, x, height. */
    const int side = 12;
    const double pitch = 1.3;
    unsigned long long rng = 5;
    int madeSpheres = 0, madeBoxes = 0;
    for (int i = 0; i < count; i++) {
        int layer = i / (side * side), j = i % (side * side);
        double z = ((j % side) - 0.5 * (side - 1)) * pitch + 0.02 * jitter(&rng);
        double x = ((j / side) - 0.5 * (side - 1)) * pitch + 0.02 * jitter(&rng);
        double height = 1.0 + layer * pitch + 0.02 * jitter(&rng);
        double p[3] = {x, height, z};
        int sphere = (i % 2 == 0 && madeSpheres < spheres) || madeBoxes >= boxes;
        double yaw = 0.25 * jitter(&rng);
        if (sphere) {
            add_body(s, BENCH_SPHERE, 0.5, 0, 0, 1.0, p, kIdentity, 0);
            madeSpheres++;
        } else {
            double q[4];
            BenchQuatFromAxisAngle(q, kAxisY, yaw);
            add_body(s, BENCH_BOX, 0.5, 0.5, 0.5, 1.0, p, q, 0);
            madeBoxes++;
        }
    }
    snprintf(s->description, sizeof s->description,
             "%d spheres (r 0.5 m) and %d unit boxes dropped into a 16 m x 16 m walled box, 10 s", spheres,
             boxes);
    s->quality = BENCH_Q_ESCAPED;
    s->qualityName = "escaped";
    s->container[0][0] = s->container[0][2] = -inner;
    s->container[1][0] = s->container[1][2] = inner;
    s->container[0][1] = 0;
    s->container[1][1] = 1e6;
    scene_finish(s);
    return s;
}

BenchScene *BenchSceneHeap(int boxes)
{
    if (boxes < 1)
        return NULL;
    BenchScene *s = scene_new("heap", boxes, 200, boxes, 0);
    if (!s)
        return NULL;
    /* Boxes of 0.6 to 1.2 m sides at random orientations, 16 to a layer on a 4 x 4 grid 1.6 m apart
     * (jittered by ±0.1 m; no two overlap), layers 1.6 m apart, dropped onto the open ground: a heap
     * that collapses, spreads and settles, the case of a fallen stack (issue 17 point 6). 30 s: long
     * enough to go to sleep. */
    unsigned long long rng = 17;
    for (int i = 0; i < boxes; i++) {
        int layer = i / 16, j = i % 16;
        double p[3] = {((j % 4) - 1.5) * 1.6 + 0.1 * jitter(&rng), 1.0 + 1.6 * layer,
                       ((j / 4) - 1.5) * 1.6 + 0.1 * jitter(&rng)};
        double axis[3] = {jitter(&rng), jitter(&rng), jitter(&rng)}, q[4];
        double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]) + 1e-9;
        for (int k = 0; k < 3; k++)
            axis[k] /= len;
        BenchQuatFromAxisAngle(q, axis, 3.14159265358979 * jitter(&rng));
        double hx = 0.45 + 0.15 * jitter(&rng), hy = 0.45 + 0.15 * jitter(&rng), hz = 0.45 + 0.15 * jitter(&rng);
        add_body(s, BENCH_BOX, hx, hy, hz, 8.0 * hx * hy * hz, p, q, 0);
    }
    snprintf(s->description, sizeof s->description,
             "%d boxes (0.6-1.2 m) dropped at random onto the open ground, a heap that settles, 30 s", boxes);
    s->steps = 1800;
    s->quality = BENCH_Q_ESCAPED;
    s->qualityName = "escaped";
    s->container[0][0] = s->container[0][2] = -1e6;
    s->container[1][0] = s->container[1][2] = 1e6;
    s->container[0][1] = -0.1;
    s->container[1][1] = 1e6;
    scene_finish(s);
    return s;
}

/* The chain of `links` capsules with its fixed end `height` m above the ground (0: no ground). */
static BenchScene *chain_scene(const char *prefix, int links, double height)
{
    if (links < 1)
        return NULL;
    BenchScene *s = scene_new(prefix, links, 100, links, links);
    if (!s)
        return NULL;
    s->hasGround = height > 0;
    /* Capsules along z, unrotated (a capsule's axis is its local z). Radius 0.1, cylinder 0.8 m:
     * 1 m tip to tip; the ball joints sit at the tips, z = 0, 1, 2 ... The chain swings down in the
     * y-z plane, each link turning about x alone: the engines' arithmetic keeps it in that plane, as
     * it kept the z-up chain (laid along x, links turned about y) in its own. */
    for (int i = 0; i < links; i++) {
        double p[3] = {0, height, 0.5 + i};
        int b = add_body(s, BENCH_CAPSULE, 0.1, 0.4, 0, 1.0, p, kIdentity, 0);
        double anchor[3] = {0, height, (double)i};
        add_joint(s, BENCH_BALL, b, i == 0 ? -1 : b - 1, anchor, NULL, 1, 0);
    }
    if (height > 0)
        snprintf(s->description, sizeof s->description,
                 "chain of %d capsules (1 m, 1 kg) on ball joints, one end fixed %d m above the ground, released "
                 "horizontal, lands, 10 s",
                 links, (int)height);
    else
        snprintf(s->description, sizeof s->description,
                 "chain of %d capsules (1 m, 1 kg) on ball joints, one end fixed, released horizontal, 10 s", links);
    s->quality = BENCH_Q_JOINT_ERROR;
    s->qualityName = "joint_err_m";
    scene_finish(s);
    return s;
}

BenchScene *BenchSceneChain(int links) { return chain_scene("chain", links, 0); }

/* Issue 17 point 4: the chain with contacts (Kea's exact path with friction passes every step). */
BenchScene *BenchSceneChainFloor(int links) { return chain_scene("chainfloor", links, 60); }

/* One ragdoll, standing with its feet at y = 0, facing -x, arms out along ±z (T-pose). */
typedef struct RagdollPart {
    BenchShape shape;
    double radius, halfLength, mass;
    double pos[3];
    int alongZ; /* capsule axis along world z (arms: unrotated) instead of y */
} RagdollPart;

static const RagdollPart kRagdollParts[11] = {
    {BENCH_CAPSULE, 0.12, 0.04, 10.0, {0, 1.00, 0}, 0},      /* 0 pelvis */
    {BENCH_CAPSULE, 0.14, 0.12, 15.0, {0, 1.42, 0}, 0},      /* 1 chest */
    {BENCH_SPHERE, 0.10, 0, 4.0, {0, 1.80, 0}, 0},           /* 2 head */
    {BENCH_CAPSULE, 0.05, 0.10, 2.0, {0, 1.58, 0.31}, 1},    /* 3 right upper arm */
    {BENCH_CAPSULE, 0.045, 0.10, 1.5, {0, 1.58, 0.605}, 1},  /* 4 right forearm */
    {BENCH_CAPSULE, 0.05, 0.10, 2.0, {0, 1.58, -0.31}, 1},   /* 5 left upper arm */
    {BENCH_CAPSULE, 0.045, 0.10, 1.5, {0, 1.58, -0.605}, 1}, /* 6 left forearm */
    {BENCH_CAPSULE, 0.07, 0.16, 7.0, {0, 0.69, 0.1}, 0},     /* 7 right thigh */
    {BENCH_CAPSULE, 0.06, 0.17, 4.0, {0, 0.23, 0.1}, 0},     /* 8 right shin */
    {BENCH_CAPSULE, 0.07, 0.16, 7.0, {0, 0.69, -0.1}, 0},    /* 9 left thigh */
    {BENCH_CAPSULE, 0.06, 0.17, 4.0, {0, 0.23, -0.1}, 0},    /* 10 left shin */
};

typedef struct RagdollJoint {
    BenchJointType type;
    int a, b;
    double anchor[3], axis[3];
    double lo, hi;
} RagdollJoint;

/* Hinge limits bound the angle of b relative to a: knees bend the shin backwards (+x), elbows the
 * forearm forwards (-x), the spine bends the chest forwards, the head nods either way.
 * The neck is a limited hinge, not a free ball joint: the head (a sphere) hangs from a point of its
 * surface and does not collide with the chest (jointed pairs never do), so on a free ball joint a
 * head lying on the ground rolls without slipping in circles about that point, through the top of
 * its own chest, for as long as the run lasts (no friction acts on rolling; seen in every engine:
 * heads still turning at 1-9 rad/s after 10 s). */
static const RagdollJoint kRagdollJoints[10] = {
    {BENCH_HINGE, 0, 1, {0, 1.16, 0}, {0, 0, 1}, -0.3, 0.8},     /* spine */
    {BENCH_HINGE, 1, 2, {0, 1.70, 0}, {0, 0, 1}, -0.5, 0.5},     /* neck */
    {BENCH_BALL, 1, 3, {0, 1.58, 0.16}, {0, 0, 0}, 1, 0},        /* right shoulder */
    {BENCH_HINGE, 3, 4, {0, 1.58, 0.46}, {0, -1, 0}, 0, 2.5},    /* right elbow */
    {BENCH_BALL, 1, 5, {0, 1.58, -0.16}, {0, 0, 0}, 1, 0},       /* left shoulder */
    {BENCH_HINGE, 5, 6, {0, 1.58, -0.46}, {0, 1, 0}, 0, 2.5},    /* left elbow */
    {BENCH_BALL, 0, 7, {0, 0.92, 0.1}, {0, 0, 0}, 1, 0},         /* right hip */
    {BENCH_HINGE, 7, 8, {0, 0.46, 0.1}, {0, 0, 1}, 0, 2.5},      /* right knee */
    {BENCH_BALL, 0, 9, {0, 0.92, -0.1}, {0, 0, 0}, 1, 0},        /* left hip */
    {BENCH_HINGE, 9, 10, {0, 0.46, -0.1}, {0, 0, 1}, 0, 2.5},    /* left knee */
};

/* Lowest height of a body (its deepest point along -y). */
double body_lowest_y(const BenchBody *b, const double pos[3], const double quat[4])
{
    switch (b->shape) {
    case BENCH_SPHERE:
        return pos[1] - b->size[0];
    case BENCH_CAPSULE: {
        double half[3] = {0, 0, b->size[1]}, w[3];
        BenchQuatRotate(w, quat, half);
        return pos[1] - fabs(w[1]) - b->size[0];
    }
    case BENCH_BOX:
    default: {
        double reach = 0;
        static const double axes[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (int i = 0; i < 3; i++) {
            double w[3];
            BenchQuatRotate(w, quat, axes[i]);
            reach += fabs(w[1]) * b->size[i];
        }
        return pos[1] - reach;
    }
    }
}

/* A point of the standing ragdoll, turned by q about `centre` and moved over `place` on the grid. */
static void ragdoll_place(double out[3], const double q[4], const double centre[3], const double place[3],
                          const double point[3])
{
    double d[3] = {point[0] - centre[0], point[1] - centre[1], point[2] - centre[2]};
    BenchQuatRotate(out, q, d);
    out[0] += place[0];
    out[1] += centre[1];
    out[2] += place[2];
}

int add_ragdoll(BenchScene *s, const double q[4], const double place[3], double lowest)
{
    const double centre[3] = {0, 1.0, 0}; /* each ragdoll turns about its hips */
    int first = s->bodyCount;
    for (int i = 0; i < 11; i++) {
        const RagdollPart *part = &kRagdollParts[i];
        double p[3], bq[4];
        ragdoll_place(p, q, centre, place, part->pos);
        BenchQuatMultiply(bq, q, part->shape == BENCH_CAPSULE && !part->alongZ ? kStandUp : kIdentity);
        add_body(s, part->shape, part->radius, part->halfLength, 0, part->mass, p, bq, 0);
    }
    for (int i = 0; i < 10; i++) {
        const RagdollJoint *rj = &kRagdollJoints[i];
        double a[3], axis[3];
        ragdoll_place(a, q, centre, place, rj->anchor);
        BenchQuatRotate(axis, q, rj->axis);
        add_joint(s, rj->type, first + rj->a, first + rj->b, a, axis, rj->lo, rj->hi);
    }
    /* Lift the ragdoll so that its lowest point is `lowest` above the ground. */
    double low = 1e9;
    for (int i = first; i < s->bodyCount; i++) {
        double y = body_lowest_y(&s->bodies[i], s->bodies[i].pos, s->bodies[i].quat);
        low = y < low ? y : low;
    }
    double lift = lowest - low;
    for (int i = first; i < s->bodyCount; i++)
        s->bodies[i].pos[1] += lift;
    for (int i = s->jointCount - 10; i < s->jointCount; i++)
        s->joints[i].anchor[1] += lift;
    return first;
}

void ragdoll_tilt(double q[4], int k)
{
    /* A different yaw (golden angle steps, about y) and a forward tilt of 0.3 to 1.5 rad for each
     * (about z: the face, towards -x, goes down). */
    double yaw = 2.39996 * k, tilt = 0.3 + 1.2 * fmod(0.6180339887 * k, 1.0);
    double qYaw[4], qTilt[4];
    BenchQuatFromAxisAngle(qYaw, kAxisY, yaw);
    BenchQuatFromAxisAngle(qTilt, kAxisZ, tilt);
    BenchQuatMultiply(q, qYaw, qTilt);
}

BenchScene *BenchSceneRagdolls(int count)
{
    if (count < 1)
        return NULL;
    BenchScene *s = scene_new("ragdolls", count, 100, 11 * count, 10 * count);
    if (!s)
        return NULL;
    int side = 1;
    while (side * side < count)
        side++;
    for (int k = 0; k < count; k++) {
        double q[4];
        ragdoll_tilt(q, k);
        double place[3] = {((k / side) - 0.5 * (side - 1)) * 3.0, 0, ((k % side) - 0.5 * (side - 1)) * 3.0};
        add_ragdoll(s, q, place, 0.5);
    }
    snprintf(s->description, sizeof s->description,
             "%d ragdolls of 11 bodies (4 ball, 6 limited hinge joints) dropped on the ground, 10 s", count);
    s->quality = BENCH_Q_JOINT_ERROR;
    s->qualityName = "joint_err_m";
    scene_finish(s);
    return s;
}

BenchScene *BenchSceneColumn(int boxes)
{
    if (boxes < 1)
        return NULL;
    BenchScene *s = scene_new("column", boxes, 20, boxes, 0);
    if (!s)
        return NULL;
    for (int i = 0; i < boxes; i++) {
        double p[3] = {0, 0.5 + i, 0};
        add_body(s, BENCH_BOX, 0.5, 0.5, 0.5, 1.0, p, kIdentity, 0);
    }
    s->steps = 1200;
    snprintf(s->description, sizeof s->description,
             "column of %d unit boxes stacked face to face on the ground, 20 s", boxes);
    s->quality = BENCH_Q_TOP_DISPLACEMENT;
    s->qualityName = "top_disp_m";
    s->fallDistance = BENCH_FALL_DISTANCE;
    scene_finish(s);
    return s;
}

/* "prefix" or "prefixN" → N (or `fallback` without a number); -1 when the name does not match. */
int parse_count(const char *name, const char *prefix, int fallback)
{
    size_t n = strlen(prefix);
    if (strncmp(name, prefix, n) != 0)
        return -1;
    if (name[n] == '\0')
        return fallback;
    char *end = NULL;
    long v = strtol(name + n, &end, 10);
    if (*end != '\0' || v < 1 || v > 100000)
        return -1;
    return (int)v;
}

BenchScene *BenchSceneCreate(const char *name)
{
    int n;
    if (!name)
        return NULL;
    if ((n = parse_count(name, "pyramid", -1)) > 0)
        return BenchScenePyramid(n);
    if ((n = parse_count(name, "pile", 500)) > 0)
        return BenchScenePile(n, n);
    if ((n = parse_count(name, "chainfloor", 100)) > 0)
        return BenchSceneChainFloor(n);
    if ((n = parse_count(name, "chain", 100)) > 0)
        return BenchSceneChain(n);
    if ((n = parse_count(name, "ragdolls", 100)) > 0)
        return BenchSceneRagdolls(n);
    if ((n = parse_count(name, "column", 20)) > 0)
        return BenchSceneColumn(n);
    if ((n = parse_count(name, "heap", 200)) > 0)
        return BenchSceneHeap(n);
    return BenchSceneOthersCreate(name);
}

void BenchSceneDestroy(BenchScene *scene)
{
    if (!scene)
        return;
    free(scene->bodies);
    free(scene->joints);
    free(scene);
}

/* ---- quality ----------------------------------------------------------------------------------- */

static double distance(const double a[3], const double b[3])
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

double BenchJointError(const BenchScene *scene, const double (*pos)[3], const double (*quat)[4])
{
    double worst = 0;
    for (int k = 0; k < scene->jointCount; k++) {
        const BenchJoint *j = &scene->joints[k];
        double w[2][3];
        for (int side = 0; side < 2; side++) {
            int b = j->body[side];
            if (b < 0) {
                memcpy(w[side], j->local[side], sizeof w[side]);
                continue;
            }
            BenchQuatRotate(w[side], quat[b], j->local[side]);
            for (int i = 0; i < 3; i++)
                w[side][i] += pos[b][i];
        }
        double e = distance(w[0], w[1]);
        if (!(e <= worst)) /* also lets a NaN through, so that it is seen */
            worst = e;
    }
    return worst;
}

static int poses_finite(const BenchScene *scene, const double (*pos)[3], const double (*quat)[4])
{
    for (int i = 0; i < scene->bodyCount; i++) {
        for (int k = 0; k < 3; k++)
            if (!isfinite(pos[i][k]))
                return 0;
        for (int k = 0; k < 4; k++)
            if (!isfinite(quat[i][k]))
                return 0;
    }
    return 1;
}

/* Is body i jointed to the world (a motorised wall or bar)? */
static int held_by_world(const BenchScene *scene, int i)
{
    for (int k = 0; k < scene->jointCount; k++)
        if (scene->joints[k].body[0] == i && scene->joints[k].body[1] < 0)
            return 1;
    return 0;
}

void BenchQualityInit(const BenchScene *scene, BenchQuality *quality)
{
    (void)scene;
    memset(quality, 0, sizeof *quality);
    quality->standing = -1;
}

void BenchQualityObserve(const BenchScene *scene, BenchQuality *quality, const double (*pos)[3],
                         const double (*quat)[4])
{
    quality->observed++;
    if (!poses_finite(scene, pos, quat)) {
        quality->nonFinite = 1;
        return;
    }
    if (scene->jointCount > 0) {
        double e = BenchJointError(scene, pos, quat);
        quality->sumJointError += e;
        if (e > quality->maxJointError)
            quality->maxJointError = e;
    }
}

void BenchQualityFinish(const BenchScene *scene, BenchQuality *quality, const double (*pos)[3],
                        const double (*quat)[4], int complete)
{
    if (!poses_finite(scene, pos, quat))
        quality->nonFinite = 1;
    quality->meanJointError = scene->jointCount > 0 && quality->observed > 0
                                  ? quality->sumJointError / quality->observed
                                  : (double)NAN;
    quality->standing = -1;
    if (quality->nonFinite) {
        quality->value = NAN;
        quality->standing = scene->fallDistance >= 0 ? 0 : -1;
        return;
    }
    double value = 0;
    switch (scene->quality) {
    case BENCH_Q_MAX_DRIFT: /* = maxDisplacement, computed below */
        break;
    case BENCH_Q_TOP_DISPLACEMENT: {
        int top = scene->bodyCount - 1;
        value = distance(pos[top], scene->bodies[top].pos);
        break;
    }
    case BENCH_Q_JOINT_ERROR:
        value = quality->maxJointError;
        break;
    case BENCH_Q_COM_DRIFT: {
        /* no external force: the centre of mass moves on the line com0 + (momentum / mass) t */
        double mass = 0, line[3] = {0, 0, 0}, com[3] = {0, 0, 0};
        double t = quality->observed * scene->step;
        for (int i = 0; i < scene->bodyCount; i++) {
            const BenchBody *b = &scene->bodies[i];
            if (b->fixed)
                continue;
            mass += b->mass;
            for (int k = 0; k < 3; k++) {
                line[k] += b->mass * (b->pos[k] + b->vel[k] * t);
                com[k] += b->mass * pos[i][k];
            }
        }
        for (int k = 0; k < 3; k++) {
            line[k] /= mass;
            com[k] /= mass;
        }
        value = distance(com, line);
        break;
    }
    case BENCH_Q_ESCAPED:
        for (int i = 0; i < scene->bodyCount; i++) {
            if (scene->bodies[i].fixed || held_by_world(scene, i)) /* walls and bars are not the contents */
                continue;
            int inside = 1;
            for (int k = 0; k < 3; k++)
                inside &= pos[i][k] > scene->container[0][k] && pos[i][k] < scene->container[1][k];
            value += !inside;
        }
        break;
    }
    quality->maxDisplacement = 0;
    for (int i = 0; i < scene->bodyCount; i++)
        if (!scene->bodies[i].fixed) {
            double d = distance(pos[i], scene->bodies[i].pos);
            quality->maxDisplacement = d > quality->maxDisplacement ? d : quality->maxDisplacement;
        }
    quality->value = scene->quality == BENCH_Q_MAX_DRIFT ? quality->maxDisplacement : value;
    if (scene->fallDistance >= 0 && complete)
        quality->standing = quality->maxDisplacement < scene->fallDistance;
    quality->floorPenetration = 0;
    if (scene->hasGround)
        for (int i = 0; i < scene->bodyCount; i++)
            if (!scene->bodies[i].fixed) {
                double depth = -body_lowest_y(&scene->bodies[i], pos[i], quat[i]);
                if (depth > quality->floorPenetration)
                    quality->floorPenetration = depth;
            }
}
