/* kea.h -- Kea, Karma's LCP solver core: the bounded LCP of one partition, solved exactly (direct
 * path) or by projected Gauss-Seidel with subspace minimisation (iterative path).
 *
 * The problem (one partition at a time; the constraint packer fills a KeaProblem):
 *   bodies 0..nb-1 with inverse mass m^-1 and world-frame inverse inertia I^-1 (3x3 symmetric);
 *   rows 0..n-1, row i with a Jacobian J_i = (lin0, ang0 | lin1, ang1) acting on bodies b0_i, b1_i
 *   (KEA_WORLD = -1: that half is ignored), softness eps_i >= 0, right-hand side r_i (target
 *   constraint-velocity change), bounds lo_i <= hi_i (+-MEINFINITY allowed) and optionally a
 *   friction link (link_i = index of the normal row, coefficient mu_i).
 *   Unknown: the row impulses x over the step. With A = J M^-1 J^T + diag(eps) and w = A x - r:
 *       lo <= x <= hi,  x_i = lo_i => w_i >= 0,  x_i = hi_i => w_i <= 0,  lo_i < x_i < hi_i => w_i = 0.
 *   With A positive definite (eps > 0 is enough) this is the strictly convex box QP
 *   min 1/2 x^T A x - r^T x over the box, with one solution.
 *
 * Friction links make the bounds depend on the solution: a linked row i has the effective bounds
 *   [max(lo_i, -mu_i max(x_link, 0)), min(hi_i, mu_i max(x_link, 0))]    (lo_i <= 0 <= hi_i assumed;
 * a row's own bounds are widened to include 0 if they do not). The iterative path applies them
 * dynamically row by row; the direct path solves a sequence of box QPs, the bounds of each taken from
 * the previous solution (the first from the warm start), until the bounds stop moving or
 * maxFrictionPasses is reached (an outer fixed-point; KeaStats.frictionPasses counts the passes).
 *
 * Residual (KeaResidual, KeaStats.residual): the natural-map residual in constraint-velocity units,
 *   res = max_i d_i |x_i - mid(lo_i, x_i - w_i / d_i, hi_i)|,   d_i = A_ii,
 * with the effective (link) bounds at x. It is zero exactly at a solution; for a row strictly inside
 * its bounds it is |w_i|, for a row at a bound it is the velocity with which the row would still
 * push against that bound (or the size of a bound violation scaled by d_i).
 *
 * Memory: Kea never allocates. The caller asks KeaMemoryRequired(nRows, nBodies, path) and passes a
 * workspace of at least that many bytes (any alignment) to KeaSolve.
 *
 * The algorithms and their costs are described in docs/kea.md and at the top of kea_direct.c and
 * kea_iterative.h. Internal API: the public MdtKea* wrappers (MdtKea.h) sit on top. */
#ifndef KEA_H
#define KEA_H

#include <stddef.h>

#include <karma/MePrecision.h>

/** Largest block of rows the iterative path solves together (KeaParameters.maxBlockRows). */
#define KEA_MAX_BLOCK_ROWS 24

/** Body index of a row half that acts on the world (or on nothing): that half is ignored. */
#define KEA_WORLD (-1)

/** One Jacobian row, padded to 16 reals so that each 3-vector starts on a 16-byte boundary (float).
 *  The fourth element of each part is padding and is never read. */
typedef struct KeaJacobianRow {
    MeReal lin0[4]; /**< linear part on body 0 (acts on its linear velocity) */
    MeReal ang0[4]; /**< angular part on body 0 */
    MeReal lin1[4]; /**< linear part on body 1 */
    MeReal ang1[4]; /**< angular part on body 1 */
} KeaJacobianRow;

/** Inverse mass data of a body, world frame. A body with invMass 0 and zero invInertia is immovable. */
typedef struct KeaBody {
    MeReal invMass;          /**< 1/m, 1/kg; >= 0 */
    MeReal invInertia[3][3]; /**< I^-1 in the world frame, symmetric positive semi-definite */
} KeaBody;

