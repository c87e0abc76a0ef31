/* convex_hull.c -- Quickhull (Barber, Dobkin, Huhdanpaa 1996) and the merge of coplanar triangles
 * into polygons (internal).
 *
 * Everything runs in double whatever MeReal is: the hull is built once, at load time. Every point
 * not yet inside sits in the conflict list of one face it lies above (by more than the tolerance);
 * the farthest point of a face's list becomes a vertex: the faces it sees are removed and the
 * horizon is joined to it. Points within the tolerance of the hull are dropped. Triangles whose
 * vertices lie within the tolerance of a larger neighbour's plane are then merged, and each merged
 * group becomes the convex polygon of its vertices (points on its edges dropped). */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <karma/MeMemory.h>

#include "convex_hull.h"

typedef struct Face {
    int v[3];    /* counter-clockwise seen from outside */
    int nb[3];   /* face across edge (v[i], v[i+1]) */
    double n[3]; /* outward unit normal */
    double d;    /* plane offset: n . x = d */
    double area;
    int head;    /* first point of the conflict list, -1 if none */
    int alive;
    int visible; /* scratch: marked in the current step */
} Face;

typedef struct Builder {
    int np;
    double (*p)[3];
    int *next;       /* conflict list links, per point */
    int *startFace;  /* scratch per point: the new face whose horizon edge starts there */
    Face *f;
    int nf, capf;
    int *stack;      /* scratch list of face indices */
    int capStack;
    double tol;
} Builder;

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void sub3(double *o, const double *a, const double *b)
{
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

static void cross3(double *o, const double *a, const double *b)
{
    double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2], z = a[0] * b[1] - a[1] * b[0];
    o[0] = x;
    o[1] = y;
    o[2] = z;
}

static double dist(const Builder *b, const Face *f, int i) { return dot3(f->n, b->p[i]) - f->d; }

/* Plane of a face from its vertices: the cross product of the two edges from the vertex opposite
 * the longest edge (the best conditioned pair). */
static void facePlane(const Builder *b, Face *f)
{
    double e[3][3], c[3], len;
    int k, best = 0;
    for (k = 0; k < 3; k++)
        sub3(e[k], b->p[f->v[(k + 1) % 3]], b->p[f->v[k]]);
    for (k = 1; k < 3; k++)
        if (dot3(e[k], e[k]) > dot3(e[best], e[best]))
            best = k;
    /* the two edges meeting at the vertex opposite edge `best` */
    {
        int o = (best + 2) % 3; /* vertex v[(best+2)%3] is opposite edge best */
        double a[3], bb[3];
        sub3(a, b->p[f->v[(o + 1) % 3]], b->p[f->v[o]]);
        sub3(bb, b->p[f->v[(o + 2) % 3]], b->p[f->v[o]]);
        cross3(c, a, bb);
    }
    len = sqrt(dot3(c, c));
    f->area = 0.5 * len;
    if (len > 0) {
        f->n[0] = c[0] / len;
        f->n[1] = c[1] / len;
        f->n[2] = c[2] / len;
    } else {
        f->n[0] = f->n[1] = 0;
        f->n[2] = 1;
    }
    f->d = (dot3(f->n, b->p[f->v[0]]) + dot3(f->n, b->p[f->v[1]]) + dot3(f->n, b->p[f->v[2]])) / 3;
}

static int addFace(Builder *b, int a, int c, int d)
{
    Face *f;
    if (b->nf == b->capf) {
        int cap = b->capf * 2;
        Face *nf = MeMemoryResize(b->f, (size_t)cap * sizeof(Face));
        if (!nf)
            return -1;
        b->f = nf;
        b->capf = cap;
    }
    f = &b->f[b->nf];
    f->v[0] = a;
    f->v[1] = c;
    f->v[2] = d;
    f->nb[0] = f->nb[1] = f->nb[2] = -1;
    f->head = -1;
    f->alive = 1;
    f->visible = 0;
    facePlane(b, f);
    return b->nf++;
}

static int pushStack(Builder *b, int n, int value)
{
    if (n == b->capStack) {
        int cap = b->capStack * 2;
        int *s = MeMemoryResize(b->stack, (size_t)cap * sizeof(int));
        if (!s)
            return -1;
        b->stack = s;
        b->capStack = cap;
    }
    b->stack[n] = value;
    return n + 1;
}

