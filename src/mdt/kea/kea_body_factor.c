/* kea_body_factor.c -- the direct path's free-row solves through the bodies' coordinates, for
 * partitions with many rows on few bodies (a stack of blocks: 12 contact rows a body, twice its six
 * degrees of freedom).
 *
 * With E = diag(eps_F) and J = J_F the free rows, A_FF = E + J M^-1 J^T, and by Woodbury
 *     A_FF^-1 v = E^-1 (v - J z),   H z = J^T E^-1 v,   H = M + J^T E^-1 J,
 * so a solve with the free rows needs a factor of H (6 per body) instead of one of A_FF (one per
 * row), and neither A's off-diagonal entries nor the rows' pattern. H's blocks couple two bodies only
 * when a free row joins them; its coordinates go body by body in the elimination order
 * (kea_order.c), and its Cholesky factor is kept on envelopes (a stack's is block-tridiagonal).
 *
 * Accuracy: x comes from a difference of nearly equal terms divided by eps, so in float one such
 * solve loses what eps is small against (8 to 230 times the error of A_FF's own factor, measured by
 * bench/topple/body_space_accuracy.py). The Newton points are therefore refined once: r = v - A_FF x
 * through the bodies (O(rows)), x += the same solve of r; refined, they match A_FF's factor. The
 * final refinement and the friction polish's own refinement step need no second one. Unrefined
 * Newton points were as exact by the residual but a few 1e-4 off in the worst solves, enough to
 * change how Topple's fallen blocks rest (bench/RESULTS.md, "Topple: the exact path in body
 * coordinates"). The polish's columns A_FF^-1 A_F,i need no difference at all:
 * A_FF^-1 J_F M^-1 = E^-1 J_F H^-1.
 *
 * Changes of the free set (the friction passes'; the direct path leaves this factor at the active
 * set's first pivot, kea_direct.c): freeing row i adds j_i j_i^T / eps_i to H, fixing it subtracts
 * the same (a downdate of the factor would be unstable, a subtraction from H is not: its rounding is
 * of the size of H's own); H is refactored at the next solve from the first body that changed. */
#include "kea_internal.h"

/* The partitions laid out for this path: at least 1.5 rows a body coordinate (a stack of blocks has
 * 2; a ragdoll or a chain less than 1), at least two bodies and more than 18 rows (smaller ones, a
 * block on the ground or on a block, cost more this way: bench/RESULTS.md), at most 16 bodies (H is
 * D x D, dense storage). */
#define KEA_BODY_FACTOR_ROWS_NUM 3
#define KEA_BODY_FACTOR_ROWS_DEN 2
#define KEA_BODY_FACTOR_MIN_ROWS 18
#define KEA_BODY_FACTOR_MAX_BODIES 16
/* Softness below this share of a row's own J M^-1 J^T makes E^-1 too large for H in float: such a
 * partition keeps the row factor. */
#define KEA_BODY_FACTOR_MIN_EPS ME_R(1e-3)

struct KeaBodyFactor {
    int nb, D, ld;      /**< bodies, coordinates, H's and L's row stride (D + 4: a block row is
                             written as eight lanes, the last two adding 0 to what follows) */
    const KeaProblem *rows;
    int *slot;          /**< nb: first coordinate of each body in H */
    int *bodyFirst;     /**< nb: first body (by slot) coupled to each body by some row */
    MeReal *H;          /**< D x D row-major, lower triangle: M + sum_F j j^T / eps */
    MeReal *L;          /**< D x D: H's Cholesky factor on envelopes */
    int *first;         /**< D: first column of each row's envelope */
    MeReal *inv;        /**< D: 1 / L_kk */
    MeReal *g;          /**< D: J^T E^-1 v, then z */
    MeReal *gp;         /**< 8 (nb + 1): g body by body as two padded 3-vectors (lanes), the last
                             body the world's (written, never read into g) */
    int *rowSlot;       /**< 2n: each half's body in gp (8 rank, the world 8 nb) */
    const KeaBodyColumns *columns; /**< nb: the bodies' inverse mass and inertia (lanes) */
    MeReal *invEps;     /**< n */
    MeReal *rhs;        /**< n: the refinement's right-hand side, by position */
    int dirty;          /**< H changed since it was factored */
    int dirtyFrom;      /**< the factor's rows before this one are still H's (H changed after them) */
};