/** Velocity change of a body: the solver's output Delta v = M^-1 J^T x. */
typedef struct KeaBodyVelocity {
    MeReal lin[3]; /**< linear velocity change, m/s */
    MeReal ang[3]; /**< angular velocity change, rad/s (world frame) */
} KeaBodyVelocity;

/** A contact declared as one (typed): its three rows, consecutive from `row`, are its normal row and
 *  its two friction rows. What the declaration promises, and KeaSolve checks (KeaStatusBadInput
 *  otherwise): the three rows act on the same two bodies, the first a body (not KEA_WORLD), the
 *  second another body or KEA_WORLD; the normal row has bounds [0, MEINFINITY) and no link; each
 *  friction row is linked to the normal row (its mu_i its own, so friction may be anisotropic) and
 *  has no bounds of its own (+-MEINFINITY). Softness eps and right-hand sides are free (a soft or
 *  bouncing contact, slip, a surface or world velocity are all typed contacts). The iterative path
 *  solves a declared contact with its contact step (kea_contact_kernel.h); rows not declared are
 *  generic rows, solved in blocks of a constraint's rows (a contact that does not fit the promise,
 *  e.g. an adhesive one or one with bounded friction, is written as generic rows). The rows stay
 *  in KeaProblem's row arrays: the declaration adds what they are, not a second copy of them. */
typedef struct KeaContact {
    int row; /**< the normal row; the friction rows are row + 1 and row + 2 */
} KeaContact;

/** One partition's bounded LCP. Arrays are indexed by row (nRows entries) unless said otherwise;
 *  they are read only. Optional arrays may be NULL. */
typedef struct KeaProblem {
    int nRows;                 /**< number of rows n >= 0 */
    int nBodies;               /**< number of bodies nb >= 0 */
    const KeaBody *bodies;     /**< nb bodies */
    const KeaJacobianRow *J;   /**< Jacobian rows */
    const int (*rowBodies)[2]; /**< partition-local body indices of each row's halves, or KEA_WORLD */
    const MeReal *epsilon;     /**< softness eps_i >= 0 added to A_ii (NULL = 0 for every row) */
    const MeReal *rhs;         /**< r_i: target constraint-velocity change */
    const MeReal *lo;          /**< lower bounds (may be -MEINFINITY) */
    const MeReal *hi;          /**< upper bounds (may be MEINFINITY), lo_i <= hi_i */
    const int *link;           /**< friction link: normal row of row i, or -1 (NULL = no links) */
    const MeReal *mu;          /**< friction coefficient of linked rows (needed if link != NULL) */
    const MeReal *x0;          /**< warm start (NULL = start from 0); may alias the output x */
    int nContacts;             /**< declared contacts (KeaContact), >= 0 */
    const KeaContact *contacts; /**< nContacts, in increasing row order and not overlapping (NULL
                                     when none); needs link and mu */
} KeaProblem;

/** Which method solves a partition. */
typedef enum KeaPath {
    KeaPathAuto = 0,      /**< direct when nRows <= maxDirectRows, or nRows <= 4 maxDirectRows and the
                               ordered factor has at most maxDirectRows (maxDirectRows + 1) / 2
                               entries (kea_direct.c); else iterative. With a pivot budget
                               (autoPivotsPerRow), a direct solve of at most maxDirectRows rows that
                               runs over it is finished by the iterative path */
    KeaPathDirect = 1,    /**< exact: Cholesky-based active-set (pivoting) method, sparse factor */
    KeaPathIterative = 2  /**< projected Gauss-Seidel (+ subspace minimisation) on the sparse rows */
} KeaPath;

/** Outcome of a solve. The solution is usable for every status except the last two. */
typedef enum KeaStatus {
    KeaStatusOk = 0,             /**< converged (direct: exact; iterative: residual <= tolerance) */
    KeaStatusMaxIterations = 1,  /**< iterative path stopped at maxIterations (the usual case) */
    KeaStatusMaxPivots = 2,      /**< direct path hit maxPivots (best feasible iterate returned) */
    KeaStatusFrictionPasses = 3, /**< direct path: friction bounds still moving after the last pass */
    KeaStatusWorkspaceTooSmall = 4, /**< workspace smaller than KeaMemoryRequired: nothing solved */
    KeaStatusBadInput = 5        /**< invalid problem (index out of range, lo > hi, eps < 0, NaN) */
} KeaStatus;

