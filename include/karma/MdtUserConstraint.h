/* MdtUserConstraint.h -- a constraint whose rows the application writes.
 *
 * Each step, for each enabled user constraint in a partition being solved, the world calls the
 * constraint's MdtUserConstraintRowsFn. The function fills up to `maxRows` rows and returns how many it
 * wrote. A row constrains one scalar combination of the two bodies' velocities, its constraint
 * velocity
 *
 *     J·v = linear0·v0 + angular0·ω0 + linear1·v1 + angular1·ω1
 *
 * (world frame; v the velocity of a body's centre of mass, ω its angular velocity). Write the row as
 * the time derivative of a constraint function φ(poses) that is 0 when satisfied: for a point at
 * lever arm r from a body's centre of mass (MdtBodyGetCenterOfMassPosition) moving along a unit
 * direction n, the linear part is n and the angular part r × n. Then give φ's present value as
 * `error`: the solver asks J·v⁺ = velocity − γ·error/h after the step, within the force bounds, so
 * drift is corrected at the world's γ per step. With a finite `stiffness` the row is a spring-damper
 * on φ instead (force ≈ −stiffness·φ − damping·(J·v − velocity); the discretisation of docs/step.md).
 * When body 1 is the world, linear1 and angular1 multiply the constraint's world velocities
 * (MdtConstraintSetWorldLinearVelocity/AngularVelocity), normally zero.
 *
 * The function runs inside MdtWorldStep (the world is locked: it may read bodies, not create or
 * destroy anything). Rows that are not finite, or whose bounds are crossed (lo > hi), are reported
 * (ME_ERR_NONFINITE_ARGUMENT, ME_ERR_ARGUMENT_RANGE) and left out. The force each row applied in the
 * last step is MdtUserConstraintGetRowForce.
 * Defaults: no function (no rows), no constraint struct, at most 6 rows per step. */
#ifndef MDT_USERCONSTRAINT_H
#define MDT_USERCONSTRAINT_H

#include "MdtConstraint.h"

ME_EXTERN_C_BEGIN

/** A new disabled user constraint, or NULL (reported) when the world's constraint pool is full. */
ME_API MdtUserConstraintID MdtUserConstraintCreate(MdtWorldID w);
/** Restore the defaults (bodies kept). */
ME_API void MdtUserConstraintReset(MdtUserConstraintID j);
/** The joint as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtUserConstraintQuaConstraint(MdtUserConstraintID j);
/** The user constraint behind a constraint ID, or NULL if it is of another type. */
ME_API MdtUserConstraintID MdtConstraintDCastUserConstraint(MdtConstraintID c);

/** Most rows a user constraint may write per step. */
#define MDT_USER_CONSTRAINT_MAX_ROWS 16

/** One row, as the application's function writes it. The rows it receives are already set to the
 *  defaults: Jacobian 0, velocity 0, error 0, bounds ±MEINFINITY (an equality), stiffness MEINFINITY
 *  (rigid), damping 0. */
typedef struct MdtUserConstraintRow {
    MeVector3 linear0, angular0; /**< Jacobian on body 0 (world frame) */
    MeVector3 linear1, angular1; /**< Jacobian on body 1 */
    MeReal velocity;             /**< desired constraint velocity (row units per second) */
    MeReal error;                /**< present value of the constraint function φ (row units) */
    MeReal lo, hi;               /**< force bounds, N (or N·m): lo = 0 for a row that only pushes */
    MeReal stiffness, damping;   /**< MEINFINITY: rigid; finite: spring-damper on φ (≥ 0) */
} MdtUserConstraintRow;

/** The step's solver parameters, given to the function. */
typedef struct MdtBclSolverParameters {
    MeReal stepsize; /**< h, s */
    MeReal epsilon;  /**< the world's ε */
    MeReal gamma;    /**< the world's γ */
} MdtBclSolverParameters;

/** Writes the rows of `constraint` into rows[0 ... maxRows−1] and returns how many (0 ... maxRows).
 *  `constraintStruct` is what MdtUserConstraintSetConstraintStruct gave. */
typedef int (*MdtUserConstraintRowsFn)(MdtUserConstraintID constraint, MdtUserConstraintRow *rows, int maxRows,
                                     const MdtBclSolverParameters *params, void *constraintStruct);

