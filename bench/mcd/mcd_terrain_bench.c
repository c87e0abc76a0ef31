/* mcd_terrain_bench -- the static triangle geometries (issue 18 point 3): the build of a triangle
 * mesh's AABB tree and adjacency for a 100k-triangle terrain, a box query of the tree against the
 * brute-force scan, and the pair tests of a sphere and a box resting on the mesh and on a 512 x 512
 * height field. Karma only (the peers' runs are issue 18 point 6). Argument: seconds per figure. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <karma/karma.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static MeReal heightAt(double x, double y) { return (MeReal)(0.5 * sin(0.3 * x) * cos(0.2 * y) + 0.1 * sin(1.7 * x + y)); }

/* The vertices and indices of a rolling terrain of n x n cells (2 n^2 triangles) over [0, n] m. */
static void terrainArrays(int n, MeVector3 **vertices, int **indices)
{
    int nv = (n + 1) * (n + 1), nt = 2 * n * n, t = 0;
    MeVector3 *v = malloc((size_t)nv * sizeof *v);
    int *idx = malloc((size_t)nt * 3 * sizeof *idx);
    for (int j = 0; j <= n; j++)
        for (int i = 0; i <= n; i++)
            MeVector3Set(v[j * (n + 1) + i], (MeReal)i, (MeReal)j, heightAt(i, j));
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            int tri[6] = {a, b, c, a, c, d};
            for (int k = 0; k < 6; k++)
                idx[3 * t + k] = tri[k];
            t += 2;
        }
    *vertices = v;
    *indices = idx;
}

/* ns per McdIntersect of `shape` resting at random places on `floor` (over [1, n-1]^2). */
static double pairCost(McdFrameworkID fw, McdModelID floor, McdGeometryID shape, int n, double budget, double *contacts)
{
    McdModelID m = McdModelCreate(shape);
    McdContact c[4];
    McdIntersectResult r = {0};
    r.contacts = c;
    r.contactMaxCount = 4;
    long tests = 0, total = 0;
    double t0 = now(), t1;
    (void)fw;
    srand(5);
    do {
        MeMatrix4Ptr tm = McdModelGetTransformPtr(m);
        MeReal x = 1 + (MeReal)(n - 2) * (MeReal)rand() / (MeReal)RAND_MAX;
        MeReal y = 1 + (MeReal)(n - 2) * (MeReal)rand() / (MeReal)RAND_MAX;
        MeMatrix4TMMakeIdentity(tm);
        MeMatrix4TMSetPosition(tm, x, y, heightAt(x, y) + ME_R(0.2));
        McdModelUpdate(m);
        McdModelPairID pair = McdModelPairCreate(m, floor);
        McdHello(pair);
        for (int k = 0; k < 100; k++) {
            McdIntersect(pair, &r);
            total += r.contactCount;
        }
        McdGoodbye(pair);
        McdModelPairDestroy(pair);
        tests += 100;
        t1 = now();
    } while (t1 - t0 < budget);
    McdModelDestroy(m);
    *contacts = (double)total / (double)tests;
    return 1e9 * (t1 - t0) / (double)tests;
}

/* The box query of the mesh's tree (vertices v, indices idx of an n x n terrain) against a scan of
 * every triangle's box, at random places: ns per query of each, printed. */
