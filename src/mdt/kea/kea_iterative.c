/* kea_iterative.c -- the sweep of Kea's iterative path and its driver (kea_iterative.h): the
 * generic block step (a block at rest, or a block LCP), the projected Gauss-Seidel sweep over the
 * blocks (a declared contact through the contact step, kea_contact_kernel.h), and KeaSolveIterative,
 * which sets up the blocks, warm-starts, alternates sweeps with subspace minimisation
 * (kea_subspace.c) and NNCG's momentum steps (kea_nncg.c), and reports the residual. */
#include <string.h>

#include "kea_contact_kernel.h"

static MeReal KeaRowW(const KeaProblem *problem, const KeaIterativeWork *w, int i, const MeReal *x,
                      const KeaVel4 *v0, const KeaVel4 *v1)
{
    return KeaRowVel4(&w->J[i], v0, v1) + w->eps[i] * x[i] - problem->rhs[i];
}

/* A block whose all-free solution xNew breaks the bound of one row l while every other row is
 * unbounded and no row is linked (a joint whose limit the step reaches): its LCP's solution is row l
 * at the bound it broke and the others moved by A^-1 e_l mu, mu = (bound - xNew_l) / (A^-1)_ll,
 * which keeps their w at 0 and makes w_l = mu, of the sign that bound asks ((A^-1)_ll > 0, A
 * positive definite). Writes that solution into xNew and returns 1; returns 0, xNew unchanged, for
 * any other block (the dense solver's). Not inlined: a rare case kept out of the block step's
 * common path. */
KEA_NOINLINE int KeaBlockClampOneRow(int m, const MeReal *inv, const MeReal *lo, const MeReal *hi, const int *link,
                                     MeReal *xNew)
{
    MeReal bound, mu;
    int r, l = -1;
    for (r = 0; r < m; ++r) {
        if (link[r] >= 0)
            return 0;
        if (xNew[r] < lo[r] || xNew[r] > hi[r]) {
            if (l >= 0)
                return 0;
            l = r;
        } else if (KeaIsFinite(lo[r]) || KeaIsFinite(hi[r])) {
            return 0; /* a bound of its own that the correction could break */
        }
    }
    if (l < 0 || !(inv[l * m + l] > ME_R(0.0)))
        return 0;
    bound = xNew[l] < lo[l] ? lo[l] : hi[l];
    mu = (bound - xNew[l]) / inv[l * m + l];
    for (r = 0; r < m; ++r)
        xNew[r] += inv[r * m + l] * mu;
    xNew[l] = bound;
    return 1;
}

/* The generic block step: solve the block of m generic rows from s exactly with the rest of x
 * fixed: its local LCP has the matrix A_bb and r_loc = A_bb x_b - w_b, so that its w is the true w
 * of these rows. The common case of a block at rest first: all rows free, x_b - A_bb^-1 w_b with the
 * block's precomputed inverse, taken if it lies within every row's bounds (friction links inside
 * the block read the new normal values: w_b = 0 there, the block's exact solution); then a joint
 * whose limit the step reaches, one bounded row clamped in closed form (KeaBlockClampOneRow); else
 * the dense box-LCP solver. A friction link to a row outside the block becomes a fixed bound.
 * Contacts written as generic rows (adhesive, bounded friction) come here; declared contacts go to
 * the contact step.
 * Returns the block's largest row residual before (when sweep->measure; else 0).
 * Inlined with m a constant for a joint's usual blocks (KeaBlockStep), so that its loops over the
 * rows unroll and its rows stay in locals; the work's block scratch is filled for the dense solver
 * only. Size: one step's parts sharing those locals. */
