/* kea_contact_kernel.h -- the contact step of the iterative path (kea_iterative.h): one declared
 * contact (KeaContact, kea.h: a normal row [0, inf) and two friction rows linked to it) solved
 * exactly with the rest of x fixed. The one contact step: every declared contact goes through it,
 * and rows not declared as a contact (an adhesive contact's, bounded friction, a one-row contact)
 * through the generic block step (kea_iterative.c), which has no contact case of its own.
 *
 * With x = (n, f1, f2), A the contact's 3 x 3 block matrix and w = A x - r_loc, the step tries, in
 * this order: every row free (one product with the block's inverse, valid when the result is in
 * the cone); the active set the contact was in (a sliding contact usually keeps sliding the same
 * way); opening (n = 0); then each friction row free or sliding at +-mu n, not both free. A set is
 * valid when its equations' solution keeps n > 0, a free friction impulse within +-mu n and a
 * sliding row's w pushing against its bound. With mu small enough the solution is unique, so the
 * order only chooses among equal answers. A set valid only within rounding fails these exact
 * tests; the contact then goes to the dense box-LCP solver (kea_dense_lcp.c), as does any contact
 * whose matrix has no safe factor (two friction directions parallel, a row that touches nothing).
 * Included by kea_iterative.c alone, so that the step is inlined into the sweep, its one call
 * site. */
#ifndef KEA_CONTACT_KERNEL_H
#define KEA_CONTACT_KERNEL_H

#include "kea_block_kernels.h"

/* One active set of KeaContactActiveSets (below): friction row k free (sigk 0) or sliding at
 * sigk mu_k n. Returns 1, with the solution in out, if it is valid. */
static inline int KeaContactTry(const MeReal *A, const MeReal *r, const MeReal *mu, const int sig1, const int sig2,
                                MeReal *out)
{
    const int sig[3] = {0, sig1, sig2};
    const int free = sig1 == 0 ? 1 : (sig2 == 0 ? 2 : -1);
    MeReal an[3], x[3], wv;
    int k;
    for (k = 0; k < 3; ++k) /* the column of n with the sliding rows substituted */
        an[k] = A[k * 3 + 0] + (MeReal)sig[1] * mu[1] * A[k * 3 + 1] + (MeReal)sig[2] * mu[2] * A[k * 3 + 2];
    if (free < 0) {
        if (!(an[0] > ME_R(0.0)))
            return 0;
        x[0] = r[0] / an[0];
    } else {
        const MeReal det = an[0] * A[free * 3 + free] - A[0 * 3 + free] * an[free];
        if (!(det > ME_R(0.0)))
            return 0;
        x[0] = (r[0] * A[free * 3 + free] - A[0 * 3 + free] * r[free]) / det;
        x[free] = (an[0] * r[free] - an[free] * r[0]) / det;
        if (!(KeaFabs(x[free]) <= mu[free] * x[0]))
            return 0;
    }
    if (!(x[0] > ME_R(0.0)))
        return 0;
    for (k = 1; k < 3; ++k)
        if (sig[k] != 0)
            x[k] = (MeReal)sig[k] * mu[k] * x[0];
    for (k = 1; k < 3; ++k) {
        if (sig[k] == 0)
            continue;
        wv = A[k * 3 + 0] * x[0] + A[k * 3 + 1] * x[1] + A[k * 3 + 2] * x[2] - r[k];
        if (sig[k] > 0 ? wv > ME_R(0.0) : wv < ME_R(0.0))
            return 0; /* the row would rather slide less */
    }
    out[0] = x[0];
    out[1] = x[1];
    out[2] = x[2];
    return 1;
}

/* n = 0 is valid: w_n = A 0 - r_n = -r_n >= 0. */
static inline int KeaContactOpens(MeReal rn) { return -rn >= ME_R(0.0); }

