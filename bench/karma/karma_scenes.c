/* karma_scenes.c -- the benchmark scenes in Karma (this library, through MstUniverse).
 *
 * Two variants on the same scenes:
 *   default  Karma's defaults: Kea with MdtLCPSolverAuto (exact up to 128 rows per partition,
 *            iterative with 10 sweeps above), ε = 0.01 / massScale (but see "Heavy jointed
 *            bodies"), γ = 0.2, auto-disable on with Karma's thresholds (bodies at rest go to
 *            sleep, their models are frozen)
 *   nosleep  the same with auto-disable off (compare with bullet si10-nosleep)
 *
 * What a Karma user writes: one MstUniverse sized from the scene, a plane for the ground and static
 * models (MstFixedModelCreate) for fixed bodies, one model with a body per dynamic body
 * (MstModelAndBodyCreate), ball joints (MdtBSJoint) and hinges (MdtHinge) from the world anchor and
 * axis, the pairs of jointed bodies disabled in the space, and one material-table entry (the default
 * pair) for every contact: 2-D friction, NormalForce model (Coulomb: bound = μ × normal force) with
 * μ = 0.6, restitution 0 (the default). The timed step is MstUniverseStep: McdSpaceUpdateAll (farfield),
 * MstBridgeUpdateContacts (nearfield and contact conversion) and MdtWorldStep.
 *
 * Mass properties: the scene's masses and principal moments (BenchBodyInertia, uniform solids), set
 * as a diagonal tensor with non-spherical inertia enabled (MdtBody uses the mean of the diagonal
 * otherwise, and MstModelAndBodyCreate does not enable it). The gyroscopic term stays off, Karma's
 * default (MdtBodyEnableCoriolisForce).
 *
 * massScale: the world's ε is 0.01 / massScale, and Karma asks the application to set massScale to a
 * typical mass of the scene (docs/decisions.md M5; every demo does), or heavy bodies sink into soft
 * contacts. We pass the mean mass of the scene's dynamic bodies: 1 kg for the boxes, spheres and
 * chain links, 58/11 = 5.3 kg for the ragdolls. lengthScale is 1 (metre-sized bodies).
 *
 * Heavy jointed bodies (b2spinner's bar, b2tumbler's walls): Karma's ε is one world-wide compliance,
 * so every joint row is a spring of stiffness γ/(ε h²) whatever the masses it holds, and a body of
 * mass m hanging on a joint sags by ε m g h²/γ = 0.01 (m / massScale) g h²/γ (1.4 mm per unit of
 * m / massScale at 60 Hz, γ 0.2). Karma asks for masses within 100 times massScale (ME_ERR_MASS_SCALE);
 * where a jointed body is heavier than that, we do what a Karma user does on that warning and set the
 * world's ε (MdtWorldSetEpsilon) from that body's mass, 0.01 / m: its joints then hold to a tenth of a
 * millimetre per g, while the light bodies' contacts, already rigid (ε m ≪ 1), do not change. The
 * other scenes keep ε = 0.01 / massScale (docs/decisions.md, "K-quality" entries).
 *
 * Motors (b2spinner, b2tumbler): a hinge's limit motor (MdtLimitSetLimitedForceMotor) with the scene's
 * speed and torque bound; Karma's angle, body 0 relative to body 1, is the sense the scene's motor
 * speed is given in. Initial velocities (b2smash): MdtBodySetLinearVelocity.
 *
 * Hinge limits: Karma's hinge angle is that of body 0 relative to body 1 (MdtHinge.h), the opposite of
 * the scene's (body[1] relative to body[0]), so the stops swap and change sign, as for ODE. Karma's
 * stops bounce with restitution 1 by default (MdtLimit.h); the scenes ask for restitution 0 (and ODE's
 * and Bullet's stops do not bounce), so the stops get restitution 0.
 *
 * Warnings: a message handler counts Karma's messages at warning level and above (pool full,
 * non-finite state...) instead of printing them, and the remark column gives their count and the
 * first one's code.
 *
 * Threads: with --threads=N above 1 the universe steps on a MeThreadPool of N threads (karma_threads,
 * MeThreadPoolAttachUniverse), made once for the process; the trajectories are the same for any N.
 * KARMA_SPLIT_ROWS=R in the environment splits every iterative partition of at least R rows over the
 * threads (MdtWorldSetPartitionSplitRows: the pile's heap); its trajectories differ from the unsplit
 * ones, but are again the same for any N (one thread included). KARMA_DEFLATION=1 turns the
 * solver's coarse correction on (MdtWorldSetDeflation; off by default).
 *
 * Profile: with KARMA_BENCH_PROFILE=1 in the environment, each run prints to stderr the time per step
 * of every profile section (MstUniverseGetProfile: Collision = Farfield + Nearfield;
 * MdtWorldGetProfile: Dynamics = Partition, AutoDisable, LOD, Pack, Solve, Integrate, Unpack), mean
 * solver statistics and the pools' high-water marks. The sections are timed in process CPU time then
 * (the profiles' clock is replaced), which the load of a shared machine inflates far less than wall
 * time; the harness's own timing is unaffected apart from the clock calls (~20 per step).
 *
 * Tasks: with KARMA_BENCH_TASKS=1, the world's task system is wrapped so that every task the step
 * hands out is logged by stage (tasks per step, items, wall time of the hand-outs); at the end of the
 * run the figures are printed to stderr, with the step's wall time outside the tasks. With
 * --threads=1 the wrapper declares 2 workers and runs every task inline on the stepping thread (what
 * the serial step does, plus the marks), so that the two runs compare stage by stage. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <karma/karma.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <MeThreadPool.h>

#include "bench_harness.h"
#include "bench_karma.h"

typedef struct KarmaWorld {
    const BenchScene *scene;
    MstUniverseID universe;
    MdtWorldID world;
    MdtBodyID *bodies;   /* NULL for fixed bodies */
    MeMatrix4 *fixedTM;  /* transforms of the fixed models (they must outlive the models) */
    MeMatrix4 groundTM;  /* the ground plane's, turned to y-up (it must outlive the model) */
    int steps;
    int profile;         /* KARMA_BENCH_PROFILE set: gather and print the profile */
    int stepStats;       /* KARMA_BENCH_STEPSTATS set: print the solver statistics of every step */
    int taskLog;         /* KARMA_BENCH_TASKS set: log the tasks of every step */
    /* solver statistics summed over the steps (profile only) */
    double partitions, iterativePartitions, iterations, pivots, rows;
    int maxPartitionRows, maxPairs, unconverged;
    char remark[160];
} KarmaWorld;

