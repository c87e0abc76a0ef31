/* RGL.c -- drawing a context's render lists with OpenGL 3.3 core: one lit program for triangles and
 * lines (Karma's lights, Blinn-Phong, an anti-aliased checkerboard for planes), one for 2D text,
 * a multisampled framebuffer resolved into the window or into an offscreen picture. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <epoxy/gl.h>
#include <stb_truetype.h>

#include "RInternal.h"

#ifndef KARMA_VIEWER_FONT
#define KARMA_VIEWER_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif

/** Samples per pixel of the multisampled framebuffer (fewer when the driver offers fewer). */
#define R_MSAA_SAMPLES 4
/** The font is baked once at this height (pixels) into a square atlas of R_FONT_ATLAS pixels. */
#define R_FONT_BAKE_PX 32.0f
#define R_FONT_ATLAS 512
/** Height of text in Karma's virtual 640×448 screen. */
#define R_TEXT_HEIGHT 16.0f
#define R_VIRTUAL_W 640.0f
#define R_VIRTUAL_H 448.0f

struct RGL {
    RBackend *backend;                /* whose context holds every object below */
    RGraphic *graphics;               /* graphics holding GL objects of this context */
    int width, height, samples;
    GLuint msFbo, msColor, msDepth;   /* multisampled target */
    GLuint fbo, color;                /* resolved picture (offscreen) */
    GLuint prog3D, prog2D;
    GLint u3[32];                     /* uniform locations of prog3D, by the enum below */
    GLint u2Screen, u2Color, u2Font;
    GLuint fontTexture, textVao, textVbo;
    stbtt_bakedchar glyphs[96];
    int haveFont;
};

enum {
    U_MODEL, U_VIEW, U_PROJ, U_AMBIENT, U_DIFFUSE, U_SPECULAR, U_SHININESS, U_EMISSIVE, U_GLOBAL_AMBIENT, U_EYE,
    U_L1_ON, U_L1_DIR, U_L1_AMB, U_L1_DIF, U_L1_SPEC, U_L2_ON, U_L2_DIR, U_L2_AMB, U_L2_DIF, U_L2_SPEC,
    U_P_ON, U_P_POS, U_P_AMB, U_P_DIF, U_P_SPEC, U_P_ATT, U_UNLIT, U_CHECKER, U_CHECKER_U, U_CHECKER_V, U_COUNT
};
static const char *const uniformNames[U_COUNT] = {
    "uModel", "uView", "uProj", "uAmbient", "uDiffuse", "uSpecular", "uShininess", "uEmissive", "uGlobalAmbient",
    "uEye", "uL1.on", "uL1.dir", "uL1.amb", "uL1.dif", "uL1.spec", "uL2.on", "uL2.dir", "uL2.amb", "uL2.dif",
    "uL2.spec", "uPointOn", "uPointPos", "uPointAmb", "uPointDif", "uPointSpec", "uPointAtt", "uUnlit",
    "uChecker", "uCheckerU", "uCheckerV"};

static const char *const vertex3D =
    "#version 330 core\n"
    "layout(location = 0) in vec3 aPos;\n"
    "layout(location = 1) in vec3 aNormal;\n"
    "uniform mat4 uModel, uView, uProj;\n"
    "out vec3 vWorld, vNormal, vLocal;\n"
    "void main() {\n"
    "  vec4 w = uModel * vec4(aPos, 1.0);\n"
    "  vWorld = w.xyz; vNormal = mat3(uModel) * aNormal; vLocal = aPos;\n"
    "  gl_Position = uProj * uView * w;\n"
    "}\n";

/* Karma's lights as OpenGL's fixed pipeline lit them (ambient + diffuse + specular per light, the
 * global ambient), two-sided; the checkerboard is box-filtered so it fades to grey far away instead
 * of shimmering. */
