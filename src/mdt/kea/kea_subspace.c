/* kea_subspace.c -- subspace minimisation (SM) of Kea's iterative path (kea_iterative.h), with its
 * schedule, after the idea of Silcowitz, Niebe and Erleben, "Interactive rigid body dynamics using a
 * projected Gauss-Seidel subspace minimization method", 2010.
 *
 * A PGS sweep is good at finding which rows sit at a bound, poor at solving the linear system on the
 * rows that do not. So between two sweeps, with the bounds frozen at their current values, the free
 * rows F (strictly inside their bounds) take a few conjugate-gradient steps on A_FF delta = -w_F
 * (block-Jacobi preconditioned, matrix-free: A_FF p = J_F M^-1 J_F^T p + eps p costs two passes over
 * F through the per-body scratch), then a projected backtracking line search
 * x_F <- mid(lo, x_F + a delta, hi), a = 1, 1/2, ... (KEA_SM_LINE_SEARCH_TRIES), accepts the first
 * step that lowers the QP objective
 *   f(x) = 1/2 x^T A x - r^T x;   f(x + s) - f(x) = s . (w + 1/2 (J M^-1 J^T s + eps s))
 * (A s from CG's residual and the clamped rows alone: KeaTrialStep; dv moves by M^-1 J^T s summed
 * over CG's steps, with no scatter of s). A rejected step leaves x as PGS made it, so
 * SM never makes the QP worse; the next sweep re-applies the friction links and the active set.
 * Each CG step costs about half a sweep; KeaStats.subspaceSteps counts them.
 *
 * The schedule (KeaSubspaceMinimise; its thresholds are the KEA_SM_* constants of kea_tuning.h).
 * SM pays when the sweeps have (nearly) settled which rows sit at a bound: CG on a free set that the
 * next sweep changes again is mostly thrown away. So an SM chance is skipped when many rows went
 * from free to bound or back since the last chance (KEA_SM_SKIP_MIN_CHANGED, KEA_SM_SKIP_FRACTION),
 * but this rule never skips two chances in a row (skipping at any change without that rule let the
 * pyramids fall). And SM must pay for itself: when the sweep after an SM step lowers the objective
 * more than that step did (the sweep's decrease estimated as 1/2 delta . w per updated row, exact
 * for an unclamped block step, low for a clamped one, so the estimate favours SM), later chances
 * wait until few rows change (KEA_SM_UNPAID_FRACTION); that rule can skip several chances in a row.
 * A settling or resting stack's SM steps lower the objective far more than the next sweep and all
 * run; once a pile's active set settles, SM runs again, so a solve run to convergence keeps it.
 * KeaStats.subspaceSkipped counts the skips. Figures: bench/RESULTS.md. */
#include "kea_block_kernels.h"
#include "kea_contact_packs.h"
#include "kea_joint_packs.h"

/* dvTmp += M^-1 J_F^T v (v by position in the free list) for the pieces (KeaFindSegments) order[j]
 * (order NULL: j itself), j in [j0, j1), in that order: a segment through the sweep's block kernels, a
 * row on its own by itself; the world's half (dvTmp[nb], all zero) is not written, so that a colour's
 * pieces on the world may run at once. The work's arrays are read into
 * locals once: a four-lane store may alias anything for the compiler, which would reload them for
 * every piece. */
KEA_ALWAYS_INLINE void KeaScatterPieces(const KeaIterativeWork *w, const MeReal *v, const int *order, int j0, int j1)
{
    const KeaFreePiece *pieces = w->pieces;
    const KeaJacobianRow *B = w->B;
    KeaVel4 *dvTmp = w->dvTmp;
    const int nb = w->nb;
    int j;
    for (j = j0; j < j1; ++j) {
        const KeaFreePiece *piece = &pieces[order ? order[j] : j];
        const int onWorld0 = piece->body[0] == nb, onWorld1 = piece->body[1] == nb;
        KeaVel4 *v0 = &dvTmp[piece->body[0]], *v1 = onWorld1 ? NULL : &dvTmp[piece->body[1]];
        const MeReal *vp = v + piece->pos;
        if (piece->rows == 1) {
            if (vp[0] == ME_R(0.0))
                continue;
            if (!onWorld0)
                KeaHalfApply4(B[piece->row].lin0, B[piece->row].ang0, vp[0], v0);
            if (v1)
                KeaHalfApply4(B[piece->row].lin1, B[piece->row].ang1, vp[0], v1);
        } else if (!onWorld0) {
            KeaBlockScatter(piece->rows, &B[piece->row], vp, v0, v1);
        } else if (v1) {
            KeaBlockScatterHalf1(piece->rows, &B[piece->row], vp, v1);
        }
    }
}

