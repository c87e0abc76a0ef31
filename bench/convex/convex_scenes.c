/* convex_scenes.c -- the scenes, the penetration measure and the runner of convex_scenes.h. */
#define _POSIX_C_SOURCE 199309L
#include "convex_scenes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef CVX_HAVE_CALLGRIND
#include <valgrind/callgrind.h>
#else /* no valgrind headers: the instruction counts are unavailable, the timings are not */
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define RUNNING_ON_VALGRIND 0
#endif

static const double kPi = 3.14159265358979323846;

/* A small deterministic generator, the same stream on every platform. */
static unsigned long long rngState;
static void rng_seed(unsigned long long s) { rngState = s * 0x9E3779B97F4A7C15ULL + 1; }
static double rnd(void)
{
    rngState ^= rngState << 13;
    rngState ^= rngState >> 7;
    rngState ^= rngState << 17;
    return (double)(rngState >> 11) / 9007199254740992.0;
}
static double rnd_in(double a, double b) { return a + (b - a) * rnd(); }

static void random_quat(double q[4])
{
    double u1 = rnd(), u2 = 2 * kPi * rnd(), u3 = 2 * kPi * rnd();
    q[0] = sqrt(1 - u1) * sin(u2);
    q[1] = sqrt(1 - u1) * cos(u2);
    q[2] = sqrt(u1) * sin(u3);
    q[3] = sqrt(u1) * cos(u3);
}

static void random_dir(double d[3])
{
    double z = rnd_in(-1, 1), a = rnd_in(0, 2 * kPi), r = sqrt(1 - z * z);
    d[0] = r * cos(a);
    d[1] = r * sin(a);
    d[2] = z;
}

/* v rotated by the unit quaternion q (w, x, y, z). */
static void rotate(const double q[4], const double v[3], double out[3])
{
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double tx = 2 * (y * v[2] - z * v[1]), ty = 2 * (z * v[0] - x * v[2]), tz = 2 * (x * v[1] - y * v[0]);
    out[0] = v[0] + w * tx + (y * tz - z * ty);
    out[1] = v[1] + w * ty + (z * tx - x * tz);
    out[2] = v[2] + w * tz + (x * ty - y * tx);
}

/* A random hull cloud: 10-30 points on an ellipsoid of semi-axes 0.25-0.45 m, inside points included. */
static void random_hull(CvxHull *h)
{
    double axes[3] = {rnd_in(0.25, 0.45), rnd_in(0.25, 0.45), rnd_in(0.25, 0.45)};
    h->count = 10 + (int)(rnd() * 21);
    h->p = malloc((size_t)h->count * sizeof *h->p);
    for (int i = 0; i < h->count; i++) {
        double d[3], r = i % 5 == 4 ? 0.5 : 1; /* every fifth point inside: the builder drops it */
        random_dir(d);
        for (int k = 0; k < 3; k++)
            h->p[i][k] = r * axes[k] * d[k];
    }
    /* the origin (the body's centre of mass here) at the points' mean, which is inside their hull
     * (ODE asks for the origin inside its convex) */
    double mean[3] = {0, 0, 0};
    for (int i = 0; i < h->count; i++)
        for (int k = 0; k < 3; k++)
            mean[k] += h->p[i][k] / h->count;
    for (int i = 0; i < h->count; i++)
        for (int k = 0; k < 3; k++)
            h->p[i][k] -= mean[k];
}

static double terrain_height(double x, double y)
{
    return 0.6 * sin(0.3 * x) * cos(0.2 * y) + 0.15 * sin(0.7 * x + 0.5 * y);
}

