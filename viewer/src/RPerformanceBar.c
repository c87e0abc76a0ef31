/* RPerformanceBar.c -- Karma's performance bar and frame-rate display: a bar at the bottom of the
 * picture whose four parts are the last frame's collision, dynamics, rendering and idle times, on
 * a scale with ticks at 0, 4, 8, 12 and 16 ms, with the figures written after it; and "FPS" text
 * at the top left. RRun feeds the bar every frame from MeProfile's "Collision" and "Dynamics"
 * sections and its own rendering and idle times. */
#include <stdio.h>
#include <stdlib.h>

#include "RInternal.h"

/** Layout in Karma's virtual 640 × 448 screen: the bar's left end, top, height, and length a millisecond. */
#define R_BAR_X 20.0f
#define R_BAR_Y 428.0f
#define R_BAR_H 8.0f
#define R_BAR_PER_MS 12.0f
#define R_BAR_TICKS 5
#define R_BAR_TICK_MS 4.0f

struct RPerformanceBar {
    RGraphic *part[4];          /* collision, dynamics, rendering, idle */
    RGraphic *tick[R_BAR_TICKS];
    RGraphic *figures;
    MeReal ms[4];               /* the last update */
};

/* Collision orange, dynamics green, rendering blue, idle grey. */
static const float partColor[4][4] = {
    {1, 0.55f, 0.1f, 1}, {0.2f, 0.8f, 0.3f, 1}, {0.3f, 0.5f, 1, 1}, {0.6f, 0.6f, 0.6f, 1}};

RPerformanceBar *MEAPI RPerformanceBarCreate(RRender *rc)
{
    if (!rc) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RPerformanceBarCreate", "NULL render context");
        return NULL;
    }
    struct RRenderPrivate *p = rc->m_private;
    if (p->perfBar)
        return p->perfBar;
    RPerformanceBar *bar = calloc(1, sizeof *bar);
    if (!bar)
        return NULL;
    static const float white[4] = {1, 1, 1, 1};
    for (int k = 0; k < 4; k++)
        bar->part[k] = RGraphic2DRectangleCreate(rc, R_BAR_X, R_BAR_Y, 0, R_BAR_H, partColor[k]);
    for (int t = 0; t < R_BAR_TICKS; t++)
        bar->tick[t] = RGraphic2DRectangleCreate(rc, R_BAR_X + R_BAR_PER_MS * R_BAR_TICK_MS * (float)t, R_BAR_Y - 3, 1,
                                                 R_BAR_H + 6, white);
    bar->figures = RGraphicTextCreate(rc, "", R_BAR_X + R_BAR_PER_MS * R_BAR_TICK_MS * (R_BAR_TICKS - 1) + 12,
                                      R_BAR_Y - 6, white);
    p->perfBar = bar;
    return bar;
}

void MEAPI RPerformanceBarUpdate(RRender *rc, AcmeReal coltime, AcmeReal dyntime, AcmeReal rentime, AcmeReal idletime)
{
    if (!rc || !rc->m_private->perfBar)
        return;
    RPerformanceBar *bar = rc->m_private->perfBar;
    AcmeReal ms[4] = {coltime, dyntime, rentime, idletime};
    float x = R_BAR_X;
    for (int k = 0; k < 4; k++) {
        AcmeReal t = ms[k] > 0 ? ms[k] : 0; /* a negative or NaN time draws nothing */
        bar->ms[k] = t;
        float w = R_BAR_PER_MS * (float)t;
        RRectangleSet(bar->part[k], x, R_BAR_Y, w, R_BAR_H);
        x += w;
    }
    char text[96];
    snprintf(text, sizeof text, "%.1f + %.1f + %.1f + %.1f ms", (double)bar->ms[0], (double)bar->ms[1],
             (double)bar->ms[2], (double)bar->ms[3]);
    RGraphicTextSet(bar->figures, text);
}

void RPerformanceBarDestroy(RRender *rc)
{
    RPerformanceBar *bar = rc->m_private->perfBar;
    if (!bar)
        return;
    for (int k = 0; k < 4; k++)
        RGraphicDelete(rc, bar->part[k], 1);
    for (int t = 0; t < R_BAR_TICKS; t++)
        RGraphicDelete(rc, bar->tick[t], 1);
    RGraphicDelete(rc, bar->figures, 1);
    free(bar);
    rc->m_private->perfBar = NULL;
}

void MEAPI RRenderDisplayFps(RRender *rc, AcmeReal fps)
{
    if (!rc)
        return;
    struct RRenderPrivate *p = rc->m_private;
    char text[32];
    snprintf(text, sizeof text, "FPS: %.1f", (double)fps);
    if (!p->fpsText) {
        static const float white[4] = {1, 1, 1, 1};
        p->fpsText = RGraphicTextCreate(rc, text, 5, 0, white);
    } else {
        RGraphicTextSet(p->fpsText, text);
    }
}

void MEAPI RRenderSetDisplayFps(RRender *rc, int bVal)
{
    if (!rc)
        return;
    struct RRenderPrivate *p = rc->m_private;
    p->showFps = bVal != 0;
    if (!p->showFps && p->fpsText) {
        RGraphicDelete(rc, p->fpsText, 1);
        p->fpsText = NULL;
    }
}
