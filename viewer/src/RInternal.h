/* RInternal.h -- what the viewer's files share: the private parts of a context and a graphic, and
 * the backends (window through GLFW, offscreen through EGL) behind one small interface. */
#ifndef R_INTERNAL_H
#define R_INTERNAL_H

#include <stddef.h>

#include <karma/MeMessage.h>

#include "MeViewer.h"

/** Report a coded message (docs/errors.md) from viewer function `fn`. */
#define R_REPORT(code, fn, ...) MeReport((code), (fn), __FILE__, __LINE__, __VA_ARGS__)

/** Whether rc and object are both given; when not, ME_ERR_NULL_ARGUMENT in fn's name ("NULL render
 *  context or <what>"). */
int RBothGiven(const RRender *rc, const void *object, const char *fn, const char *what);
/** A zeroed block of `size` bytes (the caller frees it), or NULL after ME_ERR_OUT_OF_MEMORY in fn's
 *  name ("no memory for <what>"). */
void *RZeroedOrReport(size_t size, const char *fn, const char *what);

/** Textures a context holds (Karma's limit). */
#define R_MAX_TEXTURES 25

/** A texture's pixels, kept by the context (RTexture.c). */
typedef struct RTexture {
    char name[128];          /**< as RRenderTextureCreate was given it */
    int width, height;
    unsigned char *rgba;     /**< bottom row first */
} RTexture;

/** Coarser copies a round graphic keeps for when it is small on the picture. */
#define R_LOD_LEVELS 2

/** What a graphic draws. */
typedef enum { kRKindTriangles, kRKindLines, kRKindText, kRKindRect2D } RGraphicKind;

struct RGraphicPrivate {
    RGraphicKind kind;
    int inList;              /**< 0 none, 1 the 3D list, 2 the 2D list */
    int dirty;               /**< vertices changed since the last upload */
    struct RMesh *mesh;      /**< the vertex buffer it draws (NULL until first drawn; shared when equal) */
    struct RGL *gl;          /**< the GL state that made it (NULL when none); it frees it when it goes */
    RGraphic *glPrev, *glNext; /**< in that state's list of graphics holding GL objects */
    float radius;            /**< of the sphere about the local origin holding the vertices (m) */
    float checkerCell;       /**< > 0: checkerboard of this cell size (local units) */
    char *text;              /**< kRKindText: the string */
    float x, y;              /**< kRKindText, kRKindRect2D: top left in the virtual 640×448 screen */
    float w, h;              /**< kRKindRect2D: size in the virtual screen */
    RGraphic *lod[R_LOD_LEVELS]; /**< spheres, sphyls: the same shape with 1/2 and 1/4 of the sides (in no list) */
    float lodExtent;         /**< their farthest point from the local origin (m) */
    int unlit;               /**< drawn in its colour (and texture) alone: no light, no shadow (the skydome) */
    RGraphic *part;          /**< the next graphic of the same model (an aggregate's elements, chained
                                  from the model's graphic): listed, coloured and destroyed with it */
};

typedef struct RBackend RBackend;

/** Where the last camera drag was (window pixels). */
typedef struct RDrag {
    int x, y, active;
} RDrag;