/* Karma's warnings, counted instead of printed. The harness runs one world at a time, so a
 * process-wide count reset at creation is the current world's. */
static unsigned long karmaWarnings;
static char karmaFirstWarning[96];

static void count_message(const MeMessageInfo *info, void *user)
{
    (void)user;
    if (info->level < ME_LEVEL_WARNING)
        return;
    if (info->level >= ME_LEVEL_FATAL)
        MeDefaultMessageHandler(info, NULL); /* an internal inconsistency: print it and abort */
    if (karmaWarnings++ == 0)
        snprintf(karmaFirstWarning, sizeof karmaFirstWarning, "%s in %s", MeErrorCodeName(info->code),
                 info->function ? info->function : "?");
}

/* The profiles' clock in profile mode: process CPU time (seconds). */
static double cpu_seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The pool of --threads=N (N > 1), made at the first world and kept for the process. */
static MeThreadPool *threadPool;

static double wall_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return 1e9 * (double)t.tv_sec + (double)t.tv_nsec;
}

/* KARMA_BENCH_TASKS: the tasks of the steps, by stage. The stage is told by the task's smallest
 * range (docs/step.md's table: pair tests 8, prediction 64, rows 4 before the solves' 1, integration
 * 4 after it, unpack 32), which is all a task system sees of it. */
