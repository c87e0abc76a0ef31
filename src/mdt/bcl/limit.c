/* limit.c -- MdtLimit and MdtSingleLimit (their API), and the row that a limit adds for the free
 * coordinate x of a joint (hinge angle, prismatic displacement, spring length).
 *
 * The joint gives the Jacobian of x (J·v = dx/dt) and its measured value; this file decides which
 * single row, if any, to add (docs/step.md, "Limits and motors"):
 *   lock        error x − x_lock, bounds ±fmax_lock;
 *   hard stop   one-sided row (force pushes back into the range) with the speculative gap φ/h, or a
 *               bounce target e·u (u: arrival speed) when the stop is reached within the step; a
 *               motor pushing into the stop widens the bound to −fmax (it keeps pushing there);
 *   soft stop   past the stop, a one-sided spring-damper row (ε, γ and target from k, d, h: SPOOK);
 *   both stops  (a range narrower than one step's motion, or a spring's two coinciding soft stops):
 *               one two-sided row;
 *   motor       otherwise: target the desired rate, bounds ±fmax.
 * A motor pushing away from a hard stop it sits on drives the coordinate with its own row; if it
 * saturates and still sinks into the stop it is marked stalled, and the next steps write the stop
 * row with the motor's force as the lower bound (the stop adds what the motor lacks) until the stop
 * no longer needs to push. One row per limit, as in Karma. */
#include <string.h>

#include "../../me/check.h"
#include "limit_internal.h"

#define LIMIT_MAGIC 0x4C696D74u
/* Arrival speed (coordinate units per second) below which a hard stop does not bounce: resting
 * bodies would otherwise hop at every step. */
#define BOUNCE_THRESHOLD ME_R(1e-3)
/* The row written this step (rowKind). */
enum { ROW_NONE, ROW_LOCK, ROW_MOTOR, ROW_STOP, ROW_TWO_SIDED, ROW_MOTOR_AT_STOP0, ROW_MOTOR_AT_STOP1,
       ROW_STALLED0, ROW_STALLED1 };

/* ---- single limits -------------------------------------------------------------------------- */
static void singleDefaults(MdtSingleLimit *sl)
{
    sl->stop = 0;
    sl->stiffness = MEINFINITY;
    sl->damping = 0;
    sl->restitution = 1;
}

static MeBool checkStiffness(MeReal k, const char *function)
{
    if (k != k || k < 0) {
        ME_REPORT_IN(function, k < 0 ? ME_ERR_NEGATIVE_VALUE : ME_ERR_NONFINITE_ARGUMENT,
                     "argument 'stiffness' is %g; it must be zero or positive (MEINFINITY: hard); call ignored",
                     (double)k);
        return MEFALSE;
    }
    return METRUE;
}

static MeBool checkDamping(MeReal d, const char *function)
{
    if (!ME_IS_FINITE(d) || d < 0) {
        ME_REPORT_IN(function, ME_IS_FINITE(d) ? ME_ERR_NEGATIVE_DAMPING : ME_ERR_NONFINITE_ARGUMENT,
                     "argument 'damping' is %g; it must be finite and zero or positive; call ignored", (double)d);
        return MEFALSE;
    }
    return METRUE;
}

static MeBool checkRestitution(MeReal e, const char *function)
{
    if (!(e >= 0 && e <= 1)) {
        ME_REPORT_IN(function, ME_IS_FINITE(e) ? ME_ERR_ARGUMENT_RANGE : ME_ERR_NONFINITE_ARGUMENT,
                     "argument 'restitution' is %g; it must lie in 0 ... 1; call ignored", (double)e);
        return MEFALSE;
    }
    return METRUE;
}

static MeBool checkSingle(const MdtSingleLimit *sl, const char *function)
{
    if (!sl) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument 'sl' is NULL; call ignored");
        return MEFALSE;
    }
    if (!ME_IS_FINITE(sl->stop)) {
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT, "the stop is %g (not finite); call ignored",
                     (double)sl->stop);
        return MEFALSE;
    }
    return checkStiffness(sl->stiffness, function) && checkDamping(sl->damping, function) &&
           checkRestitution(sl->restitution, function);
}