/* The edge index of face f that runs from vertex a to vertex c, or -1. */
static int edgeOf(const Face *f, int a, int c)
{
    int k;
    for (k = 0; k < 3; k++)
        if (f->v[k] == a && f->v[(k + 1) % 3] == c)
            return k;
    return -1;
}

/* Put point i in the conflict list of the face among [first, last) it lies farthest above (if any
 * lies above it by more than the tolerance). */
static void assign(Builder *b, int i, int first, int last)
{
    int k, best = -1;
    double bestD = b->tol;
    for (k = first; k < last; k++) {
        double d;
        if (!b->f[k].alive)
            continue;
        d = dist(b, &b->f[k], i);
        if (d > bestD) {
            bestD = d;
            best = k;
        }
    }
    if (best >= 0) {
        b->next[i] = b->f[best].head;
        b->f[best].head = i;
    }
}

/* The initial tetrahedron: two extreme points, the farthest from their line, the farthest from their
 * plane. Returns MEFALSE when the points are (within the tolerance) on a line or a plane. */
static MeBool initialSimplex(Builder *b, int s[4])
{
    int ext[6], i, j, k;
    double best = -1, line[3], nrm[3];
    for (k = 0; k < 6; k++)
        ext[k] = 0;
    for (i = 1; i < b->np; i++)
        for (k = 0; k < 3; k++) {
            if (b->p[i][k] < b->p[ext[2 * k]][k])
                ext[2 * k] = i;
            if (b->p[i][k] > b->p[ext[2 * k + 1]][k])
                ext[2 * k + 1] = i;
        }
    s[0] = s[1] = 0;
    for (i = 0; i < 6; i++)
        for (j = i + 1; j < 6; j++) {
            double d[3], dd;
            sub3(d, b->p[ext[i]], b->p[ext[j]]);
            dd = dot3(d, d);
            if (dd > best) {
                best = dd;
                s[0] = ext[i];
                s[1] = ext[j];
            }
        }
    if (sqrt(best) <= b->tol)
        return MEFALSE;
    sub3(line, b->p[s[1]], b->p[s[0]]);
    best = -1;
    for (i = 0; i < b->np; i++) {
        double d[3], c[3], dd;
        sub3(d, b->p[i], b->p[s[0]]);
        cross3(c, line, d);
        dd = dot3(c, c);
        if (dd > best) {
            best = dd;
            s[2] = i;
        }
    }
    if (sqrt(best / dot3(line, line)) <= b->tol)
        return MEFALSE;
    {
        double u[3];
        sub3(u, b->p[s[2]], b->p[s[0]]);
        cross3(nrm, line, u);
    }
    {
        double len = sqrt(dot3(nrm, nrm));
        best = -1;
        for (i = 0; i < b->np; i++) {
            double d[3], dd;
            sub3(d, b->p[i], b->p[s[0]]);
            dd = fabs(dot3(nrm, d)) / len;
            if (dd > best) {
                best = dd;
                s[3] = i;
            }
        }
    }
    return best > b->tol;
}

/* Link the neighbours of the faces [first, last) among themselves (edge a->c meets edge c->a). */
static void linkFaces(Builder *b, int first, int last)
{
    int i, j, k;
    for (i = first; i < last; i++)
        for (k = 0; k < 3; k++)
            for (j = first; j < last; j++) {
                int e = edgeOf(&b->f[j], b->f[i].v[(k + 1) % 3], b->f[i].v[k]);
                if (j != i && e >= 0)
                    b->f[i].nb[k] = j;
            }
}

/* Takes the farthest point of face fi's conflict list out of it and returns it: the eye. */
static int takeEye(Builder *b, int fi)
{
    int eye = -1, eyePrev = -1, prev = -1;
    double far = -1;
    for (int i = b->f[fi].head; i >= 0; prev = i, i = b->next[i]) {
        double d = dist(b, &b->f[fi], i);
        if (d > far) {
            far = d;
            eye = i;
            eyePrev = prev;
        }
    }
    if (eyePrev < 0)
        b->f[fi].head = b->next[eye];
    else
        b->next[eyePrev] = b->next[eye];
    return eye;
}

