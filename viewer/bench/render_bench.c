/* render_bench.c -- how fast the viewer draws without a display: N bodies (boxes or spheres, each
 * following its own moving matrix, as graphics follow bodies) on a checkerboard ground, at W × H
 * with 4× multisampling, through EGL (Mesa's llvmpipe on a machine without a GPU).
 *
 *     karma_render_bench [--bodies N] [--size WxH] [--frames F] [--shape box|sphere]
 *                        [--particles P] [--lines L]
 *
 * --particles: P particles (one particle system, 0.1 m each) moving through the bodies' region;
 * --lines: L lines given again each frame with RLineAdd (as a demo's debug lines). Both are drawn
 * in one call each.
 *
 * Prints frames per second of drawing alone (the last frame is read back before the clock stops) and
 * the processor time per frame over all threads. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <MeMath.h>
#include <MeViewer.h>

#include "RInternal.h"

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Processor time of every thread of the process (llvmpipe draws on several): what the frames cost
 * on a machine shared with other work, where the wall clock says more about the others. */
static double cpuSeconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* What the command line asked for. */
typedef struct Options {
    int bodies, width, height, frames, spheres, shadows, particles, lines;
} Options;

/* Reads the options into *o; returns 0, or 2 (the exit status) after printing what was wrong. */
static int parseOptions(int argc, char **argv, Options *o)
{
    *o = (Options){.bodies = 1000, .width = 1280, .height = 720, .frames = 200, .shadows = 1};
    for (int i = 1; i + 1 < argc; i += 2) {
        if (strcmp(argv[i], "--bodies") == 0)
            o->bodies = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "--size") == 0 && sscanf(argv[i + 1], "%dx%d", &o->width, &o->height) == 2)
            continue;
        else if (strcmp(argv[i], "--frames") == 0)
            o->frames = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "--shape") == 0)
            o->spheres = strcmp(argv[i + 1], "sphere") == 0;
        else if (strcmp(argv[i], "--particles") == 0)
            o->particles = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "--lines") == 0)
            o->lines = atoi(argv[i + 1]);
        else if (strcmp(argv[i], "--shadows") == 0)
            o->shadows = strcmp(argv[i + 1], "off") != 0;
        else {
            fprintf(stderr, "usage: %s [--bodies N] [--size WxH] [--frames F] [--shape box|sphere] [--shadows on|off] "
                    "[--particles P] [--lines L]\n",
                    argv[0]);
            return 2;
        }
    }
    if (o->bodies < 0 || o->frames < 1 || o->particles < 0 || o->lines < 0) {
        fprintf(stderr, "--frames takes a positive count, --bodies, --particles and --lines counts >= 0\n");
        return 2;
    }
    return 0;
}

/* The drawn scene: the bodies' matrices (a cube of side `side` bodies), the particles' centres. */
typedef struct Scene {
    const Options *o;
    RRender *rc;
    MeMatrix4 *tm;
    MeVector3 *centres;
    int side;
} Scene;

/* The ground and the bodies, in a cube from the ground up. */
static void createBodies(Scene *s)
{
    const float grey[4] = {0.85f, 0.85f, 0.82f, 1};
    RGraphicGroundPlaneCreate(s->rc, 60, 60, grey, 0);
    int side = (int)ceil(cbrt((double)s->o->bodies));
    for (int i = 0; i < s->o->bodies; i++) {
        float color[4] = {0.3f + 0.6f * (float)(i % 3) / 2, 0.4f + 0.5f * (float)(i % 5) / 4, 0.8f - 0.5f * (float)(i % 7) / 6, 1};
        MeMatrix4 *tm = s->tm;
        for (int k = 0; k < 4; k++)
            tm[i][k][k] = 1;
        tm[i][3][0] = (MeReal)(0.8 * (i % side - side / 2.0));
        tm[i][3][1] = (MeReal)(0.4 + 0.8 * (i / (side * side)));
        tm[i][3][2] = (MeReal)(0.8 * ((i / side) % side - side / 2.0));
        if (s->o->spheres)
            RGraphicSphereCreate(s->rc, ME_R(0.3), color, tm[i]);
        else
            RGraphicBoxCreate(s->rc, ME_R(0.5), ME_R(0.5), ME_R(0.5), color, tm[i]);
    }
    s->side = side < 1 ? 1 : side;
}

