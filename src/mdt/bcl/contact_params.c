/* contact_params.c -- MdtContactParams: defaults and checked setters (see MdtContactParams.h). */
#include <karma/MdtContactParams.h>

#include "../../me/check.h"

void MdtContactParamsReset(MdtContactParamsID p)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    p->type = MdtContactTypeFrictionZero;
    p->options = 0;
    p->model1 = p->model2 = MdtFrictionModelBox;
    p->friction1 = p->friction2 = MEINFINITY;
    p->frictioncoeff1 = p->frictioncoeff2 = 0;
    p->restitution = 0;
    p->velThreshold = ME_R(0.001);
    p->softness = 0;
    p->max_adhesive_force = 0;
    p->slip1 = p->slip2 = 0;
    p->slide1 = p->slide2 = 0;
}

#define GETTER(name, expr, type)                                                                     \
    type name(MdtContactParamsID p)                                                                  \
    {                                                                                                \
        ME_CHECK_NOT_NULL(p, (type)0);                                                               \
        return expr;                                                                                 \
    }

GETTER(MdtContactParamsGetType, p->type, MdtContactType)
GETTER(MdtContactParamsGetPrimaryFrictionModel, p->model1, MdtFrictionModel)
GETTER(MdtContactParamsGetSecondaryFrictionModel, p->model2, MdtFrictionModel)
GETTER(MdtContactParamsGetRestitution, p->restitution, MeReal)
GETTER(MdtContactParamsGetRestitutionThreshold, p->velThreshold, MeReal)
GETTER(MdtContactParamsGetSoftness, p->softness, MeReal)
GETTER(MdtContactParamsGetMaxAdhesiveForce, p->max_adhesive_force, MeReal)
GETTER(MdtContactParamsGetPrimaryFriction, p->friction1, MeReal)
GETTER(MdtContactParamsGetPrimaryFrictionCoeffecient, p->frictioncoeff1, MeReal)
GETTER(MdtContactParamsGetPrimarySlip, p->slip1, MeReal)
GETTER(MdtContactParamsGetPrimarySlide, p->slide1, MeReal)
GETTER(MdtContactParamsGetSecondaryFriction, p->friction2, MeReal)
GETTER(MdtContactParamsGetSecondaryFrictionCoeffecient, p->frictioncoeff2, MeReal)
GETTER(MdtContactParamsGetSecondarySlip, p->slip2, MeReal)
GETTER(MdtContactParamsGetSecondarySlide, p->slide2, MeReal)

/* A value that must be finite and at least zero (MEINFINITY allowed where `infinityOk`). */
static MeBool nonNegative(MeReal v, MeBool infinityOk, const char *function)
{
    if (v != v || (!infinityOk && !ME_IS_FINITE(v)) || (v > MEINFINITY)) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "the value %g is not finite; call ignored", (double)v);
        return MEFALSE;
    }
    if (v < 0) {
        ME_REPORT_IN(function, ME_ERR_NEGATIVE_VALUE, "the value %g must not be negative; call ignored", (double)v);
        return MEFALSE;
    }
    return METRUE;
}

static void setOption(MdtContactParamsID p, MeU32 bit, MeBool on)
{
    if (on)
        p->options |= bit;
    else
        p->options &= ~bit;
}

void MdtContactParamsSetType(MdtContactParamsID p, MdtContactType t)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (t != MdtContactTypeFrictionZero && t != MdtContactTypeFriction1D && t != MdtContactTypeFriction2D) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 't' (%d) is not an MdtContactType", (int)t);
        return;
    }
    p->type = t;
}

static MeBool validModel(MdtFrictionModel m, const char *function)
{
    if (m != MdtFrictionModelBox && m != MdtFrictionModelNormalForce) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "argument 'm' (%d) is not an MdtFrictionModel", (int)m);
        return MEFALSE;
    }
    return METRUE;
}

void MdtContactParamsSetPrimaryFrictionModel(MdtContactParamsID p, MdtFrictionModel m)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (validModel(m, __func__))
        p->model1 = m;
}