double CvxFloorHeight(const CvxScene *s, double x, double y)
{
    if (s->floor == CVX_GROUND)
        return 0;
    int n = s->side;
    int i = (int)floor(x), j = (int)floor(y);
    if (i < 0 || j < 0 || i >= n - 1 || j >= n - 1)
        return -1e9; /* off the terrain: nothing to penetrate */
    double fx = x - i, fy = y - j;
    const double *h = s->heights;
    double ha = h[j * n + i], hb = h[j * n + i + 1], hc = h[(j + 1) * n + i + 1], hd = h[(j + 1) * n + i];
    if (fx >= fy) /* triangle (i,j) (i+1,j) (i+1,j+1) */
        return ha + fx * (hb - ha) + fy * (hc - hb);
    return ha + fy * (hd - ha) + fx * (hc - hd); /* triangle (i,j) (i+1,j+1) (i,j+1) */
}

/* Directions sampling a sphere: the poles and 11 rings of 24. */
static double sphereDirs[2 + 11 * 24][3];
static int sphereDirCount;
static void make_sphere_dirs(void)
{
    if (sphereDirCount)
        return;
    sphereDirs[sphereDirCount][0] = 0, sphereDirs[sphereDirCount][1] = 0, sphereDirs[sphereDirCount++][2] = -1;
    sphereDirs[sphereDirCount][0] = 0, sphereDirs[sphereDirCount][1] = 0, sphereDirs[sphereDirCount++][2] = 1;
    for (int r = 1; r <= 11; r++)
        for (int a = 0; a < 24; a++) {
            double th = kPi * r / 12, ph = 2 * kPi * a / 24;
            double *d = sphereDirs[sphereDirCount++];
            d[0] = sin(th) * cos(ph), d[1] = sin(th) * sin(ph), d[2] = -cos(th);
        }
}

static double point_depth(const CvxScene *s, const double p[3])
{
    double d = CvxFloorHeight(s, p[0], p[1]) - p[2];
    return d > 0 ? d : 0;
}

double CvxBodyDepth(const CvxScene *s, int i, const double pos[3], const double quat[4])
{
    const CvxBody *b = &s->bodies[i];
    double worst = 0, local[3], w[3];
    make_sphere_dirs();
#define CVX_SAMPLE()                                                                                              \
    do {                                                                                                         \
        rotate(quat, local, w);                                                                                  \
        for (int k_ = 0; k_ < 3; k_++)                                                                           \
            w[k_] += pos[k_];                                                                                    \
        double d_ = point_depth(s, w);                                                                           \
        if (d_ > worst)                                                                                          \
            worst = d_;                                                                                          \
    } while (0)
    switch (b->shape) {
    case CVX_BOX: /* corners, edge middles and face centres */
        for (int x = -1; x <= 1; x++)
            for (int y = -1; y <= 1; y++)
                for (int z = -1; z <= 1; z++) {
                    local[0] = x * b->size[0], local[1] = y * b->size[1], local[2] = z * b->size[2];
                    CVX_SAMPLE();
                }
        break;
    case CVX_SPHERE:
    case CVX_CAPSULE:
        for (int e = -1; e <= 1; e += 2)
            for (int k = 0; k < sphereDirCount; k++) {
                double half = b->shape == CVX_CAPSULE ? b->size[1] : 0;
                for (int c = 0; c < 3; c++)
                    local[c] = b->size[0] * sphereDirs[k][c];
                local[2] += e * half;
                CVX_SAMPLE();
            }
        break;
    case CVX_HULL:
        for (int k = 0; k < s->hulls[b->hull].count; k++) {
            memcpy(local, s->hulls[b->hull].p[k], sizeof local);
            CVX_SAMPLE();
        }
        break;
    }
#undef CVX_SAMPLE
    return worst;
}

