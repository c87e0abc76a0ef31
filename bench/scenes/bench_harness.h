/* bench_harness.h -- the loop every benchmark program shares: build a scene, time each step, count
 * contacts, measure the scene's quality, print one CSV line per (engine variant, scene).
 *
 * An engine (Karma, an ODE variant, Bullet) only supplies a BenchEngine: create a world from a
 * BenchScene, step it once, say how many contacts the step used, copy the body poses out, destroy.
 * The harness times the step callback alone (CLOCK_MONOTONIC, and CPU time beside it); reading poses and measuring quality
 * happen outside the timed region.
 *
 * Output (stdout), one line per run, columns:
 *   engine,variant,scene,bodies,steps,steps_run,median_ms,mean_ms,median_cpu_ms,mean_contacts,
 *   quality_name,quality_value,standing,floor_pen_m,mean_joint_err_m,note,p99_ms,p99_cpu_ms
 * median_ms and mean_ms are wall time (CLOCK_MONOTONIC); median_cpu_ms is the process CPU time of
 * the step (CLOCK_PROCESS_CPUTIME_ID), which a loaded machine inflates far less.
 * p99_ms and p99_cpu_ms are the 99th-percentile step (nearest rank), wall and CPU: a game budgets for
 * its worst frames, and p99 / median says how steady the steps are (issue 17 point 4).
 * standing is yes / no / - (no verdict); note says why a run stopped early (no commas). Progress goes
 * to stderr. */
#ifndef KARMA_BENCH_HARNESS_H
#define KARMA_BENCH_HARNESS_H

#include "bench_scenes.h"

#ifdef __cplusplus
extern "C" {
#endif

#define BENCH_CSV_HEADER                                                                            \
    "engine,variant,scene,bodies,steps,steps_run,median_ms,mean_ms,median_cpu_ms,mean_contacts,quality_name," \
    "quality_value,standing,floor_pen_m,mean_joint_err_m,note,p99_ms,p99_cpu_ms"

typedef struct BenchEngine {
    const char *engine;   /**< "karma", "ode", "bullet" */
    const char *variant;  /**< e.g. "quickstep20"; what --variants= selects */
    const char *settings; /**< one line: the solver settings used (printed by --list) */
    /** Build a world for `scene`; NULL on failure. */
    void *(*create)(const BenchScene *scene);
    /** One step of scene->step seconds, collision included. 0 to go on; non-zero stops the run
     *  (that step is not counted) with a reason in *why. */
    int (*step)(void *world, const char **why);
    /** Contacts the last step solved with. */
    int (*contacts)(void *world);
    /** Current poses of all bodies (fixed bodies may be left as they are). */
    void (*read)(void *world, double (*pos)[3], double (*quat)[4]);
    void (*destroy)(void *world);
    /** Optional (may be NULL): a remark on the finished run for the note column (no commas), e.g.
     *  how many solver failures the engine reported; NULL or "" for none. Called before destroy. */
    const char *(*remark)(void *world);
} BenchEngine;

/** Parse the command line and run the selected scenes with the selected engines. Options:
 *    --scenes=a,b,...   scene names (default: the set's)
 *    --set=S            standard (BENCH_STANDARD_SCENES, the default), others (BENCH_OTHERS_SCENES) or
 *                       all: the scenes --list lists and --scenes defaults to
 *    --variants=x,y     engine variants (default: all that the program has)
 *    --steps=N          override every scene's step count
 *    --budget=S         stop a run once its timed steps add up to S seconds of CPU time (default 60)
 *    --trace=I          print body I's pose every 60 steps to stderr
 *    --threads=N        threads an engine may step with (BenchThreads; default 1; engines without
 *                       threads ignore it)
 *    --step-times       print every timed step's CPU and wall time (ms) to stderr
 *    --header           print the CSV header first
 *    --list             list variants and scenes and exit
 *  Returns the process exit status (0, or 2 on a bad argument). */
/** --threads=N: threads the engine may step a world with (1 = the calling thread only). */
extern int BenchThreads;

int BenchMain(int argc, char **argv, const BenchEngine *engines, int engineCount);

#ifdef __cplusplus
}
#endif

#endif
