/* The benchmark scenes (bench/scenes) checked as data: the sizes issue 5 asks for, no two bodies
 * overlapping at the start (brute force over every pair), joints whose anchors agree at the initial
 * pose, and quality figures that measure what they claim on hand-made poses. The engines that run the
 * scenes (ODE, Bullet, later Karma) are benchmarks, not tests; this is the part every engine shares. */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>

#include "bench_scenes.h"

/* ---- geometry for the overlap check ------------------------------------------------------------- */

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* Closest distance between segments p0-p1 and q0-q1 (Ericson, Real-Time Collision Detection, 5.1.9). */
static double segment_distance(const double p0[3], const double p1[3], const double q0[3], const double q1[3])
{
    double d1[3], d2[3], r[3];
    for (int i = 0; i < 3; i++) {
        d1[i] = p1[i] - p0[i];
        d2[i] = q1[i] - q0[i];
        r[i] = p0[i] - q0[i];
    }
    double a = dot3(d1, d1), e = dot3(d2, d2), f = dot3(d2, r), s = 0, t = 0;
    if (a <= 1e-15 && e <= 1e-15) {
        s = t = 0;
    } else if (a <= 1e-15) {
        t = fmin(fmax(f / e, 0), 1);
    } else {
        double c = dot3(d1, r);
        if (e <= 1e-15) {
            s = fmin(fmax(-c / a, 0), 1);
        } else {
            double b = dot3(d1, d2), denom = a * e - b * b;
            s = denom > 1e-15 ? fmin(fmax((b * f - c * e) / denom, 0), 1) : 0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = fmin(fmax(-c / a, 0), 1);
            } else if (t > 1) {
                t = 1;
                s = fmin(fmax((b - c) / a, 0), 1);
            }
        }
    }
    double d = 0;
    for (int i = 0; i < 3; i++) {
        double x = (p0[i] + d1[i] * s) - (q0[i] + d2[i] * t);
        d += x * x;
    }
    return sqrt(d);
}

/* A sphere or capsule as its core segment and radius. */
static void round_core(const BenchBody *b, double p0[3], double p1[3])
{
    double half[3] = {0, 0, b->shape == BENCH_CAPSULE ? b->size[1] : 0}, w[3];
    BenchQuatRotate(w, b->quat, half);
    for (int i = 0; i < 3; i++) {
        p0[i] = b->pos[i] - w[i];
        p1[i] = b->pos[i] + w[i];
    }
}