KEA_ALWAYS_INLINE MeReal KeaBlockStepSized(const int m, const KeaProblem *problem, KeaIterativeWork *w, int block,
                                           MeReal *x, KeaSweepState *sweep)
{
    const int s = w->blockStart[block];
    const MeReal *const eps = w->eps, *const rhs = problem->rhs;
    MeReal wb[KEA_MAX_BLOCK_ROWS], lo[KEA_MAX_BLOCK_ROWS], hi[KEA_MAX_BLOCK_ROWS], xNew[KEA_MAX_BLOCK_ROWS];
    int link[KEA_MAX_BLOCK_ROWS];
    MeReal worst = ME_R(0.0);
    int r, fits = w->blockFactored[block];
    KeaBlockGather(w, s, m, &w->dv[w->body[s][0]], &w->dv[w->body[s][1]], wb);
    for (r = 0; r < m; ++r) /* w_b = J_b dv + eps x_b - r_b (a loop of its own: it vectorises) */
        wb[r] = wb[r] + eps[s + r] * x[s + r] - rhs[s + r];
    for (r = 0; r < m; ++r) { /* the bounds (a link inside the block stays a link, with the row's own) */
        const int i = s + r;
        KeaRowBoundsInline(problem, x, i, &lo[r], &hi[r]);
        if (sweep->measure && w->invDiag[i] != ME_R(0.0))
            worst = KeaMax(worst, w->diag[i] * KeaFabs(x[i] - KeaClamp(x[i] - wb[r] * w->invDiag[i], lo[r], hi[r])));
        link[r] = -1;
        if (problem->link && problem->link[i] >= s && problem->link[i] < s + m) {
            link[r] = problem->link[i] - s;
            lo[r] = problem->lo[i];
            hi[r] = problem->hi[i];
        }
    }
    if (fits) { /* every row free */
        KeaBlockSymmetricApply(m, w->blockInv + w->blockMatrix[block], wb, xNew);
        for (r = 0; r < m; ++r)
            xNew[r] = x[s + r] - xNew[r];
        for (r = 0; r < m; ++r) {
            MeReal rlo = lo[r], rhi = hi[r];
            if (link[r] >= 0)
                KeaFrictionBounds(rlo, rhi, problem->mu[s + r], xNew[link[r]], &rlo, &rhi);
            fits &= xNew[r] >= rlo && xNew[r] <= rhi;
        }
    }
    if (fits || (w->blockFactored[block] &&
                 KeaBlockClampOneRow(m, w->blockInv + w->blockMatrix[block], lo, hi, link, xNew))) {
        KeaBlockApplyNew(w, s, m, xNew, wb, w->localD, x, &sweep->decrease);
        return worst;
    }
    for (r = 0; r < m; ++r) {
        w->localW[r] = wb[r];
        w->localX[r] = x[s + r];
        w->localLo[r] = lo[r];
        w->localHi[r] = hi[r];
        w->localLink[r] = link[r];
    }
    KeaBlockSymmetricApply(m, w->blockA + w->blockMatrix[block], x + s, w->localR); /* r_loc = A_bb x_b - w_b */
    for (r = 0; r < m; ++r)
        w->localR[r] -= w->localW[r];
    KeaSmallLcp(problem, w, block, sweep->maxPasses, sweep->stats);
    KeaBlockApplyDeltas(w, s, m, x, &sweep->decrease);
    return worst;
}

/* KeaBlockStepSized, with m a constant for a ball joint's, a hinge's and a fixed joint's blocks. */
static MeReal KeaBlockStep(const KeaProblem *problem, KeaIterativeWork *w, int block, MeReal *x, KeaSweepState *sweep)
{
    const int m = w->blockStart[block + 1] - w->blockStart[block];
    switch (m) {
    case 3: return KeaBlockStepSized(3, problem, w, block, x, sweep);
    case 5: return KeaBlockStepSized(5, problem, w, block, x, sweep);
    case 6: return KeaBlockStepSized(6, problem, w, block, x, sweep);
    default: return KeaBlockStepSized(m, problem, w, block, x, sweep);
    }
}

/* One block's step in a sweep (the contact step, the generic block step, or a lone row's scalar
 * update); returns the block's largest row residual before its step (0 when not measured). A row's
 * half on the world (dv[nb]) is not written: it stays zero, and a split sweep's blocks on the world
 * run at once. Always inlined into its two sweeps, so that the contact step stays inlined. */
KEA_ALWAYS_INLINE MeReal KeaSweepBlock(const KeaProblem *problem, KeaIterativeWork *w,
                                                                  int block, MeReal *x, KeaSweepState *sweep,
                                                                  MeReal omega)
{
    const int i = w->blockStart[block];
    MeReal lo, hi, wi, xNew, r;
    if (w->blockContact[block])
        return KeaContactBlockStep(problem, w, block, x, sweep);
    if (w->blockStart[block + 1] - i > 1) {
        /* a copy: the generic step is not inlined, and sweep's address given to it would keep
         * sweep in memory for the contact steps too */
        KeaSweepState blockSweep = *sweep;
        r = KeaBlockStep(problem, w, block, x, &blockSweep);
        sweep->decrease = blockSweep.decrease;
        return r;
    }
    if (w->invDiag[i] == ME_R(0.0))
        return ME_R(0.0);
    KeaRowBoundsInline(problem, x, i, &lo, &hi);
    wi = KeaRowW(problem, w, i, x, &w->dv[w->body[i][0]], &w->dv[w->body[i][1]]);
    r = w->diag[i] * KeaFabs(x[i] - KeaClamp(x[i] - wi * w->invDiag[i], lo, hi));
    xNew = KeaClamp(x[i] - omega * wi * w->invDiag[i], lo, hi);
    if (xNew != x[i]) {
        const KeaJacobianRow *B = &w->B[i];
        sweep->decrease -= ME_R(0.5) * (xNew - x[i]) * wi;
        if (w->body[i][0] != w->nb)
            KeaHalfApply4(B->lin0, B->ang0, xNew - x[i], &w->dv[w->body[i][0]]);
        if (w->body[i][1] != w->nb)
            KeaHalfApply4(B->lin1, B->ang1, xNew - x[i], &w->dv[w->body[i][1]]);
        x[i] = xNew;
    }
    return r;
}