void MdtSingleLimitReset(MdtSingleLimitID sl)
{
    ME_CHECK_NOT_NULL(sl, ME_NOTHING);
    singleDefaults(sl);
}

MeReal MdtSingleLimitGetStop(const MdtSingleLimit *sl)
{
    ME_CHECK_NOT_NULL(sl, 0);
    return sl->stop;
}

MeReal MdtSingleLimitGetStiffness(const MdtSingleLimit *sl)
{
    ME_CHECK_NOT_NULL(sl, 0);
    return sl->stiffness;
}

MeReal MdtSingleLimitGetDamping(const MdtSingleLimit *sl)
{
    ME_CHECK_NOT_NULL(sl, 0);
    return sl->damping;
}

MeReal MdtSingleLimitGetRestitution(const MdtSingleLimit *sl)
{
    ME_CHECK_NOT_NULL(sl, 0);
    return sl->restitution;
}

void MdtSingleLimitSetStop(MdtSingleLimitID sl, MeReal stop)
{
    ME_CHECK_NOT_NULL(sl, ME_NOTHING);
    ME_CHECK_FINITE(stop, ME_NOTHING);
    sl->stop = stop;
}

void MdtSingleLimitSetStiffness(MdtSingleLimitID sl, MeReal stiffness)
{
    ME_CHECK_NOT_NULL(sl, ME_NOTHING);
    if (checkStiffness(stiffness, __func__))
        sl->stiffness = stiffness;
}

void MdtSingleLimitSetDamping(MdtSingleLimitID sl, MeReal damping)
{
    ME_CHECK_NOT_NULL(sl, ME_NOTHING);
    if (checkDamping(damping, __func__))
        sl->damping = damping;
}

void MdtSingleLimitSetRestitution(MdtSingleLimitID sl, MeReal restitution)
{
    ME_CHECK_NOT_NULL(sl, ME_NOTHING);
    if (checkRestitution(restitution, __func__))
        sl->restitution = restitution;
}

/* ---- limits: state ---------------------------------------------------------------------------- */
static void clearState(MdtLimit *l)
{
    MDT_LIMIT_MEASURED(l) = 0;
    l->position = l->offset;
    l->velocity = 0;
    l->overshoot = 0;
    MDT_LIMIT_PENDING_BOUNCE(l) = 0;
    MDT_LIMIT_ROW(l) = -1;
    MDT_LIMIT_ROW_KIND(l) = ROW_NONE;
    MDT_LIMIT_STALLED(l) = MEFALSE;
}

void MdtLimitInit(MdtLimit *l)
{
    memset(l, 0, sizeof *l);
    singleDefaults(&l->limit[0]);
    singleDefaults(&l->limit[1]);
    l->stiffness_threshold = MEINFINITY;
    l->fmax_lock = MEINFINITY;
    clearState(l);
    MDT_LIMIT_MAGIC(l) = LIMIT_MAGIC;
}

MeBool MdtLimitCheckOrder(const MdtLimit *l, MeReal lower, MeReal upper, const char *function)
{
    if (l->limited && lower > upper) {
        ME_REPORT_IN(function, ME_ERR_LIMIT_ORDER,
                     "the lower stop (%g) would lie above the upper stop (%g) of an active limit; call ignored",
                     (double)lower, (double)upper);
        return MEFALSE;
    }
    return METRUE;
}

MdtLimit *MdtLimitCheck(const MdtLimit *l, const char *function)
{
    if (!l) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "argument 'l' (the limit) is NULL; call ignored");
        return NULL;
    }
    if (MDT_LIMIT_MAGIC(l) != LIMIT_MAGIC) {
        ME_REPORT_IN(function, ME_ERR_BAD_STATE,
                     "the limit was not initialised by MdtLimitReset (or its joint was destroyed); call ignored");
        return NULL;
    }
    return (MdtLimit *)l;
}

