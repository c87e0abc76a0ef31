/* kea_deflation.c -- a coarse correction (deflation) on Kea's iterative path (kea_iterative.h,
 * KeaParameters.deflation): after each pair of sweeps (and the SM step between, when it runs), the
 * QP objective f(x) = 1/2 x^T A x - r^T x is minimised exactly over x + sum_k alpha_k d_k for a few
 * directions d_k that the solve has made itself:
 *   d_0 = the last pass's change of x,
 *   d_1 = the change of the pass before (after its own correction: NNCG's direction p),
 *   d_2 = the change since the warm start.
 * The slow mode of a stack (a wall's sway) is global and moves little from one pass to the next, so
 * the passes' changes hold it; a sweep only moves it a neighbour at a time. The step is NNCG's
 * momentum (kea_nncg.c) with its length found, not guessed, and with a third direction.
 *
 * Each direction is restricted to the rows free now (a row at a bound takes no part: its entries
 * are taken out of the direction and, by a scatter of those rows, out of its image). The k x k
 * system (k <= 3) needs no product with J: each d_k's image dvD_k = M^-1 J^T d_k is the change of dv
 * that came with it (kept beside x, as NNCG keeps it), so with J^T d_k = M dvD_k
 *   g_k = d_k . w = dvD_k^T M dv + sum_i d_k,i (eps_i x_i - r_i)     (w = J dv + eps x - r),
 *   G_kl = d_k^T A d_l = dvD_k^T M dvD_l + sum_i eps_i d_k,i d_l,i,
 * one pass over the rows and one over the bodies; alpha solves G alpha = -g (directions that add
 * nothing new dropped at the factor's pivots). The step u = D alpha is clipped to the bounds as
 * they stand (friction bounds from the normal rows' x, frozen as SM freezes them); the clipped part
 * c = s - u of the step s is on few rows, so the objective's change
 *   f(x + s) - f(x) = alpha.g + 1/2 alpha^T G alpha + c.(w + A u) + 1/2 c^T A c
 * costs a scatter and gathers of those rows only. As SM's trial, a step that does not lower f is
 * halved (KEA_SM_LINE_SEARCH_TRIES times) and otherwise dropped, so the correction never makes the QP
 * worse. The accepted step moves dv by a scatter of its rows, not by the images (whose rounding
 * would add up over a long solve). It runs on the solve's own thread in a split solve (serial
 * passes: the same bits for any worker count). Figures: bench/RESULTS.md, "defl". */
#include <string.h>

#include "kea_iterative.h"

enum { KEA_DEFLATION_DIRECTIONS = 3 };

/* A direction's pivot below this fraction of its diagonal adds nothing new: dropped. */
#define KEA_DEFLATION_DROP ME_R(1e-6)

/* Row i of the directions, of their images under A and of w (a clipped row of the trial). */
typedef struct KeaDeflationRow {
    MeReal d[KEA_DEFLATION_DIRECTIONS];  /* d_k,i */
    MeReal Ad[KEA_DEFLATION_DIRECTIONS]; /* (A d_k)_i */
    MeReal w;                            /* w_i at x */
} KeaDeflationRow;

/* Row i's entries of the directions, their images and w (the images by differences of dv: d_0's is
 * dv - dvPrev, d_1's dvDir, d_2's dv - dvStart). */
static void KeaDeflationRowOf(const KeaProblem *problem, const KeaIterativeWork *w, const MeReal *x, int i,
                              KeaDeflationRow *row)
{
    const KeaJacobianRow *J = &w->J[i];
    const int b0 = w->body[i][0], b1 = w->body[i][1];
    const MeReal eps = w->eps[i];
    const MeReal jv = KeaRowVel4(J, &w->dv[b0], &w->dv[b1]);
    row->d[0] = x[i] - w->xPrev[i];
    row->d[1] = w->nncgDir[i];
    row->d[2] = x[i] - w->xStart[i];
    row->Ad[0] = jv - KeaRowVel4(J, &w->dvPrev[b0], &w->dvPrev[b1]) + eps * row->d[0];
    row->Ad[1] = KeaRowVel4(J, &w->dvDir[b0], &w->dvDir[b1]) + eps * row->d[1];
    row->Ad[2] = jv - KeaRowVel4(J, &w->dvStart[b0], &w->dvStart[b1]) + eps * row->d[2];
    row->w = jv + eps * x[i] - problem->rhs[i];
}

