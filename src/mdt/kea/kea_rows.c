/* kea_rows.c -- per-row quantities shared by both of Kea's paths: M^-1 J^T of a row, the effective
 * (friction-linked) bounds, Delta v = M^-1 J^T x, and the natural-map residual that both paths report.
 * Everything here is O(rows + bodies) and needs no workspace. */
#include "kea_internal.h"
#include "kea_lanes.h"

static void KeaInvInertiaTimes(const KeaBody *body, const MeReal *v, MeReal *out)
{
    int k;
    for (k = 0; k < 3; ++k)
        out[k] = KeaDot3(body->invInertia[k], v);
}

void KeaBodyColumnsFill(const KeaProblem *problem, KeaBodyColumns *out)
{
    int b;
    for (b = 0; b < problem->nBodies; ++b)
        KeaBodyColumnsOf(&problem->bodies[b], &out[b]);
}

MeReal KeaRowInvMassJT(const KeaProblem *problem, int i, KeaJacobianRow *B)
{
    const int *b = problem->rowBodies[i];
    KeaBodyColumns c0, c1;
    if (b[0] >= 0)
        KeaBodyColumnsOf(&problem->bodies[b[0]], &c0);
    if (b[1] >= 0)
        KeaBodyColumnsOf(&problem->bodies[b[1]], &c1);
    return KeaRowInvMassJTOf(&problem->J[i], b[0] >= 0 ? &c0 : NULL, b[1] >= 0 ? &c1 : NULL,
                             problem->epsilon ? problem->epsilon[i] : ME_R(0.0), B);
}

/* The sums run in a local array (no aliasing with M or in for the compiler); the row counts of
 * a constraint's block (1 to 6: a fixed joint has 6) have their own instances with a constant trip
 * count, which the compiler unrolls and vectorises; every instance gives the same bits. */
static inline void KeaColumnsSized(const int m, const int nc, const MeReal *M, const MeReal *in, MeReal *out)
{
    MeReal acc[KEA_MAX_BLOCK_ROWS];
    int r, c;
    for (r = 0; r < m; ++r)
        acc[r] = ME_R(0.0);
    for (c = 0; c < nc; ++c) {
        const MeReal v = in[c];
        const MeReal *column = M + c * m;
        for (r = 0; r < m; ++r)
            acc[r] += column[r] * v;
    }
    for (r = 0; r < m; ++r)
        out[r] = acc[r];
}

static inline void KeaColumnsDispatch(int m, int nc, const MeReal *M, const MeReal *in, MeReal *out)
{
    switch (m) { /* a constraint's block sizes, each with a constant row count */
    case 1: KeaColumnsSized(1, nc, M, in, out); break;
    case 2: KeaColumnsSized(2, nc, M, in, out); break;
    case 3: KeaColumnsSized(3, nc, M, in, out); break;
    case 4: KeaColumnsSized(4, nc, M, in, out); break;
    case 5: KeaColumnsSized(5, nc, M, in, out); break;
    case 6: KeaColumnsSized(6, nc, M, in, out); break;
    default: KeaColumnsSized(m, nc, M, in, out); break;
    }
}

void KeaColumnsApply(int m, int nc, const MeReal *M, const MeReal *in, MeReal *out)
{
    KeaColumnsDispatch(m, nc, M, in, out);
}

/* out = M (v0, v1) for the m x 12 column-major M of a block's J_b^T: the 12 components
 * (lin0, ang0, lin1, ang1) gathered here, next to the column kernel; the same sums, in the same
 * order, as KeaColumnsApply on them. Size: the four vectors come apart, as the sweep holds the two
 * bodies' velocities, so that no 12-vector is copied on its hot path. */
void KeaColumnsApplyPair(int m, const MeReal *M, const MeReal *lin0, const MeReal *ang0, const MeReal *lin1,
                         const MeReal *ang1, MeReal *out)
{
    MeReal in[12];
    int c;
    for (c = 0; c < 3; ++c) {
        in[c] = lin0[c];
        in[3 + c] = ang0[c];
        in[6 + c] = lin1[c];
        in[9 + c] = ang1[c];
    }
    KeaColumnsDispatch(m, 12, M, in, out);
}

void KeaRowBounds(const KeaProblem *problem, const MeReal *x, int i, MeReal *lo, MeReal *hi)
{
    KeaRowBoundsInline(problem, x, i, lo, hi);
}

void KeaBodyVelocityFromImpulses(const KeaProblem *problem, const MeReal *x, KeaBodyVelocity *dv)
{
    KeaBodyVelocityFromImpulsesOf(problem, x, dv, 0, problem->nBodies);
}

