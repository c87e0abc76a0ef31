/* RConvex.c -- convex meshes drawn as their polygons: each polygon a fan of triangles with the
 * polygon's own normal, so the faces are flat and their edges sharp, as the hull collides. */
#include <karma/Mcd.h>
#include <karma/McdConvexMesh.h>

#include "RConvex.h"
#include "RInternal.h"

RGraphic *MEAPI RGraphicConvexCreate(RRender *const rc, const McdConvexMeshID conv, const float color[4],
                                     const MeMatrix4Ptr matrix)
{
    if (!rc || !conv) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicConvexCreate", "NULL %s", rc ? "convex mesh" : "render context");
        return NULL;
    }
    if (McdGeometryGetTypeId(conv) != McdConvexMeshGetTypeId()) {
        R_REPORT(ME_ERR_WRONG_HANDLE_KIND, "RGraphicConvexCreate", "a %s is not a convex mesh",
                 McdGeometryGetTypeName(conv));
        return NULL;
    }
    int polygons = McdConvexMeshGetPolygonCount(conv), triangles = 0;
    for (int i = 0; i < polygons; i++)
        triangles += McdConvexMeshGetPolygonVertexCount(conv, i) - 2;
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 3 * triangles, color, matrix);
    if (!rg)
        return NULL;
    RObjectVertex *out = rg->m_pVertices;
    for (int i = 0; i < polygons; i++) {
        MeVector3 n, v[3];
        McdConvexMeshGetPolygonNormal(conv, i, n);
        int count = McdConvexMeshGetPolygonVertexCount(conv, i);
        McdConvexMeshGetPolygonVertex(conv, i, 0, v[0]);
        for (int k = 1; k + 1 < count; k++) {
            McdConvexMeshGetPolygonVertex(conv, i, k, v[1]);
            McdConvexMeshGetPolygonVertex(conv, i, k + 1, v[2]);
            for (int c = 0; c < 3; c++, out++) {
                out->m_X = (AcmeReal)v[c][0], out->m_Y = (AcmeReal)v[c][1], out->m_Z = (AcmeReal)v[c][2];
                out->m_NX = (AcmeReal)n[0], out->m_NY = (AcmeReal)n[1], out->m_NZ = (AcmeReal)n[2];
                out->m_U = out->m_V = 0; /* as Karma's: no texture coordinates on hulls */
            }
        }
    }
    return rg;
}