static const char *const fragment3D =
    "#version 330 core\n"
    "struct Light { int on; vec3 dir, amb, dif, spec; };\n"
    "uniform vec4 uAmbient, uDiffuse, uSpecular, uEmissive;\n"
    "uniform float uShininess, uChecker;\n"
    "uniform vec3 uGlobalAmbient, uEye, uCheckerU, uCheckerV;\n"
    "uniform Light uL1, uL2;\n"
    "uniform int uPointOn, uUnlit;\n"
    "uniform vec3 uPointPos, uPointAmb, uPointDif, uPointSpec, uPointAtt;\n"
    "in vec3 vWorld, vNormal, vLocal;\n"
    "out vec4 fragColor;\n"
    "vec3 shade(vec3 n, vec3 v, vec3 l, vec3 amb, vec3 dif, vec3 spec, vec3 ka, vec3 kd) {\n"
    "  float d = max(dot(n, l), 0.0);\n"
    "  float s = d > 0.0 ? pow(max(dot(n, normalize(l + v)), 0.0), uShininess) : 0.0;\n"
    "  return amb * ka + dif * kd * d + spec * uSpecular.rgb * s;\n"
    "}\n"
    "void main() {\n"
    "  vec3 kd = uDiffuse.rgb, ka = uAmbient.rgb;\n"
    "  if (uChecker > 0.0) {\n"
    "    vec2 p = vec2(dot(vLocal, uCheckerU), dot(vLocal, uCheckerV)) / uChecker;\n"
    "    vec2 w = fwidth(p) + 1e-4;\n"
    "    vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;\n"
    "    float k = mix(0.74, 1.0, 0.5 + 0.5 * i.x * i.y);\n"
    "    kd *= k; ka *= k;\n"
    "  }\n"
    "  if (uUnlit != 0) { fragColor = vec4(kd, uDiffuse.a); return; }\n"
    "  vec3 n = normalize(vNormal);\n"
    "  if (!gl_FrontFacing) n = -n;\n"
    "  vec3 v = normalize(uEye - vWorld);\n"
    "  vec3 c = uEmissive.rgb + uGlobalAmbient * ka;\n"
    "  if (uL1.on != 0) c += shade(n, v, normalize(uL1.dir), uL1.amb, uL1.dif, uL1.spec, ka, kd);\n"
    "  if (uL2.on != 0) c += shade(n, v, normalize(uL2.dir), uL2.amb, uL2.dif, uL2.spec, ka, kd);\n"
    "  if (uPointOn != 0) {\n"
    "    vec3 l = uPointPos - vWorld; float r = length(l);\n"
    "    float a = 1.0 / max(uPointAtt.x + uPointAtt.y * r + uPointAtt.z * r * r, 1e-6);\n"
    "    c += a * shade(n, v, l / r, uPointAmb, uPointDif, uPointSpec, ka, kd);\n"
    "  }\n"
    "  fragColor = vec4(min(c, vec3(1.0)), uDiffuse.a);\n"
    "}\n";

static const char *const vertex2D =
    "#version 330 core\n"
    "layout(location = 0) in vec4 aPosUV;\n"
    "uniform vec2 uScreen;\n"
    "out vec2 vUV;\n"
    "void main() {\n"
    "  vUV = aPosUV.zw;\n"
    "  gl_Position = vec4(aPosUV.x / uScreen.x * 2.0 - 1.0, 1.0 - aPosUV.y / uScreen.y * 2.0, 0.0, 1.0);\n"
    "}\n";

static const char *const fragment2D =
    "#version 330 core\n"
    "uniform vec4 uColor;\n"
    "uniform sampler2D uFont;\n"
    "in vec2 vUV;\n"
    "out vec4 fragColor;\n"
    "void main() { fragColor = vec4(uColor.rgb, uColor.a * texture(uFont, vUV).r); }\n";

static GLuint compile(GLenum type, const char *source)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        R_REPORT(ME_ERR_INTERNAL, "RGLCreate", "shader does not compile: %s", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

static GLuint link(const char *vs, const char *fs)
{
    GLuint v = compile(GL_VERTEX_SHADER, vs), f = compile(GL_FRAGMENT_SHADER, fs);
    if (!v || !f) { /* the one that compiled is not kept */
        glDeleteShader(v); /* deleting shader 0 is a no-op */
        glDeleteShader(f);
        return 0;
    }
    GLuint p = glCreateProgram();
    glAttachShader(p, v);
    glAttachShader(p, f);
    glLinkProgram(p);
    glDeleteShader(v);
    glDeleteShader(f);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[1024];
        glGetProgramInfoLog(p, sizeof log, NULL, log);
        R_REPORT(ME_ERR_INTERNAL, "RGLCreate", "shaders do not link: %s", log);
        glDeleteProgram(p);
        return 0;
    }
    return p;
}

