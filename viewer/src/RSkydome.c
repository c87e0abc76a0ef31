/* RSkydome.c -- Karma's skydome: a textured sphere around the camera, far away but inside the far
 * plane, drawn unlit and casting no shadow; RGL.c centres it on the camera each frame. Its poles
 * are on y, Karma's demos' up. */
#include "RInternal.h"

/** Radius of the sky's sphere (m): inside the far plane (500) wherever the camera looks. */
#define R_SKY_RADIUS 400

void MEAPI RRenderSkydomeCreate(RRender *const rc, const char *name, int tileU, int tileV)
{
    if (!rc || !name) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RRenderSkydomeCreate", "NULL %s", rc ? "texture name" : "render context");
        return;
    }
    if (tileU < 1 || tileV < 1) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RRenderSkydomeCreate", "tiles %d x %d: each must be 1 or more", tileU, tileV);
        return;
    }
    int texture = RRenderTextureCreate(rc, name); /* reports an unreadable file */
    if (texture < 0)
        return;
    const float white[4] = {1, 1, 1, 1};
    RGraphic *sky = RGraphicSphereCreate(rc, R_SKY_RADIUS, white, NULL);
    if (!sky)
        return;
    struct RGraphicPrivate *p = sky->m_private;
    for (int k = 0; k < R_LOD_LEVELS; k++) { /* always large on the picture: no coarser copies */
        RGraphicDestroy(p->lod[k]);
        p->lod[k] = NULL;
    }
    for (int i = 0; i < sky->m_pObject->m_nNumVertices; i++) {
        sky->m_pVertices[i].m_U *= (AcmeReal)tileU;
        sky->m_pVertices[i].m_V *= (AcmeReal)tileV;
    }
    p->unlit = 1;
    sky->m_pObject->m_nTextureID = texture;
    MeReal(*m)[4] = sky->m_pObject->m_Matrix; /* local z (the poles) to y, local y to −z */
    m[1][1] = 0, m[1][2] = -1, m[2][1] = 1, m[2][2] = 0;
    if (rc->m_private->skydome)
        RGraphicDelete(rc, rc->m_private->skydome, 0);
    rc->m_private->skydome = sky;
}
