/* RGL.c -- drawing a context's render lists with OpenGL 3.3 core: one lit program for triangles and
 * lines (Karma's lights, Blinn-Phong, an anti-aliased checkerboard for planes), one for 2D text,
 * a multisampled framebuffer resolved into the window or into an offscreen picture. */
#include <math.h>
#include <stdint.h>
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

/** Floats per instance: the model matrix (16), ambient, diffuse, specular (rgb, shininess), emissive (4 each). */
#define R_INSTANCE_FLOATS 32
/** Texture units of the shadow map and of graphics' textures (the font uses unit 0). */
#define R_SHADOW_UNIT 1
#define R_TEXTURE_UNIT 2
/** In the key light's shadow its ambient part is scaled by this too (its diffuse and specular
 *  parts vanish): Karma's light 1 is mostly ambient (0.7 of 1.3), and a shadow of its diffuse
 *  part alone would hardly show. */
#define R_SHADOW_AMBIENT "0.55"

/** One graphic drawn this frame: its mesh, whether it may be batched with others of that mesh. */
typedef struct RDrawItem {
    RGraphic *g;
    RMesh *mesh;
    int plain;   /* filled, lit, opaque, no checkerboard: drawn instanced with its mesh's other plain graphics */
    int casts;
    int order;   /* in the render list */
    float depth; /* of its origin along the camera's view direction */
} RDrawItem;

struct RGL {
    RBackend *backend;                /* whose context holds every object below */
    RGraphic *graphics;               /* graphics holding GL objects of this context */
    int width, height, samples;
    GLuint msFbo, msColor, msDepth;   /* multisampled target */
    GLuint fbo, color;                /* resolved picture (offscreen) */
    GLuint prog3D, prog2D;
    GLint u3[32];                     /* uniform locations of prog3D, by the enum below */
    GLint u2Screen, u2Color, u2Font, u2Solid;
    GLuint fontTexture, textVao, textVbo;
    stbtt_bakedchar glyphs[96];
    int haveFont;
    RMeshCache cache;                 /* meshes, and the instance buffer */
    struct RShadow *shadow;           /* NULL: no shadows */
    RDrawItem *items;                 /* this frame's graphics, batched */
    float *instances;                 /* their instance data */
    int itemCount, itemCapacity;
    RRender *rc;                      /* the context being drawn */
    GLuint textures[R_MAX_TEXTURES];  /* the context's textures, uploaded when first used (0: not yet) */
    struct RGLNative *native;         /* native lines and particles (NULL: not drawn) */
};

enum {
    U_VIEW, U_PROJ, U_GLOBAL_AMBIENT, U_EYE,
    U_L1_ON, U_L1_DIR, U_L1_AMB, U_L1_DIF, U_L1_SPEC, U_L2_ON, U_L2_DIR, U_L2_AMB, U_L2_DIF, U_L2_SPEC,
    U_P_ON, U_P_POS, U_P_AMB, U_P_DIF, U_P_SPEC, U_P_ATT, U_UNLIT, U_CHECKER, U_CHECKER_U, U_CHECKER_V,
    U_SHADOW_ON, U_SHADOW_VP, U_SHADOW_TEXEL, U_SHADOW_MAP, U_TEXTURED, U_TEXTURE, U_COUNT
};
static const char *const uniformNames[U_COUNT] = {
    "uView", "uProj", "uGlobalAmbient",
    "uEye", "uL1.on", "uL1.dir", "uL1.amb", "uL1.dif", "uL1.spec", "uL2.on", "uL2.dir", "uL2.amb", "uL2.dif",
    "uL2.spec", "uPointOn", "uPointPos", "uPointAmb", "uPointDif", "uPointSpec", "uPointAtt", "uUnlit",
    "uChecker", "uCheckerU", "uCheckerV", "uShadowOn", "uShadowVP", "uShadowTexel", "uShadowMap", "uTextured", "uTexture"};

