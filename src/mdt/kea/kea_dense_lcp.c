/* kea_dense_lcp.c -- the exact solver of a dense box LCP, the core of Kea's direct path (whole
 * partition) and of the block sweeps of its iterative path (the rows of one constraint): a primal
 * active-set (pivoting) method on A = J M^-1 J^T + diag(eps), symmetric positive definite, with an
 * updatable Cholesky factor of the free block.
 *
 * The box LCP with A symmetric positive definite is the convex QP  min 1/2 x^T A x - r^T x  over
 * lo <= x <= hi. Every row is in one of three states: free, fixed at lo, fixed at hi (a row with
 * lo == hi is pinned and never freed). The method keeps a feasible x and the factor A_FF = L L^T of
 * the free rows F, and repeats:
 *   1. Newton point on the current face: y_F = A_FF^-1 (r_F - A_FB x_B) (two triangular solves).
 *   2. Ratio test: walk from x_F towards y_F; if a free row reaches a bound first, stop there, fix
 *      that row at the bound (remove it from the factor) and go to 1. The objective does not increase.
 *   3. Otherwise x_F = y_F is optimal on the face. Compute the multipliers w_j = (A x - r)_j of the
 *      fixed rows; a row at lo with w_j < 0 (or at hi with w_j > 0) could lower the objective by
 *      moving inside. If none does (within a tolerance scaled to the problem), x solves the LCP;
 *      else free the one with the largest predicted decrease w_j^2 / A_jj (append it to the factor)
 *      and go to 1.
 * Each free/fix is a pivot costing O(n^2) (factor update, solves, multipliers). The objective
 * decreases strictly at every step of positive length, so no face repeats unless steps of zero
 * length occur (degeneracy); against that, a row freed and immediately re-fixed without progress is
 * locked (not freed again) until a step of positive length is taken, and maxPivots caps the total,
 * returning the current (feasible, best so far) iterate with KeaStatusMaxPivots.
 *
 * Warm start: x0 clamped to the bounds gives the first x; rows strictly inside are free, and so are
 * rows at a bound whose multiplier at x0 has the wrong sign (they would be freed by the first pivots
 * anyway: a new contact's pressed normal row); the first factor is built from them. With last step's
 * impulses the active set is usually right and the solve is one factorisation plus a handful of
 * pivots. Each pivot costs O(n^2) on a dense problem (O(n) plus the factor's envelope on a sparse
 * one, below).
 *
 * Friction links (bounds +-mu x_link): each pass solves the box QP with the bounds fixed from the
 * current x; then the bounds are recomputed from the solution. If they moved by more than a small
 * tolerance, the next pass starts from the current x and factor (rows whose bound moved stay at the
 * same side of their new bound, free rows now outside are fixed, rows pinned at 0 that can now move
 * are freed), until the bounds stop moving or maxFrictionPasses. The fixed point of this outer loop
 * is the solution of the friction-coupled LCP.
 *
 * A final step of iterative refinement on the free block removes the drift left by the updates.
 *
 * Sparse partitions (the direct path): the LCP may come with a factoring order, A's pattern and the
 * rows A is made of (KeaDenseLcp). Then the factor works on envelopes (kea_dense.c), only A's
 * pattern is read, and every product with A goes through the bodies (A v = J M^-1 J^T v + eps v,
 * O(n)), so the costs above become those of the sparse factor: about linear in n for chains and
 * trees of bodies. The blocks of the iterative path use the plain dense form.
 *
 * The free rows' factor may instead be kept in the bodies' coordinates (KeaDenseWorkUseBodyFactor,
 * kea_body_factor.c: a resting stack); then only A's diagonal is read. */
#include <string.h>

#include "kea_internal.h"

enum { KEA_FREE = 0, KEA_AT_LO = 1, KEA_AT_HI = 2 };
/* Whether a solve with the body factor is refined once (kea_body_factor.c): the Newton points are,
 * the final refinement and the polish's Woodbury solves (followed by their own refinement) are not. */
enum { KEA_REFINE_NEWTON = 1, KEA_REFINE_OTHER = 0 };

/* The per-row helpers below run inside every O(n) pass of the method; gcc's heuristics keep some of
 * them out of line, so they are asked inline by attribute where the compiler has one. */
#if defined(__GNUC__)
#  define KEA_DENSE_INLINE static inline __attribute__((always_inline))
#else
#  define KEA_DENSE_INLINE static inline
#endif