static MeReal KeaSweepOmega(const KeaParameters *params)
{
    return params->sor > ME_R(0.0) && params->sor < ME_R(2.0) ? params->sor : ME_R(1.0);
}

/* One PGS sweep over the blocks, forwards or backwards; returns the largest residual met (the rows'
 * residuals before their steps). Only whether that is within `measureUpTo` (the tolerance, or the
 * extra effort's threshold in a round's last sweep) matters, so once a row is above it the block
 * steps stop measuring (a sizeable part of a contact step's work, and a pile rarely converges within
 * its sweeps); the steps themselves are the same either way. w->sweepAbove counts the blocks above
 * measureUpTo; blocks are measured on while at most `countUpTo` are (-1: only until the first).
 * Size: the solve's state, passed as KeaSolveIterative holds it (its one call site). */
KEA_NOINLINE MeReal KeaSweep(const KeaProblem *problem, KeaIterativeWork *w, const KeaParameters *params,
                             MeReal *x, KeaStats *stats, int backward, MeReal measureUpTo, int countUpTo)
{
    const MeReal omega = KeaSweepOmega(params);
    MeReal worst = ME_R(0.0);
    KeaSweepState sweep;
    int k, above = 0;
    sweep.decrease = ME_R(0.0);
    sweep.changed = 0;
    sweep.tally = w->smRan;
    sweep.maxPasses = params->maxFrictionPasses;
    sweep.stats = stats;
    for (k = 0; k < w->nBlocks; ++k) {
        MeReal r;
        sweep.measure = worst <= measureUpTo || above <= countUpTo;
        r = KeaSweepBlock(problem, w, backward ? w->nBlocks - 1 - k : k, x, &sweep, omega);
        above += r > measureUpTo;
        worst = KeaMax(worst, r);
    }
    w->sweepDecrease = sweep.decrease;
    w->sweepChanged = sweep.changed;
    w->sweepAbove = above;
    return worst;
}

/* What a split sweep's chunks share (kea_iterative.h, "the split solve"). */
typedef struct KeaSplitSweep {
    const KeaProblem *problem;
    KeaSplit *split;
    MeReal *x;
    MeReal omega, measureUpTo;
    int backward, tally, maxPasses, countUpTo;
    int firstChunk, lastChunk; /* the colour's chunks */
} KeaSplitSweep;

/* Chunk `chunk` of a colour on a worker's copy of the work: its blocks in sweep order, its tallies
 * into its own record. */
static void KeaSweepChunk(const KeaSplitSweep *t, int chunk, KeaIterativeWork *w)
{
    const KeaSplit *split = t->split;
    const int first = split->chunkStart[chunk], count = split->chunkStart[chunk + 1] - first;
    KeaSplitChunk *record = &split->chunks[chunk];
    MeReal worst = ME_R(0.0);
    KeaStats local;
    KeaSweepState sweep;
    int k, above = 0;
    memset(&local, 0, sizeof local);
    sweep.decrease = ME_R(0.0);
    sweep.changed = 0;
    sweep.tally = t->tally;
    sweep.maxPasses = t->maxPasses;
    sweep.stats = &local;
    for (k = 0; k < count; ++k) {
        const int block = split->order[t->backward ? first + count - 1 - k : first + k];
        MeReal r;
        sweep.measure = worst <= t->measureUpTo || above <= t->countUpTo;
        r = KeaSweepBlock(t->problem, w, block, t->x, &sweep, t->omega);
        above += r > t->measureUpTo;
        worst = KeaMax(worst, r);
    }
    record->decrease = sweep.decrease;
    record->worst = worst;
    record->changed = sweep.changed;
    record->above = above;
    record->pivots = local.pivots;
    record->regularised = local.regularised;
}

/* The task over a colour's chunks (item j: the j-th in sweep order). */
static void KeaSweepChunks(int start, int end, int worker, void *data)
{
    const KeaSplitSweep *t = data;
    int j;
    for (j = start; j < end; ++j)
        KeaSweepChunk(t, t->backward ? t->lastChunk - j : t->firstChunk + j, &t->split->works[worker]);
}

/* KeaSweep on a split partition: colour after colour (ascending forwards, descending backwards), a
 * colour's chunks over the workers (the overflow colour's, whose blocks may share bodies, on this
 * thread in order), then the chunks' tallies added in sweep order. Size: as KeaSweep. */