/* Per instance (divisor 1): the model matrix and the material, passed on flat. */
static const char *const vertex3D =
    "#version 330 core\n"
    "layout(location = 0) in vec3 aPos;\n"
    "layout(location = 1) in vec3 aNormal;\n"
    "layout(location = 2) in mat4 aModel;\n"
    "layout(location = 6) in vec4 aAmbient;\n"
    "layout(location = 7) in vec4 aDiffuse;\n"
    "layout(location = 8) in vec4 aSpecular;\n"
    "layout(location = 9) in vec4 aEmissive;\n"
    "layout(location = 10) in vec2 aUV;\n"
    "uniform mat4 uView, uProj;\n"
    "out vec3 vWorld, vNormal, vLocal;\n"
    "out vec2 vUV;\n"
    "flat out vec4 vAmbient, vDiffuse, vSpecular, vEmissive;\n"
    "void main() {\n"
    "  vec4 w = aModel * vec4(aPos, 1.0);\n"
    "  vWorld = w.xyz; vNormal = mat3(aModel) * aNormal; vLocal = aPos; vUV = aUV;\n"
    "  vAmbient = aAmbient; vDiffuse = aDiffuse; vSpecular = aSpecular; vEmissive = aEmissive;\n"
    "  gl_Position = uProj * uView * w;\n"
    "}\n";

/* Karma's lights as OpenGL's fixed pipeline lit them (ambient + diffuse + specular per light, the
 * global ambient), two-sided; light 1 shadowed through its depth map (4 taps, each a bilinear
 * 2 × 2 comparison; a point deeper than the map's box compares as its far end, so the ground far
 * below the casters still receives their shadows), the sample point pushed a texel and a half along the normal against acne;
 * the checkerboard is box-filtered so it fades to grey far away instead of shimmering. */