/* Marks the faces the eye sees (more than the tolerance above), from fi across edges, and lists them
 * in b->stack. Returns their count, or -1 when memory ran out. */
static int markVisible(Builder *b, int fi, int eye)
{
    b->f[fi].visible = 1;
    int n = pushStack(b, 0, fi);
    if (n < 0)
        return -1;
    for (int top = 0; top < n; top++) {
        Face *f = &b->f[b->stack[top]];
        for (int k = 0; k < 3; k++) {
            Face *g = &b->f[f->nb[k]];
            if (!g->visible && dist(b, g, eye) > b->tol) {
                g->visible = 1;
                n = pushStack(b, n, f->nb[k]);
                if (n < 0)
                    return -1;
            }
        }
    }
    return n;
}

/* The horizon: edges of the n visible faces whose neighbour is not visible. Claims each edge's start
 * vertex in startFace and returns the count; 0 or -1 when a start vertex repeats (the visible region
 * is not a disc). */
static int claimHorizon(Builder *b, int n)
{
    int hc = 0;
    for (int top = 0; top < n; top++) {
        const Face *f = &b->f[b->stack[top]];
        for (int k = 0; k < 3; k++)
            if (!b->f[f->nb[k]].visible) {
                if (b->startFace[f->v[k]] != -1)
                    hc = -1;
                else if (hc >= 0) {
                    b->startFace[f->v[k]] = -2; /* claimed; the face comes below */
                    hc++;
                }
            }
    }
    return hc;
}

/* Joins each horizon edge of the n visible faces to the eye with a new face, and the new faces to
 * each other. Returns 0, or -1 when memory ran out. */
static int coneToEye(Builder *b, int n, int eye)
{
    const int firstNew = b->nf;
    for (int top = 0; top < n; top++) {
        int fIdx = b->stack[top];
        for (int k = 0; k < 3; k++) {
            int a = b->f[fIdx].v[k], c = b->f[fIdx].v[(k + 1) % 3], out = b->f[fIdx].nb[k], nf;
            if (b->f[out].visible)
                continue;
            nf = addFace(b, a, c, eye);
            if (nf < 0)
                return -1;
            b->f[nf].nb[0] = out;
            b->f[out].nb[edgeOf(&b->f[out], c, a)] = nf;
            b->startFace[a] = nf;
        }
    }
    /* join the new faces around the eye: face (a, c, eye) meets (c, x, eye) across (c, eye) */
    for (int h = firstNew; h < b->nf; h++) {
        int c = b->f[h].v[1], other = b->startFace[c];
        b->f[h].nb[1] = other;
        b->f[other].nb[2] = h;
    }
    for (int h = firstNew; h < b->nf; h++)
        b->startFace[b->f[h].v[0]] = -1;
    return 0;
}

/* Add the farthest point of face fi's conflict list. Returns 0, or -1 when memory ran out. */
static int addPoint(Builder *b, int fi)
{
    const int eye = takeEye(b, fi);
    const int n = markVisible(b, fi, eye);
    if (n < 0)
        return -1;
    const int firstNew = b->nf;
    if (claimHorizon(b, n) <= 0) {
        /* Rounding made the visible region other than a disc: the eye lies within a rounding error
         * of several faces. Drop it (it is within the hull's tolerance of the faces it pinches). */
        for (int top = 0; top < n; top++) {
            const Face *f = &b->f[b->stack[top]];
            b->f[b->stack[top]].visible = 0;
            for (int k = 0; k < 3; k++)
                b->startFace[f->v[k]] = -1;
        }
        return 0;
    }
    if (coneToEye(b, n, eye) < 0)
        return -1;
    /* the visible faces die; their points go to the new faces or are inside now */
    for (int top = 0; top < n; top++) {
        Face *f = &b->f[b->stack[top]];
        int next;
        f->alive = 0;
        f->visible = 0;
        for (int i = f->head; i >= 0; i = next) {
            next = b->next[i];
            assign(b, i, firstNew, b->nf);
        }
        f->head = -1;
    }
    return 0;
}

