/* RRender.c -- render contexts: options, creation on a backend (window, offscreen, none), the main
 * loop RRun with pause, single step and the frame-rate lock, resizing, and reading the picture back. */
#define _POSIX_C_SOURCE 200809L /* nanosleep */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <karma/MeProfile.h>

#include <stb_image_write.h>

#include "RInternal.h"

/** Karma's default window. */
#define R_DEFAULT_WIDTH 640
#define R_DEFAULT_HEIGHT 448
#define R_MAX_SIZE 8192
#define R_DEFAULT_TITLE "MathEngine Karma (v1.2.1) [OpenGL / GLFW]"

MeBool MEAPI RRenderParseSize(const char *text, int *w, int *h)
{
    char *end;
    errno = 0;
    long a = strtol(text, &end, 10);
    if (errno || end == text || *end != 'x')
        return MEFALSE;
    const char *second = end + 1;
    long b = strtol(second, &end, 10);
    if (errno || end == second || *end || a < 1 || b < 1 || a > R_MAX_SIZE || b > R_MAX_SIZE)
        return MEFALSE;
    *w = (int)a, *h = (int)b;
    return METRUE;
}

/* Read the viewer's options from one list (later lists override earlier ones). */
static MeBool readOptions(RRender *rc, MeCommandLineOptions *o, int eat, int *w, int *h)
{
    if (!o)
        return METRUE;
    if (MeCommandLineOptionsCheckFor(o, "-gl", (MeBool)eat))
        rc->m_options.m_renderType = kROpenGL;
    if (MeCommandLineOptionsCheckFor(o, "-null", (MeBool)eat))
        rc->m_options.m_renderType = kRNull;
    if (MeCommandLineOptionsCheckFor(o, "-headless", (MeBool)eat))
        rc->m_options.m_renderType = kRHeadless;
    if (MeCommandLineOptionsCheckFor(o, "-bench", (MeBool)eat))
        rc->m_options.m_renderType = kRBenchmark;
    /* -profile [frames]: the frame count is optional. */
    int profileFrames = MeCommandLineOptionsGetNumeric(o, "-profile", (MeBool)eat);
    if (profileFrames >= 0 || MeCommandLineOptionsCheckFor(o, "-profile", (MeBool)eat)) {
        rc->m_bProfiling = 1;
        if (profileFrames > 0)
            rc->m_private->profileFrames = (unsigned int)profileFrames;
    }
    if (MeCommandLineOptionsCheckFor(o, "-wireframe", (MeBool)eat))
        rc->m_options.m_bWireFrame = METRUE;
    if (MeCommandLineOptionsCheckFor(o, "-notextures", (MeBool)eat))
        rc->m_options.m_bTextures = MEFALSE;
    const char *size = MeCommandLineOptionsGetString(o, "-size", (MeBool)eat);
    if (size && !RRenderParseSize(size, w, h)) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderContextCreate", "-size takes WxH, each 1 to %d (got %s)", R_MAX_SIZE, size);
        return MEFALSE;
    }
    const char *timeout = MeCommandLineOptionsGetString(o, "-timeout", (MeBool)eat);
    if (timeout) {
        char *end;
        errno = 0;
        long n = strtol(timeout, &end, 10);
        if (errno || end == timeout || *end || n < 0 || n > INT_MAX) {
            R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderContextCreate", "-timeout takes a frame count (got %s)", timeout);
            return MEFALSE;
        }
        rc->m_nTimeout = (unsigned int)n;
    }
    return METRUE;
}

static RRender *contextNew(void)
{
    RRender *rc = calloc(1, sizeof *rc);
    RRenderCallBacks *cb = calloc(1, sizeof *cb);
    struct RRenderPrivate *p = calloc(1, sizeof *p);
    if (!rc || !cb || !p) {
        free(rc), free(cb), free(p);
        return NULL;
    }
    rc->m_pCallBacks = cb;
    rc->m_private = p;
    /* Karma's keys of actions 2–5: Enter, Space, o, p. */
    cb->m_actionKeys[0] = '\r', cb->m_actionKeys[1] = ' ', cb->m_actionKeys[2] = 'o', cb->m_actionKeys[3] = 'p';
    rc->m_options.m_renderType = kROpenGL;
    rc->m_options.m_bDisplayHelpOnConsole = METRUE;
    rc->m_options.m_bTextures = METRUE;
    rc->m_sphereRes = 24;
    rc->m_backgroundColour[3] = 1;
    snprintf(p->title, sizeof p->title, "%s", R_DEFAULT_TITLE);
    RLightSetDefaults(rc);
    return rc;
}