void MdtLimitCopySettings(MdtLimit *dst, const MdtLimit *src)
{
    dst->limit[0] = src->limit[0];
    dst->limit[1] = src->limit[1];
    dst->stiffness_threshold = src->stiffness_threshold;
    dst->desired_velocity = src->desired_velocity;
    dst->fmax = src->fmax;
    dst->position_lock = src->position_lock;
    dst->fmax_lock = src->fmax_lock;
    dst->limited = src->limited;
    dst->calculate_position = src->calculate_position;
    dst->powered = src->powered;
    dst->locked = src->locked;
}

MeReal MdtLimitUnwrap(const MdtLimit *l, MeReal angle)
{
    const MeReal twoPi = 2 * ME_PI;
    MeReal d = angle - MDT_LIMIT_MEASURED(l);
    d -= twoPi * ME_LIBM_(floor)(d / twoPi + ME_R(0.5));
    return MDT_LIMIT_MEASURED(l) + d;
}

void MdtLimitSetMeasured(MdtLimit *l, MeReal measured, MeReal rate)
{
    MDT_LIMIT_MEASURED(l) = measured;
    l->position = measured + l->offset;
    l->velocity = rate;
    l->overshoot = 0;
    if (l->limited) {
        if (l->position > l->limit[1].stop)
            l->overshoot = l->position - l->limit[1].stop;
        else if (l->position < l->limit[0].stop)
            l->overshoot = l->position - l->limit[0].stop;
    }
}

/* ---- limits: API ------------------------------------------------------------------------------ */
#define LIMIT_OR_RETURN(var, l, ret)                                                                 \
    MdtLimit *var = MdtLimitCheck((l), __func__);                                                    \
    if (!var)                                                                                        \
    return ret

void MdtLimitReset(MdtLimitID l)
{
    ME_CHECK_NOT_NULL(l, ME_NOTHING);
    MdtLimitInit(l);
}

void MdtLimitResetState(MdtLimitID l)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    clearState(m);
}

MeBool MdtLimitIsActive(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, MEFALSE);
    return m->limited;
}

MeBool MdtLimitPositionIsCalculated(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, MEFALSE);
    return m->calculate_position || m->limited;
}

MdtSingleLimitID MdtLimitGetLowerLimit(MdtLimitID l)
{
    LIMIT_OR_RETURN(m, l, NULL);
    return &m->limit[0];
}

MdtSingleLimitID MdtLimitGetUpperLimit(MdtLimitID l)
{
    LIMIT_OR_RETURN(m, l, NULL);
    return &m->limit[1];
}

MeReal MdtLimitGetPosition(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, 0);
    return m->position;
}

MeReal MdtLimitGetVelocity(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, 0);
    return m->velocity;
}

MeReal MdtLimitGetOvershoot(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, 0);
    return m->overshoot;
}

MeReal MdtLimitGetStiffnessThreshold(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, 0);
    return m->stiffness_threshold;
}

MeBool MdtLimitIsMotorized(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, MEFALSE);
    return m->powered;
}

MeBool MdtLimitIsLocked(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, MEFALSE);
    return m->locked;
}

MeReal MdtLimitGetMotorDesiredVelocity(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, 0);
    return m->desired_velocity;
}

MeReal MdtLimitGetMotorMaxForce(const MdtLimit *l)
{
    LIMIT_OR_RETURN(m, l, 0);
    return m->fmax;
}

void MdtLimitSetLowerLimit(MdtLimitID l, const MdtSingleLimit *sl)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    if (checkSingle(sl, __func__) && MdtLimitCheckOrder(m, sl->stop, m->limit[1].stop, __func__))
        m->limit[0] = *sl;
}

void MdtLimitSetUpperLimit(MdtLimitID l, const MdtSingleLimit *sl)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    if (checkSingle(sl, __func__) && MdtLimitCheckOrder(m, m->limit[0].stop, sl->stop, __func__))
        m->limit[1] = *sl;
}