struct KeaDenseWork {
    int capacity;        /**< largest n this workspace serves */
    KeaCholesky chol;    /**< factor of the free block */
    MeReal *lo, *hi;     /**< bounds of the current pass */
    MeReal *y;           /**< Newton point (by position in F) */
    int *nonzero;        /**< rows with x != 0 (scratch list; LCPs given without their rows) */
    MeReal *xFixed;      /**< x on the fixed rows, 0 on the free ones (scratch) */
    signed char *state;  /**< KEA_FREE, KEA_AT_LO, KEA_AT_HI */
    unsigned char *locked; /**< freed-and-refixed without progress: not freed again for now */
    /* Friction polish (coupled solve), at most n/2 normal rows carry sliding friction rows: */
    MeReal *U;           /**< n x n/2: columns u_N, then A_FF^-1 u_N */
    MeReal *G;           /**< (n/2)^2: the capacitance matrix I + V^T A_FF^-1 U */
    MeReal *t;           /**< n/2 */
    MeReal *cand;        /**< n: candidate solution */
    int *slot;           /**< n: column of a normal row in U, or -1 */
    unsigned char *sliding; /**< n: KeaIsSliding of each row, set once by each polish */
    int *normals;        /**< n/2: normal rows with sliding friction rows */
    int *perm;           /**< n/2: row swaps of the capacitance matrix's LU */
    int velocityCurrent; /**< the last solve ended on an accepted polish whose products left
                              M^-1 J^T x in lcp->velocity, and its rows' residuals in residual */
    int velocityOfX;     /**< lcp->velocity holds M^-1 J^T x for the x of the last pricing, which
                              found the optimum, and x has not moved since (the refinement's) */
    MeReal residual;     /**< then: KeaResidualWithDiagonal of the returned x (same sums) */
    MeReal rScale;       /**< max |r_i| of the LCP being solved (the tolerances' scale) */
    MeReal diagMax;      /**< max A_ii of the LCP being solved */
    MeReal xScale;       /**< max |x_i| at the last pricing (x unchanged since when it found the optimum) */
    KeaBodyFactor *body; /**< the free rows solved through the bodies (kea_body_factor.c), or NULL */
};

KeaDenseWork *KeaDenseWorkCreate(KeaArena *arena, int n)
{
    KeaDenseWork *result = KEA_ALLOC(arena, KeaDenseWork, 1);
    KeaDenseWork counting, *w = result ? result : &counting; /* counting mode: same layout */
    const int half = (n + 1) / 2;
    w->capacity = n;
    w->chol.L = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)n);
    w->chol.F = KEA_ALLOC(arena, int, n);
    w->chol.pos = KEA_ALLOC(arena, int, n);
    w->chol.first = KEA_ALLOC(arena, int, n);
    w->chol.inv = KEA_ALLOC(arena, MeReal, n);
    w->lo = KEA_ALLOC(arena, MeReal, n);
    w->hi = KEA_ALLOC(arena, MeReal, n);
    w->y = KEA_ALLOC(arena, MeReal, n);
    w->nonzero = KEA_ALLOC(arena, int, n);
    w->xFixed = KEA_ALLOC(arena, MeReal, n);
    w->state = KEA_ALLOC(arena, signed char, n);
    w->locked = KEA_ALLOC(arena, unsigned char, n);
    w->U = KEA_ALLOC(arena, MeReal, (size_t)n * (size_t)half);
    w->G = KEA_ALLOC(arena, MeReal, (size_t)half * (size_t)half);
    w->t = KEA_ALLOC(arena, MeReal, half);
    w->cand = KEA_ALLOC(arena, MeReal, n);
    w->slot = KEA_ALLOC(arena, int, n);
    w->sliding = KEA_ALLOC(arena, unsigned char, n);
    w->normals = KEA_ALLOC(arena, int, half);
    w->perm = KEA_ALLOC(arena, int, half);
    w->chol.ld = n;
    w->chol.size = 0;
    w->chol.regularised = 0;
    w->body = NULL;
    return result;
}

void KeaDenseWorkUseBodyFactor(KeaDenseWork *w, KeaBodyFactor *f) { w->body = f; }

/* The free set's factor, whichever it is: append row i, remove the row at position p, solve
 * A_FF v = b in place (b zero before position `from`). The body factor keeps only F and pos here. */
static void KeaFreeAppend(const KeaDenseLcp *lcp, KeaDenseWork *w, int i)
{
    KeaCholesky *c = &w->chol;
    if (!w->body) {
        KeaCholeskyAppend(c, lcp->A, lcp->n, i);
        return;
    }
    c->F[c->size] = i;
    c->pos[i] = c->size++;
    KeaBodyFactorAddRow(w->body, i, ME_R(1.0));
}

static void KeaFreeRemove(KeaDenseWork *w, int p)
{
    KeaCholesky *c = &w->chol;
    int q;
    if (!w->body) {
        KeaCholeskyRemove(c, p);
        return;
    }
    KeaBodyFactorAddRow(w->body, c->F[p], ME_R(-1.0));
    c->pos[c->F[p]] = -1;
    for (q = p + 1; q < c->size; ++q) {
        c->F[q - 1] = c->F[q];
        c->pos[c->F[q - 1]] = q - 1;
    }
    --c->size;
}