static const char *const fragment3D =
    "#version 330 core\n"
    "struct Light { int on; vec3 dir, amb, dif, spec; };\n"
    "uniform float uChecker;\n"
    "uniform vec3 uGlobalAmbient, uEye, uCheckerU, uCheckerV;\n"
    "uniform Light uL1, uL2;\n"
    "uniform int uPointOn, uUnlit, uShadowOn;\n"
    "uniform vec3 uPointPos, uPointAmb, uPointDif, uPointSpec, uPointAtt;\n"
    "uniform mat4 uShadowVP;\n"
    "uniform float uShadowTexel;\n"
    "uniform sampler2DShadow uShadowMap;\n"
    "uniform int uTextured;\n"
    "uniform sampler2D uTexture;\n"
    "in vec3 vWorld, vNormal, vLocal;\n"
    "in vec2 vUV;\n"
    "flat in vec4 vAmbient, vDiffuse, vSpecular, vEmissive;\n"
    "out vec4 fragColor;\n"
    "vec3 shade(vec3 n, vec3 v, vec3 l, vec3 amb, vec3 dif, vec3 spec, vec3 ka, vec3 kd, float lit) {\n"
    "  float d = max(dot(n, l), 0.0);\n"
    "  float s = d > 0.0 ? pow(max(dot(n, normalize(l + v)), 0.0), vSpecular.a) : 0.0;\n"
    "  return amb * ka * mix(" R_SHADOW_AMBIENT ", 1.0, lit) + lit * (dif * kd * d + spec * vSpecular.rgb * s);\n"
    "}\n"
    "float lightFraction(vec3 n, vec3 l) {\n"
    "  if (uShadowOn == 0) return 1.0;\n"
    "  vec3 p = vWorld + (dot(n, l) < 0.0 ? -n : n) * 1.5 * uShadowTexel;\n"
    "  vec4 c = uShadowVP * vec4(p, 1.0);\n"
    "  vec3 t = c.xyz * 0.5 + 0.5;\n"
    "  if (t.x <= 0.0 || t.x >= 1.0 || t.y <= 0.0 || t.y >= 1.0) return 1.0;\n"
    "  t.z = min(t.z, 1.0);\n"
    "  vec2 o = vec2(0.5) / vec2(textureSize(uShadowMap, 0));\n"
    "  return 0.25 * (texture(uShadowMap, vec3(t.xy + vec2(-o.x, -o.y), t.z)) +\n"
    "                 texture(uShadowMap, vec3(t.xy + vec2(o.x, -o.y), t.z)) +\n"
    "                 texture(uShadowMap, vec3(t.xy + vec2(-o.x, o.y), t.z)) +\n"
    "                 texture(uShadowMap, vec3(t.xy + vec2(o.x, o.y), t.z)));\n"
    "}\n"
    "void main() {\n"
    "  vec3 kd = vDiffuse.rgb, ka = vAmbient.rgb;\n"
    "  if (uChecker > 0.0) {\n"
    "    vec2 p = vec2(dot(vLocal, uCheckerU), dot(vLocal, uCheckerV)) / uChecker;\n"
    "    vec2 w = fwidth(p) + 1e-4;\n"
    "    vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;\n"
    "    float k = mix(0.74, 1.0, 0.5 + 0.5 * i.x * i.y);\n"
    "    kd *= k; ka *= k;\n"
    "  }\n"
    "  if (uTextured != 0) { vec3 t = texture(uTexture, vUV).rgb; kd *= t; ka *= t; }\n"
    "  if (uUnlit != 0) { fragColor = vec4(kd, vDiffuse.a); return; }\n"
    "  vec3 n = normalize(vNormal);\n"
    "  if (!gl_FrontFacing) n = -n;\n"
    "  vec3 v = normalize(uEye - vWorld);\n"
    "  vec3 c = vEmissive.rgb + uGlobalAmbient * ka;\n"
    "  if (uL1.on != 0) {\n"
    "    vec3 l = normalize(uL1.dir);\n"
    "    c += shade(n, v, l, uL1.amb, uL1.dif, uL1.spec, ka, kd, lightFraction(n, l));\n"
    "  }\n"
    "  if (uL2.on != 0) c += shade(n, v, normalize(uL2.dir), uL2.amb, uL2.dif, uL2.spec, ka, kd, 1.0);\n"
    "  if (uPointOn != 0) {\n"
    "    vec3 l = uPointPos - vWorld; float r = length(l);\n"
    "    float a = 1.0 / max(uPointAtt.x + uPointAtt.y * r + uPointAtt.z * r * r, 1e-6);\n"
    "    c += a * shade(n, v, l / r, uPointAmb, uPointDif, uPointSpec, ka, kd, 1.0);\n"
    "  }\n"
    "  fragColor = vec4(min(c, vec3(1.0)), vDiffuse.a);\n"
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
    "uniform int uSolid;\n"
    "void main() { fragColor = vec4(uColor.rgb, uColor.a * (uSolid != 0 ? 1.0 : texture(uFont, vUV).r)); }\n";

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

unsigned int RGLLink(const char *vs, const char *fs)
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

void RGLInstanceAttributes(unsigned int buffer, size_t offset)
{
    const GLsizei stride = R_INSTANCE_FLOATS * sizeof(float);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    for (GLuint k = 0; k < 8; k++) { /* 2–5: the matrix's columns; 6–9: the material */
        glVertexAttribPointer(2 + k, 4, GL_FLOAT, GL_FALSE, stride, (const void *)(offset + 4 * sizeof(float) * k));
        glVertexAttribDivisor(2 + k, 1);
        glEnableVertexAttribArray(2 + k);
    }
}