int KeaBodyFactorFits(int nRows, int nBodies)
{
    return nBodies >= 2 && nRows > KEA_BODY_FACTOR_MIN_ROWS && nBodies <= KEA_BODY_FACTOR_MAX_BODIES &&
           KEA_BODY_FACTOR_ROWS_DEN * nRows >= KEA_BODY_FACTOR_ROWS_NUM * 6 * nBodies;
}

KeaBodyFactor *KeaBodyFactorCreate(KeaArena *arena, int n, int nb)
{
    KeaBodyFactor *f;
    const int D = 6 * nb;
    if (!KeaBodyFactorFits(n, nb))
        return NULL;
    f = KEA_ALLOC(arena, KeaBodyFactor, 1);
    {
        KeaBodyFactor counting, *w = f ? f : &counting; /* counting mode: same layout */
        w->nb = nb;
        w->D = D;
        w->ld = D + 4;
        w->slot = KEA_ALLOC(arena, int, nb);
        w->bodyFirst = KEA_ALLOC(arena, int, nb);
        w->H = KEA_ALLOC(arena, MeReal, (size_t)D * (size_t)(D + 4));
        w->L = KEA_ALLOC(arena, MeReal, (size_t)D * (size_t)(D + 4));
        w->first = KEA_ALLOC(arena, int, D);
        w->inv = KEA_ALLOC(arena, MeReal, D);
        w->g = KEA_ALLOC(arena, MeReal, D);
        w->gp = KEA_ALLOC(arena, MeReal, 8 * (nb + 1));
        w->rowSlot = KEA_ALLOC(arena, int, 2 * n);
        w->invEps = KEA_ALLOC(arena, MeReal, n);
        w->rhs = KEA_ALLOC(arena, MeReal, n);
    }
    return f;
}

/* 3 x 3 inverse of a symmetric positive definite matrix (the body's inertia from its inverse);
 * returns 0 when it is not safely invertible.
 * Not MeMatrix3SymmetricInvert, which takes any non-singular symmetric matrix: H's Cholesky needs a
 * positive definite inertia, held to the row factor's pivot floor (a refusal: the row factor). */
