/* RViewerMenu.c -- the viewer's own menu, F12 (Karma's context menu): pause, single step,
 * wireframe, textures, shadows, particles, frame rate, frame-rate lock, aspect lock, performance bar,
 * help, exit. */
#include "RInternal.h"

static int pauseEntry(RRender *rc, int set)
{
    if (set >= 0)
        RRenderSetPause(rc, !rc->m_bPause);
    return rc->m_bPause != 0;
}

static int stepEntry(RRender *rc, int set)
{
    if (set >= 0) {
        RRenderSetPause(rc, 1);
        RRenderSingleStep(rc);
    }
    return -1;
}

static int wireframeEntry(RRender *rc, int set)
{
    if (set >= 0)
        RRenderSetWireframe(rc, !rc->m_options.m_bWireFrame);
    return rc->m_options.m_bWireFrame != 0;
}

static int shadowsEntry(RRender *rc, int set)
{
    if (set >= 0)
        rc->m_private->noShadows = !rc->m_private->noShadows;
    return !rc->m_private->noShadows;
}

static int texturesEntry(RRender *rc, int set)
{
    if (set >= 0)
        rc->m_options.m_bTextures = rc->m_options.m_bTextures ? MEFALSE : METRUE;
    return rc->m_options.m_bTextures != 0;
}

static int particlesEntry(RRender *rc, int set)
{
    if (set >= 0)
        rc->m_private->noParticles = !rc->m_private->noParticles;
    return !rc->m_private->noParticles;
}

static int frameLockEntry(RRender *rc, int set)
{
    if (set >= 0)
        RRenderSetFrameRateLock(rc, !rc->m_private->frameLock);
    return rc->m_private->frameLock != 0;
}

static int aspectLockEntry(RRender *rc, int set)
{
    if (set >= 0)
        rc->m_private->aspectLock = !rc->m_private->aspectLock;
    return rc->m_private->aspectLock != 0;
}

static int fpsEntry(RRender *rc, int set)
{
    if (set >= 0)
        RRenderSetDisplayFps(rc, !rc->m_private->showFps);
    return rc->m_private->showFps;
}

static int barEntry(RRender *rc, int set)
{
    if (set >= 0) {
        if (rc->m_private->perfBar)
            RPerformanceBarDestroy(rc);
        else
            RPerformanceBarCreate(rc);
    }
    return rc->m_private->perfBar != NULL;
}

static int helpEntry(RRender *rc, int set)
{
    if (set >= 0) {
        RMenuToggle(rc, NULL);
        RRenderToggleUserHelp(rc);
    }
    return -1;
}

static int exitEntry(RRender *rc, int set)
{
    if (set >= 0) {
        RMenuToggle(rc, NULL);
        RRenderQuit(rc);
    }
    return -1;
}

RMenu *RViewerMenu(RRender *rc)
{
    struct RRenderPrivate *p = rc->m_private;
    if (p->menuViewer)
        return p->menuViewer;
    RMenu *m = RMenuCreate(rc, "Viewer (F12)");
    if (!m)
        return NULL;
    RMenuAddViewerEntry(m, "Pause", pauseEntry);
    RMenuAddViewerEntry(m, "Single step", stepEntry);
    RMenuAddViewerEntry(m, "Wireframe", wireframeEntry);
    RMenuAddViewerEntry(m, "Shadows", shadowsEntry);
    RMenuAddViewerEntry(m, "Frame rate", fpsEntry);
    RMenuAddViewerEntry(m, "Performance bar", barEntry);
    RMenuAddViewerEntry(m, "Textures", texturesEntry);
    RMenuAddViewerEntry(m, "Particles", particlesEntry);
    RMenuAddViewerEntry(m, "Frame-rate lock", frameLockEntry);
    RMenuAddViewerEntry(m, "Aspect lock", aspectLockEntry);
    RMenuAddViewerEntry(m, "Help", helpEntry);
    RMenuAddViewerEntry(m, "Exit", exitEntry);
    p->menuViewer = m; /* destroyed with the context (RMenuContextGone) */
    return m;
}
