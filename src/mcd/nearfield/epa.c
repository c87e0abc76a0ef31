/* epa.c -- penetration depth of overlapping cores by the Expanding Polytope Algorithm (internal).
 *
 * Grows a polytope inside D = core1 - core2 from GJK's simplex, always pushing out the face nearest to
 * the origin with the support point along its normal, until that face lies on D's boundary (van den
 * Bergen, "Proximity queries and penetration depth computation on 3D game objects", 2001). The
 * nearest face's normal is the minimum translation direction, core 1 -> core 2 (the distance query's
 * direction; the contact normal is its opposite, see nearfield.h). */
#include "nearfield.h"

#define EPA_MAX_VERTS 256
#define EPA_MAX_FACES 512
#define EPA_MAX_EDGES 128

typedef struct EpaFace {
    int v[3];
    MeVector3 n;
    MeReal d;
    MeBool alive;
} EpaFace;

typedef struct Epa {
    int nv, nf;
    MeVector3 w[EPA_MAX_VERTS], a[EPA_MAX_VERTS], b[EPA_MAX_VERTS];
    EpaFace f[EPA_MAX_FACES];
} Epa;

static int addVertex(Epa *e, const McdNfShape *s1, const McdNfShape *s2, const MeVector3 dir)
{
    MeVector3 neg;
    if (e->nv >= EPA_MAX_VERTS)
        return -1;
    MeVector3MultiplyScalar(neg, dir, -ME_R(1.0));
    McdNfCoreSupport(s1, dir, e->a[e->nv]);
    McdNfCoreSupport(s2, neg, e->b[e->nv]);
    MeVector3Subtract(e->w[e->nv], e->a[e->nv], e->b[e->nv]);
    return e->nv++;
}

/* A face with its outward normal (relative to the interior point c) and plane offset. */
static MeBool addFace(Epa *e, int i, int j, int k, const MeVector3 c)
{
    EpaFace *f;
    MeVector3 u, v;
    if (e->nf >= EPA_MAX_FACES)
        return MEFALSE;
    f = &e->f[e->nf];
    MeVector3Subtract(u, e->w[j], e->w[i]);
    MeVector3Subtract(v, e->w[k], e->w[i]);
    MeVector3Cross(f->n, u, v);
    f->v[0] = i;
    f->v[1] = j;
    f->v[2] = k;
    if (c) {
        MeVector3 ic;
        MeVector3Subtract(ic, e->w[i], c);
        if (MeVector3Dot(f->n, ic) < ME_R(0.0)) {
            f->v[1] = k;
            f->v[2] = j;
            MeVector3Scale(f->n, -ME_R(1.0));
        }
    }
    f->alive = METRUE;
    if (!MeVector3NormalizeSafe(f->n)) {
        /* a sliver: keep it for the topology, never nearest, never visible */
        MeVector3Set(f->n, ME_R(0.0), ME_R(0.0), ME_R(0.0));
        f->d = MEINFINITY;
        e->nf++;
        return METRUE;
    }
    f->d = MeVector3Dot(f->n, e->w[i]);
    e->nf++;
    return METRUE;
}

/* Distance of point p from the line or plane spanned by the first n vertices. */
static MeReal offDistance(const Epa *e, int n, const MeVector3 p)
{
    MeVector3 u, v, d, c;
    MeVector3Subtract(d, p, e->w[0]);
    if (n == 1)
        return MeVector3Magnitude(d);
    MeVector3Subtract(u, e->w[1], e->w[0]);
    if (n == 2) {
        MeVector3Cross(c, u, d);
        return MeVector3Magnitude(c) / MeMAX(MeVector3Magnitude(u), ME_MIN_EPSILON);
    }
    MeVector3Subtract(v, e->w[2], e->w[0]);
    MeVector3Cross(c, u, v);
    MeVector3Normalize(c);
    return MeFabs(MeVector3Dot(c, d));
}