/* alpha solving G alpha = -g (G row-major, 3 x 3) over the first k directions by Cholesky, a direction whose pivot is
 * not above KEA_DEFLATION_DROP of its diagonal left out (its alpha 0); returns the directions kept. */
int KeaDeflationSolve(int k, const MeReal G[9], const MeReal g[3], MeReal alpha[3])
{
    MeReal L[3][3] = {{0}}, y[3] = {0};
    int keep[3] = {0}, i, j, m, kept = 0;
    for (i = 0; i < k; ++i) {
        MeReal pivot = G[3 * i + i];
        for (m = 0; m < i; ++m)
            pivot -= L[i][m] * L[i][m];
        alpha[i] = ME_R(0.0);
        if (!(pivot > KEA_DEFLATION_DROP * G[3 * i + i]) || !(G[3 * i + i] > ME_R(0.0)))
            continue; /* L[i][*] stays 0 */
        keep[i] = 1;
        ++kept;
        L[i][i] = KeaSqrt(pivot);
        for (j = i + 1; j < k; ++j) {
            MeReal s = G[3 * j + i];
            for (m = 0; m < i; ++m)
                s -= L[j][m] * L[i][m];
            L[j][i] = s / L[i][i];
        }
    }
    for (i = 0; i < k; ++i) /* L y = -g */
        if (keep[i]) {
            MeReal s = -g[i];
            for (m = 0; m < i; ++m)
                s -= L[i][m] * y[m];
            y[i] = s / L[i][i];
        }
    for (i = k - 1; i >= 0; --i) /* L^T alpha = y */
        if (keep[i]) {
            MeReal s = y[i];
            for (m = i + 1; m < k; ++m)
                s -= L[m][i] * alpha[m];
            alpha[i] = s / L[i][i];
        }
    for (i = k; i < KEA_DEFLATION_DIRECTIONS; ++i)
        alpha[i] = ME_R(0.0);
    return kept;
}

/* The trial's new x, s = mid(lo, x + u, hi) with u = D alpha, and its clipped part c = (s - x) - u
 * (0 where x + u is within the bounds) over n rows, element by element so that the compiler runs it
 * four lanes at a time; returns whether any row was clipped. Size: separate restrict arrays, so
 * that the loop is vectorised. */
static int KeaDeflationClamp(int n, const MeReal alpha[3], const MeReal *restrict x, const MeReal *restrict xPrev,
                             const MeReal *restrict p, const MeReal *restrict xStart, const MeReal *restrict lo,
                             const MeReal *restrict hi, MeReal *restrict s, MeReal *restrict c)
{
    const MeReal a0 = alpha[0], a1 = alpha[1], a2 = alpha[2];
    int i, clipped = 0;
    for (i = 0; i < n; ++i) {
        const MeReal u = (a0 * (x[i] - xPrev[i]) + a1 * p[i]) + a2 * (x[i] - xStart[i]);
        const MeReal v = x[i] + u, sv = KeaClamp(v, lo[i], hi[i]);
        s[i] = sv;
        c[i] = sv != v ? (sv - x[i]) - u : ME_R(0.0);
        clipped |= sv != v;
    }
    return clipped;
}

/* The trial x + s = mid(lo, x + D alpha, hi) (the bounds as KeaDeflationRows stored them) into SM's
 * z (the new x itself, within the bounds to the bit), the clipped part c into SM's q, *clipped whether
 * any; returns f(x + s) - f(x) (top comment) from the model's alpha.g + 1/2 alpha^T G alpha (dvTmp
 * is its scratch for M^-1 J^T c). */
