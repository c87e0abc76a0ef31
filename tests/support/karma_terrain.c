/* karma_terrain.c -- flat tessellated floors for the terrain tests (see karma_terrain.h). */
#include "karma_terrain.h"

#include <stdint.h>
#include <stdlib.h>

#define LIST_MAX 8192

static MeVector3 listVertices[LIST_MAX][3];
static MeVector3 listNormals[LIST_MAX];
static int listFlags[LIST_MAX];
static int listCount, listCalls;
static McdModelPair *listLastPair;

static double lcg(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (double)(*s >> 8) / 16777216.0;
}

McdTriangleMeshID karma_floor_mesh(McdFrameworkID fw, double half, int cells, double jitter, unsigned seed)
{
    int nv = (cells + 1) * (cells + 1), nt = 2 * cells * cells;
    MeVector3 *v = malloc((size_t)nv * sizeof *v);
    int *idx = malloc((size_t)nt * 3 * sizeof *idx);
    double step = 2 * half / cells;
    for (int j = 0; j <= cells; j++)
        for (int i = 0; i <= cells; i++) {
            double x = -half + i * step, y = -half + j * step;
            if (i > 0 && i < cells && j > 0 && j < cells) {
                x += (2 * lcg(&seed) - 1) * jitter * step;
                y += (2 * lcg(&seed) - 1) * jitter * step;
            }
            MeVector3Set(v[j * (cells + 1) + i], (MeReal)x, (MeReal)y, 0);
        }
    int t = 0;
    for (int j = 0; j < cells; j++)
        for (int i = 0; i < cells; i++) {
            int a = j * (cells + 1) + i, b = a + 1, c = a + cells + 2, d = a + cells + 1;
            if ((i + j) % 2 == 0) {
                int tri[6] = {a, b, c, a, c, d};
                for (int k = 0; k < 6; k++)
                    idx[3 * t + k] = tri[k];
            } else {
                int tri[6] = {a, b, d, b, c, d};
                for (int k = 0; k < 6; k++)
                    idx[3 * t + k] = tri[k];
            }
            t += 2;
        }
    McdTriangleMeshID m = McdTriangleMeshCreate(fw, (const MeVector3 *)v, nv, idx, nt);
    free(v);
    free(idx);
    return m;
}

McdRGHeightFieldID karma_floor_field(McdFrameworkID fw, double half, int cells)
{
    int n = cells + 1;
    MeReal *h = calloc((size_t)n * (size_t)n, sizeof *h);
    double step = 2 * half / cells;
    McdRGHeightFieldID f = McdRGHeightFieldCreate(fw, h, n, n, (MeReal)step, (MeReal)step, (MeReal)-half, (MeReal)-half);
    free(h);
    return f;
}

static int generator(McdModelPair *pair, McdUserTriangle *out, MeVector3 pos, MeReal radius, int maxTriangles)
{
    int n = 0;
    listCalls++;
    listLastPair = pair;
    for (int i = 0; i < listCount && n < maxTriangles; i++) {
        MeBool near = 1;
        for (int k = 0; k < 3 && near; k++) {
            MeReal lo = listVertices[i][0][k], hi = lo;
            for (int v = 1; v < 3; v++) {
                lo = listVertices[i][v][k] < lo ? listVertices[i][v][k] : lo;
                hi = listVertices[i][v][k] > hi ? listVertices[i][v][k] : hi;
            }
            near = pos[k] + radius >= lo && pos[k] - radius <= hi;
        }
        if (!near)
            continue;
        for (int v = 0; v < 3; v++)
            out[n].vertices[v] = &listVertices[i][v];
        out[n].normal = &listNormals[i];
        out[n].triangleData.ptr = (void *)(intptr_t)(i + 1);
        out[n].flags = (McdTriangleFlags)listFlags[i];
        n++;
    }
    return n;
}

McdTriangleListID karma_floor_list(McdFrameworkID fw, McdTriangleMeshID mesh)
{
    listCount = McdTriangleMeshGetTriangleCount(mesh);
    if (listCount > LIST_MAX)
        return NULL;
    MeVector3 lo = {MEINFINITY, MEINFINITY, MEINFINITY}, hi = {-MEINFINITY, -MEINFINITY, -MEINFINITY};
    for (int i = 0; i < listCount; i++) {
        int flags;
        McdTriangleMeshGetTriangle(mesh, i, listVertices[i][0], listVertices[i][1], listVertices[i][2], &flags);
        listFlags[i] = flags;
        MeVector3Set(listNormals[i], 0, 0, 1);
        for (int v = 0; v < 3; v++)
            for (int k = 0; k < 3; k++) {
                lo[k] = listVertices[i][v][k] < lo[k] ? listVertices[i][v][k] : lo[k];
                hi[k] = listVertices[i][v][k] > hi[k] ? listVertices[i][v][k] : hi[k];
            }
    }
    lo[2] -= ME_R(0.1);
    hi[2] += ME_R(0.1);
    listCalls = 0;
    return McdTriangleListCreate(fw, lo, hi, 256, generator);
}

int karma_floor_list_calls(void) { return listCalls; }
McdModelPair *karma_floor_list_last_pair(void) { return listLastPair; }