enum { TASK_PAIRS, TASK_PREDICT, TASK_ROWS, TASK_SOLVE, TASK_INTEGRATE, TASK_UNPACK, TASK_OTHER, TASK_STAGES };
static const char *const taskStageNames[TASK_STAGES] = {"pair tests", "prediction", "rows", "solves",
                                                        "integration", "unpack", "other"};
typedef struct TaskStage {
    double count, items, wallNs;
} TaskStage;
static TaskStage taskStages[TASK_STAGES];
static int taskSolved;        /* the current step's solves have been handed out */
static double taskStepWallNs; /* wall time of the steps, summed */

static int task_stage(int minRange)
{
    switch (minRange) {
    case 8: return TASK_PAIRS;
    case 64: return TASK_PREDICT;
    case 4: return taskSolved ? TASK_INTEGRATE : TASK_ROWS;
    case 1: taskSolved = 1; return TASK_SOLVE;
    case 32: return TASK_UNPACK;
    default: return TASK_OTHER;
    }
}

static void *logged_enqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    double t0 = wall_ns();
    if (user)
        MeThreadPoolEnqueue(task, itemCount, minRange, taskData, user);
    else
        task(0, itemCount, 0, taskData);
    TaskStage *s = &taskStages[task_stage(minRange)];
    s->wallNs += wall_ns() - t0;
    s->count++;
    s->items += itemCount;
    return NULL;
}

static void logged_finish(void *userTask, void *user)
{
    (void)userTask;
    (void)user;
}

static void print_task_log(const char *scene, int steps)
{
    double inTasks = 0;
    fprintf(stderr, "  karma tasks, %s, %d steps (%s): stage: tasks per step, mean items, wall us per step\n", scene,
            steps, threadPool ? "pool" : "inline");
    for (int i = 0; i < TASK_STAGES; i++) {
        const TaskStage *s = &taskStages[i];
        if (s->count == 0)
            continue;
        fprintf(stderr, "    %-12s %6.2f %8.1f %9.1f\n", taskStageNames[i], s->count / steps, s->items / s->count,
                s->wallNs / steps * 1e-3);
        inTasks += s->wallNs;
    }
    fprintf(stderr, "    step wall us: %.1f, in tasks %.1f, outside %.1f\n", taskStepWallNs / steps * 1e-3,
            inTasks / steps * 1e-3, (taskStepWallNs - inTasks) / steps * 1e-3);
    memset(taskStages, 0, sizeof taskStages);
    taskStepWallNs = 0;
}

static double mean_dynamic_mass(const BenchScene *s)
{
    double sum = 0;
    int n = 0;
    for (int i = 0; i < s->bodyCount; i++)
        if (!s->bodies[i].fixed) {
            sum += s->bodies[i].mass;
            n++;
        }
    return n ? sum / n : 1.0;
}

/* The heaviest dynamic body held by a joint (0 kg when none). */
static double heaviest_jointed_mass(const BenchScene *s)
{
    double heaviest = 0;
    for (int k = 0; k < s->jointCount; k++)
        for (int side = 0; side < 2; side++) {
            int b = s->joints[k].body[side];
            if (b >= 0 && !s->bodies[b].fixed && s->bodies[b].mass > heaviest)
                heaviest = s->bodies[b].mass;
        }
    return heaviest;
}

static McdGeometryID make_geometry(McdFrameworkID fw, const BenchBody *b)
{
    switch (b->shape) {
    case BENCH_SPHERE:
        return McdSphereCreate(fw, (MeReal)b->size[0]);
    case BENCH_CAPSULE: /* Karma's height is the cylinder part: twice the scene's half-length */
        return McdSphylCreate(fw, (MeReal)b->size[0], (MeReal)(2 * b->size[1]));
    case BENCH_BOX:
    default: /* full edge lengths */
        return McdBoxCreate(fw, (MeReal)(2 * b->size[0]), (MeReal)(2 * b->size[1]), (MeReal)(2 * b->size[2]));
    }
}