/** A range of a task: items [start, end) on worker `worker` (0 <= worker < KeaTaskHook.workers). */
typedef void (*KeaTaskFn)(int start, int end, int worker, void *data);

/** How Kea hands work to the caller's workers (the split solve, KeaParameters.splitRows): run(task,
 *  itemCount, minRange, data, user) must run task over every item of [0, itemCount) exactly once, in
 *  ranges of at least minRange items (but the last), each range with a worker index in [0, workers)
 *  that no other range runs at the same time, and return when all have run. run NULL or workers <= 1:
 *  Kea runs the items itself, in order, as worker 0. The results are the same bits either way. */
typedef struct KeaTaskHook {
    void (*run)(KeaTaskFn task, int itemCount, int minRange, void *data, void *user);
    void *user;    /**< handed to run */
    int workers;   /**< how many worker indices run may use, 1 .. KEA_MAX_WORKERS */
    int perStage;  /**< 0 (default): one task of `workers` items for the whole solve, whose items
                        spin-wait for the next stage (kea_split.c, "the team"); 1: one run call per
                        stage (a colour of a sweep, a loop of SM), no item waiting for another: for
                        task systems whose tasks must not block, at a hand-out per stage */
} KeaTaskHook;

/** Most workers a split solve uses (KeaTaskHook.workers). */
#define KEA_MAX_WORKERS 64

