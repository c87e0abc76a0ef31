/* RParticles.c -- Karma 1.2's particle systems: an application's array of positions drawn as
 * camera-facing discs (RGLNative.c draws a system's particles in one instanced draw). The context's
 * list is the order they are drawn in. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "RInternal.h"

RParticleSystem *MEAPI RParticleSystemNew(int numParticles, MeVector3 *positions, int tex_id, const float color[4],
                                          AcmeReal size)
{
    if (numParticles < 0 || !(size > 0) || !isfinite(size)) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RParticleSystemNew", "%d particles of size %g: the count must be >= 0 and "
                 "the size finite and > 0", numParticles, (double)size);
        return NULL;
    }
    if ((numParticles > 0 && !positions) || !color) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RParticleSystemNew", "NULL positions or colour");
        return NULL;
    }
    RParticleSystem *ps = RZeroedOrReport(sizeof *ps, "RParticleSystemNew", "a particle system");
    if (!ps)
        return NULL;
    /* As 1.2: the colour is the ambient one; diffuse, specular and emissive black, the alpha kept. */
    memcpy(ps->m_rgbAmbient, color, sizeof ps->m_rgbAmbient);
    ps->m_rgbDiffuse[3] = ps->m_rgbSpecular[3] = ps->m_rgbEmissive[3] = color[3];
    ps->m_TriangleSize = size;
    ps->m_Positions = positions;
    ps->m_nNumParticles = numParticles;
    ps->m_nTextureID = tex_id < 0 ? -1 : tex_id;
    return ps;
}

RParticleSystem *MEAPI RParticleSystemCreate(RRender *rc, int numParticles, MeVector3 *positions, char *tex_filename,
                                             const float color[4], AcmeReal tri_size)
{
    if (!rc) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RParticleSystemCreate", "NULL render context");
        return NULL;
    }
    int texture = -1;
    if (tex_filename && (texture = RRenderTextureCreate(rc, tex_filename)) < 0)
        return NULL; /* reported by RRenderTextureCreate */
    RParticleSystem *ps = RParticleSystemNew(numParticles, positions, texture, color, tri_size);
    if (ps)
        RParticleSystemAddToList(rc, ps);
    return ps;
}

/* Take ps out of the list of the context holding it (nothing when none does). */
static void unlink(RParticleSystem *ps)
{
    if (!ps->m_pRender)
        return;
    RParticleSystem **at = &ps->m_pRender->m_private->particles;
    while (*at && *at != ps)
        at = &(*at)->m_pNextSystem;
    if (*at)
        *at = ps->m_pNextSystem;
    ps->m_pNextSystem = NULL;
    ps->m_pRender = NULL;
}

void MEAPI RParticleSystemAddToList(RRender *rc, RParticleSystem *ps)
{
    if (!RBothGiven(rc, ps, "RParticleSystemAddToList", "particle system"))
        return;
    if (ps->m_pRender == rc)
        return; /* listed already */
    if (ps->m_pRender) {
        R_REPORT(ME_ERR_FOREIGN_HANDLE, "RParticleSystemAddToList", "the system is in another context's list");
        return;
    }
    RParticleSystem **at = &rc->m_private->particles;
    while (*at)
        at = &(*at)->m_pNextSystem;
    *at = ps;
    ps->m_pNextSystem = NULL;
    ps->m_pRender = rc;
}

void MEAPI RParticleSystemRemoveFromList(RRender *rc, RParticleSystem *ps)
{
    if (!RBothGiven(rc, ps, "RParticleSystemRemoveFromList", "particle system"))
        return;
    if (ps->m_pRender == rc)
        unlink(ps);
}

void MEAPI RParticleSystemDestroy(RParticleSystem *ps)
{
    if (!ps)
        return;
    unlink(ps);
    free(ps);
}

void RParticlesContextGone(RRender *rc)
{
    while (rc->m_private->particles)
        RParticleSystemDestroy(rc->m_private->particles);
}