double McdHullTolerance(const MeVector3 *points, int n)
{
    double lo[3], hi[3], diag = 0, big = 0;
    int i, k;
    for (k = 0; k < 3; k++)
        lo[k] = hi[k] = n > 0 ? (double)points[0][k] : 0;
    for (i = 0; i < n; i++)
        for (k = 0; k < 3; k++) {
            double x = (double)points[i][k];
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
            big = fabs(x) > big ? fabs(x) : big;
        }
    for (k = 0; k < 3; k++)
        diag += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    return MCD_HULL_REL_TOL * sqrt(diag) + 8 * (double)ME_MIN_EPSILON * big;
}

/* ---- polygons from the triangles ------------------------------------------------------------ */

typedef struct Order {
    double key;
    int index;
} Order;

static int byAreaDesc(const void *x, const void *y)
{
    const Order *a = x, *b = y;
    if (a->key != b->key)
        return a->key > b->key ? -1 : 1;
    return a->index - b->index;
}

typedef struct P2 {
    double x, y;
    int v;
} P2;

static int byXY(const void *x, const void *y)
{
    const P2 *a = x, *b = y;
    if (a->x != b->x)
        return a->x < b->x ? -1 : 1;
    if (a->y != b->y)
        return a->y < b->y ? -1 : 1;
    return a->v - b->v;
}

/* Turn of o -> a -> c: positive counter-clockwise, and counted as a turn only beyond tol (distance
 * of a from the line o-c). */
static MeBool leftTurn(const P2 *o, const P2 *a, const P2 *c, double tol)
{
    double cr = (a->x - o->x) * (c->y - o->y) - (a->y - o->y) * (c->x - o->x);
    double len = hypot(c->x - o->x, c->y - o->y);
    return cr > tol * len;
}

/* Convex polygon (counter-clockwise) of m 2D points, points on its edges dropped: Andrew's monotone
 * chain. Writes vertex ids to out; returns the count. pts is sorted in place, work holds 2m + 1. */
static int polygon2D(P2 *pts, int m, P2 *work, double tol, int *out)
{
    int i, k = 0, lower;
    qsort(pts, (size_t)m, sizeof(P2), byXY);
    for (i = 0; i < m; i++) {
        while (k >= 2 && !leftTurn(&work[k - 2], &work[k - 1], &pts[i], tol))
            k--;
        work[k++] = pts[i];
    }
    lower = k + 1;
    for (i = m - 2; i >= 0; i--) {
        while (k >= lower && !leftTurn(&work[k - 2], &work[k - 1], &pts[i], tol))
            k--;
        work[k++] = pts[i];
    }
    k--; /* the last point repeats the first */
    for (i = 0; i < k; i++)
        out[i] = work[i].v;
    return k < 3 ? 0 : k;
}

static int byPair(const void *x, const void *y)
{
    const int *a = x, *b = y;
    return a[0] != b[0] ? a[0] - b[0] : a[1] - b[1];
}

/* The merge's scratch: the coplanar groups of live triangles and, after groupPolygons, each group's
 * polygon (gVerts from gStart[g], polyCount[g] vertices). */
typedef struct Merge {
    int nt, groups, polyVerts, nv, ne;
    int *group;               /* per face: its group, -1 before it has one */
    int *queue;               /* faces waiting to join the group being grown */
    Order *order;             /* live faces by area, largest first */
    int *mark;                /* per point: scratch */
    int *remap;               /* per point: its index among the hull's vertices, -1 if none */
    int *gStart, *gVerts;     /* each group's vertices */
    double (*gNormal)[3];     /* each group's area-weighted normal */
    int *polyCount;           /* vertices of each group's polygon */
    P2 *pts, *work;           /* polygon2D's points and work space */
    int *edgeList;            /* the polygons' edges as (lower, higher) vertex pairs */
} Merge;

static void mergeFree(Merge *m)
{
    MeMemoryDestroy(m->group);
    MeMemoryDestroy(m->queue);
    MeMemoryDestroy(m->order);
    MeMemoryDestroy(m->mark);
    MeMemoryDestroy(m->remap);
    MeMemoryDestroy(m->gStart);
    MeMemoryDestroy(m->gVerts);
    MeMemoryDestroy(m->gNormal);
    MeMemoryDestroy(m->polyCount);
    MeMemoryDestroy(m->pts);
    MeMemoryDestroy(m->work);
    MeMemoryDestroy(m->edgeList);
}

