/* kea_dense.c -- the dense side of Kea's direct path: forming A = J M^-1 J^T + diag(eps), and a
 * Cholesky factor of A restricted to the free rows that can grow and shrink one row at a time.
 *
 * Forming A: each row touches at most two bodies, so A_ij is non-zero only when rows i and j share a
 * body. A body -> (row, half) incidence list turns the O(n^2) pair scan into O(sum over bodies of
 * degree^2) six-term dot products, four at a time, each entry written where its first term is
 * made: only A's pattern is touched, nothing is cleared first.
 *
 * Factor updates (free set F, A_FF = L L^T, rows of L in the order of F):
 *  - append row i: solve L l = A_F,i, then d = A_ii - l.l, new row (l, sqrt(d)): O(|F|^2);
 *  - remove the row at position p: the rows below lose column p; their trailing block L33 must then
 *    satisfy L33' L33'^T = L33 L33^T + v v^T with v the removed column, a rank-one update done with
 *    Givens-like rotations (Golub & Van Loan, "Matrix Computations", sec. on updating Cholesky): O(|F|^2).
 *  Sparsity: the factor keeps each row's envelope (its first non-zero column). A row of A_FF that
 *  couples to no earlier free row before column f has L zero before f too (Cholesky fills only
 *  inside the envelope), so appends, solves and removals work on envelopes only. With rows ordered
 *  so that rows sharing bodies are near each other (kea_order.c), a chain or a tree of joints
 *  factors in time about linear in its rows instead of cubic.
 *  A pivot d below KEA_PIVOT_FLOOR * A_ii (a row dependent on the free ones, possible only when
 *  eps = 0) is raised to that floor and counted. */

#include "kea_internal.h"

/* The half h of a row as (linear, angular) 3-vectors. */
static const MeReal *KeaHalfLin(const KeaJacobianRow *row, int half) { return half ? row->lin1 : row->lin0; }
static const MeReal *KeaHalfAng(const KeaJacobianRow *row, int half) { return half ? row->ang1 : row->ang0; }

void KeaBodyIncidence(const KeaProblem *problem, int *incidence, int *start)
{
    const int n = problem->nRows, nb = problem->nBodies;
    int i, b, h;

    /* Body -> (row, half) incidence in CSR form, rows in ascending order within each body. */
    for (b = 0; b <= nb; ++b)
        start[b] = 0;
    for (i = 0; i < n; ++i)
        for (h = 0; h < 2; ++h)
            if (problem->rowBodies[i][h] >= 0)
                ++start[problem->rowBodies[i][h] + 1];
    for (b = 0; b < nb; ++b)
        start[b + 1] += start[b];
    for (i = 0; i < n; ++i)
        for (h = 0; h < 2; ++h) {
            b = problem->rowBodies[i][h];
            if (b >= 0)
                incidence[start[b]++] = 2 * i + h;
        }
    for (b = nb; b > 0; --b) /* the fill advanced each start to the next body's: shift back */
        start[b] = start[b - 1];
    start[0] = 0;
}

size_t KeaFormScratchReals(int nRows) { return (size_t)7 * (size_t)(2 * nRows + 4); }
size_t KeaFormScratchInts(int nRows) { return (size_t)2 * (size_t)(2 * nRows + 4); }

/* Body b's rows (its incidence entries q = 0 .. deg - 1): the six components of each row's half of
 * M^-1 J^T on b, one column per component (stride entries each, the pad zeroed), the row of each
 * entry and the body on the row's other half (-1: the world). Size: the three outputs are the
 * pieces of KeaFormDenseMatrix's scratch, and deg, stride their shape. */
static void KeaGatherBody(const KeaProblem *problem, const KeaJacobianRow *B, const int *entries, int deg,
                          int stride, MeReal *columns, int *rows, int *others)
{
    int q, k;
    for (q = 0; q < stride; ++q) {
        const int e = q < deg ? entries[q] : 0, h = e & 1;
        const MeReal *bl = KeaHalfLin(&B[e >> 1], h), *ba = KeaHalfAng(&B[e >> 1], h);
        for (k = 0; k < 3; ++k) {
            columns[k * stride + q] = q < deg ? bl[k] : ME_R(0.0);
            columns[(3 + k) * stride + q] = q < deg ? ba[k] : ME_R(0.0);
        }
        if (q < deg) {
            rows[q] = e >> 1;
            others[q] = problem->rowBodies[e >> 1][1 - h];
        }
    }
}

