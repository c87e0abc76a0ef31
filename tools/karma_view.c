/* karma_view.c -- `karma render` and `karma view`: a registry scene drawn by the viewer. Each frame
 * is one step of the scene, as a Karma demo's tick steps once per frame; `render` draws the last. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <karma/MeProfile.h>

#include "demo_view_app.h"
#include "karma_view_video.h"
#include "karma_view.h"

/* The scene a viewer command names first (argv[0]), or NULL after saying what is wrong. */
static const DemoScene *commandScene(const char *command, int argc, char **argv)
{
    if (argc < 1) {
        KarmaUsageError("`%s` needs a scene (see `karma list`)", command);
        return NULL;
    }
    const DemoScene *scene = DemoSceneFind(argv[0]);
    if (!scene)
        KarmaUsageError("no scene '%s' (see `karma list`)", argv[0]);
    return scene;
}

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* --mp4: every frame drawn (the camera framed once, on the first) and piped to ffmpeg; the last
 * also written as a PNG when --out was given. Frees the view, the context and the scene. */
static int renderVideo(const DemoScene *scene, DemoInstance *demo, DemoView *view, long frames, const char *mp4,
                       const char *png)
{
    RRender *rc = view->rc;
    int width, height;
    RRenderGetSize(rc, &width, &height);
    int fps = (int)(1.0 / (double)scene->defaultStepSize + 0.5);
    KarmaVideo video;
    int status = EXIT_FAILURE;
    double drawing = 0;
    if (KarmaVideoOpen(&video, mp4, width, height, fps > 0 ? fps : 1) == 0) {
        int ok = 1;
        for (long f = 0; f < frames && ok; f++) {
            DemoStep(demo, scene->defaultStepSize);
            double t0 = seconds();
            RRenderDrawFrame(rc);
            ok = RRenderReadPixels(rc, video.rgba) == 0 && KarmaVideoWrite(&video, video.rgba) == 0;
            drawing += seconds() - t0;
        }
        ok = KarmaVideoClose(&video) == 0 && ok;
        if (ok && png)
            ok = RRenderSavePNG(rc, png) == 0;
        if (ok) {
            printf("%s: %ld frames (%.3f s simulated), %dx%d at %d frames/s, video written to %s; drawing %.1f ms a frame\n",
                   scene->name, frames, (double)demo->time, width, height, fps, mp4,
                   frames ? 1e3 * drawing / (double)frames : 0.0);
            status = EXIT_SUCCESS;
        }
    }
    DemoViewDestroy(view);
    RRenderContextDestroy(rc);
    DemoDestroy(demo);
    return status;
}

int KarmaRender(int argc, char **argv)
{
    const DemoScene *scene = commandScene("render", argc, argv);
    if (!scene)
        return KARMA_EXIT_USAGE;
    long frames = scene->defaultSteps;
    int width = 1280, height = 720;
    char defaultOut[64];
    snprintf(defaultOut, sizeof defaultOut, "%s.png", scene->name);
    const char *out = defaultOut, *mp4 = NULL;
    MeBool outGiven = MEFALSE;
    for (int i = 1; i < argc; i++) {
        const char *option = argv[i];
        if (i + 1 >= argc)
            return KarmaUsageError("'%s' needs a value, or is not an option of `render`", option);
        const char *value = argv[++i];
        if (strcmp(option, "--frames") == 0) {
            char *end;
            errno = 0;
            frames = strtol(value, &end, 10);
            if (errno || end == value || *end || frames < 0 || frames > INT_MAX)
                return KarmaUsageError("--frames takes a count of frames >= 0 (got '%s')", value);
        } else if (strcmp(option, "--size") == 0) {
            if (!RRenderParseSize(value, &width, &height))
                return KarmaUsageError("--size takes WxH, each 1 to 8192 (got '%s')", value);
        } else if (strcmp(option, "--out") == 0) {
            out = value, outGiven = METRUE;
        } else if (strcmp(option, "--mp4") == 0) {
            mp4 = value;
        } else {
            return KarmaUsageError("unknown option '%s' of `render`", option);
        }
    }
    DemoInstance demo;
    if (!DemoCreate(scene, &demo)) {
        fprintf(stderr, "karma: scene '%s' could not be built\n", scene->name);
        return EXIT_FAILURE;
    }
    RRender *rc = RRenderContextCreateHeadless(width, height);
    DemoView view;
    if (!rc || !DemoViewCreate(&view, rc, &demo)) {
        fprintf(stderr, "karma: cannot draw without a display here (EGL with Mesa is needed)\n");
        RRenderContextDestroy(rc);
        DemoDestroy(&demo);
        return EXIT_FAILURE;
    }
    if (mp4)
        return renderVideo(scene, &demo, &view, frames, mp4, outGiven ? out : NULL);
    double physics = 0, drawing = 0;
    for (long f = 0; f < frames; f++) {
        double t0 = seconds();
        DemoStep(&demo, scene->defaultStepSize);
        physics += seconds() - t0;
    }
    /* Only the last frame is drawn, its picture is what --out asks for, framed where the scene is now. */
    DemoViewFrame(&view, &demo);
    double t0 = seconds();
    RRenderDrawFrame(rc);
    drawing = seconds() - t0;
    int status = RRenderSavePNG(rc, out) == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
    if (status == EXIT_SUCCESS)
        printf("%s: %ld frames (%.3f s simulated), %dx%d, written to %s; physics %.3f s, drawing the frame %.1f ms\n",
               scene->name, frames, (double)demo.time, width, height, out, physics, 1e3 * drawing);
    DemoViewDestroy(&view);
    RRenderContextDestroy(rc);
    DemoDestroy(&demo);
    return status;
}