/* Bodies whose impulses one pass over the rows gathers (a stack's worth; a larger partition takes a
 * pass per chunk). */
#define KEA_VELOCITY_CHUNK 32

/* J^T x of bodies [c0, c1) (at most KEA_VELOCITY_CHUNK) into acc, four lanes for the linear and four for
 * the angular part (the pads unused): each component is the scalar loop's sum, term by term in row order. */
static void KeaImpulsesOfChunk(const KeaProblem *problem, const MeReal *x, int c0, int c1, KeaLanes acc[][2])
{
    const unsigned width = (unsigned)(c1 - c0); /* the world (-1) and bodies outside wrap past it */
    for (int b = 0; b < c1 - c0; ++b)
        acc[b][0] = acc[b][1] = KeaLanesSplat(ME_R(0.0));
    for (int i = 0; i < problem->nRows; ++i) {
        const KeaJacobianRow *J = &problem->J[i];
        const int *rb = problem->rowBodies[i];
        const MeReal s = x[i];
        KeaLanes sv;
        if (s == ME_R(0.0))
            continue;
        sv = KeaLanesSplat(s);
        if ((unsigned)(rb[0] - c0) < width) {
            KeaLanes *a = acc[rb[0] - c0];
            a[0] = KeaLanesAdd(a[0], KeaLanesMul(KeaLanesLoad(J->lin0), sv));
            a[1] = KeaLanesAdd(a[1], KeaLanesMul(KeaLanesLoad(J->ang0), sv));
        }
        if ((unsigned)(rb[1] - c0) < width) {
            KeaLanes *a = acc[rb[1] - c0];
            a[0] = KeaLanesAdd(a[0], KeaLanesMul(KeaLanesLoad(J->lin1), sv));
            a[1] = KeaLanesAdd(a[1], KeaLanesMul(KeaLanesLoad(J->ang1), sv));
        }
    }
}

void KeaBodyVelocityFromImpulsesOf(const KeaProblem *problem, const MeReal *x, KeaBodyVelocity *dv, int b0, int b1)
{
    KeaLanes acc[KEA_VELOCITY_CHUNK][2];
    /* Accumulate the impulses J^T x per body, then apply M^-1 once per body. */
    for (int c0 = b0; c0 < b1; c0 += KEA_VELOCITY_CHUNK) {
        const int c1 = MeMIN(b1, c0 + KEA_VELOCITY_CHUNK);
        KeaImpulsesOfChunk(problem, x, c0, c1, acc);
        for (int b = c0; b < c1; ++b) {
            MeReal lin[4], angularImpulse[4];
            const KeaBody *body = &problem->bodies[b];
            KeaLanesStore(lin, acc[b - c0][0]);
            KeaLanesStore(angularImpulse, acc[b - c0][1]);
            for (int k = 0; k < 3; ++k)
                dv[b].lin[k] = lin[k] * body->invMass;
            KeaInvInertiaTimes(body, angularImpulse, dv[b].ang);
        }
    }
}

/* Row i's residual at x, with d_i given (NaN propagates: r != r counts as the worst). */
static MeReal KeaResidualOfRow(const KeaProblem *problem, const MeReal *x, const KeaBodyVelocity *dv, int i,
                               MeReal d)
{
    const MeReal eps = problem->epsilon ? problem->epsilon[i] : ME_R(0.0);
    const MeReal w = KeaRowVelocity(&problem->J[i], problem->rowBodies[i], dv) + eps * x[i] - problem->rhs[i];
    MeReal lo, hi;
    KeaRowBounds(problem, x, i, &lo, &hi);
    return KeaRowResidual(d, x[i], w, lo, hi);
}

MeReal KeaResidual(const KeaProblem *problem, const MeReal *x, const KeaBodyVelocity *dv)
{
    MeReal worst = ME_R(0.0);
    int i;
    for (i = 0; i < problem->nRows; ++i) {
        KeaJacobianRow B;
        const MeReal r = KeaResidualOfRow(problem, x, dv, i, KeaRowInvMassJT(problem, i, &B));
        if (r > worst || r != r)
            worst = r;
    }
    return worst;
}

MeReal KeaResidualWithDiagonal(const KeaProblem *problem, const MeReal *x, const KeaBodyVelocity *dv,
                               const MeReal *diag, size_t stride)
{
    MeReal worst = ME_R(0.0);
    int i;
    for (i = 0; i < problem->nRows; ++i) {
        const MeReal r = KeaResidualOfRow(problem, x, dv, i, diag[(size_t)i * stride]);
        if (r > worst || r != r)
            worst = r;
    }
    return worst;
}
