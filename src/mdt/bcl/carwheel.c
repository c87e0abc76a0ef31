/* carwheel.c -- the car wheel joint: its API and its rows (see MdtCarWheel.h). With s the steering
 * axis and h0 the hinge axis as fixed in the chassis (body 0), n0 = s × h0, h1 and a1 the hinge axis
 * and the steering axis as fixed in the wheel (body 1), and d = p0 − p1 between the attachment points:
 *   2 rows   d·h0 = 0, d·n0 = 0           the wheel's centre stays on the suspension line;
 *   1 row    s·h1 = 0                      the hinge axis stays perpendicular to the steering axis;
 *   1 row    suspension on d·s: stops, else the spring-damper;
 *   1 row    steering on atan2(h1·n0, h1·h0): lock at 0, or the motor;
 *   1 row    wheel motor on atan2(s·(a1 × h1), s·a1).
 * A stop of the suspension carries the spring's own force (explicit, at the stop) as its bound, so
 * the spring can still push the wheel off the stop it rests on. */
#include <karma/MdtCarWheel.h>

#include "../../me/check.h"
#include "limit_internal.h"

typedef struct CarWheelData {
    MeReal steerVelocity, steerForce;
    MeBool steerLock;
    MeReal hingeVelocity, hingeForce;
    MeReal kp, kd, softness, lo, hi, reference;
} CarWheelData;
MDT_CONSTRAINT_DATA_FITS(CarWheelData);

/* The joint's axes in the world. */
typedef struct Axes {
    MeVector3 s, h0, n0, h1, a1, a1xh1;
} Axes;

static void axes(const MdtConstraintData *c, Axes *a)
{
    MdtConstraintWorldPrimary(c, 0, a->s);
    MdtConstraintWorldOrthogonal(c, 0, a->h0);
    MeVector3Cross(a->n0, a->s, a->h0);
    MdtConstraintWorldOrthogonal(c, 1, a->h1);
    MdtConstraintWorldPrimary(c, 1, a->a1);
    MeVector3Cross(a->a1xh1, a->a1, a->h1);
}

static void reset(MdtConstraintData *c)
{
    CarWheelData *d = MDT_CONSTRAINT_DATA(c, CarWheelData);
    for (int i = 0; i < 2; i++) {
        MeVector3Set(c->position[i], 0, 0, 0);
        MeVector3Set(c->primary[i], 0, 0, 1);
        MeVector3Set(c->orthogonal[i], 0, 1, 0);
    }
    d->steerVelocity = 0;
    d->steerForce = ME_R(1e9);
    d->steerLock = MEFALSE;
    d->hingeVelocity = 0;
    d->hingeForce = 0;
    d->kp = d->kd = d->softness = d->reference = 0;
    d->lo = ME_R(-1e9);
    d->hi = ME_R(1e9);
}

static MeReal steeringRow(const MdtConstraintData *c, const Axes *a, MdtRow *row)
{
    (void)c;
    MdtRowInit(row);
    return MdtBclAngleRow(row, a->h0, a->n0, a->h1, 1);
}

static MeReal hingeRow(const MdtConstraintData *c, const Axes *a, MdtRow *row)
{
    (void)c;
    MdtRowInit(row);
    return MdtBclAngleRow(row, a->a1, a->a1xh1, a->s, 0);
}

static MeReal heightRow(const MdtConstraintData *c, const Axes *a, MdtRow *row)
{
    MdtRowInit(row);
    return MdtBclSlideRow(row, c, a->s, 0);
}

static int rowCount(const MdtConstraintData *c)
{
    const CarWheelData *d = MDT_CONSTRAINT_DATA(c, const CarWheelData);
    return 4 + ((d->steerLock || d->steerForce > 0) ? 1 : 0) + (d->hingeForce > 0 ? 1 : 0);
}