/* The font atlas from DejaVu Sans (fonts-dejavu-core); without it text is not drawn (reported once). */
static void loadFont(struct RGL *gl)
{
    FILE *f = fopen(KARMA_VIEWER_FONT, "rb");
    if (!f) {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate", "font %s not found: text will not be drawn", KARMA_VIEWER_FONT);
        return;
    }
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *ttf = size > 0 ? malloc((size_t)size) : NULL;
    unsigned char *atlas = malloc(R_FONT_ATLAS * R_FONT_ATLAS);
    if (ttf && atlas && fread(ttf, 1, (size_t)size, f) == (size_t)size &&
        stbtt_BakeFontBitmap(ttf, 0, R_FONT_BAKE_PX, atlas, R_FONT_ATLAS, R_FONT_ATLAS, 32, 96, gl->glyphs) > 0) {
        glGenTextures(1, &gl->fontTexture);
        glBindTexture(GL_TEXTURE_2D, gl->fontTexture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, R_FONT_ATLAS, R_FONT_ATLAS, 0, GL_RED, GL_UNSIGNED_BYTE, atlas);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl->haveFont = 1;
    } else {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate", "font %s unreadable: text will not be drawn", KARMA_VIEWER_FONT);
    }
    free(ttf);
    free(atlas);
    fclose(f);
}

static int makeTargets(struct RGL *gl)
{
    glGenFramebuffers(1, &gl->msFbo);
    glGenRenderbuffers(1, &gl->msColor);
    glGenRenderbuffers(1, &gl->msDepth);
    glBindRenderbuffer(GL_RENDERBUFFER, gl->msColor);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, gl->samples, GL_RGBA8, gl->width, gl->height);
    glBindRenderbuffer(GL_RENDERBUFFER, gl->msDepth);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, gl->samples, GL_DEPTH_COMPONENT24, gl->width, gl->height);
    glBindFramebuffer(GL_FRAMEBUFFER, gl->msFbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, gl->msColor);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, gl->msDepth);
    int complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;

    glGenFramebuffers(1, &gl->fbo);
    glGenRenderbuffers(1, &gl->color);
    glBindRenderbuffer(GL_RENDERBUFFER, gl->color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, gl->width, gl->height);
    glBindFramebuffer(GL_FRAMEBUFFER, gl->fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, gl->color);
    complete = complete && glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return complete;
}

static void freeTargets(struct RGL *gl)
{
    GLuint fbos[2] = {gl->msFbo, gl->fbo}, rbs[3] = {gl->msColor, gl->msDepth, gl->color};
    glDeleteFramebuffers(2, fbos);
    glDeleteRenderbuffers(3, rbs);
}

struct RGL *RGLCreate(RBackend *backend, int width, int height)
{
    struct RGL *gl = calloc(1, sizeof *gl);
    if (!gl)
        return NULL;
    gl->backend = backend;
    gl->width = width, gl->height = height;
    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    gl->samples = maxSamples < R_MSAA_SAMPLES ? maxSamples : R_MSAA_SAMPLES;
    gl->prog3D = link(vertex3D, fragment3D);
    gl->prog2D = link(vertex2D, fragment2D);
    if (!gl->prog3D || !gl->prog2D || !makeTargets(gl)) {
        R_REPORT(ME_ERR_BAD_STATE, "RRenderContextCreate", "OpenGL 3.3 programs or framebuffers could not be made");
        RGLDestroy(gl);
        return NULL;
    }
    for (int i = 0; i < U_COUNT; i++)
        gl->u3[i] = glGetUniformLocation(gl->prog3D, uniformNames[i]);
    gl->u2Screen = glGetUniformLocation(gl->prog2D, "uScreen");
    gl->u2Color = glGetUniformLocation(gl->prog2D, "uColor");
    gl->u2Font = glGetUniformLocation(gl->prog2D, "uFont");
    glGenVertexArrays(1, &gl->textVao);
    glGenBuffers(1, &gl->textVbo);
    glBindVertexArray(gl->textVao);
    glBindBuffer(GL_ARRAY_BUFFER, gl->textVbo);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), NULL);
    glEnableVertexAttribArray(0);
    glBindVertexArray(0);
    loadFont(gl);
    return gl;
}

