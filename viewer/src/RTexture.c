/* RTexture.c -- textures as Karma's: RRenderTextureCreate loads an image (BMP as Karma's
 * resources, PNG too; any format stb_image reads) by file name, Karma's way without the extension
 * (".bmp", then ".png" is tried), and RGraphicSetTexture puts it on a graphic, whose diffuse and
 * ambient colours it multiplies at the graphic's texture coordinates. The pixels are kept by the
 * context; each GL state uploads them when a graphic first uses them (RGL.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <stb_image.h>

#include "RInternal.h"

/* The image at `path`, as RGBA, or NULL. */
static unsigned char *load(const char *path, int *w, int *h)
{
    int channels;
    stbi_set_flip_vertically_on_load(1); /* v = 0 at the bottom row, as OpenGL and Karma's BMPs */
    return stbi_load(path, w, h, &channels, 4);
}

int MEAPI RRenderTextureCreate(RRender *rc, const char *filename)
{
    if (!rc || !filename || !*filename) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RRenderTextureCreate", "NULL render context or empty file name");
        return -1;
    }
    struct RRenderPrivate *p = rc->m_private;
    for (int i = 0; i < p->textureCount; i++)
        if (strcmp(p->textures[i].name, filename) == 0)
            return i;
    if (p->textureCount == R_MAX_TEXTURES) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderTextureCreate", "at most %d textures (as Karma); '%s' not loaded",
                 R_MAX_TEXTURES, filename);
        return -1;
    }
    int w = 0, h = 0;
    unsigned char *rgba = load(filename, &w, &h);
    const char *slash = strrchr(filename, '/'), *dot = strrchr(filename, '.');
    static const char *const extensions[] = {".bmp", ".png"};
    for (size_t k = 0; !rgba && (!dot || (slash && dot < slash)) && k < 2; k++) {
        char path[1024];
        snprintf(path, sizeof path, "%s%s", filename, extensions[k]);
        rgba = load(path, &w, &h);
    }
    if (!rgba) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderTextureCreate", "cannot read an image from '%s' (nor with .bmp or .png)",
                 filename);
        return -1;
    }
    RTexture *t = &p->textures[p->textureCount];
    snprintf(t->name, sizeof t->name, "%s", filename);
    t->width = w, t->height = h, t->rgba = rgba;
    return p->textureCount++;
}

int MEAPI RGraphicSetTexture(RRender *rc, RGraphic *rg, const char *filename)
{
    if (!rg) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicSetTexture", "NULL graphic");
        return -1;
    }
    int id = RRenderTextureCreate(rc, filename);
    if (id >= 0)
        rg->m_pObject->m_nTextureID = id;
    return id;
}

void RTexturesContextGone(RRender *rc)
{
    struct RRenderPrivate *p = rc->m_private;
    for (int i = 0; i < p->textureCount; i++)
        stbi_image_free(p->textures[i].rgba);
    p->textureCount = 0;
}
