/* karma_bench_mdt.c -- Karma's dynamics on the scenes of mdt_scenes.h, with hand-made contacts.
 *
 *   karma_bench_mdt [--scenes=chain,column,wall] [--paths=direct,iterative] [--steps=N] [--budget=S]
 *
 * For every scene and solver path: build the world from the scene's data, refresh the hand-made
 * contacts (tests/support/karma_contacts.c) before every step, time each MdtWorldStep, and print one
 * Markdown table row: partitions and rows of the largest partition, median milliseconds per step
 * (wall clock, and processor time of this process, which a busy shared machine inflates less),
 * the solver's worst residual, iterations, and the scene's quality figure. Auto-disable is off so
 * that every step does the same work. A run that exceeds its time budget (default 20 s) stops early
 * and says after how many steps. Nothing here is part of the library. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <karma/Mdt.h>
#include <karma/MeVersion.h>

#include "karma_contacts.h"
#include "mdt_scenes.h"

typedef struct Run {
    int steps;              /* steps done */
    double medianMs;        /* wall clock */
    double medianCpuMs;     /* processor time of this process (robust on a shared machine) */
    int partitions, maxRows;
    double maxResidual;     /* worst solver residual over the run (m/s) */
    double iterations;      /* mean iterations per step (iterative path) */
    BenchMdtQualityState quality;
} Run;