/* One contact with friction (a normal row with bounds [0, inf) and two rows linked to it with no
 * bounds of their own), solved exactly by trying its few active sets, x = (n, f1, f2):
 *   n = 0 (the contact opens; the friction rows are pinned at 0): valid if w_n >= 0;
 *   n > 0 with each friction row free or sliding at +-mu n, not both free: the rows that are free
 *   (and the normal) have w = 0, a 1x1 or 2x2 system in n and the free friction impulse; valid if
 *   n > 0, a free friction row stays within +-mu n, and a sliding one's w pushes against its bound.
 * A is the contact's 3 x 3 matrix, r its r_loc = A x - w, mu its rows' friction coefficients.
 * The all-free case is the contact step's first try (with the block's precomputed inverse).
 * The first valid set in that fixed order is taken (with mu small enough the solution is unique).
 * Exact comparisons: a set valid only within rounding is left to the dense solver. Returns 1 if
 * solved (out holds the solution). */
static inline int KeaContactActiveSets(const MeReal *A, const MeReal *r, const MeReal *mu, MeReal *out)
{
    if (KeaContactOpens(r[0])) { /* n = 0 */
        out[0] = out[1] = out[2] = ME_R(0.0);
        return 1;
    }
    /* Each friction row free (0) or sliding (+1, -1), not both free, in this order; one call per set
     * (constants: each test its own branch, which predicts better than one loop's). */
    return KeaContactTry(A, r, mu, 0, 1, out) || KeaContactTry(A, r, mu, 0, -1, out) ||
           KeaContactTry(A, r, mu, 1, 0, out) || KeaContactTry(A, r, mu, 1, 1, out) ||
           KeaContactTry(A, r, mu, 1, -1, out) || KeaContactTry(A, r, mu, -1, 0, out) ||
           KeaContactTry(A, r, mu, -1, 1, out) || KeaContactTry(A, r, mu, -1, -1, out);
}

/* A contact's rows free now (KeaRowIsFree: its normal row's bounds [0, inf), its friction rows'
 * +-mu n: -b < x_r < b is |x_r| < b) into its record's mask, from its impulses xn in lanes; returns
 * how many of the three changed. The sweep calls it after each contact's step, which is that block's
 * last change before the next SM chance (a contact's bounds depend on its own rows only). */
static inline int KeaContactFreeRows(KeaContactConsts *k, KeaLanes xn)
{
    static const unsigned char bitsSet[8] = {0, 1, 1, 2, 1, 2, 2, 3};
    const MeReal n = KeaLanesAt(xn, 0);
    const KeaLanes bound = KeaLanesMul(KeaLanesLoadA(k->mu), KeaLanesSplat(KeaMax(n, ME_R(0.0))));
    const int now = (KeaLanesLt3(KeaLanesAbs(xn), bound) & 6) | (ME_R(0.0) < n && n < MEINFINITY);
    const int changed = bitsSet[now ^ k->freeRows];
    k->freeRows = now;
    return changed;
}

/* The contact step is the sweep's every block on a pile: inlined into the sweep, its fields stay in
 * registers across blocks; gcc's heuristics decline it (it is long), so it is asked by attribute
 * where the compiler has one. */
#if defined(__GNUC__)
#  define KEA_ALWAYS_INLINE static inline __attribute__((always_inline))
#else
#  define KEA_ALWAYS_INLINE static inline
#endif

/* The contact's block when the closed forms fail: its local LCP (r_loc in rl, w in wl, x in xb) to
 * the dense solver, then applied like a generic block's step. Size: the contact step's state handed
 * on as that step holds it (its one call site). */
static void KeaContactDense(const KeaProblem *problem, KeaIterativeWork *w, int block, KeaLanes wl,
                            const MeReal *rl, MeReal *x, KeaSweepState *sweep)
{
    const int s = w->blockStart[block];
    MeReal wb[4];
    int r;
    KeaLanesStore(wb, wl);
    for (r = 0; r < 3; ++r) {
        w->localW[r] = wb[r];
        w->localR[r] = rl[r];
        w->localX[r] = x[s + r];
        w->localLo[r] = problem->lo[s + r];
        w->localHi[r] = problem->hi[s + r];
        w->localLink[r] = r == 0 ? -1 : 0;
    }
    KeaSmallLcp(problem, w, block, sweep->maxPasses, sweep->stats);
    KeaBlockApplyDeltas(w, s, 3, x, &sweep->decrease);
}