static MeReal KeaDeflationTrial(const KeaProblem *problem, KeaIterativeWork *w, const MeReal *x,
                                const MeReal alpha[3], MeReal model, int *clipped)
{
    const int n = problem->nRows;
    MeReal cross = ME_R(0.0), cAc = ME_R(0.0), *s = w->z, *c = w->q; /* SM's scratch */
    int i;
    *clipped = KeaDeflationClamp(n, alpha, x, w->xPrev, w->nncgDir, w->xStart, w->lo, w->hi, s, c);
    if (!*clipped)
        return model;
    KeaVel4Clear(w->dvTmp, w->nb + 1);
    for (i = 0; i < n; ++i)
        if (c[i] != ME_R(0.0)) {
            KeaDeflationRow row;
            KeaDeflationRowOf(problem, w, x, i, &row);
            cross += c[i] * (row.w + ((alpha[0] * row.Ad[0] + alpha[1] * row.Ad[1]) + alpha[2] * row.Ad[2]));
            KeaRowApply4(&w->B[i], c[i], &w->dvTmp[w->body[i][0]], &w->dvTmp[w->body[i][1]]);
        }
    for (i = 0; i < n; ++i)
        if (c[i] != ME_R(0.0))
            cAc += c[i] * (KeaRowVel4(&w->J[i], &w->dvTmp[w->body[i][0]], &w->dvTmp[w->body[i][1]]) +
                           w->eps[i] * c[i]);
    return model + cross + ME_R(0.5) * cAc;
}

/* Before the first sweep: remember x and dv (the warm start's, and the pass's start), no direction. */
void KeaDeflationStart(KeaIterativeWork *w, const MeReal *x, int n)
{
    memcpy(w->xStart, x, sizeof(MeReal) * (size_t)n);
    memcpy(w->dvStart, w->dv, sizeof(KeaVel4) * (size_t)(w->nb + 1));
    memcpy(w->xPrev, x, sizeof(MeReal) * (size_t)n);
    memcpy(w->dvPrev, w->dv, sizeof(KeaVel4) * (size_t)(w->nb + 1));
    memset(w->nncgDir, 0, sizeof(MeReal) * (size_t)n);
    KeaVel4Clear(w->dvDir, w->nb + 1);
    w->nncgLast = ME_R(0.0);
}

/* Apply the accepted step: dv += M^-1 J^T (s - x) by a scatter of the rows that moved, then x = the
 * trial's (s); then the pass's whole change becomes d_1 for the next, and x, dv the next pass's
 * start. The images of the directions are exact only up to rounding, and a long solve's steps (with
 * alpha of a few) would let dv drift from x by the sum of those errors, so the step's own rows are
 * scattered. s NULL: nothing applied. */
static void KeaDeflationApply(const KeaProblem *problem, KeaIterativeWork *w, MeReal *x, const MeReal *s)
{
    const int n = problem->nRows, nb = w->nb;
    MeReal *restrict xPrev = w->xPrev, *restrict p = w->nncgDir;
    int i, b, k;
    if (s) {
        for (i = 0; i < n; ++i)
            if (s[i] != x[i])
                KeaRowApply4(&w->B[i], s[i] - x[i], &w->dv[w->body[i][0]], &w->dv[w->body[i][1]]);
        memcpy(x, s, sizeof(MeReal) * (size_t)n); /* s is SM's scratch, apart from x */
    }
    for (i = 0; i < n; ++i) {
        p[i] = x[i] - xPrev[i];
        xPrev[i] = x[i];
    }
    for (b = 0; b < nb; ++b)
        for (k = 0; k < 4; ++k) {
            w->dvDir[b].lin[k] = w->dv[b].lin[k] - w->dvPrev[b].lin[k];
            w->dvDir[b].ang[k] = w->dv[b].ang[k] - w->dvPrev[b].ang[k];
            w->dvPrev[b].lin[k] = w->dv[b].lin[k];
            w->dvPrev[b].ang[k] = w->dv[b].ang[k];
        }
}

