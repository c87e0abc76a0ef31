/* kea_internal.h -- pieces shared by Kea's source files (not part of any API).
 *
 * - scalar helpers (MeMath's wrappers under short names; clamp, finite-bound test),
 * - the workspace arena: a bump allocator over the caller's buffer that can also run in "counting"
 *   mode, so that KeaMemoryRequired and the solve lay the workspace out with the same code,
 * - row kernels: J_i . (dv_b0, dv_b1), with B_i = M^-1 J_i^T stored as a row, and the column
 *   kernel of the iterative path's blocks,
 * - the updatable Cholesky factor of the direct path,
 * - the entry points of the two paths.
 * The tuning constants are in kea_tuning.h. */
#ifndef KEA_INTERNAL_H
#define KEA_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include <karma/MeMath.h>

#include "kea.h"
#include "kea_lanes.h"
#include "kea_tuning.h"

/* ---- scalars -------------------------------------------------------------------------------- */

static inline MeReal KeaSqrt(MeReal a) { return MeSqrt(a); }
static inline MeReal KeaFabs(MeReal a) { return MeFabs(a); }
static inline MeReal KeaMax(MeReal a, MeReal b) { return a > b ? a : b; }
static inline MeReal KeaMin(MeReal a, MeReal b) { return a < b ? a : b; }

/** mid(lo, v, hi) for lo <= hi (every caller's bounds are): v < lo gives lo, v > hi gives hi, else v
 *  (NaN stays NaN). Written as min then max so that it compiles to minss / maxss, not to branches:
 *  a clamp's outcome is data, which a branch predictor guesses badly in the sweeps. */
static inline MeReal KeaClamp(MeReal v, MeReal lo, MeReal hi)
{
    const MeReal t = hi < v ? hi : v; /* minss */
    return lo > t ? lo : t;           /* maxss */
}

/** A bound at or beyond +-MEINFINITY means "no bound". */
static inline int KeaIsFinite(MeReal bound) { return bound > -MEINFINITY && bound < MEINFINITY; }

/* ---- workspace arena ------------------------------------------------------------------------ */

#define KEA_ALIGN 16

typedef struct KeaArena {
    unsigned char *base; /**< NULL: counting mode (allocations return NULL, only `used` grows) */
    size_t size;         /**< bytes available from base */
    size_t used;         /**< bytes handed out so far, including alignment gaps */
} KeaArena;

/** 16-byte aligned block of `bytes` bytes from the arena (NULL in counting mode or when full). */
static inline void *KeaArenaAlloc(KeaArena *arena, size_t bytes)
{
    size_t offset = (arena->used + (KEA_ALIGN - 1)) & ~(size_t)(KEA_ALIGN - 1);
    arena->used = offset + bytes;
    if (!arena->base || arena->used > arena->size)
        return NULL;
    return arena->base + offset;
}

#define KEA_ALLOC(arena, type, count) ((type *)KeaArenaAlloc((arena), sizeof(type) * (size_t)(count)))

/* ---- row kernels ---------------------------------------------------------------------------- */