/* World AABB of any body (exact for boxes and capsules). */
static void body_aabb(const BenchBody *b, double lo[3], double hi[3])
{
    double reach[3] = {0, 0, 0};
    if (b->shape == BENCH_BOX) {
        const double axes[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (int k = 0; k < 3; k++) {
            double w[3];
            BenchQuatRotate(w, b->quat, axes[k]);
            for (int i = 0; i < 3; i++)
                reach[i] += fabs(w[i]) * b->size[k];
        }
    } else {
        double p0[3], p1[3];
        round_core(b, p0, p1);
        for (int i = 0; i < 3; i++)
            reach[i] = 0.5 * fabs(p1[i] - p0[i]) + b->size[0];
    }
    for (int i = 0; i < 3; i++) {
        lo[i] = b->pos[i] - reach[i];
        hi[i] = b->pos[i] + reach[i];
    }
}

static int joined(const BenchScene *s, int a, int b)
{
    for (int k = 0; k < s->jointCount; k++) {
        const int *j = s->joints[k].body;
        if ((j[0] == a && j[1] == b) || (j[0] == b && j[1] == a))
            return 1;
    }
    return 0;
}

/* Smallest gap between two bodies that no joint joins: exact for round pairs (segment distance), a
 * separating-AABB gap otherwise (negative = overlap of the boxes, so a pass proves no overlap). */
static double smallest_gap(const BenchScene *s)
{
    double smallest = 1e9;
    for (int a = 0; a < s->bodyCount; a++)
        for (int b = a + 1; b < s->bodyCount; b++) {
            const BenchBody *A = &s->bodies[a], *B = &s->bodies[b];
            if (A->fixed && B->fixed)
                continue;
            /* the AABB gap never exceeds the true gap: pairs it puts past the smallest are skipped */
            double alo[3], ahi[3], blo[3], bhi[3], gap = -1e9;
            body_aabb(A, alo, ahi);
            body_aabb(B, blo, bhi);
            for (int i = 0; i < 3; i++)
                gap = fmax(gap, fmax(blo[i] - ahi[i], alo[i] - bhi[i]));
            if (gap >= smallest)
                continue;
            if (A->shape != BENCH_BOX && B->shape != BENCH_BOX) {
                double a0[3], a1[3], b0[3], b1[3];
                round_core(A, a0, a1);
                round_core(B, b0, b1);
                gap = segment_distance(a0, a1, b0, b1) - A->size[0] - B->size[0];
            }
            if (gap < smallest && !joined(s, a, b))
                smallest = gap;
        }
    return smallest;
}

static double lowest_point(const BenchScene *s)
{
    double lowest = 1e9;
    for (int i = 0; i < s->bodyCount; i++) {
        double lo[3], hi[3];
        body_aabb(&s->bodies[i], lo, hi);
        if (!s->bodies[i].fixed)
            lowest = fmin(lowest, lo[1]);
    }
    return lowest;
}

static void initial_poses(const BenchScene *s, double (**pos)[3], double (**quat)[4])
{
    *pos = malloc(sizeof **pos * (size_t)s->bodyCount);
    *quat = malloc(sizeof **quat * (size_t)s->bodyCount);
    assert_non_null(*pos);
    assert_non_null(*quat);
    for (int i = 0; i < s->bodyCount; i++) {
        memcpy((*pos)[i], s->bodies[i].pos, sizeof(*pos)[i]);
        memcpy((*quat)[i], s->bodies[i].quat, sizeof(*quat)[i]);
    }
}

/* ---- tests ---------------------------------------------------------------------------------------- */

/* The six standard scenes: the counts and settings issue 5 names, valid data, nothing overlapping. */
static void standard_scenes(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int dynamic, fixed, joints, steps, ground;
    } expect[] = {
        {"pyramid20", 210, 0, 0, 600, 1}, {"pyramid40", 820, 0, 0, 600, 1}, {"pile", 1000, 4, 0, 600, 1},
        {"chain", 100, 0, 100, 600, 0},   {"ragdolls", 1100, 0, 1000, 600, 1}, {"column", 20, 0, 0, 1200, 1},
    };
    char names[] = BENCH_STANDARD_SCENES;
    int k = 0;
    for (char *name = strtok(names, ","); name; name = strtok(NULL, ","), k++) {
        assert_true(k < 6);
        BenchScene *s = BenchSceneCreate(name);
        assert_non_null(s);
        assert_string_equal(s->name, expect[k].name);
        assert_int_equal(s->dynamicCount, expect[k].dynamic);
        assert_int_equal(s->bodyCount - s->dynamicCount, expect[k].fixed);
        assert_int_equal(s->jointCount, expect[k].joints);
        assert_int_equal(s->steps, expect[k].steps);
        assert_int_equal(s->hasGround, expect[k].ground);
        assert_near(s->step, 1.0 / 60, 1e-15);
        assert_near(s->friction, 0.6, 0);
        assert_near(s->gravity[0], 0, 0);
        assert_near(s->gravity[1], -9.81, 0); /* y up */
        assert_near(s->gravity[2], 0, 0);
        for (int i = 0; i < s->bodyCount; i++) {
            const BenchBody *b = &s->bodies[i];
            double n = sqrt(b->quat[0] * b->quat[0] + b->quat[1] * b->quat[1] + b->quat[2] * b->quat[2] +
                            b->quat[3] * b->quat[3]);
            assert_near(n, 1, 1e-12);
            assert_true(b->size[0] > 0);
            if (!b->fixed)
                assert_true(b->mass >= 1.0 && b->mass <= 15.0); /* within 15x of the 1 kg unit box */
        }
        double gap = smallest_gap(s), lowest = lowest_point(s);
        print_message("%-10s %4d bodies %4d joints: smallest gap between bodies %.4f m, lowest point %.4f m\n",
                      s->name, s->dynamicCount, s->jointCount, gap, lowest);
        assert_true(gap >= -1e-12); /* stacks start exactly touching (gap 0), nothing overlaps */
        if (s->hasGround)
            assert_true(lowest >= -1e-12);
        BenchSceneDestroy(s);
    }
    assert_int_equal(k, 6);
}

/* Names with counts build scaled scenes; bad names and counts give NULL. */
static void scene_names(void **state)
{
    (void)state;
    BenchScene *s = BenchSceneCreate("pyramid3");
    assert_non_null(s);
    assert_int_equal(s->dynamicCount, 6);
    /* rows at y = 0.5, 1.5, 2.5 along z, one box deep (x = 0); the top box centred over the base */
    assert_near(s->bodies[5].pos[1], 2.5, 0);
    assert_near(s->bodies[5].pos[2], 0, 1e-15);
    assert_near(s->bodies[1].pos[2] - s->bodies[0].pos[2], 1.05, 1e-12);
    for (int i = 0; i < 6; i++)
        assert_near(s->bodies[i].pos[0], 0, 0);
    BenchSceneDestroy(s);
    s = BenchSceneCreate("column5");
    assert_non_null(s);
    assert_int_equal(s->dynamicCount, 5);
    assert_near(s->bodies[4].pos[1], 4.5, 0);
    BenchSceneDestroy(s);
    s = BenchSceneCreate("pile10");
    assert_non_null(s);
    assert_int_equal(s->dynamicCount, 20);
    int spheres = 0;
    for (int i = 0; i < s->bodyCount; i++)
        spheres += s->bodies[i].shape == BENCH_SPHERE;
    assert_int_equal(spheres, 10);
    BenchSceneDestroy(s);
    assert_null(BenchSceneCreate("pyramid"));
    assert_null(BenchSceneCreate("pyramid0"));
    assert_null(BenchSceneCreate("column-3"));
    assert_null(BenchSceneCreate("tower"));
    assert_null(BenchSceneCreate(NULL));
}

