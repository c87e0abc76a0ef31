/* MdtWorld.h -- the dynamics world: its pools, its settings and its step.
 *
 * A world holds fixed pools of bodies and constraints, sized at creation, and the solver settings.
 * Defaults follow Karma: gravity (0,0,0); epsilon 0.01 / massScale; gamma 0.2; 10 LCP iterations;
 * auto-disable on, with thresholds velocity 0.02, angular velocity 0.001, acceleration 0.05,
 * angular acceleration 0.05 (each compared with a squared magnitude, and scaled by lengthScale at
 * creation) and an alive window of 0.2 s (see docs/conventions.md, decision D1).
 *
 * One MdtWorldStep(w, h) runs the stages of docs/step.md, each also callable on its own and each a
 * timed section of the world's MeProfile: update partitions, auto-disable, pack, Kea solve,
 * integrate, unpack forces. The step allocates nothing once its scratch chunks have grown. */
#ifndef MDT_WORLD_H
#define MDT_WORLD_H

#include "MdtTypes.h"
#include "MeProfile.h"

ME_EXTERN_C_BEGIN

/* A library built with the other precision does not have this symbol: link errors, not corruption. */
#define MdtWorldCreate ME_PRECISION_SYMBOL(MdtWorldCreate)

/** Create a world with room for `maxBodies` bodies and `maxConstraints` constraints (joints,
 *  contact groups and contacts together). `lengthScale` is a typical object size and `massScale` a
 *  typical mass (both > 0; 1 for SI scenes of human-sized objects): tolerances and defaults derive
 *  from them. Returns NULL (and reports) on bad arguments or when memory runs out. */
ME_API MdtWorldID MdtWorldCreate(unsigned int maxBodies, unsigned int maxConstraints, MeReal lengthScale,
                                 MeReal massScale);
/** Destroy the world with every body and constraint in it. Their IDs become invalid. */
ME_API void MdtWorldDestroy(MdtWorldID w);
/** Destroy every body and constraint but keep the world and its settings. */
ME_API void MdtWorldReset(MdtWorldID w);
/** Restore every setting to its default (keeps bodies and constraints). */
ME_API void MdtWorldReCreate(MdtWorldID w);

/** Advance every enabled body by `stepSize` seconds (finite, at least MDT_MIN_STEP_SIZE = 1e-6 s; else
 *  refused with ME_ERR_STEP_SIZE, nothing changed). */
ME_API void MdtWorldStep(MdtWorldID w, MeReal stepSize);

/* ---- accessors ---------------------------------------------------------------------------- */
/** Number of live bodies, enabled or not; 0 for an invalid ID (ME_ERR_INVALID_HANDLE). */
ME_API int MdtWorldGetTotalBodies(MdtWorldID w);
/** Number of enabled bodies; 0 for an invalid ID. */
ME_API int MdtWorldGetEnabledBodies(MdtWorldID w);
/** Number of live constraints (joints, contact groups and contacts); 0 for an invalid ID. */
ME_API int MdtWorldGetTotalConstraints(MdtWorldID w);
/** Number of enabled constraints; 0 for an invalid ID. */
ME_API int MdtWorldGetEnabledConstraints(MdtWorldID w);
/** Size of the body pool given to MdtWorldCreate; 0 for an invalid ID. */
ME_API int MdtWorldGetMaxBodies(MdtWorldID w);
/** Size of the constraint pool given to MdtWorldCreate; 0 for an invalid ID. */
ME_API int MdtWorldGetMaxConstraints(MdtWorldID w);
/** Constraint softness ε (MdtWorldSetEpsilon); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetEpsilon(MdtWorldID w);
/** Error relaxation γ (MdtWorldSetGamma); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetGamma(MdtWorldID w);
/** Gravity acceleration (m/s²) into g; NULL g refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtWorldGetGravity(MdtWorldID w, MeVector3 g);
/** Whether resting bodies are disabled automatically; MEFALSE for an invalid ID. */
ME_API MeBool MdtWorldGetAutoDisable(MdtWorldID w);
/** Squared-speed threshold of auto-disable (m²/s²); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetAutoDisableVelocityThreshold(MdtWorldID w);
/** Squared angular speed threshold of auto-disable (rad²/s²); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetAutoDisableAngularVelocityThreshold(MdtWorldID w);
/** Squared acceleration threshold of auto-disable (m²/s⁴); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetAutoDisableAccelerationThreshold(MdtWorldID w);
/** Squared angular acceleration threshold (rad²/s⁴); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetAutoDisableAngularAccelerationThreshold(MdtWorldID w);
/** Seconds a body stays enabled before it may be auto-disabled (s); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetAutoDisableAliveTime(MdtWorldID w);
/** Iteration cap of the LCP solver; 0 for an invalid ID. */
ME_API int MdtWorldGetMaxLCPIterations(MdtWorldID w);
/** Density giving a cube of side lengthScale the mass massScale. */
ME_API MeReal MdtWorldGetDefaultDensity(MdtWorldID w);
/** The typical object size given to MdtWorldCreate (m); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetLengthScale(MdtWorldID w);
/** The typical mass given to MdtWorldCreate (kg); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetMassScale(MdtWorldID w);
/** The world's profile: one section per step stage (times of the last completed step). */
ME_API const MeProfile *MdtWorldGetProfile(MdtWorldID w);
/** The world's profile, writable (owned by the world, valid while it lives); NULL for an invalid ID. */
ME_API MeProfile *MdtWorldGetProfilePtr(MdtWorldID w);

