/* kea_test_problems.h -- problems and independent references for Kea's tests.
 *
 * - a deterministic random generator (xorshift64*),
 * - KtProblem: a KeaProblem together with the arrays it points into (heap owned),
 * - random partitions: bodies with random masses and inertias, rows with random Jacobians between
 *   random body pairs (or a body and the world), random softness, rhs and a mix of bilateral,
 *   unilateral, two-sided bounded and friction-linked rows,
 * - the dense A = J M^-1 J^T + diag(eps) in double, formed from a full J and block M^-1 (not from
 *   Kea's code),
 * - brute-force references: every assignment of each row to {free, at lo, at hi}, the free block
 *   solved by Gaussian elimination in double, kept when feasible and complementary; with friction
 *   links the fixed rows sit at +-mu x_link and the equations stay linear,
 * - a solve helper that sizes the workspace with KeaMemoryRequired.
 * Everything is static inline so that each test program takes what it uses. */
#ifndef KEA_TEST_PROBLEMS_H
#define KEA_TEST_PROBLEMS_H

#include <stdlib.h>
#include <string.h>

#include "mdt/kea/kea.h"
#include "mdt/kea/kea_tuning.h"

/* ---- random numbers ------------------------------------------------------------------------- */

typedef struct KtRng {
    uint64_t s;
} KtRng;

static inline KtRng kt_rng(uint64_t seed)
{
    KtRng r;
    r.s = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
    if (!r.s)
        r.s = 1;
    return r;
}

/** Uniform in [0, 1). */
static inline double kt_uniform(KtRng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return (double)((r->s * 0x2545F4914F6CDD1Dull) >> 11) * (1.0 / 9007199254740992.0);
}

static inline double kt_range(KtRng *r, double a, double b) { return a + (b - a) * kt_uniform(r); }
static inline int kt_int(KtRng *r, int n) { return (int)(kt_uniform(r) * n); }
/* Random values of mixed sign and magnitude (including exact zeros), as solver data has. */
static inline MeReal kt_mixed_value(KtRng *r)
{
    const double u = kt_uniform(r);
    if (u < 0.05)
        return ME_R(0.0);
    return (MeReal)(kt_range(r, -1.0, 1.0) * (u < 0.5 ? 1.0 : 1e3 * kt_uniform(r)));
}
/* The same bits (a "same trajectory" check: -0 and +0 differ). */
static inline int kt_same_bits(MeReal a, MeReal b) { return memcmp(&a, &b, sizeof a) == 0; }

/* ---- problems ------------------------------------------------------------------------------- */

typedef struct KtProblem {
    KeaProblem p;
    KeaBody *bodies;
    KeaJacobianRow *J;
    int (*rowBodies)[2];
    MeReal *eps, *rhs, *lo, *hi, *mu, *x0;
    int *link;
    KeaContact *contacts; /* the declared contacts (kt_declare_contacts) */
} KtProblem;

static inline void kt_alloc(KtProblem *t, int nRows, int nBodies, int withLinks)
{
    memset(t, 0, sizeof *t);
    t->bodies = (KeaBody *)calloc((size_t)(nBodies ? nBodies : 1), sizeof(KeaBody));
    t->J = (KeaJacobianRow *)calloc((size_t)(nRows ? nRows : 1), sizeof(KeaJacobianRow));
    t->rowBodies = (int(*)[2])calloc((size_t)(nRows ? nRows : 1), sizeof(int[2]));
    t->eps = (MeReal *)calloc((size_t)(nRows ? nRows : 1), sizeof(MeReal));
    t->rhs = (MeReal *)calloc((size_t)(nRows ? nRows : 1), sizeof(MeReal));
    t->lo = (MeReal *)calloc((size_t)(nRows ? nRows : 1), sizeof(MeReal));
    t->hi = (MeReal *)calloc((size_t)(nRows ? nRows : 1), sizeof(MeReal));
    t->x0 = (MeReal *)calloc((size_t)(nRows ? nRows : 1), sizeof(MeReal));
    t->p.nRows = nRows;
    t->p.nBodies = nBodies;
    t->p.bodies = t->bodies;
    t->p.J = t->J;
    t->p.rowBodies = (const int(*)[2])t->rowBodies;
    t->p.epsilon = t->eps;
    t->p.rhs = t->rhs;
    t->p.lo = t->lo;
    t->p.hi = t->hi;
    if (withLinks) {
        int i;
        t->link = (int *)calloc((size_t)(nRows ? nRows : 1), sizeof(int));
        t->mu = (MeReal *)calloc((size_t)(nRows ? nRows : 1), sizeof(MeReal));
        for (i = 0; i < nRows; ++i)
            t->link[i] = -1;
        t->p.link = t->link;
        t->p.mu = t->mu;
    }
}