/* The scratch for the live faces of b; MEFALSE when memory ran out (mergeFree frees what was made). */
static MeBool mergeAlloc(const Builder *b, Merge *m)
{
    memset(m, 0, sizeof *m);
    for (int i = 0; i < b->nf; i++)
        m->nt += b->f[i].alive;
    const int nt = m->nt;
    m->group = MeMemoryCreate((size_t)b->nf * sizeof(int));
    m->queue = MeMemoryCreate((size_t)nt * sizeof(int));
    m->order = MeMemoryCreate((size_t)nt * sizeof(Order));
    m->mark = MeMemoryCreate((size_t)b->np * sizeof(int));
    m->remap = MeMemoryCreate((size_t)b->np * sizeof(int));
    m->gStart = MeMemoryCreate((size_t)(nt + 1) * sizeof(int));
    m->gVerts = MeMemoryCreate((size_t)(3 * nt) * sizeof(int));
    m->gNormal = MeMemoryCreate((size_t)nt * sizeof *m->gNormal);
    m->polyCount = MeMemoryCreate((size_t)(nt + 1) * sizeof(int));
    m->pts = MeMemoryCreate((size_t)(3 * nt) * sizeof(P2));
    m->work = MeMemoryCreate((size_t)(6 * nt + 1) * sizeof(P2));
    return m->group && m->queue && m->order && m->mark && m->remap && m->gStart && m->gVerts && m->gNormal &&
           m->polyCount && m->pts && m->work;
}

/* Grows the group of face `seed` (number m->groups): from it to neighbours whose vertices lie on its
 * plane; records the group's vertices and its area-weighted normal. */
static void growGroup(const Builder *b, Merge *m, int seed)
{
    const int groups = m->groups;
    int qn = 1, gv = 0, k;
    const Face *s = &b->f[seed];
    double acc[3] = {0, 0, 0};
    m->group[seed] = groups;
    m->queue[0] = seed;
    m->gStart[groups] = m->polyVerts;
    for (int qi = 0; qi < qn; qi++) {
        const Face *f = &b->f[m->queue[qi]];
        for (k = 0; k < 3; k++) {
            acc[k] += f->area * f->n[k];
            if (m->mark[f->v[k]] != groups) {
                m->mark[f->v[k]] = groups;
                m->gVerts[m->polyVerts + gv++] = f->v[k];
            }
        }
        for (k = 0; k < 3; k++) {
            int u = f->nb[k], j;
            MeBool on = METRUE;
            if (m->group[u] >= 0 || dot3(b->f[u].n, s->n) <= 0)
                continue;
            for (j = 0; j < 3 && on; j++)
                on = fabs(dist(b, s, b->f[u].v[j])) <= b->tol;
            if (on) {
                m->group[u] = groups;
                m->queue[qn++] = u;
            }
        }
    }
    double len = sqrt(dot3(acc, acc));
    for (k = 0; k < 3; k++)
        m->gNormal[groups][k] = len > 0 ? acc[k] / len : s->n[k];
    m->polyVerts += gv;
    m->groups++;
}

/* Groups: from the largest triangle, spread to neighbours whose vertices lie on its plane. */
static void groupCoplanar(const Builder *b, Merge *m)
{
    int i, k;
    for (i = 0, k = 0; i < b->nf; i++) {
        m->group[i] = -1;
        if (b->f[i].alive) {
            m->order[k].key = b->f[i].area;
            m->order[k].index = i;
            k++;
        }
    }
    for (i = 0; i < b->np; i++)
        m->mark[i] = -1;
    qsort(m->order, (size_t)m->nt, sizeof(Order), byAreaDesc);
    for (int t = 0; t < m->nt; t++)
        if (m->group[m->order[t].index] < 0)
            growGroup(b, m, m->order[t].index);
    m->gStart[m->groups] = m->polyVerts;
}

/* Each group's polygon in its plane (counter-clockwise about the normal), in place in gVerts; marks
 * the points a polygon uses. */
