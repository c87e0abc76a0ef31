/* karma.c -- the karma command-line tool: list the demo scenes and run one headless.
 *
 *     karma list
 *     karma run SCENE [--steps N] [--dt H] [--csv FILE [--long]]
 *     karma plot SCENE [--steps N] [--dt H] [--csv FILE] [--png FILE]
 *     karma render SCENE [--frames N] [--size WxH] [--out FILE] [--mp4 FILE]   (built with the viewer)
 *     karma view SCENE [-size WxH] [-timeout N] [-null] [-bench] [-profile [N]] (built with the viewer)
 *     karma version
 *     karma --help
 *
 * `run` builds the scene from the registry (demos/), steps it and prints what happened: body
 * counts, the time spent in each stage of the step (from the world's MeProfile), energy and momenta
 * before and after, final positions and the scene's own report. `--csv` writes the run for plotting: one row per step
 * with columns per body (or, with --long, one row per body and step); `plot` also writes a gnuplot
 * script of the bodies' heights and runs gnuplot when it is installed. Exit status: 0 on success, 1 when the run reported a Karma warning or the scene
 * could not be built, 2 on a bad command line. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "demo.h"
#include "karma_view.h" /* the usage error; the viewer commands when the viewer is built */

static const char *const stageNames[] = {"Partition", "AutoDisable", "Pack", "Solve", "Integrate", "Unpack"};
#define STAGE_COUNT ((int)(sizeof stageNames / sizeof stageNames[0]))

static void printUsage(FILE *out)
{
    fprintf(out,
            "usage: karma <command> [options]\n"
            "\n"
            "commands:\n"
            "  list                      list the demo scenes\n"
            "  run SCENE [options]       run SCENE headless and print what happened\n"
            "      --steps N             number of steps (default: the scene's)\n"
            "      --dt H                step size in seconds (default: the scene's)\n"
            "      --csv FILE            write the run to FILE: one row per step, columns per body\n"
            "                            (BODY.x, BODY.y_up, BODY.z, BODY.speed, BODY.awake; y is up)\n"
            "      --long                with --csv: one row per body and step, with its whole state\n"
            "  plot SCENE [options]      run SCENE, write SCENE.csv and SCENE.gp (a gnuplot script of\n"
            "                            each body's height over time) and draw it if gnuplot is installed\n"
            "      --steps N, --dt H, --csv FILE   as for run\n"
            "      --png FILE            draw into FILE instead of the terminal\n"
            "  render SCENE [options]    draw SCENE without a display (EGL) and write a PNG picture\n"
            "      --frames N            frames before the picture, one step each (default: the scene's steps)\n"
            "      --size WxH            picture size in pixels (default 1280x720)\n"
            "      --out FILE            the PNG file (default SCENE.png; with --mp4 only when given)\n"
            "      --mp4 FILE            also draw every frame into an H.264 video (needs ffmpeg)\n"
            "  view SCENE [options]      open a window on SCENE (mouse: left orbits, middle zooms, right pans;\n"
            "                            Ctrl+left drags a body, Enter resets, Space shoots, m options menu,\n"
            "                            F1 help, F12 viewer menu, Esc quits, F8 single step, Ctrl+F8 pause);\n"
            "                            options: -size WxH, -timeout N (frames), -headless, -null (no\n"
            "                            drawing), -bench (no drawing, timings), -profile [N] (N frames\n"
            "                            profiled, default 1000), -wireframe\n"
            "  version                   print the library version and precision\n"
            "  help, --help, -h          print this help\n"
            "\n"
            "`make demo` runs `karma run " DEMO_DEFAULT_SCENE "`.\n");
}

int KarmaUsageError(const char *format, const char *argument)
{
    fprintf(stderr, "karma: ");
    fprintf(stderr, format, argument);
    fprintf(stderr, "\n(see `karma --help`)\n");
    return KARMA_EXIT_USAGE;
}

static int listScenes(void)
{
    for (int i = 0; i < DemoSceneCount(); i++) {
        const DemoScene *scene = DemoSceneAt(i);
        printf("%-12s %s (%d steps of %.4g s)%s\n", scene->name, scene->description, scene->defaultSteps,
               (double)scene->defaultStepSize, strcmp(scene->name, DEMO_DEFAULT_SCENE) == 0 ? " [make demo]" : "");
    }
    return EXIT_SUCCESS;
}

