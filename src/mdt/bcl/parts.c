/* parts.c -- row pieces shared by the joints (point, parallel axes, perpendicular axes, orientation).
 *
 * Conventions. A row's constraint velocity is J·v = lin0·v0 + ang0·ω0 + lin1·v1 + ang1·ω1, where v
 * is the velocity of a body's centre of mass and ω its angular velocity (world frame). The velocity
 * of a point at lever arm r from the COM is v + ω × r, so e·(v + ω × r) = e·v + (r × e)·ω. Each
 * piece states its constraint function φ (the row's `error`, driven to 0 at rate γ/h) and makes J
 * its time derivative. When body 1 is the world, its lever arm is taken from the anchor itself, so
 * the world's velocity at the anchor (MdtConstraintSetWorldLinearVelocity) enters through lin1. */
#include "../constraint.h"

void MdtBclLeverArm(const MdtConstraintData *c, int index, MeVector3 r)
{
    if (!c->body[index]) {
        MeVector3Set(r, 0, 0, 0);
        return;
    }
    MeVector3 p;
    MdtConstraintWorldPosition(c, index, p);
    const MdtBodyData *b = c->body[index];
    MeVector3Set(r, p[0] - b->comTM[3][0], p[1] - b->comTM[3][1], p[2] - b->comTM[3][2]);
}

/* φ_k = (p0 − p1)·e_k for the three world axes: the two attachment points coincide. */
void MdtBclAddPointRows(MdtRowWriter *w, const MdtConstraintData *c)
{
    MeVector3 p0, p1, r0, r1;
    MdtConstraintWorldPosition(c, 0, p0);
    MdtConstraintWorldPosition(c, 1, p1);
    MdtBclLeverArm(c, 0, r0);
    MdtBclLeverArm(c, 1, r1);
    for (int k = 0; k < 3; k++) {
        MdtRow row;
        MdtRowInit(&row);
        row.lin0[k] = 1;
        row.lin1[k] = -1;
        MeVector3 e = {0, 0, 0};
        e[k] = 1;
        MeVector3Cross(row.ang0, r0, e);
        MeVector3Cross(row.ang1, r1, e);
        MeVector3Scale(row.ang1, -1);
        row.error = p0[k] - p1[k];
        MdtRowWriterAdd(w, &row);
    }
}

/* φ = d0·d1 with d0 fixed in body 0 and d1 in body 1: dφ/dt = (ω0 − ω1)·(d0 × d1). */
void MdtBclAddPerpendicularRow(MdtRowWriter *w, const MdtConstraintData *c, const MeVector3 d0, const MeVector3 d1)
{
    (void)c;
    MdtRow row;
    MdtRowInit(&row);
    MeVector3Cross(row.ang0, d0, d1);
    MeVector3Copy(row.ang1, row.ang0);
    MeVector3Scale(row.ang1, -1);
    row.error = MeVector3Dot(d0, d1);
    MdtRowWriterAdd(w, &row);
}

/* Body 1's primary axis kept perpendicular to the two directions of body 0's frame that are
 * perpendicular to body 0's primary axis: the primary axes stay parallel (2 rows). */
void MdtBclAddParallelAxisRows(MdtRowWriter *w, const MdtConstraintData *c)
{
    MeVector3 a0, o0, n0, a1;
    MdtConstraintWorldPrimary(c, 0, a0);
    MdtConstraintWorldOrthogonal(c, 0, o0);
    MeVector3Cross(n0, a0, o0);
    MdtConstraintWorldPrimary(c, 1, a1);
    MdtBclAddPerpendicularRow(w, c, o0, a1);
    MdtBclAddPerpendicularRow(w, c, n0, a1);
}

/* θ = atan2(d·v, d·u): the angle of direction d (fixed in body `dBody`) in the plane of u and v
 * (fixed in the other body). With x = d·u, y = d·v and d/dt(a·b) = (ω_a − ω_b)·(a × b) for a and b
 * fixed in bodies a and b, dθ/dt = (x ẏ − y ẋ)/(x² + y²) exactly, at any pose. */
