/* kea_tuning.h -- Kea's tuning constants in one place, each with the reason for its value. None of
 * them is a parameter a user sets (those are KeaParameters, kea.h); changing one changes
 * trajectories (the golden hashes in tests/determinism say so), and the figures that chose them
 * are in bench/RESULTS.md and docs/kea_log.md. */
#ifndef KEA_TUNING_H
#define KEA_TUNING_H

#include <karma/MePrecision.h>

/* ---- the direct path (kea_direct.c, kea_dense.c, kea_dense_lcp.c) ------------------------------ */

/* Relative thresholds tied to the precision (rounding of a float is ~1e-7, of a double ~1e-16):
 *  KEA_PIVOT_FLOOR: a free-block Cholesky pivot d (squared) below KEA_PIVOT_FLOOR * A_ii is raised
 *    to it (the row then behaves as if it had that much extra softness); a block of the iterative
 *    path whose pivot falls below it has no inverse and goes to the dense solver;
 *  KEA_DIRECT_TOL: multipliers and feasibility are judged against KEA_DIRECT_TOL times the problem's
 *    scale (|r| + max A_ii |x|), so that rounding noise does not cause pivots. */
#if KARMA_DOUBLE
#  define KEA_PIVOT_FLOOR ME_R(1e-12)
#  define KEA_DIRECT_TOL ME_R(1e-12)
#else
#  define KEA_PIVOT_FLOOR ME_R(1e-6)
#  define KEA_DIRECT_TOL ME_R(2e-6)
#endif

/** Auto takes the direct path up to this many times maxDirectRows rows when the factor is sparse:
 *  a tree of bodies has a factor without fill, as cheap as its rows, but A and the factor are
 *  still stored densely (n^2), which this cap bounds. */
#define KEA_SPARSE_DIRECT_FACTOR 4

/** The friction polish accepts its candidate when every row's natural map is within
 *  KEA_POLISH_TOL_W KEA_DIRECT_TOL of the problem's scale and its bounds within KEA_POLISH_TOL_X
 *  KEA_DIRECT_TOL |x|: the coupled solve carries more rounding than one pivot's (a Woodbury update
 *  and a refinement step), and a rejected polish costs another friction pass. The passes also stop
 *  when the bounds moved less than KEA_POLISH_TOL_W KEA_DIRECT_TOL |x|. */
#define KEA_POLISH_TOL_W ME_R(10.0)
#define KEA_POLISH_TOL_X ME_R(100.0)

/** The dense solver's automatic pivot budget, KEA_DENSE_PIVOTS_PER_ROW n + KEA_DENSE_PIVOTS_EXTRA
 *  (maxPivots 0): a warm-started solve takes a few pivots, a cold one about one per row that
 *  changes state; the budget only stops a cycling solve, and the extra covers tiny problems. */
#define KEA_DENSE_PIVOTS_PER_ROW 8
#define KEA_DENSE_PIVOTS_EXTRA 64

/** Auto's pivot budget (KeaParameters.autoPivotsPerRow, set by the world): a partition of at most
 *  maxDirectRows rows whose direct solve needs more than KEA_AUTO_PIVOTS_PER_ROW n +
 *  KEA_AUTO_PIVOTS_EXTRA pivots is finished by the iterative path, warm-started from the direct
 *  path's feasible iterate. Larger partitions are on the direct path because their bodies form a
 *  tree (a chain, a column), where 10 sweeps are far from the exact answer: a jittered column of 20
 *  handed over in one step fell (double precision), so they stay exact. A warm-started step takes a
 *  few pivots and the first step of a new contact group about one per row that changes state; the
 *  spikes are groups landing with their friction rows cycling through many states and friction
 *  passes (1.5 to 2 pivots per row, up to 8 passes), each pivot costing about one sweep
 *  (docs/kea.md, "Worst frames"; bench/RESULTS.md, notes "spikes"). */
#define KEA_AUTO_PIVOTS_PER_ROW ME_R(0.25)
#define KEA_AUTO_PIVOTS_EXTRA 16

/* ---- the iterative path (kea_iterative.h and its files) ----------------------------------------- */

/** Blocks of at most this many rows compute J_b dv row by row from the padded rows; larger ones (a
 *  fixed joint's 6) from their 12 x m transpose, one column kernel call: below it, the call and
 *  the transpose cost more than the rows. */
#define KEA_GATHER_ROW_BY_ROW 4

/** An SM step is skipped when more rows than this (and than the fraction below) went from free to
 *  bound or back since the last SM chance: a small problem's CG is cheap, and a lone box's four
 *  corners need it to share their load, so a few changes never skip it. */
#define KEA_SM_SKIP_MIN_CHANGED 16
/** ... and more than 1/KEA_SM_SKIP_FRACTION of the rows changed: CG on a free set that the next
 *  sweep changes again is mostly thrown away (a pile whose contacts keep opening and slipping). This
 *  rule never skips twice in a row, so a moving pile still gets an SM step every other sweep
 *  (skipping at a lower fraction, or twice in a row, let the pyramids fall). */
#define KEA_SM_SKIP_FRACTION 20
/** When the last SM step lowered the QP objective less than the sweep after it ("did not pay"), the
 *  next one waits until at most 1/KEA_SM_UNPAID_FRACTION of the rows (or KEA_SM_SKIP_MIN_CHANGED)
 *  change between chances; this rule may skip any number of chances in a row, until the active set
 *  settles, so a solve run to convergence keeps its SM steps. */