static inline void kt_free(KtProblem *t)
{
    free(t->bodies);
    free(t->J);
    free(t->rowBodies);
    free(t->eps);
    free(t->rhs);
    free(t->lo);
    free(t->hi);
    free(t->x0);
    free(t->link);
    free(t->mu);
    free(t->contacts);
    memset(t, 0, sizeof *t);
}

/** A body with inverse mass 1/m and a random symmetric positive definite inverse inertia. */
static inline void kt_random_body(KtRng *r, KeaBody *b)
{
    double R[3][3], d[3], a[3], len;
    int i, j, k;
    b->invMass = (MeReal)kt_range(r, 0.5, 2.0);
    /* Random orthonormal frame (Gram-Schmidt) and principal values. */
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j)
            a[j] = kt_range(r, -1.0, 1.0);
        for (k = 0; k < i; ++k) {
            double dot = a[0] * R[k][0] + a[1] * R[k][1] + a[2] * R[k][2];
            for (j = 0; j < 3; ++j)
                a[j] -= dot * R[k][j];
        }
        len = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (j = 0; j < 3; ++j)
            R[i][j] = a[j] / len;
        d[i] = kt_range(r, 0.5, 4.0);
    }
    for (i = 0; i < 3; ++i)
        for (j = 0; j < 3; ++j) {
            double s = 0.0;
            for (k = 0; k < 3; ++k)
                s += R[k][i] * d[k] * R[k][j];
            b->invInertia[i][j] = (MeReal)s;
        }
    for (i = 0; i < 3; ++i) /* exactly symmetric after rounding */
        for (j = 0; j < i; ++j)
            b->invInertia[i][j] = b->invInertia[j][i];
}

enum { KT_BILATERAL = 0, KT_UNILATERAL = 1, KT_BOX = 2, KT_UPPER = 3 };

/** Random bounded LCP: n rows, nb bodies, softness in [epsLo, epsHi], rows of random kinds. */
static inline void kt_random_problem(KtProblem *t, KtRng *r, int n, int nb, double epsLo, double epsHi)
{
    int i, k;
    kt_alloc(t, n, nb, 0);
    for (i = 0; i < nb; ++i)
        kt_random_body(r, &t->bodies[i]);
    for (i = 0; i < n; ++i) {
        int b0 = kt_int(r, nb), b1 = kt_int(r, nb + 1) - 1; /* b1 may be the world */
        if (b1 == b0)
            b1 = KEA_WORLD;
        t->rowBodies[i][0] = b0;
        t->rowBodies[i][1] = b1;
        for (k = 0; k < 3; ++k) {
            t->J[i].lin0[k] = (MeReal)kt_range(r, -1, 1);
            t->J[i].ang0[k] = (MeReal)kt_range(r, -1, 1);
            t->J[i].lin1[k] = b1 >= 0 ? (MeReal)kt_range(r, -1, 1) : ME_R(0.0);
            t->J[i].ang1[k] = b1 >= 0 ? (MeReal)kt_range(r, -1, 1) : ME_R(0.0);
        }
        t->eps[i] = (MeReal)(epsLo * pow(epsHi / epsLo, kt_uniform(r)));
        t->rhs[i] = (MeReal)kt_range(r, -1, 1);
        switch (kt_int(r, 4)) {
        case KT_BILATERAL:
            t->lo[i] = -MEINFINITY;
            t->hi[i] = MEINFINITY;
            break;
        case KT_UNILATERAL:
            t->lo[i] = ME_R(0.0);
            t->hi[i] = MEINFINITY;
            break;
        case KT_BOX:
            t->lo[i] = (MeReal)-kt_range(r, 0.05, 0.6);
            t->hi[i] = (MeReal)kt_range(r, 0.05, 0.6);
            break;
        default:
            t->lo[i] = -MEINFINITY;
            t->hi[i] = (MeReal)kt_range(r, -0.3, 0.3);
            break;
        }
    }
}