static void karma_destroy(void *world)
{
    KarmaWorld *w = world;
    if (!w)
        return;
    if (w->profile && w->steps > 0) {
        const MeProfile *p[2] = {MstUniverseGetProfile(w->universe), MdtWorldGetProfile(w->world)};
        fprintf(stderr, "  karma profile, %s, ms per step over %d steps (CPU):", w->scene->name, w->steps);
        for (int k = 0; k < 2; k++)
            for (int i = 0; i < MeProfileGetSectionCount(p[k]); i++) {
                const MeProfileSection *s = MeProfileGetSectionByIndex(p[k], i);
                fprintf(stderr, " %s %.3f", s->name, s->totalTime / w->steps * 1e3);
            }
        MdtWorldCounters c;
        MdtWorldGetCounters(w->world, &c);
        McdSpaceID space = MstUniverseGetSpace(w->universe);
        fprintf(stderr,
                "\n  karma solver, mean per step: %.1f partitions (%.2f iterative), %.1f rows, %.1f sweeps, %.1f pivots; largest "
                "partition %d rows; %d unconverged partition-steps; pools: bodies %d/%d constraints %d/%d pairs "
                "%d/%d (lost %d)\n",
                w->partitions / w->steps, w->iterativePartitions / w->steps, w->rows / w->steps,
                w->iterations / w->steps, w->pivots / w->steps, w->maxPartitionRows, w->unconverged, c.bodyPoolHighWater,
                MdtWorldGetMaxBodies(w->world), c.constraintPoolHighWater, MdtWorldGetMaxConstraints(w->world),
                w->maxPairs, McdSpaceGetPairCapacity(space), McdSpaceGetLostPairCount(space));
    }
    if (w->taskLog && w->steps > 0)
        print_task_log(w->scene->name, w->steps);
    if (w->universe)
        MstUniverseDestroy(w->universe);
    free(w->bodies);
    free(w->fixedTM);
    free(w);
}

/* Whether the environment variable `name` is set to something other than "" or "0". */
static MeBool env_flag(const char *name)
{
    const char *v = getenv(name);
    return v && *v && strcmp(v, "0") != 0;
}

/* The universe for the scene (its pools, thread pool, task log, profile clock) and its world's
 * settings; MEFALSE when it cannot be made. */