void MdtLimitSetPosition(MdtLimitID l, MeReal position)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    ME_CHECK_FINITE(position, ME_NOTHING);
    m->offset = position - MDT_LIMIT_MEASURED(m);
    m->position = position;
}

void MdtLimitActivateLimits(MdtLimitID l, MeBool on)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    if (on && m->limit[0].stop > m->limit[1].stop) {
        ME_REPORT(ME_ERR_LIMIT_ORDER,
                  "the lower stop (%g) lies above the upper stop (%g): set the stops in order first; the limits "
                  "stay inactive", (double)m->limit[0].stop, (double)m->limit[1].stop);
        return;
    }
    m->limited = on ? METRUE : MEFALSE;
}

void MdtLimitCalculatePosition(MdtLimitID l, MeBool on)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    m->calculate_position = on ? METRUE : MEFALSE;
}

void MdtLimitSetStiffnessThreshold(MdtLimitID l, MeReal threshold)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    if (threshold != threshold || threshold <= 0) {
        ME_REPORT(threshold != threshold ? ME_ERR_NONFINITE_ARGUMENT : ME_ERR_ARGUMENT_RANGE,
                  "argument 'threshold' is %g; it must be positive (MEINFINITY allowed); call ignored",
                  (double)threshold);
        return;
    }
    m->stiffness_threshold = threshold;
}

void MdtLimitActivateMotor(MdtLimitID l, MeBool on)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    m->powered = on ? METRUE : MEFALSE;
    if (on)
        m->locked = MEFALSE;
}

MeBool MdtCheckNonNegative(MeReal x, const char *name, MeBool infiniteAllowed, const char *function)
{
    if (x != x || x < 0 || (!infiniteAllowed && x >= MEINFINITY)) {
        ME_REPORT_IN(function, x < 0 ? ME_ERR_NEGATIVE_VALUE : ME_ERR_NONFINITE_ARGUMENT,
                     "argument '%s' is %g; it must be %szero or positive; call ignored", name, (double)x,
                     infiniteAllowed ? "" : "finite and ");
        return MEFALSE;
    }
    return METRUE;
}

void MdtLimitSetLimitedForceMotor(MdtLimitID l, MeReal desiredVelocity, MeReal maxForce)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    ME_CHECK_FINITE(desiredVelocity, ME_NOTHING);
    if (!MdtCheckNonNegative(maxForce, "maxForce", METRUE, __func__))
        return;
    m->desired_velocity = desiredVelocity;
    m->fmax = maxForce;
    m->powered = maxForce > 0 ? METRUE : MEFALSE;
    if (m->powered)
        m->locked = MEFALSE;
}

void MdtLimitActivateLock(MdtLimitID l, MeBool on)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    m->locked = on ? METRUE : MEFALSE;
    if (on)
        m->powered = MEFALSE;
}

void MdtLimitSetLock(MdtLimitID l, MeReal position, MeReal maxForce)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    ME_CHECK_FINITE(position, ME_NOTHING);
    if (!MdtCheckNonNegative(maxForce, "maxForce", METRUE, __func__))
        return;
    m->position_lock = position;
    m->fmax_lock = maxForce;
}

void MdtLimitController(MdtLimitID l, MeReal desiredPos, MeReal gap, MeReal maxSpeed, MeReal maxForce)
{
    LIMIT_OR_RETURN(m, l, ME_NOTHING);
    ME_CHECK_FINITE(desiredPos, ME_NOTHING);
    if (!(ME_IS_FINITE(gap) && gap > 0)) {
        ME_REPORT(ME_IS_FINITE(gap) ? ME_ERR_ARGUMENT_RANGE : ME_ERR_NONFINITE_ARGUMENT,
                  "argument 'gap' is %g; it must be positive and finite; call ignored", (double)gap);
        return;
    }
    if (!MdtCheckNonNegative(maxSpeed, "maxSpeed", MEFALSE, __func__) ||
        !MdtCheckNonNegative(maxForce, "maxForce", METRUE, __func__))
        return;
    MeReal v = maxSpeed * (desiredPos - m->position) / gap;
    if (v > maxSpeed)
        v = maxSpeed;
    if (v < -maxSpeed)
        v = -maxSpeed;
    m->desired_velocity = v;
    m->fmax = maxForce;
    m->powered = METRUE;
    m->locked = MEFALSE;
}