/* Frame f's motion: every body turns about y, the particles swirl, the lines turn about the centre. */
static void moveScene(const Scene *s, int f)
{
    const int side = s->side;
    for (int i = 0; i < s->o->bodies; i++) { /* every body turns about y, as moving bodies do */
        double a = 0.01 * f + i;
        s->tm[i][0][0] = s->tm[i][2][2] = (MeReal)cos(a);
        s->tm[i][0][2] = (MeReal)-sin(a);
        s->tm[i][2][0] = (MeReal)sin(a);
    }
    for (int i = 0; i < s->o->particles; i++) { /* a swirl through the bodies' region */
        double a = 0.02 * f + 0.37 * i, r = 0.4 * side * (0.2 + 0.8 * (i % 97) / 96.0);
        MeVector3Set(s->centres[i], (MeReal)(r * cos(a)), (MeReal)(0.8 * side * (i % 89) / 88.0), (MeReal)(r * sin(a)));
    }
    RLineRemoveAll(s->rc);
    for (int i = 0; i < s->o->lines; i++) {
        double a = 0.01 * f + 6.283 * i / s->o->lines;
        MeVector3 p = {0, (MeReal)(0.4 * side), 0}, q = {(MeReal)(side * cos(a)), 0, (MeReal)(side * sin(a))};
        RLineAdd(s->rc, p, q, 1, 1, 0);
    }
}

int main(int argc, char **argv)
{
    Options o;
    const int usage = parseOptions(argc, argv, &o);
    if (usage)
        return usage;
    RRender *rc = RRenderContextCreateHeadless(o.width, o.height);
    if (!rc)
        return 1;
    rc->m_private->noShadows = !o.shadows; /* what the F12 menu's "Shadows" does */
    Scene s = {&o, rc, calloc((size_t)(o.bodies > 0 ? o.bodies : 1), sizeof(MeMatrix4)),
               calloc((size_t)(o.particles > 0 ? o.particles : 1), sizeof(MeVector3)), 1};
    if (!s.tm || !s.centres)
        return 1;
    createBodies(&s);
    const float orange[4] = {1, 0.55f, 0.1f, 1};
    RParticleSystem *ps = o.particles > 0 ? RParticleSystemCreate(rc, o.particles, s.centres, NULL, orange, ME_R(0.1)) : NULL;
    const AcmeVector3 at = {0, (AcmeReal)(0.4 * s.side), 0};
    RCameraSetLookAt(rc, at);
    RCameraSetView(rc, (AcmeReal)(2.2 * s.side), ME_R(0.5), ME_R(0.4));
    RRenderDrawFrame(rc); /* compiles the shaders and uploads the meshes */
    double start = seconds(), cpuStart = cpuSeconds();
    for (int f = 0; f < o.frames; f++) {
        moveScene(&s, f);
        RRenderDrawFrame(rc);
    }
    unsigned char *rgba = malloc((size_t)o.width * (size_t)o.height * 4);
    RRenderReadPixels(rc, rgba); /* waits for the last frame */
    double elapsed = seconds() - start, cpu = cpuSeconds() - cpuStart;
    printf("%d %s, %d particles, %d lines at %dx%d, shadows %s: %d frames in %.2f s, %.1f frames/s; processor time "
           "%.1f ms per frame (all threads)\n",
           o.bodies, o.spheres ? "spheres" : "boxes", o.particles, o.lines, o.width, o.height, o.shadows ? "on" : "off",
           o.frames, elapsed, o.frames / elapsed, 1e3 * cpu / o.frames);
    RParticleSystemDestroy(ps);
    free(rgba);
    RRenderContextDestroy(rc);
    free(s.tm);
    free(s.centres);
    return 0;
}