/* ---- command-line values ------------------------------------------------------------------- */

static MeBool parseSteps(const char *text, long *steps)
{
    char *end;
    errno = 0;
    long value = strtol(text, &end, 10);
    if (errno || end == text || *end || value < 0 || value > INT_MAX)
        return MEFALSE;
    *steps = value;
    return METRUE;
}

static MeBool parseStepSize(const char *text, MeReal *h)
{
    char *end;
    errno = 0;
    double value = strtod(text, &end);
    if (errno || end == text || *end || !(value > 0) || !isfinite(value) || value > 10)
        return MEFALSE;
    *h = (MeReal)value;
    return METRUE;
}

/* ---- what the run measures ----------------------------------------------------------------- */

typedef struct Totals {
    double kinetic, potential;       /* J */
    double momentum[3];              /* kg·m/s */
    double angularMomentum[3];       /* about the world origin, kg·m²/s */
    double gravityImpulsePerSecond[3]; /* Σ m·g over enabled bodies, N */
    int bodies, enabled;
} Totals;

static void measure(MdtWorldID world, Totals *t)
{
    MeVector3 g;
    memset(t, 0, sizeof *t);
    MdtWorldGetGravity(world, g);
    for (MdtBodyID b = MdtBodyGetFirst(world); b; b = MdtBodyGetNext(b)) {
        MeVector3 x, v, L;
        double m = (double)MdtBodyGetMass(b);
        MdtBodyGetCenterOfMassPosition(b, x);
        MdtBodyGetLinearVelocity(b, v);
        DemoBodyAngularMomentum(b, L);
        t->bodies++;
        if (MdtBodyIsEnabled(b)) {
            t->enabled++;
            for (int k = 0; k < 3; k++)
                t->gravityImpulsePerSecond[k] += m * (double)g[k];
        }
        t->kinetic += (double)MdtBodyGetKineticEnergy(b);
        for (int k = 0; k < 3; k++) {
            t->potential -= m * (double)g[k] * (double)x[k];
            t->momentum[k] += m * (double)v[k];
        }
        t->angularMomentum[0] += m * ((double)x[1] * (double)v[2] - (double)x[2] * (double)v[1]) + (double)L[0];
        t->angularMomentum[1] += m * ((double)x[2] * (double)v[0] - (double)x[0] * (double)v[2]) + (double)L[1];
        t->angularMomentum[2] += m * ((double)x[0] * (double)v[1] - (double)x[1] * (double)v[0]) + (double)L[2];
    }
}

static void printVector(const char *label, const double v[3], const char *unit)
{
    printf("%s(%.4f, %.4f, %.4f)%s%s", label, v[0], v[1], v[2], *unit ? " " : "", unit);
}

/* ---- CSV ------------------------------------------------------------------------------------ */

/* A body's column label: its scene name, with its index when the name is shared or missing
 * ("door", "ball3", "body12"); labels hold no comma or space, so plotting tools take them as is. */
static void bodyLabel(const DemoInstance *demo, MdtBodyID body, int index, char *label, size_t size)
{
    const char *name = DemoBodyName(demo, body);
    int sharing = 0;
    if (name)
        for (MdtBodyID b = MdtBodyGetFirst(demo->world); b; b = MdtBodyGetNext(b)) {
            const char *other = DemoBodyName(demo, b);
            sharing += other && strcmp(other, name) == 0;
        }
    if (!name)
        snprintf(label, size, "body%d", index);
    else if (sharing > 1)
        snprintf(label, size, "%s%d", name, index);
    else
        snprintf(label, size, "%s", name);
    for (char *c = label; *c; c++)
        if (*c == ',' || *c == ' ')
            *c = '_';
}

/* Wide (default): one row per step, `step,time` then x, y_up, z, speed and awake per body, so a
 * column is one quantity of one body over time. Long (--long): one row per body and step with its
 * whole state. The height column is y_up: every scene is y-up (docs/decisions.md K30). */