/* Size, camera and, unless null, the backend and GL objects. */
static RRender *contextStart(RRender *rc, int width, int height)
{
    struct RRenderPrivate *p = rc->m_private;
    p->width = width, p->height = height;
    rc->m_AspectRatio = (AcmeReal)width / (AcmeReal)height;
    RCameraSetDefaults(rc);
    switch (rc->m_options.m_renderType) {
    case kRNull:
    case kRBenchmark:
        return rc;
    case kRHeadless:
        p->backend = RBackendEGLCreate();
        break;
    default:
        rc->m_options.m_renderType = kROpenGL;
        p->backend = RBackendGLFWCreate(rc, width, height, p->title);
        break;
    }
    if (p->backend)
        p->gl = RGLCreate(p->backend, width, height);
    if (!p->backend || !p->gl) {
        RRenderContextDestroy(rc);
        return NULL;
    }
    p->frameLock = p->backend->drawsToWindow; /* a window starts with vsync, as Karma's locked rate */
    return rc;
}

int RRenderResize(RRender *rc, int width, int height)
{
    if (!rc)
        return -1;
    if (width < 1 || height < 1 || width > R_MAX_SIZE || height > R_MAX_SIZE) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderResize", "size %d x %d is outside 1 to %d", width, height, R_MAX_SIZE);
        return -1;
    }
    struct RRenderPrivate *p = rc->m_private;
    if (p->gl) {
        p->backend->makeCurrent(p->backend);
        if (RGLResize(p->gl, width, height) != 0) {
            R_REPORT(ME_ERR_BAD_STATE, "RRenderResize", "no framebuffers of %d x %d: the picture keeps its size", width,
                     height);
            return -1;
        }
        p->drawn = 0; /* the picture read back must be one of the new size */
    }
    p->width = width, p->height = height;
    if (!p->aspectLock)
        rc->m_AspectRatio = (AcmeReal)width / (AcmeReal)height;
    RCameraUpdate(rc);
    return 0;
}

void RRenderSetFrameRateLock(RRender *rc, int on)
{
    struct RRenderPrivate *p = rc->m_private;
    p->frameLock = on ? 1 : 0;
    if (p->backend && p->backend->setSwapInterval)
        p->backend->setSwapInterval(p->backend, p->frameLock);
}

void MEAPI RRenderToggleFrameLock(RRender *rc)
{
    if (rc)
        RRenderSetFrameRateLock(rc, !rc->m_private->frameLock);
}

void MEAPI RRenderSetFrameLockRate(RRender *rc, unsigned int iRate)
{
    if (!rc)
        return;
    if (iRate < 1 || iRate > 1000) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderSetFrameLockRate", "%u frames a second is not 1 to 1000", iRate);
        return;
    }
    rc->m_private->lockRate = (int)iRate;
}

void RRenderSetFullscreen(RRender *rc, int on)
{
    struct RRenderPrivate *p = rc->m_private;
    p->fullscreen = on ? 1 : 0;
    if (p->backend && p->backend->setFullscreen)
        p->backend->setFullscreen(p->backend, p->fullscreen);
}

/* Sleep until `until` (seconds of `seconds()`'s clock); nothing when it has passed. */
static void sleepUntil(double until, double now)
{
    if (until <= now)
        return;
    double wait = until - now;
    struct timespec t = {(time_t)wait, (long)((wait - (double)(time_t)wait) * 1e9)};
    while (nanosleep(&t, &t) != 0 && errno == EINTR)
        ;
}

RRender *MEAPI RRenderContextCreate(MeCommandLineOptions *options, MeCommandLineOptions *overrideoptions, int eat)
{
    RRender *rc = contextNew();
    if (!rc)
        return NULL;
    int w = R_DEFAULT_WIDTH, h = R_DEFAULT_HEIGHT;
    if (!readOptions(rc, options, eat, &w, &h) || !readOptions(rc, overrideoptions, eat, &w, &h)) {
        RRenderContextDestroy(rc);
        return NULL;
    }
    return contextStart(rc, w, h);
}

RRender *MEAPI RRenderContextCreateHeadless(int width, int height)
{
    if (width < 1 || height < 1 || width > R_MAX_SIZE || height > R_MAX_SIZE) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderContextCreateHeadless", "size %d x %d is outside 1 to %d", width, height,
                 R_MAX_SIZE);
        return NULL;
    }
    RRender *rc = contextNew();
    if (!rc)
        return NULL;
    rc->m_options.m_renderType = kRHeadless;
    return contextStart(rc, width, height);
}

static void deleteList(RRender *rc, int is2D)
{
    RGraphic **head = is2D ? &rc->m_pRG_First2D : &rc->m_pRG_First;
    while (*head)
        RGraphicDelete(rc, *head, is2D);
}