/* Each ragdoll weighs 58 kg; the chain hangs from the origin; every joint's two local anchors name
 * the same world point at the start (joint error 0), and a hinge axis is a unit vector. */
static void joints_agree_at_start(void **state)
{
    (void)state;
    const char *names[] = {"chain", "ragdolls"};
    for (int n = 0; n < 2; n++) {
        BenchScene *s = BenchSceneCreate(names[n]);
        assert_non_null(s);
        double (*pos)[3], (*quat)[4];
        initial_poses(s, &pos, &quat);
        double err = BenchJointError(s, (const double(*)[3])pos, (const double(*)[4])quat);
        print_message("%s: joint error at the initial pose %.3e m\n", s->name, err);
        assert_true(err < 1e-12);
        for (int k = 0; k < s->jointCount; k++)
            if (s->joints[k].type == BENCH_HINGE) {
                assert_near(sqrt(dot3(s->joints[k].axis, s->joints[k].axis)), 1, 1e-12);
                assert_true(s->joints[k].limited && s->joints[k].lo <= 0 && s->joints[k].hi >= 0);
            }
        if (n == 0) {
            assert_int_equal(s->joints[0].body[1], -1);
            assert_near(s->joints[0].anchor[0], 0, 0);
        } else {
            double total = 0;
            for (int i = 0; i < 11; i++)
                total += s->bodies[i].mass;
            assert_near(total, 58, 1e-12);
        }
        free(pos), free(quat);
        BenchSceneDestroy(s);
    }
}

/* Joint error measures what it says: moving a chain link by d opens its two joints by |d|; turning
 * the first link about its fixed anchor opens nothing at the anchor and the link's far joint by the
 * chord 2 L sin(θ/2). */
static void joint_error_is_a_distance(void **state)
{
    (void)state;
    BenchScene *s = BenchSceneCreate("chain3");
    assert_non_null(s);
    double (*pos)[3], (*quat)[4];
    initial_poses(s, &pos, &quat);
    pos[1][1] += 0.03;
    pos[1][2] -= 0.04;
    assert_near(BenchJointError(s, (const double(*)[3])pos, (const double(*)[4])quat), 0.05, 1e-12);
    memcpy(pos[1], s->bodies[1].pos, sizeof pos[1]);
    /* turn link 0 by θ about world y through its anchor at the origin */
    const double y[3] = {0, 1, 0}, theta = 0.4;
    double r[4], c[3];
    BenchQuatFromAxisAngle(r, y, theta);
    BenchQuatMultiply(quat[0], r, s->bodies[0].quat);
    BenchQuatRotate(c, r, s->bodies[0].pos);
    memcpy(pos[0], c, sizeof c);
    double err = BenchJointError(s, (const double(*)[3])pos, (const double(*)[4])quat);
    assert_near(err, 2 * 1.0 * sin(theta / 2), 1e-12);
    print_message("chain3: link turned by %.2f rad about its anchor opens its far joint by %.6f m (chord %.6f)\n",
                  theta, err, 2 * sin(theta / 2));
    free(pos), free(quat);
    BenchSceneDestroy(s);
}

static void finish(const BenchScene *s, BenchQuality *q, double (*pos)[3], double (*quat)[4], int complete)
{
    BenchQualityFinish(s, q, (const double(*)[3])pos, (const double(*)[4])quat, complete);
}

/* A scene and its quality tracker at the initial poses. */
static BenchScene *start(const char *name, BenchQuality *q, double (**pos)[3], double (**quat)[4])
{
    BenchScene *s = BenchSceneCreate(name);
    assert_non_null(s);
    initial_poses(s, pos, quat);
    BenchQualityInit(s, q);
    return s;
}

/* Quality figures on hand-made end poses: drift, top displacement, the fall verdict at half an
 * edge, escapes from the pile's container, floor penetration of a tilted box, NaN. */
