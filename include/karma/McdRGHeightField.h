/* McdRGHeightField.h -- a regular-grid height field (Karma 1.2's predecessors' McdRGHeightField).
 *
 * Heights are along local z (Mcd's shape axis, as the plane's normal): vertex (ix, iy) lies at
 * (x0 + ix xIncrement, y0 + iy yIncrement, heightArray[iy * xVertexCount + ix]). Each cell is two
 * triangles split along its (ix, iy)-(ix+1, iy+1) diagonal; the solid is below the surface (the
 * triangles push along their upward normals only). In a y-up scene turn the model as a plane
 * (-pi/2 about x: local z becomes world y, local y world -z). The heights are copied.
 * Holes: McdRGHeightFieldSetHoles marks cells with no triangles. Internal edges that are flat or
 * concave never give contact normals (no snagging); edges at the border or at a hole do. A contact's
 * element2 is the triangle's number, 2 (iy (xVertexCount - 1) + ix) + (0 lower, 1 upper), cast to a
 * pointer. Height fields are static: no mass, no support point. */
#ifndef MCD_RG_HEIGHT_FIELD_H
#define MCD_RG_HEIGHT_FIELD_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdRGHeightFieldID;

/** A height field of xVertexCount by yVertexCount vertices (each 2 ... 65536), spacing xIncrement
 *  and yIncrement (> 0, within the size range), first vertex at (x0, y0); heightArray holds
 *  xVertexCount * yVertexCount finite heights (row after row of x). NULL (reported) otherwise. */
ME_API McdRGHeightFieldID McdRGHeightFieldCreate(McdFrameworkID fw, MeReal *heightArray, int xVertexCount,
                                                 int yVertexCount, MeReal xIncrement, MeReal yIncrement,
                                                 MeReal x0, MeReal y0);
/** The parameters: heightArray points to the field's own copy (valid until it is destroyed). */
ME_API void McdRGHeightFieldGetParameters(McdRGHeightFieldID g, MeReal **heightArray, int *xVertexCount,
                                          int *yVertexCount, MeReal *xIncrement, MeReal *yIncrement, MeReal *x0,
                                          MeReal *y0);
/** Mark holes: holes[iy * (xVertexCount - 1) + ix] non-zero removes cell (ix, iy); NULL removes every
 *  hole. Copied; edges next to a hole are in use from then on (an addition to Karma). */
ME_API void McdRGHeightFieldSetHoles(McdRGHeightFieldID g, const unsigned char *holes);
/** Karma's utility (its spelling): read an uncompressed 24-bit BMP into heights, one per pixel,
 *  rMult r + gMult g + bMult b + z0 with r, g, b in [0, 1]; row 0 is the image's bottom row. On
 *  success returns non-zero and *outHeightMatrix (free it with MeMemoryDestroy), *outXsize and
 *  *outYsize (pixels); 0 (ME_ERR_MCD_BAD_IMAGE) for a file that cannot be read or another format. */
ME_API int McduRGHeighFieldCreateHeightMatrixFromBmp(char *filename, MeReal rMult, MeReal gMult, MeReal bMult,
                                                     MeReal z0, MeReal **outHeightMatrix, int *outXsize,
                                                     int *outYsize);
/** Karma's utility: a height field from a BMP (as above) spanning xSize by ySize metres from the
 *  corner (x0, y0); NULL (reported) when the image or the sizes are refused. */
ME_API McdRGHeightFieldID McduRGHeighFieldCreateFromBmp(McdFrameworkID fw, char *bmpFileName, MeReal x0, MeReal y0,
                                                        MeReal xSize, MeReal ySize, MeReal rMult, MeReal gMult,
                                                        MeReal bMult, MeReal z0);
/** The height field's type number (kMcdGeometryTypeRGHeightField). */
ME_API MeI16 McdRGHeightFieldGetTypeId(void);

ME_EXTERN_C_END

#endif /* MCD_RG_HEIGHT_FIELD_H */
