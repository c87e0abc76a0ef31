/* mcd_nearfield_bench -- pair tests per second for every built-in pair (sphere, box, cylinder,
 * sphyl, cone, and each against the plane), on 1024 random poses near contact (about two thirds
 * touching), contacts asked: 4. Usage: mcd_nearfield_bench [seconds per pair, default 0.3]. */
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

static void makeGeometry(McdGeometry *g, int type)
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
    printf("Karma Mcd nearfield benchmark (%s precision), %d poses per pair, maxContacts 4\n",
           sizeof(MeReal) == sizeof(double) ? "double" : "single", POSES);
    printf("%-18s %12s %10s %9s %9s\n", "pair", "tests/s", "ns/test", "touching", "contacts");
    for (k = 0; k < count; k++) {
        McdGeometry g1, g2;
        McdContact c[4];
        long tests = 0, touching = 0, contacts = 0;
        double t0, t1;
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
        do {
            for (i = 0; i < POSES; i++) {
                int n = table[k].fn(&g1, tm1[i], &g2, tm2[i], ME_R(0.01), c, 4, NULL);
                touching += n > 0;
                contacts += n;
            }
            tests += POSES;
            t1 = now();
        } while (t1 - t0 < budget);
        printf("%-18s %12.0f %10.1f %8.0f%% %9.2f\n", table[k].name, (double)tests / (t1 - t0),
               1e9 * (t1 - t0) / (double)tests, 100.0 * (double)touching / (double)tests,
               touching ? (double)contacts / (double)touching : 0.0);
    }
    return 0;
}