static double now(void)
{
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int compareDoubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Read the poses of all bodies into double arrays. */
static void poses(MdtBodyID *bodies, int n, double (*pos)[3], double (*quat)[4])
{
    for (int i = 0; i < n; i++) {
        MeVector3 p;
        MeVector4 q;
        MdtBodyGetPosition(bodies[i], p);
        MdtBodyGetQuaternion(bodies[i], q);
        for (int k = 0; k < 3; k++)
            pos[i][k] = (double)p[k];
        for (int k = 0; k < 4; k++)
            quat[i][k] = (double)q[k];
    }
}

/* The scene's bodies, ball joints and contact groups (one per support) in world w. */
static void populate(const BenchMdtScene *s, MdtWorldID w, MdtBodyID *bodies, MdtContactGroupID *groups)
{
    for (int i = 0; i < s->bodyCount; i++) {
        const BenchMdtBody *b = &s->bodies[i];
        MeMatrix3 I;
        bodies[i] = MdtBodyCreate(w);
        MdtBodySetMass(bodies[i], (MeReal)b->mass);
        MdtMakeInertiaTensorBox((MeReal)b->mass, (MeReal)(2 * b->half[0]), (MeReal)(2 * b->half[1]),
                                (MeReal)(2 * b->half[2]), I);
        MdtBodySetInertiaTensor(bodies[i], I);
        MdtBodyEnableNonSphericalInertia(bodies[i]);
        MdtBodySetPosition(bodies[i], (MeReal)b->pos[0], (MeReal)b->pos[1], (MeReal)b->pos[2]);
        MdtBodyEnable(bodies[i]);
    }
    for (int j = 0; j < s->jointCount; j++) {
        const BenchMdtJoint *jt = &s->joints[j];
        MdtBSJointID joint = MdtBSJointCreate(w);
        MdtBSJointSetBodies(joint, bodies[jt->body[0]], jt->body[1] >= 0 ? bodies[jt->body[1]] : NULL);
        MdtBSJointSetPosition(joint, (MeReal)jt->anchor[0], (MeReal)jt->anchor[1], (MeReal)jt->anchor[2]);
        MdtBSJointEnable(joint);
    }
    for (int k = 0; k < s->supportCount; k++) {
        const BenchMdtSupport *sp = &s->supports[k];
        groups[k] = MdtContactGroupCreate(w);
        MdtContactGroupSetBodies(groups[k], bodies[sp->upper], sp->lower >= 0 ? bodies[sp->lower] : NULL);
        MdtContactGroupEnable(groups[k]);
    }
}

/* Each support's contacts for this step: a box on the ground plane (normal `up`) or on another box. */
static void placeContacts(const BenchMdtScene *s, const MdtBodyID *bodies, MdtContactGroupID *groups,
                          const MeVector3 up, const MdtContactParams *params)
{
    for (int k = 0; k < s->supportCount; k++) {
        const BenchMdtSupport *sp = &s->supports[k];
        const BenchMdtBody *u = &s->bodies[sp->upper];
        MeVector3 hu = {(MeReal)u->half[0], (MeReal)u->half[1], (MeReal)u->half[2]};
        if (sp->lower < 0) {
            karma_box_on_plane(groups[k], bodies[sp->upper], hu, up, 0, params);
        } else {
            const BenchMdtBody *l = &s->bodies[sp->lower];
            MeVector3 hl = {(MeReal)l->half[0], (MeReal)l->half[1], (MeReal)l->half[2]};
            karma_box_on_box_clipped(groups[k], bodies[sp->upper], hu, bodies[sp->lower], hl, params);
        }
    }
}

/* The step's solver statistics into run's largest figures; returns the step's iterations. */
static double recordStats(MdtWorldID w, Run *run)
{
    MdtSolverStats st;
    MdtWorldGetSolverStats(w, &st);
    if (st.maxPartitionRows > run->maxRows)
        run->maxRows = st.maxPartitionRows;
    if (st.partitions > run->partitions)
        run->partitions = st.partitions;
    if ((double)st.maxResidual > run->maxResidual)
        run->maxResidual = (double)st.maxResidual;
    return st.iterations;
}

static int runScene(const BenchMdtScene *s, MdtLCPSolver path, int steps, double budget, Run *run)
{
    memset(run, 0, sizeof *run);
    const unsigned maxConstraints = (unsigned)(s->jointCount + 5 * s->supportCount + 8);
    MdtWorldID w = MdtWorldCreate((unsigned)s->bodyCount, maxConstraints, 1, 1);
    MdtBodyID *bodies = calloc((size_t)s->bodyCount, sizeof *bodies);
    MdtContactGroupID *groups = calloc((size_t)(s->supportCount + 1), sizeof *groups);
    double(*pos)[3] = calloc((size_t)s->bodyCount, sizeof *pos);
    double(*quat)[4] = calloc((size_t)s->bodyCount, sizeof *quat);
    double *times = calloc((size_t)steps, sizeof *times);
    double *cpu = calloc((size_t)steps, sizeof *cpu);
    if (!w || !bodies || !groups || !pos || !quat || !times || !cpu)
        return 0;
    MdtWorldSetGravity(w, (MeReal)s->gravity[0], (MeReal)s->gravity[1], (MeReal)s->gravity[2]);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtWorldSetLCPSolver(w, path);
    populate(s, w, bodies, groups);
    MdtContactParams params;
    karma_contact_params_friction(&params, (MeReal)s->friction);
    const MeVector3 up = {0, 1, 0}; /* the scenes are y-up */

    BenchMdtQualityInit(s, &run->quality);
    double start = now(), iterations = 0;
    for (int i = 0; i < steps; i++) {
        placeContacts(s, bodies, groups, up, &params);
        double t0 = now();
        clock_t c0 = clock();
        MdtWorldStep(w, (MeReal)s->step);
        cpu[i] = (double)(clock() - c0) / CLOCKS_PER_SEC;
        times[i] = now() - t0;
        iterations += recordStats(w, run);
        poses(bodies, s->bodyCount, pos, quat);
        BenchMdtQualityObserve(s, &run->quality, (const double(*)[3])pos, (const double(*)[4])quat);
        run->steps = i + 1;
        if (now() - start > budget)
            break;
    }
    BenchMdtQualityFinish(s, &run->quality, (const double(*)[3])pos, (const double(*)[4])quat);
    qsort(times, (size_t)run->steps, sizeof *times, compareDoubles);
    run->medianMs = 1e3 * times[run->steps / 2];
    qsort(cpu, (size_t)run->steps, sizeof *cpu, compareDoubles);
    run->medianCpuMs = 1e3 * cpu[run->steps / 2];
    run->iterations = iterations / run->steps;
    MdtWorldDestroy(w);
    free(bodies);
    free(groups);
    free(pos);
    free(quat);
    free(times);
    free(cpu);
    return 1;
}

static void printMachine(void)
{
    char model[256] = "unknown";
    int cpus = 0;
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f)) {
            if (!strncmp(line, "processor", 9))
                cpus++;
            else if (!strncmp(line, "model name", 10) && !strcmp(model, "unknown")) {
                const char *colon = strchr(line, ':');
                if (colon) {
                    snprintf(model, sizeof model, "%s", colon + 2);
                    model[strcspn(model, "\n")] = 0;
                }
            }
        }
        fclose(f);
    }
    printf("machine: %s, %d logical CPUs; %s, MeReal = %s\n\n", model, cpus, MeToolkitVersionString(),
           MeIsDoublePrecision() ? "double" : "float");
}