/** Declare rows 3c, 3c + 1, 3c + 2 of every c < nContacts a contact (KeaContact): the contact step
 *  solves them. Without it (or with p.nContacts set back to 0) they are generic rows. */
static inline void kt_declare_contacts(KtProblem *t, int nContacts)
{
    int c;
    free(t->contacts);
    t->contacts = (KeaContact *)calloc((size_t)(nContacts ? nContacts : 1), sizeof(KeaContact));
    for (c = 0; c < nContacts; ++c)
        t->contacts[c].row = 3 * c;
    t->p.contacts = t->contacts;
    t->p.nContacts = nContacts;
}

/** Random contact partition: nContacts contacts, each a unilateral normal row followed by two friction
 *  rows linked to it with coefficient mu (unbounded own bounds), declared (kt_declare_contacts);
 *  plus nJoint bilateral rows. */
static inline void kt_random_contacts(KtProblem *t, KtRng *r, int nContacts, int nJoint, int nb, double mu,
                                      double eps)
{
    const int n = 3 * nContacts + nJoint;
    int c, i, k;
    kt_alloc(t, n, nb, 1);
    for (i = 0; i < nb; ++i)
        kt_random_body(r, &t->bodies[i]);
    for (i = 0; i < n; ++i) {
        int b0 = kt_int(r, nb), b1 = kt_int(r, nb + 1) - 1;
        const int contact = i < 3 * nContacts ? i / 3 : -1;
        if (contact >= 0 && i % 3) { /* friction rows act on the same bodies as their normal */
            b0 = t->rowBodies[i - i % 3][0];
            b1 = t->rowBodies[i - i % 3][1];
        } else if (b1 == b0) {
            b1 = KEA_WORLD;
        }
        t->rowBodies[i][0] = b0;
        t->rowBodies[i][1] = b1;
        for (k = 0; k < 3; ++k) {
            t->J[i].lin0[k] = (MeReal)kt_range(r, -1, 1);
            t->J[i].ang0[k] = (MeReal)kt_range(r, -1, 1);
            t->J[i].lin1[k] = b1 >= 0 ? (MeReal)kt_range(r, -1, 1) : ME_R(0.0);
            t->J[i].ang1[k] = b1 >= 0 ? (MeReal)kt_range(r, -1, 1) : ME_R(0.0);
        }
        t->eps[i] = (MeReal)eps;
        t->rhs[i] = (MeReal)kt_range(r, -1, 1);
        if (contact < 0) {
            t->lo[i] = -MEINFINITY;
            t->hi[i] = MEINFINITY;
        } else if (i % 3 == 0) {
            t->lo[i] = ME_R(0.0);
            t->hi[i] = MEINFINITY;
            t->rhs[i] = (MeReal)kt_range(r, 0.2, 1.0); /* contacts mostly pressed */
        } else {
            t->lo[i] = -MEINFINITY;
            t->hi[i] = MEINFINITY;
            t->link[i] = i - i % 3;
            t->mu[i] = (MeReal)mu;
        }
    }
    (void)c;
    kt_declare_contacts(t, nContacts);
}

/** The QP objective f(x) = 1/2 x^T A x - r^T x in double, A dense n x n (kt_dense_matrix). */
static inline double kt_objective(int n, const double *A, const MeReal *r, const MeReal *x)
{
    double f = 0.0;
    int i, j;
    for (i = 0; i < n; ++i) {
        double ax = 0.0;
        for (j = 0; j < n; ++j)
            ax += A[i * n + j] * (double)x[j];
        f += 0.5 * (double)x[i] * ax - (double)r[i] * (double)x[i];
    }
    return f;
}