MeReal MdtBclAngleRow(MdtRow *row, const MeVector3 u, const MeVector3 v, const MeVector3 d, int dBody)
{
    MeReal x = MeVector3Dot(d, u), y = MeVector3Dot(d, v), r2 = x * x + y * y;
    MeVector3 vxd, uxd, j;
    MeVector3Cross(vxd, v, d);
    MeVector3Cross(uxd, u, d);
    MeReal s = r2 > ME_SMALL_EPSILON ? 1 / r2 : 0; /* d along the axis: no angle to measure */
    for (int k = 0; k < 3; k++)
        j[k] = s * (x * vxd[k] - y * uxd[k]);
    /* j is the angular Jacobian of the body holding u and v; the other body's is −j. */
    MeReal *own = dBody == 0 ? row->ang1 : row->ang0, *other = dBody == 0 ? row->ang0 : row->ang1;
    MeVector3Copy(own, j);
    MeVector3MultiplyScalar(other, j, -1);
    return MeAtan2(y, x);
}

/* φ = (p0 − p1)·d for the attachment points p0, p1 and a direction d fixed in body `dBody`:
 * dφ/dt = (ṗ0 − ṗ1)·d + (p0 − p1)·(ω_dBody × d), hence lin = ±d and the angular parts
 * r0 × d, −r1 × d plus d × (p0 − p1) on the body that carries d. */
MeReal MdtBclSlideRow(MdtRow *row, const MdtConstraintData *c, const MeVector3 d, int dBody)
{
    MeVector3 p0, p1, r0, r1, D, t;
    MdtConstraintWorldPosition(c, 0, p0);
    MdtConstraintWorldPosition(c, 1, p1);
    MdtBclLeverArm(c, 0, r0);
    MdtBclLeverArm(c, 1, r1);
    MeVector3Subtract(D, p0, p1);
    MeVector3Copy(row->lin0, d);
    MeVector3MultiplyScalar(row->lin1, d, -1);
    MeVector3Cross(row->ang0, r0, d);
    MeVector3Cross(row->ang1, d, r1);
    MeVector3Cross(t, d, D);
    MeVector3Add(dBody == 0 ? row->ang0 : row->ang1, dBody == 0 ? row->ang0 : row->ang1, t);
    return MeVector3Dot(D, d);
}

/* ==== pieces that fill a row without adding it (joint_parts.h) ============================== */
#include "../../me/check.h"
#include "joint_parts.h"

void MdtBclWorldFrame(const MdtConstraintData *c, int index, MeVector3 f[3])
{
    MdtConstraintWorldPrimary(c, index, f[0]);
    MdtConstraintWorldOrthogonal(c, index, f[1]);
    MeVector3Cross(f[2], f[0], f[1]);
}

MeReal MdtBclRowVelocityNow(const MdtRow *row, const MdtConstraintData *c)
{
    const MdtBodyData *b0 = c->body[0], *b1 = c->body[1];
    MeReal jv = MeVector3Dot(row->lin0, b0->vel) + MeVector3Dot(row->ang0, b0->velrot);
    if (b1)
        jv += MeVector3Dot(row->lin1, b1->vel) + MeVector3Dot(row->ang1, b1->velrot);
    else
        jv += MeVector3Dot(row->lin1, c->worldLinearVelocity) + MeVector3Dot(row->ang1, c->worldAngularVelocity);
    return jv;
}

/* SPOOK (Lacoursière 2007): with τ = d/k and Υ = 1/(1 + 4τ/h) = hk/(hk + 4d) the row solves
 *   J v⁺ + ε x = −(4Υ/h) φ + Υ (J v − c) + c,   ε = 4Υ/(h²k) = 4/(h (hk + 4d)),
 * i.e. γ = 4Υ and no world ε. k = 0 gives a pure damper (ε = 1/(h d), γ = 0). See docs/step.md. */
MeBool MdtBclRowSpring(MdtRow *row, const MdtConstraintData *c, MeReal k, MeReal d, MeReal h)
{
    if (k >= MEINFINITY || d >= MEINFINITY)
        return METRUE;
    if (k <= 0 && d <= 0)
        return MEFALSE;
    const MeReal hk = h * k, denom = hk + 4 * d;
    const MeReal upsilon = hk / denom;
    row->epsilon = 4 / (h * denom);
    row->gamma = 4 * upsilon;
    row->noWorldEpsilon = METRUE;
    row->velocity += upsilon * (MdtBclRowVelocityNow(row, c) - row->velocity);
    return METRUE;
}