/* The contact's r_loc = A_bb x_b - w_b (the local LCP's right-hand side, for which its w is the true
 * w), in lanes 0-2: A_bb's rows j at A + 3 j give lane r A_jr, so lane r is ((A_0r x_0 + A_1r x_1) +
 * A_2r x_2) - w_r, the scalar sums in their order; lane 3 is not used. */
static inline KeaLanes KeaContactRloc(const MeReal *A, const MeReal *xb, KeaLanes wl)
{
    const KeaLanes x0 = KeaLanesSplat(xb[0]), x1 = KeaLanesSplat(xb[1]), x2 = KeaLanesSplat(xb[2]);
    return KeaLanesSub(KeaLanesAdd(KeaLanesAdd(KeaLanesMul(KeaLanesLoad(A), x0), KeaLanesMul(KeaLanesLoad(A + 3), x1)),
                                   KeaLanesMul(KeaLanesLoad3(A + 6), x2)),
                       wl);
}

/* The contact's closed forms when not all rows are free (a quarter of the steps on a pile, more
 * where contacts slide): r_loc into rl, then the set the contact was in, then KeaContactActiveSets;
 * 1 with the solution in out if one is valid. Kept out of line, so that the common step's registers
 * are not spent on it. Size: the step's state handed on as the step holds it (its one call site). */
KEA_NOINLINE int KeaContactClosedForms(const MeReal *A, const MeReal *mu, const MeReal *xb, KeaLanes wl, MeReal *rl,
                                       MeReal *out)
{
    const MeReal was1Bound = KeaFrictionBound(mu[1], xb[0]), was2Bound = KeaFrictionBound(mu[2], xb[0]);
    const int was1 = xb[1] >= was1Bound ? 1 : (xb[1] <= -was1Bound ? -1 : 0);
    const int was2 = xb[2] >= was2Bound ? 1 : (xb[2] <= -was2Bound ? -1 : 0);
    KeaLanesStore(rl, KeaContactRloc(A, xb, wl));
    return ((was1 | was2) != 0 && xb[0] > ME_R(0.0) && KeaContactTry(A, rl, mu, was1, was2, out)) ||
           KeaContactActiveSets(A, rl, mu, out);
}

/* The contact step (top comment) for the declared contact `block` (blockContact: on two bodies, or
 * on a body and the world, whose half of the rows, exact zeros, is not computed), its three rows
 * in lanes (their constants from the contact's KeaContactConsts). Returns the block's largest row
 * residual before the step (when sweep->measure; else 0).
 * Longer than most functions here, and on purpose: it is the pile's every block step, and its
 * parts (gather, residual, all-free try, active sets, scatter) share the block's rows held in
 * locals; split into functions they would pass those locals through memory. */