void RGLDestroy(struct RGL *gl)
{
    if (!gl)
        return;
    while (gl->graphics) /* graphics taken out of the lists outlive the context */
        RGLReleaseGraphic(gl->graphics);
    freeTargets(gl);
    glDeleteProgram(gl->prog3D);
    glDeleteProgram(gl->prog2D);
    glDeleteTextures(1, &gl->fontTexture);
    glDeleteVertexArrays(1, &gl->textVao);
    glDeleteBuffers(1, &gl->textVbo);
    free(gl);
}

void RGLReleaseGraphic(RGraphic *rg)
{
    struct RGraphicPrivate *p = rg->m_private;
    struct RGL *gl = p->gl;
    if (!gl)
        return;
    gl->backend->makeCurrent(gl->backend); /* names belong to the context that made them */
    glDeleteVertexArrays(1, &p->vao);
    glDeleteBuffers(1, &p->vbo);
    p->vao = p->vbo = 0;
    p->uploaded = 0;
    p->dirty = 1;
    if (p->glPrev)
        p->glPrev->m_private->glNext = p->glNext;
    else
        gl->graphics = p->glNext;
    if (p->glNext)
        p->glNext->m_private->glPrev = p->glPrev;
    p->gl = NULL;
    p->glPrev = p->glNext = NULL;
}

/* Positions and normals as floats, uploaded when the vertices changed. A graphic drawn by a second
 * context moves its objects there. */
static void upload(struct RGL *gl, RGraphic *rg)
{
    struct RGraphicPrivate *p = rg->m_private;
    int n = rg->m_pObject->m_nNumVertices;
    if (n > rg->m_nMaxNumVertices)
        n = rg->m_nMaxNumVertices;
    if (p->gl != gl) {
        RGLReleaseGraphic(rg);
        gl->backend->makeCurrent(gl->backend);
    }
    if (!p->vao) {
        p->gl = gl;
        p->glPrev = NULL;
        p->glNext = gl->graphics;
        if (gl->graphics)
            gl->graphics->m_private->glPrev = rg;
        gl->graphics = rg;
        glGenVertexArrays(1, &p->vao);
        glGenBuffers(1, &p->vbo);
        glBindVertexArray(p->vao);
        glBindBuffer(GL_ARRAY_BUFFER, p->vbo);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), NULL);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (const void *)(3 * sizeof(float)));
        glEnableVertexAttribArray(0);
        glEnableVertexAttribArray(1);
        p->dirty = 1;
    }
    if (!p->dirty)
        return;
    float *data = malloc(sizeof(float) * 6 * (size_t)(n > 0 ? n : 1));
    if (!data)
        return;
    for (int i = 0; i < n; i++) {
        const RObjectVertex *v = &rg->m_pVertices[i];
        float *d = data + 6 * i;
        d[0] = (float)v->m_X, d[1] = (float)v->m_Y, d[2] = (float)v->m_Z;
        d[3] = (float)v->m_NX, d[4] = (float)v->m_NY, d[5] = (float)v->m_NZ;
    }
    glBindBuffer(GL_ARRAY_BUFFER, p->vbo);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * 6 * (size_t)n), data, GL_STATIC_DRAW);
    free(data);
    p->uploaded = n;
    p->dirty = 0;
}

static void matrixToFloat(MeMatrix4Ptr m, float out[16])
{
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            out[4 * i + j] = (float)m[i][j];
}

static void uniform3(GLint location, const AcmeReal v[3])
{
    glUniform3f(location, (float)v[0], (float)v[1], (float)v[2]);
}