/* What SM's chunked loops share (kea_iterative.h, "the split solve"). Split: the first packChunks
 * chunks are the packs [k packSize, (k + 1) packSize), the others the free list's pieces after the
 * pack region, size to a chunk; not split: one chunk, every pack and piece. */
typedef struct KeaSmTask {
    const KeaProblem *problem;
    const KeaIterativeWork *w;
    const MeReal *x;   /* the impulses (the first chunked loop) */
    const MeReal *v;   /* the scatter's input */
    MeReal a;          /* CG's step length */
    MeReal *partial;   /* one partial sum per chunk */
    int nFree, size, packSize, packChunks, chunks;
    int firstChunk, lastChunk; /* the scatter: a colour's chunks */
} KeaSmTask;

static void KeaScatterChunks(int start, int end, int worker, void *data)
{
    const KeaSmTask *t = data;
    const KeaSplit *split = t->w->split;
    int k;
    (void)worker;
    for (k = t->firstChunk + start; k < t->firstChunk + end; ++k)
        KeaScatterPieces(t->w, t->v, split->pieceOrder, split->pieceChunk[k], split->pieceChunk[k + 1]);
}

/* A colour's pack chunks (KeaSplitPacks). */
static void KeaScatterPackChunks(int start, int end, int worker, void *data)
{
    const KeaSmTask *t = data;
    const KeaSplit *split = t->w->split;
    (void)worker;
    KeaPacksScatterSplit(t->w, t->v, t->w->dvTmp, split->packOrder, split->packChunk[t->firstChunk + start],
                         split->packChunk[t->firstChunk + end]);
}

/* A split scatter's colours one after the other: colour c's chunks colourChunk[c] ... colourChunk[c +
 * 1] - 1 over the workers, the overflow colour's on this thread. */
static void KeaScatterColours(const KeaSplit *split, KeaTaskFn task, const int *colourChunk, KeaSmTask *t)
{
    int c;
    for (c = 0; c <= KEA_COLOUR_COUNT; ++c) {
        const int chunks = colourChunk[c + 1] - colourChunk[c];
        t->firstChunk = colourChunk[c];
        if (c == KEA_COLOUR_OVERFLOW)
            task(0, chunks, 0, t);
        else
            KeaSplitRun(split, task, chunks, t);
    }
}

/* dvTmp = M^-1 J_F^T v: the packs, then the pieces in free-list order; in a split solve the packs
 * colour by colour (KeaSplitPacks), then the pieces colour by colour (KeaSplitPieces). */
static void KeaScatter(const KeaProblem *problem, KeaIterativeWork *w, const MeReal *v)
{
    KeaSplit *split = w->split;
    KeaSmTask t;
    KeaVel4Clear(w->dvTmp, problem->nBodies + 1);
    if (!split) {
        KeaPacksScatter(w, v, w->dvTmp, 0, w->nPacks);
        KeaScatterPieces(w, v, NULL, 0, w->nPieces);
        return;
    }
    t.w = w;
    t.v = v;
    KeaScatterColours(split, KeaScatterPackChunks, split->packColourChunk, &t);
    KeaScatterColours(split, KeaScatterChunks, split->pieceColourChunk, &t);
}

/* out[p] = J_i . dv of the free rows of pieces order[j] (order NULL: j itself), j in [j0, j1). */
KEA_ALWAYS_INLINE void KeaGatherPieces(const KeaIterativeWork *w, const KeaVel4 *dv, MeReal *out, const int *order,
                                       int j0, int j1)
{
    const KeaFreePiece *pieces = w->pieces;
    const KeaJacobianRow *J = w->J;
    int j;
    for (j = j0; j < j1; ++j) {
        const KeaFreePiece *piece = &pieces[order ? order[j] : j];
        const KeaVel4 *v0 = &dv[piece->body[0]], *v1 = &dv[piece->body[1]];
        MeReal *o = out + piece->pos;
        if (piece->rows == 1)
            o[0] = KeaRowVel4(&J[piece->row], v0, v1);
        else
            KeaBlockGather(w, piece->row, piece->rows, v0, v1, o);
    }
}

/* out[p] = J_i . dv of the free rows of pieces [k0, k1) (the packs' positions by KeaPacksCg*). Not
 * split, [k0, k1) is every piece: the segments in joint packs by the packs, the others a piece at a
 * time. */