KEA_ALWAYS_INLINE MeReal KeaContactBlockStep(const KeaProblem *problem, KeaIterativeWork *w, int block,
                                             MeReal *x, KeaSweepState *sweep)
{
    const int s = w->blockStart[block], onWorld = w->blockContact[block] == KEA_CONTACT_WORLD;
    KeaVel4 *v0 = &w->dv[w->body[s][0]], *v1 = &w->dv[w->body[s][1]];
    KeaContactConsts *k = KeaContactConstsOf(w->JT, s);
    const KeaLanes xl = KeaLanesLoad3(x + s);
    /* w_b = J_b dv + eps x_b - r_b */
    const KeaLanes wl = KeaLanesSub(KeaLanesAdd(KeaContactGather(&w->J[s], v0, onWorld ? NULL : v1),
                                                KeaLanesMul(KeaLanesLoadA(k->eps), xl)),
                                    KeaLanesLoadA(k->rhs));
    KeaLanes xn = xl, d;
    MeReal worst = ME_R(0.0);
    int fits = 0;
    /* the residual before the step (when the sweep still measures): normal row in [0, inf), friction
     * rows in [-mu n, mu n] */
    if (sweep->measure) {
        const MeReal *mu = problem->mu + s;
        const MeReal xb[3] = {x[s], x[s + 1], x[s + 2]}, wb[3] = {KeaLanesAt(wl, 0), KeaLanesAt(wl, 1), KeaLanesAt(wl, 2)};
        MeReal bound;
        int r;
        worst = w->diag[s] * KeaFabs(xb[0] - KeaClamp(xb[0] - wb[0] * w->invDiag[s], ME_R(0.0), MEINFINITY));
        for (r = 1; r < 3; ++r) {
            bound = KeaFrictionBound(mu[r], xb[0]);
            worst = KeaMax(worst, w->diag[s + r] *
                                      KeaFabs(xb[r] - KeaClamp(xb[r] - wb[r] * w->invDiag[s + r], -bound, bound)));
        }
    }
    /* every row free: x_b - A_bb^-1 w_b (the inverse's columns in lanes), if it keeps within the
     * bounds its own normal gives (-b <= x_r <= b is |x_r| <= b) */
    if (w->blockFactored[block]) {
        const KeaLanes t = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(KeaLanesLoadA(k->inv[0]), KeaLanesSplat(KeaLanesAt(wl, 0))),
                                                   KeaLanesMul(KeaLanesLoadA(k->inv[1]), KeaLanesSplat(KeaLanesAt(wl, 1)))),
                                       KeaLanesMul(KeaLanesLoadA(k->inv[2]), KeaLanesSplat(KeaLanesAt(wl, 2))));
        const MeReal n = KeaLanesAt(xn = KeaLanesSub(xl, t), 0);
        const KeaLanes bounds = KeaLanesMul(KeaLanesLoadA(k->mu), KeaLanesSplat(KeaMax(n, ME_R(0.0))));
        fits = n >= ME_R(0.0) && (KeaLanesLe3(KeaLanesAbs(xn), bounds) & 6) == 6;
    }
    if (!fits) {
        const MeReal *A = w->blockA + w->blockMatrix[block];
        MeReal rl[4], out[3];
        /* an open contact (n not positive) whose r_loc_n says it stays open: the closed forms' answer
         * without their call (for such a contact they skip the set it was in and try opening first) */
        if (!(x[s] > ME_R(0.0)) && KeaContactOpens(KeaLanesAt(KeaContactRloc(A, x + s, wl), 0))) {
            xn = KeaLanesSplat(ME_R(0.0));
        } else if (KeaContactClosedForms(A, problem->mu + s, x + s, wl, rl, out)) {
            xn = KeaLanesLoad3(out);
        } else { /* valid only within rounding, or no factor */
            KeaContactDense(problem, w, block, wl, rl, x, sweep);
            sweep->changed += KeaContactFreeRows(k, KeaLanesLoad3(x + s));
            return worst;
        }
    }
    d = KeaLanesSub(xn, xl);
    if (sweep->tally) { /* only the sweep after an SM step is asked how much it lowered the objective */
        const KeaLanes halfDW = KeaLanesMul(KeaLanesMul(KeaLanesSplat(ME_R(0.5)), d), wl);
        sweep->decrease = ((sweep->decrease - KeaLanesAt(halfDW, 0)) - KeaLanesAt(halfDW, 1)) - KeaLanesAt(halfDW, 2);
    }
    if (KeaLanesNonZero3(d))
        KeaContactScatter(&w->B[s], d, v0, onWorld ? NULL : v1);
    x[s] = KeaLanesAt(xn, 0); /* d_r = 0: xn_r is x_r */
    x[s + 1] = KeaLanesAt(xn, 1);
    x[s + 2] = KeaLanesAt(xn, 2);
    sweep->changed += KeaContactFreeRows(k, xn);
    return worst;
}

#endif