static void setLights(struct RGL *gl, RRender *rc)
{
    const GLint *u = gl->u3;
    AcmeVector3 eye;
    RCameraGetPosition(rc, eye);
    uniform3(u[U_EYE], eye);
    const AcmeReal *a = rc->m_rgbAmbientLightColor;
    float on = rc->m_bUseAmbientLight ? 1.0f : 0.0f;
    glUniform3f(u[U_GLOBAL_AMBIENT], on * (float)a[0], on * (float)a[1], on * (float)a[2]);
    const RDirectLight *lights[2] = {&rc->m_DirectLight1, &rc->m_DirectLight2};
    for (int k = 0; k < 2; k++) {
        int base = k ? U_L2_ON : U_L1_ON;
        glUniform1i(u[base], lights[k]->m_bUseLight);
        uniform3(u[base + 1], lights[k]->m_Direction);
        uniform3(u[base + 2], lights[k]->m_rgbAmbient);
        uniform3(u[base + 3], lights[k]->m_rgbDiffuse);
        uniform3(u[base + 4], lights[k]->m_rgbSpecular);
    }
    const RPointLight *pl = &rc->m_PointLight;
    glUniform1i(u[U_P_ON], pl->m_bUseLight);
    uniform3(u[U_P_POS], pl->m_Position);
    glUniform3fv(u[U_P_AMB], 1, pl->m_rgbAmbient);
    glUniform3fv(u[U_P_DIF], 1, pl->m_rgbDiffuse);
    glUniform3fv(u[U_P_SPEC], 1, pl->m_rgbSpecular);
    glUniform3f(u[U_P_ATT], (float)pl->m_AttenuationConstant, (float)pl->m_AttenuationLinear,
                (float)pl->m_AttenuationQuadratic);
}

static void draw3D(struct RGL *gl, RRender *rc)
{
    const GLint *u = gl->u3;
    float m[16];
    glUseProgram(gl->prog3D);
    matrixToFloat(rc->m_CamMatrix, m);
    glUniformMatrix4fv(u[U_VIEW], 1, GL_FALSE, m);
    matrixToFloat(rc->m_ProjMatrix, m);
    glUniformMatrix4fv(u[U_PROJ], 1, GL_FALSE, m);
    setLights(gl, rc);
    for (RGraphic *rg = rc->m_pRG_First; rg; rg = rg->m_pNext) {
        RObjectHeader *h = rg->m_pObject;
        struct RGraphicPrivate *p = rg->m_private;
        if (h->m_nNumVertices <= 0)
            continue;
        /* Karma's composite matrix: the followed transform, copied in each frame. */
        if (rg->m_pLWMatrix)
            memcpy(h->m_Matrix, rg->m_pLWMatrix, sizeof h->m_Matrix);
        upload(gl, rg);
        matrixToFloat(h->m_Matrix, m);
        /* Karma's matrices are row-vector (p·M): read as OpenGL's column-major they are the
         * column-vector matrices the shader multiplies. */
        glUniformMatrix4fv(u[U_MODEL], 1, GL_FALSE, m);
        glUniform4fv(u[U_AMBIENT], 1, h->m_ColorAmbient);
        glUniform4fv(u[U_DIFFUSE], 1, h->m_ColorDiffuse);
        glUniform4fv(u[U_SPECULAR], 1, h->m_ColorSpecular);
        glUniform4fv(u[U_EMISSIVE], 1, h->m_ColorEmissive);
        glUniform1f(u[U_SHININESS], (float)h->m_SpecularPower);
        glUniform1i(u[U_UNLIT], p->kind == kRKindLines);
        glUniform1f(u[U_CHECKER], p->checkerCell);
        if (p->checkerCell > 0) {
            /* A ground plane's cells lie in its x–z plane, a square's in its x–y plane. */
            int ground = rg->m_pVertices[0].m_Y == 0 && rg->m_pVertices[1].m_Y == 0 && rg->m_pVertices[2].m_Y == 0;
            glUniform3f(u[U_CHECKER_U], 1, 0, 0);
            glUniform3f(u[U_CHECKER_V], 0, ground ? 0.0f : 1.0f, ground ? 1.0f : 0.0f);
        }
        int wire = h->m_bIsWireFrame || rc->m_options.m_bWireFrame;
        if (wire)
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glBindVertexArray(p->vao);
        glDrawArrays(p->kind == kRKindLines ? GL_LINES : GL_TRIANGLES, 0, p->uploaded);
        if (wire)
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    }
    glBindVertexArray(0);
}

