/* spring.c -- the spring joint: its API and its row, the limit row of the distance between the two
 * attachment points (φ = |p0 − p1|; J = the unit direction u = (p0 − p1)/|p0 − p1| at each point). */
#include <karma/MdtSpring.h>

#include "../../me/check.h"
#include "limit_internal.h"

#define SPRING_DEFAULT_STIFFNESS ME_R(100.0)
#define SPRING_DEFAULT_DAMPING ME_R(1.0)

typedef struct SpringData {
    MdtLimit limit;
    MeReal separation;  /* initial separation: the coordinate is length − separation */
    MeBool measured;    /* separation taken */
    MeVector3 lastDirection; /* used when the points coincide */
} SpringData;
MDT_CONSTRAINT_DATA_FITS(SpringData);

static void reset(MdtConstraintData *c)
{
    SpringData *d = MDT_CONSTRAINT_DATA(c, SpringData);
    MdtConstraintResetFrames(c);
    MdtLimitInit(&d->limit);
    for (int s = 0; s < 2; s++) {
        d->limit.limit[s].stiffness = SPRING_DEFAULT_STIFFNESS;
        d->limit.limit[s].damping = SPRING_DEFAULT_DAMPING;
    }
    d->limit.limited = METRUE;
    d->separation = 0;
    d->measured = MEFALSE;
    MeVector3Set(d->lastDirection, 1, 0, 0);
}

/* The distance row; returns |p0 − p1|. */
static MeReal lengthRow(const MdtConstraintData *c, MdtRow *row)
{
    const SpringData *d = MDT_CONSTRAINT_DATA(c, const SpringData);
    MeVector3 p0, p1, u, r0, r1;
    MdtConstraintWorldPosition(c, 0, p0);
    MdtConstraintWorldPosition(c, 1, p1);
    MeVector3Subtract(u, p0, p1);
    MeReal length = MeSqrt(MeVector3MagnitudeSqr(u));
    if (length > ME_SMALL_EPSILON)
        MeVector3Scale(u, 1 / length);
    else
        MeVector3Copy(u, d->lastDirection);
    MdtBclLeverArm(c, 0, r0);
    MdtBclLeverArm(c, 1, r1);
    MdtRowInit(row);
    MeVector3Copy(row->lin0, u);
    MeVector3MultiplyScalar(row->lin1, u, -1);
    MeVector3Cross(row->ang0, r0, u);
    MeVector3Cross(row->ang1, u, r1);
    return length;
}

static void measureSeparation(MdtConstraintData *c)
{
    SpringData *d = MDT_CONSTRAINT_DATA(c, SpringData);
    MdtRow row;
    d->separation = lengthRow(c, &row);
    d->measured = METRUE;
}

static int rowCount(const MdtConstraintData *c)
{
    return MdtLimitMayAddRow(&MDT_CONSTRAINT_DATA(c, const SpringData)->limit) ? 1 : 0;
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    SpringData *d = MDT_CONSTRAINT_DATA(c, SpringData);
    if (!d->measured && !w->captured)
        measureSeparation(c);
    MdtRow row;
    MeReal length = lengthRow(c, &row);
    if (!w->captured)
        MeVector3Copy(d->lastDirection, row.lin0);
    MdtLimitAddRow(&d->limit, w, &row, length - d->separation);
}

static void unpack(MdtConstraintData *c, const MeReal *impulses, int rows, MeReal h)
{
    SpringData *d = MDT_CONSTRAINT_DATA(c, SpringData);
    MdtRow row;
    MeReal length = lengthRow(c, &row);
    MdtLimitSetMeasured(&d->limit, length - d->separation, MdtRowVelocity(c, &row));
    MdtLimitUnpack(&d->limit, impulses, rows, h);
}

static void destroy(MdtConstraintData *c) { MDT_LIMIT_MAGIC(&MDT_CONSTRAINT_DATA(c, SpringData)->limit) = 0; }

static const MdtConstraintClass springClass = {"Spring", 1, reset, rowCount, addRows, unpack, destroy};

#define SPRING_OR_RETURN(c, j, ret)                                                                  \
    MdtConstraintData *c = MdtConstraintFromIDOfType((j), MdtBclSPRING, __func__);                       \
    if (!c)                                                                                          \
    return ret

MdtSpringID MdtSpringCreate(MdtWorldID w)
{
    MdtConstraintData *c = MdtConstraintCreateInternal(w, MdtBclSPRING, &springClass, __func__);
    return c ? (MdtSpringID)c->id : NULL;
}

