/* mcd_continuous_bench -- the cost of continuous collision (issue 18 point 4): a scene of many slow
 * bodies (400 boxes of 6.4 kg resting on a plane, kept awake) and a few fast ones (4 spheres of
 * 0.05 m fired at 100 m/s at a 2 cm wall, fired again when they stop or pass it), stepped through
 * MstUniverseStep at 1/60 s, z up.
 *   mcd_continuous_bench MODE [STEPS]    MODE: off (no flag), fast (the 4 spheres flagged), all
 * Prints ms per step (median of the steps after the first 60) and how many times a fast sphere went
 * through the wall. Instructions per step: run it under valgrind --tool=callgrind for two step
 * counts and divide the difference. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <karma/karma.h>

#define BOXES 400
#define FAST 4

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int byValue(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static void fire(MdtBodyID b, int i)
{
    MdtBodySetPosition(b, -3, (MeReal)(-0.6 + 0.4 * i), ME_R(0.5));
    MdtBodySetLinearVelocity(b, 100, 0, 0);
    MdtBodySetAngularVelocity(b, 0, 0, 0);
    MdtBodyEnable(b);
}

int main(int argc, char **argv)
{
    if (argc < 2 || (strcmp(argv[1], "off") && strcmp(argv[1], "fast") && strcmp(argv[1], "all"))) {
        fprintf(stderr, "usage: mcd_continuous_bench off|fast|all [STEPS]\n");
        return 2;
    }
    const int mode = !strcmp(argv[1], "off") ? 0 : !strcmp(argv[1], "fast") ? 1 : 2;
    const int steps = argc > 2 ? atoi(argv[2]) : 600;
    if (steps < 1)
        return 2;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = BOXES + FAST + 4;
    sizes.collisionModelsMaxCount = BOXES + FAST + 8;
    sizes.collisionPairsMaxCount = 16 * (BOXES + FAST);
    sizes.dynamicConstraintsMaxCount = 8 * (BOXES + FAST);
    sizes.massScale = 6;
    MstUniverseID u = MstUniverseCreate(&sizes);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, 0, ME_R(-9.81));
    MdtWorldSetAutoDisable(w, MEFALSE); /* the slow bodies keep costing what awake bodies cost */
    McdFrameworkID fw = MstUniverseGetFramework(u);
    static MeMatrix4 ground, wall;
    MeMatrix4TMMakeIdentity(ground);
    MeMatrix4TMMakeIdentity(wall);
    MeMatrix4TMSetPosition(wall, 0, 0, 1);
    MstFixedModelCreate(u, McdPlaneCreate(fw), ground);
    MstFixedModelCreate(u, McdBoxCreate(fw, ME_R(0.02), 2, 2), wall);
    McdGeometryID box = McdBoxCreate(fw, ME_R(0.4), ME_R(0.4), ME_R(0.4));
    for (int i = 0; i < BOXES; i++) {
        McdModelID m = MstModelAndBodyCreate(u, box, 100);
        if (mode == 2)
            McdModelEnableContinuous(m);
        /* a 20 x 20 grid away from the firing line, two layers staggered */
        MdtBodySetPosition(McdModelGetBody(m), (MeReal)(3 + 0.5 * (i % 20)), (MeReal)(-5 + 0.5 * (i / 20)),
                           (MeReal)(0.3 + 0.05 * (i % 3)));
    }
    MdtBodyID fast[FAST];
    McdGeometryID ball = McdSphereCreate(fw, ME_R(0.05));
    for (int i = 0; i < FAST; i++) {
        McdModelID m = MstModelAndBodyCreate(u, ball, 12000);
        if (mode >= 1)
            McdModelEnableContinuous(m);
        fast[i] = McdModelGetBody(m);
        fire(fast[i], i);
    }
    double *ms = malloc((size_t)steps * sizeof *ms);
    int through = 0;
    for (int s = 0; s < steps; s++) {
        double t0 = now();
        MstUniverseStep(u, ME_R(1.0) / 60);
        ms[s] = 1e3 * (now() - t0);
        for (int i = 0; i < FAST; i++) {
            MeVector3 x, v;
            MdtBodyGetPosition(fast[i], x);
            MdtBodyGetLinearVelocity(fast[i], v);
            if (x[0] > 0) { /* beyond the wall's middle: it went through */
                through++;
                fire(fast[i], i);
            } else if (MeVector3MagnitudeSqr(v) < ME_R(1.0)) {
                fire(fast[i], i);
            }
        }
    }
    int skip = steps > 120 ? 60 : 0;
    qsort(ms + skip, (size_t)(steps - skip), sizeof *ms, byValue);
    printf("%s: %d steps, median %.3f ms/step, fast spheres through the wall: %d\n", argv[1], steps,
           ms[skip + (steps - skip) / 2], through);
    free(ms);
    MstUniverseDestroy(u);
    return 0;
}