/* Text: one quad per glyph, in pixels, scaled from Karma's virtual 640×448 screen. */
static void draw2D(struct RGL *gl, RRender *rc)
{
    if (!gl->haveFont || !rc->m_pRG_First2D)
        return;
    float sx = (float)gl->width / R_VIRTUAL_W, sy = (float)gl->height / R_VIRTUAL_H;
    float scale = R_TEXT_HEIGHT / R_FONT_BAKE_PX * sy;
    glUseProgram(gl->prog2D);
    glUniform2f(gl->u2Screen, (float)gl->width, (float)gl->height);
    glUniform1i(gl->u2Font, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, gl->fontTexture);
    glBindVertexArray(gl->textVao);
    glBindBuffer(GL_ARRAY_BUFFER, gl->textVbo);
    glDisable(GL_DEPTH_TEST);
    for (RGraphic *rg = rc->m_pRG_First2D; rg; rg = rg->m_pNext) {
        const char *text = rg->m_private->text;
        if (rg->m_private->kind != kRKindText || !text || !*text)
            continue;
        size_t n = strlen(text);
        float *quads = malloc(sizeof(float) * 24 * n);
        if (!quads)
            continue;
        float x = 0, y = R_FONT_BAKE_PX * 0.8f; /* baseline below the top of the text */
        float ox = rg->m_private->x * sx, oy = rg->m_private->y * sy;
        int count = 0;
        for (size_t i = 0; i < n; i++) {
            unsigned char c = (unsigned char)text[i];
            if (c < 32 || c >= 128)
                c = '?';
            stbtt_aligned_quad q;
            stbtt_GetBakedQuad(gl->glyphs, R_FONT_ATLAS, R_FONT_ATLAS, c - 32, &x, &y, &q, 1);
            float x0 = ox + q.x0 * scale, x1 = ox + q.x1 * scale, y0 = oy + q.y0 * scale, y1 = oy + q.y1 * scale;
            float v[24] = {x0, y0, q.s0, q.t0, x1, y0, q.s1, q.t0, x1, y1, q.s1, q.t1,
                           x0, y0, q.s0, q.t0, x1, y1, q.s1, q.t1, x0, y1, q.s0, q.t1};
            memcpy(quads + 24 * count++, v, sizeof v);
        }
        glUniform4fv(gl->u2Color, 1, rg->m_pObject->m_ColorDiffuse);
        glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * 24 * (size_t)count), quads, GL_STREAM_DRAW);
        glDrawArrays(GL_TRIANGLES, 0, 6 * count);
        free(quads);
    }
    glEnable(GL_DEPTH_TEST);
    glBindVertexArray(0);
}

void RGLDrawFrame(struct RGL *gl, RRender *rc, int toWindow)
{
    glBindFramebuffer(GL_FRAMEBUFFER, gl->msFbo);
    glViewport(0, 0, gl->width, gl->height);
    const AcmeReal *bg = rc->m_backgroundColour;
    glClearColor((float)bg[0], (float)bg[1], (float)bg[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_MULTISAMPLE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    draw3D(gl, rc);
    draw2D(gl, rc);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, gl->msFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gl->fbo);
    glBlitFramebuffer(0, 0, gl->width, gl->height, 0, 0, gl->width, gl->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (toWindow) { /* the resolved picture stays readable (RRenderReadPixels) in a window too */
        glBindFramebuffer(GL_READ_FRAMEBUFFER, gl->fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, gl->width, gl->height, 0, 0, gl->width, gl->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RGLReadPixels(struct RGL *gl, unsigned char *rgba)
{
    size_t row = (size_t)gl->width * 4;
    unsigned char *flipped = malloc(row * (size_t)gl->height);
    if (!flipped)
        return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, gl->fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, gl->width, gl->height, GL_RGBA, GL_UNSIGNED_BYTE, flipped);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    for (int y = 0; y < gl->height; y++) /* OpenGL's rows start at the bottom */
        memcpy(rgba + row * (size_t)y, flipped + row * (size_t)(gl->height - 1 - y), row);
    free(flipped);
}