static void KeaFreeSolve(KeaDenseWork *w, MeReal *b, int from, int refine)
{
    if (w->body)
        w->chol.regularised += KeaBodyFactorSolve(w->body, w->chol.F, w->chol.size, b, refine);
    else
        KeaCholeskySolveFrom(&w->chol, b, from);
}

/* Effective bounds of row i (friction links applied, same rule as KeaRowBounds). */
KEA_DENSE_INLINE void KeaDenseLinkBounds(const KeaDenseLcp *lcp, int i, MeReal xLink, MeReal *lo, MeReal *hi)
{
    KeaFrictionBounds(lcp->lo[i], lcp->hi[i], lcp->mu[i], xLink, lo, hi);
}

KEA_DENSE_INLINE void KeaDenseBounds(const KeaDenseLcp *lcp, const MeReal *x, int i, MeReal *lo, MeReal *hi)
{
    if (lcp->link && lcp->link[i] >= 0) {
        KeaDenseLinkBounds(lcp, i, x[lcp->link[i]], lo, hi);
    } else {
        *lo = lcp->lo[i];
        *hi = lcp->hi[i];
    }
}

/* Get ready for products (A v)_i with this v: with the LCP's rows, the bodies' velocity changes
 * M^-1 J^T v (O(n)), so that each product costs one row (A v = J M^-1 J^T v + eps v); else the list
 * of v's non-zeros (returns their count). Either way what was ready for x is no longer. */
static int KeaDensePrepare(const KeaDenseLcp *lcp, KeaDenseWork *w, const MeReal *v, int *list)
{
    int j, nz = 0;
    w->velocityOfX = 0;
    if (lcp->rows) {
        KeaBodyVelocityFromImpulses(lcp->rows, v, lcp->velocity);
        return 0;
    }
    for (j = 0; j < lcp->n; ++j)
        if (v[j] != ME_R(0.0))
            list[nz++] = j;
    return nz;
}

/* (A v)_i, after KeaDensePrepare(lcp, w, v, list) returned nz. */
KEA_DENSE_INLINE MeReal KeaDenseRowDot(const KeaDenseLcp *lcp, int i, const MeReal *v, const int *list, int nz)
{
    const MeReal *Ai;
    MeReal s = ME_R(0.0);
    int k;
    if (lcp->rows) {
        const KeaProblem *p = lcp->rows;
        return KeaRowVelocity(&p->J[i], p->rowBodies[i], lcp->velocity) + (p->epsilon ? p->epsilon[i] * v[i] : ME_R(0.0));
    }
    Ai = lcp->A + (size_t)i * (size_t)lcp->n;
    for (k = 0; k < nz; ++k)
        s += Ai[list[k]] * v[list[k]];
    return s;
}

/* y[p] = (r - A v)_F[p] with the products ready for v (KeaDensePrepare returned nz). */
static void KeaFreeRowsProducts(const KeaDenseLcp *lcp, KeaDenseWork *w, const MeReal *v, int nz)
{
    const KeaCholesky *c = &w->chol;
    const KeaProblem *rows = lcp->rows;
    int p;
    if (rows && rows->epsilon) { /* the direct path: KeaDenseRowDot's two tests once, not once a row */
        for (p = 0; p < c->size; ++p) {
            const int i = c->F[p];
            const MeReal Av = KeaRowVelocity(&rows->J[i], rows->rowBodies[i], lcp->velocity) + rows->epsilon[i] * v[i];
            w->y[p] = lcp->r[i] - Av;
        }
        return;
    }
    for (p = 0; p < c->size; ++p)
        w->y[p] = lcp->r[c->F[p]] - KeaDenseRowDot(lcp, c->F[p], v, w->nonzero, nz);
}

/* y[p] = (r - A v)_F[p]: the free rows' right-hand side at v (the Newton point's, the refinement's
 * and the polish's residual). */
static void KeaFreeRowsResidual(const KeaDenseLcp *lcp, KeaDenseWork *w, const MeReal *v)
{
    KeaFreeRowsProducts(lcp, w, v, KeaDensePrepare(lcp, w, v, w->nonzero));
}

/* Free every row that is free by state, in the LCP's order (a fresh factorisation). */
static void KeaDenseFactorFree(const KeaDenseLcp *lcp, KeaDenseWork *w, KeaStats *stats)
{
    const int n = lcp->n;
    int i, k;
    w->chol.size = 0;
    for (i = 0; i < n; ++i)
        w->chol.pos[i] = -1;
    for (k = 0; k < n; ++k) {
        i = lcp->order ? lcp->order[k] : k;
        if (w->state[i] != KEA_FREE)
            continue;
        if (w->body) {
            w->chol.F[w->chol.size] = i;
            w->chol.pos[i] = w->chol.size++;
        } else {
            KeaCholeskyAppend(&w->chol, lcp->A, n, i);
        }
    }
    if (w->body)
        (void)KeaBodyFactorRebuild(w->body, w->chol.F, w->chol.size);
    ++stats->factorizations;
}