static int KeaInverse3(const MeReal m[3][3], MeReal out[3][3])
{
    const MeReal c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1], c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2],
                 c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const MeReal det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    const MeReal scale = m[0][0] * m[1][1] * m[2][2];
    MeReal s;
    if (!(m[0][0] > ME_R(0.0) && m[1][1] > ME_R(0.0) && m[2][2] > ME_R(0.0) && det > KEA_PIVOT_FLOOR * scale))
        return 0;
    s = ME_R(1.0) / det;
    out[0][0] = c00 * s;
    out[1][0] = c01 * s;
    out[2][0] = c02 * s;
    out[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * s;
    out[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * s;
    out[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * s;
    out[0][1] = out[1][0];
    out[0][2] = out[2][0];
    out[1][2] = out[2][1];
    return 1;
}

/* H = M: each body's mass on its linear coordinates, its inertia on its angular ones. */
static int KeaBodyFactorMass(KeaBodyFactor *f)
{
    const int D = f->ld;
    int b, k, q, r;
    for (r = 0; r < f->D; ++r) /* the envelope, to the end of the row's own block and its lanes' pad */
        for (k = f->first[r]; k < r - r % 6 + 8; ++k)
            f->H[(size_t)r * (size_t)D + (size_t)k] = ME_R(0.0);
    f->dirty = 1;
    f->dirtyFrom = 0;
    for (b = 0; b < f->nb; ++b) {
        const KeaBody *body = &f->rows->bodies[b];
        MeReal inertia[3][3];
        MeReal *h = f->H + (size_t)f->slot[b] * (size_t)D + (size_t)f->slot[b];
        if (!(body->invMass > ME_R(0.0)) || !KeaInverse3(body->invInertia, inertia))
            return 0;
        for (k = 0; k < 3; ++k) {
            h[k * D + k] = ME_R(1.0) / body->invMass;
            for (q = 0; q < 3; ++q)
                h[(3 + k) * D + 3 + q] = inertia[k][q];
        }
    }
    return 1;
}

/* The six components (linear, angular) of row i's half h. */
static void KeaHalf6(const KeaJacobianRow *J, int h, MeReal *a)
{
    const MeReal *l = h ? J->lin1 : J->lin0, *g = h ? J->ang1 : J->ang0;
    int k;
    for (k = 0; k < 3; ++k) {
        a[k] = l[k];
        a[3 + k] = g[k];
    }
    a[6] = a[7] = ME_R(0.0); /* the lanes' pad (KeaBodyFactorBlock) */
}

/* H's block (s1, s2) += c a1 a2^T, each row as eight lanes: a2's last two are 0, so they add 0 to
 * the entries after the block. In a diagonal block the entries above the diagonal are never read:
 * its first four rows get only their first four lanes.
 * Size: H's storage (pointer, stride), the block's place and the outer product's three factors. */
static void KeaBodyFactorBlock(MeReal *H, int ld, int s1, int s2, MeReal c, const MeReal *a1, const MeReal *a2)
{
    const KeaLanes lo = KeaLanesLoad(a2), hi = KeaLanesLoad(a2 + 4);
    int p;
    for (p = 0; p < 6; ++p) {
        MeReal *row = H + (size_t)(s1 + p) * (size_t)ld + (size_t)s2;
        const KeaLanes cp = KeaLanesSplat(c * a1[p]);
        KeaLanesStore(row, KeaLanesAdd(KeaLanesLoad(row), KeaLanesMul(cp, lo)));
        if (p >= 4 || s1 != s2)
            KeaLanesStore(row + 4, KeaLanesAdd(KeaLanesLoad(row + 4), KeaLanesMul(cp, hi)));
    }
}

void KeaBodyFactorAddRow(KeaBodyFactor *f, int i, MeReal sign)
{
    const int *rb = f->rows->rowBodies[i];
    const MeReal c = sign * f->invEps[i];
    MeReal a[2][8];
    int s0, s1;
    KeaHalf6(&f->rows->J[i], 0, a[0]);
    KeaHalf6(&f->rows->J[i], 1, a[1]);
    s0 = rb[0] >= 0 ? f->slot[rb[0]] : -1;
    s1 = rb[1] >= 0 ? f->slot[rb[1]] : -1;
    if (s0 >= 0) {
        KeaBodyFactorBlock(f->H, f->ld, s0, s0, c, a[0], a[0]);
        f->dirtyFrom = s0 < f->dirtyFrom ? s0 : f->dirtyFrom;
    }
    if (s1 >= 0) {
        KeaBodyFactorBlock(f->H, f->ld, s1, s1, c, a[1], a[1]);
        f->dirtyFrom = s1 < f->dirtyFrom ? s1 : f->dirtyFrom;
    }
    if (s0 >= 0 && s1 >= 0) { /* the lower triangle's block of the pair */
        if (s0 > s1)
            KeaBodyFactorBlock(f->H, f->ld, s0, s1, c, a[0], a[1]);
        else
            KeaBodyFactorBlock(f->H, f->ld, s1, s0, c, a[1], a[0]);
    }
    f->dirty = 1;
}

int KeaBodyFactorBegin(KeaBodyFactor *f, const KeaProblem *problem, const KeaBodyColumns *columns,
                       const int *rank, const MeReal *diag, size_t stride)
{
    const int n = problem->nRows;
    int i, b, k;
    if (!f || !problem->epsilon)
        return 0;
    f->rows = problem;
    f->columns = columns;
    for (i = 0; i < n; ++i) {
        const int *rb = problem->rowBodies[i];
        f->rowSlot[2 * i] = 8 * (rb[0] >= 0 ? rank[rb[0]] : f->nb);
        f->rowSlot[2 * i + 1] = 8 * (rb[1] >= 0 ? rank[rb[1]] : f->nb);
        const MeReal eps = problem->epsilon[i];
        /* a row touching one body twice, or softness too small against the row's own diagonal */
        if ((rb[0] >= 0 && rb[0] == rb[1]) || !(eps > KEA_BODY_FACTOR_MIN_EPS * diag[(size_t)i * stride]))
            return 0;
        f->invEps[i] = ME_R(1.0) / eps;
    }
    for (b = 0; b < f->nb; ++b) {
        f->slot[b] = 6 * rank[b];
        f->bodyFirst[b] = rank[b];
    }
    for (i = 0; i < n; ++i) { /* envelopes by body: the lowest-ranked body a row joins to each */
        const int *rb = problem->rowBodies[i];
        if (rb[0] >= 0 && rb[1] >= 0) {
            const int lo = rank[rb[0]] < rank[rb[1]] ? rank[rb[0]] : rank[rb[1]];
            if (lo < f->bodyFirst[rb[0]])
                f->bodyFirst[rb[0]] = lo;
            if (lo < f->bodyFirst[rb[1]])
                f->bodyFirst[rb[1]] = lo;
        }
    }
    for (b = 0; b < f->nb; ++b)
        for (k = 0; k < 6; ++k)
            f->first[f->slot[b] + k] = 6 * f->bodyFirst[b];
    return KeaBodyFactorMass(f);
}

int KeaBodyFactorRebuild(KeaBodyFactor *f, const int *F, int size)
{
    int p;
    if (!KeaBodyFactorMass(f))
        return 0;
    for (p = 0; p < size; ++p)
        KeaBodyFactorAddRow(f, F[p], ME_R(1.0));
    return 1;
}

/* H = L L^T on the envelopes; a pivot below the floor (H's rounding after many subtractions) is
 * raised to it and counted, as the row factor does. */
static int KeaBodyFactorFactor(KeaBodyFactor *f)
{
    const int D = f->D;
    int r, c, regularised = 0;
    for (r = f->dirtyFrom; r < D; ++r) { /* row r of L depends on H's rows up to r only */
        const int fr = f->first[r];
        const MeReal *h = f->H + (size_t)r * (size_t)f->ld;
        MeReal *l = f->L + (size_t)r * (size_t)f->ld, d;
        for (c = fr; c < r; ++c) {
            const MeReal *lc = f->L + (size_t)c * (size_t)f->ld;
            const int m0 = fr > f->first[c] ? fr : f->first[c];
            l[c] = (h[c] - KeaDotN4(l + m0, lc + m0, c - m0)) * f->inv[c];
        }
        d = h[r] - KeaDotN4(l + fr, l + fr, r - fr);
        if (!(d > KEA_PIVOT_FLOOR * h[r])) {
            d = KEA_PIVOT_FLOOR * h[r] > ME_R(0.0) ? KEA_PIVOT_FLOOR * h[r] : ME_MIN_EPSILON;
            ++regularised;
        }
        l[r] = KeaSqrt(d);
        f->inv[r] = ME_R(1.0) / l[r];
    }
    f->dirty = 0;
    f->dirtyFrom = D;
    return regularised;
}

/* gp = sum over the rows F[p] of J_F[p]^T w[p] (w by position; the world's half lands in the last
 * body, unread): two lane operations a half. */
static void KeaBodyFactorScatter(KeaBodyFactor *f, const int *F, int size, const MeReal *w, int scaled)
{
    const KeaProblem *pr = f->rows;
    int p, k;
    for (k = 0; k < 8 * (f->nb + 1); ++k)
        f->gp[k] = ME_R(0.0);
    for (p = 0; p < size; ++p) {
        const int i = F[p];
        const KeaJacobianRow *J = &pr->J[i];
        const KeaLanes s = KeaLanesSplat(scaled ? w[p] * f->invEps[i] : w[p]);
        MeReal *g0 = f->gp + f->rowSlot[2 * i], *g1 = f->gp + f->rowSlot[2 * i + 1];
        KeaLanesStore(g0, KeaLanesAdd(KeaLanesLoad(g0), KeaLanesMul(KeaLanesLoad(J->lin0), s)));
        KeaLanesStore(g0 + 4, KeaLanesAdd(KeaLanesLoad(g0 + 4), KeaLanesMul(KeaLanesLoad(J->ang0), s)));
        KeaLanesStore(g1, KeaLanesAdd(KeaLanesLoad(g1), KeaLanesMul(KeaLanesLoad(J->lin1), s)));
        KeaLanesStore(g1 + 4, KeaLanesAdd(KeaLanesLoad(g1 + 4), KeaLanesMul(KeaLanesLoad(J->ang1), s)));
    }
}

/* J_F[p] . gp for the row F[p] (lanes 0-2 of each half; gp's pads and the world's body are 0). */
static MeReal KeaBodyFactorGather(const KeaBodyFactor *f, int i)
{
    const KeaJacobianRow *J = &f->rows->J[i];
    const MeReal *g0 = f->gp + f->rowSlot[2 * i], *g1 = f->gp + f->rowSlot[2 * i + 1];
    const KeaLanes a = KeaLanesAdd(KeaLanesMul(KeaLanesLoad(J->lin0), KeaLanesLoad(g0)),
                                   KeaLanesMul(KeaLanesLoad(J->ang0), KeaLanesLoad(g0 + 4)));
    const KeaLanes b = KeaLanesAdd(KeaLanesMul(KeaLanesLoad(J->lin1), KeaLanesLoad(g1)),
                                   KeaLanesMul(KeaLanesLoad(J->ang1), KeaLanesLoad(g1 + 4)));
    return KeaLanesSum3(KeaLanesAdd(a, b));
}

/* gp (J^T E^-1 v, padded) -> z = H^-1 of it, back in gp (padded, pads and the world 0). */
static void KeaBodyFactorSolveH(KeaBodyFactor *f)
{
    const int D = f->D, nb = f->nb;
    MeReal *g = f->g;
    int r, k;
    for (r = 0; r < nb; ++r)
        for (k = 0; k < 3; ++k) {
            g[6 * r + k] = f->gp[8 * r + k];
            g[6 * r + 3 + k] = f->gp[8 * r + 4 + k];
        }
    for (r = 0; r < D; ++r) { /* L y = g */
        const MeReal *l = f->L + (size_t)r * (size_t)f->ld;
        g[r] = (g[r] - KeaDotN4(l + f->first[r], g + f->first[r], r - f->first[r])) * f->inv[r];
    }
    for (r = D - 1; r >= 0; --r) { /* L^T z = y, by columns so that L is read by rows */
        const MeReal *l = f->L + (size_t)r * (size_t)f->ld;
        const MeReal z = g[r] * f->inv[r];
        g[r] = z;
        KeaSubtractScaled(g + f->first[r], l + f->first[r], z, r - f->first[r]);
    }
    for (r = 0; r < nb; ++r) {
        for (k = 0; k < 3; ++k) {
            f->gp[8 * r + k] = g[6 * r + k];
            f->gp[8 * r + 4 + k] = g[6 * r + 3 + k];
        }
        f->gp[8 * r + 3] = f->gp[8 * r + 7] = ME_R(0.0);
    }
    for (k = 0; k < 8; ++k)
        f->gp[8 * nb + k] = ME_R(0.0);
}

/* v = A_FF^-1 v once through H (v by position in F; the top comment's formula). */
static void KeaBodyFactorSolveOnce(KeaBodyFactor *f, const int *F, int size, MeReal *v)
{
    int p;
    KeaBodyFactorScatter(f, F, size, v, 1);
    KeaBodyFactorSolveH(f);
    for (p = 0; p < size; ++p)
        v[p] = (v[p] - KeaBodyFactorGather(f, F[p])) * f->invEps[F[p]];
}

int KeaBodyFactorSolve(KeaBodyFactor *f, const int *F, int size, MeReal *v, int refine)
{
    const KeaProblem *pr = f->rows;
    int p, regularised = 0;
    if (size == 0)
        return 0;
    if (f->dirty)
        regularised = KeaBodyFactorFactor(f);
    for (p = 0; p < size; ++p)
        f->rhs[p] = v[p];
    KeaBodyFactorSolveOnce(f, F, size, v);
    if (!refine)
        return regularised;
    /* one step of refinement: rhs - A_FF v through the bodies (M^-1 J^T v, then each row's J and
     * eps), solved the same way */
    KeaBodyFactorScatter(f, F, size, v, 0);
    {
        int b;
        for (b = 0; b < pr->nBodies; ++b) { /* by body: its slot is 8 rank */
            const KeaBodyColumns *c = &f->columns[b];
            MeReal *g = f->gp + f->slot[b] / 6 * 8;
            const KeaLanes lin = KeaLanesMul(KeaLanesSplat(c->invMass), KeaLanesLoad(g));
            const KeaLanes ang = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(KeaLanesLoad(c->col[0]), KeaLanesSplat(g[4])),
                                                         KeaLanesMul(KeaLanesLoad(c->col[1]), KeaLanesSplat(g[5]))),
                                             KeaLanesMul(KeaLanesLoad(c->col[2]), KeaLanesSplat(g[6])));
            KeaLanesStore(g, lin);
            KeaLanesStore(g + 4, ang);
            g[3] = g[7] = ME_R(0.0);
        }
        for (p = 0; p < 8; ++p)
            f->gp[8 * f->nb + p] = ME_R(0.0);
    }
    for (p = 0; p < size; ++p)
        f->rhs[p] -= KeaBodyFactorGather(f, F[p]) + pr->epsilon[F[p]] * v[p];
    KeaBodyFactorSolveOnce(f, F, size, f->rhs);
    for (p = 0; p < size; ++p)
        v[p] += f->rhs[p];
    return regularised;
}

void KeaBodyFactorColumn(KeaBodyFactor *f, const int *F, int size, int row, MeReal coef, MeReal *u)
{
    int p;
    if (f->dirty)
        (void)KeaBodyFactorFactor(f);
    KeaBodyFactorScatter(f, &row, 1, &coef, 0);
    KeaBodyFactorSolveH(f);
    for (p = 0; p < size; ++p)
        u[p] = KeaBodyFactorGather(f, F[p]) * f->invEps[F[p]];
}