int MEAPI RRenderContextDestroy(RRender *rc)
{
    if (!rc)
        return 0;
    struct RRenderPrivate *p = rc->m_private;
    if (p->backend)
        p->backend->makeCurrent(p->backend);
    RMenuContextGone(rc);
    RHelpContextGone(rc);
    RDebugDrawDestroy(rc);
    RPerformanceBarDestroy(rc);
    RNLineContextGone(rc);
    RParticlesContextGone(rc);
    deleteList(rc, 0);
    deleteList(rc, 1); /* the "Paused" text too */
    RGLDestroy(p->gl);
    RTexturesContextGone(rc);
    if (p->backend)
        p->backend->destroy(p->backend);
    free(rc->m_pCallBacks);
    free(p);
    free(rc);
    return 0;
}

void MEAPI RRenderQuit(RRender *rc)
{
    if (rc)
        rc->m_bQuitNextFrame = 1;
}

/** Karma's "Paused" overlay: grey text at the top right of the virtual 640 × 448 screen. */
#define R_PAUSED_X 575
#define R_PAUSED_Y 0

void MEAPI RRenderSetPause(RRender *rc, int p)
{
    if (!rc)
        return;
    rc->m_bPause = p != 0;
    struct RRenderPrivate *priv = rc->m_private;
    if (rc->m_bPause && !priv->pausedText) {
        static const float grey[4] = {0.6f, 0.6f, 0.6f, 1};
        priv->pausedText = RGraphicTextCreate(rc, "Paused", R_PAUSED_X, R_PAUSED_Y, grey);
    } else if (!rc->m_bPause && priv->pausedText) {
        RGraphicDelete(rc, priv->pausedText, 1);
        priv->pausedText = NULL;
    }
}

void MEAPI RRenderSingleStep(RRender *rc)
{
    if (rc)
        rc->m_private->singleStep = 1;
}

void MEAPI RRenderSetWindowTitle(RRender *rc, const char *title)
{
    if (!rc || !title)
        return;
    snprintf(rc->m_private->title, sizeof rc->m_private->title, "%s", title);
    RBackend *b = rc->m_private->backend;
    if (b && b->setTitle)
        b->setTitle(b, rc->m_private->title);
}

void MEAPI RRenderSetAppName(RRender *rc, const char *appname)
{
    if (rc && appname)
        snprintf(rc->m_AppName, sizeof rc->m_AppName, "%s", appname);
}

void MEAPI RRenderSetWireframe(RRender *rc, MeBool b)
{
    if (rc)
        rc->m_options.m_bWireFrame = b ? METRUE : MEFALSE;
}

void MEAPI RRenderSetBackgroundColor(RRender *rc, const float color[4])
{
    if (!rc || !color) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RRenderSetBackgroundColor", "NULL render context or colour");
        return;
    }
    for (int i = 0; i < 4; i++)
        if (!isfinite(color[i])) {
            R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RRenderSetBackgroundColor", "the colour is not finite");
            return;
        }
    for (int i = 0; i < 4; i++)
        rc->m_backgroundColour[i] = color[i];
}

/** Sides a round primitive may have (RRenderSetSphereResolution). */
#define R_MIN_SPHERE_RES 3
#define R_MAX_SPHERE_RES 256

void MEAPI RRenderSetSphereResolution(RRender *rc, int res)
{
    if (!rc) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RRenderSetSphereResolution", "NULL render context");
        return;
    }
    if (res < R_MIN_SPHERE_RES || res > R_MAX_SPHERE_RES) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderSetSphereResolution", "%d sides: %d to %d", res, R_MIN_SPHERE_RES,
                 R_MAX_SPHERE_RES);
        return;
    }
    rc->m_sphereRes = res;
}

int MEAPI RRenderGetSphereResolution(RRender *rc)
{
    return rc ? rc->m_sphereRes : 0;
}

void MEAPI RRenderGetSize(RRender *rc, int *width, int *height)
{
    if (width)
        *width = rc ? rc->m_private->width : 0;
    if (height)
        *height = rc ? rc->m_private->height : 0;
}

void MEAPI RRenderDrawFrame(RRender *rc)
{
    if (!rc)
        return;
    struct RRenderPrivate *p = rc->m_private;
    RDebugDrawFrame(rc); /* the null renderer too: the lines are there to be read */
    if (!p->gl) /* the null renderer draws nothing */
        return;
    p->backend->makeCurrent(p->backend);
    RGLDrawFrame(p->gl, rc, p->backend->drawsToWindow);
    if (p->backend->present)
        p->backend->present(p->backend);
    p->drawn = 1;
}