void MdtSpringReset(MdtSpringID j)
{
    SPRING_OR_RETURN(c, j, ME_NOTHING);
    reset(c);
}

MdtConstraintID MdtSpringQuaConstraint(MdtSpringID j) { return (MdtConstraintID)j; }

MdtSpringID MdtConstraintDCastSpring(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclSPRING ? (MdtSpringID)c : NULL;
}

void MdtSpringSetPosition(MdtSpringID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z)
{
    SPRING_OR_RETURN(c, j, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    if (bodyindex > 1) {
        ME_REPORT(ME_ERR_BODY_INDEX, "argument 'bodyindex' is %u; it must be 0 or 1", bodyindex);
        return;
    }
    MeVector3 p = {x, y, z};
    MdtConstraintToBodyPoint(c, (int)bodyindex, p, c->position[bodyindex]);
    measureSeparation(c);
}

void MdtSpringSetNaturalLength(MdtSpringID j, MeReal length)
{
    SPRING_OR_RETURN(c, j, ME_NOTHING);
    ME_CHECK_FINITE(length, ME_NOTHING);
    MdtLimit *l = &MDT_CONSTRAINT_DATA(c, SpringData)->limit;
    l->limit[0].stop = l->limit[1].stop = length;
}

void MdtSpringSetStiffness(MdtSpringID j, MeReal stiffness)
{
    SPRING_OR_RETURN(c, j, ME_NOTHING);
    if (stiffness != stiffness || stiffness < 0) {
        ME_REPORT(stiffness < 0 ? ME_ERR_NEGATIVE_VALUE : ME_ERR_NONFINITE_ARGUMENT,
                  "argument 'stiffness' is %g; it must be zero or positive (MEINFINITY: a rod); call ignored",
                  (double)stiffness);
        return;
    }
    MdtLimit *l = &MDT_CONSTRAINT_DATA(c, SpringData)->limit;
    l->limit[0].stiffness = l->limit[1].stiffness = stiffness;
}

void MdtSpringSetDamping(MdtSpringID j, MeReal damping)
{
    SPRING_OR_RETURN(c, j, ME_NOTHING);
    if (!ME_IS_FINITE(damping) || damping < 0) {
        ME_REPORT(ME_IS_FINITE(damping) ? ME_ERR_NEGATIVE_DAMPING : ME_ERR_NONFINITE_ARGUMENT,
                  "argument 'damping' is %g; it must be finite and zero or positive; call ignored", (double)damping);
        return;
    }
    MdtLimit *l = &MDT_CONSTRAINT_DATA(c, SpringData)->limit;
    l->limit[0].damping = l->limit[1].damping = damping;
}

MeReal MdtSpringGetLength(MdtSpringID j)
{
    SPRING_OR_RETURN(c, j, 0);
    if (!c->body[0])
        return 0;
    MdtRow row;
    return lengthRow(c, &row);
}

MeReal MdtSpringGetNaturalLength(MdtSpringID j)
{
    SPRING_OR_RETURN(c, j, 0);
    return MDT_CONSTRAINT_DATA(c, SpringData)->limit.limit[0].stop;
}

MeReal MdtSpringGetStiffness(MdtSpringID j)
{
    SPRING_OR_RETURN(c, j, 0);
    return MDT_CONSTRAINT_DATA(c, SpringData)->limit.limit[0].stiffness;
}

MeReal MdtSpringGetDamping(MdtSpringID j)
{
    SPRING_OR_RETURN(c, j, 0);
    return MDT_CONSTRAINT_DATA(c, SpringData)->limit.limit[0].damping;
}

MdtLimitID MdtSpringGetLimit(MdtSpringID j)
{
    SPRING_OR_RETURN(c, j, NULL);
    return &MDT_CONSTRAINT_DATA(c, SpringData)->limit;
}

void MdtSpringSetLimit(MdtSpringID j, const MdtLimit *limit)
{
    SPRING_OR_RETURN(c, j, ME_NOTHING);
    const MdtLimit *src = MdtLimitCheck(limit, __func__);
    if (src && MdtLimitCheckOrder(src, src->limit[0].stop, src->limit[1].stop, __func__))
        MdtLimitCopySettings(&MDT_CONSTRAINT_DATA(c, SpringData)->limit, src);
}