KEA_NOINLINE MeReal KeaSweepSplit(const KeaProblem *problem, KeaIterativeWork *w, const KeaParameters *params,
                                  MeReal *x, KeaStats *stats, int backward, MeReal measureUpTo, int countUpTo)
{
    KeaSplit *split = w->split;
    KeaSplitSweep t;
    MeReal worst = ME_R(0.0), decrease = ME_R(0.0);
    int changed = 0, above = 0, k, c;
    t.problem = problem;
    t.split = split;
    t.x = x;
    t.omega = KeaSweepOmega(params);
    t.measureUpTo = measureUpTo;
    t.countUpTo = countUpTo;
    t.backward = backward;
    t.tally = w->smRan;
    t.maxPasses = params->maxFrictionPasses;
    KeaSplitWorks(w, split);
    for (k = 0; k <= KEA_COLOUR_COUNT; ++k) {
        c = backward ? KEA_COLOUR_COUNT - k : k;
        t.firstChunk = split->colourChunk[c];
        t.lastChunk = split->colourChunk[c + 1] - 1;
        if (c == KEA_COLOUR_OVERFLOW)
            KeaSweepChunks(0, t.lastChunk - t.firstChunk + 1, 0, &t);
        else
            KeaSplitRun(split, KeaSweepChunks, t.lastChunk - t.firstChunk + 1, &t);
    }
    for (k = 0; k < split->nChunks; ++k) {
        const KeaSplitChunk *record = &split->chunks[backward ? split->nChunks - 1 - k : k];
        decrease += record->decrease;
        worst = KeaMax(worst, record->worst);
        changed += record->changed;
        above += record->above;
        stats->pivots += record->pivots;
        stats->regularised += record->regularised;
    }
    w->sweepDecrease = decrease;
    w->sweepChanged = changed;
    w->sweepAbove = above;
    return worst;
}

/* worst after a row's residual r: KeaResidual's rule (a NaN stays, else the largest). */
static MeReal KeaWorseResidual(MeReal worst, MeReal r) { return r > worst || r != r ? r : worst; }

/* KeaResidualRows' measure of a declared contact's rows s, s + 1, s + 2 folded into worst, row after
 * row: their J dv gathered at once (KeaContactGather, KeaRowVel4's sums with the world's half
 * included), the friction rows' bounds from the normal row's x (their link, KeaContactsAreValid). */
static MeReal KeaResidualContact(const KeaProblem *problem, const KeaIterativeWork *w, const MeReal *x, int s,
                                 MeReal worst)
{
    _Alignas(16) MeReal jdv[4];
    int r;
    KeaLanesStoreA(jdv, KeaContactGather(&w->J[s], &w->dv[w->body[s][0]], &w->dv[w->body[s][1]]));
    for (r = 0; r < 3; ++r) {
        const int i = s + r;
        const MeReal wi = jdv[r] + w->eps[i] * x[i] - problem->rhs[i];
        MeReal lo = problem->lo[i], hi = problem->hi[i];
        if (r > 0)
            KeaFrictionBounds(problem->lo[i], problem->hi[i], problem->mu[i], x[s], &lo, &hi);
        worst = KeaWorseResidual(worst, KeaRowResidual(w->diag[i], x[i], wi, lo, hi));
    }
    return worst;
}

/* KeaResidual (kea_rows.c) of rows [i0, i1) of the final x and dv from the work's diagonal and padded
 * rows (no M^-1 J^T recomputed per row): the same measure, J_i dv summed in the padded kernel's order;
 * a declared contact whose rows all lie in the range by KeaResidualContact. */
static MeReal KeaResidualRows(const KeaProblem *problem, const KeaIterativeWork *w, const MeReal *x, int i0, int i1)
{
    MeReal worst = ME_R(0.0);
    int i;
    for (i = i0; i < i1; ++i) {
        const int b = w->rowBlock[i];
        if (w->blockContact[b] && w->blockStart[b] == i && i + 3 <= i1) {
            worst = KeaResidualContact(problem, w, x, i, worst);
            i += 2;
            continue;
        }
        const MeReal d = w->diag[i];
        const MeReal wi = KeaRowW(problem, w, i, x, &w->dv[w->body[i][0]], &w->dv[w->body[i][1]]);
        MeReal lo, hi, r;
        KeaRowBoundsInline(problem, x, i, &lo, &hi);
        r = KeaRowResidual(d, x[i], wi, lo, hi);
        worst = KeaWorseResidual(worst, r);
    }
    return worst;
}