static void KeaGather(const KeaIterativeWork *w, const KeaVel4 *dv, MeReal *out, int k0, int k1)
{
    if (w->split) {
        KeaGatherPieces(w, dv, out, NULL, k0, k1);
        return;
    }
    KeaGatherPieces(w, dv, out, w->loosePieces, 0, w->nLoosePieces);
    KeaJointPacksGather(w, dv, out);
}

/* After the pack region (positions before first), the blocks whose rows are all free (and whose
 * factor exists) become segments of the free list, preconditioned by their exact inverse A_bb^-1;
 * the other free rows by 1 / d_i. */
static void KeaFindSegments(KeaIterativeWork *w, int first, int nFree)
{
    int p = first;
    w->nPieces = w->nLoosePieces = 0;
    if (w->nJointPacks < 0) /* the solve's first SM step that runs */
        KeaJointPacksFill(w);
    KeaJointPacksClear(w);
    while (p < nFree) {
        const int i = w->freeRows[p], b = w->rowBlock[i];
        const int m = w->blockStart[b + 1] - w->blockStart[b];
        KeaFreePiece *piece = &w->pieces[w->nPieces++];
        piece->pos = p;
        piece->row = i;
        piece->body[0] = w->body[i][0];
        piece->body[1] = w->body[i][1];
        if (m > 1 && i == w->blockStart[b] && w->blockFactored[b] && p + m <= nFree &&
            w->freeRows[p + m - 1] == i + m - 1) {
            piece->rows = m;
            piece->matrix = w->blockMatrix[b];
            p += m;
        } else {
            piece->rows = 1;
            piece->matrix = -1;
            ++p;
        }
        if (piece->rows > 1 && w->jointPackOf[b] >= 0)
            KeaJointPacksMark(w, b, piece->pos);
        else
            w->loosePieces[w->nLoosePieces++] = w->nPieces - 1;
    }
    KeaJointPacksFinish(w);
}

/* z = P^-1 res (block-Jacobi preconditioner of the free rows) over pieces order[j] (order NULL: j
 * itself), j in [j0, j1): a segment by its block's inverse, a row on its own by 1 / d_i (the packs'
 * contacts: KeaPackPrecondition, in KeaPacksCgStart and KeaPacksCgUpdate). */
KEA_ALWAYS_INLINE void KeaPreconditionPieces(const KeaIterativeWork *w, const MeReal *res, MeReal *z, const int *order,
                                             int j0, int j1)
{
    const KeaFreePiece *pieces = w->pieces;
    const MeReal *blockInv = w->blockInv, *invDiag = w->invDiag;
    int j;
    for (j = j0; j < j1; ++j) {
        const KeaFreePiece *piece = &pieces[order ? order[j] : j];
        const int p = piece->pos;
        if (piece->rows == 1)
            z[p] = res[p] * invDiag[piece->row];
        else
            KeaBlockSymmetricApply(piece->rows, blockInv + piece->matrix, res + p, z + p);
    }
}

/* KeaPreconditionPieces over pieces [k0, k1), as KeaGather: not split, the joint packs' segments by
 * the packs. */
static void KeaPrecondition(const KeaIterativeWork *w, const MeReal *res, MeReal *z, int k0, int k1)
{
    if (w->split) {
        KeaPreconditionPieces(w, res, z, NULL, k0, k1);
        return;
    }
    KeaPreconditionPieces(w, res, z, w->loosePieces, 0, w->nLoosePieces);
    KeaJointPacksPrecondition(w, res, z);
}

/* q += eps p, returning p . q (the new q) in one pass: the sums of KeaDotN4, in its order, carried
 * on from sum[0 .. 3] (the sums of the positions before, a multiple of 4; zeros for none). */
static MeReal KeaAddEpsDot(const MeReal sum[4], MeReal *q, const MeReal *eps, const MeReal *p, int n)
{
    MeReal s0 = sum[0], s1 = sum[1], s2 = sum[2], s3 = sum[3];
    int m = 0;
    for (; m + 4 <= n; m += 4) {
        const MeReal q0 = q[m] + eps[m] * p[m], q1 = q[m + 1] + eps[m + 1] * p[m + 1];
        const MeReal q2 = q[m + 2] + eps[m + 2] * p[m + 2], q3 = q[m + 3] + eps[m + 3] * p[m + 3];
        q[m] = q0;
        q[m + 1] = q1;
        q[m + 2] = q2;
        q[m + 3] = q3;
        s0 += p[m] * q0;
        s1 += p[m + 1] * q1;
        s2 += p[m + 2] * q2;
        s3 += p[m + 3] * q3;
    }
    for (; m < n; ++m) {
        q[m] = q[m] + eps[m] * p[m];
        s0 += p[m] * q[m];
    }
    return (s0 + s1) + (s2 + s3);
}