static void quality_figures(void **state)
{
    (void)state;
    double (*pos)[3], (*quat)[4];
    BenchQuality q;
    BenchScene *s = start("pyramid3", &q, &pos, &quat);
    pos[2][0] += 0.3;
    pos[2][2] += 0.4; /* 0.5 m: just fallen */
    pos[4][1] -= 0.2;
    BenchQualityObserve(s, &q, (const double(*)[3])pos, (const double(*)[4])quat);
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 0.5, 1e-12);
    assert_int_equal(q.standing, 0);
    pos[2][2] -= 0.4; /* now 0.3 and 0.2 apart from their starts: standing */
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 0.3, 1e-12);
    assert_int_equal(q.standing, 1);
    finish(s, &q, pos, quat, 0);
    assert_int_equal(q.standing, -1); /* no verdict on an incomplete run */
    /* box 0 turned 45° about x: its lowest edge sits 0.5 (√2 - 1) m below the ground */
    const double x[3] = {1, 0, 0};
    BenchQuatFromAxisAngle(quat[0], x, 0.25 * 3.14159265358979323846);
    finish(s, &q, pos, quat, 1);
    assert_near(q.floorPenetration, 0.5 * (sqrt(2.0) - 1), 1e-12);
    pos[3][0] = NAN;
    finish(s, &q, pos, quat, 1);
    assert_true(isnan(q.value));
    assert_int_equal(q.standing, 0);
    free(pos), free(quat);
    BenchSceneDestroy(s);

    s = start("column4", &q, &pos, &quat);
    pos[3][0] += 0.06;
    pos[3][1] -= 0.08;
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 0.1, 1e-12);
    assert_int_equal(q.standing, 1);
    free(pos), free(quat);
    BenchSceneDestroy(s);

    s = start("pile10", &q, &pos, &quat);
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 0, 0);
    assert_int_equal(q.standing, -1);
    pos[5][0] = 8.2;  /* through a wall */
    pos[6][2] = -9;   /* through another */
    pos[7][1] = -0.1; /* through the floor */
    pos[0][0] = 8.2;  /* a wall itself: fixed bodies are not counted */
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 3, 0);
    free(pos), free(quat);
    BenchSceneDestroy(s);
}

/* y is up (docs/decisions.md K30): stacks rise along y, the ragdolls' heads are above their hips,
 * their chests lean from y by their tilt and their lowest points are 0.5 m above the plane y = 0,
 * the pile's container is open towards +y, and the chain hangs from the origin along z. */
static void scenes_are_y_up(void **state)
{
    (void)state;
    BenchScene *s = BenchSceneCreate("column5");
    assert_non_null(s);
    for (int i = 0; i < 5; i++) {
        assert_near(s->bodies[i].pos[0], 0, 0);
        assert_near(s->bodies[i].pos[1], 0.5 + i, 0);
        assert_near(s->bodies[i].pos[2], 0, 0);
    }
    BenchSceneDestroy(s);
    s = BenchSceneCreate("ragdolls4");
    assert_non_null(s);
    const double up[3] = {0, 1, 0}, localAxis[3] = {0, 0, 1};
    for (int k = 0; k < 4; k++) {
        const BenchBody *part = &s->bodies[11 * k];
        double lowest = 1e9;
        for (int i = 0; i < 11; i++) {
            double lo[3], hi[3];
            body_aabb(&part[i], lo, hi);
            lowest = fmin(lowest, lo[1]);
        }
        assert_near(lowest, 0.5, 1e-12);
        assert_true(part[2].pos[1] > part[0].pos[1]); /* head above pelvis (tilted at most 1.5 rad) */
        /* the chest's axis (local z) leans from up by the ragdoll's tilt, 0.3 to 1.5 rad */
        double axis[3];
        BenchQuatRotate(axis, part[1].quat, localAxis);
        double tilt = acos(fmin(1, fabs(dot3(axis, up))));
        assert_true(tilt > 0.3 - 1e-9 && tilt < 1.5 + 1e-9);
    }
    BenchSceneDestroy(s);
    s = BenchSceneCreate("pile10");
    assert_non_null(s);
    assert_near(s->container[0][1], 0, 0);
    assert_true(s->container[1][1] > 100);
    for (int i = 0; i < s->bodyCount; i++) {
        const BenchBody *b = &s->bodies[i];
        if (b->fixed) {
            assert_near(b->size[1], 6, 0); /* walls 12 m high, standing on the ground */
            assert_near(b->pos[1], 6, 0);
            continue;
        }
        assert_true(b->pos[1] >= 1.0 - 0.02);
        for (int k = 0; k < 3; k += 2)
            assert_true(b->pos[k] > s->container[0][k] && b->pos[k] < s->container[1][k]);
    }
    BenchSceneDestroy(s);
    s = BenchSceneCreate("chain3");
    assert_non_null(s);
    for (int i = 0; i < 3; i++) {
        assert_near(s->bodies[i].pos[2], 0.5 + i, 0);
        assert_near(s->joints[i].anchor[2], i, 0);
    }
    BenchSceneDestroy(s);
}