/* Is `name` in the comma-separated `list`? */
static int listed(const char *list, const char *name)
{
    size_t n = strlen(name);
    for (const char *p = list; p && *p;) {
        if (!strncmp(p, name, n) && (p[n] == ',' || p[n] == 0))
            return 1;
        p = strchr(p, ',');
        p = p ? p + 1 : NULL;
    }
    return 0;
}

int main(int argc, char **argv)
{
    const char *scenes = BENCH_MDT_SCENES, *paths = "direct,iterative";
    int steps = 0;
    double budget = 20;
    for (int i = 1; i < argc; i++) {
        if (!strncmp(argv[i], "--scenes=", 9))
            scenes = argv[i] + 9;
        else if (!strncmp(argv[i], "--paths=", 8))
            paths = argv[i] + 8;
        else if (!strncmp(argv[i], "--steps=", 8))
            steps = atoi(argv[i] + 8);
        else if (!strncmp(argv[i], "--budget=", 9))
            budget = atof(argv[i] + 9);
        else {
            fprintf(stderr, "usage: %s [--scenes=%s] [--paths=direct,iterative] [--steps=N] [--budget=SECONDS]\n",
                    argv[0], BENCH_MDT_SCENES);
            return 2;
        }
    }
    MeSetMessageLevel(ME_LEVEL_WARNING);
    printMachine();
    printf("| scene | bodies | path | partitions | rows (largest partition) | median ms/step (wall) | "
           "median ms/step (CPU) | steps | worst residual (m/s) | iterations/step | figure | value |\n");
    printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    static const char *const names[] = {"chain", "column", "wall"};
    static const char *const pathNames[] = {"direct", "iterative"};
    static const MdtLCPSolver pathIds[] = {MdtLCPSolverDirect, MdtLCPSolverIterative};
    int failures = 0;
    for (int n = 0; n < 3; n++) {
        if (!listed(scenes, names[n]))
            continue;
        BenchMdtScene *s = BenchMdtSceneCreate(names[n]);
        for (int p = 0; p < 2 && s; p++) {
            if (!listed(paths, pathNames[p]))
                continue;
            Run run;
            if (!runScene(s, pathIds[p], steps > 0 ? steps : s->steps, budget, &run)) {
                fprintf(stderr, "%s: out of memory\n", s->name);
                failures++;
                continue;
            }
            char value[64];
            if (run.steps < (steps > 0 ? steps : s->steps))
                snprintf(value, sizeof value, "n/a (stopped after %d steps)", run.steps);
            else
                snprintf(value, sizeof value, "%.3g", run.quality.value);
            printf("| %s | %d | %s | %d | %d | %.3f | %.3f | %d | %.2e | %.1f | %s | %s |\n", s->name, s->bodyCount,
                   pathNames[p], run.partitions, run.maxRows, run.medianMs, run.medianCpuMs, run.steps,
                   run.maxResidual, run.iterations, s->qualityName, value);
            fflush(stdout);
        }
        BenchMdtSceneDestroy(s);
    }
    return failures ? 1 : 0;
}
