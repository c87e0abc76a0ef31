/* mcd_space_bench.c -- cost of the farfield: McdSpaceUpdateAll + reading every pair, per step, for
 * spheres moving coherently in a box (about two neighbours each), 1,000 and 10,000 models, every
 * model moving every step.
 *
 * Usage: mcd_space_bench [steps]   (default 300). Prints one Markdown table row per (models, axes):
 * median wall-clock and processor-time milliseconds per step over the timed steps (the processor
 * time of this process is less inflated when other jobs share the machine), the best wall-clock
 * step, pairs reported per step (Hello + Staying), Hellos and Goodbyes per step, and the pairs lost
 * to a full pool (0 = the pool held them all). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <karma/Mcd.h>
#include <karma/McdSpace.h>
#include <karma/MeVersion.h>

static double nowMs(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static int cmpDouble(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static unsigned rng = 2463534242u;
static double uniform(double lo, double hi)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return lo + (hi - lo) * (double)(rng % 1000001u) / 1e6;
}

static void run(int n, int axes, int steps)
{
    double side = cbrt(4.0 * n); /* unit boxes (radius 0.5): ~8n/side^3 = 2 neighbours each */
    McdFrameworkID fw = McdInit(0, n + 1, 1, 1);
    /* One axis finds every overlap of the x intervals (~125 per model here): room for them all. */
    McdSpaceID space = McdSpaceAxisSortCreate(fw, axes, n, axes == McdAllAxes ? 8 * n : 120 * n);
    McdGeometryID ball = McdSphereCreate(fw, 0.5f);
    McdModelID *model = malloc((size_t)n * sizeof *model);
    double (*vel)[3] = malloc((size_t)n * sizeof *vel);
    for (int i = 0; i < n; i++) {
        model[i] = McdModelCreate(ball);
        MeMatrix4Ptr tm = McdModelGetTransformPtr(model[i]);
        for (int k = 0; k < 3; k++) {
            tm[3][k] = (MeReal)uniform(0, side);
            vel[i][k] = uniform(-0.05, 0.05); /* a twentieth of a diameter per step */
        }
        McdModelSetSortKey(model[i], i % 32768);
        McdSpaceInsertModel(space, model[i]);
    }
    McdSpaceBuild(space);
    McdModelPairContainer *c = McdModelPairContainerCreate(1024);
    McdSpacePairIterator it;
    double *wall = malloc((size_t)steps * sizeof *wall), *cpu = malloc((size_t)steps * sizeof *cpu);
    long pairs = 0, hellos = 0, goodbyes = 0;
    int timed = 0;
    for (int step = 0; step < steps; step++) {
        for (int i = 0; i < n; i++) { /* the application moves its models (not timed) */
            MeMatrix4Ptr tm = McdModelGetTransformPtr(model[i]);
            for (int k = 0; k < 3; k++) {
                tm[3][k] += (MeReal)vel[i][k];
                if (tm[3][k] < 0 || tm[3][k] > side)
                    vel[i][k] = -vel[i][k];
            }
        }
        double t0 = nowMs();
        clock_t c0 = clock();
        McdSpaceUpdateAll(space);
        McdSpaceEndChanges(space);
        McdSpacePairIteratorBegin(space, &it);
        long p = 0, h = 0, g = 0;
        MeBool more;
        do {
            more = McdSpaceGetPairs(space, &it, c);
            h += McdModelPairContainerGetHelloCount(c);
            g += McdModelPairContainerGetGoodbyeCount(c);
            p += McdModelPairContainerGetHelloCount(c) + McdModelPairContainerGetStayingCount(c);
        } while (more);
        McdSpaceBeginChanges(space);
        double dt = nowMs() - t0, dc = 1e3 * (double)(clock() - c0) / CLOCKS_PER_SEC;
        if (step >= 10) { /* after the first steps (first sort, caches) */
            wall[timed] = dt;
            cpu[timed] = dc;
            pairs += p;
            hellos += h;
            goodbyes += g;
            timed++;
        }
    }
    qsort(wall, (size_t)timed, sizeof *wall, cmpDouble);
    qsort(cpu, (size_t)timed, sizeof *cpu, cmpDouble);
    printf("| %d | %s | %.3f | %.3f | %.3f | %.1f | %.1f | %.1f | %d |\n", n,
           axes == McdAllAxes ? "xyz" : axes == McdXAxis ? "x" : "?", wall[timed / 2], cpu[timed / 2], wall[0],
           (double)pairs / timed, (double)hellos / timed, (double)goodbyes / timed, McdSpaceGetLostPairCount(space));
    fflush(stdout);
    free(wall);
    free(cpu);
    McdModelPairContainerDestroy(c);
    McdSpaceDestroy(space);
    McdTerm(fw);
    free(model);
    free(vel);
}

int main(int argc, char **argv)
{
    int steps = argc > 1 ? atoi(argv[1]) : 300;
    if (steps < 20)
        steps = 20;
    printf("McdSpace axis sort: UpdateAll + EndChanges + GetPairs (container 1024) + BeginChanges, %d steps "
           "(first 10 untimed), %s\n\n",
           steps, MeIsDoublePrecision() ? "double" : "float");
    printf("| models | axes | median ms/step (wall) | median ms/step (CPU) | best ms/step (wall) | pairs/step | "
           "Hello/step | Goodbye/step | lost |\n|---|---|---|---|---|---|---|---|---|\n");
    run(1000, McdAllAxes, steps);
    run(10000, McdAllAxes, steps);
    run(1000, McdXAxis, steps); /* one axis: many more pairs (10,000 models would hold ~6 million) */
    return 0;
}