int RGLResize(struct RGL *gl, int width, int height)
{
    int oldWidth = gl->width, oldHeight = gl->height;
    freeTargets(gl);
    gl->width = width, gl->height = height;
    if (makeTargets(gl))
        return 0;
    freeTargets(gl);
    gl->width = oldWidth, gl->height = oldHeight;
    makeTargets(gl);
    return -1;
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
    gl->prog3D = RGLLink(vertex3D, fragment3D);
    gl->prog2D = RGLLink(vertex2D, fragment2D);
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
    gl->u2Solid = glGetUniformLocation(gl->prog2D, "uSolid");
    glGenVertexArrays(1, &gl->textVao);
    glGenBuffers(1, &gl->textVbo);
    glBindVertexArray(gl->textVao);
    glBindBuffer(GL_ARRAY_BUFFER, gl->textVbo);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), NULL);
    glEnableVertexAttribArray(0);
    glBindVertexArray(0);
    glGenBuffers(1, &gl->cache.instances);
    gl->shadow = RShadowCreate();
    gl->native = RGLNativeCreate();
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
    RShadowDestroy(gl->shadow);
    RGLNativeDestroy(gl->native);
    glDeleteTextures(R_MAX_TEXTURES, gl->textures); /* 0s are ignored */
    glDeleteBuffers(1, &gl->cache.instances);
    glDeleteProgram(gl->prog3D);
    glDeleteProgram(gl->prog2D);
    glDeleteTextures(1, &gl->fontTexture);
    glDeleteVertexArrays(1, &gl->textVao);
    glDeleteBuffers(1, &gl->textVbo);
    free(gl->items);
    free(gl->instances);
    free(gl);
}