/** Counts describing the last step and the pools, for tools and the viewer. */
typedef struct MdtWorldCounters {
    int bodies, enabledBodies, constraints, enabledConstraints;
    int partitions;           /**< partitions simulated in the last step */
    int rows;                 /**< constraint rows solved in the last step */
    int droppedRows;          /**< rows removed by matrix capping in the last step (MdtLOD.h) */
    int cappedPartitions;     /**< partitions that matrix capping reduced in the last step */
    int simErrors;            /**< partitions disabled by the simulation check in the last step */
    int bodyPoolHighWater, constraintPoolHighWater;
    unsigned long steps;      /**< completed calls to MdtWorldStep */
    MeReal time;              /**< simulated seconds */
    unsigned long speedWarnings;  /**< ME_ERR_SPEED_LIMIT reports since the world was created */
    unsigned long energyWarnings; /**< ME_ERR_ENERGY_JUMP reports since the world was created */
} MdtWorldCounters;
/** Fill `counters` with the world's counts and step totals (NULL refused). */
ME_API void MdtWorldGetCounters(MdtWorldID w, MdtWorldCounters *counters);

/** Which LCP method solves a partition. */
typedef enum MdtLCPSolver {
    MdtLCPSolverAuto = 0,      /**< exact (direct) up to MdtWorldSetMaxDirectRows rows, and up to four times
                                    that when the partition's factor is sparse (chains, trees:
                                    docs/decisions.md K26); else iterative */
    MdtLCPSolverDirect = 1,    /**< always the exact pivoting solver */
    MdtLCPSolverIterative = 2  /**< always the iterative solver (MdtWorldSetMaxLCPIterations sweeps) */
} MdtLCPSolver;

/** What the solver did in the last step, over all partitions. */
typedef struct MdtSolverStats {
    int partitions;          /**< partitions solved */
    int rows;                /**< constraint rows, all partitions */
    int maxPartitionRows;    /**< rows of the largest partition */
    int directPartitions;    /**< partitions solved exactly */
    int iterativePartitions; /**< partitions solved iteratively */
    int iterations;          /**< iterative sweeps, summed over partitions */
    int pivots;              /**< direct-path pivots, summed */
    int unconverged;         /**< partitions that stopped at a cap (iterations, pivots) */
    MeReal maxResidual;      /**< largest residual (m/s: how far a row's velocity is from what the
                                  constraint asks), over partitions */
    int splitPartitions;     /**< not in Karma 1.2: iterative partitions split over the workers
                                  (MdtWorldSetPartitionSplitRows) */
    int maxColours;          /**< not in Karma 1.2: most colours of a split partition */
} MdtSolverStats;
/** Fill `stats` with what the last step's solver did (partitions, rows, iterations); then the
 *  solver settings: method, largest direct partition (rows), tolerance. */