static void set_inertia(CvxBody *b)
{
    double m = b->mass, x = b->size[0], y = b->size[1], z = b->size[2];
    switch (b->shape) {
    case CVX_BOX:
        b->inertia[0] = m * (y * y + z * z) / 3, b->inertia[1] = m * (x * x + z * z) / 3,
        b->inertia[2] = m * (x * x + y * y) / 3;
        break;
    case CVX_SPHERE:
        b->inertia[0] = b->inertia[1] = b->inertia[2] = 0.4 * m * x * x;
        break;
    case CVX_CAPSULE: /* as the cylinder of its whole length: close enough, and the same everywhere */
    {
        double l = 2 * (y + x);
        b->inertia[0] = b->inertia[1] = m * (3 * x * x + l * l) / 12;
        b->inertia[2] = 0.5 * m * x * x;
        break;
    }
    case CVX_HULL: /* as the solid sphere of radius 0.35 m */
        b->inertia[0] = b->inertia[1] = b->inertia[2] = 0.4 * m * 0.35 * 0.35;
        break;
    }
}

CvxScene *CvxSceneCreate(const char *name)
{
    CvxScene *s = calloc(1, sizeof *s);
    s->step = 1.0 / 60;
    s->gravity = 9.81;
    s->friction = 0.6;
    s->steps = 300;
    s->bodyCount = 1000;
    s->bodies = calloc((size_t)s->bodyCount, sizeof *s->bodies);
    rng_seed(18);
    if (strcmp(name, "pile") == 0) {
        s->name = "pile";
        s->what = "1,000 random hulls (10-30 points) dropped in a 10 x 10 x 10 lattice (1.2 m) onto the ground";
        s->floor = CVX_GROUND;
    } else if (strcmp(name, "mesh") == 0) {
        s->name = "mesh";
        s->what = "1,000 mixed bodies (boxes, spheres, capsules, hulls) onto a 100,352-triangle wavy mesh";
        s->floor = CVX_MESH;
        s->side = 225;
    } else if (strcmp(name, "field") == 0) {
        s->name = "field";
        s->what = "1,000 mixed bodies (boxes, spheres, capsules, hulls) onto a 512 x 512 height field";
        s->floor = CVX_FIELD;
        s->side = 512;
    } else {
        free(s->bodies);
        free(s);
        return NULL;
    }
    if (s->side) {
        int n = s->side;
        s->heights = malloc((size_t)n * n * sizeof *s->heights);
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++)
                s->heights[j * n + i] = terrain_height(i, j);
        if (s->floor == CVX_MESH) {
            s->triangleCount = 2 * (n - 1) * (n - 1);
            s->indices = malloc((size_t)s->triangleCount * 3 * sizeof *s->indices);
            int t = 0;
            for (int j = 0; j < n - 1; j++)
                for (int i = 0; i < n - 1; i++) {
                    int a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
                    int tri[6] = {a, b, c, a, c, d};
                    memcpy(s->indices + 6 * t, tri, sizeof tri);
                    t++;
                }
        }
    }
    s->hulls = calloc((size_t)s->bodyCount, sizeof *s->hulls);
    double cx = s->side ? 0.5 * (s->side - 1) : 0;
    for (int i = 0; i < s->bodyCount; i++) {
        CvxBody *b = &s->bodies[i];
        int ix = i % 10, iy = (i / 10) % 10, iz = i / 100;
        int kind = s->floor == CVX_GROUND ? 3 : i % 4;
        b->shape = (CvxShape)kind;
        b->mass = 1;
        switch (b->shape) {
        case CVX_BOX:
            b->size[0] = rnd_in(0.2, 0.35), b->size[1] = rnd_in(0.2, 0.35), b->size[2] = rnd_in(0.2, 0.35);
            break;
        case CVX_SPHERE:
            b->size[0] = rnd_in(0.25, 0.4);
            break;
        case CVX_CAPSULE:
            b->size[0] = rnd_in(0.15, 0.25), b->size[1] = rnd_in(0.15, 0.3);
            break;
        case CVX_HULL:
            b->hull = s->hullCount++;
            random_hull(&s->hulls[b->hull]);
            break;
        }
        set_inertia(b);
        b->pos[0] = cx + 1.2 * (ix - 4.5) + rnd_in(-0.05, 0.05);
        b->pos[1] = cx + 1.2 * (iy - 4.5) + rnd_in(-0.05, 0.05);
        b->pos[2] = CvxFloorHeight(s, b->pos[0], b->pos[1]) + 0.7 + 1.2 * iz;
        random_quat(b->quat);
    }
    return s;
}

