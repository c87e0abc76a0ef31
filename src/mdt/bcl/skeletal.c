/* skeletal.c -- the skeletal joint: its API and its rows.
 *
 * Rows: the ball and socket (3); then the swing, a function of u = (u_x, u_y, u_z), body 0's bone
 * axis a0 in body 1's frame (MdtBclAxisFunctionRow gives the exact Jacobian from ∂g/∂u):
 *   Cone:  θ = atan2(s, u_x), s = √(u_y² + u_z²), φ = atan2(u_z, u_y); the ellipse of half-angles
 *          (α_p, α_s) in polar form θ_max(φ) = (cos²φ/α_p² + sin²φ/α_s²)^(−1/2); limit g = θ − θ_max ≤ 0.
 *   Slot:  u_z = 0 (a0 ⊥ body 1's third axis, 1 row) and |atan2(u_y, u_x)| ≤ α_p (limit).
 *   Fixed: u_y = u_z = 0 (2 rows).
 * and the twist ψ (MdtBclTwistRow): Limited, |ψ| − α_t ≤ 0; Fixed, ψ = 0. Limits use
 * MdtBclLimitRow (hard, or a spring-damper past the limit); locked rows are springs when given a
 * finite stiffness. */
#include <karma/MdtDefaults.h>
#include <karma/MdtSkeletal.h>

#include "joint_parts.h"

typedef struct SkeletalData {
    MdtSkeletalConeOption coneOption;
    MdtSkeletalTwistOption twistOption;
    MeReal primary, secondary, twist; /* limit angles */
    MeReal coneK, coneD, twistK, twistD;
    MeBool combined;
} SkeletalData;
MDT_CONSTRAINT_DATA_FITS(SkeletalData);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    SkeletalData *d = MDT_CONSTRAINT_DATA(c, SkeletalData);
    d->coneOption = MdtSkeletalConeOptionCone;
    d->twistOption = MdtSkeletalTwistOptionLimited;
    d->primary = MDTSKELETAL_DEFAULT_PRI_ANGLE; /* decision D6 */
    d->secondary = MDTSKELETAL_DEFAULT_SEC_ANGLE;
    d->twist = MDTSKELETAL_DEFAULT_TWIST_ANGLE;
    d->coneK = d->twistK = MEINFINITY;
    d->coneD = d->twistD = 0;
    d->combined = MEFALSE;
}

static int rowCount(const MdtConstraintData *c)
{
    const SkeletalData *d = MDT_CONSTRAINT_DATA(c, const SkeletalData);
    int cone = d->coneOption == MdtSkeletalConeOptionFree ? 0 : d->coneOption == MdtSkeletalConeOptionCone ? 1 : 2;
    int twist = d->twistOption == MdtSkeletalTwistOptionFree ? 0 : 1;
    return 3 + cone + twist;
}

/* The bone in the world and in body 1's frame. */
typedef struct Swing {
    MeVector3 a0, f1[3], u;
} Swing;

static void swingOf(const MdtConstraintData *c, Swing *s)
{
    MdtConstraintWorldPrimary(c, 0, s->a0);
    MdtBclWorldFrame(c, 1, s->f1);
    for (int j = 0; j < 3; j++)
        s->u[j] = MeVector3Dot(s->a0, s->f1[j]);
}

/* Elliptical cone limit row; MEFALSE when the bone is on the cone's axis (far inside). */
static MeBool coneRow(MdtRow *row, const Swing *sw, MeReal ap, MeReal as)
{
    const MeReal x = sw->u[0], y = sw->u[1], z = sw->u[2];
    const MeReal s = MeSqrt(y * y + z * z);
    if (s < ME_SMALL_EPSILON)
        return MEFALSE;
    ap = ap > ME_R(1e-3) ? ap : ME_R(1e-3);
    as = as > ME_R(1e-3) ? as : ME_R(1e-3);
    const MeReal theta = MeAtan2(s, x), cp = y / s, sp = z / s;
    const MeReal thetaMax = 1 / MeSqrt(cp * cp / (ap * ap) + sp * sp / (as * as));
    /* dθmax/dφ, and the gradients of θ and φ with respect to u (|u| = 1). */
    const MeReal dMax = -thetaMax * thetaMax * thetaMax * cp * sp * (1 / (as * as) - 1 / (ap * ap));
    MeVector3 grad = {-s, x * cp, x * sp};
    grad[1] -= dMax * (-z / (s * s));
    grad[2] -= dMax * (y / (s * s));
    MdtBclAxisFunctionRow(row, sw->a0, &sw->f1[0][0], grad, theta - thetaMax);
    return METRUE;
}

