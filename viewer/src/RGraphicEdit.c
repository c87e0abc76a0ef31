/* RGraphicEdit.c -- changing a graphic's vertices as 1.2's helpers do: RGraphicTranslateVertices
 * (a scene loader's offset of a mesh) and RGraphicCombine (an aggregate's graphic built element by
 * element: one graphic holding both, the second placed by a relative transform). */
#include <math.h>
#include <string.h>

#include "RInternal.h"

void MEAPI RGraphicTranslateVertices(RRender *rc, RGraphic *rg, MeVector3 offset)
{
    (void)rc; /* as 1.2's: the vertices are the graphic's own */
    if (!rg || !offset) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicTranslateVertices", "NULL graphic or offset");
        return;
    }
    if (!isfinite(offset[0]) || !isfinite(offset[1]) || !isfinite(offset[2])) {
        R_REPORT(ME_ERR_NONFINITE_ARGUMENT, "RGraphicTranslateVertices", "the offset is not finite");
        return;
    }
    for (int i = 0; i < rg->m_pObject->m_nNumVertices; i++) {
        RObjectVertex *v = &rg->m_pVertices[i];
        v->m_X += offset[0], v->m_Y += offset[1], v->m_Z += offset[2];
    }
    rg->m_private->dirty = 1;
}

RGraphic *MEAPI RGraphicCombine(RRender *rc, RGraphic *first, RGraphic *second, MeMatrix4Ptr secondTM)
{
    if (!rc || !first || !second) {
        R_REPORT(ME_ERR_NULL_ARGUMENT, "RGraphicCombine", "NULL render context or graphic");
        return NULL;
    }
    if (first->m_private->kind != kRKindTriangles || second->m_private->kind != kRKindTriangles) {
        R_REPORT(ME_ERR_WRONG_HANDLE_KIND, "RGraphicCombine", "only triangle graphics combine");
        return NULL;
    }
    int n1 = first->m_pObject->m_nNumVertices, n2 = second->m_pObject->m_nNumVertices;
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, n1 + n2, first->m_pObject->m_ColorDiffuse, first->m_pLWMatrix);
    if (!rg)
        return NULL;
    /* The first's material, texture and drawing state; its vertices as they are. */
    RObjectHeader *h = rg->m_pObject;
    const RObjectHeader *f = first->m_pObject;
    memcpy(h->m_ColorAmbient, f->m_ColorAmbient, sizeof h->m_ColorAmbient);
    memcpy(h->m_ColorSpecular, f->m_ColorSpecular, sizeof h->m_ColorSpecular);
    memcpy(h->m_ColorEmissive, f->m_ColorEmissive, sizeof h->m_ColorEmissive);
    memcpy(h->m_Matrix, f->m_Matrix, sizeof h->m_Matrix);
    h->m_nTextureID = f->m_nTextureID, h->m_bIsWireFrame = f->m_bIsWireFrame, h->m_SpecularPower = f->m_SpecularPower;
    memcpy(rg->m_pVertices, first->m_pVertices, sizeof *rg->m_pVertices * (size_t)n1);
    /* The second's placed by secondTM (Karma's row-vector matrix: p·M; normals by its rotation). */
    for (int i = 0; i < n2; i++) {
        const RObjectVertex *s = &second->m_pVertices[i];
        RObjectVertex *v = &rg->m_pVertices[n1 + i];
        *v = *s;
        if (!secondTM)
            continue;
        const MeReal(*m)[4] = (const MeReal(*)[4])secondTM;
        const double p[3] = {s->m_X, s->m_Y, s->m_Z}, nn[3] = {s->m_NX, s->m_NY, s->m_NZ};
        double q[3], r[3];
        for (int j = 0; j < 3; j++) {
            q[j] = p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + m[3][j];
            r[j] = nn[0] * m[0][j] + nn[1] * m[1][j] + nn[2] * m[2][j];
        }
        v->m_X = (AcmeReal)q[0], v->m_Y = (AcmeReal)q[1], v->m_Z = (AcmeReal)q[2];
        v->m_NX = (AcmeReal)r[0], v->m_NY = (AcmeReal)r[1], v->m_NZ = (AcmeReal)r[2];
    }
    h->m_nNumVertices = n1 + n2;
    return rg;
}