ME_API void MdtWorldGetSolverStats(MdtWorldID w, MdtSolverStats *stats);
/** The LCP method in use (MdtWorldSetLCPSolver); MdtLCPSolverAuto for an invalid ID. */
ME_API MdtLCPSolver MdtWorldGetLCPSolver(MdtWorldID w);
/** Largest partition (rows) the automatic solver solves exactly; 0 for an invalid ID. */
ME_API int MdtWorldGetMaxDirectRows(MdtWorldID w);
/** Residual (m/s) at which the iterative solver stops; 0 for an invalid ID. */
ME_API MeReal MdtWorldGetLCPTolerance(MdtWorldID w);
/** Rows from which an iterative partition is split over the workers (MdtWorldSetPartitionSplitRows);
 *  0 (never) by default and for an invalid ID. */
ME_API int MdtWorldGetPartitionSplitRows(MdtWorldID w);
/** Whether the iterative solver adds NNCG's momentum to its sweeps (MdtWorldSetNonsmoothCG); METRUE
 *  by default, MEFALSE for an invalid ID. */
ME_API MeBool MdtWorldGetNonsmoothCG(MdtWorldID w);
/** Whether the iterative solver takes the coarse correction (MdtWorldSetDeflation); MEFALSE by
 *  default and for an invalid ID. */
ME_API MeBool MdtWorldGetDeflation(MdtWorldID w);

/* ---- mutators ----------------------------------------------------------------------------- */
/** Gravity acceleration (m/s²); default (0,0,0). */
ME_API void MdtWorldSetGravity(MdtWorldID w, MeReal gx, MeReal gy, MeReal gz);
/** Constraint softness ε (> 0): added to the diagonal of the solver's matrix; larger is softer and
 *  converges faster. Default 0.01 / massScale; sensible 1e-5 ... 0.1. */
ME_API void MdtWorldSetEpsilon(MdtWorldID w, MeReal e);
/** Error relaxation γ (0 < γ ≤ 1): share of a constraint's position error corrected per step.
 *  Default 0.2. */
ME_API void MdtWorldSetGamma(MdtWorldID w, MeReal g);
/** γ chosen for a reference step and rescaled to the actual step: γ = aGamma·aTimeStep/aRefStep. */
ME_API void MdtWorldSetGammaWithRefTimeStep(MdtWorldID w, MeReal aGamma, MeReal aRefStep, MeReal aTimeStep);
/** Zero the force, torque and impulse accumulators of every body. */
ME_API void MdtWorldResetForces(MdtWorldID w);
/** Turn automatic disabling of resting bodies on (METRUE) or off; invalid ID refused. */
ME_API void MdtWorldSetAutoDisable(MdtWorldID w, MeBool d);
/** Squared-speed threshold (m²/s²) below which a body may be disabled. Default 0.02·lengthScale². */
ME_API void MdtWorldSetAutoDisableVelocityThreshold(MdtWorldID w, MeReal vt);
/** Squared angular speed threshold (rad²/s²). Default 0.001. */
ME_API void MdtWorldSetAutoDisableAngularVelocityThreshold(MdtWorldID w, MeReal avt);
/** Squared acceleration threshold (m²/s⁴). Default 0.05·lengthScale². */
ME_API void MdtWorldSetAutoDisableAccelerationThreshold(MdtWorldID w, MeReal at);
/** Squared angular acceleration threshold (rad²/s⁴). Default 0.05. */
ME_API void MdtWorldSetAutoDisableAngularAccelerationThreshold(MdtWorldID w, MeReal aat);
/** Seconds a body must have been enabled before it may be auto-disabled. Default 0.2. */
ME_API void MdtWorldSetAutoDisableAliveTime(MdtWorldID w, MeReal aw);
/** Seconds over which auto-disable averages each body's motion before comparing it with the four
 *  thresholds (this library's addition, docs/api_changes.md): the mean velocity and angular velocity
 *  and the fitted (least-squares) acceleration and angular acceleration over that time, so that a
 *  settled heap's solver noise averages out while steady motion is judged as in Karma 1.2. A body can
 *  be disabled only once it has been enabled that long (and longer than the alive time). 0 judges the
 *  last step alone: Karma 1.2's test. Default MDTWORLD_DEFAULT_AVERAGING_TIME (0.5 s); rejects a
 *  negative or non-finite time (message, no change). */