/* The quaternion helpers against each other: (q ⊗ p) v = q (p v), and q* undoes q. */
static void quaternions(void **state)
{
    (void)state;
    const double a[3] = {0.48, -0.6, 0.64}, b[3] = {0, 0.6, 0.8}, v[3] = {0.3, -1.2, 2.5};
    double q[4], p[4], qp[4], w1[3], w2[3], back[3];
    BenchQuatFromAxisAngle(q, a, 1.1);
    BenchQuatFromAxisAngle(p, b, -2.3);
    BenchQuatMultiply(qp, q, p);
    BenchQuatRotate(w1, qp, v);
    BenchQuatRotate(w2, p, v);
    BenchQuatRotate(w2, q, w2);
    BenchQuatRotateInverse(back, qp, w1);
    for (int i = 0; i < 3; i++) {
        assert_near(w1[i], w2[i], 1e-14);
        assert_near(back[i], v[i], 1e-14);
    }
    /* -90° about x takes local z to world y: a standing capsule's axis (y up) */
    const double x[3] = {1, 0, 0}, z[3] = {0, 0, 1};
    BenchQuatFromAxisAngle(q, x, -0.5 * 3.14159265358979323846);
    BenchQuatRotate(w1, q, z);
    assert_near(w1[1], 1, 1e-15);
    assert_near(w1[2], 0, 1e-15);
}

/* Inertia of the uniform solids against brute-force integration over a grid of cell centres in the
 * bounding box: a unit box, a sphere, a chain link and a ragdoll thigh (capsules). */
static void inertia_by_integration(void **state)
{
    (void)state;
    const BenchBody bodies[] = {
        {BENCH_BOX, {0.5, 0.3, 0.2}, 2.0, {0, 0, 0}, {1, 0, 0, 0}, 0, {0, 0, 0}},
        {BENCH_SPHERE, {0.5, 0, 0}, 1.0, {0, 0, 0}, {1, 0, 0, 0}, 0, {0, 0, 0}},
        {BENCH_CAPSULE, {0.1, 0.4, 0}, 1.0, {0, 0, 0}, {1, 0, 0, 0}, 0, {0, 0, 0}},
        {BENCH_CAPSULE, {0.07, 0.16, 0}, 7.0, {0, 0, 0}, {1, 0, 0, 0}, 0, {0, 0, 0}},
    };
    const int n = 120;
    for (size_t k = 0; k < sizeof bodies / sizeof bodies[0]; k++) {
        const BenchBody *b = &bodies[k];
        double half[3];
        if (b->shape == BENCH_BOX)
            memcpy(half, b->size, sizeof half);
        else
            half[0] = half[1] = b->size[0], half[2] = b->size[0] + (b->shape == BENCH_CAPSULE ? b->size[1] : 0);
        double sum[3] = {0, 0, 0};
        long inside = 0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                for (int l = 0; l < n; l++) {
                    double p[3] = {(2 * (i + 0.5) / n - 1) * half[0], (2 * (j + 0.5) / n - 1) * half[1],
                                   (2 * (l + 0.5) / n - 1) * half[2]};
                    if (b->shape != BENCH_BOX) {
                        double axial = fmax(fabs(p[2]) - (b->shape == BENCH_CAPSULE ? b->size[1] : 0), 0);
                        if (p[0] * p[0] + p[1] * p[1] + axial * axial > b->size[0] * b->size[0])
                            continue;
                    }
                    inside++;
                    sum[0] += p[1] * p[1] + p[2] * p[2];
                    sum[1] += p[0] * p[0] + p[2] * p[2];
                    sum[2] += p[0] * p[0] + p[1] * p[1];
                }
        double inertia[3];
        BenchBodyInertia(b, inertia);
        for (int a = 0; a < 3; a++) {
            double numeric = b->mass * sum[a] / (double)inside;
            print_message("shape %d axis %d: inertia %.6f kg m2, grid %.6f (%.2e relative)\n", (int)b->shape, a,
                          inertia[a], numeric, fabs(inertia[a] - numeric) / numeric);
            assert_rel(inertia[a], numeric, 5e-3);
        }
    }
}

/* ---- the scene set of others' making (issue 17) -------------------------------------------------- */

/* Smallest gap between dynamic bodies (fixed ones left out: the spinner's ring is of turned boxes,
 * whose AABBs the round check cannot use) and between them and the ground. */
static double smallest_dynamic_gap(const BenchScene *s)
{
    BenchScene copy = *s;
    BenchBody *bodies = malloc(sizeof *bodies * (size_t)s->bodyCount);
    int *map = malloc(sizeof *map * (size_t)s->bodyCount);
    BenchJoint *joints = malloc(sizeof *joints * (size_t)(s->jointCount + 1));
    assert_non_null(bodies);
    assert_non_null(map);
    assert_non_null(joints);
    copy.bodyCount = 0;
    for (int i = 0; i < s->bodyCount; i++) {
        map[i] = -1;
        if (!s->bodies[i].fixed) {
            map[i] = copy.bodyCount;
            bodies[copy.bodyCount++] = s->bodies[i];
        }
    }
    for (int k = 0; k < s->jointCount; k++) {
        joints[k] = s->joints[k];
        for (int n = 0; n < 2; n++)
            joints[k].body[n] = joints[k].body[n] >= 0 ? map[joints[k].body[n]] : -1;
    }
    copy.bodies = bodies;
    copy.joints = joints;
    double gap = smallest_gap(&copy);
    if (s->hasGround)
        gap = fmin(gap, lowest_point(s));
    free(bodies), free(map), free(joints);
    return gap;
}