static inline MeReal KeaDot3(const MeReal *a, const MeReal *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/** a . b over n entries with four running sums: the dense factor's inner products are otherwise
 *  one long chain of dependent additions, bound by the adder's latency. The order of the sums is
 *  fixed, so the result is the same on every run and at every optimisation level. */
static inline MeReal KeaDotN4(const MeReal *a, const MeReal *b, int n)
{
    KeaLanes lanes;
    MeReal s[4];
    int m = 0;
    if (n < 4) { /* the other three sums stay 0; the one to three terms written out, in order */
        MeReal s0 = ME_R(0.0);
        if (n > 0)
            s0 += a[0] * b[0];
        if (n > 1)
            s0 += a[1] * b[1];
        if (n > 2)
            s0 += a[2] * b[2];
        return s0 + ME_R(0.0);
    }
    lanes = KeaLanesSplat(ME_R(0.0)); /* sum k runs over entries k, k + 4, ... (kea_lanes.h) */
    for (; m + 4 <= n; m += 4)
        lanes = KeaLanesAdd(lanes, KeaLanesMul(KeaLanesLoad(a + m), KeaLanesLoad(b + m)));
    KeaLanesStore(s, lanes);
    for (; m < n; ++m)
        s[0] += a[m] * b[m];
    return (s[0] + s[1]) + (s[2] + s[3]);
}

/** y -= a x over n entries; y and x never overlap (four lanes at a time: each entry is one multiply
 * and one subtract either way, so the bits do not depend on it). */
static inline void KeaSubtractScaled(MeReal *restrict y, const MeReal *restrict x, MeReal a, int n)
{
    const KeaLanes scale = KeaLanesSplat(a);
    int m = 0;
    for (; m + 4 <= n; m += 4)
        KeaLanesStore(y + m, KeaLanesSub(KeaLanesLoad(y + m), KeaLanesMul(KeaLanesLoad(x + m), scale)));
    switch (n - m) { /* the last one to three entries written out: most calls are that short */
    case 3: y[m + 2] -= x[m + 2] * a; /* fall through */
    case 2: y[m + 1] -= x[m + 1] * a; /* fall through */
    case 1: y[m] -= x[m] * a; /* fall through */
    default: break;
    }
}

/** J_i . (dv of body b0, dv of body b1): the constraint velocity of row i under dv. */
static inline MeReal KeaRowVelocity(const KeaJacobianRow *J, const int b[2], const KeaBodyVelocity *dv)
{
    MeReal s = ME_R(0.0);
    if (b[0] >= 0)
        s += KeaDot3(J->lin0, dv[b[0]].lin) + KeaDot3(J->ang0, dv[b[0]].ang);
    if (b[1] >= 0)
        s += KeaDot3(J->lin1, dv[b[1]].lin) + KeaDot3(J->ang1, dv[b[1]].ang);
    return s;
}

/** The natural-map residual of one row (KeaResidual's measure): d |x - mid(lo, x - w / d, hi)| for a
 *  row with d > 0, else its infeasibility |x - mid(lo, x, hi)|. */
static inline MeReal KeaRowResidual(MeReal d, MeReal x, MeReal w, MeReal lo, MeReal hi)
{
    if (d > ME_R(0.0))
        return d * KeaFabs(x - KeaClamp(x - w / d, lo, hi));
    return KeaFabs(x - KeaClamp(x, lo, hi)); /* a row that touches nothing: only its feasibility counts */
}

/** out = M in for the m x nc column-major M (column c at M + c m; m <= KEA_MAX_BLOCK_ROWS; out
 *  distinct from M and in): every out[r] is its own running sum over the columns in order, so the
 *  loop over r vectorises without reassociating any sum. The iterative path's block kernels (a
 *  block's inverse, its J_b from the transpose) use it; it lives in kea_rows.c, out of line, so
 *  that the compiler vectorises the one copy the same way for every caller. */
void KeaColumnsApply(int m, int nc, const MeReal *M, const MeReal *in, MeReal *out);

/** out = M (lin0, ang0, lin1, ang1) for the m x 12 column-major M (the 3-vectors read in place);
 *  the same bits as KeaColumnsApply(m, 12, ...) on the 12 components in that order. The four
 *  3-vectors are separate arguments because this column kernel serves padded and unpadded
 *  callers alike; gathering them into a struct first is the copy it exists to avoid. */
void KeaColumnsApplyPair(int m, const MeReal *M, const MeReal *lin0, const MeReal *ang0, const MeReal *lin1,
                         const MeReal *ang1, MeReal *out);

/** A body's inverse mass and the columns of its world inverse inertia, padded for the lanes:
 *  col[j] = (I^-1[0][j], I^-1[1][j], I^-1[2][j], 0), so that a row's M^-1 J^T takes a few lane
 *  operations (KeaRowInvMassJTOf). */
typedef struct KeaBodyColumns {
    MeReal col[3][4];
    MeReal invMass;
} KeaBodyColumns;

/** out = the columns of `body` (KeaBodyColumns). */
static inline void KeaBodyColumnsOf(const KeaBody *body, KeaBodyColumns *out)
{
    int j, k;
    for (j = 0; j < 3; ++j) {
        for (k = 0; k < 3; ++k)
            out->col[j][k] = body->invInertia[k][j];
        out->col[j][3] = ME_R(0.0);
    }
    out->invMass = body->invMass;
}

/** Every body's columns, once per solve (the paths' workspaces hold them). */
void KeaBodyColumnsFill(const KeaProblem *problem, KeaBodyColumns *out);

/** KeaBodyVelocityFromImpulses for bodies [b0, b1) only (writes dv[b0 .. b1 - 1]): each body's J^T x
 *  summed over the rows in row order, as the whole pass sums it, so any cut into ranges gives the
 *  whole pass's bits (the split solve runs ranges on its workers). */
void KeaBodyVelocityFromImpulsesOf(const KeaProblem *problem, const MeReal *x, KeaBodyVelocity *dv, int b0, int b1);

/* One half of a row's M^-1 J^T: B's half from J's half (pads 0), returning J . B over the half. */
static inline MeReal KeaHalfInvMassJT4(const KeaBodyColumns *body, const MeReal *jLin, const MeReal *jAng,
                                       MeReal *bLin, MeReal *bAng)
{
    const KeaLanes l = KeaLanesLoad(jLin), a = KeaLanesLoad(jAng);
    const KeaLanes bl = KeaLanesMul(KeaLanesSplat(body->invMass), l);
    /* lane k: (I[k][0] a0 + I[k][1] a1) + I[k][2] a2 */
    const KeaLanes ba = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(KeaLanesLoad(body->col[0]), KeaLanesSplat(jAng[0])),
                                                KeaLanesMul(KeaLanesLoad(body->col[1]), KeaLanesSplat(jAng[1]))),
                                    KeaLanesMul(KeaLanesLoad(body->col[2]), KeaLanesSplat(jAng[2])));
    KeaLanesStore(bLin, bl);
    KeaLanesStore(bAng, ba);
    bLin[3] = bAng[3] = ME_R(0.0); /* whatever J's pads held */
    return KeaLanesSum3(KeaLanesMul(l, bl)) + KeaLanesSum3(KeaLanesMul(a, ba));
}