ME_API void MdtWorldSetAutoDisableAveragingTime(MdtWorldID w, MeReal t);
/** MdtWorldSetAutoDisableAveragingTime's setting (s); 0 for a bad world. */
ME_API MeReal MdtWorldGetAutoDisableAveragingTime(MdtWorldID w);
/** Sweeps of the iterative LCP solver (≥ 1). Default 10. A resting partition whose residual stays
 *  above 5 mm/s after them gets up to twice as many more (docs/kea.md, "Extra effort"). */
ME_API void MdtWorldSetMaxLCPIterations(MdtWorldID w, int mi);
/** Choose the LCP method (default MdtLCPSolverAuto). */
ME_API void MdtWorldSetLCPSolver(MdtWorldID w, MdtLCPSolver solver);
/** Largest partition (in rows) that MdtLCPSolverAuto solves exactly whatever its structure; up to
 *  four times this many rows it also does when the ordered factor costs no more than a dense one of
 *  this size (decision K26). 0: always iterative. Default 128. */
ME_API void MdtWorldSetMaxDirectRows(MdtWorldID w, int rows);
/** Not in Karma 1.2. Split every partition of at least `rows` rows that the iterative solver takes:
 *  its constraints coloured so that no two of a colour share a body, each sweep colour by colour, a
 *  colour's constraints over the task system's workers (MdtTaskSystem.h), so that one large partition
 *  (a pile) uses every core. The results are the same bits for any worker count, one included, but
 *  the sweep order is the colours', so a split partition's trajectory differs from the unsplit one's
 *  (decision K42). 0 = never, the default; rows < 0 is refused (ME_ERR_ARGUMENT_RANGE). A few
 *  thousand rows is where the split pays on two cores (docs/kea.md). */
ME_API void MdtWorldSetPartitionSplitRows(MdtWorldID w, int rows);
/** Not in Karma 1.2: the iterative solver's sweeps with a momentum step after each forward-and-backward
 *  pair (nonsmooth nonlinear conjugate gradient, NNCG; docs/kea.md): the same LCP, reached in fewer
 *  sweeps. On by default (decision K47); MEFALSE gives Karma 1.2's plain sweeps. */
ME_API void MdtWorldSetNonsmoothCG(MdtWorldID w, MeBool on);
/** Not in Karma 1.2: after each pair of the iterative solver's sweeps, a coarse correction
 *  (deflation; docs/kea.md) in place of NNCG's momentum: the LCP's objective minimised over the
 *  solve's own last changes of the impulses, with subspace minimisation at every second chance
 *  only. The same LCP; MEFALSE (the default) keeps NNCG and SM at every chance. */
ME_API void MdtWorldSetDeflation(MdtWorldID w, MeBool on);
/** The iterative solver stops early once its residual is below this (m/s, > 0). Default 1e-4 x the
 *  world's length scale. */
ME_API void MdtWorldSetLCPTolerance(MdtWorldID w, MeReal tolerance);
/** Called when the world enables a body (also by the partitioner) / disables one (auto-disable). */
ME_API void MdtWorldSetBodyEnableCallback(MdtWorldID w, MdtBodyEnableCBPtr cb, void *userData);
/** Called when auto-disable disables a body (NULL: none); userData is not owned. */
ME_API void MdtWorldSetBodyDisableCallback(MdtWorldID w, MdtBodyEnableCBPtr cb, void *userData);
/** Called when a contact group is destroyed, by the application or with its body. */
ME_API void MdtWorldSetContactGroupDestroyCallback(MdtWorldID w, MdtContactGroupDestroyCBPtr cb, void *userData);

/* ---- simulation check (NaN / infinity containment) ---------------------------------------- */
/** What went wrong in a partition. */
typedef enum MdtSimErrorKind {
    MdtSimErrorSolver = 1, /**< the solver's input or result (impulses, velocity changes) was not finite */
    MdtSimErrorState = 2   /**< the integrated state (position, orientation, velocities) was not finite */
} MdtSimErrorKind;
/** A partition that failed the simulation check, as the callback sees it. The partition's bodies are
 *  still in the failed state during the callback; afterwards they are put back to their pose at the
 *  start of the step, stopped and disabled, and its constraints' outputs and warm starts cleared. */