/** Solver settings; fill with KeaParametersDefault, then change what you need. */
typedef struct KeaParameters {
    KeaPath path;           /**< method; default KeaPathAuto */
    int maxDirectRows;      /**< Auto chooses direct up to this many rows (and beyond, up to 4x, for a
                                 sparse factor: KeaPathAuto); default 128 */
    int maxIterations;      /**< iterative: Gauss-Seidel sweeps; default 10 (Karma's) */
    MeReal tolerance;       /**< iterative: stop when a sweep's residual (velocity units, see top
                                 comment, measured during the sweep) is <= this; default 1e-6 m/s */
    MeReal sor;             /**< iterative: over-relaxation factor in (0, 2); default 1 */
    int subspaceIterations; /**< iterative: conjugate-gradient steps on the free rows between two
                                 sweeps (subspace minimisation); 0 = plain PGS; default 4 */
    int maxBlockRows;       /**< iterative: consecutive rows on the same two bodies (a constraint)
                                 up to this many are solved together exactly in each sweep, a
                                 contact's normal and friction rows as a block of their own (a
                                 declared contact, KeaContact, by the contact step when this is
                                 3 or more); 1 = scalar PGS; at most KEA_MAX_BLOCK_ROWS; default 12 */
    int maxPivots;          /**< direct: cap on active-set changes; 0 = automatic (8 n + 64) */
    int maxFrictionPasses;  /**< direct: box-QP passes for friction links; default 8 */
    MeReal effortResidual;  /**< iterative: extra effort (kea_iterative.c): while a round's last sweep
                                 leaves a residual above this (velocity units), two more sweeps, up to
                                 KEA_EFFORT_FACTOR maxIterations more; 0 = none, the default here (the
                                 world sets KEA_EFFORT_RESIDUAL x its length scale, docs/kea.md) */
    MeReal effortRestSpeed; /**< iterative: the extra effort only for a partition at rest, every row's
                                 |rhs| at most this (velocity units); 0 = no limit, the default here
                                 (the world sets KEA_EFFORT_REST_SPEED x its length scale) */
    MeReal autoPivotsPerRow; /**< Auto: a partition of at most maxDirectRows rows whose direct solve
                                 needs more than this many pivots per row (plus KEA_AUTO_PIVOTS_EXTRA)
                                 is handed to the iterative path for this step, warm-started from
                                 where the pivots left it (larger, tree-like ones stay exact);
                                 0 = never, the default here (the world sets KEA_AUTO_PIVOTS_PER_ROW;
                                 docs/kea.md, "Worst frames") */
    int splitRows;          /**< iterative: a partition of at least this many rows is split (kea_split.c):
                                 its blocks coloured so that no two of a colour share a body, and each
                                 sweep taken colour by colour, a colour's blocks over the workers of
                                 `tasks`; SM, the set-up and the residual run over fixed chunks. The
                                 sweep order is then the colours' for any worker count (one included),
                                 so the result differs from the unsplit solve's but not between worker
                                 counts. 0 = never, the default */
    KeaTaskHook tasks;      /**< the caller's workers for a split solve; default none (run NULL) */
    int nonsmoothCg;        /**< iterative: 1 = nonsmooth nonlinear conjugate gradient (NNCG, kea_nncg.c):
                                 after each pair of sweeps (forwards, backwards, SM between) a
                                 Fletcher-Reeves momentum step along the pairs' changes; 0 = plain
                                 sweeps, the default (opt-in: docs/kea_log.md, "NNCG") */
    int subspaceEvery;      /**< iterative: an SM chance only after the first sweep and every this-many-th
                                 (values below 1 count as 1); default 1, every sweep (the world's: 2) */
    MeReal subspaceStop;    /**< iterative: SM's conjugate gradient stops before subspaceIterations steps
                                 once its preconditioned residual r.z has fallen to this times its
                                 first value; 0 = only at rounding's floor, the default (the world's:
                                 KEA_WORLD_SM_STOP) */
    int deflation;          /**< iterative: 1 = a coarse correction (kea_deflation.c) after each pair of
                                 sweeps in place of NNCG's momentum: the QP minimised over the
                                 solve's last changes of x, and SM at every second chance only;
                                 0 = off, the default */
    MeReal subspaceJointShare; /**< iterative: a partition whose generic rows (every row not in a declared
                                 contact: joints, limits, motors) are at least this share of its rows
                                 has its SM chances after the first every subspaceJointEvery sweeps
                                 instead of every subspaceEvery (not with deflation, whose SM chances
                                 stay every second); 0 = none, the default (the world's:
                                 KEA_WORLD_SM_JOINT_SHARE, decision K58) */
    int subspaceJointEvery; /**< iterative: see subspaceJointShare; 0 = subspaceEvery, the default (the
                                 world's: KEA_WORLD_SM_JOINT_EVERY) */
} KeaParameters;

/** What a solve did. */
typedef struct KeaStats {
    KeaPath path;       /**< path used (never Auto) */
    KeaStatus status;   /**< same as KeaSolve's return value */
    int rows;           /**< nRows */
    int bodies;         /**< nBodies */
    int iterations;     /**< iterative: Gauss-Seidel sweeps done (maxIterations and the extra effort's) */
    int effortRounds;   /**< iterative: pairs of sweeps added because the residual stayed high
                             (KEA_EFFORT_RESIDUAL, kea_tuning.h) */
    int subspaceSteps;  /**< iterative: conjugate-gradient steps done (all sweeps) */
    int subspaceSkipped; /**< iterative: subspace minimisations skipped (the active set still moving,
                              or the last one did not pay) */
    int pivots;         /**< direct: active-set changes (a row freed or fixed at a bound) */
    int handedOver;     /**< Auto: 1 when the direct path spent its pivot budget (autoPivotsPerRow)
                             and the iterative path finished the solve (path is then iterative) */
    int frictionPasses; /**< direct: box-QP passes (1 without links) */
    int factorizations; /**< direct: full Cholesky factorisations */
    int regularised;    /**< direct: free-block pivots raised to the floor (A near singular) */
    MeReal residual;    /**< natural-map residual of the returned x (top comment), velocity units */
    int colours;        /**< iterative, split (KeaParameters.splitRows): the blocks' colours (the
                             overflow colour counted when used); 0 when not split */
    int bodyFactor;     /**< direct: 1 when the free rows were solved through the bodies' coordinates
                             (a resting stack; kea_body_factor.c), 0 with the rows' own factor */
} KeaStats;