/* Grow GJK's simplex (1-4 points) to a tetrahedron of non-zero volume. */
static MeBool makeTetrahedron(Epa *e, const McdNfShape *s1, const McdNfShape *s2, MeReal eps)
{
    while (e->nv < 4) {
        MeVector3 dirs[6];
        int nd = 0, k;
        MeBool grown = MEFALSE;
        if (e->nv == 1) {
            MeVector3Set(dirs[0], ME_R(1.0), ME_R(0.0), ME_R(0.0));
            MeVector3Set(dirs[1], -ME_R(1.0), ME_R(0.0), ME_R(0.0));
            MeVector3Set(dirs[2], ME_R(0.0), ME_R(1.0), ME_R(0.0));
            MeVector3Set(dirs[3], ME_R(0.0), -ME_R(1.0), ME_R(0.0));
            MeVector3Set(dirs[4], ME_R(0.0), ME_R(0.0), ME_R(1.0));
            MeVector3Set(dirs[5], ME_R(0.0), ME_R(0.0), -ME_R(1.0));
            nd = 6;
        } else if (e->nv == 2) {
            MeVector3 u, p, q;
            MeVector3Subtract(u, e->w[1], e->w[0]);
            MeVector3Normalize(u);
            McdNfPerpendicular(p, u);
            MeVector3Cross(q, u, p);
            MeVector3Copy(dirs[0], p);
            MeVector3MultiplyScalar(dirs[1], p, -ME_R(1.0));
            MeVector3Copy(dirs[2], q);
            MeVector3MultiplyScalar(dirs[3], q, -ME_R(1.0));
            nd = 4;
        } else {
            MeVector3 u, v;
            MeVector3Subtract(u, e->w[1], e->w[0]);
            MeVector3Subtract(v, e->w[2], e->w[0]);
            MeVector3Cross(dirs[0], u, v);
            MeVector3Normalize(dirs[0]);
            MeVector3MultiplyScalar(dirs[1], dirs[0], -ME_R(1.0));
            nd = 2;
        }
        for (k = 0; k < nd && !grown; k++) {
            int i = addVertex(e, s1, s2, dirs[k]);
            if (i < 0)
                return MEFALSE;
            if (offDistance(e, e->nv - 1, e->w[i]) > eps)
                grown = METRUE;
            else
                e->nv--;
        }
        if (!grown)
            return MEFALSE;
    }
    return METRUE;
}

/* The live face nearest to the origin (-1 when none), its offset in *bestD. */
static int nearestFace(const Epa *e, MeReal *bestD)
{
    int f, best = -1;
    *bestD = MEINFINITY;
    for (f = 0; f < e->nf; f++)
        if (e->f[f].alive && e->f[f].d < *bestD) {
            *bestD = e->f[f].d;
            best = f;
        }
    return best;
}

/* The first tetrahedron, from GJK's simplex: its vertices and four faces facing out. MEFALSE when D is
 * flat near the origin. */
static MeBool startPolytope(Epa *e, const McdNfShape *s1, const McdNfShape *s2, const McdNfSimplex *sx, MeReal eps)
{
    MeVector3 c;
    int k;
    e->nf = 0;
    e->nv = sx->n;
    for (k = 0; k < sx->n; k++) {
        MeVector3Copy(e->w[k], sx->w[k]);
        MeVector3Copy(e->a[k], sx->a[k]);
        MeVector3Copy(e->b[k], sx->b[k]);
    }
    if (e->nv == 0)
        addVertex(e, s1, s2, s1->tm[0]);
    if (e->nv == 4 && offDistance(e, 3, e->w[3]) <= eps)
        e->nv = 3; /* a flat tetrahedron from GJK: regrow the last vertex */
    if (!makeTetrahedron(e, s1, s2, eps * ME_R(10.0)))
        return MEFALSE;
    MeVector3Set(c, ME_R(0.0), ME_R(0.0), ME_R(0.0));
    for (k = 0; k < 4; k++)
        MeVector3MultiplyAdd(c, ME_R(0.25), e->w[k]);
    addFace(e, 0, 1, 2, c);
    addFace(e, 0, 1, 3, c);
    addFace(e, 0, 2, 3, c);
    addFace(e, 1, 2, 3, c);
    return METRUE;
}

/* Remove the faces that see the new vertex nw, by a flood from the nearest face `best` across shared
 * edges (a connected set even when rounding blurs visibility); its rim, the horizon, goes to edges.
 * Returns the number of horizon edges. */
static int removeVisible(Epa *e, int best, int nw, MeReal eps, int edges[EPA_MAX_EDGES][2])
{
    int stack[EPA_MAX_FACES], top = 0, ne = 0;
    e->f[best].alive = MEFALSE;
    stack[top++] = best;
    while (top > 0) {
        const EpaFace *fc = &e->f[stack[--top]];
        int j;
        for (j = 0; j < 3; j++) {
            int i0 = fc->v[j], i1 = fc->v[(j + 1) % 3], g, nb = -1;
            for (g = 0; g < e->nf && nb < 0; g++) {
                const EpaFace *o = &e->f[g];
                if (o->alive && ((o->v[0] == i1 && o->v[1] == i0) || (o->v[1] == i1 && o->v[2] == i0) ||
                                 (o->v[2] == i1 && o->v[0] == i0)))
                    nb = g;
            }
            if (nb >= 0) {
                MeVector3 d;
                MeVector3Subtract(d, e->w[nw], e->w[e->f[nb].v[0]]);
                if (MeVector3Dot(e->f[nb].n, d) > eps * ME_R(0.01)) {
                    e->f[nb].alive = MEFALSE;
                    stack[top++] = nb;
                    continue;
                }
                if (ne < EPA_MAX_EDGES) {
                    edges[ne][0] = i0;
                    edges[ne][1] = i1;
                    ne++;
                }
            }
        }
    }
    return ne;
}

/* Compact the face list, then close the hole (its ne horizon edges) with a fan to the new vertex nw.
 * MEFALSE when the face list is full. */
