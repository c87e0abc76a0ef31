/* RGraphicFile.c -- Karma 1.2's object files (.meg): RGraphicLoadMEG, RGraphicSave, RGraphicCreate
 * (load, normalise, scale, list) and RGraphicNormalize.
 *
 * The text format as 1.2's reader takes it: a number is the text from a ':' to the next white space
 * ("label:number"); words without ':' are labels and are skipped. The first number is the vertex
 * count (a positive multiple of 3: a triangle list), then each vertex is 8 numbers: position,
 * normal, texture coordinates. Unlike 1.2's reader (atof, which reads garbage as 0, and stops at the
 * count), a number that is not wholly a finite number, or a file with fewer or more numbers than the
 * count says, is refused with ME_ERR_VIEWER_BAD_MEG. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "RInternal.h"

/** Numbers a vertex has in a .meg file. */
#define R_MEG_VERTEX_NUMBERS 8

/** The whole file as a NUL-terminated string of *size bytes (NULL when it cannot be read; caller
 *  frees). */
static char *readWholeFile(const char *filename, size_t *sizeOut)
{
    FILE *f = fopen(filename, "rb");
    if (!f)
        return NULL;
    size_t size = 0, cap = 4096;
    char *buf = malloc(cap);
    while (buf) {
        size += fread(buf + size, 1, cap - size - 1, f);
        if (size < cap - 1)
            break;
        char *bigger = realloc(buf, cap * 2);
        if (!bigger)
            free(buf);
        buf = bigger, cap *= 2;
    }
    int failed = ferror(f);
    fclose(f);
    if (buf && failed) {
        free(buf);
        return NULL;
    }
    if (buf)
        buf[size] = '\0';
    *sizeOut = size;
    return buf;
}

/** The next number of the file from *cursor (advanced past it): 1 with *value, 0 at the end, −1
 *  when the text after a ':' is not wholly a number (*cursor then at that text). */
static int nextNumber(const char **cursor, double *value)
{
    const char *s = *cursor;
    for (;;) {
        while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r' || *s == '\v' || *s == '\f')
            s++;
        if (!*s) {
            *cursor = s;
            return 0;
        }
        const char *end = s + strcspn(s, " \t\n\r\v\f");
        const char *colon = memchr(s, ':', (size_t)(end - s));
        if (!colon) { /* a label */
            s = end;
            continue;
        }
        char *stop;
        errno = 0;
        *value = strtod(colon + 1, &stop);
        if (stop == colon + 1 || stop != end) {
            *cursor = colon + 1;
            return -1;
        }
        *cursor = end;
        return 1;
    }
}

/** Report a bad file with the byte offset of the trouble and return NULL. */
static RGraphic *badFile(const char *fn, const char *filename, const char *text, const char *at, const char *why)
{
    R_REPORT(ME_ERR_VIEWER_BAD_MEG, fn, "'%s' (byte %ld): %s; no graphic made", filename, (long)(at - text), why);
    return NULL;
}

/** Parse a .meg file's text into a new graphic (no list), or NULL with a message. */
static RGraphic *parseMEG(const char *fn, const char *filename, const char *text)
{
    const char *cur = text;
    double count;
    int got = nextNumber(&cur, &count);
    if (got <= 0)
        return badFile(fn, filename, text, cur, got == 0 ? "no vertex count" : "the vertex count is not a number");
    if (!(count >= 3 && count <= (double)(INT32_MAX / 2) && count == floor(count) && fmod(count, 3) == 0))
        return badFile(fn, filename, text, cur, "the vertex count is not a positive whole multiple of 3");
    const int n = (int)count;
    /* Count the numbers before allocating, so a count the file does not back costs nothing. */
    const char *body = cur;
    long numbers = 0, want = (long)n * R_MEG_VERTEX_NUMBERS;
    double v;
    while ((got = nextNumber(&cur, &v)) == 1) {
        if (!isfinite((AcmeReal)v))
            return badFile(fn, filename, text, cur, "a number is not finite (or is out of range)");
        if (++numbers > want)
            return badFile(fn, filename, text, cur, "more numbers than the vertex count says");
    }
    if (got < 0)
        return badFile(fn, filename, text, cur, "text after ':' is not a number");
    if (numbers < want) {
        char why[128];
        snprintf(why, sizeof why, "%ld numbers for %d vertices of 8 (truncated?)", numbers, n);
        return badFile(fn, filename, text, cur, why);
    }
    RGraphic *rg = RGraphicCreateEmpty(n);
    if (!rg) {
        R_REPORT(ME_ERR_OUT_OF_MEMORY, fn, "no memory for %d vertices of '%s'", n, filename);
        return NULL;
    }
    cur = body;
    for (int i = 0; i < n; i++) {
        double x[R_MEG_VERTEX_NUMBERS];
        for (int k = 0; k < R_MEG_VERTEX_NUMBERS; k++)
            nextNumber(&cur, &x[k]);
        RObjectVertex *p = &rg->m_pVertices[i];
        p->m_X = (AcmeReal)x[0], p->m_Y = (AcmeReal)x[1], p->m_Z = (AcmeReal)x[2];
        p->m_NX = (AcmeReal)x[3], p->m_NY = (AcmeReal)x[4], p->m_NZ = (AcmeReal)x[5];
        p->m_U = (AcmeReal)x[6], p->m_V = (AcmeReal)x[7];
    }
    return rg;
}