/* The active-set method's ratio test: along y - x_F (y by position in F), the largest step alpha
 * <= 1 before a free row meets a bound; returns the position in F of the row that blocks (ties go
 * to the first row in F: deterministic) with *side its bound, or -1 (alpha 1). */
static int KeaRatioTest(const KeaDenseWork *w, const MeReal *x, MeReal *alpha, int *side)
{
    const KeaCholesky *c = &w->chol;
    int i, p, block = -1;
    *alpha = ME_R(1.0);
    *side = KEA_FREE;
    for (p = 0; p < c->size; ++p) {
        i = c->F[p];
        const MeReal d = w->y[p] - x[i];
        if (d < ME_R(0.0) && KeaIsFinite(w->lo[i]) && w->y[p] < w->lo[i]) {
            const MeReal t = KeaMax((w->lo[i] - x[i]) / d, ME_R(0.0));
            if (t < *alpha) {
                *alpha = t;
                block = p;
                *side = KEA_AT_LO;
            }
        } else if (d > ME_R(0.0) && KeaIsFinite(w->hi[i]) && w->y[p] > w->hi[i]) {
            const MeReal t = KeaMax((w->hi[i] - x[i]) / d, ME_R(0.0));
            if (t < *alpha) {
                *alpha = t;
                block = p;
                *side = KEA_AT_HI;
            }
        }
    }
    return block;
}

/* The active-set method's pricing, at the optimum on the current face: the fixed row (not locked)
 * whose multiplier points inside its bounds by more than the tolerance, the largest w_j^2 / A_jj
 * first; -1 when none does (the box QP's optimum). */
static int KeaEnteringRow(const KeaDenseLcp *lcp, KeaDenseWork *w, const MeReal *x)
{
    const int n = lcp->n;
    MeReal xScale = ME_R(0.0), tolW, bestScore = ME_R(0.0);
    int j, nz, best = -1;
    for (j = 0; j < n; ++j)
        xScale = KeaMax(xScale, KeaFabs(x[j]));
    w->xScale = xScale;
    nz = KeaDensePrepare(lcp, w, x, w->nonzero);
    tolW = KEA_DIRECT_TOL * (w->rScale + w->diagMax * xScale);
    for (j = 0; j < n; ++j) {
        MeReal wj, score;
        if (w->state[j] == KEA_FREE || w->locked[j] || !(w->lo[j] < w->hi[j]))
            continue;
        wj = KeaDenseRowDot(lcp, j, x, w->nonzero, nz) - lcp->r[j];
        if (w->state[j] == KEA_AT_LO ? wj >= -tolW : wj <= tolW)
            continue;
        score = wj * wj / KeaMax(lcp->A[(size_t)j * (size_t)n + (size_t)j], ME_MIN_EPSILON);
        if (score > bestScore) {
            bestScore = score;
            best = j;
        }
    }
    w->velocityOfX = best < 0 && lcp->rows; /* x stays: the refinement may reuse the velocity */
    return best;
}

/* Active-set iterations for the current bounds. Returns KeaStatusOk at the optimum of the box QP,
 * KeaStatusMaxPivots when the cap is hit (x stays feasible). */
