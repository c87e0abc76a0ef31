/* RGLNative.c -- native lines and particle systems with OpenGL 3.3 core: every line of a context in
 * one GL_LINES draw (positions and colours streamed each frame), each particle system in one
 * instanced draw of a camera-facing quad (a disc, or the texture's square when textured). Both are
 * unlit and depth-tested against the 3D list. */
#include <math.h>
#include <stdlib.h>

#include <epoxy/gl.h>

#include "RInternal.h"

/** Texture unit the particles' texture is bound to (the 3D program's use 0–2). */
#define R_PARTICLE_UNIT 3

struct RGLNative {
    GLuint lineProg, lineVao, lineVbo;
    GLint lineView, lineProj;
    GLuint partProg, partVao, cornerVbo, centreVbo;
    GLint partView, partProj, partSize, partColor, partTextured, partTexture;
    float *ends;                 /* this frame's line ends */
    int endCapacity;
    float *centres;              /* one system's particle centres */
    int centreCapacity;
};

static const char *const lineVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec3 aPos;\n"
    "layout(location = 1) in vec4 aColor;\n"
    "uniform mat4 uView, uProj;\n"
    "out vec4 vColor;\n"
    "void main() { vColor = aColor; gl_Position = uProj * uView * vec4(aPos, 1.0); }\n";

static const char *const lineFragment =
    "#version 330 core\n"
    "in vec4 vColor;\n"
    "out vec4 fragColor;\n"
    "void main() { fragColor = vColor; }\n";

/* The quad's corner is added in eye space, so it faces the camera in either projection. */
static const char *const particleVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec2 aCorner;\n"
    "layout(location = 1) in vec3 aCentre;\n"
    "uniform mat4 uView, uProj;\n"
    "uniform float uSize;\n"
    "out vec2 vCorner;\n"
    "void main() {\n"
    "  vec4 e = uView * vec4(aCentre, 1.0);\n"
    "  e.xy += 0.5 * uSize * aCorner;\n"
    "  vCorner = aCorner;\n"
    "  gl_Position = uProj * e;\n"
    "}\n";

static const char *const particleFragment =
    "#version 330 core\n"
    "uniform vec4 uColor;\n"
    "uniform int uTextured;\n"
    "uniform sampler2D uTexture;\n"
    "in vec2 vCorner;\n"
    "out vec4 fragColor;\n"
    "void main() {\n"
    "  if (uTextured != 0) { fragColor = uColor * texture(uTexture, 0.5 * vCorner + 0.5); return; }\n"
    "  if (dot(vCorner, vCorner) > 1.0) discard;\n"
    "  fragColor = uColor;\n"
    "}\n";

struct RGLNative *RGLNativeCreate(void)
{
    struct RGLNative *n = calloc(1, sizeof *n);
    if (!n)
        return NULL;
    n->lineProg = RGLLink(lineVertex, lineFragment);
    n->partProg = RGLLink(particleVertex, particleFragment);
    if (!n->lineProg || !n->partProg) {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate", "the programs of native lines and particles could not be made");
        RGLNativeDestroy(n);
        return NULL;
    }
    n->lineView = glGetUniformLocation(n->lineProg, "uView");
    n->lineProj = glGetUniformLocation(n->lineProg, "uProj");
    n->partView = glGetUniformLocation(n->partProg, "uView");
    n->partProj = glGetUniformLocation(n->partProg, "uProj");
    n->partSize = glGetUniformLocation(n->partProg, "uSize");
    n->partColor = glGetUniformLocation(n->partProg, "uColor");
    n->partTextured = glGetUniformLocation(n->partProg, "uTextured");
    n->partTexture = glGetUniformLocation(n->partProg, "uTexture");

    const GLsizei stride = R_LINE_FLOATS * sizeof(float);
    glGenVertexArrays(1, &n->lineVao);
    glGenBuffers(1, &n->lineVbo);
    glBindVertexArray(n->lineVao);
    glBindBuffer(GL_ARRAY_BUFFER, n->lineVbo);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, NULL);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, (const void *)(3 * sizeof(float)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);

    static const float corners[8] = {-1, -1, 1, -1, -1, 1, 1, 1}; /* a triangle strip */
    glGenVertexArrays(1, &n->partVao);
    glGenBuffers(1, &n->cornerVbo);
    glGenBuffers(1, &n->centreVbo);
    glBindVertexArray(n->partVao);
    glBindBuffer(GL_ARRAY_BUFFER, n->cornerVbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, n->centreVbo);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, NULL);
    glVertexAttribDivisor(1, 1);
    glEnableVertexAttribArray(1);
    glBindVertexArray(0);
    return n;
}

