/* RNLine.c -- Karma 1.2's native lines (RNLine*: segments a context draws with GL lines, all in one
 * draw, instead of a graphic each) and its immediate lines (RLineAdd until RLineRemoveAll, what 1.2's
 * demos hand MeDebugDrawAPI.line). The context keeps every native line it made, listed or not, and
 * frees them when it goes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "RInternal.h"

struct RNLine {
    RRender *rc;             /* the context that made it (and frees it) */
    AcmeReal origin[3], end[3];
    float color[4];
    MeMatrix4Ptr matrix;     /* the ends are local to it when not NULL */
    int listed;              /* drawn */
    RNLine *next;            /* in rc's lines */
};

static int finite3(const AcmeReal *v)
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

static int finiteColor(const float c[4])
{
    return isfinite(c[0]) && isfinite(c[1]) && isfinite(c[2]) && isfinite(c[3]);
}

RNLine *MEAPI RNLineCreate(RRender *rc, AcmeReal origin[3], AcmeReal end[3], const float color[4], MeMatrix4Ptr matrix)
{
    if (!rc || !origin || !end || !color) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RNLineCreate", "NULL render context, end or colour");
        return NULL;
    }
    if (!finite3(origin) || !finite3(end) || !finiteColor(color)) {
        R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RNLineCreate", "an end or the colour is not finite");
        return NULL;
    }
    RNLine *line = RZeroedOrReport(sizeof *line, "RNLineCreate", "a line");
    if (!line)
        return NULL;
    line->rc = rc;
    memcpy(line->origin, origin, sizeof line->origin);
    memcpy(line->end, end, sizeof line->end);
    memcpy(line->color, color, sizeof line->color);
    line->matrix = matrix;
    line->listed = 1;
    line->next = rc->m_private->nlines;
    rc->m_private->nlines = line;
    return line;
}

int MEAPI RNLineMoveEnds(RNLine *line, AcmeReal *origin, AcmeReal *end)
{
    if (!line || !origin || !end) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RNLineMoveEnds", "NULL line or end");
        return -1;
    }
    if (!finite3(origin) || !finite3(end)) {
        R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RNLineMoveEnds", "an end is not finite; the line is kept");
        return -1;
    }
    memcpy(line->origin, origin, sizeof line->origin);
    memcpy(line->end, end, sizeof line->end);
    return 0;
}

void MEAPI RNLineSetColor(RNLine *line, const float color[4])
{
    if (!line || !color) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RNLineSetColor", "NULL line or colour");
        return;
    }
    if (!finiteColor(color)) {
        R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RNLineSetColor", "the colour is not finite");
        return;
    }
    memcpy(line->color, color, sizeof line->color);
}

/* Whether line may be listed in rc: both given, and the line rc's. */
static int ownLine(RRender *rc, RNLine *line, const char *fn)
{
    if (!RBothGiven(rc, line, fn, "line"))
        return 0;
    if (line->rc != rc) {
        R_REPORT(ME_ERR_FOREIGN_HANDLE, fn, "the line belongs to another render context");
        return 0;
    }
    return 1;
}

void MEAPI RNLineAddToList(RRender *rc, RNLine *line)
{
    if (ownLine(rc, line, "RNLineAddToList"))
        line->listed = 1;
}

void MEAPI RNLineRemoveFromList(RRender *rc, RNLine *line)
{
    if (ownLine(rc, line, "RNLineRemoveFromList"))
        line->listed = 0;
}

void MEAPI RNLineDestroy(RNLine *line)
{
    if (!line)
        return;
    RNLine **at = &line->rc->m_private->nlines;
    while (*at && *at != line)
        at = &(*at)->next;
    if (*at)
        *at = line->next;
    free(line);
}

void MEAPI RNLineDelete(RRender *rc, RNLine *line)
{
    if (ownLine(rc, line, "RNLineDelete"))
        RNLineDestroy(line);
}

/* Room for `more` ends in the buffer of *capacity ends. */
static int reserve(float **ends, int *capacity, int used, int more)
{
    if (used + more <= *capacity)
        return 1;
    int n = *capacity ? *capacity : 64;
    while (n < used + more)
        n *= 2;
    float *bigger = realloc(*ends, sizeof(float) * R_LINE_FLOATS * (size_t)n);
    if (!bigger)
        return 0;
    *ends = bigger;
    *capacity = n;
    return 1;
}

static void writeEnd(float *e, const AcmeReal p[3], const float color[4])
{
    e[0] = (float)p[0], e[1] = (float)p[1], e[2] = (float)p[2];
    memcpy(e + 3, color, 4 * sizeof(float));
}

void MEAPI RLineAdd(RRender *rc, MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b)
{
    if (!rc || !start || !end) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RLineAdd", "NULL render context or end");
        return;
    }
    if (!finite3(start) || !finite3(end) || !isfinite(r) || !isfinite(g) || !isfinite(b)) {
        R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RLineAdd", "an end or the colour is not finite");
        return;
    }
    struct RRenderPrivate *p = rc->m_private;
    if (!reserve(&p->immediate, &p->immediateCapacity, p->immediateEnds, 2)) {
        R_REPORT(ME_ERR_OUT_OF_MEMORY, "RLineAdd", "no memory for another line");
        return;
    }
    const float color[4] = {(float)r, (float)g, (float)b, 1};
    writeEnd(p->immediate + R_LINE_FLOATS * p->immediateEnds, start, color);
    writeEnd(p->immediate + R_LINE_FLOATS * (p->immediateEnds + 1), end, color);
    p->immediateEnds += 2;
}

void MEAPI RLineRemoveAll(RRender *rc)
{
    if (rc)
        rc->m_private->immediateEnds = 0;
}

/* p·M for a point local to Karma's row-vector matrix m. */
static void transform(const MeReal (*m)[4], const AcmeReal p[3], AcmeReal out[3])
{
    for (int j = 0; j < 3; j++)
        out[j] = p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j];
}

int RNLineGather(RRender *rc, float **ends, int *capacity)
{
    struct RRenderPrivate *p = rc->m_private;
    int used = 0;
    for (RNLine *line = p->nlines; line; line = line->next) {
        if (!line->listed)
            continue;
        if (!reserve(ends, capacity, used, 2))
            return -1;
        AcmeReal a[3], b[3];
        if (line->matrix) {
            transform((const MeReal(*)[4])line->matrix, line->origin, a);
            transform((const MeReal(*)[4])line->matrix, line->end, b);
        } else {
            memcpy(a, line->origin, sizeof a);
            memcpy(b, line->end, sizeof b);
        }
        writeEnd(*ends + R_LINE_FLOATS * used, a, line->color);
        writeEnd(*ends + R_LINE_FLOATS * (used + 1), b, line->color);
        used += 2;
    }
    if (p->immediateEnds > 0) {
        if (!reserve(ends, capacity, used, p->immediateEnds))
            return -1;
        memcpy(*ends + R_LINE_FLOATS * used, p->immediate, sizeof(float) * R_LINE_FLOATS * (size_t)p->immediateEnds);
        used += p->immediateEnds;
    }
    return used;
}

void RNLineContextGone(RRender *rc)
{
    struct RRenderPrivate *p = rc->m_private;
    while (p->nlines) {
        RNLine *next = p->nlines->next;
        free(p->nlines);
        p->nlines = next;
    }
    free(p->immediate);
    p->immediate = NULL;
    p->immediateEnds = p->immediateCapacity = 0;
}
