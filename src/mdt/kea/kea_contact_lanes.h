/* kea_contact_lanes.h -- the contact step (kea_contact_kernel.h) four contacts at a time, a lane
 * each, for contacts that share no body (one colour's units, kea_colour.h; the world aside, whose
 * velocity change no step writes).
 *
 * Each lane's arithmetic is the scalar step's, operation for operation: the rows' w (the bodies
 * gathered by KeaContactGather, then + eps x - r), the residual before the step and the all-free
 * try (the block's inverse applied to w, then the friction cone test). Those are plain loops over
 * [4] arrays, which the compiler turns into four-lane operations (no intrinsics, no -ffast-math:
 * each lane rounds as the scalar code does). A lane whose all-free result leaves a bound (or whose
 * block has no factor) then takes the whole scalar contact step (its active sets, the dense
 * box-LCP), and the others apply their result as that step would, lane after lane in lane order:
 * since the four contacts share no body, no lane reads what another writes, so every contact's
 * impulses and bodies get the bits the scalar step gives them taken one after the other in lane
 * order (test_kea_lanes checks it). Included by kea_iterative.c, so that both steps are inlined
 * into the split sweep. */
#ifndef KEA_CONTACT_LANES_H
#define KEA_CONTACT_LANES_H

#include "kea_contact_kernel.h"

/** Contacts per laned contact step. */
#define KEA_SWEEP_LANES 4

/* A lane's part of the laned step (KeaContactLanesStep): its rows' w [row][lane], impulses before
 * and after the all-free try, and whether that try keeps within the bounds. */
typedef struct KeaLaneTry {
    MeReal xb[3][KEA_SWEEP_LANES], wb[3][KEA_SWEEP_LANES], xn[3][KEA_SWEEP_LANES];
    int fits[KEA_SWEEP_LANES];
} KeaLaneTry;

/* The rows' w of four contacts, their residual before the step (when measure) and the all-free try,
 * lane by lane the scalar step's operations (KeaContactBlockStep). Returns the lanes' largest
 * residual. Size: the lanes' blocks and bodies as the laned step holds them (its one call site). */
KEA_ALWAYS_INLINE MeReal KeaContactLanesTry(const KeaProblem *problem, const KeaIterativeWork *w, const int *block,
                                            const int *s, KeaVel4 *const *v0, KeaVel4 *const *v1, const MeReal *x,
                                            int measure, KeaLaneTry *t)
{
    enum { L = KEA_SWEEP_LANES };
    MeReal g[L][3], e[3][L], rh[3][L], mu[3][L], dg[3][L], id[3][L], inv[9][L], worst[L], tr[3][L];
    MeReal result = ME_R(0.0);
    int factored[L], l, r, k;
    for (l = 0; l < L; ++l) {
        const MeReal *iv = w->blockInv + w->blockMatrix[block[l]];
        KeaContactGather(&w->J[s[l]], v0[l], v1[l], g[l]);
        factored[l] = w->blockFactored[block[l]];
        for (r = 0; r < 3; ++r) {
            t->xb[r][l] = x[s[l] + r];
            e[r][l] = w->eps[s[l] + r];
            rh[r][l] = problem->rhs[s[l] + r];
            mu[r][l] = problem->mu[s[l] + r];
            dg[r][l] = w->diag[s[l] + r];
            id[r][l] = w->invDiag[s[l] + r];
        }
        for (k = 0; k < 9; ++k) /* an unfactored block's inverse is not read: its lane fails */
            inv[k][l] = factored[l] ? iv[k] : ME_R(0.0);
    }
    for (r = 0; r < 3; ++r)
        for (l = 0; l < L; ++l)
            t->wb[r][l] = g[l][r] + e[r][l] * t->xb[r][l] - rh[r][l];
    if (measure) { /* normal row in [0, inf), friction rows in [-mu n, mu n] */
        for (l = 0; l < L; ++l)
            worst[l] = KeaMax(ME_R(0.0), dg[0][l] * KeaFabs(t->xb[0][l] - KeaClamp(t->xb[0][l] - t->wb[0][l] * id[0][l],
                                                                                  ME_R(0.0), MEINFINITY)));
        for (r = 1; r < 3; ++r)
            for (l = 0; l < L; ++l) {
                const MeReal bound = KeaFrictionBound(mu[r][l], t->xb[0][l]);
                worst[l] = KeaMax(worst[l], dg[r][l] * KeaFabs(t->xb[r][l] - KeaClamp(t->xb[r][l] - t->wb[r][l] * id[r][l],
                                                                                     -bound, bound)));
            }
        for (l = 0; l < L; ++l)
            result = KeaMax(result, worst[l]);
    }
    for (r = 0; r < 3; ++r)
        for (l = 0; l < L; ++l)
            tr[r][l] = (inv[r][l] * t->wb[0][l] + inv[3 + r][l] * t->wb[1][l]) + inv[6 + r][l] * t->wb[2][l];
    for (r = 0; r < 3; ++r)
        for (l = 0; l < L; ++l)
            t->xn[r][l] = t->xb[r][l] - tr[r][l];
    for (l = 0; l < L; ++l) {
        const MeReal bound = KeaFrictionBound(mu[1][l], t->xn[0][l]), bound2 = KeaFrictionBound(mu[2][l], t->xn[0][l]);
        t->fits[l] = factored[l] & (t->xn[0][l] >= ME_R(0.0)) & (t->xn[1][l] >= -bound) & (t->xn[1][l] <= bound) &
                     (t->xn[2][l] >= -bound2) & (t->xn[2][l] <= bound2);
    }
    return result;
}

