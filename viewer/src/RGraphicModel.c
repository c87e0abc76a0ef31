/* RGraphicModel.c -- graphics from collision geometry: what the model collides with is what is drawn. */
#include <karma/Mcd.h>

#include "RInternal.h"

/** Side of the square drawn for an infinite plane (m). */
#define R_PLANE_SIDE 60
/** Its checkerboard cells (m): metres can be counted on the ground. */
#define R_PLANE_CELL 1.0f

RGraphic *MEAPI RGraphicCreateFromGeometry(RRender *rc, McdGeometryID g, float color[4], MeMatrix4Ptr matrix)
{
    if (!rc || !g) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicCreateFromGeometry", "NULL %s", rc ? "geometry" : "render context");
        return NULL;
    }
    int type = McdGeometryGetTypeId(g);
    if (type == McdSphereGetTypeId())
        return RGraphicSphereCreate(rc, McdSphereGetRadius(g), color, matrix);
    if (type == McdBoxGetTypeId()) {
        MeReal x, y, z;
        McdBoxGetDimensions(g, &x, &y, &z);
        return RGraphicBoxCreate(rc, x, y, z, color, matrix);
    }
    if (type == McdCylinderGetTypeId())
        return RGraphicCylinderCreate(rc, McdCylinderGetRadius(g), McdCylinderGetHeight(g), color, matrix);
    if (type == McdSphylGetTypeId())
        return RGraphicSphylCreate(rc, McdSphylGetRadius(g), McdSphylGetHeight(g), color, matrix);
    if (type == McdConeGetTypeId())
        return RGraphicFrustumCreate(rc, McdConeGetLowerRadius(g), McdConeGetUpperRadius(g), McdConeGetLowerZ(g),
                                     McdConeGetUpperZ(g), rc->m_sphereRes, color, matrix);
    if (type == McdPlaneGetTypeId()) {
        RGraphic *rg = RGraphicSquareCreate(rc, R_PLANE_SIDE, color, matrix);
        if (rg)
            rg->m_private->checkerCell = R_PLANE_CELL;
        return rg;
    }
    R_REPORT(ME_ERR_WRONG_HANDLE_KIND, "RGraphicCreateFromGeometry", "cannot draw a geometry of type %s",
             McdGeometryGetTypeName(g));
    return NULL;
}

RGraphic *MEAPI RGraphicCreateFromModel(RRender *rc, McdModelID m, float color[4])
{
    if (!m) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicCreateFromModel", "NULL model");
        return NULL;
    }
    return RGraphicCreateFromGeometry(rc, McdModelGetGeometry(m), color, McdModelGetTransformPtr(m));
}