void RGLReleaseGraphic(RGraphic *rg)
{
    struct RGraphicPrivate *p = rg->m_private;
    struct RGL *gl = p->gl;
    if (!gl)
        return;
    gl->backend->makeCurrent(gl->backend); /* names belong to the context that made them */
    RMeshRelease(&gl->cache, p->mesh);
    p->mesh = NULL;
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

/* The graphic's mesh, made or renewed when its vertices changed: triangle lists share a mesh with
 * graphics of equal vertices, lines keep one of their own (they move). A graphic drawn by a second
 * context moves its mesh there. */
static void upload(struct RGL *gl, RGraphic *rg)
{
    struct RGraphicPrivate *p = rg->m_private;
    if (p->gl != gl) {
        RGLReleaseGraphic(rg);
        gl->backend->makeCurrent(gl->backend);
    }
    if (p->mesh && !p->dirty)
        return;
    if (p->mesh && RMeshUpdate(p->mesh, rg, &p->radius)) {
        p->dirty = 0;
        return;
    }
    RMeshRelease(&gl->cache, p->mesh);
    p->mesh = RMeshAcquire(&gl->cache, rg, p->kind == kRKindTriangles, &p->radius);
    if (!p->gl) {
        p->gl = gl;
        p->glPrev = NULL;
        p->glNext = gl->graphics;
        if (gl->graphics)
            gl->graphics->m_private->glPrev = rg;
        gl->graphics = rg;
    }
    p->dirty = p->mesh == NULL;
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

/* Plain graphics first, grouped by mesh, nearest the camera first within a mesh (what is hidden
 * then fails the depth test before it is shaded); then the others in list order. */
static int itemOrder(const void *a, const void *b)
{
    const RDrawItem *x = a, *y = b;
    if (x->plain != y->plain)
        return y->plain - x->plain;
    if (x->plain && x->mesh != y->mesh)
        return (uintptr_t)x->mesh < (uintptr_t)y->mesh ? -1 : 1;
    if (x->plain && x->depth != y->depth)
        return x->depth < y->depth ? -1 : 1;
    return x->order - y->order;
}

static void instanceData(const RGraphic *rg, float *d)
{
    const RObjectHeader *h = rg->m_pObject;
    /* Karma's matrices are row-vector (p·M): read as OpenGL's column-major they are the
     * column-vector matrices the shader multiplies. */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            d[4 * i + j] = (float)h->m_Matrix[i][j];
    memcpy(d + 16, h->m_ColorAmbient, 4 * sizeof(float));
    memcpy(d + 20, h->m_ColorDiffuse, 4 * sizeof(float));
    memcpy(d + 24, h->m_ColorSpecular, 3 * sizeof(float));
    d[27] = (float)h->m_SpecularPower;
    memcpy(d + 28, h->m_ColorEmissive, 4 * sizeof(float));
}

/* The texture a graphic is drawn with: its id when textures are on and it names one, else −1. */
static int textureOf(const RRender *rc, const RGraphic *rg)
{
    int id = rg->m_pObject->m_nTextureID;
    return rc->m_options.m_bTextures && id >= 0 && id < rc->m_private->textureCount ? id : -1;
}

/** A round graphic whose radius covers fewer pixels than these is drawn with its coarser copies. */
#define R_LOD_PIXELS_HALF 24.0
#define R_LOD_PIXELS_QUARTER 8.0

/* What to draw for rg at `depth` in front of the camera: itself, or a coarser copy when it is small
 * on the picture (its radius in pixels from the projection's vertical scale). */
static RGraphic *lodFor(const struct RGL *gl, const RRender *rc, RGraphic *rg, float depth)
{
    const struct RGraphicPrivate *p = rg->m_private;
    if (!p->lod[0] || !(depth > 0))
        return rg;
    /* A parallel projection (clip w = 1) draws the same size at every depth. */
    double perDepth = rc->m_ProjMatrix[3][3] != 0 ? 1.0 : 1.0 / depth;
    double pixels = p->lodExtent * rc->m_ProjMatrix[1][1] * 0.5 * gl->height * perDepth;
    if (pixels < R_LOD_PIXELS_QUARTER && p->lod[1])
        return p->lod[1];
    return pixels < R_LOD_PIXELS_HALF ? p->lod[0] : rg;
}

/* This frame's graphics: matrices copied from what they follow, meshes uploaded, batched, and the
 * instance data of all of them in one buffer. Returns 0 when out of memory. */
static int prepare(struct RGL *gl, RRender *rc)
{
    int n = 0;
    for (RGraphic *rg = rc->m_pRG_First; rg; rg = rg->m_pNext)
        n++;
    if (n > gl->itemCapacity) {
        RDrawItem *items = realloc(gl->items, sizeof *items * (size_t)n);
        float *instances = items ? realloc(gl->instances, sizeof(float) * R_INSTANCE_FLOATS * (size_t)n) : NULL;
        if (items)
            gl->items = items;
        if (!instances)
            return 0;
        gl->instances = instances;
        gl->itemCapacity = n;
    }
    int count = 0, order = 0;
    for (RGraphic *rg = rc->m_pRG_First; rg; rg = rg->m_pNext, order++) {
        RObjectHeader *h = rg->m_pObject;
        struct RGraphicPrivate *p = rg->m_private;
        if (h->m_nNumVertices <= 0)
            continue;
        /* Karma's composite matrix: the followed transform, copied in each frame. */
        if (rg->m_pLWMatrix)
            memcpy(h->m_Matrix, rg->m_pLWMatrix, sizeof h->m_Matrix);
        if (rg == rc->m_private->skydome) { /* the sky is as far away wherever the camera goes */
            AcmeVector3 eye;
            RCameraGetPosition(rc, eye);
            for (int k = 0; k < 3; k++)
                h->m_Matrix[3][k] = eye[k];
        }
        /* Eye-space z (negative in front): −z is the distance along the view direction. */
        const MeReal(*c)[4] = (const MeReal(*)[4])rc->m_CamMatrix, *t = h->m_Matrix[3];
        float depth = -(float)(t[0] * c[0][2] + t[1] * c[1][2] + t[2] * c[2][2] + c[3][2]);
        RGraphic *shape = lodFor(gl, rc, rg, depth);
        upload(gl, shape);
        if (!shape->m_private->mesh || shape->m_private->mesh->count <= 0)
            continue;
        RDrawItem *it = &gl->items[count++];
        it->g = rg, it->mesh = shape->m_private->mesh, it->order = order, it->depth = depth;
        it->plain = p->kind == kRKindTriangles && !p->unlit && p->checkerCell <= 0 && !h->m_bIsWireFrame &&
                    !rc->m_options.m_bWireFrame && h->m_ColorDiffuse[3] >= 1.0f && textureOf(rc, rg) < 0;
        it->casts = RShadowCasts(rg, rc);
    }
    if (count > 1) /* an empty list may have no array at all */
        qsort(gl->items, (size_t)count, sizeof *gl->items, itemOrder);
    for (int i = 0; i < count; i++)
        instanceData(gl->items[i].g, gl->instances + R_INSTANCE_FLOATS * i);
    glBindBuffer(GL_ARRAY_BUFFER, gl->cache.instances);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof(float) * R_INSTANCE_FLOATS * (size_t)(count ? count : 1)),
                 gl->instances, GL_STREAM_DRAW);
    gl->itemCount = count;
    gl->rc = rc;
    return 1;
}

