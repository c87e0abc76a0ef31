/* bench_harness.c -- timing loop, quality measurement and CSV output shared by every bench program. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include "bench_harness.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct Options {
    const char *scenes;
    const char *variants;
    int steps;       /* 0: the scene's own */
    double budget;   /* s of CPU time in timed steps per run */
    int header, list;
    int trace;       /* >= 0: print this body's pose every 60 steps to stderr */
    const char *set; /* the scenes --list lists and --scenes defaults to */
    int stepTimes;   /* print every step's CPU time to stderr */
} Options;

static double clock_seconds(clockid_t clock)
{
    struct timespec ts;
    clock_gettime(clock, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    if (n <= 0)
        return NAN;
    qsort(v, (size_t)n, sizeof *v, compare_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The p-th quantile (0..1) of v[0..n) sorted ascending: the nearest rank, ceil(p n). */
static double quantile_sorted(const double *v, int n, double p)
{
    if (n <= 0)
        return NAN;
    int rank = (int)ceil(p * n);
    return v[rank < 1 ? 0 : rank > n ? n - 1 : rank - 1];
}

/* Is `name` one of the comma-separated `list` (NULL: everything)? */
static int in_list(const char *list, const char *name)
{
    if (!list)
        return 1;
    size_t n = strlen(name);
    for (const char *p = list; *p;) {
        const char *end = strchr(p, ',');
        size_t len = end ? (size_t)(end - p) : strlen(p);
        if (len == n && strncmp(p, name, n) == 0)
            return 1;
        if (!end)
            break;
        p = end + 1;
    }
    return 0;
}

/* One run's record: the poses, every step's wall and CPU time, their sums, the contacts summed over
 * the steps and the quality measured. */
typedef struct RunRecord {
    double (*pos)[3], (*quat)[4];
    double *times, *cpuTimes;
    int done;
    double contacts, spent, spentCpu;
    BenchQuality quality;
} RunRecord;

/* Step the world up to `steps` times, timing each step and observing the quality into r; returns why
 * it stopped early ("" when it did not). */
static const char *run_steps(const BenchEngine *e, void *world, const BenchScene *scene, const Options *opt,
                             int steps, RunRecord *r)
{
    int n = scene->bodyCount;
    for (; r->done < steps; ) {
        const char *why = "stopped by the engine";
        /* wall time (what the brief asks for) and process CPU time (what a loaded, shared machine
         * does not inflate) of the step call alone */
        double c0 = clock_seconds(CLOCK_PROCESS_CPUTIME_ID), t0 = clock_seconds(CLOCK_MONOTONIC);
        int stop = e->step(world, &why);
        double dt = clock_seconds(CLOCK_MONOTONIC) - t0;
        double dc = clock_seconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
        if (stop)
            return why;
        if (opt->stepTimes)
            fprintf(stderr, "    step %5d cpu_ms %.4f wall_ms %.4f\n", r->done + 1, dc * 1e3, dt * 1e3);
        r->cpuTimes[r->done] = dc;
        r->times[r->done++] = dt;
        r->spent += dt;
        r->spentCpu += dc;
        r->contacts += e->contacts(world);
        e->read(world, r->pos, r->quat);
        BenchQualityObserve(scene, &r->quality, (const double(*)[3])r->pos, (const double(*)[4])r->quat);
        if (opt->trace >= 0 && opt->trace < n && r->done % 60 == 0)
            fprintf(stderr, "    step %5d body %d pos %9.4f %9.4f %9.4f quat %7.4f %7.4f %7.4f %7.4f\n", r->done,
                    opt->trace, r->pos[opt->trace][0], r->pos[opt->trace][1], r->pos[opt->trace][2],
                    r->quat[opt->trace][0], r->quat[opt->trace][1], r->quat[opt->trace][2], r->quat[opt->trace][3]);
        if (r->spentCpu > opt->budget && r->done < steps) /* CPU time: the same runs finish under any load */
            return "time budget reached";
    }
    return "";
}

/* The run's CSV line on stdout and its summary on stderr (r's times are sorted on the way). */
static void print_run(const BenchEngine *e, const BenchScene *scene, int steps, RunRecord *r, const char *note)
{
    const BenchQuality *quality = &r->quality;
    int done = r->done;
    double mean = done ? r->spent / done * 1e3 : (double)NAN;
    double med = median(r->times, done) * 1e3, cpu = median(r->cpuTimes, done) * 1e3; /* median() sorts */
    double p99 = quantile_sorted(r->times, done, 0.99) * 1e3, p99cpu = quantile_sorted(r->cpuTimes, done, 0.99) * 1e3;
    const char *standing = quality->standing < 0 ? "-" : quality->standing ? "yes" : "no";
    if (done == steps || quality->nonFinite)
        printf("%s,%s,%s,%d,%d,%d,%.4f,%.4f,%.4f,%.1f,%s,%.6g,%s,%.4f,%.6g,%s,%.4f,%.4f\n", e->engine, e->variant,
               scene->name, scene->dynamicCount, steps, done, med, mean, cpu, done ? r->contacts / done : 0.0,
               scene->qualityName, quality->value, standing, quality->floorPenetration, quality->meanJointError, note,
               p99, p99cpu);
    else /* an incomplete run has no quality figure: it was not measured at the scene's time */
        printf("%s,%s,%s,%d,%d,%d,%.4f,%.4f,%.4f,%.1f,%s,,-,,,%s,%.4f,%.4f\n", e->engine, e->variant, scene->name,
               scene->dynamicCount, steps, done, med, mean, cpu, done ? r->contacts / done : 0.0, scene->qualityName,
               note, p99, p99cpu);
    fflush(stdout);
    fprintf(stderr, "  %-6s %-14s %-10s %5d steps, %8.3f ms/step (CPU %.3f, CPU p99 %.3f = %.2f x median), %s\n",
            e->engine, e->variant, scene->name, done, med, cpu, p99cpu, cpu > 0 ? p99cpu / cpu : (double)NAN,
            *note ? note : "ok");
}

static void run_one(const BenchEngine *e, const BenchScene *scene, const Options *opt)
{
    int steps = opt->steps > 0 ? opt->steps : scene->steps;
    int n = scene->bodyCount;
    RunRecord r;
    memset(&r, 0, sizeof r);
    r.pos = malloc(sizeof *r.pos * (size_t)n);
    r.quat = malloc(sizeof *r.quat * (size_t)n);
    r.times = malloc(sizeof *r.times * (size_t)steps);
    r.cpuTimes = malloc(sizeof *r.cpuTimes * (size_t)steps);
    if (!r.pos || !r.quat || !r.times || !r.cpuTimes) {
        fprintf(stderr, "bench: out of memory for %s\n", scene->name);
        free(r.pos), free(r.quat), free(r.times), free(r.cpuTimes);
        return;
    }
    for (int i = 0; i < n; i++) {
        memcpy(r.pos[i], scene->bodies[i].pos, sizeof r.pos[i]);
        memcpy(r.quat[i], scene->bodies[i].quat, sizeof r.quat[i]);
    }
    const char *note = "";
    char remarkCopy[160];
    BenchQualityInit(scene, &r.quality);
    void *world = e->create(scene);
    if (!world) {
        note = "world creation failed";
    } else {
        note = run_steps(e, world, scene, opt, steps, &r);
        const char *remark = e->remark ? e->remark(world) : NULL;
        if (remark && *remark && !*note) {
            snprintf(remarkCopy, sizeof remarkCopy, "%s", remark);
            note = remarkCopy;
        }
        e->destroy(world);
    }
    BenchQualityFinish(scene, &r.quality, (const double(*)[3])r.pos, (const double(*)[4])r.quat, r.done == steps);
    if (r.quality.nonFinite && !*note)
        note = "non-finite state";
    print_run(e, scene, steps, &r, note);
    free(r.pos), free(r.quat), free(r.times), free(r.cpuTimes);
}

int BenchThreads = 1;

static int parse_options(int argc, char **argv, Options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->scenes = NULL;
    opt->set = BENCH_STANDARD_SCENES;
    opt->budget = 60;
    opt->trace = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strncmp(a, "--scenes=", 9) == 0)
            opt->scenes = a + 9;
        else if (strncmp(a, "--variants=", 11) == 0)
            opt->variants = a + 11;
        else if (strncmp(a, "--steps=", 8) == 0)
            opt->steps = atoi(a + 8);
        else if (strncmp(a, "--budget=", 9) == 0)
            opt->budget = atof(a + 9);
        else if (strncmp(a, "--trace=", 8) == 0)
            opt->trace = atoi(a + 8);
        else if (strcmp(a, "--set=standard") == 0)
            opt->set = BENCH_STANDARD_SCENES;
        else if (strcmp(a, "--set=others") == 0)
            opt->set = BENCH_OTHERS_SCENES;
        else if (strcmp(a, "--set=all") == 0)
            opt->set = BENCH_STANDARD_SCENES "," BENCH_OTHERS_SCENES;
        else if (strncmp(a, "--threads=", 10) == 0)
            BenchThreads = atoi(a + 10);
        else if (strcmp(a, "--step-times") == 0)
            opt->stepTimes = 1;
        else if (strcmp(a, "--header") == 0)
            opt->header = 1;
        else if (strcmp(a, "--list") == 0)
            opt->list = 1;
        else {
            fprintf(stderr,
                    "unknown option '%s' (--scenes= --set=standard|others|all --variants= --steps= --budget= --trace= "
                    "--threads= --step-times --header --list)\n",
                    a);
            return 0;
        }
    }
    if (!opt->scenes)
        opt->scenes = opt->set;
    if (opt->budget <= 0 || opt->steps < 0 || BenchThreads < 1) {
        fprintf(stderr, "--budget must be > 0, --steps >= 0 and --threads >= 1\n");
        return 0;
    }
    return 1;
}

int BenchMain(int argc, char **argv, const BenchEngine *engines, int engineCount)
{
    Options opt;
    if (!parse_options(argc, argv, &opt))
        return 2;
    if (opt.list) {
        for (int i = 0; i < engineCount; i++)
            printf("variant %s %s: %s\n", engines[i].engine, engines[i].variant, engines[i].settings);
        char *names = malloc(strlen(opt.set) + 1);
        if (!names)
            return 1;
        strcpy(names, opt.set);
        for (char *name = strtok(names, ","); name; name = strtok(NULL, ",")) {
            BenchScene *scene = BenchSceneCreate(name);
            if (scene)
                printf("scene %s: %s; %d dynamic bodies, %d joints, %d steps of %.4f s, figure %s\n", scene->name,
                       scene->description, scene->dynamicCount, scene->jointCount, scene->steps, scene->step,
                       scene->qualityName);
            BenchSceneDestroy(scene);
        }
        free(names);
        return 0;
    }
    if (opt.header)
        printf("%s\n", BENCH_CSV_HEADER);
    /* Scenes in the order given; each one built once and run by every selected variant. */
    char *list = malloc(strlen(opt.scenes) + 1);
    if (!list)
        return 1;
    strcpy(list, opt.scenes);
    int status = 0;
    for (char *name = list; name && *name;) {
        char *comma = strchr(name, ',');
        if (comma)
            *comma = '\0';
        BenchScene *scene = BenchSceneCreate(name);
        if (!scene) {
            fprintf(stderr, "unknown scene '%s'\n", name);
            status = 2;
        } else {
            for (int i = 0; i < engineCount; i++)
                if (in_list(opt.variants, engines[i].variant))
                    run_one(&engines[i], scene, &opt);
            BenchSceneDestroy(scene);
        }
        name = comma ? comma + 1 : NULL;
    }
    free(list);
    return status;
}