/* a . b over n entries with KeaDotN4's sums, carried on from the lanes acc (the sums of the packs'
 * positions before a, KeaPacksCgStart's; zeros for none): KeaDotN4 over the whole range, to the bit
 * (with fewer than four entries in all, (s0 + 0) + (0 + 0) is KeaDotN4's s0 + 0). */
static MeReal KeaDotFrom(KeaLanes acc, const MeReal *a, const MeReal *b, int n)
{
    MeReal s[4];
    int m = 0;
    for (; m + 4 <= n; m += 4)
        acc = KeaLanesAdd(acc, KeaLanesMul(KeaLanesLoad(a + m), KeaLanesLoad(b + m)));
    KeaLanesStore(s, acc);
    for (; m < n; ++m)
        s[0] += a[m] * b[m];
    return (s[0] + s[1]) + (s[2] + s[3]);
}

/* Set wasFree to which rows are free now (KeaRowIsFree); returns how many rows changed. Every
 * chance of an SM step does this, skipped or not, so it is kept cheaper than the bounds and the
 * free list, which only a step that runs needs: the declared contacts, a pile's every block, were
 * tallied by the sweep just before (KeaContactFreeRows), only the other blocks are visited here
 * (their friction bounds can follow a row that a later block of the sweep changed). */
static int KeaUpdateFreeRows(const KeaProblem *problem, KeaIterativeWork *w, const MeReal *x)
{
    unsigned char *was = w->wasFree;
    int b, i, changed = w->sweepChanged;
    if (w->nContactBlocks == w->nBlocks)
        return changed;
    for (b = 0; b < w->nBlocks; ++b) {
        const int s = w->blockStart[b];
        if (w->blockContact[b])
            continue; /* the sweep has tallied it (KeaContactFreeRows) */
        for (i = s; i < w->blockStart[b + 1]; ++i) {
            MeReal lo, hi;
            unsigned char isFree;
            KeaRowBoundsInline(problem, x, i, &lo, &hi);
            isFree = KeaRowIsFree(w, i, x[i], lo, hi);
            changed += isFree != was[i];
            was[i] = isFree;
        }
    }
    return changed;
}

/* CG's update step += a dir, res -= a q over the free list: element by element, so that the
 * compiler runs it four lanes at a time with the same operations on each element (restrict: the
 * arrays are distinct). */
static void KeaCgUpdate(int nFree, MeReal a, const MeReal *restrict dir, const MeReal *restrict q,
                        MeReal *restrict step, MeReal *restrict res)
{
    int p;
    for (p = 0; p < nFree; ++p) {
        step[p] += a * dir[p];
        res[p] -= a * q[p];
    }
}

/* CG's new direction dir = z + beta dir (as KeaCgUpdate, element by element). */
static void KeaCgDirection(int nFree, MeReal beta, const MeReal *restrict z, MeReal *restrict dir)
{
    int p;
    for (p = 0; p < nFree; ++p)
        dir[p] = z[p] + beta * dir[p];
}

/* CG's next direction, dir = z + beta dir, and its scatter dvTmp = M^-1 J_F^T dir: not split, in one
 * pass over the packs (KeaPacksScatterDirection), then the pieces; split, the direction first. */
static void KeaScatterDirection(const KeaProblem *problem, KeaIterativeWork *w, int nFree, MeReal beta)
{
    const int p0 = KEA_PACK_POSITIONS * w->nPacks;
    if (w->split) {
        KeaCgDirection(nFree, beta, w->z, w->dir);
        KeaScatter(problem, w, w->dir);
        return;
    }
    KeaVel4Clear(w->dvTmp, problem->nBodies + 1);
    KeaPacksScatterDirection(w, beta, 0, w->nPacks);
    KeaCgDirection(nFree - p0, beta, w->z + p0, w->dir + p0);
    KeaScatterPieces(w, w->dir, NULL, 0, w->nPieces);
}

/* SM's chunk k: its packs [r[0], r[1]), its pieces [r[2], r[3]) and their positions [r[4], r[5]) in
 * the free list (a chunk holds packs or pieces when split, both when not). */