/** B = M^-1 J^T of row J on bodies c0 and c1 (NULL: the world, a zero half); returns the row's
 *  diagonal J B + eps. Each half is (J.l)(I^-1 ...) in KeaDot3's order of operations: every lane
 *  the scalar IEEE operations, so the same bits however the lanes are made. */
static inline MeReal KeaRowInvMassJTOf(const KeaJacobianRow *J, const KeaBodyColumns *c0, const KeaBodyColumns *c1,
                                       MeReal eps, KeaJacobianRow *B)
{
    MeReal diag = eps;
    int k;
    if (c0) {
        diag += KeaHalfInvMassJT4(c0, J->lin0, J->ang0, B->lin0, B->ang0);
    } else {
        for (k = 0; k < 4; ++k)
            B->lin0[k] = B->ang0[k] = ME_R(0.0);
    }
    if (c1) {
        diag += KeaHalfInvMassJT4(c1, J->lin1, J->ang1, B->lin1, B->ang1);
    } else {
        for (k = 0; k < 4; ++k)
            B->lin1[k] = B->ang1[k] = ME_R(0.0);
    }
    return diag;
}

/** B = M^-1 J_i^T of row i from the bodies' columns (KeaBodyColumnsFill); returns J_i B + eps_i. */
static inline MeReal KeaRowInvMassJT4(const KeaProblem *problem, const KeaBodyColumns *bodies, int i,
                                      KeaJacobianRow *B)
{
    const int *b = problem->rowBodies[i];
    return KeaRowInvMassJTOf(&problem->J[i], b[0] >= 0 ? &bodies[b[0]] : NULL, b[1] >= 0 ? &bodies[b[1]] : NULL,
                             problem->epsilon ? problem->epsilon[i] : ME_R(0.0), B);
}

/** The same without a workspace: the row's two bodies' columns are made here (KeaResidual). */
MeReal KeaRowInvMassJT(const KeaProblem *problem, int i, KeaJacobianRow *B);

/** A friction row's bound mu max(xLink, 0) for its normal row's impulse xLink. */
static inline MeReal KeaFrictionBound(MeReal mu, MeReal xLink) { return mu * KeaMax(xLink, ME_R(0.0)); }

/** The friction rule: own bounds [lo, hi] widened to contain 0, intersected with
 *  [-KeaFrictionBound, KeaFrictionBound]. */