static void boxQueries(McdTriangleMeshID mesh, const MeVector3 *v, const int *idx, int n, double budget)
{
    const int nt = 2 * n * n;
    int *out = malloc((size_t)nt * sizeof *out);
    long queries = 0, found = 0;
    srand(3);
    double t0 = now(), t1;
    do {
        for (int k = 0; k < 1000; k++) {
            MeReal x = (MeReal)(n - 2) * (MeReal)rand() / (MeReal)RAND_MAX, y = (MeReal)(n - 2) * (MeReal)rand() / (MeReal)RAND_MAX;
            MeVector3 lo = {x, y, -2}, hi = {x + 1, y + 1, 2};
            found += McdTriangleMeshQueryBox(mesh, lo, hi, out, nt);
        }
        queries += 1000;
        t1 = now();
    } while (t1 - t0 < budget);
    double tree = 1e9 * (t1 - t0) / (double)queries, perQuery = (double)found / (double)queries;
    long scans = 0;
    static volatile long scanSink; /* keeps the scan from being optimised away */
    t0 = now();
    do {
        MeReal x = (MeReal)(n - 2) * (MeReal)rand() / (MeReal)RAND_MAX, y = (MeReal)(n - 2) * (MeReal)rand() / (MeReal)RAND_MAX;
        long hits = 0;
        for (int i = 0; i < nt; i++) {
            int ok = 1;
            for (int k = 0; k < 3 && ok; k++) {
                const MeReal *p = v[idx[3 * i + k]];
                ok = !(p[0] < x - 1 || p[0] > x + 2 || p[1] < y - 1 || p[1] > y + 2);
            }
            hits += ok;
        }
        scanSink += hits;
        scans++;
        t1 = now();
    } while (t1 - t0 < budget);
    double scan = 1e9 * (t1 - t0) / (double)scans;
    printf("box query (1 x 1 x 4 m, ~%.1f triangles found): tree %.0f ns, scan of all triangles %.0f ns\n",
           perQuery, tree, scan);
    free(out);
}

/* The pair tests of a sphere and a box resting on a 512 x 512 height field of the terrain: printed. */
static void heightFieldCosts(McdFrameworkID fw, double budget)
{
    const int g = 512;
    MeReal *h = malloc((size_t)g * g * sizeof *h);
    for (int j = 0; j < g; j++)
        for (int i = 0; i < g; i++)
            h[j * g + i] = heightAt(i, j);
    double t0 = now();
    McdRGHeightFieldID field = McdRGHeightFieldCreate(fw, h, g, g, 1, 1, 0, 0);
    double fieldBuild = now() - t0;
    McdModelID fieldModel = McdModelCreate(field);
    McdModelUpdate(fieldModel);
    double cs, cb;
    double sphereNs = pairCost(fw, fieldModel, McdSphereCreate(fw, ME_R(0.3)), g, budget, &cs);
    double boxNs = pairCost(fw, fieldModel, McdBoxCreate(fw, ME_R(0.5), ME_R(0.5), ME_R(0.5)), g, budget, &cb);
    printf("height field %d x %d (created in %.1f ms): sphere %.0f ns per McdIntersect (%.2f contacts), box %.0f ns "
           "(%.2f contacts)\n", g, g, 1e3 * fieldBuild, sphereNs, cs, boxNs, cb);
    free(h);
}

int main(int argc, char **argv)
{
    double budget = argc > 1 ? atof(argv[1]) : 0.5;
    McdFrameworkID fw = McdInit(0, 16, 0, 1);
    McdPrimitivesRegisterInteractions(fw);
    const int n = 224; /* 2 x 224^2 = 100,352 triangles */
    int nv = (n + 1) * (n + 1), nt = 2 * n * n;
    MeVector3 *v;
    int *idx;
    terrainArrays(n, &v, &idx);
    double t0 = now();
    McdTriangleMeshID mesh = McdTriangleMeshCreate(fw, (const MeVector3 *)v, nv, idx, nt);
    double build = now() - t0;
    printf("Karma Mcd terrain benchmark (%s precision)\n\n", sizeof(MeReal) == sizeof(double) ? "double" : "single");
    printf("triangle mesh of %d triangles: tree and adjacency built in %.1f ms\n", nt, 1e3 * build);

    boxQueries(mesh, (const MeVector3 *)v, idx, n, budget);

    McdModelID meshModel = McdModelCreate(mesh);
    McdModelUpdate(meshModel);
    double cs, cb;
    double sphereNs = pairCost(fw, meshModel, McdSphereCreate(fw, ME_R(0.3)), n, budget, &cs);
    double boxNs = pairCost(fw, meshModel, McdBoxCreate(fw, ME_R(0.5), ME_R(0.5), ME_R(0.5)), n, budget, &cb);
    printf("on the mesh: sphere (r 0.3) %.0f ns per McdIntersect (%.2f contacts), box (0.5 m) %.0f ns (%.2f contacts)\n",
           sphereNs, cs, boxNs, cb);

    heightFieldCosts(fw, budget);
    free(v);
    free(idx);
    McdTerm(fw);
    return 0;
}
