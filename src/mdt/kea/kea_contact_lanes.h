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
 * and after the all-free try, and which lanes' tries keep within the bounds (bit l: lane l). */
typedef struct KeaLaneTry {
    _Alignas(16) MeReal xb[3][KEA_SWEEP_LANES];
    _Alignas(16) MeReal wb[3][KEA_SWEEP_LANES];
    _Alignas(16) MeReal xn[3][KEA_SWEEP_LANES];
    int fits;
} KeaLaneTry;

/* mid(lo, v, hi) lane by lane, as KeaClamp: min then max. */
static inline KeaLanes KeaLanesClamp(KeaLanes v, KeaLanes lo, KeaLanes hi)
{
    return KeaLanesMax(lo, KeaLanesMin(hi, v));
}

/* The rows' w of four contacts, their residual before the step (when measure) and the all-free try,
 * lane by lane the scalar step's operations (KeaContactBlockStep) in four-lane operations
 * (kea_lanes.h). Returns the lanes' largest residual. Size: the lanes' blocks and bodies as the
 * laned step holds them (its one call site). */
KEA_ALWAYS_INLINE MeReal KeaContactLanesTry(const KeaProblem *problem, const KeaIterativeWork *w, const int *block,
                                            const int *s, KeaVel4 *const *v0, KeaVel4 *const *v1, const MeReal *x,
                                            int measure, KeaLaneTry *t)
{
    enum { L = KEA_SWEEP_LANES };
    _Alignas(16) MeReal g[L][4], e[3][L], rh[3][L], mu[3][L], dg[3][L], id[3][L], inv[L][8], inv8[L], worst[L];
    const KeaLanes zero = KeaLanesSplat(ME_R(0.0));
    KeaLanes wb[3], xb[3], xn[3], a, b, c, d, m, bound, bound2;
    MeReal result = ME_R(0.0);
    int factored = 0, l, r, k;
    for (l = 0; l < L; ++l) {
        KeaContactGather(&w->J[s[l]], v0[l], v1[l], g[l]);
        g[l][3] = ME_R(0.0);
        for (r = 0; r < 3; ++r) {
            t->xb[r][l] = x[s[l] + r];
            e[r][l] = w->eps[s[l] + r];
            rh[r][l] = problem->rhs[s[l] + r];
            mu[r][l] = problem->mu[s[l] + r];
            dg[r][l] = w->diag[s[l] + r];
            id[r][l] = w->invDiag[s[l] + r];
        }
        if (w->blockFactored[block[l]]) {
            const MeReal *iv = w->blockInv + w->blockMatrix[block[l]];
            factored |= 1 << l;
            for (k = 0; k < 8; ++k)
                inv[l][k] = iv[k];
            inv8[l] = iv[8];
        } else { /* an unfactored block's inverse is not read: its lane fails */
            for (k = 0; k < 8; ++k)
                inv[l][k] = ME_R(0.0);
            inv8[l] = ME_R(0.0);
        }
    }
    /* the lanes' gathers as rows: w = g + eps x - r */
    a = KeaLanesLoadA(g[0]);
    b = KeaLanesLoadA(g[1]);
    c = KeaLanesLoadA(g[2]);
    d = KeaLanesLoadA(g[3]);
    KeaLanesTranspose4(&a, &b, &c, &d);
    wb[0] = a;
    wb[1] = b;
    wb[2] = c;
    for (r = 0; r < 3; ++r) {
        xb[r] = KeaLanesLoadA(t->xb[r]);
        wb[r] = KeaLanesSub(KeaLanesAdd(wb[r], KeaLanesMul(KeaLanesLoadA(e[r]), xb[r])), KeaLanesLoadA(rh[r]));
        KeaLanesStoreA(t->wb[r], wb[r]);
    }
    if (measure) { /* normal row in [0, inf), friction rows in [-mu n, mu n] */
        m = KeaLanesMax(zero, KeaLanesMul(KeaLanesLoadA(dg[0]),
                                          KeaLanesAbs(KeaLanesSub(xb[0], KeaLanesClamp(KeaLanesSub(xb[0], KeaLanesMul(wb[0], KeaLanesLoadA(id[0]))),
                                                                                      zero, KeaLanesSplat(MEINFINITY))))));
        for (r = 1; r < 3; ++r) {
            bound = KeaLanesMul(KeaLanesLoadA(mu[r]), KeaLanesMax(xb[0], zero));
            m = KeaLanesMax(m, KeaLanesMul(KeaLanesLoadA(dg[r]),
                                           KeaLanesAbs(KeaLanesSub(xb[r], KeaLanesClamp(KeaLanesSub(xb[r], KeaLanesMul(wb[r], KeaLanesLoadA(id[r]))),
                                                                                       KeaLanesNeg(bound), bound)))));
        }
        KeaLanesStoreA(worst, m);
        for (l = 0; l < L; ++l)
            result = KeaMax(result, worst[l]);
    }
    /* every row free: x - A^-1 w, the inverse's nine entries as lanes (two transposes and the last) */
    {
        KeaLanes i0 = KeaLanesLoadA(inv[0]), i1 = KeaLanesLoadA(inv[1]), i2 = KeaLanesLoadA(inv[2]),
                 i3 = KeaLanesLoadA(inv[3]);
        KeaLanes j0 = KeaLanesLoadA(inv[0] + 4), j1 = KeaLanesLoadA(inv[1] + 4), j2 = KeaLanesLoadA(inv[2] + 4),
                 j3 = KeaLanesLoadA(inv[3] + 4);
        KeaLanes col[9];
        KeaLanesTranspose4(&i0, &i1, &i2, &i3);
        KeaLanesTranspose4(&j0, &j1, &j2, &j3);
        col[0] = i0;
        col[1] = i1;
        col[2] = i2;
        col[3] = i3;
        col[4] = j0;
        col[5] = j1;
        col[6] = j2;
        col[7] = j3;
        col[8] = KeaLanesLoadA(inv8);
        for (r = 0; r < 3; ++r) {
            xn[r] = KeaLanesSub(xb[r], KeaLanesAdd(KeaLanesAdd(KeaLanesMul(col[r], wb[0]), KeaLanesMul(col[3 + r], wb[1])),
                                                   KeaLanesMul(col[6 + r], wb[2])));
            KeaLanesStoreA(t->xn[r], xn[r]);
        }
    }
    bound = KeaLanesMul(KeaLanesLoadA(mu[1]), KeaLanesMax(xn[0], zero));
    bound2 = KeaLanesMul(KeaLanesLoadA(mu[2]), KeaLanesMax(xn[0], zero));
    t->fits = factored & KeaLanesLeMask(zero, xn[0]) & KeaLanesLeMask(KeaLanesNeg(bound), xn[1]) &
              KeaLanesLeMask(xn[1], bound) & KeaLanesLeMask(KeaLanesNeg(bound2), xn[2]) & KeaLanesLeMask(xn[2], bound2);
    return result;
}

/* The contact step for `count` (1 to KEA_SWEEP_LANES) declared contacts block[0 .. count - 1] that
 * share no body but the world, in lane order: their rows' w, residuals and all-free tries four at a
 * time (KeaContactLanesTry, the missing lanes repeating the first contact, their results unused),
 * then lane after lane the rest of the scalar step (KeaContactFinish: the result applied, or the
 * active sets or the dense solver first). Returns the largest residual measured before the steps
 * (when sweep->measure; else 0). */
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
        MeReal xb[3], wb[3], xn[3];
        for (r = 0; r < 3; ++r) {
            xb[r] = t.xb[r][l];
            wb[r] = t.wb[r][l];
            xn[r] = t.xn[r][l];
        }
        KeaContactFinish(problem, w, block[l], xb, wb, xn, (t.fits >> l) & 1, x, sweep);
    }
    return worst;
}

#endif
