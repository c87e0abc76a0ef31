/* RGraphic.c -- graphics: creation, render lists, colour, the matrix they follow, scaling and
 * strips to triangle lists. A graphic may carry others (`part`: an aggregate model's elements) that
 * are listed, coloured and destroyed with it. The primitives'
 * triangle lists are built in RPrimitives.c; GL buffers are made when a graphic is first drawn, so
 * graphics can be made and changed without a GL context (the null renderer). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <karma/MeMessage.h>

#include "RInternal.h"

RGraphic *MEAPI RGraphicCreateEmpty(int numVertices)
{
    if (numVertices < 0) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RGraphicCreateEmpty", "negative vertex count %d", numVertices);
        return NULL;
    }
    RGraphic *rg = calloc(1, sizeof *rg);
    RObjectHeader *h = calloc(1, sizeof *h);
    struct RGraphicPrivate *p = calloc(1, sizeof *p);
    RObjectVertex *v = calloc((size_t)(numVertices > 0 ? numVertices : 1), sizeof *v);
    if (!rg || !h || !p || !v) {
        free(rg), free(h), free(p), free(v);
        return NULL;
    }
    rg->m_pObject = h;
    rg->m_pVertices = v;
    rg->m_nMaxNumVertices = numVertices;
    rg->m_private = p;
    h->m_nNumVertices = numVertices;
    h->m_nTextureID = -1;
    h->m_SpecularPower = 40;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            h->m_Matrix[i][j] = (MeReal)(i == j);
    const float white[4] = {1, 1, 1, 1};
    RGraphicSetColor(rg, white);
    p->dirty = 1;
    return rg;
}

RGraphic *RGraphicNew(RRender *rc, RGraphicKind kind, int n, const float color[4], MeMatrix4Ptr matrix)
{
    if (!rc) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphic*Create", "NULL render context");
        return NULL;
    }
    RGraphic *rg = RGraphicCreateEmpty(n);
    if (!rg)
        return NULL;
    rg->m_private->kind = kind;
    if (color)
        RGraphicSetColor(rg, color);
    rg->m_pLWMatrix = matrix;
    RGraphicAddToList(rc, rg, kind == kRKindText || kind == kRKindRect2D);
    return rg;
}

void MEAPI RGraphicAddToList(RRender *rc, RGraphic *rg, int is2D)
{
    if (!rc || !rg)
        return;
    RGraphicAddToList(rc, rg->m_private->part, is2D);
    if (rg->m_private->inList)
        return;
    RGraphic **head = is2D ? &rc->m_pRG_First2D : &rc->m_pRG_First;
    /* Appended, so graphics draw in the order they were made (later text over earlier). */
    while (*head)
        head = &(*head)->m_pNext;
    *head = rg;
    rg->m_pNext = NULL;
    rg->m_private->inList = is2D ? 2 : 1;
}

void MEAPI RGraphicRemoveFromList(RRender *rc, RGraphic *rg, int is2D)
{
    if (!rc || !rg)
        return;
    RGraphicRemoveFromList(rc, rg->m_private->part, is2D);
    RGraphic **head = is2D ? &rc->m_pRG_First2D : &rc->m_pRG_First;
    for (; *head; head = &(*head)->m_pNext)
        if (*head == rg) {
            *head = rg->m_pNext;
            rg->m_pNext = NULL;
            rg->m_private->inList = 0;
            return;
        }
}

void MEAPI RGraphicDestroy(RGraphic *rg)
{
    if (!rg)
        return;
    if (rg->m_private->inList)
        R_REPORT(ME_ERR_BAD_STATE, "RGraphicDestroy", "the graphic is still in a render list: use RGraphicDelete");
    RGraphicDestroy(rg->m_private->part);
    RGLReleaseGraphic(rg);
    for (int k = 0; k < R_LOD_LEVELS; k++)
        RGraphicDestroy(rg->m_private->lod[k]);
    free(rg->m_private->text);
    free(rg->m_private);
    free(rg->m_pVertices);
    free(rg->m_pObject);
    free(rg);
}

void MEAPI RGraphicDelete(RRender *rc, RGraphic *rg, int is2D)
{
    if (!rg)
        return;
    RGraphicRemoveFromList(rc, rg, is2D);
    RGraphicDestroy(rg);
}

void MEAPI RGraphicSetTransformPtr(RGraphic *g, MeMatrix4Ptr matrix)
{
    if (g)
        g->m_pLWMatrix = matrix;
}

void MEAPI RGraphicSetColor(RGraphic *g, const float color[4])
{
    if (!g || !color)
        return;
    RGraphicSetColor(g->m_private->part, color);
    RObjectHeader *h = g->m_pObject;
    for (int i = 0; i < 3; i++) {
        h->m_ColorAmbient[i] = 0.5f * color[i]; /* with Karma's lights: lit faces bright, unlit ones still coloured */
        h->m_ColorDiffuse[i] = color[i];
        h->m_ColorSpecular[i] = 0.3f;
        h->m_ColorEmissive[i] = 0;
    }
    h->m_ColorAmbient[3] = h->m_ColorDiffuse[3] = h->m_ColorSpecular[3] = color[3];
    h->m_ColorEmissive[3] = 0;
}

void MEAPI RGraphicGetColor(RGraphic *g, float color[4])
{
    if (g && color)
        memcpy(color, g->m_pObject->m_ColorDiffuse, 4 * sizeof(float));
}

MeBool MEAPI RGraphicIsWireframe(RGraphic *g)
{
    return g && g->m_pObject->m_bIsWireFrame ? METRUE : MEFALSE;
}