void CvxSceneDestroy(CvxScene *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->hullCount; i++)
        free(s->hulls[i].p);
    free(s->hulls);
    free(s->bodies);
    free(s->heights);
    free(s->indices);
    free(s);
}

CvxPairSet *CvxPairSetCreate(int count)
{
    CvxPairSet *p = calloc(1, sizeof *p);
    rng_seed(6);
    p->hullCount = 64;
    p->hulls = calloc((size_t)p->hullCount, sizeof *p->hulls);
    for (int i = 0; i < p->hullCount; i++)
        random_hull(&p->hulls[i]);
    p->count = count;
    p->hull = malloc((size_t)count * sizeof *p->hull);
    p->pos = malloc((size_t)count * sizeof *p->pos);
    p->quat = malloc((size_t)count * sizeof *p->quat);
    for (int i = 0; i < count; i++) {
        double d[3], r = rnd_in(0.35, 0.95); /* hull radii 0.25-0.45 m: about half touch */
        p->hull[i][0] = (int)(rnd() * p->hullCount) % p->hullCount;
        p->hull[i][1] = (int)(rnd() * p->hullCount) % p->hullCount;
        random_dir(d);
        for (int k = 0; k < 3; k++) {
            p->pos[i][0][k] = 0;
            p->pos[i][1][k] = r * d[k];
        }
        random_quat(p->quat[i][0]);
        random_quat(p->quat[i][1]);
    }
    return p;
}

void CvxPairSetDestroy(CvxPairSet *p)
{
    if (!p)
        return;
    for (int i = 0; i < p->hullCount; i++)
        free(p->hulls[i].p);
    free(p->hulls);
    free(p->hull);
    free(p->pos);
    free(p->quat);
    free(p);
}

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void run_pairs(const CvxEngine *e, double seconds)
{
    CvxPairSet *p = CvxPairSetCreate(1024);
    void *pw = e->pairsCreate(p);
    long contacts = 0, touching = 0, tests = 0;
    e->pairsRun(pw, 1, &contacts, &touching); /* warm the caches */
    contacts = touching = 0;
    if (RUNNING_ON_VALGRIND) { /* callgrind: two rounds, instructions / 2,048 = per test */
        CALLGRIND_START_INSTRUMENTATION;
        e->pairsRun(pw, 2, &contacts, &touching);
        CALLGRIND_STOP_INSTRUMENTATION;
        printf("| %s | pairs | %d tests instrumented |\n", e->name, 2 * p->count);
        e->pairsDestroy(pw);
        CvxPairSetDestroy(p);
        return;
    }
    double t0 = cpu_now(), t1;
    do {
        e->pairsRun(pw, 10, &contacts, &touching);
        tests += 10L * p->count;
        t1 = cpu_now();
    } while (t1 - t0 < seconds);
    printf("| %s | pairs | hull-hull, 1,024 random poses | %.0f ns/test | %.2f M tests/s | %.1f%% touching | %.2f "
           "contacts/test |\n",
           e->name, 1e9 * (t1 - t0) / (double)tests, 1e-6 * (double)tests / (t1 - t0),
           100.0 * (double)touching / (double)tests, (double)contacts / (double)tests);
    e->pairsDestroy(pw);
    CvxPairSetDestroy(p);
}

