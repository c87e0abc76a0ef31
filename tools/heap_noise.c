/* heap_noise -- the velocity noise of settled heaps (tests/support/karma_heap.c), auto-disable off:
 * from 10 s to 20 s after the drop, per heap, the RMS and largest body speed and angular speed over
 * those steps, and the RMS of each second to show how it decays. World settings come from the
 * environment so that each candidate cause can be ablated alone:
 *   HN_ITER n (sweeps cap), HN_TOL t, HN_NNCG 0/1, HN_GAMMA g, HN_EPS e, HN_SOLVER d|i|a,
 *   HN_MAXCORR v (max correcting velocity), HN_DIRECTROWS n. HN_TRACE=1 also lists the bodies over a
 *   sleep threshold in more than a tenth of the steps, and the worst one's speed, spin and height.
 * Per heap it prints, besides RMS and largest, the median and 90th percentile of the bodies' speeds
 * (averaged over the steps) and the share of body-steps over the default sleep thresholds.
 *
 *   heap_noise [firstSeed [lastSeed [boxes]]]     defaults 1 10 120 */
#include <karma/karma.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "karma_heap.h"

#define STEP (ME_R(1.0) / 60)
#define FROM_S 10
#define TO_S 20
#define SLEEP_SPEED 0.1414 /* sqrt of the default thresholds on squared speeds */
#define SLEEP_SPIN 0.0316