static void groupPolygons(const Builder *b, Merge *m)
{
    int written = 0, k;
    for (int i = 0; i < b->np; i++)
        m->mark[i] = 0;
    for (int t = 0; t < m->groups; t++) {
        const double *n = m->gNormal[t];
        double u[3], v[3], ax[3] = {0, 0, 0};
        int count = m->gStart[t + 1] - m->gStart[t], c;
        ax[fabs(n[0]) <= fabs(n[1]) && fabs(n[0]) <= fabs(n[2]) ? 0 : (fabs(n[1]) <= fabs(n[2]) ? 1 : 2)] = 1;
        cross3(u, n, ax);
        double l = sqrt(dot3(u, u));
        u[0] /= l, u[1] /= l, u[2] /= l;
        cross3(v, n, u); /* (u, v, n) right-handed: counter-clockwise in (u, v) is about n */
        for (k = 0; k < count; k++) {
            int vi = m->gVerts[m->gStart[t] + k];
            m->pts[k].x = dot3(b->p[vi], u);
            m->pts[k].y = dot3(b->p[vi], v);
            m->pts[k].v = vi;
        }
        c = polygon2D(m->pts, count, m->work, b->tol, &m->gVerts[written]);
        m->gStart[t] = written;
        m->polyCount[t] = c;
        for (k = 0; k < c; k++)
            m->mark[m->gVerts[written + k]] = 1;
        written += c;
    }
    m->polyVerts = written;
}

/* The hull's vertices (the points a polygon uses, numbered in input order), polygons, normals and
 * offsets, and the polygons' edges in m->edgeList; MEFALSE when memory ran out. */
static MeBool fillPolygons(const Builder *b, const MeVector3 *points, Merge *m, McdHull *hull)
{
    const int polyVerts = m->polyVerts;
    int i, k;
    for (i = 0; i < b->np; i++)
        m->remap[i] = m->mark[i] ? m->nv++ : -1;
    hull->vertices = MeMemoryCreate((size_t)m->nv * sizeof(MeVector3));
    hull->polygonStart = MeMemoryCreate((size_t)(m->groups + 1) * sizeof(int));
    hull->polygonVertices = MeMemoryCreate((size_t)(polyVerts > 0 ? polyVerts : 1) * sizeof(int));
    hull->normals = MeMemoryCreate((size_t)m->groups * sizeof(MeVector3));
    hull->offsets = MeMemoryCreate((size_t)m->groups * sizeof(MeReal));
    m->edgeList = MeMemoryCreate((size_t)(2 * (polyVerts > 0 ? polyVerts : 1)) * sizeof(int));
    if (!hull->vertices || !hull->polygonStart || !hull->polygonVertices || !hull->normals || !hull->offsets ||
        !m->edgeList)
        return MEFALSE;
    for (i = 0; i < b->np; i++)
        if (m->remap[i] >= 0)
            MeVector3Copy(hull->vertices[m->remap[i]], points[i]);
    hull->vertexCount = m->nv;
    int pc = 0, w = 0;
    const int *remap = m->remap;
    for (int t = 0; t < m->groups; t++) {
        int c = m->polyCount[t];
        double off = -DBL_MAX;
        if (c < 3)
            continue; /* a sliver of rounding: its neighbours cover it */
        hull->polygonStart[pc] = w;
        for (k = 0; k < c; k++) {
            int vi = m->gVerts[m->gStart[t] + k], vn = m->gVerts[m->gStart[t] + (k + 1) % c];
            double o = dot3(m->gNormal[t], b->p[vi]);
            off = o > off ? o : off;
            hull->polygonVertices[w++] = remap[vi];
            m->edgeList[2 * m->ne] = remap[vi] < remap[vn] ? remap[vi] : remap[vn];
            m->edgeList[2 * m->ne + 1] = remap[vi] < remap[vn] ? remap[vn] : remap[vi];
            m->ne++;
        }
        MeVector3Set(hull->normals[pc], (MeReal)m->gNormal[t][0], (MeReal)m->gNormal[t][1], (MeReal)m->gNormal[t][2]);
        hull->offsets[pc] = (MeReal)off;
        pc++;
    }
    hull->polygonStart[pc] = w;
    hull->polygonCount = pc;
    return METRUE;
}

/* The edges, each once, and each vertex's neighbours; MEFALSE when memory ran out. m->remap is
 * reused as the per-vertex write position. */
