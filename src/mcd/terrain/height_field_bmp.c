/* height_field_bmp.c -- Karma's utility that makes heights from an image: an uncompressed 24-bit
 * BMP, one height per pixel from a weighted sum of its colour (McdRGHeightField.h). */
#include <stdio.h>
#include <stdint.h>

#include <karma/MeMemory.h>

#include "../../me/check.h"
#include "terrain.h"

/* Images larger than this on a side are refused (the grid's own limit). */
#define BMP_MAX_SIDE MCD_TERRAIN_MAX_GRID

static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static unsigned le16(const unsigned char *p) { return (unsigned)p[0] | (unsigned)p[1] << 8; }

/* A pixel's height: r, g and b times its red, green and blue (each 0 to 1), plus z0 (m). */
typedef struct ColourWeights {
    MeReal r, g, b, z0;
} ColourWeights;

/* Read the file's pixels into heights; returns 0 with a reason on failure. */
static int readBmp(FILE *f, const ColourWeights *weights, MeReal **out, int *nx, int *ny, const char **why)
{
    unsigned char h[54];
    if (fread(h, 1, sizeof h, f) != sizeof h || h[0] != 'B' || h[1] != 'M') {
        *why = "not a BMP file";
        return 0;
    }
    uint32_t offset = le32(h + 10), infoSize = le32(h + 14), compression = le32(h + 30);
    int32_t width = (int32_t)le32(h + 18), height = (int32_t)le32(h + 22);
    unsigned bpp = le16(h + 28);
    if (infoSize < 40 || bpp != 24 || compression != 0) {
        *why = "not an uncompressed 24-bit BMP";
        return 0;
    }
    int bottomUp = height > 0;
    int64_t rows = height > 0 ? (int64_t)height : -(int64_t)height;
    if (width < 2 || rows < 2 || width > BMP_MAX_SIDE || rows > BMP_MAX_SIDE) {
        *why = "the image must be 2 to 65536 pixels on each side";
        return 0;
    }
    size_t stride = ((size_t)width * 3 + 3) & ~(size_t)3;
    unsigned char *row = MeMemoryCreate(stride);
    MeReal *heights = MeMemoryCreate((size_t)width * (size_t)rows * sizeof *heights);
    if (!row || !heights || fseek(f, (long)offset, SEEK_SET) != 0) {
        MeMemoryDestroy(row);
        MeMemoryDestroy(heights);
        *why = "the pixels cannot be read";
        return 0;
    }
    for (int64_t r = 0; r < rows; r++) {
        if (fread(row, 1, stride, f) != stride) {
            MeMemoryDestroy(row);
            MeMemoryDestroy(heights);
            *why = "the file ends inside the pixels";
            return 0;
        }
        int64_t iy = bottomUp ? r : rows - 1 - r; /* row 0 of the heights is the bottom of the image */
        for (int32_t ix = 0; ix < width; ix++) {
            const unsigned char *px = row + 3 * (size_t)ix; /* blue, green, red */
            heights[(size_t)iy * (size_t)width + (size_t)ix] =
                weights->r * (MeReal)px[2] / ME_R(255.0) + weights->g * (MeReal)px[1] / ME_R(255.0) +
                weights->b * (MeReal)px[0] / ME_R(255.0) + weights->z0;
        }
    }
    MeMemoryDestroy(row);
    *out = heights;
    *nx = (int)width;
    *ny = (int)rows;
    return 1;
}

/* Size: Karma 1.2's signature. */
int McduRGHeighFieldCreateHeightMatrixFromBmp(char *filename, MeReal rMult, MeReal gMult, MeReal bMult, MeReal z0,
                                              MeReal **outHeightMatrix, int *outXsize, int *outYsize)
{
    ME_CHECK_NOT_NULL(filename, 0);
    ME_CHECK_NOT_NULL(outHeightMatrix, 0);
    ME_CHECK_NOT_NULL(outXsize, 0);
    ME_CHECK_NOT_NULL(outYsize, 0);
    ME_CHECK_FINITE(rMult, 0);
    ME_CHECK_FINITE(gMult, 0);
    ME_CHECK_FINITE(bMult, 0);
    ME_CHECK_FINITE(z0, 0);
    FILE *f = fopen(filename, "rb");
    const char *why = "it cannot be opened";
    const ColourWeights weights = {rMult, gMult, bMult, z0};
    int ok = f && readBmp(f, &weights, outHeightMatrix, outXsize, outYsize, &why);
    if (f)
        fclose(f);
    if (!ok)
        ME_REPORT(ME_ERR_MCD_BAD_IMAGE, "'%s': %s; no heights made", filename, why);
    return ok;
}

/* Size: Karma 1.2's signature. */
McdRGHeightFieldID McduRGHeighFieldCreateFromBmp(McdFrameworkID fw, char *bmpFileName, MeReal x0, MeReal y0,
                                                 MeReal xSize, MeReal ySize, MeReal rMult, MeReal gMult, MeReal bMult,
                                                 MeReal z0)
{
    MeReal *heights;
    int nx, ny;
    if (!McduRGHeighFieldCreateHeightMatrixFromBmp(bmpFileName, rMult, gMult, bMult, z0, &heights, &nx, &ny))
        return NULL;
    McdRGHeightFieldID g = McdRGHeightFieldCreate(fw, heights, nx, ny, xSize / (MeReal)(nx - 1),
                                                  ySize / (MeReal)(ny - 1), x0, y0);
    MeMemoryDestroy(heights);
    return g;
}