/** A = J M^-1 J^T + diag(eps) in double, from a full J (n x 6 nb) and block-diagonal M^-1. */
static inline void kt_dense_matrix(const KeaProblem *p, double *A)
{
    const int n = p->nRows, nb = p->nBodies, m = 6 * nb;
    double *Jf = (double *)calloc((size_t)(n * m + 1), sizeof(double));
    double *MJ = (double *)calloc((size_t)(n * m + 1), sizeof(double));
    int i, j, b, k, h;
    for (i = 0; i < n; ++i)
        for (h = 0; h < 2; ++h) {
            b = p->rowBodies[i][h];
            if (b < 0)
                continue;
            for (k = 0; k < 3; ++k) {
                Jf[i * m + 6 * b + k] += (double)(h ? p->J[i].lin1[k] : p->J[i].lin0[k]);
                Jf[i * m + 6 * b + 3 + k] += (double)(h ? p->J[i].ang1[k] : p->J[i].ang0[k]);
            }
        }
    for (i = 0; i < n; ++i) /* MJ = (M^-1 J^T)^T row by row */
        for (b = 0; b < nb; ++b)
            for (k = 0; k < 3; ++k) {
                double s = 0.0;
                MJ[i * m + 6 * b + k] = (double)p->bodies[b].invMass * Jf[i * m + 6 * b + k];
                for (j = 0; j < 3; ++j)
                    s += (double)p->bodies[b].invInertia[k][j] * Jf[i * m + 6 * b + 3 + j];
                MJ[i * m + 6 * b + 3 + k] = s;
            }
    for (i = 0; i < n; ++i)
        for (j = 0; j < n; ++j) {
            double s = 0.0;
            for (k = 0; k < m; ++k)
                s += Jf[i * m + k] * MJ[j * m + k];
            A[i * n + j] = s + (i == j && p->epsilon ? (double)p->epsilon[i] : 0.0);
        }
    free(Jf);
    free(MJ);
}

/** Solve the m x m system M y = b (row-major, destroyed) by Gaussian elimination with partial
 *  pivoting; returns 0 when singular. */
static inline int kt_gauss(int m, double *M, double *b)
{
    int i, j, k;
    double scale = 0.0;
    for (i = 0; i < m * m; ++i)
        scale = fmax(scale, fabs(M[i]));
    for (k = 0; k < m; ++k) {
        int piv = k;
        for (i = k + 1; i < m; ++i)
            if (fabs(M[i * m + k]) > fabs(M[piv * m + k]))
                piv = i;
        if (!(fabs(M[piv * m + k]) > 1e-13 * scale))
            return 0;
        if (piv != k) {
            for (j = 0; j < m; ++j) {
                double t = M[k * m + j];
                M[k * m + j] = M[piv * m + j];
                M[piv * m + j] = t;
            }
            double t = b[k];
            b[k] = b[piv];
            b[piv] = t;
        }
        for (i = k + 1; i < m; ++i) {
            double f = M[i * m + k] / M[k * m + k];
            for (j = k; j < m; ++j)
                M[i * m + j] -= f * M[k * m + j];
            b[i] -= f * b[k];
        }
    }
    for (i = m - 1; i >= 0; --i) {
        double s = b[i];
        for (j = i + 1; j < m; ++j)
            s -= M[i * m + j] * b[j];
        b[i] = s / M[i * m + i];
    }
    return 1;
}

static inline int kt_is_inf(MeReal bound) { return !(bound > -MEINFINITY && bound < MEINFINITY); }

/** Brute-force solution of the box LCP (with friction links when p->link): tries all 3^n
 *  assignments. Writes the first solution found to x and returns how many assignments satisfied
 *  feasibility and complementarity within tol (scaled by 1 + |r|). n <= 10. */