static inline void KeaFrictionBounds(MeReal lo, MeReal hi, MeReal mu, MeReal xLink, MeReal *effLo, MeReal *effHi)
{
    const MeReal bound = KeaFrictionBound(mu, xLink);
    *effLo = KeaMax(KeaMin(lo, ME_R(0.0)), -bound);
    *effHi = KeaMin(KeaMax(hi, ME_R(0.0)), bound);
}

/** KeaRowBounds, inline: the iterative path asks for a row's bounds several times per sweep. */
static inline void KeaRowBoundsInline(const KeaProblem *problem, const MeReal *x, int i, MeReal *lo, MeReal *hi)
{
    if (problem->link && problem->link[i] >= 0) {
        KeaFrictionBounds(problem->lo[i], problem->hi[i], problem->mu[i], x[problem->link[i]], lo, hi);
    } else {
        *lo = problem->lo[i];
        *hi = problem->hi[i];
    }
}

/* ---- dense matrix and updatable Cholesky factor (kea_dense.c) -------------------------------- */

/** The body -> (row, half) incidence: body b's entries are incidence[start[b] .. start[b+1] - 1],
 *  each 2 * row + half, rows ascending (incidence: 2n ints, start: nb + 1 ints). */
void KeaBodyIncidence(const KeaProblem *problem, int *incidence, int *start);
/** A = J M^-1 J^T + diag(eps), dense n x n row-major, using B (M^-1 J^T rows) and the incidence.
 *  Only the entries in A's pattern (rows sharing a body, as the direct path builds it) are written;
 *  the rest of A is left as it was and must not be read. Nine arguments: the pairs (incidence,
 *  start) and (patternStart, pattern) are the direct path's two sparse structures, each a CSR
 *  pair its set-up fills once, and columns (KeaFormScratchReals(n) reals) and ints
 *  (KeaFormScratchInts(n)) the workspace for one body's rows. */
void KeaFormDenseMatrix(const KeaProblem *problem, const KeaJacobianRow *B, MeReal *A, const int *incidence,
                        const int *start, const int *patternStart, const int *pattern, MeReal *columns,
                        int *ints);
/** Scratch sizes of KeaFormDenseMatrix for n rows (a body has at most 2n incidence entries). */
size_t KeaFormScratchReals(int nRows);
size_t KeaFormScratchInts(int nRows);

/** Cholesky factor L (row-major, leading dimension ld) of A restricted to an ordered list of rows
 *  F[0..size-1]: A_FF = L L^T. */
typedef struct KeaCholesky {
    MeReal *L;  /**< ld x ld storage; row k holds L[k][0..k] */
    int ld;     /**< leading dimension (n) */
    int size;   /**< rows in the factor */
    int *F;     /**< F[k] = problem row at position k */
    int *pos;   /**< pos[i] = position of problem row i in F, or -1 */
    int *first; /**< first[k] = first column of row k's envelope (L[k][j] = 0 for j < first[k]) */
    MeReal *inv; /**< inv[k] = 1 / L[k][k]: the substitutions multiply (a division's latency would
                      sit on their chain of dependent steps) */
    const int *patternStart, *pattern; /**< the LCP's pattern (KeaDenseLcp), or NULL: A is scanned */
    int regularised; /**< pivots raised to the floor so far */
} KeaCholesky;

/** Append row i of A (leading dimension lda) to the factor (O(size^2)). */
void KeaCholeskyAppend(KeaCholesky *c, const MeReal *A, int lda, int i);
/** Remove the row at position p from the factor (rank-one update of the trailing block, O(size^2)). */
void KeaCholeskyRemove(KeaCholesky *c, int p);
/** Plain Cholesky A = L L^T of a small dense m x m matrix (row-major): the lower triangle and the
 *  diagonal of L are written, the upper triangle is left as it was (its readers, the blocks'
 *  inverses, do not read it). Returns 0, leaving L unusable, if a pivot falls below the floor (A
 *  not safely positive definite). Inline, for callers that know m (the blocks' usual sizes, unrolled). */
static inline int KeaCholeskyDenseInline(int m, const MeReal *A, MeReal *L)
{
    int i, j, k;
    for (i = 0; i < m; ++i) {
        for (j = 0; j <= i; ++j) {
            MeReal s = A[i * m + j];
            for (k = 0; k < j; ++k)
                s -= L[i * m + k] * L[j * m + k];
            if (j < i) {
                L[i * m + j] = s / L[j * m + j];
            } else {
                if (!(s > KEA_PIVOT_FLOOR * A[i * m + i]))
                    return 0;
                L[i * m + i] = KeaSqrt(s);
            }
        }
    }
    return 1;
}