static KeaStatus KeaActiveSet(const KeaDenseLcp *lcp, KeaDenseWork *w, MeReal *x, int maxPivots,
                              KeaStats *stats)
{
    const int n = lcp->n;
    const MeReal *r = lcp->r;
    KeaCholesky *c = &w->chol;
    int i, j, p, lastFreed = -1, nLocked = 0;

    memset(w->locked, 0, (size_t)n);
    w->velocityOfX = 0; /* x moves from here (and moved in KeaDenseApplyBounds before) */

    for (;;) {
        MeReal alpha;
        int block, blockSide, nz;

        /* 1. Newton point on the face: A_FF y = r_F - A_FB x_B. */
        nz = 0; /* fixed rows with x != 0 (often none: contacts at 0) */
        for (j = 0; j < n; ++j) {
            w->xFixed[j] = c->pos[j] < 0 ? x[j] : ME_R(0.0);
            nz += w->xFixed[j] != ME_R(0.0);
        }
        if (nz > 0) {
            KeaFreeRowsResidual(lcp, w, w->xFixed);
        } else {
            for (p = 0; p < c->size; ++p)
                w->y[p] = r[c->F[p]];
        }
        KeaFreeSolve(w, w->y, 0, KEA_REFINE_NEWTON);

        /* 2. Ratio test along y - x_F. */
        block = KeaRatioTest(w, x, &alpha, &blockSide);
        for (p = 0; p < c->size; ++p) {
            i = c->F[p];
            const MeReal xi = block < 0 ? w->y[p] : x[i] + alpha * (w->y[p] - x[i]);
            x[i] = KeaClamp(xi, w->lo[i], w->hi[i]);
        }

        if (block >= 0) {
            i = c->F[block];
            x[i] = blockSide == KEA_AT_LO ? w->lo[i] : w->hi[i];
            w->state[i] = (signed char)blockSide;
            KeaFreeRemove(w, block);
            ++stats->pivots;
            if (alpha > ME_R(0.0)) {
                if (nLocked) {
                    memset(w->locked, 0, (size_t)n);
                    nLocked = 0;
                }
            } else if (i == lastFreed) {
                w->locked[i] = 1; /* freed then re-fixed with no progress: degenerate, skip it */
                ++nLocked;
            }
            lastFreed = -1;
            if (stats->pivots >= maxPivots)
                return KeaStatusMaxPivots;
            continue;
        }

        /* 3. Optimal on the face: look for a fixed row whose multiplier has the wrong sign. */
        {
            const int best = KeaEnteringRow(lcp, w, x);
            if (best < 0)
                return KeaStatusOk;
            w->state[best] = KEA_FREE;
            KeaFreeAppend(lcp, w, best);
            lastFreed = best;
            if (++stats->pivots >= maxPivots)
                return KeaStatusMaxPivots;
        }
    }
}

/* State of row i from its value and bounds (warm start, or a pass with new bounds). */
static signed char KeaStateFromValue(MeReal *xi, MeReal lo, MeReal hi)
{
    if (!(lo < hi) || *xi <= lo) {
        *xi = lo;
        return KEA_AT_LO;
    }
    if (*xi >= hi) {
        *xi = hi;
        return KEA_AT_HI;
    }
    return KEA_FREE;
}

/* How far the friction bounds would move if recomputed from the current x. */
/* How inconsistent x is with the friction bounds recomputed from it: for a row at a bound, how far
 * that bound moved; for a pinned row, how much room it gained; for a free row, how far it lies
 * outside. Free rows that stay inside do not count: moving bounds do not change their equations. */
static MeReal KeaDenseBoundMotion(const KeaDenseLcp *lcp, const KeaDenseWork *w, const MeReal *x)
{
    MeReal moved = ME_R(0.0);
    int i;
    for (i = 0; i < lcp->n; ++i) {
        MeReal lo, hi, m;
        if (lcp->link[i] < 0)
            continue;
        KeaDenseLinkBounds(lcp, i, x[lcp->link[i]], &lo, &hi);
        if (w->state[i] == KEA_FREE)
            m = KeaMax(lo - x[i], x[i] - hi);
        else if (!(w->lo[i] < w->hi[i]))
            m = hi - lo;
        else
            m = w->state[i] == KEA_AT_LO ? KeaFabs(lo - w->lo[i]) : KeaFabs(hi - w->hi[i]);
        moved = KeaMax(moved, m);
    }
    return moved;
}

/* Recompute the friction bounds from x and move the rows onto them (see the top comment), updating
 * the factor row by row, or refactoring when many rows change state. */
static void KeaDenseApplyBounds(const KeaDenseLcp *lcp, KeaDenseWork *w, MeReal *x, KeaStats *stats)
{
    const int n = lcp->n;
    int i, leaving = 0, entering = 0;
    signed char *newState = (signed char *)w->locked; /* free scratch between passes */

    for (i = 0; i < n; ++i) {
        MeReal lo, hi;
        signed char s = w->state[i];
        if (lcp->link[i] < 0) {
            newState[i] = s;
            continue;
        }
        KeaDenseLinkBounds(lcp, i, x[lcp->link[i]], &lo, &hi);
        if (s == KEA_FREE || !(w->lo[i] < w->hi[i]) || !(lo < hi))
            s = KeaStateFromValue(&x[i], lo, hi); /* free, pinned or now pinned: clamp into the box */
        else
            x[i] = s == KEA_AT_LO ? lo : hi; /* a row at a bound follows its bound */
        w->lo[i] = lo;
        w->hi[i] = hi;
        newState[i] = s;
        if (w->state[i] == KEA_FREE && s != KEA_FREE)
            ++leaving;
        else if (w->state[i] != KEA_FREE && s == KEA_FREE)
            ++entering;
    }
    if (4 * (leaving + entering) > w->chol.size) {
        for (i = 0; i < n; ++i)
            w->state[i] = newState[i];
        KeaDenseFactorFree(lcp, w, stats);
    } else {
        for (i = 0; i < n; ++i)
            if (w->state[i] == KEA_FREE && newState[i] != KEA_FREE) {
                KeaFreeRemove(w, w->chol.pos[i]);
                ++stats->pivots;
            }
        for (i = 0; i < n; ++i)
            if (w->state[i] != KEA_FREE && newState[i] == KEA_FREE) {
                KeaFreeAppend(lcp, w, i);
                ++stats->pivots;
            }
        for (i = 0; i < n; ++i)
            w->state[i] = newState[i];
    }
}

