/* RDebugDraw.c -- Karma's debug drawing (MeDebugDraw.h: contacts from MdtWorldSetDebugDrawing,
 * shapes and bounding boxes from McduDebugDraw*) shown by the viewer: the hook collects the lines
 * drawn between two frames, one line graphic per colour, and the next frame shows them. */
#include <stdlib.h>
#include <string.h>

#include <karma/MeDebugDraw.h>

#include "RInternal.h"

/** Distinct colours kept a frame (a line of a further colour takes the last one's). */
#define R_DEBUG_COLOURS 8

typedef struct RDebugBucket {
    float color[4];
    RGraphic *lines;   /* in the 3D list while it has lines */
    int used;          /* vertices written this frame */
} RDebugBucket;

struct RDebugDraw {
    RDebugBucket bucket[R_DEBUG_COLOURS];
    int buckets;
    int fresh;         /* lines arrived since the last frame */
};

/* The context the process-wide hook draws into (one at a time, as MeDebugDrawAPI is one). */
static RRender *hooked;

static RDebugBucket *bucketFor(struct RDebugDraw *d, float r, float g, float b)
{
    for (int i = 0; i < d->buckets; i++) {
        const float *c = d->bucket[i].color;
        if (c[0] == r && c[1] == g && c[2] == b)
            return &d->bucket[i];
    }
    RDebugBucket *k = &d->bucket[d->buckets < R_DEBUG_COLOURS ? d->buckets++ : R_DEBUG_COLOURS - 1];
    if (!k->lines || k->used == 0)
        k->color[0] = r, k->color[1] = g, k->color[2] = b, k->color[3] = 1;
    return k;
}

/* Room for `more` vertices: the graphic is made again twice as large when full. */
static int reserve(RRender *rc, RDebugBucket *k, int more)
{
    if (k->lines && k->used + more <= k->lines->m_nMaxNumVertices)
        return 1;
    int capacity = k->lines ? 2 * k->lines->m_nMaxNumVertices : 256;
    while (capacity < k->used + more)
        capacity *= 2;
    RGraphic *bigger = RGraphicNew(rc, kRKindLines, capacity, k->color, NULL);
    if (!bigger)
        return 0;
    if (k->lines) {
        memcpy(bigger->m_pVertices, k->lines->m_pVertices, sizeof *bigger->m_pVertices * (size_t)k->used);
        RGraphicDelete(rc, k->lines, 0);
    }
    k->lines = bigger;
    return 1;
}

static void MEAPI collect(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b)
{
    RRender *rc = hooked;
    if (!rc || !rc->m_private->debugDraw)
        return;
    struct RDebugDraw *d = rc->m_private->debugDraw;
    if (!d->fresh) { /* the first line since a frame: the last frame's lines go */
        for (int i = 0; i < d->buckets; i++)
            d->bucket[i].used = 0;
        d->buckets = 0;
        d->fresh = 1;
    }
    RDebugBucket *k = bucketFor(d, (float)r, (float)g, (float)b);
    if (!reserve(rc, k, 2))
        return;
    RObjectVertex *v = &k->lines->m_pVertices[k->used];
    memset(v, 0, 2 * sizeof *v);
    v[0].m_X = start[0], v[0].m_Y = start[1], v[0].m_Z = start[2];
    v[1].m_X = end[0], v[1].m_Y = end[1], v[1].m_Z = end[2];
    k->used += 2;
}

void MEAPI RRenderSetDebugDrawing(RRender *rc, MeBool on)
{
    if (!rc)
        return;
    struct RRenderPrivate *p = rc->m_private;
    if (on && !p->debugDraw) {
        p->debugDraw = calloc(1, sizeof *p->debugDraw);
        if (!p->debugDraw)
            return;
        hooked = rc;
        MeDebugDrawAPI.line = collect;
    } else if (!on && p->debugDraw) {
        RDebugDrawDestroy(rc);
    }
}

void RDebugDrawFrame(RRender *rc)
{
    struct RDebugDraw *d = rc->m_private->debugDraw;
    if (!d)
        return;
    /* What was drawn since the last frame is shown; buckets not used this time are emptied. */
    for (int i = 0; i < R_DEBUG_COLOURS; i++) {
        RDebugBucket *k = &d->bucket[i];
        if (!k->lines)
            continue;
        if (i >= d->buckets)
            k->used = 0;
        k->lines->m_pObject->m_nNumVertices = k->used;
        RGraphicSetColor(k->lines, k->color);
        k->lines->m_private->dirty = 1;
    }
    d->fresh = 0;
}

void RDebugDrawDestroy(RRender *rc)
{
    struct RDebugDraw *d = rc->m_private->debugDraw;
    if (!d)
        return;
    for (int i = 0; i < R_DEBUG_COLOURS; i++)
        RGraphicDelete(rc, d->bucket[i].lines, 0);
    free(d);
    rc->m_private->debugDraw = NULL;
    if (hooked == rc) {
        hooked = NULL;
        MeDebugDrawAPI.line = RDebugDrawNothing;
    }
}

void MEAPI RDebugDrawNothing(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b)
{
    (void)start, (void)end, (void)r, (void)g, (void)b;
}