/** LU factorisation with partial pivoting of the general m x m matrix G, in place (row swaps in
 *  perm). Returns 0 when G is numerically singular. */
int KeaDenseFactor(int m, MeReal *G, int *perm);
/** Solve G y = b in place with the factors from KeaDenseFactor. */
void KeaDenseSolveFactored(int m, const MeReal *G, const int *perm, MeReal *b);
/** Solve A_FF y = b in place (b and y indexed by position in F). */
void KeaCholeskySolve(const KeaCholesky *c, MeReal *b);
/** KeaCholeskySolve for a b whose entries before position `from` are zero: the forward substitution
 *  starts there (the entries before stay zero, so the result is the same to the bit). */
void KeaCholeskySolveFrom(const KeaCholesky *c, MeReal *b, int from);

/* ---- the dense box LCP solver (kea_dense_lcp.c) --------------------------------------------- */

/** A dense box LCP: w = A x - r, bounds lo <= hi, optional friction links (indices into this LCP). */
/* ---- the free rows solved through the bodies' coordinates (kea_body_factor.c) --------------- */

/** The direct path's factor of the free rows in body coordinates (H = M + J_F^T E^-1 J_F). */
typedef struct KeaBodyFactor KeaBodyFactor;
/** Whether a partition of this size is laid out for it (many rows on few bodies). */
int KeaBodyFactorFits(int nRows, int nBodies);
/** Lay it out in the arena (NULL in counting mode, or when the partition does not fit). */
KeaBodyFactor *KeaBodyFactorCreate(KeaArena *arena, int n, int nb);
/** Ready it for the problem, bodies in the elimination order (rank[b], kea_order.c), H = M; diag:
 *  the rows' A_ii (diag[i * stride]). Returns 0 when the partition must keep the row factor (no or
 *  too little softness, a body with no mass or inertia, a row touching one body twice). */
int KeaBodyFactorBegin(KeaBodyFactor *f, const KeaProblem *problem, const KeaBodyColumns *columns,
                       const int *rank, const MeReal *diag, size_t stride);
/** H = M + sum over the free rows F[0 .. size - 1]; 0 if a body has no mass. */
int KeaBodyFactorRebuild(KeaBodyFactor *f, const int *F, int size);
/** H += sign j_i j_i^T / eps_i (sign +1: row i freed, -1: fixed); refactored at the next solve. */
void KeaBodyFactorAddRow(KeaBodyFactor *f, int i, MeReal sign);
/** v = A_FF^-1 v (v by position in F), refined once if asked; returns the pivots raised to the floor. */
int KeaBodyFactorSolve(KeaBodyFactor *f, const int *F, int size, MeReal *v, int refine);
/** u = A_FF^-1 A_F,row coef for a row not in F, as E^-1 J_F H^-1 J_row^T coef (no difference of
 *  nearly equal terms: A_FF^-1 J_F M^-1 = E^-1 J_F H^-1). */
void KeaBodyFactorColumn(KeaBodyFactor *f, const int *F, int size, int row, MeReal coef, MeReal *u);

typedef struct KeaDenseLcp {
    int n;               /**< rows */
    const MeReal *A;     /**< n x n row-major, symmetric positive (semi-)definite */
    const MeReal *r;     /**< right-hand side */
    const MeReal *lo;    /**< own lower bounds */
    const MeReal *hi;    /**< own upper bounds */
    const int *link;     /**< normal row of a friction row, or -1 (NULL: no links) */
    const MeReal *mu;    /**< friction coefficients of linked rows */
    const int *order;    /**< order in which free rows enter a fresh factor (NULL: index order) */
    const int *patternStart; /**< n + 1: row i's structural non-zeros are pattern[patternStart[i] ..
                                  patternStart[i+1] - 1] (NULL: A treated as full); with a pattern,
                                  only A's entries in it are read, and rows must be given */
    const int *pattern;
    const KeaProblem *rows;  /**< the rows A comes from (A = J M^-1 J^T + diag(eps)), for products
                                  with A in O(n) (NULL: products read A) */
    KeaBodyVelocity *velocity; /**< nBodies: scratch for those products */
} KeaDenseLcp;

