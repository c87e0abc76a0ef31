/* pool_overhead.c -- what one task costs on the default pool (MeThreadPool.h) beyond its work (issue 17
 * point 5): the wall time of MeThreadPoolEnqueue for an empty task of 2 items (1 per range, so both
 * threads take part), and for tasks of N tiny items (a few multiply-adds each, ranges of minRange), set
 * against the same items run inline on the calling thread. Between tasks the caller does `gap`
 * microseconds of its own work, as the step does between its stages (0: back to back).
 *
 * Each figure is the minimum and the median over many repetitions: the minimum is what a hand-over
 * costs when the helpers get a core at once (robust to the load of a shared machine), the median what
 * it typically costs.
 *
 *   pool_overhead [THREADS=2] [REPETITIONS=20000]
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <MeThreadPool.h>

static double nowNs(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e9 * (double)t.tv_sec + (double)t.tv_nsec;
}

/* A tiny item: a few dependent multiply-adds on its own slot (about 10 ns). */
static double slots[1 << 16];

static void tinyItems(int start, int end, int worker, void *data)
{
    (void)worker;
    int work = *(const int *)data;
    for (int i = start; i < end; i++) {
        double x = slots[i];
        for (int k = 0; k < work; k++)
            x = x * 0.999 + 0.5;
        slots[i] = x;
    }
}

static void emptyTask(int start, int end, int worker, void *data)
{
    (void)start;
    (void)end;
    (void)worker;
    (void)data;
}

/* Keep the caller busy for about `ns` nanoseconds (the step's own work between two stages). */
static void busyFor(double ns)
{
    double until = nowNs() + ns;
    while (nowNs() < until) {
    }
}

static int compareDoubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Min and median wall ns of `reps` calls of the task over `items` in ranges of `minRange`, on `pool`
 * (NULL: inline on the caller). */
/* Size: the task and its split (items, minRange, work), the gap and repetitions, and the two results. */
static void measure(MeThreadPool *pool, MdtTaskFnPtr task, int items, int minRange, int work, double gapNs, int reps,
                    double *minNs, double *medianNs)
{
    double *t = malloc(sizeof *t * (size_t)reps);
    if (!t) {
        *minNs = *medianNs = -1;
        return;
    }
    for (int r = 0; r < reps; r++) {
        if (gapNs > 0)
            busyFor(gapNs);
        double t0 = nowNs();
        if (pool)
            MeThreadPoolEnqueue(task, items, minRange, &work, pool);
        else
            task(0, items, 0, &work);
        t[r] = nowNs() - t0;
    }
    qsort(t, (size_t)reps, sizeof *t, compareDoubles);
    *minNs = t[0];
    *medianNs = t[reps / 2];
    free(t);
}

int main(int argc, char **argv)
{
    int threads = argc > 1 ? atoi(argv[1]) : 2;
    int reps = argc > 2 ? atoi(argv[2]) : 20000;
    if (threads < 2 || reps < 1) {
        fprintf(stderr, "usage: pool_overhead [THREADS >= 2] [REPETITIONS >= 1]\n");
        return 2;
    }
    MeThreadPool *pool = MeThreadPoolCreate(threads);
    if (!pool)
        return 1;
    printf("pool of %d threads, %d repetitions; wall ns per task: min / median\n", threads, reps);
    printf("%-34s %8s %19s %19s\n", "task", "gap us", "inline", "pool");
    const double gaps[] = {0, 20};
    for (int g = 0; g < 2; g++) {
        double inMin, inMed, poolMin, poolMed;
        measure(NULL, emptyTask, 2, 1, 0, 1000 * gaps[g], reps, &inMin, &inMed);
        measure(pool, emptyTask, 2, 1, 0, 1000 * gaps[g], reps, &poolMin, &poolMed);
        printf("%-34s %8.0f %9.0f / %7.0f %9.0f / %7.0f\n", "empty, 2 items of 1", gaps[g], inMin, inMed, poolMin,
               poolMed);
    }
    const struct {
        int items, minRange, work;
    } cases[] = {{64, 4, 10}, {256, 32, 10}, {1000, 64, 10}, {4000, 64, 10}, {100, 1, 200}, {1000, 32, 100}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (int g = 0; g < 2; g++) {
            double inMin, inMed, poolMin, poolMed;
            char name[64];
            snprintf(name, sizeof name, "%d items of %d madds, min %d", cases[c].items, cases[c].work,
                     cases[c].minRange);
            measure(NULL, tinyItems, cases[c].items, cases[c].minRange, cases[c].work, 1000 * gaps[g], reps / 4,
                    &inMin, &inMed);
            measure(pool, tinyItems, cases[c].items, cases[c].minRange, cases[c].work, 1000 * gaps[g], reps / 4,
                    &poolMin, &poolMed);
            printf("%-34s %8.0f %9.0f / %7.0f %9.0f / %7.0f\n", name, gaps[g], inMin, inMed, poolMin, poolMed);
        }
    MeThreadPoolDestroy(pool);
    return 0;
}