static MeBool karma_make_universe(KarmaWorld *w, const BenchScene *scene, MeBool autoDisable)
{
    /* Pools. Models: every body and the ground. Pairs (overlapping boxes, the ground's with every
     * body among them, and one entry per disabled pair): the pile's bottom layers and the pyramids
     * have up to ~8 neighbours per body. Constraints: joints, and for every pair the space can hold a
     * contact group and up to 4 contacts (the framework's default contactMaxCount): a touching 3-D
     * block (b2smash) has up to 13 pairs per box, and a full pool drops contacts (the projectile
     * then passes through the block). */
    int models = scene->bodyCount + 1;
    int pairs = 10 * scene->bodyCount + scene->jointCount + 256;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = scene->dynamicCount > 0 ? scene->dynamicCount : 1;
    sizes.collisionModelsMaxCount = models;
    sizes.collisionPairsMaxCount = pairs;
    sizes.dynamicConstraintsMaxCount = scene->jointCount + 5 * pairs;
    sizes.lengthScale = 1;
    sizes.massScale = (MeReal)mean_dynamic_mass(scene);
    w->universe = MstUniverseCreate(&sizes);
    if (!w->universe)
        return MEFALSE;
    w->world = MstUniverseGetWorld(w->universe);
    if (BenchThreads > 1) {
        if (!threadPool)
            threadPool = MeThreadPoolCreate(BenchThreads);
        if (!threadPool)
            return MEFALSE;
        MeThreadPoolAttachUniverse(threadPool, w->universe);
    }
    if (w->taskLog)
        MstUniverseSetTaskSystem(w->universe, BenchThreads > 1 ? BenchThreads : 2, logged_enqueue, logged_finish,
                                 threadPool);
    if (w->profile) {
        /* The universe hands out its profile read-only; setting its clock is all we change. */
        MeProfileSetTimer((MeProfile *)MstUniverseGetProfile(w->universe), cpu_seconds);
        MeProfileSetTimer(MdtWorldGetProfilePtr(w->world), cpu_seconds);
    }
    MdtWorldSetGravity(w->world, (MeReal)scene->gravity[0], (MeReal)scene->gravity[1], (MeReal)scene->gravity[2]);
    MdtWorldSetAutoDisable(w->world, autoDisable);
    if (env_flag("KARMA_DEFLATION"))
        MdtWorldSetDeflation(w->world, METRUE);
    const char *splitRows = getenv("KARMA_SPLIT_ROWS");
    if (splitRows && *splitRows)
        MdtWorldSetPartitionSplitRows(w->world, atoi(splitRows));
    double heavy = heaviest_jointed_mass(scene);
    if (heavy > 100 * (double)sizes.massScale) /* joints on bodies past Karma's mass range: ε for them */
        MdtWorldSetEpsilon(w->world, (MeReal)((double)MDTWORLD_DEFAULT_EPSILON / heavy));
    return METRUE;
}

/* The ground plane, when the scene has one; MEFALSE when it cannot be made. */
static MeBool karma_add_ground(KarmaWorld *w, McdFrameworkID fw)
{
    if (!w->scene->hasGround)
        return METRUE;
    /* The scenes are y-up; Karma's plane is the half-space z <= 0 of its frame, so it is turned by
     * -90 degrees about x (rows {1,0,0}, {0,0,-1}, {0,1,0}: local +z onto world +y, docs K30). */
    static const MeMatrix4 yUpGround = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
    memcpy(w->groundTM, yUpGround, sizeof w->groundTM);
    return MstFixedModelCreate(w->universe, McdPlaneCreate(fw), w->groundTM) != NULL;
}

/* The scene's bodies, fixed ones as fixed models, their models into model[]; MEFALSE on a failure. */
static MeBool karma_add_bodies(KarmaWorld *w, McdFrameworkID fw, McdModelID *model)
{
    const BenchScene *scene = w->scene;
    for (int i = 0; i < scene->bodyCount; i++) {
        const BenchBody *b = &scene->bodies[i];
        McdGeometryID g = make_geometry(fw, b);
        if (!g)
            return MEFALSE;
        if (b->fixed) {
            MeVector4 q = {(MeReal)b->quat[0], (MeReal)b->quat[1], (MeReal)b->quat[2], (MeReal)b->quat[3]};
            MeMatrix4TMMakeIdentity(w->fixedTM[i]);
            MeMatrix4TMSetRotationFromQuaternion(w->fixedTM[i], q);
            for (int k = 0; k < 3; k++)
                w->fixedTM[i][3][k] = (MeReal)b->pos[k];
            model[i] = MstFixedModelCreate(w->universe, g, w->fixedTM[i]);
            if (!model[i])
                return MEFALSE;
            continue;
        }
        double inertia[3];
        BenchBodyInertia(b, inertia);
        model[i] = bench_karma_body(w->universe, g, b->mass, inertia, b->pos, b->quat);
        if (!model[i])
            return MEFALSE;
        MdtBodyID body = McdModelGetBody(model[i]);
        MdtBodySetLinearVelocity(body, (MeReal)b->vel[0], (MeReal)b->vel[1], (MeReal)b->vel[2]);
        w->bodies[i] = body;
    }
    return METRUE;
}