/* ---- rows ------------------------------------------------------------------------------------- */
static MeReal dot3(const MeReal *a, const MeReal *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

MeReal MdtRowVelocity(const MdtConstraintData *c, const MdtRow *row)
{
    const MdtBodyData *b0 = c->body[0], *b1 = c->body[1];
    MeReal v = dot3(row->lin0, b0->vel) + dot3(row->ang0, b0->velrot);
    if (b1)
        v += dot3(row->lin1, b1->vel) + dot3(row->ang1, b1->velrot);
    else
        v += dot3(row->lin1, c->worldLinearVelocity) + dot3(row->ang1, c->worldAngularVelocity);
    return v;
}

MeReal MdtRowPredictedVelocity(const MdtConstraintData *c, const MdtRow *row)
{
    const MdtBodyData *b0 = c->body[0], *b1 = c->body[1];
    MeReal v = dot3(row->lin0, b0->velStar) + dot3(row->ang0, b0->velrotStar);
    if (b1)
        v += dot3(row->lin1, b1->velStar) + dot3(row->ang1, b1->velrotStar);
    else
        v += dot3(row->lin1, c->worldLinearVelocity) + dot3(row->ang1, c->worldAngularVelocity);
    return v;
}

/* SPOOK for a spring of stiffness k and damping d on the row's coordinate x (docs/step.md): with
 * θ = 1/4 and D = θ h k + d,
 *     J v⁺ + λ/(h D) = (θ h k / D) J v − (h k / D) φ/h,
 * i.e. ε = 1/(h D), γ = h k / D, target = Υ J v with Υ = θ h k / D (v: start-of-step velocities).
 * In equilibrium λ/h = −k φ exactly; undamped it oscillates without numerical damping at the
 * frequency 2 atan(ω h/2)/h (the trapezoidal rule's), for any k. */
void MdtRowMakeSpring(MdtRow *row, const MdtConstraintData *c, MeReal k, MeReal d, MeReal displacement, MeReal h)
{
    const MeReal theta = ME_R(0.25);
    MeReal D = theta * h * k + d;
    row->epsilon = 1 / (h * D);
    row->noWorldEpsilon = METRUE;
    row->gamma = h * k / D;
    row->error = displacement;
    row->velocity = (theta * h * k / D) * MdtRowVelocity(c, row);
}

MeBool MdtLimitMayAddRow(const MdtLimit *l)
{
    return l->locked || l->limited || (l->powered && l->fmax > 0);
}

static MeBool sideExists(const MdtSingleLimit *sl) { return sl->stiffness > 0 || sl->damping > 0; }

static MeBool isHard(const MdtLimit *l, int side) { return l->limit[side].stiffness >= l->stiffness_threshold; }

/* A hard stop reached within this step: bounce target or speculative landing (as contacts do: a
 * stop closer than e·u·h/(1 + 2e) bounces now, a farther one lands first and bounces next step). */
static void hardStopRow(MdtLimit *l, MdtRowWriter *w, MdtRow *row, int side, MeReal x, MeReal rate)
{
    const MeReal sigma = side == 0 ? 1 : -1, h = w->h, e = l->limit[side].restitution;
    const MeReal phi = sigma * (x - l->limit[side].stop); /* ≥ 0 inside the range */
    MeReal u = -sigma * rate;                             /* arrival speed */
    if (MDT_LIMIT_PENDING_BOUNCE(l) > u)
        u = MDT_LIMIT_PENDING_BOUNCE(l);
    if (!w->captured)
        MDT_LIMIT_PENDING_BOUNCE(l) = 0;
    row->error = x - l->limit[side].stop;
    row->gamma = phi > 0 ? 1 : -1; /* close a gap exactly; correct a penetration at the world's rate */
    if (e > 0 && u > BOUNCE_THRESHOLD && u * h >= phi) {
        if (phi <= 0 || phi * (1 + 2 * e) <= e * u * h) {
            MeReal correction = phi < 0 ? -w->gamma * phi / h : 0, bounce = e * u;
            row->velocity = sigma * (bounce > correction ? bounce : correction);
            row->gamma = 0;
            row->noWorldEpsilon = METRUE; /* the world's softness would absorb part of the bounce */
            row->epsilon = ME_R(1e-3) * w->epsilon0;
        } else if (!w->captured) {
            MDT_LIMIT_PENDING_BOUNCE(l) = u;
        }
    }
    row->lo = side == 0 ? 0 : -MEINFINITY;
    row->hi = side == 0 ? MEINFINITY : 0;
}

/* Which stops need a row this step (need[0] lower, need[1] upper): a hard stop the joint reaches
 * within the step at its predicted speed, a soft one it is past. Crossed stops (set one at a time
 * through MdtSingleLimitSetStop) bound no range and are not applied; reported once until they are put
 * in order. */
static void stopsNeeded(MdtLimit *l, const MdtRowWriter *w, const MdtRow *jacobian, MeReal x, MeBool need[2])
{
    const MeBool capture = w->captured != NULL;
    const MeBool crossed = l->limited && l->limit[0].stop > l->limit[1].stop;
    if (crossed && !capture && !MDT_LIMIT_ORDER_REPORTED(l))
        ME_REPORT_IN("MdtWorldStep", ME_ERR_LIMIT_ORDER,
                     "a joint's lower stop (%g) lies above its upper stop (%g); its stops are not applied until "
                     "they are in order", (double)l->limit[0].stop, (double)l->limit[1].stop);
    if (!capture)
        MDT_LIMIT_ORDER_REPORTED(l) = crossed;
    if (!l->limited || crossed)
        return;
    const MeReal vstar = MdtRowPredictedVelocity(w->constraint, jacobian), h = w->h;
    for (int s = 0; s < 2; s++) {
        if (!sideExists(&l->limit[s]))
            continue;
        MeReal sigma = s == 0 ? 1 : -1, phi = sigma * (x - l->limit[s].stop), approach = -sigma * vstar;
        need[s] = isHard(l, s) ? phi <= h * (approach > 0 ? approach : 0) : phi < 0;
    }
    /* Two stops at one place (a spring's natural length, a rod): one two-sided row. */
    if (sideExists(&l->limit[0]) && sideExists(&l->limit[1]) && l->limit[1].stop <= l->limit[0].stop)
        need[0] = need[1] = METRUE;
}

/* The row at stop s alone (soft: a spring; hard: a stop, with the motor driving away from it or
 * pushing into it); returns the row's kind. */
static int oneStopRow(MdtLimit *l, MdtRowWriter *w, MdtRow *row, int s, MeReal x, MeReal rate)
{
    const MeBool motor = l->powered && l->fmax > 0;
    const MeReal sigma = s == 0 ? 1 : -1;
    if (!isHard(l, s)) {
        MdtRowMakeSpring(row, w->constraint, l->limit[s].stiffness, l->limit[s].damping, x - l->limit[s].stop, w->h);
        row->lo = s == 0 ? 0 : -MEINFINITY;
        row->hi = s == 0 ? MEINFINITY : 0;
        return ROW_STOP;
    }
    if (motor && sigma * l->desired_velocity > 0 && !MDT_LIMIT_STALLED(l)) {
        /* The motor drives away from the stop: let it, unless it stalled there last step. */
        row->velocity = l->desired_velocity;
        row->lo = -l->fmax;
        row->hi = l->fmax;
        return s == 0 ? ROW_MOTOR_AT_STOP0 : ROW_MOTOR_AT_STOP1;
    }
    hardStopRow(l, w, row, s, x, rate);
    if (motor && sigma * l->desired_velocity > 0) {
        /* Stalled: the motor pushes away with all it has; the stop supplies the rest. */
        if (s == 0)
            row->lo = l->fmax;
        else
            row->hi = -l->fmax;
        return s == 0 ? ROW_STALLED0 : ROW_STALLED1;
    }
    /* A motor pushing into the stop (or holding still) keeps pushing with up to fmax. */
    if (motor && s == 0)
        row->lo = -l->fmax;
    else if (motor)
        row->hi = l->fmax;
    return ROW_STOP;
}

void MdtLimitAddRow(MdtLimit *l, MdtRowWriter *w, const MdtRow *jacobian, MeReal measured)
{
    MdtConstraintData *c = w->constraint;
    const MeReal x = measured + l->offset, rate = MdtRowVelocity(c, jacobian), h = w->h;
    const MeBool capture = w->captured != NULL;
    if (!capture) {
        MdtLimitSetMeasured(l, measured, rate);
        MDT_LIMIT_ROW(l) = -1;
        MDT_LIMIT_ROW_KIND(l) = ROW_NONE;
    }
    MdtRow row = *jacobian;
    row.error = x; /* rows without a position error still carry x, so Jacobian checks see dx/dt */
    row.gamma = 0;
    int kind = ROW_NONE;
    const MeBool motor = l->powered && l->fmax > 0;

    if (l->locked) {
        if (l->fmax_lock <= 0)
            return;
        row.error = x - l->position_lock;
        row.gamma = -1;
        row.lo = -l->fmax_lock;
        row.hi = l->fmax_lock;
        kind = ROW_LOCK;
    } else {
        MeBool need[2] = {MEFALSE, MEFALSE};
        stopsNeeded(l, w, jacobian, x, need);
        if (need[0] && need[1]) {
            int s = x < l->limit[0].stop ? 0 : 1;
            if (isHard(l, 0) || isHard(l, 1)) {
                /* Rigid: hold x within the (narrow) range. */
                MeReal lo = l->limit[0].stop, hi = l->limit[1].stop;
                row.error = x < lo ? x - lo : (x > hi ? x - hi : 0);
                row.gamma = -1;
            } else {
                MdtRowMakeSpring(&row, c, l->limit[s].stiffness, l->limit[s].damping, x - l->limit[s].stop, h);
            }
            kind = ROW_TWO_SIDED;
        } else if (need[0] || need[1]) {
            kind = oneStopRow(l, w, &row, need[0] ? 0 : 1, x, rate);
        } else if (motor) {
            row.velocity = l->desired_velocity;
            row.lo = -l->fmax;
            row.hi = l->fmax;
            kind = ROW_MOTOR;
        }
        if (!capture && !need[0] && !need[1])
            MDT_LIMIT_STALLED(l) = MEFALSE;
    }
    if (kind == ROW_NONE)
        return;
    int index = MdtRowWriterAdd(w, &row);
    if (!capture) {
        MDT_LIMIT_ROW(l) = index;
        MDT_LIMIT_ROW_KIND(l) = kind;
    }
}

void MdtLimitUnpack(MdtLimit *l, const MeReal *impulses, int rows, MeReal h)
{
    if (MDT_LIMIT_ROW(l) < 0 || MDT_LIMIT_ROW(l) >= rows)
        return;
    const int kind = MDT_LIMIT_ROW_KIND(l);
    const MeReal sigma = (kind == ROW_MOTOR_AT_STOP1 || kind == ROW_STALLED1) ? -1 : 1;
    const MeReal x = sigma * impulses[MDT_LIMIT_ROW(l)], cap = l->fmax * h; /* x: pushing away from the stop */
    if (kind == ROW_MOTOR_AT_STOP0 || kind == ROW_MOTOR_AT_STOP1) {
        /* saturated and still sinking into the stop */
        if (x >= cap * ME_R(0.999) && sigma * l->velocity < 0)
            MDT_LIMIT_STALLED(l) = METRUE;
    } else if (kind == ROW_STALLED0 || kind == ROW_STALLED1) {
        /* the stop no longer had to add to the motor */
        if (x <= cap * ME_R(1.001))
            MDT_LIMIT_STALLED(l) = MEFALSE;
    }
}