/* Slot end limit |atan2(u_y, u_x)| ≤ α_p. */
static MeBool slotLimitRow(MdtRow *row, const Swing *sw, MeReal ap)
{
    const MeReal x = sw->u[0], y = sw->u[1], n = x * x + y * y;
    if (n < ME_SMALL_EPSILON)
        return MEFALSE;
    const MeReal angle = MeAtan2(y, x), sign = angle < 0 ? -1 : 1;
    MeVector3 grad = {-sign * y / n, sign * x / n, 0};
    MdtBclAxisFunctionRow(row, sw->a0, &sw->f1[0][0], grad, sign * angle - ap);
    return METRUE;
}

/* A locked row: rigid, or a spring with the given stiffness and damping. */
static void addLocked(MdtRowWriter *w, MdtConstraintData *c, MdtRow *row, MeReal k, MeReal d)
{
    if (MdtBclRowSpring(row, c, k, d, w->h))
        MdtRowWriterAdd(w, row);
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    const SkeletalData *d = MDT_CONSTRAINT_DATA(c, const SkeletalData);
    MdtBclAddPointRows(w, c);

    /* Limit candidates: swing and twist, each with its violation relative to its angle. */
    MdtRow limit[2];
    MeBool use[2] = {MEFALSE, MEFALSE};
    MeReal ratio[2] = {0, 0};

    Swing sw;
    swingOf(c, &sw);
    MdtRow row;
    switch (d->coneOption) {
    case MdtSkeletalConeOptionCone:
        MdtRowInit(&limit[0]);
        if (coneRow(&limit[0], &sw, d->primary, d->secondary))
            use[0] = MdtBclLimitRow(&limit[0], c, limit[0].error, d->coneK, d->coneD, w->h);
        ratio[0] = limit[0].error / (d->primary < d->secondary ? d->primary : d->secondary);
        break;
    case MdtSkeletalConeOptionSlot:
        MdtRowInit(&row);
        MdtBclPerpendicularRowFill(&row, sw.a0, sw.f1[2]);
        addLocked(w, c, &row, d->coneK, d->coneD);
        MdtRowInit(&limit[0]);
        if (slotLimitRow(&limit[0], &sw, d->primary))
            use[0] = MdtBclLimitRow(&limit[0], c, limit[0].error, d->coneK, d->coneD, w->h);
        ratio[0] = limit[0].error / d->primary;
        break;
    case MdtSkeletalConeOptionFixed:
        for (int k = 1; k < 3; k++) {
            MdtRowInit(&row);
            MdtBclPerpendicularRowFill(&row, sw.a0, sw.f1[k]);
            addLocked(w, c, &row, d->coneK, d->coneD);
        }
        break;
    default:
        break;
    }

    if (d->twistOption != MdtSkeletalTwistOptionFree) {
        MdtBclRotation r;
        MdtBclRelativeRotation(c, NULL, &r);
        MdtRowInit(&limit[1]);
        MeReal psi = MdtBclTwistRow(&limit[1], &r);
        if (d->twistOption == MdtSkeletalTwistOptionFixed) {
            addLocked(w, c, &limit[1], d->twistK, d->twistD);
        } else {
            if (psi < 0) {
                MeVector3Scale(limit[1].ang0, -1);
                MeVector3Scale(limit[1].ang1, -1);
            }
            MeReal g = MeFabs(psi) - d->twist;
            use[1] = MdtBclLimitRow(&limit[1], c, g, d->twistK, d->twistD, w->h);
            ratio[1] = g / (d->twist > ME_R(1e-3) ? d->twist : ME_R(1e-3));
        }
    }

    if (d->combined && use[0] && use[1])
        use[ratio[0] >= ratio[1] ? 1 : 0] = MEFALSE;
    for (int i = 0; i < 2; i++)
        if (use[i])
            MdtRowWriterAdd(w, &limit[i]);
}