/* The GL texture of the context's texture `id`, uploaded (with mipmaps, repeating) when first used. */
static GLuint textureFor(struct RGL *gl, const RRender *rc, int id)
{
    if (!gl->textures[id]) {
        const RTexture *t = &rc->m_private->textures[id];
        glGenTextures(1, &gl->textures[id]);
        glBindTexture(GL_TEXTURE_2D, gl->textures[id]);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t->width, t->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, t->rgba);
        glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    }
    return gl->textures[id];
}

/* The per-graphic state of a graphic drawn alone (lines, planes, wireframe, translucent, textured). */
static void setGraphicState(struct RGL *gl, const RGraphic *rg)
{
    const GLint *u = gl->u3;
    const struct RGraphicPrivate *p = rg->m_private;
    glUniform1i(u[U_UNLIT], p->kind == kRKindLines || p->unlit);
    glUniform1f(u[U_CHECKER], p->checkerCell);
    if (p->checkerCell > 0) {
        /* A ground plane's cells lie in its x–z plane, a square's in its x–y plane. */
        int ground = rg->m_pVertices[0].m_Y == 0 && rg->m_pVertices[1].m_Y == 0 && rg->m_pVertices[2].m_Y == 0;
        glUniform3f(u[U_CHECKER_U], 1, 0, 0);
        glUniform3f(u[U_CHECKER_V], 0, ground ? 0.0f : 1.0f, ground ? 1.0f : 0.0f);
    }
    int wire = rg->m_pObject->m_bIsWireFrame || gl->rc->m_options.m_bWireFrame;
    glPolygonMode(GL_FRONT_AND_BACK, wire ? GL_LINE : GL_FILL);
    int texture = textureOf(gl->rc, rg);
    glUniform1i(u[U_TEXTURED], texture >= 0);
    if (texture >= 0) {
        glActiveTexture(GL_TEXTURE0 + R_TEXTURE_UNIT);
        glBindTexture(GL_TEXTURE_2D, textureFor(gl, gl->rc, texture));
        glActiveTexture(GL_TEXTURE0);
    }
}