/** Workspace of the dense solver, for LCPs of up to `capacity` rows. */
typedef struct KeaDenseWork KeaDenseWork;

/** Lay out a dense-solver workspace for n rows in the arena (NULL in counting mode). */
KeaDenseWork *KeaDenseWorkCreate(KeaArena *arena, int n);
/** Solve the free rows through the bodies' coordinates (f ready, KeaBodyFactorBegin) instead of
 *  A_FF's own Cholesky factor, until the next call: then only A's diagonal is read. NULL: A_FF's. */
void KeaDenseWorkUseBodyFactor(KeaDenseWork *w, KeaBodyFactor *f);
/** Solve the LCP exactly (kea_dense_lcp.c top comment). x: warm start in, solution out. Adds its
 *  pivots, factorisations, friction passes and regularised pivots to stats. maxPivots 0 = automatic
 *  (8 n + 64). */
KeaStatus KeaDenseLcpSolve(const KeaDenseLcp *lcp, int maxPivots, int maxPasses, KeaDenseWork *w,
                           MeReal *x, KeaStats *stats);
/** After KeaDenseLcpSolve on an LCP given with its rows: 1 if lcp->velocity already holds
 *  M^-1 J^T x for the returned x, with *residual its KeaResidualWithDiagonal (d = A_ii); else 0. */
int KeaDenseLcpFinalVelocity(const KeaDenseWork *w, MeReal *residual);

/** KeaResidual with the diagonal d_i = A_ii given (diag[i * stride]), e.g. from a formed A. */
MeReal KeaResidualWithDiagonal(const KeaProblem *problem, const MeReal *x, const KeaBodyVelocity *dv,
                               const MeReal *diag, size_t stride);

/* ---- the direct path's row order (kea_order.c) ---------------------------------------------- */

/** ints of scratch KeaEliminationOrder needs. */
size_t KeaEliminationOrderScratch(int nRows, int nBodies);
/** A factoring order of the problem's rows (order[k] = row factored k-th) that keeps the Cholesky
 *  factor's fill and envelopes small, from the body -> (row, half) incidence (KeaBodyIncidence). */
void KeaEliminationOrder(const KeaProblem *problem, const int *incidence, const int *start, int *scratch,
                         int *order);

/* ---- the two paths -------------------------------------------------------------------------- */

size_t KeaDirectWorkspaceBytes(int nRows, int nBodies);
size_t KeaIterativeWorkspaceBytes(int nRows, int nBodies);

/* Both take a validated problem, an arena of at least their WorkspaceBytes, write x (nRows) and
 * dv (nBodies, never NULL here) and fill the path-specific fields of stats and stats->residual
 * (KeaResidual's measure, from the diagonal each path already has). KeaSolveDirect has KeaSolve's
 * arguments with the arena for the buffer and, seventh, mayDecline (Auto's "only if the factor is
 * sparse"). */
KeaStatus KeaSolveDirect(const KeaProblem *problem, const KeaParameters *params, KeaArena *arena,
                         int mayDecline, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats);

/** KeaSolveDirect's answer when mayDecline is set and the factor would cost more than a dense one of
 *  maxDirectRows rows: nothing solved, x untouched. Never returned by KeaSolve. */
#define KeaStatusDeclined ((KeaStatus)-1)

/** KeaSolveDirect's answer under Auto (params->path) with a pivot budget (autoPivotsPerRow) when the
 *  solve needed more pivots than the budget: x is the feasible iterate where it stopped, dv and the
 *  residual are not set; the iterative path takes over. Never returned by KeaSolve. */
#define KeaStatusOverBudget ((KeaStatus)-2)

/** The iterative path; rowsProved: the caller proved the rows (KeaSolveRowsProved), J's pads and
 *  world halves among them, so that the solve reads the problem's J in place. */
KeaStatus KeaSolveIterative(const KeaProblem *problem, const KeaParameters *params, KeaArena *arena,
                            MeReal *x, KeaBodyVelocity *dv, KeaStats *stats, int rowsProved);

#endif /* KEA_INTERNAL_H */