static void KeaSmChunk(const KeaSmTask *t, int k, int r[6])
{
    const int nPacks = t->w->nPacks, nPieces = t->w->nPieces;
    if (!t->w->split) {
        r[0] = r[2] = r[4] = 0;
        r[1] = nPacks;
        r[3] = nPieces;
        r[5] = t->nFree;
    } else if (k < t->packChunks) {
        r[0] = k * t->packSize;
        r[1] = r[0] + t->packSize < nPacks ? r[0] + t->packSize : nPacks;
        r[2] = r[3] = 0;
        r[4] = KEA_PACK_POSITIONS * r[0];
        r[5] = KEA_PACK_POSITIONS * r[1];
    } else {
        r[0] = r[1] = 0;
        r[2] = (k - t->packChunks) * t->size;
        r[3] = r[2] + t->size < nPieces ? r[2] + t->size : nPieces;
        r[4] = t->w->pieces[r[2]].pos;
        r[5] = r[3] < nPieces ? t->w->pieces[r[3]].pos : t->nFree;
    }
}

/* The first position of chunk k's pieces (r: KeaSmChunk's ranges): after its packs' positions. */
static int KeaPiecesFrom(const int r[6])
{
    return r[4] + KEA_PACK_POSITIONS * (r[1] - r[0]);
}

/* CG's start on chunk k: grad = w_F at x (J_F dv + eps x - r), step = 0, res = -grad, z = P^-1 res,
 * dir = z; its partial res . z. The packs in one pass of lanes (KeaPacksCgStart), then the pieces.
 * (Each chunk writes its own positions of the work's arrays.) */
static void KeaCgStartChunks(int start, int end, int worker, void *data)
{
    const KeaSmTask *t = data;
    const KeaIterativeWork *w = t->w;
    int k, r[6], p, i, p0;
    (void)worker;
    for (k = start; k < end; ++k) {
        KeaLanes acc = KeaLanesSplat(ME_R(0.0));
        KeaSmChunk(t, k, r);
        KeaPacksCgStart(w, r[0], r[1], &acc);
        p0 = KeaPiecesFrom(r);
        KeaGather(w, w->dv, w->grad, r[2], r[3]);
        for (p = p0; p < r[5]; ++p) {
            i = w->freeRows[p];
            w->grad[p] = w->grad[p] + w->eps[i] * t->x[i] - t->problem->rhs[i];
            w->step[p] = ME_R(0.0);
            w->res[p] = -w->grad[p];
        }
        KeaPrecondition(w, w->res, w->z, r[2], r[3]);
        t->partial[k] = KeaDotFrom(acc, w->res + p0, w->z + p0, r[5] - p0);
        for (p = p0; p < r[5]; ++p)
            w->dir[p] = w->z[p];
    }
}

/* A_FF dir on chunk k: q = J_F dvTmp (KeaScatter of dir before) + eps dir; its partial dir . q. */
static void KeaCgProductChunks(int start, int end, int worker, void *data)
{
    const KeaSmTask *t = data;
    const KeaIterativeWork *w = t->w;
    int k, r[6], p0;
    (void)worker;
    for (k = start; k < end; ++k) {
        KeaLanes acc = KeaLanesSplat(ME_R(0.0));
        MeReal sum[4];
        KeaSmChunk(t, k, r);
        KeaPacksCgProduct(w, r[0], r[1], &acc);
        KeaLanesStore(sum, acc);
        p0 = KeaPiecesFrom(r);
        KeaGather(w, w->dvTmp, w->q, r[2], r[3]);
        t->partial[k] = KeaAddEpsDot(sum, w->q + p0, w->epsFree + p0, w->dir + p0, r[5] - p0);
    }
}

/* CG's update on chunk k: step += a dir, res -= a q, z = P^-1 res; its partial res . z. */
static void KeaCgUpdateChunks(int start, int end, int worker, void *data)
{
    const KeaSmTask *t = data;
    const KeaIterativeWork *w = t->w;
    int k, r[6], p0;
    (void)worker;
    for (k = start; k < end; ++k) {
        KeaLanes acc = KeaLanesSplat(ME_R(0.0));
        KeaSmChunk(t, k, r);
        KeaPacksCgUpdate(w, t->a, r[0], r[1], &acc);
        p0 = KeaPiecesFrom(r);
        KeaCgUpdate(r[5] - p0, t->a, w->dir + p0, w->q + p0, w->step + p0, w->res + p0);
        KeaPrecondition(w, w->res, w->z, r[2], r[3]);
        t->partial[k] = KeaDotFrom(acc, w->res + p0, w->z + p0, r[5] - p0);
    }
}

/* Run a chunked loop of SM: over the workers in a split solve (chunks of KEA_SPLIT_PACKS packs, then
 * of KEA_SPLIT_PIECES pieces), else as one chunk; returns its partials added in chunk order. */
static MeReal KeaSmRun(KeaSmTask *t, KeaTaskFn task)
{
    const int chunks = t->chunks;
    MeReal sum;
    int k;
    if (t->w->split)
        KeaSplitRun(t->w->split, task, chunks, t);
    else
        task(0, chunks, 0, t);
    sum = t->partial[0];
    for (k = 1; k < chunks; ++k)
        sum += t->partial[k];
    return sum;
}