MeBool MdtBclLimitRow(MdtRow *row, const MdtConstraintData *c, MeReal g, MeReal k, MeReal d, MeReal h)
{
    row->error = g;
    row->lo = -MEINFINITY;
    row->hi = 0;
    if (k >= MEINFINITY || d >= MEINFINITY) {
        if (g >= 0)
            return METRUE;
        /* Not there yet: add the row if the limit may be reached within the step (twice the
         * current closing speed, for the acceleration), closing the gap exactly at γ = 1. */
        MeReal rate = MdtBclRowVelocityNow(row, c);
        if (g + 2 * h * rate < 0)
            return MEFALSE;
        row->gamma = 1;
        return METRUE;
    }
    if (g <= 0)
        return MEFALSE;
    return MdtBclRowSpring(row, c, k, d, h);
}

/* φ = (p0 − p1)·n. dφ/dt = n·(v0 + ω0 × r0) − n·(v1 + ω1 × r1) + (p0 − p1)·(ω1 × n) when n turns with
 * body 1; the last two terms combine into the velocity of body 1's material point at p0. */
void MdtBclPointAlongRow(MdtRow *row, const MdtConstraintData *c, const MeVector3 n, MeBool turnsWithBody1)
{
    MeVector3 p0, p1, r0, r1;
    MdtConstraintWorldPosition(c, 0, p0);
    MdtConstraintWorldPosition(c, 1, p1);
    MdtBclLeverArm(c, 0, r0);
    MdtBclLeverArm(c, 1, r1);
    if (turnsWithBody1) {
        MeVector3 sep;
        MeVector3Subtract(sep, p0, p1);
        MeVector3Add(r1, r1, sep);
    }
    MeVector3Copy(row->lin0, n);
    MeVector3MultiplyScalar(row->lin1, n, -1);
    MeVector3Cross(row->ang0, r0, n);
    MeVector3Cross(row->ang1, n, r1);
    row->error = (p0[0] - p1[0]) * n[0] + (p0[1] - p1[1]) * n[1] + (p0[2] - p1[2]) * n[2];
}

/* φ = d0·d1: dφ/dt = (ω0 × d0)·d1 + d0·(ω1 × d1) = (ω0 − ω1)·(d0 × d1). */
void MdtBclPerpendicularRowFill(MdtRow *row, const MeVector3 d0, const MeVector3 d1)
{
    MeVector3Cross(row->ang0, d0, d1);
    MeVector3MultiplyScalar(row->ang1, row->ang0, -1);
    row->error = MeVector3Dot(d0, d1);
}

/* Orientation of a frame given by its world axes (rows of R = images of the unit axes). */
static void frameQuaternion(MeVector3 f[3], MeVector4 q)
{
    MeMatrix3 R;
    MeMatrix3CopyVec(R, f[0], f[1], f[2]);
    MeQuaternionFromR(q, R);
}

void MdtBclRelativeRotation(const MdtConstraintData *c, const MeVector4 target, MdtBclRotation *r)
{
    MeVector3 f0[3], f1[3];
    MeVector4 q0, q1, t, tc;
    MdtBclWorldFrame(c, 0, f0);
    MdtBclWorldFrame(c, 1, f1);
    frameQuaternion(f0, q0);
    frameQuaternion(f1, q1);
    if (target)
        MeQuaternionProduct(t, q1, target);
    else
        MeVector4Copy(t, q1);
    MeQuaternionConjugate(tc, t);
    MeQuaternionProduct(r->q, tc, q0);
    if (r->q[0] < 0)
        MeVector4Scale(r->q, -1);
    for (int k = 0; k < 3; k++) {
        MeVector3 e = {0, 0, 0};
        e[k] = 1;
        MeQuaternionRotateVector3(r->t[k], t, e);
    }
}

/* dq/dt = ½ (0, u) ⊗ q with u_j = t_j·(ω0 − ω1), so d vec(q)/dt = ½ (w I − [v]×) u (v = vec(q)). */
void MdtBclRotationRow(MdtRow *row, const MdtBclRotation *r, int k)
{
    const MeReal w = r->q[0], *v = r->q + 1;
    /* Row k of (w I − [v]×), [v]× = [[0,−v2,v1],[v2,0,−v0],[−v1,v0,0]]. */
    MeReal m[3] = {0, 0, 0};
    m[k] = w;
    m[(k + 1) % 3] += v[(k + 2) % 3];
    m[(k + 2) % 3] -= v[(k + 1) % 3];
    MeVector3Set(row->ang0, 0, 0, 0);
    for (int j = 0; j < 3; j++)
        MeVector3MultiplyAdd(row->ang0, m[j], r->t[j]);
    MeVector3MultiplyScalar(row->ang1, row->ang0, -1);
    row->error = 2 * v[k];
}