static void writeCsvHeader(FILE *csv, const DemoInstance *demo, MeBool longForm)
{
    if (longForm) {
        fprintf(csv, "step,time,body,name,awake,x,y_up,z,qw,qx,qy,qz,vx,vy_up,vz,wx,wy_up,wz\n");
        return;
    }
    fprintf(csv, "step,time");
    int index = 0;
    for (MdtBodyID b = MdtBodyGetFirst(demo->world); b; b = MdtBodyGetNext(b), index++) {
        char label[64];
        bodyLabel(demo, b, index, label, sizeof label);
        fprintf(csv, ",%s.x,%s.y_up,%s.z,%s.speed,%s.awake", label, label, label, label, label);
    }
    fprintf(csv, "\n");
}

static void writeCsvRows(FILE *csv, const DemoInstance *demo, MeBool longForm)
{
    int index = 0;
    if (!longForm)
        fprintf(csv, "%lu,%.9g", demo->steps, (double)demo->time);
    for (MdtBodyID b = MdtBodyGetFirst(demo->world); b; b = MdtBodyGetNext(b), index++) {
        MeVector3 x, v, w;
        MeVector4 q;
        const char *name = DemoBodyName(demo, b);
        MdtBodyGetPosition(b, x);
        MdtBodyGetQuaternion(b, q);
        MdtBodyGetLinearVelocity(b, v);
        MdtBodyGetAngularVelocity(b, w);
        int awake = MdtBodyIsEnabled(b) ? 1 : 0;
        if (!longForm) {
            fprintf(csv, ",%.9g,%.9g,%.9g,%.9g,%d", (double)x[0], (double)x[1], (double)x[2],
                    (double)MeVector3Magnitude(v), awake);
            continue;
        }
        fprintf(csv, "%lu,%.9g,%d,%s,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                demo->steps, (double)demo->time, index, name ? name : "", awake,
                (double)x[0], (double)x[1], (double)x[2], (double)q[0], (double)q[1], (double)q[2], (double)q[3],
                (double)v[0], (double)v[1], (double)v[2], (double)w[0], (double)w[1], (double)w[2]);
    }
    if (!longForm)
        fprintf(csv, "\n");
}

/* ---- karma plot: a gnuplot script of every named body's height over time ------------------- */

/* Writes `script` to plot the wide CSV `csvPath` of `demo` (heights of the named bodies, or of the
 * first eight): to the terminal as text, or to `png` when not NULL. */
static MeBool writePlotScript(const char *script, const char *csvPath, const DemoInstance *demo, const char *png)
{
    FILE *gp = fopen(script, "w");
    if (!gp)
        return MEFALSE;
    fprintf(gp, "# karma plot %s: height (y_up) of the scene's bodies over time, from %s\n", demo->scene->name,
            csvPath);
    if (png)
        fprintf(gp, "set terminal png size 1000,600\nset output '%s'\n", png);
    else
        fprintf(gp, "set terminal dumb size 120,32\n");
    fprintf(gp, "set datafile separator ','\nset title '%s: height of each body'\n"
                "set xlabel 'time (s)'\nset ylabel 'y_up (m)'\nset key outside right\nplot",
            demo->scene->name);
    int index = 0, plotted = 0;
    for (MdtBodyID b = MdtBodyGetFirst(demo->world); b; b = MdtBodyGetNext(b), index++) {
        if (DemoBodyName(demo, b) == NULL && (demo->namedCount > 0 || index >= 8))
            continue;
        if (plotted >= 12)
            break;
        char label[64];
        bodyLabel(demo, b, index, label, sizeof label);
        /* columns: step, time, then five per body; y_up is the body's second */
        fprintf(gp, "%s '%s' using 2:%d every ::1 with lines title '%s'", plotted ? ", \\\n    " : " ", csvPath,
                3 + 5 * index + 1, label);
        plotted++;
    }
    fprintf(gp, "\n");
    return fclose(gp) == 0;
}

/* ---- karma run ------------------------------------------------------------------------------ */