/* dv += a v over bodies 0 ... nb - 1 (the world's, nb, stays 0). */
static void KeaVel4AddScaled(KeaVel4 *restrict dv, MeReal a, const KeaVel4 *restrict v, int nb)
{
    const KeaLanes scale = KeaLanesSplat(a);
    int b;
    for (b = 0; b < nb; ++b) {
        KeaLanesAddScaled(dv[b].lin, v[b].lin, scale);
        KeaLanesAddScaled(dv[b].ang, v[b].ang, scale);
    }
}

/* Preconditioned CG on A_FF step = -w_F from step = 0 over the nFree rows of the free list (grad
 * set to w_F at x); returns the CG steps taken (at most maxSteps). Sets smRan when CG can start. */
static int KeaSubspaceCg(const KeaProblem *problem, KeaIterativeWork *w, KeaSmTask *t, int maxSteps)
{
    MeReal rz, rz0, beta = ME_R(0.0);
    int steps = 0;
    rz = rz0 = KeaSmRun(t, KeaCgStartChunks);
    if (!(rz0 > ME_R(0.0)))
        return 0;
    w->smRan = 1;
    w->smDecrease = ME_R(0.0);
    KeaVel4Clear(w->dvStep, problem->nBodies + 1);
    while (steps < maxSteps) {
        MeReal pq, rzNew;
        if (steps == 0)
            KeaScatter(problem, w, w->dir);
        else /* the direction made where it is scattered (none made after the last step) */
            KeaScatterDirection(problem, w, t->nFree, beta);
        pq = KeaSmRun(t, KeaCgProductChunks);
        if (!(pq > ME_R(0.0)))
            break;
        t->a = rz / pq;
        rzNew = KeaSmRun(t, KeaCgUpdateChunks);
        KeaVel4AddScaled(w->dvStep, t->a, w->dvTmp, problem->nBodies);
        ++steps;
        if (!(rzNew > w->smStop * rz0))
            break;
        beta = rzNew / rz;
        rz = rzNew;
    }
    return steps;
}

/* The line search's trial at `scale`, s = scale step: at the positions a bound clamps, z = mid(lo,
 * xF + s, hi) - xF and c = z - s; elsewhere z = s itself (exactly) and c = 0. Writes z and c
 * (four lanes at a time, then the tail), lists the clamped positions, and returns their count. Its
 * objective's change, with no product over the free list: CG's recurrence gives A step = -(grad +
 * res), and A is symmetric, so
 *   f(x + z) - f(x) = z . (grad + 1/2 A z)
 *                   = sum_p [z_p grad_p - 1/2 scale (z_p + c_p)(grad_p + res_p)] + 1/2 c . A c,
 * *sum: the position sum, position p in lane p mod 4 (KeaTrialChange adds the rest). */
static int KeaTrialStep(KeaIterativeWork *w, int nFree, MeReal scale, MeReal *c, MeReal *sum)
{
    const MeReal *xF = w->xFree, *step = w->step, *lo = w->lo, *hi = w->hi, *grad = w->grad, *res = w->res;
    const KeaLanes scales = KeaLanesSplat(scale), half = KeaLanesSplat(ME_R(0.5) * scale);
    KeaLanes acc = KeaLanesSplat(ME_R(0.0));
    MeReal *z = w->z;
    int p, k, n = 0;
    for (p = 0; p + 4 <= nFree; p += 4) {
        const KeaLanes x0 = KeaLanesLoadA(xF + p), s = KeaLanesMul(scales, KeaLanesLoadA(step + p));
        const KeaLanes t = KeaLanesAdd(x0, s), g = KeaLanesLoadA(grad + p);
        const KeaLanes m = KeaLanesMin(KeaLanesMax(t, KeaLanesLoadA(lo + p)), KeaLanesLoadA(hi + p));
        const KeaLanes clamps = KeaLanesSelectNotEqual(m, t), toBound = KeaLanesSub(m, x0);
        const KeaLanes zp = KeaLanesChoose(clamps, toBound, s), cp = KeaLanesKeep(KeaLanesSub(toBound, s), clamps);
        const KeaLanes minusAs = KeaLanesAdd(g, KeaLanesLoadA(res + p)); /* -(A step)_p */
        const KeaLanes curve = KeaLanesMul(half, KeaLanesMul(KeaLanesAdd(zp, cp), minusAs));
        KeaLanesStoreA(z + p, zp);
        KeaLanesStoreA(c + p, cp);
        acc = KeaLanesAdd(acc, KeaLanesSub(KeaLanesMul(zp, g), curve));
        if (KeaLanesAnyNonZero(cp))
            for (k = p; k < p + 4; ++k)
                if (c[k] != ME_R(0.0))
                    w->clamped[n++] = k;
    }
    KeaLanesStore(sum, acc);
    for (; p < nFree; ++p) {
        const MeReal s = scale * step[p], t = xF[p] + s, m = KeaMin(KeaMax(t, lo[p]), hi[p]);
        z[p] = m != t ? m - xF[p] : s;
        c[p] = m != t ? (m - xF[p]) - s : ME_R(0.0);
        sum[p & 3] += z[p] * grad[p] - ME_R(0.5) * scale * ((z[p] + c[p]) * (grad[p] + res[p]));
        if (c[p] != ME_R(0.0))
            w->clamped[n++] = p;
    }
    return n;
}