void RGLNativeDestroy(struct RGLNative *n)
{
    if (!n)
        return;
    GLuint vaos[2] = {n->lineVao, n->partVao}, vbos[3] = {n->lineVbo, n->cornerVbo, n->centreVbo};
    glDeleteVertexArrays(2, vaos); /* 0s are ignored */
    glDeleteBuffers(3, vbos);
    glDeleteProgram(n->lineProg);
    glDeleteProgram(n->partProg);
    free(n->ends);
    free(n->centres);
    free(n);
}

/* The camera's view and projection as the 3D program takes them (Karma's row-vector matrices read
 * column-major are the column-vector ones). */
static void setCamera(const RRender *rc, GLint view, GLint proj)
{
    float v[16], p[16];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            v[4 * i + j] = (float)rc->m_CamMatrix[i][j];
            p[4 * i + j] = (float)rc->m_ProjMatrix[i][j];
        }
    glUniformMatrix4fv(view, 1, GL_FALSE, v);
    glUniformMatrix4fv(proj, 1, GL_FALSE, p);
}

static void drawLines(struct RGLNative *n, RRender *rc)
{
    int count = RNLineGather(rc, &n->ends, &n->endCapacity);
    if (count <= 0)
        return;
    glUseProgram(n->lineProg);
    setCamera(rc, n->lineView, n->lineProj);
    glBindVertexArray(n->lineVao);
    glBindBuffer(GL_ARRAY_BUFFER, n->lineVbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * R_LINE_FLOATS * (size_t)count), n->ends, GL_STREAM_DRAW);
    glDrawArrays(GL_LINES, 0, count);
}

/* One system's finite centres into n->centres; returns how many, or −1 when out of memory. */
static int gatherCentres(struct RGLNative *n, const RParticleSystem *ps)
{
    if (ps->m_nNumParticles > n->centreCapacity) {
        float *bigger = realloc(n->centres, sizeof(float) * 3 * (size_t)ps->m_nNumParticles);
        if (!bigger)
            return -1;
        n->centres = bigger;
        n->centreCapacity = ps->m_nNumParticles;
    }
    int used = 0;
    for (int i = 0; i < ps->m_nNumParticles; i++) {
        const MeReal *p = ps->m_Positions[i];
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
            continue;
        float *c = n->centres + 3 * used++;
        c[0] = (float)p[0], c[1] = (float)p[1], c[2] = (float)p[2];
    }
    return used;
}

static void drawParticles(struct RGLNative *n, RRender *rc, unsigned int (*texture)(void *data, int id), void *data)
{
    if (!rc->m_private->particles || rc->m_private->noParticles)
        return;
    glUseProgram(n->partProg);
    setCamera(rc, n->partView, n->partProj);
    glUniform1i(n->partTexture, R_PARTICLE_UNIT);
    glBindVertexArray(n->partVao);
    for (const RParticleSystem *ps = rc->m_private->particles; ps; ps = ps->m_pNextSystem) {
        int count = gatherCentres(n, ps);
        if (count <= 0)
            continue;
        GLuint name = ps->m_nTextureID >= 0 ? texture(data, ps->m_nTextureID) : 0;
        glUniform1i(n->partTextured, name != 0);
        if (name) {
            glActiveTexture(GL_TEXTURE0 + R_PARTICLE_UNIT);
            glBindTexture(GL_TEXTURE_2D, name);
            glActiveTexture(GL_TEXTURE0);
        }
        glUniform1f(n->partSize, (float)ps->m_TriangleSize);
        glUniform4fv(n->partColor, 1, ps->m_rgbAmbient);
        glBindBuffer(GL_ARRAY_BUFFER, n->centreVbo);
        glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * 3 * (size_t)count), n->centres, GL_STREAM_DRAW);
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, count);
    }
}

void RGLNativeDraw(struct RGLNative *n, RRender *rc, unsigned int (*texture)(void *data, int id), void *data)
{
    if (!n)
        return;
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    drawLines(n, rc);
    drawParticles(n, rc, texture, data);
    glBindVertexArray(0);
}