/* What the command line asked of `karma run` or `karma plot`. */
typedef struct RunOptions {
    const DemoScene *scene;
    long steps;
    MeReal h;                   /* s */
    const char *csvPath, *png; /* NULL when not asked (plot: csvPath is SCENE.csv by default) */
    MeBool longForm, plot;
    char defaultCsv[96];
} RunOptions;

/* Reads the scene and options into *o; returns -1 when they are usable, else the exit status (a
 * usage error has been printed). */
static int parseRunOptions(int argc, char **argv, MeBool plot, RunOptions *o)
{
    if (argc < 1)
        return KarmaUsageError("%s", plot ? "`plot` needs a scene name; `karma list` shows them"
                                     : "`run` needs a scene name; `karma list` shows them");
    memset(o, 0, sizeof *o);
    o->plot = plot;
    o->scene = DemoSceneFind(argv[0]);
    if (!o->scene)
        return KarmaUsageError("no scene called '%s'; `karma list` shows the scenes", argv[0]);
    o->steps = o->scene->defaultSteps;
    o->h = o->scene->defaultStepSize;
    for (int i = 1; i < argc; i++) {
        const char *option = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (!plot && strcmp(option, "--long") == 0) {
            o->longForm = METRUE;
            continue;
        }
        if (strcmp(option, "--steps") == 0 || strcmp(option, "--dt") == 0 || strcmp(option, "--csv") == 0 ||
            (plot && strcmp(option, "--png") == 0)) {
            if (!value)
                return KarmaUsageError("option %s needs a value", option);
            i++;
        } else {
            return KarmaUsageError(plot ? "unknown option '%s' for `plot`" : "unknown option '%s' for `run`", option);
        }
        if (strcmp(option, "--png") == 0)
            o->png = value;
        if (strcmp(option, "--steps") == 0 && !parseSteps(value, &o->steps))
            return KarmaUsageError("--steps takes a whole number from 0 to 2147483647, not '%s'", value);
        if (strcmp(option, "--dt") == 0 && !parseStepSize(value, &o->h))
            return KarmaUsageError("--dt takes a step size in seconds, greater than 0 and at most 10, not '%s'", value);
        if (strcmp(option, "--csv") == 0)
            o->csvPath = value;
    }
    if (plot && !o->csvPath) {
        snprintf(o->defaultCsv, sizeof o->defaultCsv, "%s.csv", o->scene->name);
        o->csvPath = o->defaultCsv;
    }
    return -1;
}

/* A run in progress: the scene, what was measured before and after, and the solver's and collision's
 * counts summed over the steps. */
typedef struct Run {
    const RunOptions *options;
    DemoInstance demo;
    FILE *csv;
    Totals before, after;
    double sumPartitions, sumRows, sumPairs, sumContacts;
    int maxRows;
    unsigned long warnings;
} Run;

/* Steps the scene, writing a CSV row after each step when asked, and sums the per-step counts. */
static void stepScene(Run *run)
{
    DemoInstance *demo = &run->demo;
    measure(demo->world, &run->before);
    if (run->csv)
        writeCsvRows(run->csv, demo, run->options->longForm);
    for (long i = 0; i < run->options->steps; i++) {
        DemoStep(demo, run->options->h);
        if (run->csv)
            writeCsvRows(run->csv, demo, run->options->longForm);
        MdtSolverStats stats;
        MdtWorldGetSolverStats(demo->world, &stats);
        run->sumPartitions += stats.partitions;
        run->sumRows += stats.rows;
        if (stats.maxPartitionRows > run->maxRows)
            run->maxRows = stats.maxPartitionRows;
        if (demo->universe) {
            run->sumPairs += McdSpaceGetPairCount(MstUniverseGetSpace(demo->universe));
            run->sumContacts += MstBridgeGetLastContactCount(MstUniverseGetBridge(demo->universe));
        }
    }
    measure(demo->world, &run->after);
}