/* Suspension: a stop reached within the step (speculative, no bounce) holds; otherwise the spring. */
static void addSuspensionRow(const MdtConstraintData *c, const CarWheelData *d, MdtRowWriter *w, MdtRow *row, MeReal x)
{
    const MeReal h = w->h, v0 = MdtRowVelocity(c, row), vstar = MdtRowPredictedVelocity(c, row);
    const MeBool spring = d->kp > 0 || d->kd > 0;
    const MeBool atLo = x - d->lo <= h * (vstar < 0 ? -vstar : 0);
    const MeBool atHi = d->hi - x <= h * (vstar > 0 ? vstar : 0);
    if (atLo && atHi) {
        row->error = x < d->lo ? x - d->lo : (x > d->hi ? x - d->hi : 0);
        row->epsilon = d->softness;
    } else if (atLo || atHi) {
        MeReal stop = atLo ? d->lo : d->hi, phi = atLo ? x - d->lo : d->hi - x;
        /* the spring's force, explicit: the stop adds to it, never takes from it */
        MeReal springForce = -d->kp * (x - d->reference) - d->kd * v0;
        row->error = x - stop;
        row->gamma = phi > 0 ? 1 : -1;
        row->epsilon = d->softness;
        row->lo = atLo ? springForce : -MEINFINITY;
        row->hi = atLo ? MEINFINITY : springForce;
    } else if (spring) {
        MdtRowMakeSpring(row, c, d->kp, d->kd, x - d->reference, h);
    } else {
        return;
    }
    MdtRowWriterAdd(w, row);
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    const CarWheelData *d = MDT_CONSTRAINT_DATA(c, const CarWheelData);
    Axes a;
    axes(c, &a);
    const MeReal *across[2] = {a.h0, a.n0};
    for (int k = 0; k < 2; k++) {
        MdtRow row;
        MdtRowInit(&row);
        row.error = MdtBclSlideRow(&row, c, across[k], 0);
        MdtRowWriterAdd(w, &row);
    }
    MdtBclAddPerpendicularRow(w, c, a.s, a.h1);

    MdtRow row;
    MeReal height = heightRow(c, &a, &row);
    addSuspensionRow(c, d, w, &row, height);

    MeReal steer = steeringRow(c, &a, &row);
    row.error = steer;
    row.gamma = 0;
    if (d->steerLock) {
        row.gamma = -1; /* held at angle 0 */
        MdtRowWriterAdd(w, &row);
    } else if (d->steerForce > 0) {
        row.velocity = d->steerVelocity;
        row.lo = -d->steerForce;
        row.hi = d->steerForce;
        MdtRowWriterAdd(w, &row);
    }
    if (d->hingeForce > 0) {
        row.error = hingeRow(c, &a, &row);
        row.gamma = 0;
        row.velocity = d->hingeVelocity;
        row.lo = -d->hingeForce;
        row.hi = d->hingeForce;
        MdtRowWriterAdd(w, &row);
    }
}

static const MdtConstraintClass carWheelClass = {"CarWheel", 6, reset, rowCount, addRows, NULL, NULL};

#define CARWHEEL_OR_RETURN(c, j, ret)                                                                \
    MdtConstraintData *c = MdtConstraintFromIDOfType((j), MdtBclCARWHEEL, __func__);                     \
    if (!c)                                                                                          \
    return ret

MdtCarWheelID MdtCarWheelCreate(MdtWorldID w)
{
    MdtConstraintData *c = MdtConstraintCreateInternal(w, MdtBclCARWHEEL, &carWheelClass, __func__);
    return c ? (MdtCarWheelID)c->id : NULL;
}

void MdtCarWheelReset(MdtCarWheelID j)
{
    CARWHEEL_OR_RETURN(c, j, ME_NOTHING);
    reset(c);
}

MdtConstraintID MdtCarWheelQuaConstraint(MdtCarWheelID j) { return (MdtConstraintID)j; }

MdtCarWheelID MdtConstraintDCastCarWheel(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclCARWHEEL ? (MdtCarWheelID)c : NULL;
}

