/* RGraphicTerrain.c -- terrain geometries drawn as the triangles they collide with: a triangle
 * mesh's triangles and a height field's cells (two triangles each, split as Mcd splits them), each
 * triangle flat with its own normal. A triangle list is made by its generator callback for each
 * query box, so it has no triangles of its own to draw. */
#include <math.h>

#include <karma/MeMath.h>
#include <karma/McdRGHeightField.h>
#include <karma/McdTriangleMesh.h>

#include "RInternal.h"

/* Write triangle (a, b, c), counter-clockwise seen from its front, with its normal; degenerate ones
 * get +z. */
static RObjectVertex *triangle(RObjectVertex *out, const MeReal *a, const MeReal *b, const MeReal *c)
{
    double e1[3], e2[3], n[3];
    for (int k = 0; k < 3; k++)
        e1[k] = (double)b[k] - a[k], e2[k] = (double)c[k] - a[k];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (l > 0)
        n[0] /= l, n[1] /= l, n[2] /= l;
    else
        n[0] = n[1] = 0, n[2] = 1;
    const MeReal *v[3] = {a, b, c};
    for (int i = 0; i < 3; i++, out++) {
        out->m_X = (AcmeReal)v[i][0], out->m_Y = (AcmeReal)v[i][1], out->m_Z = (AcmeReal)v[i][2];
        out->m_NX = (AcmeReal)n[0], out->m_NY = (AcmeReal)n[1], out->m_NZ = (AcmeReal)n[2];
        out->m_U = (AcmeReal)v[i][0], out->m_V = (AcmeReal)v[i][1]; /* a texture tiles once a metre */
    }
    return out;
}

RGraphic *RGraphicTriangleMeshCreate(RRender *rc, McdGeometryID g, const float color[4], MeMatrix4Ptr matrix)
{
    int n = McdTriangleMeshGetTriangleCount(g);
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 3 * n, color, matrix);
    if (!rg)
        return NULL;
    RObjectVertex *out = rg->m_pVertices;
    for (int i = 0; i < n; i++) {
        MeVector3 a, b, c;
        int flags;
        if (McdTriangleMeshGetTriangle(g, i, a, b, c, &flags))
            out = triangle(out, a, b, c);
    }
    rg->m_pObject->m_nNumVertices = (int)(out - rg->m_pVertices);
    return rg;
}

RGraphic *RGraphicHeightFieldCreate(RRender *rc, McdGeometryID g, const float color[4], MeMatrix4Ptr matrix)
{
    MeReal *h, dx, dy, x0, y0;
    int nx, ny;
    McdRGHeightFieldGetParameters(g, &h, &nx, &ny, &dx, &dy, &x0, &y0);
    if (!h || nx < 2 || ny < 2)
        return NULL;
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 6 * (nx - 1) * (ny - 1), color, matrix);
    if (!rg)
        return NULL;
    RObjectVertex *out = rg->m_pVertices;
    for (int iy = 0; iy + 1 < ny; iy++)
        for (int ix = 0; ix + 1 < nx; ix++) {
            MeVector3 p[2][2]; /* p[j][i]: vertex (ix + i, iy + j) */
            for (int j = 0; j < 2; j++)
                for (int i = 0; i < 2; i++)
                    MeVector3Set(p[j][i], x0 + (MeReal)(ix + i) * dx, y0 + (MeReal)(iy + j) * dy,
                                 h[(size_t)(iy + j) * (size_t)nx + (size_t)(ix + i)]);
            /* Mcd's split: lower (00, 10, 11), upper (00, 11, 01). */
            out = triangle(out, p[0][0], p[0][1], p[1][1]);
            out = triangle(out, p[0][0], p[1][1], p[1][0]);
        }
    return rg;
}