#define KEA_SM_UNPAID_FRACTION 100
/** Halvings of the SM step tried by its projected line search (1, 1/2, 1/4, 1/8) before it is
 *  rejected: a rejected step costs a sweep's worth of work, more halvings rarely find a decrease. */
#define KEA_SM_LINE_SEARCH_TRIES 4
/** SM's CG stops when r . P^-1 r falls below this times its first value: the square of the
 *  precision's small epsilon, below which the residual is rounding noise. */
#define KEA_SM_CG_STOP (ME_SMALL_EPSILON * ME_SMALL_EPSILON)

/** The extra effort (kea_iterative.c, KeaParameters.effortResidual): when the last of a partition's
 *  maxIterations sweeps leaves a residual above effortResidual, the solve sweeps on, two sweeps at a
 *  time with SM between, until a round's last sweep is within it or KEA_EFFORT_FACTOR maxIterations
 *  sweeps were added. The world sets effortResidual to KEA_EFFORT_RESIDUAL (m/s) times its length
 *  scale. Touching pyramids of 30 to 60 rows need it: at a fixed 10 sweeps an under-converged
 *  out-of-plane mode grows from step to step until a box is kicked, and the first settle of a tall
 *  stack, cold-started, lets its top boxes fall freely (docs/kea_log.md, "Touching stacks": 2 mm/s
 *  costs more sweeps for the same result, 10 mm/s holds less margin; a factor of 2 rather than 1 for
 *  the 60-row pyramid's first settle). */
#define KEA_EFFORT_RESIDUAL ME_R(5e-3)
#define KEA_EFFORT_FACTOR 2
/** A round of extra effort is added only while more than this fraction of the partition's blocks is
 *  above effortResidual. An unconverged stack has many such blocks; a settled pile of mixed bodies
 *  keeps a few that more sweeps do not lower, and without the fraction it swept to the cap at most
 *  steps (bench/RESULTS.md, "The pile's extra effort after C22"; decision K57). */
#define KEA_EFFORT_FRACTION ME_R(0.02)
/** The extra effort is for a resting stack or heap that has not converged, not for a pile whose
 *  bodies collide (KeaParameters.effortRestSpeed): it runs only where every row's target velocity
 *  change r_i (only a positive one for a row that can only push: a negative one is a contact's gap)
 *  is at most KEA_EFFORT_REST_SPEED (m/s) times the world's length scale, plus what gravity adds in
 *  one step (the world adds it per step). In a resting pyramid the largest |r_i| is gravity's step
 *  (0.16 m/s at 60 Hz) plus a little correction, at most 0.20 m/s in the 60-row one; in the bench's
 *  pile of 1,000 bodies it never fell below 1.6 m/s in 460 steps, although its residual after the cap
 *  is 10 to 100 times 5 mm/s (docs/kea_log.md, "Touching stacks": a threshold relative to the
 *  velocity scale does not separate them). A settled heap's jitter reaches 0.5 m/s here and there
 *  and, with the effort shut, feeds itself; 1 m/s lets the effort calm it (bench/RESULTS.md,
 *  "Settled heaps"). */
#define KEA_EFFORT_REST_SPEED ME_R(1.0)

/** The world's LCP tolerance (MdtWorldSetLCPTolerance), m/s times its length scale: a solve whose
 *  sweep leaves every row within it stops. A residual of 1e-4 m/s moves a body 2 um in a step at
 *  60 Hz, below the penetration the correction leaves; a tighter stop would chase the rounding of the
 *  contacts' depths, which for a float scene 30 m from the origin is a few um, 1e-5 m/s and more once
 *  divided by the step (bench/RESULTS.md, "smash"): a resting block then sweeps to the cap. */
#define KEA_WORLD_TOLERANCE ME_R(1e-4)

/** The world's SM schedule (KeaParameters.subspaceEvery, subspaceIterations, subspaceStop; K55): SM
 *  after the first sweep and after every second one (before NNCG's momentum), each up to 7 CG steps,
 *  stopped once r . P^-1 r has fallen tenfold. The first chance's CG meets that in two steps (it does
 *  most of a solve's SM work); the later ones never do, and their longer CG runs damp a touching
 *  wall's slow out-of-plane mode better than four steps at every chance, with about half the SM
 *  steps' fixed passes (docs/kea_log.md, "SM's schedule"). */
#define KEA_WORLD_SM_EVERY 2
#define KEA_WORLD_SM_STEPS 7
#define KEA_WORLD_SM_STOP ME_R(0.1)
/** The world's KeaParameters.subspaceJointShare and subspaceJointEvery (K58): a partition at least a
 *  quarter of whose rows are generic (joints: a heap of ragdolls is about half, a joint grid all) gets
 *  SM after its first sweep and its eighth (with 10 sweeps: two SM steps instead of five). The steps
 *  between lower the QP's objective but do not show in the joints' gaps nor in the floor's penetration,
 *  and cost a large share of such a step; a late one is kept because without it a hinged chain on the
 *  iterative path grows unstable (bench/RESULTS.md, "Ragdoll heaps: fewer SM steps"). A stack of
 *  contacts (the touching walls the later steps are for) keeps the full schedule. */
#define KEA_WORLD_SM_JOINT_SHARE ME_R(0.25)
#define KEA_WORLD_SM_JOINT_EVERY 8

#endif