/* Friction polish: with the current states, a linked row at a bound whose normal row is free sits at
 * sigma mu x_N (sigma = +1 at hi, -1 at lo). Substituting that into the free rows' equations gives
 * (A_FF + U V^T) x_F = b, where column u_N of U gathers sigma mu A_F,i over the sliding rows i of
 * normal N and V^T picks x_N: a rank-m change of A_FF (m = normals with sliding rows). Woodbury's
 * identity solves it with the existing factor: m + 1 solves and an m x m system. If the result is
 * feasible and every fixed row's multiplier has the right sign, it is the exact solution of the
 * coupled problem (the outer passes need not creep towards it). Returns 1 when accepted. */
static int KeaIsSliding(const KeaDenseLcp *lcp, const KeaDenseWork *w, int i)
{
    const int nrm = lcp->link ? lcp->link[i] : -1;
    return nrm >= 0 && w->state[i] != KEA_FREE && w->lo[i] < w->hi[i] && w->state[nrm] == KEA_FREE;
}

/* v <- (A_FF + U V^T)^-1 v by Woodbury, with Z = A_FF^-1 U in w->U and the LU of the capacitance
 * matrix in w->G (m sliding normals). */
static void KeaWoodburySolve(KeaDenseWork *w, int m, MeReal *v)
{
    const KeaCholesky *c = &w->chol;
    const int k = c->size;
    int a, p;
    KeaFreeSolve(w, v, 0, KEA_REFINE_OTHER);
    for (a = 0; a < m; ++a)
        w->t[a] = v[c->pos[w->normals[a]]];
    KeaDenseSolveFactored(m, w->G, w->perm, w->t);
    for (a = 0; a < m; ++a) {
        const MeReal *z = w->U + (size_t)a * (size_t)k;
        for (p = 0; p < k; ++p)
            v[p] -= z[p] * w->t[a];
    }
}

/* cand = x with the free rows from y (by position) and the sliding rows at sigma mu x_N. */
static void KeaPolishCandidate(const KeaDenseLcp *lcp, KeaDenseWork *w)
{
    const KeaCholesky *c = &w->chol;
    int i, p;
    for (p = 0; p < c->size; ++p)
        w->cand[c->F[p]] = w->y[p];
    for (i = 0; i < lcp->n; ++i)
        if (w->sliding[i])
            w->cand[i] = (w->state[i] == KEA_AT_HI ? ME_R(1.0) : ME_R(-1.0)) * lcp->mu[i] *
                         w->cand[lcp->link[i]];
}

/* The polish's low-rank part for the m normal rows that carry sliding friction (w->normals, their
 * positions in w->slot): Z = A_FF^-1 U (column-major, k rows, in U) and the capacitance matrix
 * I + V^T Z, factored in G. Returns 0 when that matrix is singular. */
static int KeaPolishCapacitance(const KeaDenseLcp *lcp, KeaDenseWork *w, int m)
{
    const int n = lcp->n;
    const KeaCholesky *c = &w->chol;
    const int k = c->size;
    int i, j, p, a;
    int *from = w->perm; /* the first non-zero of each column u_N (perm is free until G's LU) */

    for (p = 0; p < k * m; ++p)
        w->U[p] = ME_R(0.0);
    for (i = 0; i < n; ++i) {
        MeReal coef, *u;
        if (!w->sliding[i])
            continue;
        coef = (w->state[i] == KEA_AT_HI ? ME_R(1.0) : ME_R(-1.0)) * lcp->mu[i];
        u = w->U + (size_t)w->slot[lcp->link[i]] * (size_t)k;
        if (w->body) { /* A_FF^-1 A_F,i coef at once, through the bodies (Z's column, not U's) */
            MeReal *column = w->cand; /* free until the candidate is made */
            KeaBodyFactorColumn(w->body, c->F, k, i, coef, column);
            for (p = 0; p < k; ++p)
                u[p] += column[p];
        } else if (lcp->patternStart) { /* A is symmetric, so is its pattern: column i = row i */
            for (j = lcp->patternStart[i]; j < lcp->patternStart[i + 1]; ++j)
                if (c->pos[lcp->pattern[j]] >= 0)
                    u[c->pos[lcp->pattern[j]]] += coef * lcp->A[(size_t)i * (size_t)n + (size_t)lcp->pattern[j]];
        } else {
            for (p = 0; p < k; ++p)
                u[p] += coef * lcp->A[(size_t)c->F[p] * (size_t)n + (size_t)i];
        }
    }
    /* A column u_N is zero before the rows on its contact's bodies: its forward substitution starts
     * at its first non-zero (most of a long chain's factor lies before or after a contact's rows) */
    for (a = 0; a < m; ++a) {
        const MeReal *u = w->U + (size_t)a * (size_t)k;
        from[a] = 0;
        while (from[a] < k && u[from[a]] == ME_R(0.0))
            ++from[a];
    }
    for (a = 0; a < m && !w->body; ++a)
        KeaFreeSolve(w, w->U + (size_t)a * (size_t)k, from[a], KEA_REFINE_OTHER);
    for (a = 0; a < m; ++a) {
        const int pa = c->pos[w->normals[a]];
        for (j = 0; j < m; ++j)
            w->G[a * m + j] = (a == j ? ME_R(1.0) : ME_R(0.0)) + w->U[(size_t)j * (size_t)k + (size_t)pa];
    }
    return KeaDenseFactor(m, w->G, w->perm);
}