static const MdtConstraintClass skeletalClass = {"Skeletal", 6, reset, rowCount, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(Skeletal, MdtBclSKELETAL, skeletalClass)

#define DATA_OR_RETURN(d, j, ret)                                                                    \
    MDT_BCL_JOINT_OR_RETURN(c_, j, MdtBclSKELETAL, ret);                                             \
    SkeletalData *d = MDT_CONSTRAINT_DATA(c_, SkeletalData)

MDT_BCL_ANGLE_PROPERTY(Skeletal, MdtBclSKELETAL, SkeletalData, ConePrimaryLimitAngle, primary, angle)
MDT_BCL_ANGLE_PROPERTY(Skeletal, MdtBclSKELETAL, SkeletalData, ConeSecondaryLimitAngle, secondary, angle)
MDT_BCL_ANGLE_PROPERTY(Skeletal, MdtBclSKELETAL, SkeletalData, TwistLimitAngle, twist, angle)
MDT_BCL_GAIN_PROPERTY(Skeletal, MdtBclSKELETAL, SkeletalData, ConeStiffness, coneK, stiffness)
MDT_BCL_GAIN_PROPERTY(Skeletal, MdtBclSKELETAL, SkeletalData, ConeDamping, coneD, damping)
MDT_BCL_GAIN_PROPERTY(Skeletal, MdtBclSKELETAL, SkeletalData, TwistStiffness, twistK, stiffness)
MDT_BCL_GAIN_PROPERTY(Skeletal, MdtBclSKELETAL, SkeletalData, TwistDamping, twistD, damping)

void MdtSkeletalSetConeLimitOption(MdtSkeletalID j, MdtSkeletalConeOption option)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    if ((int)option < 0 || (int)option > (int)MdtSkeletalConeOptionFixed) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'option' (%d) is not an MdtSkeletalConeOption", (int)option);
        return;
    }
    d->coneOption = option;
}

MdtSkeletalConeOption MdtSkeletalGetConeLimitOption(MdtSkeletalID j)
{
    DATA_OR_RETURN(d, j, MdtSkeletalConeOptionFree);
    return d->coneOption;
}

void MdtSkeletalSetTwistLimitOption(MdtSkeletalID j, MdtSkeletalTwistOption option)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    if ((int)option < 0 || (int)option > (int)MdtSkeletalTwistOptionFixed) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'option' (%d) is not an MdtSkeletalTwistOption", (int)option);
        return;
    }
    d->twistOption = option;
}

MdtSkeletalTwistOption MdtSkeletalGetTwistLimitOption(MdtSkeletalID j)
{
    DATA_OR_RETURN(d, j, MdtSkeletalTwistOptionFree);
    return d->twistOption;
}

void MdtSkeletalEnableCombinedLimits(MdtSkeletalID j, MeBool enable)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    d->combined = enable ? METRUE : MEFALSE;
}

MeBool MdtSkeletalCombinedLimitsAreEnabled(MdtSkeletalID j)
{
    DATA_OR_RETURN(d, j, MEFALSE);
    return d->combined;
}

static MeReal twistOf(const MdtConstraintData *c)
{
    MdtBclRotation r;
    MdtRow row;
    MdtBclRelativeRotation(c, NULL, &r);
    return MdtBclTwistRow(&row, &r);
}

void MdtSkeletalZeroTwist(MdtSkeletalID j)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclSKELETAL, ME_NOTHING);
    /* F0 ← F0 ⊗ rot_x(−ψ): the twist of the swing-twist decomposition becomes 0. */
    MeVector4 q;
    MeQuaternionMake(q, c->primary[0], -twistOf(c));
    MeQuaternionRotateVector3(c->orthogonal[0], q, c->orthogonal[0]);
}

MeReal MdtSkeletalGetTwistAngle(MdtSkeletalID j)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclSKELETAL, 0);
    return twistOf(c);
}

MeReal MdtSkeletalGetSwingAngle(MdtSkeletalID j)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclSKELETAL, 0);
    Swing sw;
    swingOf(c, &sw);
    return MeAtan2(MeSqrt(sw.u[1] * sw.u[1] + sw.u[2] * sw.u[2]), sw.u[0]);
}