/** The function that writes the rows (NULL: none, the constraint writes no rows). */
ME_API void MdtUserConstraintSetAddConstraintFunction(MdtUserConstraintID j, MdtUserConstraintRowsFn fn);
/** The row-writing function, or NULL (also for an invalid ID). */
ME_API MdtUserConstraintRowsFn MdtUserConstraintGetAddConstraintFunction(MdtUserConstraintID j);
/** The application's data for the function. */
ME_API void MdtUserConstraintSetConstraintStruct(MdtUserConstraintID j, void *constraintStruct);
/** The application's data for the function (owned by the application), or NULL. */
ME_API void *MdtUserConstraintGetConstraintStruct(MdtUserConstraintID j);
/** Most rows the function may write per step (1 ... MDT_USER_CONSTRAINT_MAX_ROWS; default 6). */
ME_API void MdtUserConstraintSetMaxRows(MdtUserConstraintID j, int maxRows);
/** Most rows the function may write per step; 0 for an invalid ID. */
ME_API int MdtUserConstraintGetMaxRows(MdtUserConstraintID j);
/** Force (N or N·m: impulse / h) that row `row` applied in the last step; 0 for rows not written. */
ME_API MeReal MdtUserConstraintGetRowForce(MdtUserConstraintID j, int row);

/* The common constraint API under this type's names. */
#define MdtUserConstraintDestroy(j) MdtConstraintDestroy(MdtUserConstraintQuaConstraint(j))
#define MdtUserConstraintEnable(j) MdtConstraintEnable(MdtUserConstraintQuaConstraint(j))
#define MdtUserConstraintDisable(j) MdtConstraintDisable(MdtUserConstraintQuaConstraint(j))
#define MdtUserConstraintIsEnabled(j) MdtConstraintIsEnabled(MdtUserConstraintQuaConstraint(j))
#define MdtUserConstraintSetBodies(j, b1, b2) MdtConstraintSetBodies(MdtUserConstraintQuaConstraint(j), (b1), (b2))
#define MdtUserConstraintGetBody(j, i) MdtConstraintGetBody(MdtUserConstraintQuaConstraint(j), (i))
#define MdtUserConstraintSetPosition(j, x, y, z) MdtConstraintSetPosition(MdtUserConstraintQuaConstraint(j), (x), (y), (z))
#define MdtUserConstraintGetPosition(j, p) MdtConstraintGetPosition(MdtUserConstraintQuaConstraint(j), (p))
#define MdtUserConstraintSetAxis(j, x, y, z) MdtConstraintSetAxis(MdtUserConstraintQuaConstraint(j), (x), (y), (z))
#define MdtUserConstraintSetAxes(j, px, py, pz, ox, oy, oz) MdtConstraintSetAxes(MdtUserConstraintQuaConstraint(j), (px), (py), (pz), (ox), (oy), (oz))
#define MdtUserConstraintGetAxes(j, p, o) MdtConstraintGetAxes(MdtUserConstraintQuaConstraint(j), (p), (o))
#define MdtUserConstraintGetForce(j, i, f) MdtConstraintGetForce(MdtUserConstraintQuaConstraint(j), (i), (f))
#define MdtUserConstraintGetTorque(j, i, t) MdtConstraintGetTorque(MdtUserConstraintQuaConstraint(j), (i), (t))
#define MdtUserConstraintSetUserData(j, d) MdtConstraintSetUserData(MdtUserConstraintQuaConstraint(j), (d))
#define MdtUserConstraintGetUserData(j) MdtConstraintGetUserData(MdtUserConstraintQuaConstraint(j))
#define MdtUserConstraintSetSortKey(j, k) MdtConstraintSetSortKey(MdtUserConstraintQuaConstraint(j), (k))
#define MdtUserConstraintGetSortKey(j) MdtConstraintGetSortKey(MdtUserConstraintQuaConstraint(j))
#define MdtUserConstraintGetWorld(j) MdtConstraintGetWorld(MdtUserConstraintQuaConstraint(j))
#define MdtUserConstraintGetRowCount(j) MdtConstraintGetRowCount(MdtUserConstraintQuaConstraint(j))

/* Karma 1.2's names for the function's data. */
#define MdtUserConstraintSetConstraintData(j, data) MdtUserConstraintSetConstraintStruct((j), (data))
#define MdtUserConstraintGetConstraintData(j) MdtUserConstraintGetConstraintStruct(j)

ME_EXTERN_C_END

#endif /* MDT_USERCONSTRAINT_H */