static void run_scene(const CvxEngine *e, const char *name, int steps, int from)
{
    CvxScene *s = CvxSceneCreate(name);
    if (!s) {
        fprintf(stderr, "unknown scene %s\n", name);
        return;
    }
    if (steps > 0)
        s->steps = steps;
    double c0 = cpu_now();
    void *w = e->create(s);
    double build = cpu_now() - c0;
    if (!w) {
        printf("| %s | %s | world not created |\n", e->name, s->name);
        CvxSceneDestroy(s);
        return;
    }
    double *times = malloc((size_t)s->steps * sizeof *times), total = 0, contacts = 0, runMax = 0;
    double (*pos)[3] = malloc((size_t)s->bodyCount * sizeof *pos);
    double (*quat)[4] = malloc((size_t)s->bodyCount * sizeof *quat);
    for (int k = 0; k < s->steps; k++) {
        if (k == from)
            CALLGRIND_START_INSTRUMENTATION;
        double t0 = cpu_now();
        e->step(w);
        times[k] = cpu_now() - t0;
        total += times[k];
        contacts += e->contacts(w);
        if (k % 10 == 9 && !RUNNING_ON_VALGRIND) { /* the deepest body over the run, outside the timing */
            e->read(w, pos, quat);
            for (int i = 0; i < s->bodyCount; i++)
                if (isfinite(pos[i][2]) && pos[i][2] > CvxFloorHeight(s, pos[i][0], pos[i][1]) - 1) {
                    double d = CvxBodyDepth(s, i, pos[i], quat[i]);
                    runMax = d > runMax ? d : runMax;
                }
        }
    }
    CALLGRIND_STOP_INSTRUMENTATION;
    e->read(w, pos, quat);
    double maxDepth = 0, sumDepth = 0;
    int fell = 0, nonfinite = 0;
    for (int i = 0; i < s->bodyCount; i++) {
        if (!isfinite(pos[i][0] + pos[i][1] + pos[i][2])) {
            nonfinite++;
            continue;
        }
        if (pos[i][2] < CvxFloorHeight(s, pos[i][0], pos[i][1]) - 1) {
            fell++;
            continue;
        }
        double d = CvxBodyDepth(s, i, pos[i], quat[i]);
        sumDepth += d;
        if (d > maxDepth)
            maxDepth = d;
        if (d > 0.01 && getenv("CVX_VERBOSE")) /* which bodies sink: shape, depth, position */
            fprintf(stderr, "  body %d (shape %d) %.1f mm deep at (%.2f %.2f %.2f)\n", i, (int)s->bodies[i].shape,
                    1e3 * d, pos[i][0], pos[i][1], pos[i][2]);
    }
    int counted = s->bodyCount - fell - nonfinite;
    qsort(times, (size_t)s->steps, sizeof *times, cmp_double);
    printf("| %s | %s | %d | %d | %.1f | %.3f | %.3f | %.0f | %.2f | %.3f | %.2f | %d | %d |\n", e->name, s->name,
           s->bodyCount, s->steps, 1e3 * build, 1e3 * times[s->steps / 2], 1e3 * total / s->steps,
           contacts / s->steps, 1e3 * maxDepth, counted ? 1e3 * sumDepth / counted : 0, 1e3 * runMax, fell, nonfinite);
    fflush(stdout);
    free(times);
    free(pos);
    free(quat);
    e->destroy(w);
    CvxSceneDestroy(s);
}

int CvxMain(int argc, char **argv, const CvxEngine *e)
{
    int steps = 0, from = 0, named = 0;
    double seconds = 1;
    for (int i = 1; i < argc; i++) {
        if (strncmp(argv[i], "--steps=", 8) == 0)
            steps = atoi(argv[i] + 8);
        else if (strncmp(argv[i], "--from=", 7) == 0)
            from = atoi(argv[i] + 7);
        else if (strncmp(argv[i], "--seconds=", 10) == 0)
            seconds = atof(argv[i] + 10);
    }
    fprintf(stderr, "%s: %s\n", e->name, e->settings);
    for (int i = 1; i < argc; i++) {
        if (argv[i][0] == '-')
            continue;
        named++;
        if (strcmp(argv[i], "pairs") == 0)
            run_pairs(e, seconds);
        else
            run_scene(e, argv[i], steps, from);
    }
    if (!named) {
        run_pairs(e, seconds);
        run_scene(e, "pile", steps, from);
        run_scene(e, "mesh", steps, from);
        run_scene(e, "field", steps, from);
    }
    return 0;
}
