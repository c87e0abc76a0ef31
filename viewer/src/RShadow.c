/* RShadow.c -- shadows from Karma's key light (directional light 1): a depth map drawn from the
 * light, orthographic, over the region the camera looks at, which the lit program samples with
 * percentage-closer filtering (RGL.c). Every triangle graphic casts but checkerboard planes
 * (the ground), which only receive. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <epoxy/gl.h>

#include "RInternal.h"

/** Texels along each side of the shadow map. */
#define R_SHADOW_SIZE 1024
/** The region shadowed reaches at most this many camera distances from the look-at point, so a few
 *  bodies far away (balls parked before they are shot) do not spread the map's texels thin. */
#define R_SHADOW_REACH 2.0

static const char *const vertexDepth =
    "#version 330 core\n"
    "layout(location = 0) in vec3 aPos;\n"
    "layout(location = 2) in mat4 aModel;\n"
    "uniform mat4 uLightVP;\n"
    "void main() { gl_Position = uLightVP * aModel * vec4(aPos, 1.0); }\n";

static const char *const fragmentDepth =
    "#version 330 core\n"
    "void main() { }\n";

struct RShadow {
    GLuint prog, fbo, depth;
    GLint uLightVP;
    float lightVP[16]; /* column-major, world to the light's clip space */
    float texelWorld;  /* side of one texel in the world (m) */
    int valid;         /* lightVP describes the last map drawn */
};

struct RShadow *RShadowCreate(void)
{
    struct RShadow *s = calloc(1, sizeof *s);
    if (!s)
        return NULL;
    s->prog = (GLuint)RGLLink(vertexDepth, fragmentDepth);
    s->uLightVP = glGetUniformLocation(s->prog, "uLightVP");
    glGenTextures(1, &s->depth);
    glBindTexture(GL_TEXTURE_2D, s->depth);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, R_SHADOW_SIZE, R_SHADOW_SIZE, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    /* Hardware comparison with bilinear weights: each tap is already a 2 × 2 percentage-closer filter. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glGenFramebuffers(1, &s->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, s->fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, s->depth, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    int complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!s->prog || !complete) {
        RShadowDestroy(s);
        return NULL;
    }
    return s;
}

void RShadowDestroy(struct RShadow *s)
{
    if (!s)
        return;
    glDeleteProgram(s->prog);
    glDeleteFramebuffers(1, &s->fbo);
    glDeleteTextures(1, &s->depth);
    free(s);
}

int RShadowCasts(const RGraphic *rg, const RRender *rc)
{
    const struct RGraphicPrivate *p = rg->m_private;
    return p->kind == kRKindTriangles && !p->unlit && p->checkerCell <= 0 && !rg->m_pObject->m_bIsWireFrame &&
           !rc->m_options.m_bWireFrame;
}

/* The sphere the map covers: about the look-at point, out to the farthest caster within reach. */
static double regionRadius(const RRender *rc)
{
    const AcmeReal *L = rc->m_CameraLookAt;
    double reach = R_SHADOW_REACH * rc->m_CameraDist, radius = 1;
    for (const RGraphic *rg = rc->m_pRG_First; rg; rg = rg->m_pNext) {
        if (!RShadowCasts(rg, rc))
            continue;
        const MeReal(*m)[4] = (const MeReal(*)[4])rg->m_pObject->m_Matrix;
        double d[3] = {m[3][0] - L[0], m[3][1] - L[1], m[3][2] - L[2]};
        double far = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + rg->m_private->radius;
        if (far < reach && far > radius)
            radius = far;
    }
    return radius < reach ? radius : reach > 1 ? reach : 1;
}

/* The light's view and orthographic projection, column-major: the light looks along −dir at the
 * look-at point from 2R away, its box ±R across and R to 3R deep. */
static void lightMatrix(const RRender *rc, double R, float out[16])
{
    const AcmeReal *dir = rc->m_DirectLight1.m_Direction, *L = rc->m_CameraLookAt;
    double b[3] = {dir[0], dir[1], dir[2]};
    double n = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    if (!(n > 0))
        b[0] = 0, b[1] = 1, b[2] = 0, n = 1;
    for (int i = 0; i < 3; i++)
        b[i] /= n;
    double up[3] = {0, 1, 0};
    if (fabs(b[1]) > 0.99)
        up[0] = 1, up[1] = 0;
    double r[3] = {up[1] * b[2] - up[2] * b[1], up[2] * b[0] - up[0] * b[2], up[0] * b[1] - up[1] * b[0]};
    double rn = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int i = 0; i < 3; i++)
        r[i] /= rn;
    double u[3] = {b[1] * r[2] - b[2] * r[1], b[2] * r[0] - b[0] * r[2], b[0] * r[1] - b[1] * r[0]};
    double eye[3] = {L[0] + 2 * R * b[0], L[1] + 2 * R * b[1], L[2] + 2 * R * b[2]};
    const double *axes[3] = {r, u, b};
    double near = R, far = 3 * R, a[4][4] = {{0}};
    for (int row = 0; row < 3; row++) {
        double scale = row < 2 ? 1 / R : -2 / (far - near), dot = 0;
        for (int i = 0; i < 3; i++) {
            a[row][i] = scale * axes[row][i];
            dot += axes[row][i] * eye[i];
        }
        a[row][3] = -scale * dot + (row < 2 ? 0 : -(far + near) / (far - near));
    }
    a[3][3] = 1;
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 4; col++)
            out[4 * col + row] = (float)a[row][col];
}

void RShadowDraw(struct RShadow *s, RRender *rc, RGLBatchDraw draw, void *data)
{
    double R = regionRadius(rc);
    lightMatrix(rc, R, s->lightVP);
    s->texelWorld = (float)(2 * R / R_SHADOW_SIZE);
    glBindFramebuffer(GL_FRAMEBUFFER, s->fbo);
    glViewport(0, 0, R_SHADOW_SIZE, R_SHADOW_SIZE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_DEPTH_CLAMP); /* casters between the light and the box still cast */
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    glUseProgram(s->prog);
    glUniformMatrix4fv(s->uLightVP, 1, GL_FALSE, s->lightVP);
    draw(data, 1);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    s->valid = 1;
}

void RShadowBind(const struct RShadow *s, int uLightVP, int uTexel, int uMap, int unit)
{
    glActiveTexture((GLenum)(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, s->depth);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(uMap, unit);
    glUniformMatrix4fv(uLightVP, 1, GL_FALSE, s->lightVP);
    glUniform1f(uTexel, s->texelWorld);
}