struct RRenderPrivate {
    int width, height;       /**< picture size in pixels */
    RBackend *backend;       /**< window or offscreen surface; NULL for the null renderer */
    struct RGL *gl;          /**< programs, framebuffers, font (RGL.c) */
    unsigned long frames;    /**< frames drawn or run */
    int singleStep;          /**< a single step is pending */
    int orthographic;        /**< RCameraSetOrthographic: parallel projection instead of perspective */
    int drawn;               /**< a frame has been drawn */
    RDrag drag;
    RGraphic *pausedText;    /**< "Paused", in the 2D list while paused */
    struct RMenu *menus;     /**< the application's menus (RMenuCreate) */
    struct RMenu *menuShown, *menuDefault, *menuViewer; /**< on screen; the m key's; F12's */
    char **help;             /**< the application's help lines, substituted */
    int helpCount, helpShown, pausedBeforeHelp, helpTextCount;
    RGraphic **helpText, *helpPanel;
    struct RPerformanceBar *perfBar;
    int showFps;             /**< RRun shows the frame rate */
    RGraphic *fpsText;
    double fps;              /**< frames a second, averaged over the last half second */
    int noShadows;           /**< the F12 menu turned shadows off */
    int frameLock;           /**< F3: at most R_LOCKED_RATE frames a second (a window: its refresh, vsync) */
    int aspectLock;          /**< Alt+F9: the projection keeps its aspect when the picture is resized */
    RGraphic *skydome;       /**< RRenderSkydomeCreate's sphere (in the 3D list), centred on the camera each frame */
    int lockRate;            /**< frames a second of the frame-rate lock without vsync (RRenderSetFrameLockRate) */
    int fullscreen;          /**< F9: the window covers its monitor (offscreen: only remembered) */
    unsigned int profileFrames; /**< -profile N: frames to profile (0: -timeout's, or 1,000) */
    struct RDebugDraw *debugDraw; /**< lines from MeDebugDrawAPI (RRenderSetDebugDrawing), or NULL */
    struct RNLine *nlines;   /**< every native line of the context (RNLine.c), listed or not */
    float *immediate;        /**< RLineAdd's lines: per end x y z r g b a (R_LINE_FLOATS floats) */
    int immediateEnds, immediateCapacity; /**< ends written, and room (ends) */
    RParticleSystem *particles; /**< the particle systems drawn (RParticleSystemAddToList) */
    int noParticles;         /**< the F12 menu turned particle systems off */
    RTexture textures[R_MAX_TEXTURES]; /**< RRenderTextureCreate's, by id */
    int textureCount;
    char title[128];
};

/* ---- RGraphic.c ---------------------------------------------------------------------------- */
/** A graphic of `kind` with room for n vertices, coloured, following matrix, put in the 3D list. */
RGraphic *RGraphicNew(RRender *rc, RGraphicKind kind, int n, const float color[4], MeMatrix4Ptr matrix);

/** A triangle mesh's triangles / a height field's cells (RGraphicTerrain.c), following matrix. */
RGraphic *RGraphicTriangleMeshCreate(RRender *rc, McdGeometryID g, const float color[4], MeMatrix4Ptr matrix);
RGraphic *RGraphicHeightFieldCreate(RRender *rc, McdGeometryID g, const float color[4], MeMatrix4Ptr matrix);

/** Replace a text graphic's string (copied). Returns 0, or −1 for anything but text. */
int RGraphicTextSet(RGraphic *rg, const char *text);
/** Move and size a 2D rectangle (virtual screen units; negative sizes become 0). */
void RRectangleSet(RGraphic *rg, float x, float y, float width, float height);

/* ---- RMenu.c, RHelp.c, RPerformanceBar.c ---------------------------------------------------- */
/** An entry of the viewer's own menu: with set < 0 returns its state (1, 0, or −1 for none); else
 *  acts (set 1: Right, 0: Left). */
typedef int (*RViewerEntryFn)(RRender *rc, int set);
/** Add an entry of the viewer's own (F12) menu. */
void RMenuAddViewerEntry(RMenu *rm, const char *name, RViewerEntryFn fn);
/** A key while a menu is shown: the arrows work it. Returns 1 when the menu took the key. */
int RMenuKey(RRender *rc, int key);
/** Hide the menu shown; show rm unless it was the one shown (NULL: only hide). */
void RMenuToggle(RRender *rc, RMenu *rm);
/** The context goes: menus lose their graphics and their context (the application still destroys its own). */
void RMenuContextGone(RRender *rc);
/** The context goes: help lines freed. */
void RHelpContextGone(RRender *rc);
/** The context goes: the performance bar freed. */
void RPerformanceBarDestroy(RRender *rc);
/** The context goes: the textures' pixels freed (RTexture.c). */
void RTexturesContextGone(RRender *rc);
/** Show the debug lines drawn since the last frame (RDebugDraw.c). */
void RDebugDrawFrame(RRender *rc);
/** The context goes or stops debug drawing: its lines freed, the hook silent again. */
void RDebugDrawDestroy(RRender *rc);
/** A debug-line hook that draws nothing. */
void MEAPI RDebugDrawNothing(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b);
/** The viewer's own menu (F12), made on first use. */
RMenu *RViewerMenu(RRender *rc);

/** Frames a second RRun keeps to by default when the frame rate is locked (F3) and no window's
 *  refresh paces it. */
