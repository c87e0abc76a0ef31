/* parts.c -- row pieces shared by the joints (point, parallel axes, perpendicular axes, orientation).
 *
 * Conventions. A row's constraint velocity is J·v = lin0·v0 + ang0·ω0 + lin1·v1 + ang1·ω1, where v
 * is the velocity of a body's centre of mass and ω its angular velocity (world frame). The velocity
 * of a point at lever arm r from the COM is v + ω × r, so e·(v + ω × r) = e·v + (r × e)·ω. Each
 * piece states its constraint function φ (the row's `error`, driven to 0 at rate γ/h) and makes J
 * its time derivative. When body 1 is the world, its lever arm is taken from the anchor itself, so
 * the world's velocity at the anchor (MdtConstraintSetWorldLinearVelocity) enters through lin1. */
#include "../constraint.h"

void MdtBclLeverArm(const MdtConstraint *c, int index, MeVector3 r)
{
    if (!c->body[index]) {
        MeVector3Set(r, 0, 0, 0);
        return;
    }
    MeVector3 p;
    MdtConstraintWorldPosition(c, index, p);
    const MdtBody *b = c->body[index];
    MeVector3Set(r, p[0] - b->comTM[3][0], p[1] - b->comTM[3][1], p[2] - b->comTM[3][2]);
}

/* φ_k = (p0 − p1)·e_k for the three world axes: the two attachment points coincide. */
void MdtBclAddPointRows(MdtRowWriter *w, const MdtConstraint *c)
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
void MdtBclAddPerpendicularRow(MdtRowWriter *w, const MdtConstraint *c, const MeVector3 d0, const MeVector3 d1)
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
void MdtBclAddParallelAxisRows(MdtRowWriter *w, const MdtConstraint *c)
{
    MeVector3 a0, o0, n0, a1;
    MdtConstraintWorldPrimary(c, 0, a0);
    MdtConstraintWorldOrthogonal(c, 0, o0);
    MeVector3Cross(n0, a0, o0);
    MdtConstraintWorldPrimary(c, 1, a1);
    MdtBclAddPerpendicularRow(w, c, o0, a1);
    MdtBclAddPerpendicularRow(w, c, n0, a1);
}

/* The frames' relative rotation, as a small rotation vector δ = ½ Σ_i f1_i × f0_i (f: the frame
 * axes in the world), held at zero along the three world axes: dδ/dt ≈ ω0 − ω1. */
void MdtBclAddOrientationRows(MdtRowWriter *w, const MdtConstraint *c)
{
    MeVector3 f0[3], f1[3], delta = {0, 0, 0};
    MdtConstraintWorldPrimary(c, 0, f0[0]);
    MdtConstraintWorldOrthogonal(c, 0, f0[1]);
    MeVector3Cross(f0[2], f0[0], f0[1]);
    MdtConstraintWorldPrimary(c, 1, f1[0]);
    MdtConstraintWorldOrthogonal(c, 1, f1[1]);
    MeVector3Cross(f1[2], f1[0], f1[1]);
    for (int i = 0; i < 3; i++) {
        MeVector3 t;
        MeVector3Cross(t, f1[i], f0[i]);
        MeVector3Add(delta, delta, t);
    }
    MeVector3Scale(delta, ME_R(0.5));
    for (int k = 0; k < 3; k++) {
        MdtRow row;
        MdtRowInit(&row);
        row.ang0[k] = 1;
        row.ang1[k] = -1;
        row.error = delta[k];
        MdtRowWriterAdd(w, &row);
    }
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
MeReal MdtBclSlideRow(MdtRow *row, const MdtConstraint *c, const MeVector3 d, int dBody)
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