typedef struct MdtSimError {
    MdtSimErrorKind kind;
    int partition;          /**< index in the step */
    int bodyCount;
    const MdtBodyID *bodies; /**< the partition's bodies (valid during the callback only) */
    int constraintCount;
    int rows;               /**< solver rows of the partition */
    int solverStatus;       /**< the solver's status for the partition (0 = converged) */
} MdtSimError;
/** Called once per failed partition, from inside the step (the world is locked). */
typedef void (*MdtSimErrorHandlerPtr)(MdtWorldID w, const MdtSimError *error, void *userData);
/** Check the solver's result of every partition before integrating (default on). The integrated
 *  state is always checked: a partition whose state is NaN or infinite is restored, stopped and
 *  disabled, reported with ME_ERR_NONFINITE_STATE and passed to the callback; other partitions are
 *  not affected. With the check off a bad solve is caught by the state check after integration. */
ME_API void MdtWorldSetCheckSim(MdtWorldID w, MeBool check);
/** One-time hints when a step can move nothing (default on): a world stepped with bodies of which none
 *  was ever enabled (ME_ERR_NO_BODY_ENABLED), or with zero gravity and enabled bodies on which nothing
 *  acts (no velocity, force or enabled constraint: ME_ERR_NOTHING_ACTS). Each is a warning, reported at
 *  most once per world, naming the call to make. MEFALSE silences them (a scene that means it). */
ME_API void MdtWorldSetHints(MdtWorldID w, MeBool hints);
/** Whether the one-time hints are on (MdtWorldSetHints); MEFALSE for an invalid ID. */
ME_API MeBool MdtWorldGetHints(MdtWorldID w);

/** The smallest step MdtWorldStep (and MstUniverseStep) accepts, in seconds: a shorter one is
 *  refused with ME_ERR_STEP_SIZE and changes nothing (docs/step.md). */
#define MDT_MIN_STEP_SIZE ME_R(1e-6)

/** Speed (m/s) above which a body is reported once with ME_ERR_SPEED_LIMIT (again only after it
 *  has been back under both limits); the step does not slow it. > 0, MEINFINITY turns the report
 *  off; NaN or ≤ 0 is refused. Default 1000·lengthScale (MDTWORLD_DEFAULT_SPEED_LIMIT). */
ME_API void MdtWorldSetSpeedLimit(MdtWorldID w, MeReal speed);
/** The speed limit (m/s) of MdtWorldSetSpeedLimit; 0 for an invalid ID. */
ME_API MeReal MdtWorldGetSpeedLimit(MdtWorldID w);
/** Angular speed (rad/s) above which a body is reported, as MdtWorldSetSpeedLimit. Default 1000
 *  (MDTWORLD_DEFAULT_ANGULAR_SPEED_LIMIT). */
ME_API void MdtWorldSetAngularSpeedLimit(MdtWorldID w, MeReal angularSpeed);
/** The angular speed limit (rad/s) of MdtWorldSetAngularSpeedLimit; 0 for an invalid ID. */
ME_API MeReal MdtWorldGetAngularSpeedLimit(MdtWorldID w);
/** Largest speed (m/s) at which a contact's penetration is corrected (the γ·depth/h term of its
 *  normal row; a bounce is not limited), as ODE's contact_max_correcting_vel. > 0, MEINFINITY: no
 *  bound; NaN or ≤ 0 is refused. Default 10·lengthScale (MDTWORLD_DEFAULT_MAX_CORRECTING_VEL). */
ME_API void MdtWorldSetMaxCorrectingVelocity(MdtWorldID w, MeReal speed);
/** The penetration-correction speed cap (m/s); 0 for an invalid ID. */
ME_API MeReal MdtWorldGetMaxCorrectingVelocity(MdtWorldID w);
/** Whether the solver's result is checked before integrating (MdtWorldSetCheckSim). */
ME_API MeBool MdtWorldGetCheckSim(MdtWorldID w);
/** Callback for failed partitions (NULL: none; the ME_ERR_NONFINITE_STATE report is always made).
 *  Karma 1.2's MdtWorldSetSimErrorCB passed Kea's internal arrays, which this library does not have:
 *  hence another name and callback type (docs/api_changes.md). */
