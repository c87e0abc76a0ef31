/* limit_internal.h -- the limit/motor row of a joint's free coordinate, and the soft-row mapping
 * (internal; shared by the hinge, prismatic, spring and car wheel). See limit.c and docs/step.md. */
#ifndef MDT_LIMIT_INTERNAL_H
#define MDT_LIMIT_INTERNAL_H

#include <karma/MdtLimit.h>

#include "../constraint.h"

/* The fields of a limit's private bookkeeping (MdtLimitPrivate in MdtLimit.h), by name. */
#define MDT_LIMIT_MEASURED(l) ((l)->private_.reals_[0])       /* the measured coordinate, unwrapped */
#define MDT_LIMIT_PENDING_BOUNCE(l) ((l)->private_.reals_[1]) /* arrival speed to bounce with next step */
#define MDT_LIMIT_ROW(l) ((l)->private_.ints_[0])             /* this step's limit row in the joint, or -1 */
#define MDT_LIMIT_ROW_KIND(l) ((l)->private_.ints_[1])        /* what that row was (limit.c) */
#define MDT_LIMIT_STALLED(l) ((l)->private_.ints_[2])         /* the motor cannot lift off its stop */
#define MDT_LIMIT_ORDER_REPORTED(l) ((l)->private_.ints_[3]) /* its crossed stops were reported */
#define MDT_LIMIT_MAGIC(l) ((l)->private_.word_)              /* set by MdtLimitReset */

/** Reject (report in `function`'s name) a NaN or negative `x` named `name`, or an infinite one unless
 *  `infiniteAllowed` (MEINFINITY = no bound). */
MeBool MdtCheckNonNegative(MeReal x, const char *name, MeBool infiniteAllowed, const char *function);
/** Initialise a limit embedded in a joint (MdtLimitReset without the argument check). */
void MdtLimitInit(MdtLimit *l);
/** Resolve a limit passed by the application: NULL or uninitialised ones are reported (in
 *  `function`'s name) and give NULL. */
MdtLimit *MdtLimitCheck(const MdtLimit *l, const char *function);
/** Whether stops `lower` and `upper` may be set on `l`: refused (ME_ERR_LIMIT_ORDER, reported in
 *  `function`'s name) when l is active and lower > upper. */
MeBool MdtLimitCheckOrder(const MdtLimit *l, MeReal lower, MeReal upper, const char *function);
/** Copy settings (stops, threshold, motor, lock, activation) from `src` into `dst`, keeping dst's state. */
void MdtLimitCopySettings(MdtLimit *dst, const MdtLimit *src);

/** The measured angle, unwrapped: the value congruent to `angle` (mod 2π) nearest the last one. */
MeReal MdtLimitUnwrap(const MdtLimit *l, MeReal angle);
/** Record the measured coordinate and its rate (updates position, velocity, overshoot). */
void MdtLimitSetMeasured(MdtLimit *l, MeReal measured, MeReal rate);

/** Constraint velocity J·v of `row` with the bodies' velocities at the start of the step (and the
 *  world's velocity when body 1 is the world). */
MeReal MdtRowVelocity(const MdtConstraintData *c, const MdtRow *row);

/** The same with the predicted velocities v* (this step's external forces applied). */
MeReal MdtRowPredictedVelocity(const MdtConstraintData *c, const MdtRow *row);

/** A spring-damper row (stiffness k ≥ 0, damping d ≥ 0, not both 0) on the row's coordinate, whose
 *  displacement from rest is `displacement`: sets the row's ε, γ and target velocity (SPOOK). */
void MdtRowMakeSpring(MdtRow *row, const MdtConstraintData *c, MeReal k, MeReal d, MeReal displacement, MeReal h);

/** Whether the limit may write a row this step (an upper bound for row counts). */
MeBool MdtLimitMayAddRow(const MdtLimit *l);
/** Write the limit's row, if any, for a coordinate whose Jacobian is in `jacobian` (J·v = rate of the
 *  measured coordinate) and whose measured value is `measured` (already unwrapped). Updates the
 *  limit's state (except when the writer only captures rows). */
void MdtLimitAddRow(MdtLimit *l, MdtRowWriter *w, const MdtRow *jacobian, MeReal measured);
/** After the solve: the limit row's impulse (for the motor's stall detection). `impulses` are the
 *  joint's rows. */
void MdtLimitUnpack(MdtLimit *l, const MeReal *impulses, int rows, MeReal h);

#endif /* MDT_LIMIT_INTERNAL_H */
