/* conelimit.c -- the cone limit: its API and its row. With a0, a1 the primary axes of the two frames
 * and θ = angle(a0, a1), the row is the limit g = θ − α ≤ 0 (α the half-angle), written only near
 * the limit: dθ/dt = −(ω0 − ω1)·(a0 × a1)/sin θ. */
#include <karma/MdtConeLimit.h>

#include "joint_parts.h"

typedef struct ConeLimitData {
    MeReal halfAngle, stiffness, damping;
} ConeLimitData;
MDT_CONSTRAINT_DATA_FITS(ConeLimitData);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    ConeLimitData *d = MDT_CONSTRAINT_DATA(c, ConeLimitData);
    d->halfAngle = ME_PI;
    d->stiffness = MEINFINITY;
    d->damping = MEINFINITY;
}

/* Angle between the axes; `cross` = a0 × a1. */
static MeReal coneAngle(const MdtConstraintData *c, MeVector3 cross)
{
    MeVector3 a0, a1;
    MdtConstraintWorldPrimary(c, 0, a0);
    MdtConstraintWorldPrimary(c, 1, a1);
    MeVector3Cross(cross, a0, a1);
    return MeAtan2(MeVector3Magnitude(cross), MeVector3Dot(a0, a1));
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    const ConeLimitData *d = MDT_CONSTRAINT_DATA(c, const ConeLimitData);
    if (d->halfAngle >= ME_PI)
        return;
    MeVector3 cross;
    MeReal theta = coneAngle(c, cross);
    MeReal s = MeVector3Magnitude(cross);
    if (s < ME_SMALL_EPSILON)
        return; /* on the axis (far inside) or exactly opposite: no direction to push along */
    MdtRow row;
    MdtRowInit(&row);
    MeVector3MultiplyScalar(row.ang0, cross, -1 / s);
    MeVector3MultiplyScalar(row.ang1, cross, 1 / s);
    if (MdtBclLimitRow(&row, c, theta - d->halfAngle, d->stiffness, d->damping, w->h))
        MdtRowWriterAdd(w, &row);
}

static const MdtConstraintClass coneLimitClass = {"ConeLimit", 1, reset, NULL, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(ConeLimit, MdtBclCONELIMIT, coneLimitClass)

MDT_BCL_ANGLE_PROPERTY(ConeLimit, MdtBclCONELIMIT, ConeLimitData, ConeHalfAngle, halfAngle, theta)
MDT_BCL_GAIN_PROPERTY(ConeLimit, MdtBclCONELIMIT, ConeLimitData, Stiffness, stiffness, stiffness)
MDT_BCL_GAIN_PROPERTY(ConeLimit, MdtBclCONELIMIT, ConeLimitData, Damping, damping, damping)

MeReal MdtConeLimitGetAngle(MdtConeLimitID j)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclCONELIMIT, 0);
    MeVector3 cross;
    return coneAngle(c, cross);
}