/* The contact step for `count` (1 to KEA_SWEEP_LANES) declared contacts block[0 .. count - 1] that
 * share no body but the world, in lane order: their all-free tries four at a time
 * (KeaContactLanesTry, the missing lanes repeating the first contact, their results unused), then
 * lane after lane either that result applied as the scalar step applies it, or the scalar step
 * itself. Returns the largest residual measured before the steps (when sweep->measure; else 0). */
KEA_ALWAYS_INLINE MeReal KeaContactLanesStep(const KeaProblem *problem, KeaIterativeWork *w, const int *blocks,
                                             int count, MeReal *x, KeaSweepState *sweep)
{
    enum { L = KEA_SWEEP_LANES };
    KeaVel4 *v0[L], *v1[L];
    KeaLaneTry t;
    int block[L], s[L], l, r;
    MeReal worst;
    for (l = 0; l < L; ++l) {
        block[l] = blocks[l < count ? l : 0];
        s[l] = w->blockStart[block[l]];
        v0[l] = &w->dv[w->body[s[l]][0]];
        v1[l] = w->blockContact[block[l]] == KEA_CONTACT_WORLD ? NULL : &w->dv[w->body[s[l]][1]];
    }
    worst = KeaContactLanesTry(problem, w, block, s, v0, v1, x, sweep->measure, &t);
    for (l = 0; l < count; ++l) {
        MeReal d[3], xn[3];
        if (!t.fits[l]) { /* the scalar step from the start (its residual is the lane's, measured) */
            const int measure = sweep->measure;
            sweep->measure = 0;
            (void)KeaContactBlockStep(problem, w, block[l], x, sweep);
            sweep->measure = measure;
            continue;
        }
        for (r = 0; r < 3; ++r) {
            xn[r] = t.xn[r][l];
            d[r] = xn[r] - t.xb[r][l];
        }
        if (sweep->tally)
            for (r = 0; r < 3; ++r)
                sweep->decrease -= ME_R(0.5) * d[r] * t.wb[r][l];
        if (d[0] != ME_R(0.0) || d[1] != ME_R(0.0) || d[2] != ME_R(0.0))
            KeaContactScatter(&w->B[s[l]], d, v0[l], v1[l]);
        for (r = 0; r < 3; ++r)
            x[s[l] + r] = xn[r];
        sweep->changed += KeaContactFreeRows(problem->mu + s[l], xn, w->wasFree + s[l]);
    }
    return worst;
}

#endif