static int byValue(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void configure(MdtWorldID w)
{
    const char *s;
    MdtWorldSetAutoDisable(w, 0);
    if ((s = getenv("HN_ITER")))
        MdtWorldSetMaxLCPIterations(w, atoi(s));
    if ((s = getenv("HN_TOL")))
        MdtWorldSetLCPTolerance(w, (MeReal)atof(s));
    if ((s = getenv("HN_NNCG")))
        MdtWorldSetNonsmoothCG(w, atoi(s) != 0);
    if ((s = getenv("HN_GAMMA")))
        MdtWorldSetGamma(w, (MeReal)atof(s));
    if ((s = getenv("HN_EPS")))
        MdtWorldSetEpsilon(w, (MeReal)atof(s));
    if ((s = getenv("HN_MAXCORR")))
        MdtWorldSetMaxCorrectingVelocity(w, (MeReal)atof(s));
    if ((s = getenv("HN_DIRECTROWS")))
        MdtWorldSetMaxDirectRows(w, atoi(s));
    if ((s = getenv("HN_SOLVER")))
        MdtWorldSetLCPSolver(w, s[0] == 'd' ? MdtLCPSolverDirect : s[0] == 'i' ? MdtLCPSolverIterative : MdtLCPSolverAuto);
}

#define STEPS ((TO_S - FROM_S) * 60)
#define MAX_BOXES 400

/* Sums over the measured steps, of one heap or of all. */
typedef struct Tally {
    double v2, w2, maxV, maxW, med, p90, over, iters, sec[TO_S - FROM_S][2];
    long count;
} Tally;

/* Per body and measured step: speed, spin and height, for HN_TRACE. */
static double traceV[STEPS][MAX_BOXES], traceW[STEPS][MAX_BOXES], traceZ[STEPS][MAX_BOXES];
static int overOf[MAX_BOXES];

/* One measured step's bodies into t (k: the step's index from FROM_S); sp is scratch for n speeds. */
static void tallyStep(Tally *t, int k, int n, MdtBodyID *body, double *sp)
{
    for (int i = 0; i < n; i++) {
        MeVector3 v, av, pos;
        MdtBodyGetLinearVelocity(body[i], v);
        MdtBodyGetAngularVelocity(body[i], av);
        MdtBodyGetPosition(body[i], pos);
        const double sv = MeVector3MagnitudeSqr(v), sw = MeVector3MagnitudeSqr(av);
        const int over = sqrt(sv) > SLEEP_SPEED || sqrt(sw) > SLEEP_SPIN;
        t->v2 += sv;
        t->w2 += sw;
        t->maxV = fmax(t->maxV, sqrt(sv));
        t->maxW = fmax(t->maxW, sqrt(sw));
        t->sec[k / 60][0] += sv;
        t->sec[k / 60][1] += sw;
        t->over += over;
        sp[i] = traceV[k][i] = sqrt(sv);
        traceW[k][i] = sqrt(sw);
        traceZ[k][i] = pos[2];
        overOf[i] += over;
    }
    qsort(sp, (size_t)n, sizeof(double), byValue);
    t->med += sp[n / 2];
    t->p90 += sp[n * 9 / 10];
    t->count += n;
}

/* The bodies over a threshold in more than a tenth of the steps, and the worst one's record. */
static void printTrace(int n)
{
    printf("   bodies over a threshold in more than 10 %% of steps:");
    int worst = 0;
    for (int i = 0; i < n; i++) {
        if (overOf[i] > STEPS / 10)
            printf(" %d(%d)", i, overOf[i]);
        if (overOf[i] > overOf[worst])
            worst = i;
    }
    printf("\n   body %d every 4th step (speed, spin, z):", worst);
    for (int k = 0; k < STEPS; k += 4)
        printf("%s%.3f/%.3f/%.3f", k % 40 ? " " : "\n    ", traceV[k][worst], traceW[k][worst], traceZ[k][worst]);
    printf("\n");
}

/* Drops and runs one heap, prints its line and adds it to *all; 0 when the universe was not made. */
static int measureHeap(unsigned long long seed, int n, MdtBodyID *body, double *sp, Tally *all)
{
    MstUniverseID u = karma_heap_build(n, seed, body);
    if (!u)
        return 0;
    configure(MstUniverseGetWorld(u));
    Tally t = {0};
    for (int i = 0; i < n; i++)
        overOf[i] = 0;
    for (int step = 1; step <= TO_S * 60; step++) {
        MstUniverseStep(u, STEP);
        if (step <= FROM_S * 60)
            continue;
        MdtSolverStats st;
        MdtWorldGetSolverStats(MstUniverseGetWorld(u), &st);
        t.iters += st.iterations;
        tallyStep(&t, step - FROM_S * 60 - 1, n, body, sp);
    }
    printf("seed %llu: rms %.4f m/s %.4f rad/s, max %.3f m/s %.3f rad/s, median %.4f p90 %.4f m/s, "
           "over sleep thresholds %.1f %%, sweeps/step %.1f\n",
           seed, sqrt(t.v2 / t.count), sqrt(t.w2 / t.count), t.maxV, t.maxW, t.med / STEPS, t.p90 / STEPS,
           100 * t.over / t.count, t.iters / STEPS);
    if (getenv("HN_TRACE"))
        printTrace(n);
    fflush(stdout);
    all->v2 += t.v2;
    all->w2 += t.w2;
    all->maxV = fmax(all->maxV, t.maxV);
    all->maxW = fmax(all->maxW, t.maxW);
    all->med += t.med / STEPS;
    all->p90 += t.p90 / STEPS;
    all->over += t.over;
    all->count += t.count;
    for (int k = 0; k < TO_S - FROM_S; k++) {
        all->sec[k][0] += t.sec[k][0];
        all->sec[k][1] += t.sec[k][1];
    }
    MstUniverseDestroy(u);
    return 1;
}

int main(int argc, char **argv)
{
    const unsigned long long first = argc > 1 ? strtoull(argv[1], NULL, 10) : 1;
    const unsigned long long last = argc > 2 ? strtoull(argv[2], NULL, 10) : 10;
    const int n = argc > 3 ? atoi(argv[3]) : 120;
    if (n < 1 || n > MAX_BOXES || last < first) {
        fprintf(stderr, "usage: heap_noise [firstSeed [lastSeed [boxes (1 to %d)]]]\n", MAX_BOXES);
        return 2;
    }
    MdtBodyID *body = malloc(sizeof(MdtBodyID) * (size_t)n);
    double *sp = malloc(sizeof(double) * (size_t)n);
    Tally all = {0};
    int heaps = 0;
    for (unsigned long long seed = first; seed <= last; seed++, heaps++)
        if (!measureHeap(seed, n, body, sp, &all))
            return 1;
    printf("%s, %d heaps: %d-%d s rms %.4f m/s %.4f rad/s, max %.3f m/s %.3f rad/s, median %.4f p90 %.4f m/s, "
           "over sleep thresholds %.1f %%; rms by second:",
           sizeof(MeReal) == sizeof(double) ? "double" : "float", heaps, FROM_S, TO_S, sqrt(all.v2 / all.count),
           sqrt(all.w2 / all.count), all.maxV, all.maxW, all.med / heaps, all.p90 / heaps, 100 * all.over / all.count);
    for (int k = 0; k < TO_S - FROM_S; k++)
        printf(" %.3f/%.3f", sqrt(all.sec[k][0] / (heaps * 60.0 * n)), sqrt(all.sec[k][1] / (heaps * 60.0 * n)));
    printf("\n");
    free(sp);
    free(body);
    return 0;
}