static inline int kt_brute_force(const KeaProblem *p, double *x, double tol)
{
    const int n = p->nRows;
    double *A = (double *)malloc(sizeof(double) * (size_t)(n * n + 1));
    double *M = (double *)malloc(sizeof(double) * (size_t)(n * n + 1));
    double *y = (double *)malloc(sizeof(double) * (size_t)(n + 1));
    int *s = (int *)malloc(sizeof(int) * (size_t)(n + 1));
    double rScale = 1.0;
    long code, total = 1;
    int i, j, found = 0;
    kt_dense_matrix(p, A);
    for (i = 0; i < n; ++i) {
        total *= 3;
        rScale = fmax(rScale, fabs((double)p->rhs[i]));
    }
    tol *= rScale;
    for (code = 0; code < total; ++code) {
        long c = code;
        int ok = 1;
        for (i = 0; i < n; ++i) {
            s[i] = (int)(c % 3); /* 0 free, 1 at lo, 2 at hi */
            c /= 3;
        }
        /* Equations: free rows A_i x = r_i; fixed rows x_i = bound (or x_i -+ mu x_link = 0). */
        for (i = 0; i < n && ok; ++i) {
            const int linked = p->link && p->link[i] >= 0;
            for (j = 0; j < n; ++j)
                M[i * n + j] = 0.0;
            if (s[i] == 0) {
                for (j = 0; j < n; ++j)
                    M[i * n + j] = A[i * n + j];
                y[i] = (double)p->rhs[i];
            } else if (linked) {
                M[i * n + i] = 1.0;
                M[i * n + p->link[i]] = (s[i] == 1 ? 1.0 : -1.0) * (double)p->mu[i];
                y[i] = 0.0;
            } else {
                MeReal bound = s[i] == 1 ? p->lo[i] : p->hi[i];
                if (kt_is_inf(bound) || (s[i] == 2 && p->lo[i] == p->hi[i]))
                    ok = 0;
                M[i * n + i] = 1.0;
                y[i] = (double)bound;
            }
        }
        if (!ok || !kt_gauss(n, M, y))
            continue;
        for (i = 0; i < n && ok; ++i) {
            double lo = (double)p->lo[i], hi = (double)p->hi[i], w = -(double)p->rhs[i];
            if (p->link && p->link[i] >= 0) {
                double b = (double)p->mu[i] * fmax(y[p->link[i]], 0.0);
                lo = -b;
                hi = b;
            }
            for (j = 0; j < n; ++j)
                w += A[i * n + j] * y[j];
            if (y[i] < lo - tol || y[i] > hi + tol)
                ok = 0;
            else if (s[i] == 1 && w < -tol)
                ok = 0;
            else if (s[i] == 2 && w > tol)
                ok = 0;
        }
        if (!ok)
            continue;
        if (!found)
            for (i = 0; i < n; ++i)
                x[i] = y[i];
        ++found;
    }
    free(A);
    free(M);
    free(y);
    free(s);
    return found;
}


/* ---- a column of boxes ---------------------------------------------------------------------- */