/* Take the polish's candidate (w->cand) as x only if it is feasible and complementary (every row's
 * natural map within the tolerance); returns 1 if taken. */
static int KeaPolishAccept(const KeaDenseLcp *lcp, KeaDenseWork *w, MeReal *x)
{
    const int n = lcp->n;
    MeReal xScale = ME_R(0.0), tolW, tolX, worst = ME_R(0.0);
    int i, nz, unchanged = 1, positive = 1;

    for (i = 0; i < n; ++i)
        xScale = KeaMax(xScale, KeaFabs(w->cand[i]));
    tolW = KEA_POLISH_TOL_W * KEA_DIRECT_TOL * (w->rScale + w->diagMax * xScale);
    tolX = KEA_POLISH_TOL_X * KEA_DIRECT_TOL * xScale;
    nz = KeaDensePrepare(lcp, w, w->cand, w->nonzero);
    for (i = 0; i < n; ++i) { /* natural-map test at the candidate's own bounds, every row alike */
        const MeReal Aii = lcp->A[(size_t)i * (size_t)n + (size_t)i];
        const MeReal d = Aii > ME_R(0.0) ? Aii : ME_R(1.0);
        MeReal lo, hi, wi, ri;
        KeaDenseBounds(lcp, w->cand, i, &lo, &hi);
        if (w->cand[i] < lo - tolX || w->cand[i] > hi + tolX)
            return 0;
        wi = KeaDenseRowDot(lcp, i, w->cand, w->nonzero, nz) - lcp->r[i];
        ri = d * KeaFabs(KeaClamp(w->cand[i], lo, hi) - KeaClamp(w->cand[i] - wi / d, lo, hi));
        if (ri > tolW)
            return 0;
        if (ri > worst || ri != ri)
            worst = ri;
        positive &= Aii > ME_R(0.0);
    }
    for (i = 0; i < n; ++i) {
        KeaDenseBounds(lcp, w->cand, i, &w->lo[i], &w->hi[i]);
        x[i] = KeaClamp(w->cand[i], w->lo[i], w->hi[i]);
        unchanged &= x[i] == w->cand[i];
    }
    /* x is the candidate itself (no row clamped): the velocity and the residuals just computed for
     * it are those of the result, and KeaResidualWithDiagonal's sums (d = A_ii > 0 on every row) */
    w->velocityCurrent = lcp->rows && unchanged && positive;
    w->residual = worst;
    return 1;
}

/* The friction polish (top comment): with the rows' current states (free, at a bound, or sliding at
 * +-mu times their normal), solve the coupled system exactly through a Woodbury update of the free
 * rows' factor; x becomes the solution if it is feasible and complementary. Returns 1 if so. */
static int KeaDensePolish(const KeaDenseLcp *lcp, KeaDenseWork *w, MeReal *x)
{
    const int n = lcp->n;
    const KeaCholesky *c = &w->chol;
    const int k = c->size;
    int i, p, m = 0;

    for (i = 0; i < n; ++i)
        w->slot[i] = -1;
    for (i = 0; i < n; ++i) {
        w->sliding[i] = (unsigned char)KeaIsSliding(lcp, w, i);
        if (!w->sliding[i] || w->slot[lcp->link[i]] >= 0)
            continue;
        w->slot[lcp->link[i]] = m;
        w->normals[m++] = lcp->link[i];
    }
    if (m == 0 || k == 0 || !KeaPolishCapacitance(lcp, w, m))
        return 0;

    /* Solve from cand = x with the free and sliding rows zeroed, then one refinement step. */
    for (i = 0; i < n; ++i)
        w->cand[i] = (w->state[i] == KEA_FREE || w->sliding[i]) ? ME_R(0.0) : x[i];
    KeaFreeRowsResidual(lcp, w, w->cand);
    KeaWoodburySolve(w, m, w->y);
    KeaPolishCandidate(lcp, w);
    KeaFreeRowsResidual(lcp, w, w->cand);
    KeaWoodburySolve(w, m, w->y);
    for (p = 0; p < k; ++p)
        w->y[p] += w->cand[c->F[p]];
    KeaPolishCandidate(lcp, w);
    return KeaPolishAccept(lcp, w, x);
}