static double seconds(void)
{
    struct timespec t;
    timespec_get(&t, TIME_UTC);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/** The frame rate shown is averaged over this many seconds. */
#define R_FPS_PERIOD 0.5
/** Frames -profile runs when neither it nor -timeout gives a count. */
#define R_PROFILE_FRAMES 1000

/* -profile's report and -bench's figures, after the loop. */
static void report(RRender *rc, unsigned long frames, double seconds, double applicationSeconds)
{
    if (rc->m_bProfiling) {
        MeProfileOutputResults();
        MeProfileStopTiming();
    }
    if (rc->m_options.m_renderType == kRBenchmark && frames > 0)
        printf("Benchmark: %lu frames in %.3f s, %.3f ms a frame (%.3f ms in the application's tick)\n", frames,
               seconds, 1e3 * seconds / (double)frames, 1e3 * applicationSeconds / (double)frames);
}

void MEAPI RRun(RRender *rc, RMainLoopCallBack func, void *userdata)
{
    if (!rc)
        return;
    struct RRenderPrivate *p = rc->m_private;
    rc->m_bQuitNextFrame = 0;
    unsigned long limit = rc->m_nTimeout;
    if (rc->m_bProfiling) {
        MeProfileTimerMode mode = {0};
        MeProfileStartTiming(mode, kMeProfileLogTotals);
        if (p->profileFrames)
            limit = p->profileFrames;
        else if (!limit)
            limit = R_PROFILE_FRAMES;
    }
    double start = seconds(), periodStart = start, application = 0;
    unsigned long periodFrames = 0, frame = 0;
    for (; !rc->m_bQuitNextFrame && !(limit && frame >= limit); frame++) {
        /* Idle: waiting for and handling input; then the application's tick (its MeProfile sections
         * "Collision" and "Dynamics"), then drawing ("Rendering"). */
        int timing = p->perfBar || rc->m_bProfiling;
        if (timing) {
            MeProfileStartFrame();
            MeProfileStartSection("Idle Time", 0);
        }
        double t0 = seconds();
        int open = !(p->backend && p->backend->poll && !p->backend->poll(p->backend, rc));
        double t1 = seconds();
        if (timing)
            MeProfileEndSection("Idle Time");
        if (!open) {
            if (timing)
                MeProfileEndFrame();
            break;
        }
        if (func && (!rc->m_bPause || p->singleStep))
            func(rc, userdata);
        p->singleStep = 0;
        double t2 = seconds();
        if (timing)
            MeProfileStartSection("Rendering", 0);
        RRenderDrawFrame(rc);
        if (timing) {
            MeProfileEndSection("Rendering");
            MeProfileEndFrame();
        }
        double drawn = seconds(), t3 = drawn;
        /* The frame-rate lock without a window's vsync: frames start 1/R_LOCKED_RATE s apart (idle time). */
        if (p->frameLock && !(p->backend && p->backend->setSwapInterval)) {
            sleepUntil(t0 + 1.0 / (p->lockRate > 0 ? p->lockRate : R_LOCKED_RATE), drawn);
            t3 = seconds();
        }
        application += t2 - t1;
        p->frames++;
        if (p->perfBar) { /* -profile keeps totals: the bar shows their average a frame */
            AcmeReal per = rc->m_bProfiling ? (AcmeReal)(1.0 / (double)(frame + 1)) : 1;
            RPerformanceBarUpdate(rc, per * MeProfileGetSectionTime("Collision"), per * MeProfileGetSectionTime("Dynamics"),
                                  (AcmeReal)(1e3 * (drawn - t2)), (AcmeReal)(1e3 * (t1 - t0 + t3 - drawn)));
        }
        periodFrames++;
        if (t3 - periodStart >= R_FPS_PERIOD) {
            p->fps = (double)periodFrames / (t3 - periodStart);
            periodStart = t3, periodFrames = 0;
            if (p->showFps)
                RRenderDisplayFps(rc, (AcmeReal)p->fps);
        }
    }
    report(rc, frame, seconds() - start, application);
}

int MEAPI RRenderReadPixels(RRender *rc, unsigned char *rgba)
{
    if (!rc || !rgba || !rc->m_private->gl || !rc->m_private->drawn)
        return -1;
    rc->m_private->backend->makeCurrent(rc->m_private->backend);
    RGLReadPixels(rc->m_private->gl, rgba);
    return 0;
}

int MEAPI RRenderSavePNG(RRender *rc, const char *filename)
{
    if (!rc || !filename) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RRenderSavePNG", "NULL %s", rc ? "file name" : "render context");
        return -1;
    }
    int w = rc->m_private->width, h = rc->m_private->height;
    unsigned char *rgba = malloc((size_t)w * (size_t)h * 4);
    if (!rgba)
        return -1;
    int result = -1;
    if (RRenderReadPixels(rc, rgba) != 0)
        R_REPORT(ME_ERR_BAD_STATE, "RRenderSavePNG", "no frame has been drawn (null renderer, or RRenderDrawFrame not called)");
    else if (!stbi_write_png(filename, w, h, 4, rgba, w * 4))
        R_REPORT(ME_ERR_BAD_STATE, "RRenderSavePNG", "cannot write %s", filename);
    else
        result = 0;
    free(rgba);
    return result;
}