/* Every unrotated box that does not stand on the ground stands on another box: its bottom face at
 * the other's top face (within `tol`) over an area > 0; none overlaps another (their AABBs are exact). */
static int boxes_rest_on_each_other(const BenchScene *s, int first, double tol)
{
    for (int a = first; a < s->bodyCount; a++) {
        const BenchBody *A = &s->bodies[a];
        double alo[3], ahi[3];
        body_aabb(A, alo, ahi);
        if (s->hasGround && fabs(alo[1]) <= tol)
            continue;
        int supported = 0;
        for (int b = first; b < s->bodyCount && !supported; b++) {
            double blo[3], bhi[3];
            body_aabb(&s->bodies[b], blo, bhi);
            supported = b != a && fabs(alo[1] - bhi[1]) <= tol && fmin(ahi[0], bhi[0]) - fmax(alo[0], blo[0]) > tol &&
                        fmin(ahi[2], bhi[2]) - fmax(alo[2], blo[2]) > tol;
        }
        if (!supported)
            return 0;
    }
    return 1;
}

/* Every box of a row touches its neighbours: the nearest box at the same height, when one is within
 * 1.5 edges, is exactly one edge away (centre to centre, within `tol`). */
static int rows_touch(const BenchScene *s, double tol)
{
    for (int a = 0; a < s->bodyCount; a++) {
        double nearest = 1e9, edge = 2 * s->bodies[a].size[0];
        for (int b = 0; b < s->bodyCount; b++)
            if (b != a && fabs(s->bodies[b].pos[1] - s->bodies[a].pos[1]) < tol)
                nearest = fmin(nearest, hypot(s->bodies[b].pos[0] - s->bodies[a].pos[0],
                                              s->bodies[b].pos[2] - s->bodies[a].pos[2]));
        if (nearest < 1.5 * edge && fabs(nearest - edge) > tol)
            return 0;
    }
    return 1;
}

static double total_mass(const BenchScene *s, int first, int last)
{
    double m = 0;
    for (int i = first; i < last; i++)
        m += s->bodies[i].mass;
    return m;
}

/* The set builds at its published sizes, with the sources' counts, densities, joints and motors (every
 * engine is handed these same numbers: counts, masses and BenchBodyInertia's moments), valid unit
 * quaternions, and nothing overlapping at the start. */
static void others_scenes(void **state)
{
    (void)state;
    static const struct {
        const char *name;
        int dynamic, fixed, joints, ground;
        double friction, mass; /* total dynamic mass (kg) */
    } expect[] = {
        {"b2pyramid", 820, 0, 0, 1, 0.6, 820},
        {"b2pyramids", 660, 0, 0, 1, 0.6, 660},
        /* 400 spheres less the 7 static ones; 2 x 20 x 19 joints less the 6 between static bodies */
        {"b2jointgrid", 393, 0, 754, 0, 0.6, 393 * 4.0 / 3.0 * 3.14159265358979323846 * 0.064},
        {"b2rain", 495, 0, 450, 1, 0.6, 45 * 58.0},
        /* an 8 m x 8 m x 1.2 m box of density 8; 432 boxes of 0.4 m, density 1 */
        {"b2smash", 433, 0, 0, 0, 0.6, 8 * 8 * 8 * 1.2 + 432 * 0.064},
        {"b2spinner", 451, 34, 1, 0, 0.1, -1},
        /* walls of density 50: 2 x (2 x 7 x 0.5) + 2 x (2 x 0.5 x 5.9) + 2 x (0.5 x 7 x 7) m3; 400 boxes of 0.25 m */
        {"b2tumbler", 406, 0, 6, 0, 0.6, 50 * (14 + 11.8 + 49) + 400 * 0.015625},
        {"joltpyramid", 385, 0, 0, 1, 0.2, 385 * 8000.0},
        {"joltragdolls", 440, 0, 400, 1, 0.2, 40 * 58.0},
    };
    char names[] = BENCH_OTHERS_SCENES;
    int k = 0;
    for (char *name = strtok(names, ","); name; name = strtok(NULL, ","), k++) {
        assert_true(k < 9);
        BenchScene *s = BenchSceneCreate(name);
        assert_non_null(s);
        assert_string_equal(s->name, expect[k].name);
        assert_int_equal(s->dynamicCount, expect[k].dynamic);
        assert_int_equal(s->bodyCount - s->dynamicCount, expect[k].fixed);
        assert_int_equal(s->jointCount, expect[k].joints);
        assert_int_equal(s->hasGround, expect[k].ground);
        assert_int_equal(s->steps, 600);
        assert_near(s->step, 1.0 / 60, 1e-15);
        assert_near(s->friction, expect[k].friction, 0);
        assert_near(s->gravity[1], strcmp(name, "b2smash") == 0 ? 0 : -9.81, 0); /* y up */
        assert_near(s->gravity[0], 0, 0);
        assert_near(s->gravity[2], 0, 0);
        if (expect[k].mass > 0)
            assert_rel(total_mass(s, 0, s->bodyCount), expect[k].mass, 1e-12);
        for (int i = 0; i < s->bodyCount; i++) {
            const BenchBody *b = &s->bodies[i];
            double n = sqrt(b->quat[0] * b->quat[0] + b->quat[1] * b->quat[1] + b->quat[2] * b->quat[2] +
                            b->quat[3] * b->quat[3]);
            assert_near(n, 1, 1e-12);
            assert_true(b->size[0] > 0);
            assert_true(b->fixed ? b->mass == 0 : b->mass > 0);
        }
        double gap = smallest_dynamic_gap(s);
        print_message("%-12s %4d bodies %4d joints: smallest gap %.4f m, mass %.6g kg\n", s->name, s->dynamicCount,
                      s->jointCount, gap, total_mass(s, 0, s->bodyCount));
        assert_true(gap >= -1e-12);
        BenchSceneDestroy(s);
    }
    assert_int_equal(k, 9);
}

