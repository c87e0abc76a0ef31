/* rprojoint.c -- the RPRO joint (relative position, relative orientation): its API and its rows.
 * Linear rows φ_k = (p0 − p1)·f_k along body 1's frame axes f_k; angular rows φ_k = 2·vec(q)_k with
 * q = conj(F1 ⊗ target) ⊗ F0, the rotation still needed to meet the target, about the target frame's
 * axes, and the target velocity J·(ω0 − ω1) = J·Ω, Ω the target angular velocity in the world. Each
 * row's force is bounded by its strength (force bounds ±strength). */
#include <karma/MdtRPROJoint.h>

#include "joint_parts.h"

typedef struct RPROData {
    MeVector4 target;        /* orientation of frame 0 relative to frame 1 */
    MeVector3 angularVelocity; /* ω0 − ω1 in frame 1 */
    MeReal strength[6];      /* linear x, y, z, angular x, y, z */
} RPROData;
MDT_CONSTRAINT_DATA_FITS(RPROData);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    RPROData *d = MDT_CONSTRAINT_DATA(c, RPROData);
    MeVector4Set(d->target, 1, 0, 0, 0);
    MeVector3Set(d->angularVelocity, 0, 0, 0);
    for (int k = 0; k < 6; k++)
        d->strength[k] = MEINFINITY;
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    const RPROData *d = MDT_CONSTRAINT_DATA(c, const RPROData);
    MeVector3 f[3], omega = {0, 0, 0};
    MdtBclRotation r;
    MdtBclWorldFrame(c, 1, f);
    MdtBclRelativeRotation(c, d->target, &r);
    for (int k = 0; k < 3; k++)
        MeVector3MultiplyAdd(omega, d->angularVelocity[k], f[k]);
    for (int k = 0; k < 6; k++) {
        MdtRow row;
        MeReal scale = 1;
        MdtRowInit(&row);
        if (k < 3) {
            MdtBclPointAlongRow(&row, c, f[k], METRUE);
        } else {
            MdtBclRotationRow(&row, &r, k - 3);
            row.velocity = MeVector3Dot(row.ang0, omega);
            /* The row's torque is (impulse / h)·ang0, and |ang0| ≤ 1: bound the impulse so that the
             * torque itself stays within the strength. */
            MeReal len = MeVector3Magnitude(row.ang0);
            scale = len > ME_SMALL_EPSILON ? 1 / len : 1;
        }
        row.lo = d->strength[k] >= MEINFINITY ? -MEINFINITY : -d->strength[k] * scale;
        row.hi = -row.lo;
        MdtRowWriterAdd(w, &row);
    }
}

static const MdtConstraintClass rproClass = {"RPROJoint", 6, reset, NULL, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(RPROJoint, MdtBclRPROJOINT, rproClass)

#define DATA_OR_RETURN(d, j, ret)                                                                    \
    MDT_BCL_JOINT_OR_RETURN(c_, j, MdtBclRPROJOINT, ret);                                            \
    RPROData *d = MDT_CONSTRAINT_DATA(c_, RPROData)

/* A unit copy of q, or MEFALSE (reported) when q is not unit within 1e-3 or not finite. */
static MeBool unitQuaternion(MeVector4 out, MeReal q0, MeReal q1, MeReal q2, MeReal q3, const char *function)
{
    MeVector4Set(out, q0, q1, q2, q3);
    if (!MeQuaternionIsValid(out, ME_R(1e-3))) {
        ME_REPORT_IN(function, ME_ERR_QUATERNION_NOT_UNIT,
                     "the quaternion (%g, %g, %g, %g) is not of unit length; call ignored", (double)q0, (double)q1,
                     (double)q2, (double)q3);
        return MEFALSE;
    }
    MeQuaternionNormalize(out);
    return METRUE;
}

void MdtRPROJointSetRelativeQuaternion(MdtRPROJointID j, const MeVector4 q)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(q, ME_NOTHING);
    MeVector4 u;
    if (unitQuaternion(u, q[0], q[1], q[2], q[3], __func__))
        MeVector4Copy(d->target, u);
}