static MeBool fillEdges(Merge *m, McdHull *hull)
{
    int *edgeList = m->edgeList, ne = m->ne, i;
    const int nv = m->nv;
    qsort(edgeList, (size_t)ne, 2 * sizeof(int), byPair);
    int unique = 0;
    for (i = 0; i < ne; i++)
        if (i == 0 || byPair(&edgeList[2 * i], &edgeList[2 * (unique - 1)]) != 0) {
            edgeList[2 * unique] = edgeList[2 * i];
            edgeList[2 * unique + 1] = edgeList[2 * i + 1];
            unique++;
        }
    ne = m->ne = unique;
    hull->edgeCount = ne;
    hull->edges = MeMemoryCreate((size_t)(2 * (ne > 0 ? ne : 1)) * sizeof(int));
    hull->neighbourStart = MeMemoryCreateZeroed((size_t)(nv + 1) * sizeof(int));
    hull->neighbours = MeMemoryCreate((size_t)(2 * (ne > 0 ? ne : 1)) * sizeof(int));
    if (!hull->edges || !hull->neighbourStart || !hull->neighbours)
        return MEFALSE;
    memcpy(hull->edges, edgeList, (size_t)(2 * ne) * sizeof(int));
    for (i = 0; i < 2 * ne; i++)
        hull->neighbourStart[edgeList[i] + 1]++;
    for (i = 0; i < nv; i++)
        hull->neighbourStart[i + 1] += hull->neighbourStart[i];
    int *fill = m->remap;
    for (i = 0; i < nv; i++)
        fill[i] = hull->neighbourStart[i];
    for (i = 0; i < ne; i++) {
        int a = edgeList[2 * i], c = edgeList[2 * i + 1];
        hull->neighbours[fill[a]++] = c;
        hull->neighbours[fill[c]++] = a;
    }
    return METRUE;
}

/* The polygons around each vertex; MEFALSE when memory ran out. `fill` holds a value per vertex. */
static MeBool fillVertexPolygons(McdHull *hull, int *fill)
{
    const int nv = hull->vertexCount, uses = hull->polygonStart[hull->polygonCount];
    int i;
    hull->vertexPolygonStart = MeMemoryCreateZeroed((size_t)(nv + 1) * sizeof(int));
    hull->vertexPolygons = MeMemoryCreate((size_t)(uses > 0 ? uses : 1) * sizeof(int));
    if (!hull->vertexPolygonStart || !hull->vertexPolygons)
        return MEFALSE;
    for (i = 0; i < uses; i++)
        hull->vertexPolygonStart[hull->polygonVertices[i] + 1]++;
    for (i = 0; i < nv; i++)
        hull->vertexPolygonStart[i + 1] += hull->vertexPolygonStart[i];
    for (i = 0; i < nv; i++)
        fill[i] = hull->vertexPolygonStart[i];
    for (int p = 0; p < hull->polygonCount; p++)
        for (i = hull->polygonStart[p]; i < hull->polygonStart[p + 1]; i++)
            hull->vertexPolygons[fill[hull->polygonVertices[i]]++] = p;
    return METRUE;
}

/* Bounding sphere: centre of the vertices' box, radius to the farthest vertex. */
static void fillBoundingSphere(McdHull *hull)
{
    MeVector3 lo, hi;
    MeReal r2 = 0;
    int i, k;
    MeVector3Copy(lo, hull->vertices[0]);
    MeVector3Copy(hi, hull->vertices[0]);
    for (i = 1; i < hull->vertexCount; i++)
        for (k = 0; k < 3; k++) {
            lo[k] = MeMIN(lo[k], hull->vertices[i][k]);
            hi[k] = MeMAX(hi[k], hull->vertices[i][k]);
        }
    for (k = 0; k < 3; k++)
        hull->centre[k] = ME_R(0.5) * (lo[k] + hi[k]);
    for (i = 0; i < hull->vertexCount; i++)
        r2 = MeMAX(r2, MeVector3DistanceSqr(hull->vertices[i], hull->centre));
    hull->radius = MeSqrt(r2);
}