/* Where bodies rest at the start they touch: the pyramids and Jolt's pyramid stand box on box (gap 0,
 * nothing between), smash's block is a solid of touching boxes; the bench's own pyramids keep their
 * 0.05 m gaps, so the check can tell the difference. */
static void others_resting_bodies_touch(void **state)
{
    (void)state;
    const char *stacks[] = {"b2pyramid12", "b2pyramids5", "joltpyramid5"};
    for (int k = 0; k < 3; k++) {
        BenchScene *s = BenchSceneCreate(stacks[k]);
        assert_non_null(s);
        assert_true(boxes_rest_on_each_other(s, 0, 1e-12));
        assert_near(smallest_dynamic_gap(s), 0, 1e-12);
        assert_true(rows_touch(s, 1e-12));
        BenchSceneDestroy(s);
    }
    BenchScene *s = BenchSceneCreate("b2smash2");
    assert_non_null(s);
    assert_near(s->bodies[0].vel[2], 40, 0);
    for (int a = 1; a < s->bodyCount; a++) { /* six face neighbours where the block goes on */
        int touching = 0;
        for (int b = 1; b < s->bodyCount; b++) {
            double d[3] = {s->bodies[b].pos[0] - s->bodies[a].pos[0], s->bodies[b].pos[1] - s->bodies[a].pos[1],
                           s->bodies[b].pos[2] - s->bodies[a].pos[2]};
            touching += fabs(dot3(d, d) - 0.16) < 1e-12;
        }
        assert_true(touching >= 3);
    }
    assert_near(smallest_dynamic_gap(s), 0, 1e-12);
    BenchSceneDestroy(s);
    s = BenchSceneCreate("pyramid5"); /* the bench's own: rows with 0.05 m gaps */
    assert_non_null(s);
    assert_true(boxes_rest_on_each_other(s, 0, 1e-12));
    assert_false(rows_touch(s, 1e-12));
    BenchSceneDestroy(s);
}

/* y is up in the new scenes too: stacks rise along y from the ground, the joint grid hangs from its top
 * row, the rain's columns are 10 m apart in height, the motorised drum and bar turn about a horizontal
 * axis above the ground, and the spinner's contents sit inside its ring, in its lower half. */