void MdtRPROJointGetRelativeQuaternion(MdtRPROJointID j, MeVector4 q)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(q, ME_NOTHING);
    MeVector4Copy(q, d->target);
}

void MdtRPROJointSetAngularVelocity(MdtRPROJointID j, const MeVector3 w)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(w, ME_NOTHING);
    ME_CHECK_FINITE3(w[0], w[1], w[2], ME_NOTHING);
    MeVector3Copy(d->angularVelocity, w);
}

void MdtRPROJointGetAngularVelocity(MdtRPROJointID j, MeVector3 w)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(w, ME_NOTHING);
    MeVector3Copy(w, d->angularVelocity);
}

static void setStrength(MeReal *dst, MeReal sx, MeReal sy, MeReal sz, const char *function)
{
    if (MdtBclCheckNonNegative(&sx, "sx", function) && MdtBclCheckNonNegative(&sy, "sy", function) &&
        MdtBclCheckNonNegative(&sz, "sz", function)) {
        dst[0] = sx;
        dst[1] = sy;
        dst[2] = sz;
    }
}

void MdtRPROJointSetLinearStrength(MdtRPROJointID j, MeReal sx, MeReal sy, MeReal sz)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    setStrength(d->strength, sx, sy, sz, __func__);
}

void MdtRPROJointGetLinearStrength(MdtRPROJointID j, MeVector3 s)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(s, ME_NOTHING);
    MeVector3Copy(s, d->strength);
}

void MdtRPROJointSetAngularStrength(MdtRPROJointID j, MeReal sx, MeReal sy, MeReal sz)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    setStrength(d->strength + 3, sx, sy, sz, __func__);
}

void MdtRPROJointGetAngularStrength(MdtRPROJointID j, MeVector3 s)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(s, ME_NOTHING);
    MeVector3Copy(s, d->strength + 3);
}

void MdtRPROJointSetAttachmentPosition(MdtRPROJointID j, MeReal x, MeReal y, MeReal z, unsigned int bodyindex)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclRPROJOINT, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    if (MdtBclCheckBodyIndex(bodyindex, __func__))
        MeVector3Set(c->position[bodyindex], x, y, z);
}

void MdtRPROJointGetAttachmentPosition(MdtRPROJointID j, unsigned int bodyindex, MeVector3 p)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclRPROJOINT, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (MdtBclCheckBodyIndex(bodyindex, __func__))
        MeVector3Copy(p, c->position[bodyindex]);
}

void MdtRPROJointSetAttachmentQuaternion(MdtRPROJointID j, MeReal q0, MeReal q1, MeReal q2, MeReal q3,
                                         unsigned int bodyindex)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclRPROJOINT, ME_NOTHING);
    MeVector4 q;
    if (!MdtBclCheckBodyIndex(bodyindex, __func__) || !unitQuaternion(q, q0, q1, q2, q3, __func__))
        return;
    MeMatrix3 R;
    MeQuaternionToR(R, q);
    MeVector3Copy(c->primary[bodyindex], R[0]);
    MeVector3Copy(c->orthogonal[bodyindex], R[1]);
}

void MdtRPROJointGetAttachmentQuaternion(MdtRPROJointID j, unsigned int bodyindex, MeVector4 q)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclRPROJOINT, ME_NOTHING);
    ME_CHECK_NOT_NULL(q, ME_NOTHING);
    if (!MdtBclCheckBodyIndex(bodyindex, __func__))
        return;
    MeMatrix3 R;
    MeVector3Copy(R[0], c->primary[bodyindex]);
    MeVector3Copy(R[1], c->orthogonal[bodyindex]);
    MeVector3Cross(R[2], R[0], R[1]);
    MeQuaternionFromR(q, R);
}