/* Whether some row touches one body through both halves: then a pair of rows gets several terms
 * from that body, and A is cleared and summed into (the general case). */
static int KeaSomeRowTouchesABodyTwice(const KeaProblem *problem)
{
    int i;
    for (i = 0; i < problem->nRows; ++i)
        if (problem->rowBodies[i][0] >= 0 && problem->rowBodies[i][0] == problem->rowBodies[i][1])
            return 1;
    return 0;
}

/* Size: the two compressed-row structures (body incidence: incidence and start; the matrix's
 * pattern: pattern and patternStart) come as the direct path's workspace holds them, with the
 * scratch for one body's rows (KeaFormScratchReals / KeaFormScratchInts). */
void KeaFormDenseMatrix(const KeaProblem *problem, const KeaJacobianRow *B, MeReal *A, const int *incidence,
                        const int *start, const int *patternStart, const int *pattern, MeReal *columns,
                        int *ints)
{
    const int n = problem->nRows, nb = problem->nBodies, twice = KeaSomeRowTouchesABodyTwice(problem);
    int i, b, p1, q, q1, q2;

    /* A_ij is the sum over the bodies rows i and j share, in body order, of J_i's half on b times
     * B_j's half on b. Usually each entry's first term is stored (as 0 + v: the bits of the sum into
     * a cleared A), so only the pattern's entries are written and nothing needs clearing first.
     * Body by body: its rows' halves of B gathered in columns, then for each of its rows the products
     * with the rows after it (v, a seventh column), then stored or added into A. */
    if (twice) {
        for (i = 0; i < n; ++i)
            for (p1 = patternStart[i]; p1 < patternStart[i + 1]; ++p1)
                A[(size_t)i * (size_t)n + (size_t)pattern[p1]] = ME_R(0.0);
    } else {
        for (i = 0; i < n; ++i) /* a row on no body has only its diagonal, which gets no term */
            if (problem->rowBodies[i][0] < 0 && problem->rowBodies[i][1] < 0)
                A[(size_t)i * (size_t)n + (size_t)i] = ME_R(0.0);
    }
    for (b = 0; b < nb; ++b) {
        const int deg = start[b + 1] - start[b], stride = (deg + 3) & ~3;
        int *rows = ints, *others = ints + stride;
        if (deg == 0)
            continue;
        KeaGatherBody(problem, B, incidence + start[b], deg, stride, columns, rows, others);
        for (q1 = 0; q1 < deg; ++q1) {
            /* J's half on b of row q1 against B's halves of rows q1 .. deg - 1, four at a time: lane
             * by lane the sums of KeaDot3(jl, bl) + KeaDot3(ja, ba) in their order */
            const int e1 = incidence[start[b] + q1], r1 = e1 >> 1, o1 = others[q1];
            const MeReal *jl = KeaHalfLin(&problem->J[r1], e1 & 1), *ja = KeaHalfAng(&problem->J[r1], e1 & 1);
            const KeaLanes l0 = KeaLanesSplat(jl[0]), l1 = KeaLanesSplat(jl[1]), l2 = KeaLanesSplat(jl[2]);
            const KeaLanes a0 = KeaLanesSplat(ja[0]), a1 = KeaLanesSplat(ja[1]), a2 = KeaLanesSplat(ja[2]);
            MeReal *Ar1 = A + (size_t)r1 * (size_t)n, *v = columns + 6 * stride;
            for (q2 = q1 & ~3; q2 < deg; q2 += 4) {
                const MeReal *c = columns + q2;
                const KeaLanes lin = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(l0, KeaLanesLoad(c)),
                                                             KeaLanesMul(l1, KeaLanesLoad(c + stride))),
                                                 KeaLanesMul(l2, KeaLanesLoad(c + 2 * stride)));
                const KeaLanes ang = KeaLanesAdd(KeaLanesAdd(KeaLanesMul(a0, KeaLanesLoad(c + 3 * stride)),
                                                             KeaLanesMul(a1, KeaLanesLoad(c + 4 * stride))),
                                                 KeaLanesMul(a2, KeaLanesLoad(c + 5 * stride)));
                KeaLanesStore(v + q2, KeaLanesAdd(lin, ang));
            }
            if (twice) {
                for (q = q1; q < deg; ++q) {
                    Ar1[rows[q]] += v[q];
                    if (q != q1) /* also covers a row touching one body through both halves */
                        A[(size_t)rows[q] * (size_t)n + (size_t)r1] += v[q];
                }
            } else if (o1 >= 0 && o1 < b) { /* rows also on o1 had their first term there */
                for (q = q1; q < deg; ++q) {
                    MeReal *Aji = A + (size_t)rows[q] * (size_t)n + (size_t)r1;
                    if (others[q] == o1) {
                        Ar1[rows[q]] += v[q];
                        if (q != q1)
                            *Aji += v[q];
                    } else {
                        Ar1[rows[q]] = ME_R(0.0) + v[q];
                        *Aji = ME_R(0.0) + v[q];
                    }
                }
            } else {
                for (q = q1; q < deg; ++q) {
                    Ar1[rows[q]] = ME_R(0.0) + v[q];
                    A[(size_t)rows[q] * (size_t)n + (size_t)r1] = ME_R(0.0) + v[q];
                }
            }
        }
    }
    if (problem->epsilon)
        for (i = 0; i < n; ++i)
            A[(size_t)i * (size_t)n + (size_t)i] += problem->epsilon[i];
}