/* Whether the extra effort may run on this partition (kea_tuning.h, KEA_EFFORT_REST_SPEED): every
 * row's target velocity change within params->effortRestSpeed (0 = no limit), i.e. a resting
 * partition and not one where bodies collide or slide fast; stops at the first row over it. A row
 * that can only push (lower bound 0: a contact's normal row) counts only a positive r_i: a negative
 * one is a gap the bodies may close (a contact reported apart, within its tolerance), no motion. */
static int KeaEffortAllowed(const KeaProblem *problem, const KeaParameters *params)
{
    int i;
    if (!(params->effortResidual > ME_R(0.0)))
        return 0;
    if (!(params->effortRestSpeed > ME_R(0.0)))
        return 1;
    for (i = 0; i < problem->nRows; ++i) {
        const MeReal r = problem->lo[i] == ME_R(0.0) ? problem->rhs[i] : KeaFabs(problem->rhs[i]);
        if (!(r <= params->effortRestSpeed))
            return 0;
    }
    return 1;
}

/* The set-up of rows [i0, i1): B = M^-1 J^T, the diagonal, J with its pads and world halves zeroed
 * (the work's copy, unless the solve reads the problem's J in place: KeaSolveRowsProved), the
 * halves' bodies, and the warm start's bounds (read from the unclamped x, as the direct path
 * does). Each row writes only its own entries. The arrays' addresses are read once, into locals: the
 * compiler cannot keep them over the rows' stores, which it must assume may alias them. */
static void KeaSetUpRows(const KeaProblem *problem, KeaIterativeWork *w, const MeReal *x, int i0, int i1)
{
    const int nb = problem->nBodies;
    const KeaJacobianRow *const in = problem->J;
    const int(*const rowBodies)[2] = problem->rowBodies;
    const MeReal *const epsIn = problem->epsilon, *const loIn = problem->lo, *const hiIn = problem->hi;
    const MeReal *const mu = problem->mu;
    const int *const link = problem->link;
    const KeaBodyColumns *const columns = w->bodyColumns;
    KeaJacobianRow *const B = w->B, *const J = w->paddedJ;
    const int copyJ = w->J == w->paddedJ;
    MeReal *const diag = w->diag, *const invDiag = w->invDiag, *const eps = w->eps;
    MeReal *const lo = w->lo, *const hi = w->hi;
    int(*const body)[2] = w->body;
    const KeaLanes keep = KeaLanesSelectComponents(), none = KeaLanesSplat(ME_R(0.0));
    int i;
    for (i = i0; i < i1; ++i) {
        const int b0 = rowBodies[i][0], b1 = rowBodies[i][1];
        const MeReal e = epsIn ? epsIn[i] : ME_R(0.0);
        const KeaLanes keep0 = b0 >= 0 ? keep : none, keep1 = b1 >= 0 ? keep : none; /* pads and world halves 0 */
        const MeReal d = KeaRowInvMassJTOf(&in[i], b0 >= 0 ? &columns[b0] : NULL, b1 >= 0 ? &columns[b1] : NULL, e,
                                           &B[i]);
        diag[i] = d;
        invDiag[i] = d > ME_R(0.0) ? ME_R(1.0) / d : ME_R(0.0);
        eps[i] = e;
        if (copyJ) {
            KeaLanesStore(J[i].lin0, KeaLanesKeep(KeaLanesLoad(in[i].lin0), keep0));
            KeaLanesStore(J[i].ang0, KeaLanesKeep(KeaLanesLoad(in[i].ang0), keep0));
            KeaLanesStore(J[i].lin1, KeaLanesKeep(KeaLanesLoad(in[i].lin1), keep1));
            KeaLanesStore(J[i].ang1, KeaLanesKeep(KeaLanesLoad(in[i].ang1), keep1));
        }
        body[i][0] = b0 >= 0 ? b0 : nb;
        body[i][1] = b1 >= 0 ? b1 : nb;
        if (link && link[i] >= 0) { /* KeaRowBoundsInline */
            KeaFrictionBounds(loIn[i], hiIn[i], mu[i], x[link[i]], &lo[i], &hi[i]);
        } else {
            lo[i] = loIn[i];
            hi[i] = hiIn[i];
        }
    }
}

/* The warm start of rows [i0, i1): x clamped to the bounds KeaSetUpRows read, and which rows are free. */
static void KeaWarmStartRows(KeaIterativeWork *w, MeReal *x, int i0, int i1)
{
    int i;
    for (i = i0; i < i1; ++i) {
        x[i] = KeaClamp(x[i], w->lo[i], w->hi[i]);
        w->wasFree[i] = KeaRowIsFree(w, i, x[i], w->lo[i], w->hi[i]);
    }
}

typedef struct KeaRowsTask {
    const KeaProblem *problem;
    KeaIterativeWork *w;
    MeReal *x;
    int coloured; /* KeaSplitColour's answer, from KeaColourAndWarmStartChunks */
} KeaRowsTask;