/* The scene's joint `bj` (a ball joint, or a hinge with its limits and motor), enabled; NULL when it
 * cannot be made. */
static MdtConstraintID karma_make_joint(KarmaWorld *w, const BenchJoint *bj)
{
    MdtBodyID b0 = w->bodies[bj->body[0]], b1 = bj->body[1] >= 0 ? w->bodies[bj->body[1]] : NULL;
    MdtConstraintID c;
    if (bj->type == BENCH_BALL) {
        MdtBSJointID j = MdtBSJointCreate(w->world);
        if (!j)
            return NULL;
        MdtBSJointSetBodies(j, b0, b1);
        MdtBSJointSetPosition(j, (MeReal)bj->anchor[0], (MeReal)bj->anchor[1], (MeReal)bj->anchor[2]);
        c = MdtBSJointQuaConstraint(j);
    } else {
        MdtHingeID j = MdtHingeCreate(w->world);
        if (!j)
            return NULL;
        MdtHingeSetBodies(j, b0, b1);
        MdtHingeSetPosition(j, (MeReal)bj->anchor[0], (MeReal)bj->anchor[1], (MeReal)bj->anchor[2]);
        MdtHingeSetAxis(j, (MeReal)bj->axis[0], (MeReal)bj->axis[1], (MeReal)bj->axis[2]);
        if (bj->limited) {
            /* Karma measures body 0 relative to body 1: the opposite sign of the scene's angle */
            MdtLimitID l = MdtHingeGetLimit(j);
            MdtSingleLimitSetStop(MdtLimitGetLowerLimit(l), (MeReal)-bj->hi);
            MdtSingleLimitSetStop(MdtLimitGetUpperLimit(l), (MeReal)-bj->lo);
            MdtSingleLimitSetRestitution(MdtLimitGetLowerLimit(l), 0);
            MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(l), 0);
            MdtLimitActivateLimits(l, METRUE);
        }
        if (bj->motor) /* Karma's angle is body 0 relative to body 1, the motor's sense */
            MdtLimitSetLimitedForceMotor(MdtHingeGetLimit(j), (MeReal)bj->motorSpeed, (MeReal)bj->motorTorque);
        c = MdtHingeQuaConstraint(j);
    }
    MdtConstraintEnable(c);
    return c;
}

/* The scene's joints; jointed bodies' models (model[]) do not collide. MEFALSE on a failure. */
static MeBool karma_add_joints(KarmaWorld *w, McdModelID *model)
{
    const BenchScene *scene = w->scene;
    McdSpaceID space = MstUniverseGetSpace(w->universe);
    MeBool changing = McdSpaceIsChanging(space);
    if (!changing)
        McdSpaceBeginChanges(space);
    for (int k = 0; k < scene->jointCount; k++) {
        const BenchJoint *bj = &scene->joints[k];
        if (!karma_make_joint(w, bj))
            return MEFALSE;
        if (bj->body[1] >= 0) /* jointed bodies do not collide */
            McdSpaceDisablePair(model[bj->body[0]], model[bj->body[1]]);
    }
    if (!changing)
        McdSpaceEndChanges(space);
    return METRUE;
}

static void *karma_create(const BenchScene *scene, MeBool autoDisable)
{
    KarmaWorld *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->scene = scene;
    w->profile = env_flag("KARMA_BENCH_PROFILE");
    w->stepStats = env_flag("KARMA_BENCH_STEPSTATS");
    w->taskLog = env_flag("KARMA_BENCH_TASKS");
    w->bodies = calloc((size_t)scene->bodyCount, sizeof *w->bodies);
    w->fixedTM = calloc((size_t)scene->bodyCount, sizeof *w->fixedTM);
    if (!w->bodies || !w->fixedTM) {
        karma_destroy(w);
        return NULL;
    }
    karmaWarnings = 0;
    karmaFirstWarning[0] = '\0';
    if (!karma_make_universe(w, scene, autoDisable)) {
        karma_destroy(w);
        return NULL;
    }
    bench_karma_contact_defaults(w->universe, scene->friction);
    McdFrameworkID fw = MstUniverseGetFramework(w->universe);
    if (!karma_add_ground(w, fw)) {
        karma_destroy(w);
        return NULL;
    }
    McdModelID *model = calloc((size_t)scene->bodyCount, sizeof *model);
    if (!model) {
        karma_destroy(w);
        return NULL;
    }
    if (!karma_add_bodies(w, fw, model) || !karma_add_joints(w, model)) {
        free(model);
        karma_destroy(w);
        return NULL;
    }
    free(model);
    return w;
}