/* ---- accessors ---- */
void MdtCarWheelGetSteeringAxis(MdtCarWheelID j, MeVector3 v)
{
    CARWHEEL_OR_RETURN(c, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    MdtConstraintWorldPrimary(c, 0, v);
}

void MdtCarWheelGetHingeAxis(MdtCarWheelID j, MeVector3 v)
{
    CARWHEEL_OR_RETURN(c, j, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    MdtConstraintWorldOrthogonal(c, 1, v);
}

/* The steering angle, the hinge angle or the suspension height (or their rates) at the current poses. */
enum { STEERING, HINGE, HEIGHT };
static MeReal reading(MdtCarWheelID j, int which, MeBool wantRate, const char *function)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(j, MdtBclCARWHEEL, function);
    if (!c)
        return 0;
    if (!c->body[0]) {
        ME_REPORT_IN(function, ME_ERR_BAD_STATE, "the car wheel has no bodies yet (MdtCarWheelSetBodies)");
        return 0;
    }
    Axes a;
    MdtRow row;
    axes(c, &a);
    MeReal value = which == STEERING ? steeringRow(c, &a, &row)
                                     : (which == HINGE ? hingeRow(c, &a, &row) : heightRow(c, &a, &row));
    if (wantRate)
        return MdtRowVelocity(c, &row);
    return which == HINGE && value < 0 ? value + 2 * ME_PI : value;
}

MeReal MdtCarWheelGetSteeringAngle(MdtCarWheelID j) { return reading(j, STEERING, MEFALSE, __func__); }
MeReal MdtCarWheelGetSteeringAngleRate(MdtCarWheelID j) { return reading(j, STEERING, METRUE, __func__); }
MeReal MdtCarWheelGetHingeAngle(MdtCarWheelID j) { return reading(j, HINGE, MEFALSE, __func__); }
MeReal MdtCarWheelGetHingeAngleRate(MdtCarWheelID j) { return reading(j, HINGE, METRUE, __func__); }
MeReal MdtCarWheelGetSuspensionHeight(MdtCarWheelID j) { return reading(j, HEIGHT, MEFALSE, __func__); }
MeReal MdtCarWheelGetSuspensionRate(MdtCarWheelID j) { return reading(j, HEIGHT, METRUE, __func__); }

#define CARWHEEL_GETTER(name, type, expr)                                                            \
    type name(MdtCarWheelID j)                                                                       \
    {                                                                                                \
        CARWHEEL_OR_RETURN(c, j, 0);                                                                 \
        const CarWheelData *d = MDT_CONSTRAINT_DATA(c, const CarWheelData);                          \
        return expr;                                                                                 \
    }
CARWHEEL_GETTER(MdtCarWheelGetSteeringMotorDesiredVelocity, MeReal, d->steerVelocity)
CARWHEEL_GETTER(MdtCarWheelGetSteeringMotorMaxForce, MeReal, d->steerForce)
CARWHEEL_GETTER(MdtCarWheelIsSteeringLocked, MeBool, d->steerLock)
CARWHEEL_GETTER(MdtCarWheelGetHingeMotorDesiredVelocity, MeReal, d->hingeVelocity)
CARWHEEL_GETTER(MdtCarWheelGetHingeMotorMaxForce, MeReal, d->hingeForce)
CARWHEEL_GETTER(MdtCarWheelGetSuspensionHighLimit, MeReal, d->hi)
CARWHEEL_GETTER(MdtCarWheelGetSuspensionLowLimit, MeReal, d->lo)
CARWHEEL_GETTER(MdtCarWheelGetSuspensionLimitSoftness, MeReal, d->softness)
CARWHEEL_GETTER(MdtCarWheelGetSuspensionReference, MeReal, d->reference)
CARWHEEL_GETTER(MdtCarWheelGetSuspensionKp, MeReal, d->kp)
CARWHEEL_GETTER(MdtCarWheelGetSuspensionKd, MeReal, d->kd)

/* ---- mutators ---- */
void MdtCarWheelSetSteeringLimitedForceMotor(MdtCarWheelID j, MeReal desiredVelocity, MeReal forceLimit)
{
    CARWHEEL_OR_RETURN(c, j, ME_NOTHING);
    ME_CHECK_FINITE(desiredVelocity, ME_NOTHING);
    if (!MdtCheckNonNegative(forceLimit, "forceLimit", METRUE, __func__))
        return;
    CarWheelData *d = MDT_CONSTRAINT_DATA(c, CarWheelData);
    d->steerVelocity = desiredVelocity;
    d->steerForce = forceLimit;
}

void MdtCarWheelSetSteeringLock(MdtCarWheelID j, MeBool lock)
{
    CARWHEEL_OR_RETURN(c, j, ME_NOTHING);
    MDT_CONSTRAINT_DATA(c, CarWheelData)->steerLock = lock ? METRUE : MEFALSE;
}

void MdtCarWheelSetHingeLimitedForceMotor(MdtCarWheelID j, MeReal desiredVelocity, MeReal forceLimit)
{
    CARWHEEL_OR_RETURN(c, j, ME_NOTHING);
    ME_CHECK_FINITE(desiredVelocity, ME_NOTHING);
    if (!MdtCheckNonNegative(forceLimit, "forceLimit", METRUE, __func__))
        return;
    CarWheelData *d = MDT_CONSTRAINT_DATA(c, CarWheelData);
    d->hingeVelocity = desiredVelocity;
    d->hingeForce = forceLimit;
}

/* Size: Karma 1.2's signature. */
void MdtCarWheelSetSuspension(MdtCarWheelID j, MeReal Kp, MeReal Kd, MeReal limit_softness, MeReal lolimit,
                              MeReal hilimit, MeReal reference)
{
    CARWHEEL_OR_RETURN(c, j, ME_NOTHING);
    ME_CHECK_FINITE3(lolimit, hilimit, reference, ME_NOTHING);
    if (!MdtCheckNonNegative(Kp, "Kp", MEFALSE, __func__) || !MdtCheckNonNegative(Kd, "Kd", MEFALSE, __func__) ||
        !MdtCheckNonNegative(limit_softness, "limit_softness", MEFALSE, __func__))
        return;
    if (lolimit > hilimit) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "lolimit (%g) is above hilimit (%g); call ignored", (double)lolimit,
                  (double)hilimit);
        return;
    }
    CarWheelData *d = MDT_CONSTRAINT_DATA(c, CarWheelData);
    d->kp = Kp;
    d->kd = Kd;
    d->softness = limit_softness;
    d->lo = lolimit;
    d->hi = hilimit;
    d->reference = reference;
}
