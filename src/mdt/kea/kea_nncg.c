/* kea_nncg.c -- nonsmooth nonlinear conjugate gradient (NNCG) on Kea's iterative path (kea_iterative.h,
 * KeaParameters.nonsmoothCg), after Silcowitz, Niebe and Erleben, "A nonsmooth nonlinear conjugate
 * gradient method for interactive contact force problems" (The Visual Computer, 2010).
 *
 * A projected Gauss-Seidel pass is a fixed-point map x -> G(x) whose fixed point is the LCP's
 * solution; its change r_k = x_{k-1} - G(x_{k-1}) plays the part of a gradient. After each pass the
 * iterate takes a Fletcher-Reeves momentum step along the passes' earlier changes:
 *   beta = |r_k|^2 / |r_{k-1}|^2  (restart, beta = 0, when it exceeds 1: the changes stopped shrinking),
 *   x_k = G(x_{k-1}) + beta p_{k-1},   p_k = beta p_{k-1} - r_k,
 * and since G(x_{k-1}) = x_{k-1} - r_k, the step is x_k = x_{k-1} + p_k. The pass G is a pair of sweeps,
 * forwards then backwards (with SM between when it runs): taken one sweep at a time, the forward
 * and backward sweeps' changes differ in size, beta exceeds 1 every other sweep and the direction
 * restarts each time (docs/kea_log.md, "NNCG"). The bodies' velocity change dv = M^-1 J^T x is linear
 * in x, so its image of p is kept beside p from the sweeps' own changes of dv: the momentum costs two
 * passes over the rows and bodies, no product with J. The momentum step may leave a row outside its
 * bounds for the next sweep to project (the block steps solve for x_b from w, whatever x_b was); the
 * solve always ends on a sweep, so the impulses it returns are within them. */
#include <string.h>

#include "kea_iterative.h"

/* Before the first sweep: remember x and dv, no direction yet. */
void KeaNncgStart(KeaIterativeWork *w, const MeReal *x, int n)
{
    memcpy(w->xPrev, x, sizeof(MeReal) * (size_t)n);
    memcpy(w->dvPrev, w->dv, sizeof(KeaVel4) * (size_t)(w->nb + 1));
    w->nncgLast = ME_R(0.0);
}

/* After a pass (a pair of sweeps) that is not the solve's last: the momentum step on x and dv; returns
 * beta (0: the direction restarted from this pass's change). */
MeReal KeaNncgStep(KeaIterativeWork *w, MeReal *restrict x, int n)
{
    MeReal *restrict xPrev = w->xPrev, *restrict p = w->nncgDir;
    KeaVel4 *restrict dv = w->dv, *restrict dvPrev = w->dvPrev, *restrict dvDir = w->dvDir;
    const int nb = w->nb;
    MeReal rr = ME_R(0.0), beta;
    int i, b, k;
    for (i = 0; i < n; ++i) {
        const MeReal d = x[i] - xPrev[i];
        rr += d * d;
    }
    beta = w->nncgLast > ME_R(0.0) ? rr / w->nncgLast : ME_R(0.0);
    w->nncgLast = rr;
    if (!(beta <= ME_R(1.0))) /* restart (a NaN too) */
        beta = ME_R(0.0);
    if (beta == ME_R(0.0)) {
        for (i = 0; i < n; ++i) {
            p[i] = x[i] - xPrev[i];
            xPrev[i] = x[i];
        }
        for (b = 0; b < nb; ++b)
            for (k = 0; k < 4; ++k) {
                dvDir[b].lin[k] = dv[b].lin[k] - dvPrev[b].lin[k];
                dvDir[b].ang[k] = dv[b].ang[k] - dvPrev[b].ang[k];
                dvPrev[b].lin[k] = dv[b].lin[k];
                dvPrev[b].ang[k] = dv[b].ang[k];
            }
        return beta;
    }
    for (i = 0; i < n; ++i) {
        p[i] = beta * p[i] + (x[i] - xPrev[i]);
        x[i] = xPrev[i] + p[i];
        xPrev[i] = x[i];
    }
    for (b = 0; b < nb; ++b)
        for (k = 0; k < 4; ++k) {
            dvDir[b].lin[k] = beta * dvDir[b].lin[k] + (dv[b].lin[k] - dvPrev[b].lin[k]);
            dvDir[b].ang[k] = beta * dvDir[b].ang[k] + (dv[b].ang[k] - dvPrev[b].ang[k]);
            dv[b].lin[k] = dvPrev[b].lin[k] + dvDir[b].lin[k];
            dv[b].ang[k] = dvPrev[b].ang[k] + dvDir[b].ang[k];
            dvPrev[b].lin[k] = dv[b].lin[k];
            dvPrev[b].ang[k] = dv[b].ang[k];
        }
    return beta;
}