/* Merge the live triangles into polygons and fill the hull (input points as MeReal). */
static McdHullStatus makePolygons(Builder *b, const MeVector3 *points, McdHull *hull)
{
    Merge m;
    McdHullStatus status = MCD_HULL_NO_MEMORY;
    memset(hull, 0, sizeof *hull);
    if (mergeAlloc(b, &m)) {
        groupCoplanar(b, &m);
        groupPolygons(b, &m);
        if (fillPolygons(b, points, &m, hull) && fillEdges(&m, hull) && fillVertexPolygons(hull, m.remap)) {
            fillBoundingSphere(hull);
            hull->tolerance = (MeReal)b->tol;
            status = hull->polygonCount >= 4 ? MCD_HULL_OK : MCD_HULL_FLAT;
        }
    }
    mergeFree(&m);
    if (status != MCD_HULL_OK)
        McdHullFree(hull);
    return status;
}

McdHullStatus McdHullBuild(const MeVector3 *points, int n, McdHull *hull)
{
    Builder b;
    int s[4], i, k, cursor;
    McdHullStatus status = MCD_HULL_NO_MEMORY;
    memset(hull, 0, sizeof *hull);
    if (n < 4)
        return MCD_HULL_FLAT;
    memset(&b, 0, sizeof b);
    b.np = n;
    b.tol = McdHullTolerance(points, n);
    b.capf = 64;
    b.capStack = 64;
    b.p = MeMemoryCreate((size_t)n * sizeof *b.p);
    b.next = MeMemoryCreate((size_t)n * sizeof(int));
    b.startFace = MeMemoryCreate((size_t)n * sizeof(int));
    b.f = MeMemoryCreate((size_t)b.capf * sizeof(Face));
    b.stack = MeMemoryCreate((size_t)b.capStack * sizeof(int));
    if (!b.p || !b.next || !b.startFace || !b.f || !b.stack)
        goto done;
    for (i = 0; i < n; i++) {
        for (k = 0; k < 3; k++)
            b.p[i][k] = (double)points[i][k];
        b.next[i] = -1;
        b.startFace[i] = -1;
    }
    if (!initialSimplex(&b, s)) {
        status = MCD_HULL_FLAT;
        goto done;
    }
    {
        /* orient the tetrahedron so that every face's normal points away from the fourth vertex */
        static const int tf[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
        double c[3] = {0, 0, 0};
        for (i = 0; i < 4; i++)
            for (k = 0; k < 3; k++)
                c[k] += 0.25 * b.p[s[i]][k];
        for (i = 0; i < 4; i++) {
            int fi = addFace(&b, s[tf[i][0]], s[tf[i][1]], s[tf[i][2]]);
            if (dot3(b.f[fi].n, c) - b.f[fi].d > 0) {
                int t = b.f[fi].v[1];
                b.f[fi].v[1] = b.f[fi].v[2];
                b.f[fi].v[2] = t;
                facePlane(&b, &b.f[fi]);
            }
        }
        linkFaces(&b, 0, 4);
    }
    for (i = 0; i < n; i++)
        if (i != s[0] && i != s[1] && i != s[2] && i != s[3])
            assign(&b, i, 0, 4);
    cursor = 0;
    while (cursor < b.nf) {
        if (!b.f[cursor].alive || b.f[cursor].head < 0) {
            cursor++;
            continue;
        }
        if (addPoint(&b, cursor) < 0)
            goto done;
    }
    status = makePolygons(&b, points, hull);
done:
    MeMemoryDestroy(b.p);
    MeMemoryDestroy(b.next);
    MeMemoryDestroy(b.startFace);
    MeMemoryDestroy(b.f);
    MeMemoryDestroy(b.stack);
    return status;
}

void McdHullFree(McdHull *hull)
{
    MeMemoryDestroy(hull->vertices);
    MeMemoryDestroy(hull->polygonStart);
    MeMemoryDestroy(hull->polygonVertices);
    MeMemoryDestroy(hull->normals);
    MeMemoryDestroy(hull->offsets);
    MeMemoryDestroy(hull->edges);
    MeMemoryDestroy(hull->neighbourStart);
    MeMemoryDestroy(hull->neighbours);
    MeMemoryDestroy(hull->vertexPolygonStart);
    MeMemoryDestroy(hull->vertexPolygons);
    memset(hull, 0, sizeof *hull);
}