#define R_LOCKED_RATE 60
/** The picture becomes width × height pixels (a window's framebuffer was resized): the framebuffers
 *  follow and, unless the aspect is locked (Alt+F9), the projection's aspect. Returns 0, or −1 (with
 *  a message, size unchanged) for a size outside 1 … 8192 or framebuffers that cannot be made. */
int RRenderResize(RRender *rc, int width, int height);
/** F3: lock or unlock the frame rate (a window's swap interval, else RRun's own pacing). */
void RRenderSetFrameRateLock(RRender *rc, int on);
/** F9: fullscreen on or off (a window only; offscreen the state is kept for when it matters). */
void RRenderSetFullscreen(RRender *rc, int on);

/* ---- RNLine.c, RParticles.c, RGLNative.c: native lines and particles ------------------------ */
/** Floats per line end handed to the GL: position, then colour (RGBA). */
#define R_LINE_FLOATS 7
/** Every line end to draw this frame (the native lines listed, transformed to world, then RLineAdd's)
 *  into *ends (grown as needed, R_LINE_FLOATS floats an end, *capacity ends of room). Returns the
 *  count of ends, or −1 when out of memory. */
int RNLineGather(RRender *rc, float **ends, int *capacity);
/** The context goes: its native lines and RLineAdd's freed, its particle systems' list emptied
 *  (and them freed: as graphics in the lists, they go with the context). */
void RNLineContextGone(RRender *rc);
void RParticlesContextGone(RRender *rc);
/** Programs and buffers for native lines and particles (the GL context current); NULL with a message. */
struct RGLNative *RGLNativeCreate(void);
void RGLNativeDestroy(struct RGLNative *n);
/** Draw rc's native lines and particle systems into the bound framebuffer (view and projection from
 *  the camera); `texture` gives a texture id's GL name (0: none). */
void RGLNativeDraw(struct RGLNative *n, RRender *rc, unsigned int (*texture)(void *data, int id), void *data);

/* ---- RCamera.c ----------------------------------------------------------------------------- */
/** Karma's default camera and projection for a context whose size is set. */
void RCameraSetDefaults(RRender *rc);

/* ---- RLight.c ------------------------------------------------------------------------------ */
/** Karma's default lights. */
void RLightSetDefaults(RRender *rc);

/* ---- RGL.c: drawing with OpenGL 3.3 core (a context must be current) ------------------------ */
/** Programs, framebuffers and the font for a picture of width × height, in the context `backend`
 *  makes current; NULL with a message. */
struct RGL *RGLCreate(RBackend *backend, int width, int height);
/** Free the GL objects, those of every graphic drawn with it too (which stay usable: they upload
 *  again when drawn by another context). */
void RGLDestroy(struct RGL *gl);
/** Remake the framebuffers at width × height (the context current); 0, or −1 when they cannot be made. */
int RGLResize(struct RGL *gl, int width, int height);
/** Draw every graphic of both lists into the multisampled framebuffer, resolve it into the picture
 *  RGLReadPixels reads and, with toWindow, copy it to the window's framebuffer. */
void RGLDrawFrame(struct RGL *gl, RRender *rc, int toWindow);
/** A program from a vertex and a fragment shader's sources; 0 with a message. */
unsigned int RGLLink(const char *vertexSource, const char *fragmentSource);
/** Point the bound vertex array's per-instance attributes (2–5 the model matrix, 6–9 the
 *  material) at `offset` bytes into the instance buffer `buffer`. */
void RGLInstanceAttributes(unsigned int buffer, size_t offset);
/** Draws the frame's batches; castersOnly: only those that cast shadows, without material state. */
typedef void (*RGLBatchDraw)(void *data, int castersOnly);
/** Read the resolved picture (RGBA, top row first). */
void RGLReadPixels(struct RGL *gl, unsigned char *rgba);
/** Free a graphic's GL objects in the context that made them (nothing when it has none). */
void RGLReleaseGraphic(RGraphic *rg);