static void MEAPI tick(RRender *rc, void *userdata)
{
    (void)rc;
    DemoViewAppStep(userdata);
}

int KarmaView(int argc, char **argv)
{
    const DemoScene *scene = commandScene("view", argc, argv);
    if (!scene)
        return KARMA_EXIT_USAGE;
    /* Everything after the scene is for the viewer; checked before a window opens. */
    for (int i = 1; i < argc; i++) {
        static const char *const flags[] = {"-gl", "-null", "-bench", "-headless", "-wireframe", "-notextures"};
        MeBool known = MEFALSE;
        for (size_t k = 0; k < sizeof flags / sizeof flags[0]; k++)
            known = known || strcmp(argv[i], flags[k]) == 0;
        if (!known && strcmp(argv[i], "-profile") == 0) { /* -profile [frames] */
            known = METRUE;
            if (i + 1 < argc && argv[i + 1][0] >= '0' && argv[i + 1][0] <= '9')
                i++;
        }
        if (!known && (strcmp(argv[i], "-size") == 0 || strcmp(argv[i], "-timeout") == 0)) {
            if (i + 1 >= argc)
                return KarmaUsageError("'%s' needs a value", argv[i]);
            known = METRUE;
            i++;
        }
        if (!known)
            return KarmaUsageError("unknown option '%s' of `view`", argv[i]);
    }
    MeCommandLineOptions *options = MeCommandLineOptionsCreate(argc - 1, (const char **)(argv + 1));
    RRender *rc = RRenderContextCreate(options, NULL, METRUE);
    int unread = options ? options->m_argc : 0;
    const char *first = unread ? options->p_argv[0] : NULL;
    MeCommandLineOptionsDestroy(options);
    if (unread) {
        RRenderContextDestroy(rc);
        return KarmaUsageError("unknown option '%s' of `view`", first);
    }
    if (!rc)
        return EXIT_FAILURE;
    char title[128];
    snprintf(title, sizeof title, "Karma: %s (%s)", scene->name, scene->description);
    RRenderSetWindowTitle(rc, title);
    DemoViewApp app;
    if (!DemoViewAppCreate(&app, scene, rc)) {
        RRenderContextDestroy(rc);
        return EXIT_FAILURE;
    }
    /* The performance bar's collision and dynamics times (-profile starts its own timing). */
    MeProfileTimerMode mode = {0};
    if (!rc->m_bProfiling)
        MeProfileStartTiming(mode, kMeProfileDontLog);
    RRun(rc, tick, &app);
    if (!rc->m_bProfiling)
        MeProfileStopTiming();
    printf("%s: %lu steps (%.3f s simulated), %d balls shot, %d resets\n", scene->name, app.demo.steps,
           (double)app.demo.time, app.shots, app.resets);
    DemoViewAppDestroy(&app);
    RRenderContextDestroy(rc);
    return EXIT_SUCCESS;
}
