/* viewer_two_colour_png.h -- a 2 × 1 PNG, left red, right blue, drawn and saved by the viewer itself
 * (two 2D rectangles on a 2 × 1 headless picture): a texture whose halves the tests can tell apart. */
#ifndef KARMA_VIEWER_TWO_COLOUR_PNG_H
#define KARMA_VIEWER_TWO_COLOUR_PNG_H

#include <MeViewer.h>

/** Write the picture to `path`; returns 0, or −1 when no headless context or file could be made. */
static inline int viewerWriteTwoColourPng(const char *path)
{
    RRender *small = RRenderContextCreateHeadless(2, 1);
    if (!small)
        return -1;
    const float red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
    RGraphic2DRectangleCreate(small, 0, 0, 320, 448, red);
    RGraphic2DRectangleCreate(small, 320, 0, 320, 448, blue);
    RRenderDrawFrame(small);
    int result = RRenderSavePNG(small, path);
    RRenderContextDestroy(small);
    return result;
}

#endif /* KARMA_VIEWER_TWO_COLOUR_PNG_H */