static MeReal *KeaRow(const KeaCholesky *c, int k) { return c->L + (size_t)k * (size_t)c->ld; }

void KeaCholeskyAppend(KeaCholesky *c, const MeReal *A, int lda, int i)
{
    const int k = c->size;
    const MeReal *Ai = A + (size_t)i * (size_t)lda;
    MeReal *lk = KeaRow(c, k);
    MeReal d = Ai[i], floor = KEA_PIVOT_FLOOR * KeaMax(Ai[i], ME_R(0.0));
    int j, f = k;

    /* The row's envelope starts at its first coupling to a row already in the factor; before it,
     * L is zero (fill stays inside the envelope) and is never read. A_F,i goes
     * into row k from f on (with a pattern, only A's structural non-zeros are read: the rest of A
     * may be stale), then forward substitution L l = A_F,i in place, over the two envelopes. */
    if (c->patternStart && c->patternStart[i + 1] - c->patternStart[i] == lda) {
        /* row i couples to every row (a partition of one body): every free row is in its pattern,
         * so the loop below would place them all and find the first at 0 */
        for (j = 0; j < k; ++j)
            lk[j] = Ai[c->F[j]];
        f = 0;
    } else if (c->patternStart) { /* one pass: clear the whole row (cheaper than a second pass over
                                   * the pattern), then place A's entries and find the first */
        for (j = 0; j < k; ++j)
            lk[j] = ME_R(0.0);
        for (j = c->patternStart[i]; j < c->patternStart[i + 1]; ++j) {
            const int p = c->pos[c->pattern[j]];
            if (p >= 0) {
                lk[p] = Ai[c->pattern[j]];
                f = p < f ? p : f;
            }
        }
    } else {
        for (j = 0; j < k; ++j)
            if (Ai[c->F[j]] != ME_R(0.0)) {
                f = j;
                break;
            }
        for (j = f; j < k; ++j)
            lk[j] = Ai[c->F[j]];
    }
    for (j = f; j < k; ++j) {
        const MeReal *lj = KeaRow(c, j);
        const int m0 = f > c->first[j] ? f : c->first[j];
        lk[j] = (lk[j] - KeaDotN4(lj + m0, lk + m0, j - m0)) * c->inv[j];
        d -= lk[j] * lk[j];
    }
    if (!(d > floor)) {
        d = floor > ME_R(0.0) ? floor : ME_MIN_EPSILON;
        ++c->regularised;
    }
    lk[k] = KeaSqrt(d);
    c->inv[k] = ME_R(1.0) / lk[k];
    c->first[k] = f;
    c->F[k] = i;
    c->pos[i] = k;
    c->size = k + 1;
}