/* Restrict the directions to the rows free now (KeaRowIsFree): a row at a bound (or fixed) takes no
 * part, so its entries are taken out of each direction and out of its image (xPrev, xStart set to x
 * there and dvPrev, dvStart moved by B_i times the change; d_1 zeroed there and dvDir moved back):
 * a scatter only for the rows at a bound that some direction moves. Adds the rows' terms of g and
 * G: g_k += sum_i d_k,i (eps_i x_i - r_i), G_kl += sum_i eps_i d_k,i d_l,i (lower triangle). */
static void KeaDeflationRows(const KeaProblem *problem, KeaIterativeWork *w, const MeReal *x, MeReal G[9], MeReal g[3])
{
    const int n = problem->nRows;
    int i;
    for (i = 0; i < n; ++i) {
        MeReal lo, hi, d0, d1, d2, e;
        KeaRowBoundsInline(problem, x, i, &lo, &hi);
        w->lo[i] = lo; /* for the trial (SM's arrays: free between SM steps) */
        w->hi[i] = hi;
        if (!KeaRowIsFree(w, i, x[i], lo, hi)) {
            KeaVel4 *v0 = &w->dvPrev[w->body[i][0]], *v1 = &w->dvPrev[w->body[i][1]];
            if (x[i] != w->xPrev[i])
                KeaRowApply4(&w->B[i], x[i] - w->xPrev[i], v0, v1);
            if (x[i] != w->xStart[i])
                KeaRowApply4(&w->B[i], x[i] - w->xStart[i], &w->dvStart[w->body[i][0]], &w->dvStart[w->body[i][1]]);
            if (w->nncgDir[i] != ME_R(0.0))
                KeaRowApply4(&w->B[i], -w->nncgDir[i], &w->dvDir[w->body[i][0]], &w->dvDir[w->body[i][1]]);
            w->xPrev[i] = w->xStart[i] = x[i];
            w->nncgDir[i] = ME_R(0.0);
            continue;
        }
        d0 = x[i] - w->xPrev[i];
        d1 = w->nncgDir[i];
        d2 = x[i] - w->xStart[i];
        e = w->eps[i];
        g[0] += d0 * (e * x[i] - problem->rhs[i]);
        g[1] += d1 * (e * x[i] - problem->rhs[i]);
        g[2] += d2 * (e * x[i] - problem->rhs[i]);
        G[0] += e * d0 * d0;
        G[3] += e * d1 * d0;
        G[4] += e * d1 * d1;
        G[6] += e * d2 * d0;
        G[7] += e * d2 * d1;
        G[8] += e * d2 * d2;
    }
}

/* The bodies' terms: J^T d_k = M (M^-1 J^T d_k), so d_k^T J dv = dvD_k^T M dv and d_k^T J M^-1 J^T d_l =
 * dvD_k^T M dvD_l, each body's M from its inverse (a movable body whose inverse inertia is
 * singular: returns 0, no correction). The world's and immovable bodies' dvD are 0. */