/* The objective's change made by the line search's trial at `scale` (KeaTrialStep), with c . A c =
 * c . (J_C dvTmp + eps c), dvTmp = M^-1 J_C^T c over the clamped positions C alone (*nClamped of
 * them). Leaves z the trial step and, when some position is clamped, dvTmp = M^-1 J^T c (with none,
 * dvTmp is not written: c is 0). */
static MeReal KeaTrialChange(KeaIterativeWork *w, int nFree, int nBodies, MeReal scale, int *nClamped)
{
    MeReal *c = w->q; /* q is free after CG */
    MeReal sum[4], cAc = ME_R(0.0);
    const int n = KeaTrialStep(w, nFree, scale, c, sum);
    int k;
    if (n > 0)
        KeaVel4Clear(w->dvTmp, nBodies + 1);
    for (k = 0; k < n; ++k) {
        const int i = w->freeRows[w->clamped[k]];
        KeaRowApply4(&w->B[i], c[w->clamped[k]], &w->dvTmp[w->body[i][0]], &w->dvTmp[w->body[i][1]]);
    }
    for (k = 0; k < n; ++k) {
        const int q = w->clamped[k], i = w->freeRows[q];
        const MeReal Jc = KeaRowVel4(&w->J[i], &w->dvTmp[w->body[i][0]], &w->dvTmp[w->body[i][1]]);
        cAc += c[q] * (Jc + w->epsFree[q] * c[q]);
    }
    *nClamped = n;
    return ((sum[0] + sum[1]) + (sum[2] + sum[3])) + ME_R(0.5) * cAc;
}

/* Projected backtracking line search on the QP objective (bounds frozen) along CG's step: the first
 * of KEA_SM_LINE_SEARCH_TRIES halvings that lowers it (KeaTrialChange) is applied to x and dv
 * (smDecrease set). */
static void KeaSubspaceLineSearch(const KeaProblem *problem, KeaIterativeWork *w, int nFree, MeReal *x)
{
    MeReal scale;
    int p, tries, nClamped;
    for (tries = 0, scale = ME_R(1.0); tries < KEA_SM_LINE_SEARCH_TRIES; ++tries, scale *= ME_R(0.5)) {
        const MeReal df = KeaTrialChange(w, nFree, problem->nBodies, scale, &nClamped);
        if (df < ME_R(0.0)) {
            w->smDecrease = -df;
            KeaPacksApply(w, x);
            for (p = KEA_PACK_POSITIONS * w->nPacks; p < nFree; ++p)
                if (w->z[p] != ME_R(0.0))
                    x[w->freeRows[p]] += w->z[p];
            KeaVel4AddScaled(w->dv, scale, w->dvStep, problem->nBodies);
            if (nClamped > 0)
                KeaVel4AddScaled(w->dv, ME_R(1.0), w->dvTmp, problem->nBodies);
            return;
        }
    }
}

/* A split solve's KeaPacksFill: the plan on this thread, the packs filled in chunks of
 * KEA_SPLIT_PACKS over the workers (KeaPacksSet: each pack writes only its own). */
typedef struct KeaPacksSetTask {
    const KeaProblem *problem;
    KeaIterativeWork *w;
} KeaPacksSetTask;

static void KeaPacksSetChunks(int start, int end, int worker, void *data)
{
    const KeaPacksSetTask *t = data;
    const int last = end * KEA_SPLIT_PACKS;
    (void)worker;
    KeaPacksSet(t->problem, t->w, start * KEA_SPLIT_PACKS, last < t->w->nPacks ? last : t->w->nPacks);
}