/* ψ = 2 atan2(x, w); dψ/dt = u·(w² + x², wz + xy, xz − wy)/(w² + x²). */
MeReal MdtBclTwistRow(MdtRow *row, const MdtBclRotation *r)
{
    const MeReal w = r->q[0], x = r->q[1], y = r->q[2], z = r->q[3];
    MeReal n = w * w + x * x;
    MeVector3Set(row->ang0, 0, 0, 0);
    if (n > ME_SMALL_EPSILON) {
        MeVector3MultiplyAdd(row->ang0, 1, r->t[0]);
        MeVector3MultiplyAdd(row->ang0, (w * z + x * y) / n, r->t[1]);
        MeVector3MultiplyAdd(row->ang0, (x * z - w * y) / n, r->t[2]);
    }
    MeVector3MultiplyScalar(row->ang1, row->ang0, -1);
    row->error = 2 * MeAtan2(x, w);
    return row->error;
}

/* u = (a0·f1_j): du/dt = F1ᵀ((ω0 − ω1) × a0), so dg/dt = (ω0 − ω1)·(a0 × F1 ∇g). */
void MdtBclAxisFunctionRow(MdtRow *row, const MeVector3 a0, const MeReal *f1, const MeVector3 gradient, MeReal g)
{
    MeVector3 G = {0, 0, 0};
    for (int j = 0; j < 3; j++)
        MeVector3MultiplyAdd(G, gradient[j], f1 + 3 * j);
    MeVector3Cross(row->ang0, a0, G);
    MeVector3MultiplyScalar(row->ang1, row->ang0, -1);
    row->error = g;
}

MeBool MdtBclSetBodyAxis(MdtConstraintData *c, int index, MeReal x, MeReal y, MeReal z, const char *function)
{
    if (!(ME_IS_FINITE(x) && ME_IS_FINITE(y) && ME_IS_FINITE(z))) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "the axis (%g, %g, %g) is not finite; call ignored",
                     (double)x, (double)y, (double)z);
        return MEFALSE;
    }
    MeVector3 p = {x, y, z}, o, t;
    if (!MeVector3NormalizeSafe(p)) {
        ME_REPORT_IN(function, ME_ERR_ZERO_AXIS, "the axis has zero length; call ignored");
        return MEFALSE;
    }
    /* Keep the current orthogonal axis, made perpendicular; any perpendicular if it is parallel. */
    MdtConstraintWorldOrthogonal(c, index, o);
    MeReal d = MeVector3Dot(o, p);
    MeVector3Set(t, o[0] - d * p[0], o[1] - d * p[1], o[2] - d * p[2]);
    if (MeVector3MagnitudeSqr(t) < ME_SMALL_EPSILON || !MeVector3NormalizeSafe(t)) {
        MeVector3 b;
        MeVector3PlaneSpace(p, t, b);
    }
    MdtConstraintToBodyVector(c, index, p, c->primary[index]);
    MdtConstraintToBodyVector(c, index, t, c->orthogonal[index]);
    return METRUE;
}

MeBool MdtBclCheckNonNegative(MeReal *v, const char *name, const char *function)
{
    if (isnan(*v)) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "argument '%s' is NaN; call ignored", name);
        return MEFALSE;
    }
    if (*v < 0) {
        ME_REPORT_IN(function, ME_ERR_NEGATIVE_VALUE, "argument '%s' (%g) must not be negative; call ignored", name,
                     (double)*v);
        return MEFALSE;
    }
    if (*v > MEINFINITY)
        *v = MEINFINITY;
    return METRUE;
}

MeBool MdtBclCheckAngle(MeReal v, MeReal lo, MeReal hi, const char *name, const char *function)
{
    if (!ME_IS_FINITE(v)) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "argument '%s' is %g (not finite); call ignored", name,
                     (double)v);
        return MEFALSE;
    }
    if (v < lo || v > hi) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "argument '%s' (%g) must lie in [%g, %g] rad; call ignored",
                     name, (double)v, (double)lo, (double)hi);
        return MEFALSE;
    }
    return METRUE;
}

MeBool MdtBclCheckBodyIndex(unsigned int bodyindex, const char *function)
{
    if (bodyindex > 1) {
        ME_REPORT_IN(function, ME_ERR_BODY_INDEX, "argument 'bodyindex' is %u; it must be 0 or 1", bodyindex);
        return MEFALSE;
    }
    return METRUE;
}
