/* heap_noise -- the velocity noise of settled heaps (tests/support/karma_heap.c), auto-disable off:
 * from 10 s to 20 s after the drop, per heap, the RMS and largest body speed and angular speed over
 * those steps, and the RMS of each second to show how it decays. World settings come from the
 * environment so that each candidate cause can be ablated alone:
 *   HN_ITER n (sweeps cap), HN_TOL t, HN_NNCG 0/1, HN_GAMMA g, HN_EPS e, HN_SOLVER d|i|a,
 *   HN_MAXCORR v (max correcting velocity), HN_DIRECTROWS n.
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

int main(int argc, char **argv)
{
    const unsigned long long first = argc > 1 ? strtoull(argv[1], NULL, 10) : 1;
    const unsigned long long last = argc > 2 ? strtoull(argv[2], NULL, 10) : 10;
    const int n = argc > 3 ? atoi(argv[3]) : 120;
    if (n < 1 || last < first) {
        fprintf(stderr, "usage: heap_noise [firstSeed [lastSeed [boxes]]]\n");
        return 2;
    }
    MdtBodyID *body = malloc(sizeof(MdtBodyID) * (size_t)n);
    double allV2 = 0, allW2 = 0, allMaxV = 0, allMaxW = 0, sec[TO_S - FROM_S][2] = {{0}};
    double allMed = 0, allP90 = 0, allOver = 0;
    long allCount = 0;
    int heaps = 0;
    for (unsigned long long seed = first; seed <= last; seed++) {
        MstUniverseID u = karma_heap_build(n, seed, body);
        if (!u)
            return 1;
        configure(MstUniverseGetWorld(u));
        double v2 = 0, w2 = 0, maxV = 0, maxW = 0, iters = 0, med = 0, p90 = 0, over = 0;
        double *sp = malloc(sizeof(double) * (size_t)n);
        static double hv[600][400], hw[600][400], hz[600][400];
        static int overOf[400];
        for (int i = 0; i < n; i++)
            overOf[i] = 0;
        long count = 0;
        for (int step = 1; step <= TO_S * 60; step++) {
            MstUniverseStep(u, STEP);
            if (step <= FROM_S * 60)
                continue;
            MdtSolverStats st;
            MdtWorldGetSolverStats(MstUniverseGetWorld(u), &st);
            iters += st.iterations;
            for (int i = 0; i < n; i++) {
                MeVector3 v, av;
                MdtBodyGetLinearVelocity(body[i], v);
                MdtBodyGetAngularVelocity(body[i], av);
                const double sv = MeVector3MagnitudeSqr(v), sw = MeVector3MagnitudeSqr(av);
                v2 += sv;
                w2 += sw;
                maxV = fmax(maxV, sqrt(sv));
                maxW = fmax(maxW, sqrt(sw));
                sec[(step - 1) / 60 - FROM_S][0] += sv;
                sec[(step - 1) / 60 - FROM_S][1] += sw;
                sp[i] = sqrt(sv);
                hv[step - FROM_S * 60 - 1][i] = sqrt(sv);
                hw[step - FROM_S * 60 - 1][i] = sqrt(sw);
                MeVector3 pos;
                MdtBodyGetPosition(body[i], pos);
                hz[step - FROM_S * 60 - 1][i] = pos[2];
                overOf[i] += sqrt(sv) > SLEEP_SPEED || sqrt(sw) > SLEEP_SPIN;
                over += sqrt(sv) > SLEEP_SPEED || sqrt(sw) > SLEEP_SPIN;
            }
            qsort(sp, (size_t)n, sizeof(double), byValue);
            med += sp[n / 2];
            p90 += sp[n * 9 / 10];
            count += n;
        }
        const double steps = (TO_S - FROM_S) * 60.0;
        printf("seed %llu: rms %.4f m/s %.4f rad/s, max %.3f m/s %.3f rad/s, median %.4f p90 %.4f m/s, "
               "over sleep thresholds %.1f %%, sweeps/step %.1f\n",
               seed, sqrt(v2 / count), sqrt(w2 / count), maxV, maxW, med / steps, p90 / steps, 100 * over / count,
               iters / steps);
        if (getenv("HN_TRACE")) {
            printf("   bodies over a threshold in more than 10 %% of steps:");
            int worst = 0;
            for (int i = 0; i < n; i++) {
                if (overOf[i] > 60)
                    printf(" %d(%d)", i, overOf[i]);
                if (overOf[i] > overOf[worst])
                    worst = i;
            }
            printf("\n   body %d every 4th step (speed, spin, z):", worst);
            for (int k = 0; k < 600; k += 4)
                printf("%s%.3f/%.3f/%.3f", k % 40 ? " " : "\n    ", hv[k][worst], hw[k][worst], hz[k][worst]);
            printf("\n");
        }
        allMed += med / steps;
        allP90 += p90 / steps;
        allOver += over;
        free(sp);
        fflush(stdout);
        allV2 += v2;
        allW2 += w2;
        allCount += count;
        allMaxV = fmax(allMaxV, maxV);
        allMaxW = fmax(allMaxW, maxW);
        heaps++;
        MstUniverseDestroy(u);
    }
    printf("%s, %d heaps: %d-%d s rms %.4f m/s %.4f rad/s, max %.3f m/s %.3f rad/s, median %.4f p90 %.4f m/s, "
           "over sleep thresholds %.1f %%; rms by second:",
           sizeof(MeReal) == sizeof(double) ? "double" : "float", heaps, FROM_S, TO_S, sqrt(allV2 / allCount),
           sqrt(allW2 / allCount), allMaxV, allMaxW, allMed / heaps, allP90 / heaps, 100 * allOver / allCount);
    for (int s = 0; s < TO_S - FROM_S; s++)
        printf(" %.3f/%.3f", sqrt(sec[s][0] / (heaps * 60.0 * n)), sqrt(sec[s][1] / (heaps * 60.0 * n)));
    printf("\n");
    free(body);
    return 0;
}
