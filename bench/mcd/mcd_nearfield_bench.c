/* mcd_nearfield_bench -- pair tests per second for every built-in pair (sphere, box, cylinder,
 * sphyl, cone, and each against the plane): the pair-table function itself (what McdIntersect calls
 * after the Hello-time lookup and swap), on 1024 random poses near contact (about half touching),
 * contact tolerance 0.01, contacts asked: 4. Usage: mcd_nearfield_bench [seconds per pair, default 0.3].
 * Prints one Markdown table row per pair: wall-clock and processor-time nanoseconds per test, tests
 * per second of processor time, the share of tests that report contacts, and contacts per test and per touching
 * test. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <karma/MeMath.h>

#include "mcd/nearfield/nearfield.h"

#define POSES 1024

static double now(void)
{
    struct timespec ts;
    timespec_get(&ts, TIME_UTC);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static MeU32 rngState = 12345u;
static MeReal uniform(MeReal lo, MeReal hi)
{
    rngState = rngState * 1664525u + 1013904223u;
    return lo + (hi - lo) * (MeReal)(rngState >> 8) / (MeReal)16777216.0;
}

static void makeGeometry(McdGeometryData *g, int type)
{
    memset(g, 0, sizeof *g);
    g->type = type;
    switch (type) {
    case kMcdGeometryTypeSphere: g->u.sphere.radius = ME_R(0.5); break;
    case kMcdGeometryTypeBox: MeVector3Set(g->u.box.radii, ME_R(0.5), ME_R(0.4), ME_R(0.3)); break;
    case kMcdGeometryTypeCylinder: g->u.cylinder.radius = ME_R(0.4); g->u.cylinder.halfHeight = ME_R(0.5); break;
    case kMcdGeometryTypeSphyl: g->u.sphyl.radius = ME_R(0.3); g->u.sphyl.halfHeight = ME_R(0.4); break;
    case kMcdGeometryTypeCone:
        /* radius 0.5 at the base, pointed, height 1: centroid a quarter up */
        g->u.cone.lowerRadius = ME_R(0.5);
        g->u.cone.zLower = -ME_R(0.25);
        g->u.cone.zUpper = ME_R(0.75);
        break;
    default: break;
    }
}

static void randomTM(MeMatrix4 tm, MeReal spread)
{
    MeVector4 q;
    MeQuaternionSet(q, uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    if (MeQuaternionNormalize(q) <= ME_R(0.0))
        MeQuaternionSetIdentity(q);
    MeQuaternionToTM(tm, q);
    MeMatrix4TMSetPosition(tm, uniform(-spread, spread), uniform(-spread, spread), uniform(-spread, spread));
}

int main(int argc, char **argv)
{
    static MeMatrix4 tm1[POSES], tm2[POSES];
    double budget = argc > 1 ? atof(argv[1]) : 0.3;
    int count, k;
    const McdNfPairEntry *table = McdNfPairTable(&count);
    printf("Karma Mcd nearfield benchmark (%s precision), %d poses per pair, maxContacts 4, %.2f s per pair\n\n",
           sizeof(MeReal) == sizeof(double) ? "double" : "single", POSES, budget);
    printf("| pair | ns/test (wall) | ns/test (CPU) | tests/s (CPU) | touching | contacts/test | "
           "contacts/touching test |\n|---|---|---|---|---|---|---|\n");
    for (k = 0; k < count; k++) {
        McdGeometryData g1, g2;
        McdContact c[4];
        long tests = 0, touching = 0, contacts = 0;
        double t0, t1;
        clock_t c0;
        int i;
        makeGeometry(&g1, table[k].type1);
        makeGeometry(&g2, table[k].type2);
        for (i = 0; i < POSES; i++) {
            randomTM(tm1[i], ME_R(0.0));
            randomTM(tm2[i], ME_R(1.0));
            if (table[k].type2 == kMcdGeometryTypePlane) /* the shape near the plane z = 0 */
                MeMatrix4TMSetPosition(tm1[i], uniform(-1, 1), uniform(-1, 1), uniform(-ME_R(0.1), ME_R(0.6)));
        }
        if (table[k].type2 == kMcdGeometryTypePlane)
            for (i = 0; i < POSES; i++)
                MeMatrix4TMMakeIdentity(tm2[i]);
        t0 = now();
        c0 = clock();
        do {
            for (i = 0; i < POSES; i++) {
                int n = table[k].fn(&g1, tm1[i], &g2, tm2[i], ME_R(0.01), c, 4, NULL);
                touching += n > 0;
                contacts += n;
            }
            tests += POSES;
            t1 = now();
        } while (t1 - t0 < budget);
        double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
        printf("| %s | %.1f | %.1f | %.3g | %.0f%% | %.2f | %.2f |\n", table[k].name, 1e9 * (t1 - t0) / (double)tests,
               1e9 * cpu / (double)tests, cpu > 0 ? (double)tests / cpu : 0.0, 100.0 * (double)touching / (double)tests,
               (double)contacts / (double)tests, touching ? (double)contacts / (double)touching : 0.0);
        fflush(stdout);
    }
    return 0;
}