/* ---- RMesh.c: vertex buffers shared by graphics of equal vertices ------------------------- */
typedef struct RMesh {
    unsigned long long hash; /**< of the vertex bytes */
    int count;               /**< vertices */
    int shared, refs;        /**< found by its vertices (triangle graphics); graphics holding it */
    float *data;             /**< the bytes, to compare (shared meshes) */
    unsigned int vao, vbo;
    struct RMesh *next;      /**< in the cache (shared meshes) */
} RMesh;
typedef struct RMeshCache {
    RMesh *meshes;           /**< shared meshes */
    unsigned int instances;  /**< the per-instance buffer every mesh's vertex array reads */
} RMeshCache;
/** The mesh of rg's vertices: with `shared`, one already made from equal vertices (one more
 *  holder) or a new one; else one of its own. Its radius in *radius. NULL when out of memory. */
RMesh *RMeshAcquire(RMeshCache *cache, const RGraphic *rg, int shared, float *radius);
/** Rewrite an unshared mesh from rg's vertices; 0 (nothing done) for a shared one. */
int RMeshUpdate(RMesh *m, const RGraphic *rg, float *radius);
/** One holder fewer; freed with the last (NULL is accepted). */
void RMeshRelease(RMeshCache *cache, RMesh *m);

/* ---- RShadow.c: the key light's shadow map ------------------------------------------------- */
/** Depth map, its framebuffer and program; NULL when they cannot be made (no shadows then). */
struct RShadow *RShadowCreate(void);
void RShadowDestroy(struct RShadow *s);
/** Whether a graphic casts a shadow: filled triangles but checkerboard planes (the ground). */
int RShadowCasts(const RGraphic *rg, const RRender *rc);
/** Draw the map from directional light 1 over the region the camera looks at; `draw` draws the casters. */
void RShadowDraw(struct RShadow *s, RRender *rc, RGLBatchDraw draw, void *data);
/** Bind the map on texture `unit` and set the lit program's uniforms (light matrix, texel size, sampler). */
void RShadowBind(const struct RShadow *s, int uLightVP, int uTexel, int uMap, int unit);

/* ---- backends ------------------------------------------------------------------------------ */
/** An offscreen OpenGL 3.3 core context through EGL (RBackendEGL.c); NULL with a message. */
RBackend *RBackendEGLCreate(void);
/** A window with an OpenGL 3.3 core context through GLFW (RBackendGLFW.c); NULL with a message. */
RBackend *RBackendGLFWCreate(RRender *rc, int width, int height, const char *title);

struct RBackend {
    void (*destroy)(RBackend *b);
    /** Make the context current. */
    void (*makeCurrent)(RBackend *b);
    /** Poll input and call the context's handlers; returns 0 when the window should close. */
    int (*poll)(RBackend *b, RRender *rc);
    /** Show the frame drawn (windows); NULL offscreen. */
    void (*present)(RBackend *b);
    void (*setTitle)(RBackend *b, const char *title);
    /** Windows: vsync on or off (the frame-rate lock); NULL offscreen (RRun paces itself). */
    void (*setSwapInterval)(RBackend *b, int interval);
    /** Windows: cover the primary monitor, or back to the window's size and place; NULL offscreen. */
    void (*setFullscreen)(RBackend *b, int on);
    int drawsToWindow;
};

/* ---- RInput.c: Karma's PC key map and mouse ----------------------------------------------- */
/** Key codes the backends translate to (GLFW's values for printable keys: their ASCII capitals). */
enum {
    RKEY_ESCAPE = 256, RKEY_ENTER = 257, RKEY_RIGHT = 262, RKEY_LEFT = 263, RKEY_DOWN = 264, RKEY_UP = 265,
    RKEY_PAGE_UP = 266, RKEY_PAGE_DOWN = 267, RKEY_F1 = 290, RKEY_F2 = 291, RKEY_F3 = 292, RKEY_F4 = 293, RKEY_F8 = 297, RKEY_F9 = 298,
    RKEY_F12 = 301, RKEY_KP_ADD = 334,
    RKEY_KP_SUBTRACT = 333
};
/** A key pressed with modifiers (RCONTROL, RSHIFT, RALT): Karma's key map. */
void RInputKey(RRender *rc, int key, int modifiers);
/** A mouse button pressed or released at (x, y) window pixels. */
void RInputMouseButton(RRender *rc, int x, int y, int modifiers, RMouseButtonWhich which, RMouseButtonEvent event);
/** The mouse moved to (x, y) with buttons held (`buttons` bit k−1 for RMouseButtonWhich k). */
void RInputMouseMove(RRender *rc, int x, int y, int modifiers, int buttons);

#endif /* R_INTERNAL_H */
