/* spring6.c -- the six-axis spring: its API and its rows. In body 1's frame (axes f_k): linear rows
 * φ_k = (p0 − p1)·f_k and angular rows φ_k = 2·vec(q)_k, q the rotation of body 0's frame relative
 * to body 1's; each row is a spring-damper of its own stiffness and damping (SPOOK), rigid at
 * MEINFINITY, left out when both are 0. */
#include <karma/MdtSpring6.h>

#include "joint_parts.h"

typedef struct Spring6Data {
    MeReal stiffness[6], damping[6]; /* linear x, y, z, then angular x, y, z */
} Spring6Data;
MDT_CONSTRAINT_DATA_FITS(Spring6Data);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    Spring6Data *d = MDT_CONSTRAINT_DATA(c, Spring6Data);
    for (int k = 0; k < 6; k++) {
        d->stiffness[k] = MEINFINITY;
        d->damping[k] = 0;
    }
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    const Spring6Data *d = MDT_CONSTRAINT_DATA(c, const Spring6Data);
    MeVector3 f[3];
    MdtBclRotation r;
    MdtBclWorldFrame(c, 1, f);
    MdtBclRelativeRotation(c, NULL, &r);
    for (int k = 0; k < 6; k++) {
        MdtRow row;
        MdtRowInit(&row);
        if (k < 3)
            MdtBclPointAlongRow(&row, c, f[k], METRUE);
        else
            MdtBclRotationRow(&row, &r, k - 3);
        if (MdtBclRowSpring(&row, c, d->stiffness[k], d->damping[k], w->h))
            MdtRowWriterAdd(w, &row);
    }
}

static const MdtConstraintClass spring6Class = {"Spring6", 6, reset, NULL, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(Spring6, MdtBclSPRING6, spring6Class)

/* The data of j and the checked axis index, or NULL (reported). */
static Spring6Data *axisData(MdtSpring6ID j, unsigned int axis, const char *function)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclSPRING6, function);
    if (!c)
        return NULL;
    if (axis > 2) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "argument 'axis' is %u; it must be 0, 1 or 2", axis);
        return NULL;
    }
    return MDT_CONSTRAINT_DATA(c, Spring6Data);
}

static void setValue(MdtSpring6ID j, unsigned int axis, int offset, MeBool isStiffness, MeReal v,
                     const char *function)
{
    Spring6Data *d = axisData(j, axis, function);
    if (!d || !MdtBclCheckNonNegative(&v, isStiffness ? "stiffness" : "damping", function))
        return;
    (isStiffness ? d->stiffness : d->damping)[offset + (int)axis] = v;
}

static MeReal getValue(MdtSpring6ID j, unsigned int axis, int offset, MeBool isStiffness, const char *function)
{
    Spring6Data *d = axisData(j, axis, function);
    return d ? (isStiffness ? d->stiffness : d->damping)[offset + (int)axis] : 0;
}

void MdtSpring6SetLinearStiffness(MdtSpring6ID j, unsigned int axis, MeReal stiffness)
{
    setValue(j, axis, 0, METRUE, stiffness, __func__);
}

void MdtSpring6SetLinearDamping(MdtSpring6ID j, unsigned int axis, MeReal damping)
{
    setValue(j, axis, 0, MEFALSE, damping, __func__);
}

MeReal MdtSpring6GetLinearStiffness(MdtSpring6ID j, unsigned int axis) { return getValue(j, axis, 0, METRUE, __func__); }

MeReal MdtSpring6GetLinearDamping(MdtSpring6ID j, unsigned int axis) { return getValue(j, axis, 0, MEFALSE, __func__); }

void MdtSpring6SetAngularStiffness(MdtSpring6ID j, unsigned int axis, MeReal stiffness)
{
    setValue(j, axis, 3, METRUE, stiffness, __func__);
}

void MdtSpring6SetAngularDamping(MdtSpring6ID j, unsigned int axis, MeReal damping)
{
    setValue(j, axis, 3, MEFALSE, damping, __func__);
}

MeReal MdtSpring6GetAngularStiffness(MdtSpring6ID j, unsigned int axis)
{
    return getValue(j, axis, 3, METRUE, __func__);
}

MeReal MdtSpring6GetAngularDamping(MdtSpring6ID j, unsigned int axis)
{
    return getValue(j, axis, 3, MEFALSE, __func__);
}
