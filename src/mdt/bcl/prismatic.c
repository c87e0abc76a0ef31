/* prismatic.c -- the prismatic joint: its API and its rows. With a = body 1's axis, o = its
 * orthogonal axis and n = a × o (all fixed in body 1), and d = p0 − p1 between the attachment points:
 *   2 rows  body 0's axis parallel to a (the hinge's pair);
 *   1 row   o0·n = 0: no twist about the axis;
 *   2 rows  d·o = 0, d·n = 0: body 0's point stays on body 1's line;
 *   1 row   the limit/motor row of the displacement d·a.
 * Every row's Jacobian is the exact derivative of its constraint function. */
#include <karma/MdtPrismatic.h>

#include "../../me/check.h"
#include "limit_internal.h"

typedef struct PrismaticData {
    MdtLimit limit;
    MeBool anchored;         /* body 1's attachment point put on body 0's (displacement 0) */
    uintptr_t anchoredTo[2]; /* for the bodies it was done with */
} PrismaticData;
MDT_CONSTRAINT_DATA_FITS(PrismaticData);

static void reset(MdtConstraintData *c)
{
    PrismaticData *d = MDT_CONSTRAINT_DATA(c, PrismaticData);
    MdtConstraintResetFrames(c);
    MdtLimitInit(&d->limit);
    d->anchored = MEFALSE;
}

/* Zero displacement here: body 1's attachment point goes where body 0's is now. */
static void anchor(MdtConstraintData *c)
{
    PrismaticData *d = MDT_CONSTRAINT_DATA(c, PrismaticData);
    MeVector3 p0;
    MdtConstraintWorldPosition(c, 0, p0);
    MdtConstraintToBodyPoint(c, 1, p0, c->position[1]);
    d->anchored = METRUE;
    for (int i = 0; i < 2; i++)
        d->anchoredTo[i] = c->body[i] ? c->body[i]->id : 0;
    MDT_LIMIT_MEASURED(&d->limit) = 0;
}

static MeBool anchoredToCurrentBodies(const MdtConstraintData *c)
{
    const PrismaticData *d = MDT_CONSTRAINT_DATA(c, const PrismaticData);
    for (int i = 0; i < 2; i++)
        if (d->anchoredTo[i] != (c->body[i] ? c->body[i]->id : 0))
            return MEFALSE;
    return d->anchored;
}

static MeReal displacementRow(const MdtConstraintData *c, MdtRow *row)
{
    MeVector3 a1;
    MdtConstraintWorldPrimary(c, 1, a1);
    MdtRowInit(row);
    return MdtBclSlideRow(row, c, a1, 1);
}

static int rowCount(const MdtConstraintData *c)
{
    return 5 + (MdtLimitMayAddRow(&MDT_CONSTRAINT_DATA(c, const PrismaticData)->limit) ? 1 : 0);
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    PrismaticData *d = MDT_CONSTRAINT_DATA(c, PrismaticData);
    if (!w->captured && !anchoredToCurrentBodies(c))
        anchor(c);
    MeVector3 o0, a1, o1, n1;
    MdtConstraintWorldOrthogonal(c, 0, o0);
    MdtConstraintWorldPrimary(c, 1, a1);
    MdtConstraintWorldOrthogonal(c, 1, o1);
    MeVector3Cross(n1, a1, o1);
    MdtBclAddParallelAxisRows(w, c);
    MdtBclAddPerpendicularRow(w, c, o0, n1);
    const MeReal *across[2] = {o1, n1};
    for (int k = 0; k < 2; k++) {
        MdtRow row;
        MdtRowInit(&row);
        row.error = MdtBclSlideRow(&row, c, across[k], 1);
        MdtRowWriterAdd(w, &row);
    }
    MdtRow row;
    MeReal x = displacementRow(c, &row);
    MdtLimitAddRow(&d->limit, w, &row, x);
}

static void unpack(MdtConstraintData *c, const MeReal *impulses, int rows, MeReal h)
{
    MdtLimit *l = &MDT_CONSTRAINT_DATA(c, PrismaticData)->limit;
    MdtRow row;
    MeReal x = displacementRow(c, &row);
    MdtLimitSetMeasured(l, x, MdtRowVelocity(c, &row));
    MdtLimitUnpack(l, impulses, rows, h);
}

static void destroy(MdtConstraintData *c) { MDT_LIMIT_MAGIC(&MDT_CONSTRAINT_DATA(c, PrismaticData)->limit) = 0; }

static const MdtConstraintClass prismaticClass = {"Prismatic", 6, reset, rowCount, addRows, unpack, destroy};

MdtPrismaticID MdtPrismaticCreate(MdtWorldID w)
{
    MdtConstraintData *c = MdtConstraintCreateInternal(w, MdtBclPRISMATIC, &prismaticClass, __func__);
    return c ? (MdtPrismaticID)c->id : NULL;
}

void MdtPrismaticReset(MdtPrismaticID j)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclPRISMATIC, __func__);
    if (c)
        reset(c);
}

MdtConstraintID MdtPrismaticQuaConstraint(MdtPrismaticID j) { return (MdtConstraintID)j; }

MdtPrismaticID MdtConstraintDCastPrismatic(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclPRISMATIC ? (MdtPrismaticID)c : NULL;
}

void MdtPrismaticSetAxis(MdtPrismaticID j, MeReal x, MeReal y, MeReal z)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclPRISMATIC, __func__);
    if (!c)
        return;
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    if (x * x + y * y + z * z < ME_SMALL_EPSILON) {
        ME_REPORT(ME_ERR_ZERO_AXIS, "the axis (%g, %g, %g) has zero length; call ignored", (double)x, (double)y,
                  (double)z);
        return;
    }
    MdtConstraintSetAxis((MdtConstraintID)j, x, y, z);
    anchor(c);
}

MdtLimitID MdtPrismaticGetLimit(MdtPrismaticID j)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclPRISMATIC, __func__);
    return c ? &MDT_CONSTRAINT_DATA(c, PrismaticData)->limit : NULL;
}

void MdtPrismaticSetLimit(MdtPrismaticID j, const MdtLimit *limit)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclPRISMATIC, __func__);
    const MdtLimit *src = MdtLimitCheck(limit, __func__);
    if (c && src && MdtLimitCheckOrder(src, src->limit[0].stop, src->limit[1].stop, __func__))
        MdtLimitCopySettings(&MDT_CONSTRAINT_DATA(c, PrismaticData)->limit, src);
}