static void KeaSetUpRowChunks(int start, int end, int worker, void *data)
{
    const KeaRowsTask *t = data;
    const int n = t->problem->nRows;
    (void)worker;
    KeaSetUpRows(t->problem, t->w, t->x, start * KEA_SPLIT_ROWS, KeaRowChunkEnd(end - 1, n));
}

/* The blocks' colouring (KeaSplitColour) as item 0 of the warm start's task, the warm start's row
 * chunks as items 1..: the colouring reads only the blocks and the rows' bodies and links, the warm
 * start writes only x and which rows are free, so the colouring, serial work, runs beside the rows'
 * chunks instead of before them. */
static void KeaColourAndWarmStartChunks(int start, int end, int worker, void *data)
{
    KeaRowsTask *t = data;
    const int n = t->problem->nRows;
    int j;
    (void)worker;
    for (j = start; j < end; ++j) {
        if (j == 0)
            t->coloured = KeaSplitColour(t->problem, t->w, t->w->split);
        else
            KeaWarmStartRows(t->w, t->x, (j - 1) * KEA_SPLIT_ROWS, KeaRowChunkEnd(j - 1, n));
    }
}

/* dv = M^-1 J^T x from the warm start for bodies [b0, b1), into the work's padded velocities, from
 * the padded rows and the halves' bodies of KeaSetUpRows (the world's, nb, is above every range):
 * per component the sums of KeaBodyVelocityFromImpulsesOf in its order (J^T x per body in row order,
 * then M^-1 once, KeaDot3's order lane by lane), four lanes at a time; the pads stay 0. */
static void KeaWarmVelocityOf(const KeaIterativeWork *w, const MeReal *x, int n, int b0, int b1)
{
    const KeaLanes keep = KeaLanesSelectComponents();
    const KeaJacobianRow *const J = w->J;
    const int(*const body)[2] = (const int(*)[2])w->body;
    KeaVel4 *const dv = w->dv;
    int i, b;
    KeaVel4Clear(dv + b0, b1 - b0);
    for (i = 0; i < n; ++i) {
        const MeReal s = x[i];
        const int h0 = body[i][0], h1 = body[i][1];
        if (s == ME_R(0.0))
            continue;
        if (h0 >= b0 && h0 < b1)
            KeaHalfApply4(J[i].lin0, J[i].ang0, s, &dv[h0]);
        if (h1 >= b0 && h1 < b1)
            KeaHalfApply4(J[i].lin1, J[i].ang1, s, &dv[h1]);
    }
    for (b = b0; b < b1; ++b) {
        const KeaBodyColumns *c = &w->bodyColumns[b];
        const MeReal *a = dv[b].ang;
        const KeaLanes ang = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(KeaLanesLoad(c->col[0]), KeaLanesSplat(a[0])),
                                                     KeaLanesMul(KeaLanesLoad(c->col[1]), KeaLanesSplat(a[1]))),
                                         KeaLanesMul(KeaLanesLoad(c->col[2]), KeaLanesSplat(a[2])));
        KeaLanesStoreA(dv[b].lin, KeaLanesKeep(KeaLanesMul(KeaLanesLoadA(dv[b].lin), KeaLanesSplat(c->invMass)), keep));
        KeaLanesStoreA(dv[b].ang, KeaLanesKeep(ang, keep));
    }
}

/* dv from the warm start (KeaWarmVelocityOf), item j for the j-th of `items` equal ranges of bodies:
 * each reads every row and sums its own bodies' halves in row order, so the bits do not depend on
 * the ranges, and the ranges may follow the worker count. */
static void KeaBodyVelocityRanges(int start, int end, int worker, void *data)
{
    const KeaRowsTask *t = data;
    const int nb = t->problem->nBodies, items = KeaSplitWorkers(&t->w->split->hook);
    int j;
    (void)worker;
    for (j = start; j < end; ++j)
        KeaWarmVelocityOf(t->w, t->x, t->problem->nRows, (int)((long)nb * j / items),
                          (int)((long)nb * (j + 1) / items));
}

/* Each row chunk's residual into the split's partial results (the chunk's worst, KeaResidualRows). */
static void KeaResidualRowChunks(int start, int end, int worker, void *data)
{
    const KeaRowsTask *t = data;
    const int n = t->problem->nRows;
    int j;
    (void)worker;
    for (j = start; j < end; ++j)
        t->w->split->partial[j] = KeaResidualRows(t->problem, t->w, t->x, j * KEA_SPLIT_ROWS, KeaRowChunkEnd(j, n));
}