static void *karma_create_default(const BenchScene *scene) { return karma_create(scene, METRUE); }
static void *karma_create_nosleep(const BenchScene *scene) { return karma_create(scene, MEFALSE); }

static int karma_step(void *world, const char **why)
{
    (void)why;
    KarmaWorld *w = world;
    double t0 = w->taskLog ? wall_ns() : 0;
    taskSolved = 0;
    MstUniverseStep(w->universe, (MeReal)w->scene->step);
    if (w->taskLog)
        taskStepWallNs += wall_ns() - t0;
    w->steps++;
    if (w->stepStats) { /* KARMA_BENCH_STEPSTATS=1: what the solver did in each step, to stderr */
        MdtSolverStats s;
        MdtWorldGetSolverStats(w->world, &s);
        fprintf(stderr, "    solver step %5d partitions %d direct %d iterative %d rows %d largest %d sweeps %d pivots %d unconverged %d\n",
                w->steps, s.partitions, s.directPartitions, s.iterativePartitions, s.rows, s.maxPartitionRows,
                s.iterations, s.pivots, s.unconverged);
    }
    if (w->profile) {
        MdtSolverStats s;
        MdtWorldGetSolverStats(w->world, &s);
        w->partitions += s.partitions;
        w->iterativePartitions += s.iterativePartitions;
        w->iterations += s.iterations;
        w->pivots += s.pivots;
        w->rows += s.rows;
        w->unconverged += s.unconverged;
        if (s.maxPartitionRows > w->maxPartitionRows)
            w->maxPartitionRows = s.maxPartitionRows;
        int pairs = McdSpaceGetPairCount(MstUniverseGetSpace(w->universe));
        if (pairs > w->maxPairs)
            w->maxPairs = pairs;
    }
    return 0;
}

static int karma_contacts(void *world) { return bench_karma_contact_count(((KarmaWorld *)world)->universe); }

static void karma_read(void *world, double (*pos)[3], double (*quat)[4])
{
    KarmaWorld *w = world;
    bench_karma_read(w->bodies, w->scene->bodyCount, pos, quat);
}

static const char *karma_remark(void *world)
{
    KarmaWorld *w = world;
    if (karmaWarnings == 0)
        return NULL;
    snprintf(w->remark, sizeof w->remark, "%lu Karma warnings; first: %s", karmaWarnings, karmaFirstWarning);
    return w->remark;
}

int main(int argc, char **argv)
{
    static const BenchEngine engines[] = {
        {"karma", "default",
         "MstUniverseStep; Kea auto (exact up to 128 rows; else 10 iterations); eps 0.01/massScale (massScale = "
         "mean body mass; 0.01/m for jointed bodies over 100 x massScale); gamma 0.2; auto-disable on; 2D friction NormalForce mu 0.6",
         karma_create_default, karma_step, karma_contacts, karma_read, karma_destroy, karma_remark},
        {"karma", "nosleep", "as default with auto-disable off", karma_create_nosleep, karma_step, karma_contacts,
         karma_read, karma_destroy, karma_remark},
    };
    MeSetMessageHandler(count_message, NULL, NULL);
    return BenchMain(argc, argv, engines, (int)(sizeof engines / sizeof engines[0]));
}