void MdtContactParamsSetSecondaryFrictionModel(MdtContactParamsID p, MdtFrictionModel m)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (validModel(m, __func__))
        p->model2 = m;
}

void MdtContactParamsSetFrictionModel(MdtContactParamsID p, MdtFrictionModel m)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (validModel(m, __func__))
        p->model1 = p->model2 = m;
}

void MdtContactParamsSetRestitution(MdtContactParamsID p, MeReal r)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_FINITE(r, ME_NOTHING);
    if (!(r >= 0 && r <= 1)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'r' (%g) must lie in [0, 1]", (double)r);
        return;
    }
    p->restitution = r;
    setOption(p, MdtBclContactOptionBounce, r > 0);
}

void MdtContactParamsSetRestitutionThreshold(MdtContactParamsID p, MeReal v)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (nonNegative(v, MEFALSE, __func__))
        p->velThreshold = v;
}

void MdtContactParamsSetSoftness(MdtContactParamsID p, MeReal s)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (!nonNegative(s, MEFALSE, __func__))
        return;
    p->softness = s;
    setOption(p, MdtBclContactOptionSoft, s > 0);
}

void MdtContactParamsSetMaxAdhesiveForce(MdtContactParamsID p, MeReal f)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (!nonNegative(f, METRUE, __func__))
        return;
    p->max_adhesive_force = f;
    setOption(p, MdtBclContactOptionAdhesive, f > 0);
}

void MdtContactParamsSetPrimaryFriction(MdtContactParamsID p, MeReal f)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (nonNegative(f, METRUE, __func__))
        p->friction1 = f;
}

void MdtContactParamsSetSecondaryFriction(MdtContactParamsID p, MeReal f)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (nonNegative(f, METRUE, __func__))
        p->friction2 = f;
}

void MdtContactParamsSetFriction(MdtContactParamsID p, MeReal f)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (nonNegative(f, METRUE, __func__))
        p->friction1 = p->friction2 = f;
}

void MdtContactParamsSetPrimaryFrictionCoeffecient(MdtContactParamsID p, MeReal f)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (nonNegative(f, MEFALSE, __func__))
        p->frictioncoeff1 = f;
}

void MdtContactParamsSetSecondaryFrictionCoeffecient(MdtContactParamsID p, MeReal f)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (nonNegative(f, MEFALSE, __func__))
        p->frictioncoeff2 = f;
}

void MdtContactParamsSetFrictionCoeffecient(MdtContactParamsID p, MeReal f)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (nonNegative(f, MEFALSE, __func__))
        p->frictioncoeff1 = p->frictioncoeff2 = f;
}

void MdtContactParamsSetPrimarySlip(MdtContactParamsID p, MeReal s)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (!nonNegative(s, MEFALSE, __func__))
        return;
    p->slip1 = s;
    setOption(p, MdtBclContactOptionSlip1, s > 0);
}

void MdtContactParamsSetSecondarySlip(MdtContactParamsID p, MeReal s)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (!nonNegative(s, MEFALSE, __func__))
        return;
    p->slip2 = s;
    setOption(p, MdtBclContactOptionSlip2, s > 0);
}

void MdtContactParamsSetSlip(MdtContactParamsID p, MeReal s)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (!nonNegative(s, MEFALSE, __func__))
        return;
    p->slip1 = p->slip2 = s;
    setOption(p, MdtBclContactOptionSlip1 | MdtBclContactOptionSlip2, s > 0);
}

void MdtContactParamsSetPrimarySlide(MdtContactParamsID p, MeReal s)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_FINITE(s, ME_NOTHING);
    p->slide1 = s;
    setOption(p, MdtBclContactOptionSlide1, s != 0);
}

void MdtContactParamsSetSecondarySlide(MdtContactParamsID p, MeReal s)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_FINITE(s, ME_NOTHING);
    p->slide2 = s;
    setOption(p, MdtBclContactOptionSlide2, s != 0);
}