/* The residual of the final x (KeaResidualRows over every row); split, in row chunks over the
 * workers, the chunks' worst taken in chunk order by the same rule (a NaN stays, else the largest),
 * so the same bits as one pass. */
static MeReal KeaIterativeResidual(const KeaProblem *problem, KeaIterativeWork *w, MeReal *x)
{
    const int n = problem->nRows, chunks = KeaRowChunkCount(n);
    KeaRowsTask t;
    MeReal worst = ME_R(0.0);
    int j;
    if (!w->split)
        return KeaResidualRows(problem, w, x, 0, n);
    t.problem = problem;
    t.w = w;
    t.x = x;
    t.coloured = 0;
    KeaSplitRun(w->split, KeaResidualRowChunks, chunks, &t);
    for (j = 0; j < chunks; ++j) {
        const MeReal r = w->split->partial[j];
        if (r > worst || r != r)
            worst = r;
    }
    return worst;
}

/* The solve's set-up, before the first sweep: the padded rows (KeaSetUpRows), the blocks, the warm
 * start (x clamped, which rows are free, then the work's dv), and in a split solve the colouring;
 * the row and block loops in chunks over the workers when split. Not inlined, so that a profile
 * shows the set-up apart from the sweeps. */
KEA_NOINLINE void KeaIterativeSetUp(const KeaProblem *problem, const KeaParameters *params, KeaIterativeWork *w,
                                    MeReal *x)
{
    const int n = problem->nRows, nb = problem->nBodies;
    const int rowChunks = KeaRowChunkCount(n);
    KeaRowsTask t;
    t.problem = problem;
    t.w = w;
    t.x = x;
    t.coloured = 0;
    KeaBodyColumnsFill(problem, w->bodyColumns);
    if (w->split)
        KeaSplitRun(w->split, KeaSetUpRowChunks, rowChunks, &t);
    else
        KeaSetUpRows(problem, w, x, 0, n);
    KeaSetUpBlocks(problem, w, KeaBlockCap(n, params->maxBlockRows));
    if (w->split) { /* the colouring beside the warm start's chunks */
        KeaSplitRun(w->split, KeaColourAndWarmStartChunks, rowChunks + 1, &t);
        if (!t.coloured)
            w->split = NULL; /* a friction link leaves its block: the plain sweep (KeaSplitColour) */
    } else {
        KeaWarmStartRows(w, x, 0, n);
    }
    KeaContactConstsFill(problem, w);
    if (w->split) /* dv from the warm start in ranges of bodies, one a worker */
        KeaSplitRun(w->split, KeaBodyVelocityRanges, KeaSplitWorkers(&w->split->hook), &t);
    else
        KeaWarmVelocityOf(w, x, n, 0, nb);
    memset(&w->dv[nb], 0, sizeof(KeaVel4)); /* the world's */
    w->skippedLast = 0;
    w->smRan = 0;
    w->smUnpaid = 0;
    w->smStop = KeaMax(KEA_SM_CG_STOP, params->subspaceStop);
}

/* SM's chances after the first come every this-many sweeps: subspaceEvery, or subspaceJointEvery in a
 * partition whose generic rows (those not in a declared contact: joints, limits, motors) are at least
 * params->subspaceJointShare of its rows (K58). */
static int KeaSubspaceEvery(const KeaProblem *problem, const KeaParameters *params, const KeaIterativeWork *w)
{
    const MeReal generic = (MeReal)(problem->nRows - 3 * w->nContactBlocks);
    if (params->deflation)
        return 2;
    if (params->subspaceJointShare > ME_R(0.0) && params->subspaceJointEvery > 0 &&
        generic >= params->subspaceJointShare * (MeReal)problem->nRows)
        return params->subspaceJointEvery;
    return params->subspaceEvery > 1 ? params->subspaceEvery : 1;
}

/* What a solve hands its driver (KeaIterate): the problem, its settings, the work and the outputs. */
typedef struct KeaSolveState {
    const KeaProblem *problem;
    const KeaParameters *params;
    KeaIterativeWork *w;
    MeReal *x;
    KeaBodyVelocity *dv;
    KeaStats *stats;
    KeaStatus status;
} KeaSolveState;

/* The solve after the layout: set-up, sweeps and SM, the extra effort, dv out and the residual. In a
 * split solve on several workers it runs inside the team's task, on whichever worker started first
 * (kea_split.c, KeaTeamTask), handing its chunked loops to the others. */