ME_API void MdtWorldSetSimErrorHandler(MdtWorldID w, MdtSimErrorHandlerPtr cb, void *userData);
/** The callback set by MdtWorldSetSimErrorHandler (NULL if none), and its user data. */
ME_API MdtSimErrorHandlerPtr MdtWorldGetSimErrorHandler(MdtWorldID w, void **userData);
/** A callback that prints the failed partition's bodies (state, forces) at info level. */
ME_API void MdtDefaultSimErrorHandler(MdtWorldID w, const MdtSimError *error, void *userData);

/* ---- Karma 1.2's debugging aids ------------------------------------------------------------ */
/** After each step, draw the contacts (MdtDebugDrawContacts) and their forces
 *  (MdtDebugDrawContactForce) through MeDebugDrawAPI.line; 0 (the default) draws nothing. */
ME_API void MdtWorldSetDebugDrawing(MdtWorldID w, MdtDebugDrawOptions drawOptions);
/** Keep Karma 1.2's request for Kea's data files. This solver writes and reads no such files: a
 *  request for any is reported (ME_ERR_ARGUMENT_RANGE) and has no effect. */
ME_API void MdtWorldSetKeaDebugRequest(MdtWorldID w, MdtKeaDebugDataRequest debugDataRequest);
/** Count the partitions the world solves by size from now on: sizeLog[k] (zeroed here) counts those
 *  of 4k−3 ... 4k rows (sizeLog[0] those without rows), the last entry also every larger one, as in
 *  Karma 1.2. The array must outlive the log; (NULL, 0) stops logging. */
ME_API void MdtWorldSetMatrixSizeLog(MdtWorldID w, int *const sizeLog, int logSize);
/** The world's scratch chunks (read them with MeChunkGetMaxSize...; the world owns them): the solver's
 *  workspace ("Kea pool"), the partition lists ("partition output") and the solver rows, which hold
 *  what 1.2 kept in its Kea constraints and Kea transforms chunks (both getters return that chunk). */
ME_API MeChunk *MdtWorldGetKeaPoolChunk(MdtWorldID w);
/** The partition lists' chunk (owned by the world); NULL for an invalid ID. */
ME_API MeChunk *MdtWorldGetPartitionOutputChunk(MdtWorldID w);
/** The solver rows' chunk (what 1.2 kept as Kea transforms; owned by the world); NULL if invalid. */
ME_API MeChunk *MdtWorldGetKeaTMChunk(MdtWorldID w);
/** The solver rows' chunk (same chunk as MdtWorldGetKeaTMChunk; owned by the world). */
ME_API MeChunk *MdtWorldGetKeaConstraintsChunk(MdtWorldID w);
/** The largest solver workspace any step has used, bytes (MeChunkGetMaxSize of the Kea pool chunk). */
ME_API int MdtWorldGetMaxMemoryPoolUsed(MdtWorldID w);

/** Whether `w` is a live world ID (no message). */
ME_API MeBool MdtWorldIsValid(MdtWorldID w);

/* For a layer that runs the world on the application's behalf (a bridge, MstUniverseStep): messages
 * that name what the application called and the setting to change. */
/** Name `function` (a string that outlives the world, such as a literal; NULL: none) in the messages of
 *  MdtWorldStep, of contact creation, of the mass warning and of MdtWorldSetTaskSystem's refusals
 *  while it is set; while set, a full constraint pool in contact creation is reported once per world
 *  and counted after. */
ME_API void MdtWorldSetCallerName(MdtWorldID w, const char *function);
/** The name set by MdtWorldSetCallerName, or NULL (also for an invalid ID). */
ME_API const char *MdtWorldGetCallerName(MdtWorldID w);
/** What "pool full" and mass messages tell the application to raise or set (strings that outlive the
 *  world; a NULL one keeps its current name): the body pool, the constraint pool, the mass scale. */
ME_API void MdtWorldSetSizeNames(MdtWorldID w, const char *bodies, const char *constraints, const char *massScale);

ME_EXTERN_C_END

#endif /* MDT_WORLD_H */
