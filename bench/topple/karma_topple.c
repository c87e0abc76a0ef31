/* karma_topple.c -- Topple's cost per step: Karma 1.2's benchmark scene (the guide, p.103: six stacks of
 * three to six cuboids, 0.054 ms a frame on a 1.4 GHz Pentium 4 with SSE), as demos/topple.c builds it.
 *
 *     karma_topple [--steps N] [--rounds R] [--perturb K]
 *
 * Each round builds the scene afresh and runs N steps (default: the scene's 600, 10 s: the stacks
 * settle, four balls are shot at them from 2 s on). Every call to DemoStep (MstUniverseStep: collision,
 * bridge, dynamics) is timed with CLOCK_MONOTONIC; a round reports the mean and the median ms a step,
 * the 99th percentile, and the mean per stage from the world's and the universe's profiles. The last
 * line gives the lowest mean and the lowest median of the rounds: on a loaded machine the best of a
 * few rounds is what repeats. For a figure that does not depend on the load, count instructions
 * (bench/topple/instructions.sh: callgrind at two step counts, the difference).
 *
 * --perturb K scales gravity by 1 + K 1e-6: a change far below anything visible that still sends the
 * scene down another of its chaotic runs (the balls hit the stacks a little differently, blocks fall
 * and sleep at other steps). A change of the solver's rounding does the same, so two builds whose
 * trajectories differ are compared over several K (bench/topple/perturbed.sh), not on one run. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "demo.h"

static const char *const stageNames[] = {"Partition", "AutoDisable", "Pack", "Solve", "Integrate", "Unpack"};
#define STAGE_COUNT ((int)(sizeof stageNames / sizeof stageNames[0]))

static double nowSeconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int compareDoubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* One round: returns its median ms a step and sets *mean (negative when the scene could not be
 * built). */
static double runRound(const DemoScene *scene, long steps, int round, long perturb, double *times, double *mean)
{
    DemoInstance demo;
    MeVector3 g;
    double sum = 0;
    if (!DemoCreate(scene, &demo))
        return -1;
    if (perturb != 0) {
        const MeReal scale = ME_R(1.0) + (MeReal)perturb * ME_R(1e-6);
        MdtWorldGetGravity(demo.world, g);
        MdtWorldSetGravity(demo.world, g[0] * scale, g[1] * scale, g[2] * scale);
    }
    for (long i = 0; i < steps; i++) {
        const double t0 = nowSeconds();
        DemoStep(&demo, scene->defaultStepSize);
        times[i] = 1e3 * (nowSeconds() - t0);
        sum += times[i];
    }
    const MeProfile *world = MdtWorldGetProfile(demo.world), *collision = MstUniverseGetProfile(demo.universe);
    const double perStep = 1e3 / (double)steps; /* profile seconds -> ms a step */
    *mean = sum / (double)steps;
    qsort(times, (size_t)steps, sizeof *times, compareDoubles);
    const double median = times[steps / 2], p99 = times[(steps * 99) / 100];
    printf("round %d: %ld steps, ms a step: mean %.4f median %.4f p99 %.4f | collision %.4f (farfield %.4f "
           "nearfield %.4f) | dynamics %.4f:",
           round, steps, sum / (double)steps, median, p99,
           MeProfileGetSectionTotal(collision, MST_SECTION_COLLISION) * perStep,
           MeProfileGetSectionTotal(collision, MST_SECTION_FARFIELD) * perStep,
           MeProfileGetSectionTotal(collision, MST_SECTION_NEARFIELD) * perStep,
           MeProfileGetSectionTotal(world, "Dynamics") * perStep);
    for (int s = 0; s < STAGE_COUNT; s++)
        printf(" %s %.4f", stageNames[s], MeProfileGetSectionTotal(world, stageNames[s]) * perStep);
    printf("\n");
    DemoDestroy(&demo);
    return median;
}

int main(int argc, char **argv)
{
    const DemoScene *scene = DemoSceneFind("topple");
    long steps = scene ? scene->defaultSteps : 0;
    int rounds = 5;
    long perturb = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc)
            steps = strtol(argv[++i], NULL, 10);
        else if (strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
            rounds = (int)strtol(argv[++i], NULL, 10);
        else if (strcmp(argv[i], "--perturb") == 0 && i + 1 < argc)
            perturb = strtol(argv[++i], NULL, 10);
        else {
            fprintf(stderr, "usage: karma_topple [--steps N] [--rounds R] [--perturb K]\n");
            return 2;
        }
    }
    if (!scene || steps < 1 || rounds < 1) {
        fprintf(stderr, "karma_topple: no topple scene, or steps/rounds below 1\n");
        return 2;
    }
    double *times = malloc(sizeof *times * (size_t)steps);
    double bestMedian = -1, bestMean = -1;
    if (!times)
        return 1;
    for (int r = 1; r <= rounds; r++) {
        double mean;
        const double median = runRound(scene, steps, r, perturb, times, &mean);
        if (median < 0) {
            fprintf(stderr, "karma_topple: the scene could not be built\n");
            free(times);
            return 1;
        }
        if (bestMedian < 0 || median < bestMedian)
            bestMedian = median;
        if (bestMean < 0 || mean < bestMean)
            bestMean = mean;
    }
    printf("best of %d rounds: mean %.4f ms a step, median %.4f\n", rounds, bestMean, bestMedian);
    free(times);
    return 0;
}