/* The run's sizes, counts per step and the time of each stage. */
static void printCountsAndTimes(const Run *run)
{
    const DemoScene *scene = run->options->scene;
    const DemoInstance *demo = &run->demo;
    const long steps = run->options->steps;
    printf("karma run %s: %s\n", scene->name, scene->description);
    printf("  %s; %ld steps of %.6g s = %.4g s simulated\n", MeToolkitVersionString(), steps,
           (double)run->options->h, (double)demo->time);
    printf("  bodies: %d, awake %d at the start and %d at the end; constraints: %d\n", run->after.bodies,
           run->before.enabled, run->after.enabled, MdtWorldGetTotalConstraints(demo->world));

    double perStep = steps > 0 ? 1e6 / (double)steps : 0, mean = steps > 0 ? 1.0 / (double)steps : 0;
    printf("  per step (mean): partitions %.1f, rows %.1f (largest partition %d rows)", run->sumPartitions * mean,
           run->sumRows * mean, run->maxRows);
    if (demo->universe)
        printf(", pairs %.1f, contacts %.1f", run->sumPairs * mean, run->sumContacts * mean);
    printf("\n");
    if (demo->universe) {
        const MeProfile *collision = MstUniverseGetProfile(demo->universe);
        printf("  collision time per step (µs): Farfield %.3f Nearfield %.3f\n",
               MeProfileGetSectionTotal(collision, MST_SECTION_FARFIELD) * perStep,
               MeProfileGetSectionTotal(collision, MST_SECTION_NEARFIELD) * perStep);
    }
    const MeProfile *profile = MdtWorldGetProfile(demo->world);
    printf("  dynamics time per step by stage (µs, mean of %ld):", steps);
    for (int s = 0; s < STAGE_COUNT; s++)
        printf(" %s %.3f", stageNames[s], MeProfileGetSectionTotal(profile, stageNames[s]) * perStep);
    printf("; whole step %.3f\n", MeProfileGetSectionTotal(profile, "Dynamics") * perStep);
}

/* Energy and momenta before and after, with the momentum gravity's impulse predicts. */
static void printConservation(const Run *run)
{
    const Totals *before = &run->before, *after = &run->after;
    printf("  energy (kinetic + gravitational potential): before %.4f J, after %.4f J\n",
           before->kinetic + before->potential, after->kinetic + after->potential);
    double expected[3];
    for (int k = 0; k < 3; k++)
        expected[k] = before->momentum[k] + before->gravityImpulsePerSecond[k] * (double)run->demo.time;
    printVector("  linear momentum: before ", before->momentum, "");
    printVector(", after ", after->momentum, "kg·m/s");
    printVector(" (before + gravity's impulse: ", expected, "");
    printf(")\n");
    printVector("  angular momentum about the origin: before ", before->angularMomentum, "");
    printVector(", after ", after->angularMomentum, "kg·m²/s");
    printf("\n");
}

/* Where the bodies ended (the named ones and the first few of a large scene), then the scene's own
 * report and the count of warnings. */
static void printFinalState(const Run *run)
{
    const DemoInstance *demo = &run->demo;
    const int bodies = run->after.bodies;
    printf("  final positions (m; x, y up, z)%s:\n", bodies > 12 ? ", named bodies and the first few" : "");
    int index = 0, shown = 0;
    for (MdtBodyID b = MdtBodyGetFirst(demo->world); b; b = MdtBodyGetNext(b), index++) {
        MeVector3 x;
        const char *name = DemoBodyName(demo, b);
        char fallback[32];
        if (!name && bodies > 12 && index >= 8)
            continue;
        shown++;
        if (!name) {
            snprintf(fallback, sizeof fallback, "body %d", index);
            name = fallback;
        }
        MdtBodyGetPosition(b, x);
        printf("    %-12s (%10.4f, %10.4f, %10.4f)%s\n", name, (double)x[0], (double)x[1], (double)x[2],
               MdtBodyIsEnabled(b) ? "" : "  asleep");
    }
    if (shown < bodies)
        printf("    ... and %d more\n", bodies - shown);
    if (run->options->scene->report) {
        printf("  what the scene measured:\n");
        run->options->scene->report(demo, stdout);
    }
    printf("  Karma warnings during the run: %lu\n", run->warnings);
}