/** Read and parse a .meg file for API function `fn` (messages name it): a graphic in no list, or NULL. */
static RGraphic *loadMEG(const char *fn, const char *filename)
{
    if (!filename || !*filename) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, fn, "NULL or empty file name");
        return NULL;
    }
    size_t size = 0;
    char *text = readWholeFile(filename, &size);
    if (!text) {
        R_REPORT(ME_ERR_VIEWER_BAD_MEG, fn, "cannot read '%s': %s", filename, strerror(errno));
        return NULL;
    }
    /* A NUL byte would end the text early: a binary file, not 1.2's text. */
    RGraphic *rg = strlen(text) == size ? parseMEG(fn, filename, text)
                                        : badFile(fn, filename, text, text + strlen(text), "a NUL byte: not a text file");
    free(text);
    return rg;
}

RGraphic *MEAPI RGraphicLoadMEG(char *filename)
{
    return loadMEG("RGraphicLoadMEG", filename);
}

int MEAPI RGraphicSave(RGraphic *rg, char *filename)
{
    if (!rg || !filename || !*filename) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicSave", "NULL graphic or file name");
        return -1;
    }
    const int n = rg->m_pObject->m_nNumVertices;
    if (rg->m_private->kind != kRKindTriangles || n <= 0 || n % 3 != 0) {
        R_REPORT(ME_ERR_WRONG_HANDLE_KIND, "RGraphicSave", "only a triangle list saves (this graphic: %d vertices)", n);
        return -1;
    }
    FILE *f = fopen(filename, "w");
    if (!f) {
        R_REPORT(ME_ERR_VIEWER_BAD_MEG, "RGraphicSave", "cannot write '%s': %s", filename, strerror(errno));
        return -1;
    }
    /* Enough digits that reading back gives the same AcmeReal; a space after every number, as
     * 1.2's reader ends a number only at a space. */
    const int digits = sizeof(AcmeReal) == sizeof(float) ? 9 : 17;
    fprintf(f, "Vertices:%d \n", n);
    for (int i = 0; i < n; i++) {
        const RObjectVertex *p = &rg->m_pVertices[i];
        fprintf(f, "X:%.*g Y:%.*g Z:%.*g NX:%.*g NY:%.*g NZ:%.*g U:%.*g V:%.*g \n", digits, (double)p->m_X, digits,
                (double)p->m_Y, digits, (double)p->m_Z, digits, (double)p->m_NX, digits, (double)p->m_NY, digits,
                (double)p->m_NZ, digits, (double)p->m_U, digits, (double)p->m_V);
    }
    int failed = ferror(f);
    failed |= fclose(f) != 0;
    if (failed) {
        R_REPORT(ME_ERR_VIEWER_BAD_MEG, "RGraphicSave", "writing '%s' failed", filename);
        return -1;
    }
    return 0;
}

void MEAPI RGraphicNormalize(RGraphic *rg, int bKeepAspectRatio)
{
    if (!rg) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicNormalize", "NULL graphic");
        return;
    }
    const int n = rg->m_pObject->m_nNumVertices;
    if (n <= 0)
        return;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < n; i++) {
        const RObjectVertex *p = &rg->m_pVertices[i];
        const double x[3] = {p->m_X, p->m_Y, p->m_Z};
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], x[k]), hi[k] = fmax(hi[k], x[k]);
    }
    for (int k = 0; k < 3; k++)
        if (!isfinite(lo[k]) || !isfinite(hi[k])) {
            R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RGraphicNormalize", "a vertex is not finite; nothing changed");
            return;
        }
    /* Centre the bounding box on the origin, then fit it to [-1, 1] on each axis (keeping the
     * aspect ratio: the longest axis to [-1, 1], the others in proportion). A flat axis is left. */
    MeVector3 centre;
    double half[3], longest = 0;
    for (int k = 0; k < 3; k++) {
        centre[k] = (MeReal)(-0.5 * (lo[k] + hi[k]));
        half[k] = 0.5 * (hi[k] - lo[k]);
        longest = fmax(longest, half[k]);
    }
    RGraphicTranslateVertices(NULL, rg, centre);
    if (longest <= 0)
        return;
    AcmeReal s[3];
    for (int k = 0; k < 3; k++)
        s[k] = (AcmeReal)(bKeepAspectRatio ? 1 / longest : half[k] > 0 ? 1 / half[k] : 1);
    RGraphicScale(rg, s[0], s[1], s[2]);
}

/* Size: Karma 1.2's signature. */
RGraphic *MEAPI RGraphicCreate(RRender *rc, char *filename, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale,
                               const float color[4], MeMatrix4Ptr matrix, int is2D, int bKeepAspectRatio)
{
    if (!rc) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicCreate", "NULL render context");
        return NULL;
    }
    const double s[3] = {xScale, yScale, zScale};
    for (int k = 0; k < 3; k++)
        if (!(isfinite(s[k]) && s[k] != 0)) {
            R_REPORT(ME_ERR_ARGUMENT_RANGE, "RGraphicCreate", "scale (%g, %g, %g): each must be finite and not 0", s[0],
                     s[1], s[2]);
            return NULL;
        }
    RGraphic *rg = loadMEG("RGraphicCreate", filename);
    if (!rg)
        return NULL;
    if (color)
        RGraphicSetColor(rg, color);
    rg->m_pLWMatrix = matrix;
    if (!is2D)
        RGraphicNormalize(rg, bKeepAspectRatio);
    RGraphicScale(rg, xScale, yScale, zScale);
    RGraphicAddToList(rc, rg, is2D);
    return rg;
}