/* One step of iterative refinement on the free block: x_F += A_FF^-1 (r - A x)_F. Right after the
 * pricing that found x optimal, the bodies' velocity for x is already there (KeaEnteringRow). */
static void KeaDenseRefine(const KeaDenseLcp *lcp, KeaDenseWork *w, MeReal *x)
{
    KeaCholesky *c = &w->chol;
    int p;
    if (c->size == 0)
        return;
    if (w->velocityOfX) {
        KeaFreeRowsProducts(lcp, w, x, 0);
    } else {
        KeaFreeRowsResidual(lcp, w, x);
    }
    KeaFreeSolve(w, w->y, 0, KEA_REFINE_OTHER);
    for (p = 0; p < c->size; ++p) {
        const int i = c->F[p];
        x[i] = KeaClamp(x[i] + w->y[p], w->lo[i], w->hi[i]);
    }
}

int KeaDenseLcpFinalVelocity(const KeaDenseWork *w, MeReal *residual)
{
    if (!w->velocityCurrent)
        return 0;
    *residual = w->residual;
    return 1;
}

KeaStatus KeaDenseLcpSolve(const KeaDenseLcp *lcp, int maxPivots, int maxPasses, KeaDenseWork *w,
                           MeReal *x, KeaStats *stats)
{
    const int n = lcp->n;
    const int pivotCap = stats->pivots + (maxPivots > 0 ? maxPivots : KEA_DENSE_PIVOTS_PER_ROW * n + KEA_DENSE_PIVOTS_EXTRA);
    KeaStatus status;
    MeReal rScale = ME_R(0.0), diagMax = ME_R(0.0);
    int i, polished = 0, passes = 1;

    w->chol.regularised = 0;
    w->velocityCurrent = 0;
    w->velocityOfX = 0;
    w->chol.patternStart = lcp->patternStart;
    w->chol.pattern = lcp->pattern;
    /* Warm start: bounds from x as given (links read the unclamped normal impulses), then clamp. */
    for (i = 0; i < n; ++i) {
        KeaDenseBounds(lcp, x, i, &w->lo[i], &w->hi[i]);
        rScale = KeaMax(rScale, KeaFabs(lcp->r[i]));
        diagMax = KeaMax(diagMax, lcp->A[(size_t)i * (size_t)n + (size_t)i]);
    }
    w->rScale = rScale;
    w->diagMax = diagMax;
    for (i = 0; i < n; ++i)
        w->state[i] = KeaStateFromValue(&x[i], w->lo[i], w->hi[i]);
    { /* A row at a bound whose multiplier already says it would move inside starts free: the
       * Newton step and its ratio test sort it out, where freeing such rows one per pivot costs a
       * pivot each (a new contact arrives at x = 0 with its normal row pressed). */
        const int nz = KeaDensePrepare(lcp, w, x, w->nonzero);
        for (i = 0; i < n; ++i) {
            MeReal wi;
            if (w->state[i] == KEA_FREE || !(w->lo[i] < w->hi[i]))
                continue;
            wi = KeaDenseRowDot(lcp, i, x, w->nonzero, nz) - lcp->r[i];
            if (w->state[i] == KEA_AT_LO ? wi < ME_R(0.0) : wi > ME_R(0.0))
                w->state[i] = KEA_FREE;
        }
    }
    KeaDenseFactorFree(lcp, w, stats);

    for (;;) {
        MeReal moved, scale;
        status = KeaActiveSet(lcp, w, x, pivotCap, stats);
        if (status != KeaStatusOk || !lcp->link)
            break;
        moved = KeaDenseBoundMotion(lcp, w, x);
        scale = w->xScale; /* max |x_i|: x is the one the pricing that ended the active set scanned */
        if (moved <= ME_R(0.0))
            break; /* x is consistent with its own friction bounds */
        /* Try the exact coupled solve with the current states; else settle for small motion. */
        if (KeaDensePolish(lcp, w, x)) {
            polished = 1;
            break;
        }
        if (moved <= KEA_DIRECT_TOL * KEA_POLISH_TOL_W * scale)
            break;
        if (passes >= maxPasses) {
            status = KeaStatusFrictionPasses;
            break;
        }
        KeaDenseApplyBounds(lcp, w, x, stats);
        ++passes;
    }
    if (!polished)
        KeaDenseRefine(lcp, w, x);
    stats->frictionPasses += passes;
    stats->regularised += w->chol.regularised;
    return status;
}