static void KeaIterate(void *data)
{
    KeaSolveState *state = data;
    const KeaProblem *problem = state->problem;
    const KeaParameters *params = state->params;
    KeaIterativeWork *w = state->w;
    MeReal *x = state->x;
    KeaStats *stats = state->stats;
    const int nb = problem->nBodies;
    const int effort = KeaEffortAllowed(problem, params);
    const int smFirst = !params->deflation; /* the first chance's SM does most of a solve's SM work */
    int it, b, k, limit, smEvery;

    KeaIterativeSetUp(problem, params, w, x);
    smEvery = KeaSubspaceEvery(problem, params, w);
    if (w->split)
        stats->colours = w->split->colours +
                         (w->split->colourStart[KEA_COLOUR_OVERFLOW + 1] > w->split->colourStart[KEA_COLOUR_OVERFLOW]);
    state->status = KeaStatusMaxIterations;

    /* maxIterations sweeps, then the extra effort (params->effortResidual, kea_tuning.h) if the
     * partition rests (KeaEffortAllowed): while the last sweep leaves more than KEA_EFFORT_FRACTION of
     * the blocks above it, two more (so that the last still runs backwards), up to KEA_EFFORT_FACTOR
     * maxIterations more in all.
     * SM at the first chance and every subspaceEvery-th; with nonsmoothCg, NNCG's momentum after every second sweep;
     * with deflation, its coarse correction there instead and SM at every second chance. */
    limit = params->maxIterations;
    if (params->deflation)
        KeaDeflationStart(w, x, problem->nRows);
    else if (params->nonsmoothCg)
        KeaNncgStart(w, x, problem->nRows);
    for (it = 1; it <= limit; ++it) {
        const int mayExtend = it == limit && effort &&
                              limit < params->maxIterations * (1 + KEA_EFFORT_FACTOR);
        const MeReal measureUpTo = mayExtend ? KeaMax(params->tolerance, params->effortResidual) : params->tolerance;
        const int fewAbove = mayExtend ? (int)(KEA_EFFORT_FRACTION * (MeReal)w->nBlocks) : -1;
        const MeReal sweepResidual = (w->split ? KeaSweepSplit : KeaSweep)(problem, w, params, x, stats, (it & 1) == 0,
                                                                           measureUpTo, fewAbove);
        stats->iterations = it;
        if (sweepResidual <= params->tolerance) {
            state->status = KeaStatusOk;
            break;
        }
        if (mayExtend && sweepResidual > params->effortResidual && w->sweepAbove > fewAbove) {
            limit += 2;
            ++stats->effortRounds;
        }
        if (w->smRan) /* did the last SM step lower the objective more than this sweep? */
            w->smUnpaid = w->sweepDecrease > w->smDecrease;
        w->smRan = 0;
        if (params->subspaceIterations > 0 && it < limit && (it % smEvery == 0 || (smFirst && it == 1))) {
            const int steps = KeaSubspaceMinimise(problem, w, params->subspaceIterations, x);
            if (steps < 0)
                ++stats->subspaceSkipped;
            else
                stats->subspaceSteps += steps;
        }
        /* NNCG (kea_nncg.c) or deflation (kea_deflation.c): after each pair of sweeps, never the last */
        if (params->deflation && it < limit && (it & 1) == 0)
            KeaDeflationStep(problem, w, x);
        else if (params->nonsmoothCg && it < limit && (it & 1) == 0)
            KeaNncgStep(w, x, problem->nRows);
    }
    for (b = 0; b < nb; ++b)
        for (k = 0; k < 3; ++k) {
            state->dv[b].lin[k] = w->dv[b].lin[k];
            state->dv[b].ang[k] = w->dv[b].ang[k];
        }
    stats->residual = KeaIterativeResidual(problem, w, x);
}

/* Size: KeaSolve's problem, parameters and outputs, the arena, and whether the rows were proved. */
KeaStatus KeaSolveIterative(const KeaProblem *problem, const KeaParameters *params, KeaArena *arena,
                            MeReal *x, KeaBodyVelocity *dv, KeaStats *stats, int rowsProved)
{
    KeaIterativeWork w;
    KeaSplit split;
    KeaSolveState state;

    KeaIterativeLayout(arena, problem->nRows, problem->nBodies, KEA_MAX_BLOCK_ROWS, &w);
    if (rowsProved) /* J's pads and world halves are zero already: read in place, not copied */
        w.J = problem->J;
    if (KeaSplits(problem->nRows, params)) { /* KeaSplitMemoryRequired has made room */
        KeaSplitLayout(arena, problem->nRows, problem->nBodies, KeaSplitWorkers(&params->tasks), &split);
        split.hook = params->tasks;
        split.hook.workers = KeaSplitWorkers(&params->tasks);
        w.split = &split;
    }
    state.problem = problem;
    state.params = params;
    state.w = &w;
    state.x = x;
    state.dv = dv;
    state.stats = stats;
    if (w.split)
        KeaSplitDrive(&split, KeaIterate, &state); /* on the workers' team */
    else
        KeaIterate(&state);
    return state.status;
}