static void KeaPacksFillSplit(const KeaProblem *problem, KeaIterativeWork *w)
{
    KeaPacksSetTask t;
    t.problem = problem;
    t.w = w;
    KeaPacksPlan(problem, w);
    KeaSplitRun(w->split, KeaPacksSetChunks, (w->nPacks + KEA_SPLIT_PACKS - 1) / KEA_SPLIT_PACKS, &t);
}

/* The packs' colouring (KeaSplitPacks) and their free rows (KeaPacksListFree) as the two items of one
 * task: the colouring reads the packs' bodies and writes the split's pack order, the list reads the
 * packs' rows and writes their masks and the free list's pack region, so the two serial passes run
 * side by side on two workers. */
typedef struct KeaPacksListTask {
    KeaIterativeWork *w;
    const MeReal *x;
    int listed;
} KeaPacksListTask;

static void KeaColourPacksAndListFreeItems(int start, int end, int worker, void *data)
{
    KeaPacksListTask *t = data;
    int j;
    (void)worker;
    for (j = start; j < end; ++j)
        if (j == 0)
            KeaSplitPacks(t->w, t->w->split);
        else
            t->listed = KeaPacksListFree(t->w, t->x);
}

static int KeaColourPacksAndListFree(KeaIterativeWork *w, const MeReal *x)
{
    KeaPacksListTask t;
    t.w = w;
    t.x = x;
    t.listed = 0;
    KeaSplitRun(w->split, KeaColourPacksAndListFreeItems, 2, &t);
    return t.listed;
}

/* Subspace minimisation on the rows strictly inside their bounds; returns the CG steps taken, -1 if
 * skipped because the active set is still moving (top comment). */
int KeaSubspaceMinimise(const KeaProblem *problem, KeaIterativeWork *w, int maxSteps, MeReal *x)
{
    const int n = problem->nRows;
    int b, i, nFree, listed, changed, steps;
    KeaSmTask t;
    MeReal one;

    changed = KeaUpdateFreeRows(problem, w, x);
    if (changed > KEA_SM_SKIP_MIN_CHANGED && (long)changed * KEA_SM_SKIP_FRACTION > (long)n && !w->skippedLast) {
        w->skippedLast = 1;
        return -1;
    }
    w->skippedLast = 0;
    if (w->smUnpaid && changed > KEA_SM_SKIP_MIN_CHANGED && (long)changed * KEA_SM_UNPAID_FRACTION > (long)n)
        return -1; /* it did not pay: wait until the active set has settled */
    /* the step runs: list the free rows, freeze their bounds; the packs' region first */
    if (w->nPacks < 0) { /* the first SM step of the solve that runs */
        if (w->split) { /* the packs filled in chunks, coloured beside their free rows */
            KeaPacksFillSplit(problem, w);
            listed = KeaColourPacksAndListFree(w, x);
        } else {
            KeaPacksFill(problem, w);
            listed = KeaPacksListFree(w, x);
        }
    } else {
        listed = KeaPacksListFree(w, x);
    }
    nFree = KEA_PACK_POSITIONS * w->nPacks;
    if (w->nContactBlocks < w->nBlocks) /* else every block is a declared contact, all in the packs */
        for (b = 0; b < w->nBlocks; ++b) { /* rows in order */
            if (w->blockContact[b])
                continue; /* a declared contact: its rows' places are in the packs */
            for (i = w->blockStart[b]; i < w->blockStart[b + 1]; ++i)
                if (w->wasFree[i]) { /* its eps where its place is assigned, as the packs' */
                    KeaRowBoundsInline(problem, x, i, &w->lo[nFree], &w->hi[nFree]);
                    w->xFree[nFree] = x[i];
                    w->epsFree[nFree] = w->eps[i];
                    w->freeRows[nFree++] = i;
                    ++listed;
                }
        }
    if (listed == 0)
        return 0;
    KeaFindSegments(w, KEA_PACK_POSITIONS * w->nPacks, nFree);
    if (w->split)
        KeaSplitPieces(w, w->split);
    t.problem = problem;
    t.w = w;
    t.x = x;
    t.nFree = nFree;
    t.size = KEA_SPLIT_PIECES;
    t.packSize = KEA_SPLIT_PACKS;
    t.packChunks = (w->nPacks + KEA_SPLIT_PACKS - 1) / KEA_SPLIT_PACKS;
    t.chunks = w->split ? t.packChunks + (w->nPieces + KEA_SPLIT_PIECES - 1) / KEA_SPLIT_PIECES : 1;
    t.partial = w->split ? w->split->partial : &one;
    steps = KeaSubspaceCg(problem, w, &t, maxSteps);
    if (steps > 0)
        KeaSubspaceLineSearch(problem, w, nFree, x);
    return steps;
}