static inline void kt_cross(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/** Contact row between body0 (upper, centre c0) and body1 (lower, centre c1, or the world) at point p
 *  along unit direction d: J = (d, (p - c0) x d | -d, -(p - c1) x d). */
static inline void kt_contact_row(KeaJacobianRow *J, const double p[3], const double c0[3], const double *c1,
                                  const double d[3])
{
    double r[3], rxd[3];
    int k;
    memset(J, 0, sizeof *J);
    for (k = 0; k < 3; ++k)
        r[k] = p[k] - c0[k];
    kt_cross(r, d, rxd);
    for (k = 0; k < 3; ++k) {
        J->lin0[k] = (MeReal)d[k];
        J->ang0[k] = (MeReal)rxd[k];
    }
    if (c1) {
        for (k = 0; k < 3; ++k)
            r[k] = p[k] - c1[k];
        kt_cross(r, d, rxd);
        for (k = 0; k < 3; ++k) {
            J->lin1[k] = (MeReal)-d[k];
            J->ang1[k] = (MeReal)-rxd[k];
        }
    }
}

/** A column of nBoxes unit cubes (mass m, side 1) standing on the ground (z up): interface k carries
 *  4 corner contacts, each a normal row (0, inf) and two friction rows linked to it with mu (declared
 *  contacts, kt_declare_contacts). Box k's
 *  centre is at z = k + 1/2. Rows in order: interface by interface from the ground up, each contact's
 *  normal then its x and y friction rows. Softness eps on every row. The rhs is left at 0: set it
 *  with kt_set_rhs_from_velocities. */
static inline void kt_column(KtProblem *t, int nBoxes, double m, double mu, double eps)
{
    const double corners[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
    const double dirs[3][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
    int b, k, c, d, row = 0;
    kt_alloc(t, 12 * nBoxes, nBoxes, 1);
    for (b = 0; b < nBoxes; ++b) {
        memset(&t->bodies[b], 0, sizeof t->bodies[b]);
        t->bodies[b].invMass = (MeReal)(1.0 / m);
        for (k = 0; k < 3; ++k)
            t->bodies[b].invInertia[k][k] = (MeReal)(6.0 / m); /* I = m (1 + 1) / 12 */
    }
    for (b = 0; b < nBoxes; ++b) { /* interface b: below box b */
        const double c0[3] = {0, 0, b + 0.5}, c1[3] = {0, 0, b - 0.5};
        for (c = 0; c < 4; ++c) {
            const double p[3] = {corners[c][0], corners[c][1], (double)b};
            const int normal = row;
            for (d = 0; d < 3; ++d, ++row) {
                kt_contact_row(&t->J[row], p, c0, b > 0 ? c1 : NULL, dirs[d]);
                t->rowBodies[row][0] = b;
                t->rowBodies[row][1] = b > 0 ? b - 1 : KEA_WORLD;
                t->eps[row] = (MeReal)eps;
                if (d == 0) {
                    t->lo[row] = ME_R(0.0);
                    t->hi[row] = MEINFINITY;
                } else {
                    t->lo[row] = -MEINFINITY;
                    t->hi[row] = MEINFINITY;
                    t->link[row] = normal;
                    t->mu[row] = (MeReal)mu;
                }
            }
        }
    }
    kt_declare_contacts(t, 4 * nBoxes);
}

/** r = -J (v + h a) for body velocities v (6 per body: linear, angular) and a uniform acceleration
 *  a (gravity) over the step h: the target is zero constraint velocity after the step. */
static inline void kt_set_rhs_from_velocities(KtProblem *t, const double *v, double h, const double a[3])
{
    int i, hf, k;
    for (i = 0; i < t->p.nRows; ++i) {
        double s = 0.0;
        for (hf = 0; hf < 2; ++hf) {
            const int b = t->rowBodies[i][hf];
            if (b < 0)
                continue;
            for (k = 0; k < 3; ++k) {
                s += (double)(hf ? t->J[i].lin1[k] : t->J[i].lin0[k]) * (v[6 * b + k] + h * a[k]);
                s += (double)(hf ? t->J[i].ang1[k] : t->J[i].ang0[k]) * v[6 * b + 3 + k];
            }
        }
        t->rhs[i] = (MeReal)-s;
    }
}

/* ---- solving -------------------------------------------------------------------------------- */

/** KeaSolve with a heap workspace of exactly KeaMemoryRequired bytes. */
static inline KeaStatus kt_solve(const KeaProblem *p, const KeaParameters *params, MeReal *x,
                                 KeaBodyVelocity *dv, KeaStats *stats)
{
    const size_t bytes = KeaMemoryRequired(p->nRows, p->nBodies, KeaSelectPath(p->nRows, params));
    void *work = malloc(bytes);
    KeaStatus st = KeaSolve(p, params, work, bytes, x, dv, stats);
    free(work);
    return st;
}

/** Parameters for a path with everything else at defaults. */
static inline KeaParameters kt_params(KeaPath path)
{
    KeaParameters prm;
    KeaParametersDefault(&prm);
    prm.path = path;
    return prm;
}

static inline double kt_max_abs_diff(const MeReal *a, const double *b, int n)
{
    double e = 0.0;
    int i;
    for (i = 0; i < n; ++i)
        e = fmax(e, fabs((double)a[i] - b[i]));
    return e;
}

static inline double kt_max_abs(const double *a, int n)
{
    double e = 0.0;
    int i;
    for (i = 0; i < n; ++i)
        e = fmax(e, fabs(a[i]));
    return e;
}

#endif /* KEA_TEST_PROBLEMS_H */