/* Draw the batches: each run of plain graphics sharing a mesh in one instanced call, the others one by one. */
static void drawBatches(void *data, int castersOnly)
{
    struct RGL *gl = data;
    const GLint *u = gl->u3;
    int plainState = 0;
    for (int i = 0, j; i < gl->itemCount; i = j) {
        const RDrawItem *it = &gl->items[i];
        for (j = i + 1; it->plain && j < gl->itemCount && gl->items[j].plain && gl->items[j].mesh == it->mesh; j++)
            ;
        if (castersOnly && !it->casts)
            continue;
        if (!castersOnly && !it->plain) {
            setGraphicState(gl, it->g);
            plainState = 0;
        } else if (!castersOnly && !plainState) {
            glUniform1i(u[U_UNLIT], 0);
            glUniform1i(u[U_TEXTURED], 0);
            glUniform1f(u[U_CHECKER], 0);
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            plainState = 1;
        }
        glBindVertexArray(it->mesh->vao);
        RGLInstanceAttributes(gl->cache.instances, sizeof(float) * R_INSTANCE_FLOATS * (size_t)i);
        GLenum mode = it->g->m_private->kind == kRKindLines ? GL_LINES : GL_TRIANGLES;
        glDrawArraysInstanced(mode, 0, it->mesh->count, j - i);
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glBindVertexArray(0);
}

/* The GL texture of a particle system's texture id: 0 (none) when textures are off or id is not one. */
static unsigned int nativeTexture(void *data, int id)
{
    struct RGL *gl = data;
    const RRender *rc = gl->rc;
    return rc->m_options.m_bTextures && id >= 0 && id < rc->m_private->textureCount ? textureFor(gl, rc, id) : 0;
}

static void draw3D(struct RGL *gl, RRender *rc)
{
    const GLint *u = gl->u3;
    float m[16];
    glUseProgram(gl->prog3D);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[4 * i + j] = (float)rc->m_CamMatrix[i][j];
    glUniformMatrix4fv(u[U_VIEW], 1, GL_FALSE, m);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            m[4 * i + j] = (float)rc->m_ProjMatrix[i][j];
    glUniformMatrix4fv(u[U_PROJ], 1, GL_FALSE, m);
    setLights(gl, rc);
    int shadows = gl->shadow && rc->m_DirectLight1.m_bUseLight && !rc->m_private->noShadows;
    glUniform1i(u[U_SHADOW_ON], shadows);
    glUniform1i(u[U_TEXTURE], R_TEXTURE_UNIT);
    if (shadows)
        RShadowBind(gl->shadow, u[U_SHADOW_VP], u[U_SHADOW_TEXEL], u[U_SHADOW_MAP], R_SHADOW_UNIT);
    drawBatches(gl, 0);
    RGLNativeDraw(gl->native, rc, nativeTexture, gl);
}

/* Text (one quad per glyph) and rectangles, in pixels, scaled from Karma's virtual 640×448 screen. */
static void draw2D(struct RGL *gl, RRender *rc)
{
    if (!rc->m_pRG_First2D)
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
        const struct RGraphicPrivate *p = rg->m_private;
        if (p->kind == kRKindRect2D) {
            float x0 = p->x * sx, y0 = p->y * sy, x1 = (p->x + p->w) * sx, y1 = (p->y + p->h) * sy;
            float v[24] = {x0, y0, 0, 0, x1, y0, 0, 0, x1, y1, 0, 0, x0, y0, 0, 0, x1, y1, 0, 0, x0, y1, 0, 0};
            glUniform1i(gl->u2Solid, 1);
            glUniform4fv(gl->u2Color, 1, rg->m_pObject->m_ColorDiffuse);
            glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
            glDrawArrays(GL_TRIANGLES, 0, 6);
            glUniform1i(gl->u2Solid, 0);
            continue;
        }
        const char *text = p->text;
        if (p->kind != kRKindText || !text || !*text || !gl->haveFont)
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
    int ready = prepare(gl, rc);
    if (ready && gl->shadow && rc->m_DirectLight1.m_bUseLight && !rc->m_private->noShadows)
        RShadowDraw(gl->shadow, rc, drawBatches, gl);
    glBindFramebuffer(GL_FRAMEBUFFER, gl->msFbo);
    glViewport(0, 0, gl->width, gl->height);
    const AcmeReal *bg = rc->m_backgroundColour;
    glClearColor((float)bg[0], (float)bg[1], (float)bg[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_MULTISAMPLE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    if (ready)
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