/** Default settings (see the field comments). */
void KeaParametersDefault(KeaParameters *params);

/** The path KeaSolve will use for a partition of nRows rows under params; KeaPathAuto when it
 *  depends on the partition's structure or on its pivots (decided by KeaSolve; size the workspace
 *  for either). */
KeaPath KeaSelectPath(int nRows, const KeaParameters *params);

/** Bytes of workspace KeaSolve needs for nRows rows and nBodies bodies on the given path
 *  (KeaPathAuto: enough for either path). Independent of alignment: any buffer of this size works. */
size_t KeaMemoryRequired(int nRows, int nBodies, KeaPath path);

/** Whether KeaSolve splits a partition of nRows rows under params (KeaParameters.splitRows: it may
 *  take the iterative path and has at least splitRows rows). */
int KeaSplits(int nRows, const KeaParameters *params);

/** Bytes a split solve (KeaParameters.splitRows) needs on top of KeaMemoryRequired: the colouring,
 *  the chunks' partial sums and one block scratch per worker of params->tasks; 0 when params do not
 *  split a partition of nRows rows. */
size_t KeaSplitMemoryRequired(int nRows, int nBodies, const KeaParameters *params);

/** Solve one partition. x (nRows) receives the impulses; dv (nBodies, may be NULL) the velocity
 *  changes M^-1 J^T x; stats (may be NULL) what happened. workspace: at least
 *  KeaMemoryRequired(nRows, nBodies, KeaSelectPath(nRows, params)) + KeaSplitMemoryRequired(nRows, nBodies,
 *  params) bytes. No allocation, no
 *  messages: the status says what went wrong. Deterministic: rows are visited in index order (a split
 *  solve: in its colours' order, the same bits for any worker count).
 *  Seven arguments: the problem, how to solve it, the caller's memory and the three outputs, each
 *  owned by a different party (the world, its settings, its arena, its bodies), so no struct would
 *  group them without the caller copying into it. */
KeaStatus KeaSolve(const KeaProblem *problem, const KeaParameters *params, void *workspace,
                   size_t workspaceSize, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats);

/** KeaSolve for a caller that sized the workspace for this problem itself (workspaceSize at least
 *  KeaSolve's bound above, as the world's solve stage computes it for every partition): the same
 *  solve, without computing the bound again (a layout pass of hundreds of instructions a partition).
 *  Seven arguments: KeaSolve's. */
KeaStatus KeaSolveSized(const KeaProblem *problem, const KeaParameters *params, void *workspace,
                        size_t workspaceSize, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats);
/** KeaSolveSized for a caller that has proved every row valid itself (the world's row writer,
 *  src/mdt/pack.c: indices in range, lo <= hi, softness >= 0, rhs, J, x0 and linked mu finite, links
 *  to unlinked rows) and J's pads and halves on the world zero: the rows are not checked again (the
 *  bodies and declared contacts are), and the iterative path reads J in place instead of a padded
 *  copy. A caller that could not prove its rows calls KeaSolveSized. Seven arguments: KeaSolve's. */
KeaStatus KeaSolveRowsProved(const KeaProblem *problem, const KeaParameters *params, void *workspace,
                             size_t workspaceSize, MeReal *x, KeaBodyVelocity *dv, KeaStats *stats);

/** Delta v = M^-1 J^T x for every body (nBodies entries). */
void KeaBodyVelocityFromImpulses(const KeaProblem *problem, const MeReal *x, KeaBodyVelocity *dv);

/** The effective bounds of row i at x (friction links applied; see the top comment). */
void KeaRowBounds(const KeaProblem *problem, const MeReal *x, int i, MeReal *lo, MeReal *hi);

/** Natural-map residual of x (top comment), with dv = M^-1 J^T x as KeaBodyVelocityFromImpulses
 *  gives it. Velocity units; 0 at the exact solution. */
MeReal KeaResidual(const KeaProblem *problem, const MeReal *x, const KeaBodyVelocity *dv);

#endif /* KEA_H */