static void others_are_y_up(void **state)
{
    (void)state;
    BenchScene *s = BenchSceneCreate("b2pyramid4");
    assert_non_null(s);
    assert_near(s->bodies[0].pos[1], 0.5, 0);
    assert_near(s->bodies[s->bodyCount - 1].pos[1], 3.5, 0);
    assert_near(s->bodies[s->bodyCount - 1].pos[2], 0, 1e-15);
    BenchSceneDestroy(s);
    s = BenchSceneCreate("joltpyramid3");
    assert_non_null(s);
    assert_int_equal(s->dynamicCount, 9 + 4 + 1);
    assert_near(s->bodies[0].pos[1], 1, 0);
    assert_near(s->bodies[s->bodyCount - 1].pos[1], 5, 0);
    BenchSceneDestroy(s);
    s = BenchSceneCreate("b2jointgrid10");
    assert_non_null(s);
    double top = -1e9;
    for (int i = 0; i < s->bodyCount; i++)
        top = fmax(top, s->bodies[i].pos[1]);
    int world = 0;
    for (int k = 0; k < s->jointCount; k++) {
        const BenchJoint *j = &s->joints[k];
        assert_near(j->axis[0], 1, 0); /* Box2D's revolute joints: hinges about the depth axis */
        if (j->body[1] < 0) {
            world++;
            assert_true(j->anchor[1] >= top - 0.5 - 1e-12); /* at the top row, or just below it */
        }
    }
    assert_int_equal(world, 7 + 2); /* below each static body, and beside the two ends of the static run */
    BenchSceneDestroy(s);
    s = BenchSceneCreate("b2rain10");
    assert_non_null(s);
    for (int k = 0; k < 10; k++) {
        double lowest = 1e9;
        for (int i = 11 * k; i < 11 * k + 11; i++) {
            double lo[3], hi[3];
            body_aabb(&s->bodies[i], lo, hi);
            lowest = fmin(lowest, lo[1]);
        }
        assert_near(lowest, 0.5 + 10 * (k % 5), 1e-9);
    }
    BenchSceneDestroy(s);
    s = BenchSceneCreate("b2tumbler3");
    assert_non_null(s);
    assert_int_equal(s->jointCount, 6);
    for (int k = 0; k < 6; k++) {
        const BenchJoint *j = &s->joints[k];
        assert_int_equal(j->body[1], -1);
        assert_true(j->motor);
        assert_near(j->motorSpeed, 25 * 3.14159265358979323846 / 180, 1e-15);
        assert_near(j->axis[0], 1, 0);
        assert_true(j->anchor[1] > 0);
    }
    for (int i = 6; i < s->bodyCount; i++) /* the contents inside the drum, around its axle */
        assert_true(fabs(s->bodies[i].pos[1] - s->joints[0].anchor[1]) < 3 &&
                    fabs(s->bodies[i].pos[2]) < 3 && fabs(s->bodies[i].pos[0]) < 1);
    BenchSceneDestroy(s);
    s = BenchSceneCreate("b2spinner");
    assert_non_null(s);
    assert_int_equal(s->jointCount, 1);
    const BenchJoint *bar = &s->joints[0];
    assert_true(bar->motor);
    assert_near(bar->motorSpeed, 5, 0);
    const BenchBody *barBody = &s->bodies[bar->body[0]];
    assert_true(barBody->size[1] > barBody->size[2]); /* standing: long along y */
    assert_near(barBody->pos[1] - barBody->size[1], 0.5, 1e-12);
    for (int i = 0; i < s->bodyCount; i++) {
        const BenchBody *b = &s->bodies[i];
        if (b->fixed || i == bar->body[0])
            continue;
        /* inside the ring (radius 10 about (y, z) = (10, 0)), in its lower part, clear of the bar */
        assert_true(hypot(b->pos[1] - 10, b->pos[2]) + 0.62 < 10);
        assert_true(b->pos[1] < 12.5);
        assert_true(fabs(b->pos[2]) - 0.5 > barBody->size[2]);
        assert_true(fabs(b->pos[0]) + 0.35 < s->container[1][0]);
    }
    BenchSceneDestroy(s);
}

/* The new figures: smash's centre of mass must follow its straight line (0 for poses on that line,
 * the offset for poses moved off it), and the escape count ignores bodies held by the world (the
 * tumbler's walls) but counts a box outside the drum. */
static void others_quality_figures(void **state)
{
    (void)state;
    double (*pos)[3], (*quat)[4];
    BenchQuality q;
    BenchScene *s = start("b2smash2", &q, &pos, &quat);
    const int steps = 30;
    for (int n = 0; n < steps; n++)
        BenchQualityObserve(s, &q, (const double(*)[3])pos, (const double(*)[4])quat);
    double t = steps * s->step, mass = total_mass(s, 0, s->bodyCount);
    /* all the momentum handed from the projectile to the block: the centre of mass moves alike */
    for (int i = 0; i < s->bodyCount; i++)
        pos[i][2] += s->bodies[0].mass * 40 * t / mass;
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 0, 1e-9);
    for (int i = 0; i < s->bodyCount; i++)
        pos[i][1] += 0.25;
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 0.25, 1e-9);
    free(pos), free(quat);
    BenchSceneDestroy(s);

    s = start("b2tumbler2", &q, &pos, &quat);
    for (int i = 0; i < 6; i++) /* the walls turned by 90 degrees: they stay out of the count */
        pos[i][2] += 10;
    BenchQualityObserve(s, &q, (const double(*)[3])pos, (const double(*)[4])quat);
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 0, 0);
    pos[s->bodyCount - 1][1] = -5;
    finish(s, &q, pos, quat, 1);
    assert_near(q.value, 1, 0);
    free(pos), free(quat);
    BenchSceneDestroy(s);
    assert_null(BenchSceneCreate("b2pyramid0"));
    assert_null(BenchSceneCreate("b2tumbler20")); /* would not fit in the drum */
    assert_null(BenchSceneCreate("joltragdolls-1"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(standard_scenes),     cmocka_unit_test(scene_names),
        cmocka_unit_test(joints_agree_at_start), cmocka_unit_test(joint_error_is_a_distance),
        cmocka_unit_test(quality_figures),     cmocka_unit_test(quaternions),
        cmocka_unit_test(inertia_by_integration), cmocka_unit_test(scenes_are_y_up),
        cmocka_unit_test(others_scenes),       cmocka_unit_test(others_resting_bodies_touch),
        cmocka_unit_test(others_are_y_up),     cmocka_unit_test(others_quality_figures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