void KeaCholeskyRemove(KeaCholesky *c, int p)
{
    const int k = c->size;
    int i, j, m;

    /* Rank-one update of the trailing block with the removed column v (kept in column p as it is
     * consumed: v_i lives in L[i][p]). A row whose envelope starts after p has v_i = 0 until the
     * rotations reach its envelope; a column with v_j = 0 is an identity rotation, skipped. */
    for (i = p + 1; i < k; ++i)
        if (c->first[i] > p)
            KeaRow(c, i)[p] = ME_R(0.0);
    for (j = p + 1; j < k; ++j) {
        MeReal *lj = KeaRow(c, j);
        const MeReal ljj = lj[j], vj = lj[p];
        MeReal r, cs, sn;
        if (vj == ME_R(0.0))
            continue;
        r = KeaSqrt(ljj * ljj + vj * vj);
        cs = r / ljj;
        sn = vj / ljj;
        lj[j] = r;
        for (i = j + 1; i < k; ++i) {
            MeReal *li = KeaRow(c, i);
            MeReal lij;
            if (c->first[i] > j)
                continue; /* li[j] = 0 and li[p] = 0: the rotation leaves both zero */
            lij = (li[j] + sn * li[p]) / cs;
            li[p] = cs * li[p] - sn * lij;
            li[j] = lij;
        }
    }
    /* Drop row p and column p: rows below move up one, their columns after p move left one. */
    c->pos[c->F[p]] = -1;
    for (i = p + 1; i < k; ++i) {
        MeReal *src = KeaRow(c, i), *dst = KeaRow(c, i - 1);
        const int f = c->first[i] > p ? c->first[i] - 1 : c->first[i];
        for (m = f; m < i; ++m)
            dst[m] = src[m < p ? m : m + 1];
        c->first[i - 1] = f;
        c->inv[i - 1] = ME_R(1.0) / dst[i - 1];
        c->F[i - 1] = c->F[i];
        c->pos[c->F[i - 1]] = i - 1;
    }
    c->size = k - 1;
}

void KeaCholeskySolve(const KeaCholesky *c, MeReal *b) { KeaCholeskySolveFrom(c, b, 0); }

void KeaCholeskySolveFrom(const KeaCholesky *c, MeReal *b, int from)
{
    const int k = c->size;
    int i;
    for (i = from; i < k; ++i) { /* L y = b; y_i = 0 before the first non-zero of b */
        const MeReal *li = KeaRow(c, i);
        const int f = c->first[i];
        b[i] = (b[i] - KeaDotN4(li + f, b + f, i - f)) * c->inv[i];
    }
    for (i = k - 1; i >= 0; --i) { /* L^T x = y, column-oriented so that L is read by rows */
        const MeReal *li = KeaRow(c, i);
        const MeReal xi = b[i] * c->inv[i];
        b[i] = xi;
        KeaSubtractScaled(b + c->first[i], li + c->first[i], xi, i - c->first[i]);
    }
}

int KeaDenseFactor(int m, MeReal *G, int *perm)
{
    MeReal scale = ME_R(0.0);
    int i, j, k;
    for (i = 0; i < m * m; ++i)
        scale = KeaMax(scale, KeaFabs(G[i]));
    for (k = 0; k < m; ++k) {
        int piv = k;
        for (i = k + 1; i < m; ++i)
            if (KeaFabs(G[i * m + k]) > KeaFabs(G[piv * m + k]))
                piv = i;
        perm[k] = piv;
        if (!(KeaFabs(G[piv * m + k]) > ME_SMALL_EPSILON * scale))
            return 0;
        if (piv != k)
            for (j = 0; j < m; ++j) {
                const MeReal t = G[k * m + j];
                G[k * m + j] = G[piv * m + j];
                G[piv * m + j] = t;
            }
        for (i = k + 1; i < m; ++i) {
            const MeReal f = G[i * m + k] / G[k * m + k];
            G[i * m + k] = f; /* the multiplier, kept for the solves */
            for (j = k + 1; j < m; ++j)
                G[i * m + j] -= f * G[k * m + j];
        }
    }
    return 1;
}

void KeaDenseSolveFactored(int m, const MeReal *G, const int *perm, MeReal *b)
{
    int i, j;
    for (i = 0; i < m; ++i) { /* apply the row swaps and L (unit diagonal) */
        const MeReal t = b[perm[i]];
        b[perm[i]] = b[i];
        b[i] = t;
        for (j = i + 1; j < m; ++j)
            b[j] -= G[j * m + i] * b[i];
    }
    for (i = m - 1; i >= 0; --i) {
        MeReal s = b[i];
        for (j = i + 1; j < m; ++j)
            s -= G[i * m + j] * b[j];
        b[i] = s / G[i * m + i];
    }
}