/* Draws the gnuplot script with gnuplot when it is installed; returns the exit status. */
static int drawPlot(const RunOptions *o, const char *script)
{
    printf("  wrote %s (one row per step) and %s (a gnuplot script of each body's height)\n", o->csvPath, script);
    fflush(stdout); /* the report before gnuplot's drawing */
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        printf("  gnuplot is not installed: `apt-get install gnuplot-nox`, then `gnuplot %s`\n", script);
        return EXIT_SUCCESS;
    }
    char command[256];
    snprintf(command, sizeof command, "gnuplot '%s'", script);
    if (system(command) != 0) {
        fprintf(stderr, "karma: gnuplot failed on '%s'\n", script);
        return EXIT_FAILURE;
    }
    if (o->png)
        printf("  drew %s\n", o->png);
    return EXIT_SUCCESS;
}

/* `karma run` (plot = MEFALSE) and `karma plot` (METRUE: writes SCENE.csv and SCENE.gp, then draws
 * them with gnuplot when it is installed). */
static int runScene(int argc, char **argv, MeBool plot)
{
    RunOptions o;
    const int usage = parseRunOptions(argc, argv, plot, &o);
    if (usage >= 0)
        return usage;
    Run run;
    memset(&run, 0, sizeof run);
    run.options = &o;
    unsigned long warningsBefore = MeMessageGetTotalCount(ME_LEVEL_WARNING);
    if (!DemoCreate(o.scene, &run.demo)) {
        fprintf(stderr, "karma: scene '%s' could not be built (see the messages above)\n", o.scene->name);
        return EXIT_FAILURE;
    }
    if (o.csvPath) {
        run.csv = fopen(o.csvPath, "w");
        if (!run.csv) {
            fprintf(stderr, "karma: cannot write '%s': %s\n", o.csvPath, strerror(errno));
            DemoDestroy(&run.demo);
            return EXIT_FAILURE;
        }
        writeCsvHeader(run.csv, &run.demo, o.longForm);
    }
    stepScene(&run);
    run.warnings = MeMessageGetTotalCount(ME_LEVEL_WARNING) - warningsBefore;
    printCountsAndTimes(&run);
    printConservation(&run);
    printFinalState(&run);

    char script[96] = "";
    if (plot) {
        snprintf(script, sizeof script, "%s.gp", o.scene->name);
        if (!writePlotScript(script, o.csvPath, &run.demo, o.png)) {
            fprintf(stderr, "karma: cannot write '%s': %s\n", script, strerror(errno));
            run.warnings++;
        }
    }
    DemoDestroy(&run.demo);
    if (run.csv && fclose(run.csv) != 0) {
        fprintf(stderr, "karma: error writing '%s'\n", o.csvPath);
        return EXIT_FAILURE;
    }
    if (plot && drawPlot(&o, script) != EXIT_SUCCESS)
        return EXIT_FAILURE;
    return run.warnings ? EXIT_FAILURE : EXIT_SUCCESS;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        printUsage(stderr);
        return KARMA_EXIT_USAGE;
    }
    const char *command = argv[1];
    if (strcmp(command, "help") == 0 || strcmp(command, "--help") == 0 || strcmp(command, "-h") == 0) {
        printUsage(stdout);
        return EXIT_SUCCESS;
    }
    if (strcmp(command, "list") == 0) {
        if (argc > 2)
            return KarmaUsageError("`list` takes no arguments (got '%s')", argv[2]);
        return listScenes();
    }
    if (strcmp(command, "version") == 0) {
        printf("%s\n", MeToolkitVersionString());
        return EXIT_SUCCESS;
    }
    if (strcmp(command, "run") == 0)
        return runScene(argc - 2, argv + 2, MEFALSE);
    if (strcmp(command, "plot") == 0)
        return runScene(argc - 2, argv + 2, METRUE);
    if (strcmp(command, "render") == 0 || strcmp(command, "view") == 0) {
#ifdef KARMA_HAVE_VIEWER
        return command[0] == 'r' ? KarmaRender(argc - 2, argv + 2) : KarmaView(argc - 2, argv + 2);
#else
        return KarmaUsageError("`%s` needs the viewer: this karma was built without it (KARMA_BUILD_VIEWER=OFF)", command);
#endif
    }
    return KarmaUsageError("unknown command '%s'", command);
}