void MEAPI RGraphicSetWireframe(RGraphic *g, MeBool b)
{
    if (g) {
        RGraphicSetWireframe(g->m_private->part, b);
        g->m_pObject->m_bIsWireFrame = b ? 1 : 0;
    }
}

int MEAPI RGraphicLineMoveEnds(RGraphic *lineG, AcmeReal *origin, AcmeReal *end)
{
    if (!lineG || lineG->m_private->kind != kRKindLines || lineG->m_nMaxNumVertices < 2 || !origin || !end)
        return -1;
    RObjectVertex *v = lineG->m_pVertices;
    v[0].m_X = origin[0], v[0].m_Y = origin[1], v[0].m_Z = origin[2];
    v[1].m_X = end[0], v[1].m_Y = end[1], v[1].m_Z = end[2];
    lineG->m_private->dirty = 1;
    return 0;
}

RGraphic *MEAPI RGraphicLineCreate(RRender *rc, AcmeReal origin[3], AcmeReal end[3], const float color[4],
                                   MeMatrix4Ptr matrix)
{
    if (!origin || !end)
        return NULL;
    RGraphic *rg = RGraphicNew(rc, kRKindLines, 2, color, matrix);
    if (rg)
        RGraphicLineMoveEnds(rg, origin, end);
    return rg;
}

RGraphic *MEAPI RGraphicTextCreate(RRender *rc, char *text, AcmeReal orig_x, AcmeReal orig_y, const float color[4])
{
    if (!text) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicTextCreate", "NULL text");
        return NULL;
    }
    RGraphic *rg = RGraphicNew(rc, kRKindText, 0, color, NULL);
    if (!rg)
        return NULL;
    size_t n = strlen(text);
    rg->m_private->text = malloc(n + 1);
    if (!rg->m_private->text) {
        RGraphicDelete(rc, rg, 1);
        return NULL;
    }
    memcpy(rg->m_private->text, text, n + 1);
    rg->m_private->x = (float)orig_x;
    rg->m_private->y = (float)orig_y;
    return rg;
}

int RGraphicTextSet(RGraphic *rg, const char *text)
{
    if (!rg || !text || rg->m_private->kind != kRKindText)
        return -1;
    size_t n = strlen(text);
    char *copy = malloc(n + 1);
    if (!copy)
        return -1;
    memcpy(copy, text, n + 1);
    free(rg->m_private->text);
    rg->m_private->text = copy;
    return 0;
}

RGraphic *MEAPI RGraphic2DRectangleCreate(RRender *rc, AcmeReal orig_x, AcmeReal orig_y, AcmeReal width, AcmeReal height,
                                          const float color[4])
{
    RGraphic *rg = RGraphicNew(rc, kRKindRect2D, 0, color, NULL);
    if (rg)
        RRectangleSet(rg, (float)orig_x, (float)orig_y, (float)width, (float)height);
    return rg;
}

void RRectangleSet(RGraphic *rg, float x, float y, float width, float height)
{
    if (!rg || rg->m_private->kind != kRKindRect2D)
        return;
    rg->m_private->x = x, rg->m_private->y = y;
    rg->m_private->w = width > 0 ? width : 0, rg->m_private->h = height > 0 ? height : 0;
}

void MEAPI RGraphicScale(RGraphic *rg, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale)
{
    const double s[3] = {xScale, yScale, zScale};
    if (!rg)
        return;
    for (int k = 0; k < 3; k++)
        if (!(isfinite(s[k]) && s[k] != 0)) {
            R_REPORT(ME_ERR_ARGUMENT_RANGE, "RGraphicScale", "scale (%g, %g, %g): each must be finite and not 0",
                     s[0], s[1], s[2]);
            return;
        }
    for (int i = 0; i < rg->m_pObject->m_nNumVertices; i++) {
        RObjectVertex *v = &rg->m_pVertices[i];
        double n[3] = {v->m_NX / s[0], v->m_NY / s[1], v->m_NZ / s[2]};
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        v->m_X = (AcmeReal)(v->m_X * s[0]), v->m_Y = (AcmeReal)(v->m_Y * s[1]), v->m_Z = (AcmeReal)(v->m_Z * s[2]);
        if (l > 0)
            v->m_NX = (AcmeReal)(n[0] / l), v->m_NY = (AcmeReal)(n[1] / l), v->m_NZ = (AcmeReal)(n[2] / l);
    }
    rg->m_private->dirty = 1;
}

void MEAPI RConvertTriStripToTriList(RGraphic *rg, RObjectVertex *strips, int *stripSize, int *stripStart, int numStrips)
{
    if (!rg || (numStrips > 0 && (!strips || !stripSize || !stripStart)))
        return;
    long need = 0;
    for (int i = 0; i < numStrips; i++)
        need += stripSize[i] >= 3 ? 3L * (stripSize[i] - 2) : 0;
    if (numStrips < 0 || need > rg->m_nMaxNumVertices) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RConvertTriStripToTriList", "%ld vertices do not fit in the graphic's %d",
                 need, rg->m_nMaxNumVertices);
        return;
    }
    RObjectVertex *out = rg->m_pVertices;
    for (int i = 0; i < numStrips; i++) {
        const RObjectVertex *s = strips + stripStart[i];
        for (int k = 0; k + 2 < stripSize[i]; k++) {
            /* Strip triangle k is (k, k+1, k+2); the odd ones wind the other way: swap two corners. */
            int odd = k & 1;
            *out++ = s[k];
            *out++ = s[k + 1 + odd];
            *out++ = s[k + 2 - odd];
        }
    }
    rg->m_pObject->m_nNumVertices = (int)need;
    rg->m_private->dirty = 1;
}