static int KeaDeflationBodies(const KeaProblem *problem, const KeaIterativeWork *w, MeReal G[9], MeReal g[3])
{
    int b, k, l, m;
    for (b = 0; b < problem->nBodies; ++b) {
        const KeaBody *body = &problem->bodies[b];
        const MeReal(*Ii)[3] = body->invInertia;
        MeReal I[3][3], det, D[3][6], MD[3][6], v[6];
        if (body->invMass == ME_R(0.0))
            continue;
        I[0][0] = Ii[1][1] * Ii[2][2] - Ii[1][2] * Ii[2][1];
        I[0][1] = Ii[0][2] * Ii[2][1] - Ii[0][1] * Ii[2][2];
        I[0][2] = Ii[0][1] * Ii[1][2] - Ii[0][2] * Ii[1][1];
        det = Ii[0][0] * I[0][0] + Ii[1][0] * I[0][1] + Ii[2][0] * I[0][2];
        if (!(det > ME_R(0.0)))
            return 0;
        I[1][0] = Ii[1][2] * Ii[2][0] - Ii[1][0] * Ii[2][2];
        I[1][1] = Ii[0][0] * Ii[2][2] - Ii[0][2] * Ii[2][0];
        I[1][2] = Ii[0][2] * Ii[1][0] - Ii[0][0] * Ii[1][2];
        I[2][0] = Ii[1][0] * Ii[2][1] - Ii[1][1] * Ii[2][0];
        I[2][1] = Ii[0][1] * Ii[2][0] - Ii[0][0] * Ii[2][1];
        I[2][2] = Ii[0][0] * Ii[1][1] - Ii[0][1] * Ii[1][0];
        for (m = 0; m < 3; ++m) {
            D[0][m] = w->dv[b].lin[m] - w->dvPrev[b].lin[m];
            D[0][3 + m] = w->dv[b].ang[m] - w->dvPrev[b].ang[m];
            D[1][m] = w->dvDir[b].lin[m];
            D[1][3 + m] = w->dvDir[b].ang[m];
            D[2][m] = w->dv[b].lin[m] - w->dvStart[b].lin[m];
            D[2][3 + m] = w->dv[b].ang[m] - w->dvStart[b].ang[m];
            v[m] = w->dv[b].lin[m];
            v[3 + m] = w->dv[b].ang[m];
        }
        for (k = 0; k < 3; ++k)
            for (m = 0; m < 3; ++m) {
                MD[k][m] = D[k][m] / body->invMass;
                MD[k][3 + m] = (I[m][0] * D[k][3] + I[m][1] * D[k][4] + I[m][2] * D[k][5]) / det;
            }
        for (k = 0; k < 3; ++k) {
            MeReal gk = ME_R(0.0);
            for (m = 0; m < 6; ++m)
                gk += MD[k][m] * v[m];
            g[k] += gk;
            for (l = 0; l <= k; ++l) {
                MeReal Gkl = ME_R(0.0);
                for (m = 0; m < 6; ++m)
                    Gkl += MD[k][m] * D[l][m];
                G[3 * k + l] += Gkl;
            }
        }
    }
    return 1;
}

/* After a pass that is not the solve's last: the coarse correction; returns the objective's change
 * (< 0) or 0 when no step lowered it (x and dv then as the pass left them). */
MeReal KeaDeflationStep(const KeaProblem *problem, KeaIterativeWork *w, MeReal *x)
{
    const int k = w->nncgLast > ME_R(0.0) ? KEA_DEFLATION_DIRECTIONS : 1; /* the first pass: d_0 alone */
    MeReal G[9] = {0}, g[3] = {0}, alpha[3] = {0}, scale, df = ME_R(0.0);
    int a, b, tries;
    KeaDeflationRows(problem, w, x, G, g);
    w->nncgLast = ME_R(1.0); /* a direction d_1 exists from the next pass on */
    if (KeaDeflationBodies(problem, w, G, g)) {
        for (a = 0; a < 3; ++a)
            for (b = a + 1; b < 3; ++b)
                G[3 * a + b] = G[3 * b + a];
        if (KeaDeflationSolve(k, G, g, alpha) > 0) {
            int clipped;
            for (tries = 0, scale = ME_R(1.0); tries < KEA_SM_LINE_SEARCH_TRIES; ++tries, scale *= ME_R(0.5)) {
                MeReal model = ME_R(0.0), t[3];
                for (a = 0; a < KEA_DEFLATION_DIRECTIONS; ++a)
                    t[a] = scale * alpha[a];
                for (a = 0; a < k; ++a) {
                    MeReal Gt = ME_R(0.0);
                    for (b = 0; b < k; ++b)
                        Gt += G[3 * a + b] * t[b];
                    model += t[a] * (g[a] + ME_R(0.5) * Gt);
                }
                df = KeaDeflationTrial(problem, w, x, t, model, &clipped);
                if (df < ME_R(0.0)) {
                    KeaDeflationApply(problem, w, x, w->z); /* z: the trial's x */
                    return df;
                }
            }
        }
    }
    KeaDeflationApply(problem, w, x, NULL);
    return ME_R(0.0);
}