static MeBool closeHole(Epa *e, int edges[EPA_MAX_EDGES][2], int ne, int nw)
{
    int nf = 0, f, k;
    MeBool ok = METRUE;
    for (f = 0; f < e->nf; f++)
        if (e->f[f].alive)
            e->f[nf++] = e->f[f];
    e->nf = nf;
    for (k = 0; k < ne && ok; k++)
        ok = addFace(e, edges[k][0], edges[k][1], nw, NULL);
    return ok;
}

/* Push out the face nearest to the origin with the support point along its normal until that face
 * lies on D's boundary (or a vertex comes back, or the polytope is full). */
static void expandPolytope(Epa *e, const McdNfShape *s1, const McdNfShape *s2, MeReal eps)
{
    int k, iter;
    for (iter = 0; iter < EPA_MAX_VERTS; iter++) {
        int edges[EPA_MAX_EDGES][2], ne, nw, best;
        MeReal bestD, gap;
        best = nearestFace(e, &bestD);
        if (best < 0)
            break;
        nw = addVertex(e, s1, s2, e->f[best].n);
        if (nw < 0)
            break;
        gap = MeVector3Dot(e->w[nw], e->f[best].n) - bestD;
        if (gap <= eps + MCD_NF_REL_EPS * MeFabs(bestD)) {
            e->nv--; /* the face is on D's boundary */
            break;
        }
        for (k = 0; k < nw; k++)
            if (MeVector3DistanceSqr(e->w[k], e->w[nw]) <= eps * eps)
                break;
        if (k < nw) { /* a vertex found again: as far as this precision goes */
            e->nv--;
            break;
        }
        ne = removeVisible(e, best, nw, eps, edges);
        if (!closeHole(e, edges, ne, nw))
            break;
    }
}

/* Depth, normal and (by barycentric weights of the origin's projection) witness points from face fc. */
static void resultFromFace(const Epa *e, const EpaFace *fc, McdNfDistance *out)
{
    const MeReal *A = e->w[fc->v[0]], *B = e->w[fc->v[1]], *C = e->w[fc->v[2]];
    MeVector3 p, v0, v1, v2;
    MeReal d00, d01, d11, d20, d21, den, l1, l2, l0;
    MeVector3MultiplyScalar(p, fc->n, fc->d);
    MeVector3Subtract(v0, B, A);
    MeVector3Subtract(v1, C, A);
    MeVector3Subtract(v2, p, A);
    d00 = MeVector3Dot(v0, v0);
    d01 = MeVector3Dot(v0, v1);
    d11 = MeVector3Dot(v1, v1);
    d20 = MeVector3Dot(v2, v0);
    d21 = MeVector3Dot(v2, v1);
    den = d00 * d11 - d01 * d01;
    if (den > ME_R(0.0)) {
        l1 = (d11 * d20 - d01 * d21) / den;
        l2 = (d00 * d21 - d01 * d20) / den;
    } else {
        l1 = l2 = ME_R(1.0) / ME_R(3.0);
    }
    l0 = ME_R(1.0) - l1 - l2;
    MeVector3Set(out->p1, ME_R(0.0), ME_R(0.0), ME_R(0.0));
    MeVector3Set(out->p2, ME_R(0.0), ME_R(0.0), ME_R(0.0));
    MeVector3MultiplyAdd(out->p1, l0, e->a[fc->v[0]]);
    MeVector3MultiplyAdd(out->p1, l1, e->a[fc->v[1]]);
    MeVector3MultiplyAdd(out->p1, l2, e->a[fc->v[2]]);
    MeVector3MultiplyAdd(out->p2, l0, e->b[fc->v[0]]);
    MeVector3MultiplyAdd(out->p2, l1, e->b[fc->v[1]]);
    MeVector3MultiplyAdd(out->p2, l2, e->b[fc->v[2]]);
    out->distance = -fc->d;
    MeVector3Copy(out->normal, fc->n);
}

void McdNfEpa(const McdNfShape *s1, const McdNfShape *s2, const McdNfSimplex *sx, McdNfDistance *out)
{
    Epa e;
    const MeReal scale = s1->size + s2->size, eps = MCD_NF_REL_EPS * scale;
    MeReal bestD;
    int best;
    if (!startPolytope(&e, s1, s2, sx, eps)) {
        /* D is flat near the origin (cannot happen for full-dimensional cores): report touching
         * along the line of centres. */
        out->distance = ME_R(0.0);
        MeVector3Subtract(out->normal, s2->tm[3], s1->tm[3]);
        MeVector3Normalize(out->normal);
        MeVector3Copy(out->p1, s1->tm[3]);
        MeVector3Copy(out->p2, s1->tm[3]);
        return;
    }
    expandPolytope(&e, s1, s2, eps);
    best = nearestFace(&e, &bestD);
    if (best < 0) {
        out->distance = ME_R(0.0);
        MeVector3Set(out->normal, ME_R(0.0), ME_R(0.0), ME_R(1.0));
        MeVector3Copy(out->p1, s1->tm[3]);
        MeVector3Copy(out->p2, s1->tm[3]);
        return;
    }
    resultFromFace(&e, &e.f[best], out);
}
