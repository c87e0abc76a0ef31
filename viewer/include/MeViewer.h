/* MeViewer.h -- Karma's viewer: render contexts, graphics that follow bodies' matrices, the orbit
 * camera, lights, text, callbacks and the main loop, under Karma 1.2's names (library karma_viewer,
 * OpenGL 3.3 core; the core library karma never depends on it).
 *
 * A Karma program:
 *     options = MeCommandLineOptionsCreate(argc, argv);
 *     rc = RRenderContextCreate(options, 0, !MEFALSE);
 *     MeCommandLineOptionsDestroy(options);
 *     g = RGraphicBoxCreate(rc, 1, 1, 1, red, MdtBodyGetTransformPtr(body));
 *     RRun(rc, tick, 0);                 (tick steps the physics; the viewer draws after each tick)
 *     RRenderContextDestroy(rc);
 *
 * Units are the application's (metres), angles radians, colours RGBA floats in [0, 1]. 2D positions
 * (text) are in Karma's virtual 640×448 screen, origin at the top left, whatever the real size.
 * Additions of this library (not in Karma 1.2) are marked so and listed in docs/api_changes.md. */
#ifndef ME_VIEWER_H
#define ME_VIEWER_H

#include <karma/MePrecision.h>
#include <karma/McdTypes.h>

#include "MeCommandLine.h"
#include "MeViewerTypes.h"

ME_EXTERN_C_BEGIN

/* ---- render context ------------------------------------------------------------------------ */

/** A context from command-line options (either may be NULL; `overrideoptions` win): -gl (window,
 *  the default), -null (no drawing), -headless (offscreen through EGL, no display needed), -size WxH,
 *  -timeout N (RRun returns after N frames), -wireframe, -notextures. With `eat` the options read are
 *  removed from `options`. Window 640×448, camera at distance 15 from look-at (0, 0, 1), θ = φ = 0,
 *  vertical half-angle π/6, black background, Karma's lights. NULL (with a message) when no window
 *  or surface can be made. */
RRender *MEAPI RRenderContextCreate(MeCommandLineOptions *options, MeCommandLineOptions *overrideoptions, int eat);
/** Addition: an offscreen context of width × height pixels (1 … 8192) without a display (EGL on
 *  Mesa); NULL with a message when EGL or OpenGL 3.3 is not available. */
RRender *MEAPI RRenderContextCreateHeadless(int width, int height);
/** Destroy the context, its graphics and its window or surface. Returns 0 (NULL is accepted). */
int MEAPI RRenderContextDestroy(RRender *rc);
/** Run: each frame handle input, call `func` (unless paused; once per single step), draw. Returns
 *  when the window closes, Esc is pressed, RRenderQuit is called or -timeout frames have passed. */
void MEAPI RRun(RRender *rc, RMainLoopCallBack func, void *userdata);
/** Make RRun return after the current frame. */
void MEAPI RRenderQuit(RRender *rc);
/** Pause (p ≠ 0) or resume: while paused RRun draws, with "Paused" at the top right, but does not
 *  call its callback; F8 steps once. */
void MEAPI RRenderSetPause(RRender *rc, int p);
/** Addition: while paused, let RRun call its callback once more (what F8 does). */
void MEAPI RRenderSingleStep(RRender *rc);
/** The window's title (copied). */
void MEAPI RRenderSetWindowTitle(RRender *rc, const char *title);
/** The name substituted for $APPNAME in help text (copied, at most 39 characters). */
void MEAPI RRenderSetAppName(RRender *rc, const char *appname);
/** Addition: draw one frame now (offscreen for headless contexts, into the window otherwise). */
void MEAPI RRenderDrawFrame(RRender *rc);
/** Addition: size of the picture in pixels. */
void MEAPI RRenderGetSize(RRender *rc, int *width, int *height);
/** Addition: parses "WxH" (the -size option) into a width and height of 1 to 8192 pixels; MEFALSE, and nothing
 *  written, for anything else. */
MeBool MEAPI RRenderParseSize(const char *text, int *width, int *height);
/** Addition: read the last frame drawn as RGBA bytes, top row first, into `rgba` (width·height·4
 *  bytes). Returns 0, or −1 for a null context or one that has not drawn. */
int MEAPI RRenderReadPixels(RRender *rc, unsigned char *rgba);
/** Addition: write the last frame drawn to a PNG file. Returns 0, or −1 with a message. */
int MEAPI RRenderSavePNG(RRender *rc, const char *filename);
/** Redraw everything as wireframe (b true) or filled. */
void MEAPI RRenderSetWireframe(RRender *rc, MeBool b);

/* ---- graphics ------------------------------------------------------------------------------ */

/** An empty triangle list of room for numVertices vertices, in no list (NULL when out of memory). */
RGraphic *MEAPI RGraphicCreateEmpty(int numVertices);
/** Box of full extents width (x) × height (y) × depth (z), centred; follows `matrix` when not NULL. */
RGraphic *MEAPI RGraphicBoxCreate(RRender *rc, AcmeReal width, AcmeReal height, AcmeReal depth,
                                  const float color[4], MeMatrix4Ptr matrix);
/** Sphere of `radius` centred on the origin. */
RGraphic *MEAPI RGraphicSphereCreate(RRender *rc, AcmeReal radius, const float color[4], MeMatrix4Ptr matrix);
/** Cylinder of `radius` and total `height` along z, centred. */
RGraphic *MEAPI RGraphicCylinderCreate(RRender *rc, AcmeReal radius, AcmeReal height, const float color[4],
                                       MeMatrix4Ptr matrix);
/** Cone along z: base disc of `radius` at z = −lower_height, apex at z = upper_height. */
RGraphic *MEAPI RGraphicConeCreate(RRender *rc, AcmeReal radius, AcmeReal upper_height, AcmeReal lower_height,
                                   const float color[4], MeMatrix4Ptr matrix);
/** Truncated cone along z from z = bottom (bottomRadius) to z = top (topRadius) with `sides` sides. */
RGraphic *MEAPI RGraphicFrustumCreate(RRender *rc, AcmeReal bottomRadius, AcmeReal topRadius, AcmeReal bottom,
                                      AcmeReal top, int sides, const float color[4], MeMatrix4Ptr matrix);
/** Sphyl (capsule) along z: a cylinder part of `height` between two hemispheres of `radius`. */
RGraphic *MEAPI RGraphicSphylCreate(RRender *rc, AcmeReal radius, AcmeReal height, const float color[4],
                                    MeMatrix4Ptr matrix);
/** Torus about z: tube radius innerRadius, centre-line radius outerRadius. */
RGraphic *MEAPI RGraphicTorusCreate(RRender *rc, AcmeReal innerRadius, AcmeReal outerRadius, const float color[4],
                                    MeMatrix4Ptr matrix);
/** Square of `side` in the local x–y plane (normal +z), centred, drawn with a checkerboard of cells
 *  side/8 (the plane of a model). */
RGraphic *MEAPI RGraphicSquareCreate(RRender *rc, AcmeReal side, const float color[4], MeMatrix4Ptr matrix);
/** Ground: a square of side_length in the x–z plane at height y_position (normal +y), triangles_per_side
 *  cells of a checkerboard along each side. */
RGraphic *MEAPI RGraphicGroundPlaneCreate(RRender *rc, AcmeReal side_length, int triangles_per_side,
                                          const float color[4], AcmeReal y_position);
/** A line segment from origin to end (unlit). */
RGraphic *MEAPI RGraphicLineCreate(RRender *rc, AcmeReal origin[3], AcmeReal end[3], const float color[4],
                                   MeMatrix4Ptr matrix);
/** Move a line's ends. Returns 0, or −1 when lineG is not a line. */
int MEAPI RGraphicLineMoveEnds(RGraphic *lineG, AcmeReal *origin, AcmeReal *end);
/** Text at (orig_x, orig_y) in the virtual 640×448 screen (top left of the text), in the 2D list. */
RGraphic *MEAPI RGraphicTextCreate(RRender *rc, char *text, AcmeReal orig_x, AcmeReal orig_y, const float color[4]);
/** The graphic of a model's geometry (sphere, box, cylinder, cone, sphyl, plane, convex mesh,
 *  triangle mesh, height field), following the model's transform. An aggregate model's graphic
 *  holds no vertices: a graphic for each element follows that element's geometry instance (its
 *  world transform at the model's last update, nested aggregates included) and goes with it (lists,
 *  colour, wireframe, delete). NULL (with a message) for a geometry type it cannot draw. */
RGraphic *MEAPI RGraphicCreateFromModel(RRender *rc, McdModelID m, float color[4]);
/** The graphic of a geometry in its own frame (no matrix followed: set one with
 *  RGraphicSetTransformPtr), as Karma 1.2's; an aggregate as RGraphicAggregateCreate. NULL (with a
 *  message) for a type it cannot draw (a triangle list: its triangles exist only in queries). */
RGraphic *MEAPI RGraphicCreateFromGeometry(RRender *rc, McdGeometryID g, float color[4]);
/** One graphic of all of aggregate ag's elements placed by their relative transforms (nested ones
 *  composed) as they are now, following `tm`, as Karma 1.2's. NULL (with a message) for a NULL
 *  context or a geometry that is not an aggregate. */
RGraphic *MEAPI RGraphicAggregateCreate(RRender *rc, McdAggregateID ag, float color[4], MeMatrix4Ptr tm);

/** Load a texture (BMP, PNG or another format stb_image reads) from `filename`, tried as given, then
 *  with ".bmp" and ".png" when it has no extension (Karma names textures without one); the same
 *  name twice gives the same texture. Returns its id (0 … 24), or −1 with a message (unreadable, or
 *  25 textures already). */
int MEAPI RRenderTextureCreate(RRender *rc, const char *filename);
/** Texture a graphic (RRenderTextureCreate's file names): the image, at the graphic's texture
 *  coordinates, multiplies its colour (unless -notextures). Returns the texture id, or −1 with a
 *  message (the graphic unchanged). */
int MEAPI RGraphicSetTexture(RRender *rc, RGraphic *rg, const char *filename);

/** Put a graphic in the 3D (is2D = 0) or 2D list (primitives are put there when created). */
void MEAPI RGraphicAddToList(RRender *rc, RGraphic *rg, int is2D);
/** Take a graphic out of its list (it is kept, hidden). */
void MEAPI RGraphicRemoveFromList(RRender *rc, RGraphic *rg, int is2D);
/** Free a graphic that is in no list (NULL is accepted). */
void MEAPI RGraphicDestroy(RGraphic *rg);
/** Take a graphic out of its list and free it. */
void MEAPI RGraphicDelete(RRender *rc, RGraphic *rg, int is2D);
/** Follow `matrix` (a body's or model's transform; NULL: the graphic's own m_Matrix). */
void MEAPI RGraphicSetTransformPtr(RGraphic *g, MeMatrix4Ptr matrix);
/** Colour (ambient and diffuse from it, alpha < 1 blends). */
void MEAPI RGraphicSetColor(RGraphic *g, const float color[4]);
/** The graphic's colour. */
void MEAPI RGraphicGetColor(RGraphic *g, float color[4]);
/** Draw this graphic as wireframe (b true) or filled. */
void MEAPI RGraphicSetWireframe(RGraphic *g, MeBool b);
/** Whether the graphic is drawn as wireframe (its own flag; MEFALSE for NULL). */
MeBool MEAPI RGraphicIsWireframe(RGraphic *g);
/** Move every vertex of rg by offset (local frame; rc is not used, as in 1.2). A NULL or non-finite
 *  offset is refused. */
void MEAPI RGraphicTranslateVertices(RRender *rc, RGraphic *rg, MeVector3 offset);
/** A new graphic (in rc's 3D list) of first's triangles and second's placed by secondTM (local to
 *  first; NULL: as they are), with first's colour, texture and followed matrix; first and second are
 *  left as they are (1.2's aggregate helper deletes them). NULL with a message for a NULL argument
 *  or a graphic that is not triangles. */
RGraphic *MEAPI RGraphicCombine(RRender *rc, RGraphic *first, RGraphic *second, MeMatrix4Ptr secondTM);
/** Scale a graphic's vertices along its local axes (each factor finite and non-zero; others refused
 *  with ME_ERR_ARGUMENT_RANGE, nothing changed); normals follow (inverse scale, renormalised). */
void MEAPI RGraphicScale(RGraphic *rg, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale);
/** Write numStrips triangle strips (strip i: stripSize[i] vertices from strips[stripStart[i]]) into
 *  rg's vertices as a triangle list, every triangle with the first one's winding (a strip's odd
 *  triangles are turned); a strip of n vertices gives n − 2 triangles. Refused (ME_ERR_ARGUMENT_RANGE,
 *  nothing written) when they do not fit in rg's m_nMaxNumVertices; sets its vertex count. */
void MEAPI RConvertTriStripToTriList(RGraphic *rg, RObjectVertex *strips, int *stripSize, int *stripStart, int numStrips);

/** Load a Karma object file (.meg: a vertex count, then 8 numbers per vertex, each written
 *  "label:number"; see docs/viewer.md) as a triangle graphic in no list, white, following no matrix.
 *  NULL with ME_ERR_VIEWER_BAD_MEG for a file missing, unreadable, truncated, with a number that is
 *  not finite or a count that disagrees with the numbers. */
RGraphic *MEAPI RGraphicLoadMEG(char *filename);
/** Write a triangle graphic's vertices (local frame, as they are now) to a .meg file that
 *  RGraphicLoadMEG reads back exactly. Returns 0, or −1 with a message (not a triangle list, file
 *  not writable). */
int MEAPI RGraphicSave(RGraphic *rg, char *filename);
/** Centre a graphic's bounding box on its local origin and fit it to [−1, 1] on each axis (the
 *  longest axis only, the others in proportion, when bKeepAspectRatio): the size RGraphicCreate's
 *  scales multiply (a cube loaded and scaled by w/2 is w wide). A flat axis is left flat. */
void MEAPI RGraphicNormalize(RGraphic *rg, int bKeepAspectRatio);
/** A graphic from a .meg file (RGraphicLoadMEG), coloured `color`, following `matrix`: normalised
 *  (RGraphicNormalize, unless is2D), scaled by (xScale, yScale, zScale) and put in the 2D (is2D) or
 *  3D list. NULL with a message for a bad file, a NULL context or a scale not finite or 0. */
RGraphic *MEAPI RGraphicCreate(RRender *rc, char *filename, AcmeReal xScale, AcmeReal yScale, AcmeReal zScale,
                               const float color[4], MeMatrix4Ptr matrix, int is2D, int bKeepAspectRatio);

/** A filled rectangle in the 2D list at (orig_x, orig_y) (top left) of width × height, in the
 *  virtual 640×448 screen; alpha < 1 blends. */
RGraphic *MEAPI RGraphic2DRectangleCreate(RRender *rc, AcmeReal orig_x, AcmeReal orig_y, AcmeReal width,
                                          AcmeReal height, const float color[4]);

/* ---- menus, help, performance bar ---------------------------------------------------------- */

/** An empty menu titled `name`, shown with RMenuDisplay or, as the default menu, with the menu key
 *  (m). While shown, Up and Down choose an entry; Right and Left flip a toggle, raise or lower a
 *  value, open a submenu. Destroy it with RMenuDestroy (before or after the context). */
RMenu *MEAPI RMenuCreate(RRender *rc, const char *name);
/** Free a menu (hidden first if shown; submenu entries pointing at it then open nothing). */
void MEAPI RMenuDestroy(RMenu *rm);
/** The menu the menu key (m, action 1) shows and hides; NULL: none (the key calls action 1). */
void MEAPI RRenderSetDefaultMenu(RRender *rc, RMenu *menu);
/** Show a menu (hiding the one shown). */
void MEAPI RMenuDisplay(RMenu *rm);
/** An entry flipped by Right or Left; func (may be NULL) gets the new state. */
void MEAPI RMenuAddToggleEntry(RMenu *rm, const char *name, RMenuToggleCallback func, MeBool defaultValue);
/** An entry raised (Right) or lowered (Left) by increment (> 0) within [lo, hi]; func gets the new
 *  value; the default is brought within the bounds. lo > hi or increment ≤ 0 is refused. */
void MEAPI RMenuAddValueEntry(RMenu *rm, const char *name, RMenuValueCallback func, MeReal hi, MeReal lo,
                              MeReal increment, MeReal defaultValue);
/** An entry that shows `submenu` when chosen. */
void MEAPI RMenuAddSubmenuEntry(RMenu *rm, const char *name, RMenu *submenu);

/** Copy text_in to text_out (at most outbuffersize bytes with the final 0) with Karma's names
 *  replaced by this key map's keys: $UP $DOWN $LEFT $RIGHT (arrows), $UP2 $DOWN2 $LEFT2 $RIGHT2
 *  (w s a d), $ACTION0 … $ACTION5 (h m and the keys of actions 2–5), $MOUSE, $JOYSTICK, $APPNAME. */
void MEAPI RParseText(RRender *rc, const char *text_in, char *text_out, int outbuffersize);
/** The help F1 shows: arraySize lines (at most 40, each substituted by RParseText and copied). */
void MEAPI RRenderCreateUserHelp(RRender *rc, char *help[], int arraySize);
/** Show or hide the help; the simulation pauses while it is shown. */
void MEAPI RRenderToggleUserHelp(RRender *rc);

/** The performance bar at the bottom of the picture (one a context; made once, then returned):
 *  RRun feeds it each frame from MeProfile's "Collision" and "Dynamics" sections (the application
 *  times them, MeProfileStartSection) and its own rendering and idle times. */
RPerformanceBar *MEAPI RPerformanceBarCreate(RRender *rc);
/** Show these times of the last frame (ms): collision, dynamics, rendering, idle. */
void MEAPI RPerformanceBarUpdate(RRender *rc, AcmeReal coltime, AcmeReal dyntime, AcmeReal rentime, AcmeReal idletime);
/** Show "FPS: fps" at the top left. */
void MEAPI RRenderDisplayFps(RRender *rc, AcmeReal fps);
/** Have RRun show the frame rate it measures (Ctrl+F3 flips it). */
void MEAPI RRenderSetDisplayFps(RRender *rc, int bVal);
/** Lock the frame rate or unlock it (F3): a window waits for its display's refresh (vsync, on when
 *  it opens); without a window RRun keeps its frames 1/rate s apart (off when it starts). */
void MEAPI RRenderToggleFrameLock(RRender *rc);
/** The locked rate without a window's refresh, frames a second (1 … 1000; 60 until set); others
 *  refused (ME_ERR_ARGUMENT_RANGE, unchanged). */
void MEAPI RRenderSetFrameLockRate(RRender *rc, unsigned int iRate);
/** A sky: a sphere textured with `name` (as RRenderTextureCreate finds it) repeated tileU times
 *  around and tileV times from pole to pole, drawn unlit and without shadows, always centred on the
 *  camera (400 m away, inside the far plane). One a context: a second call replaces it. An
 *  unreadable texture or tiles below 1 are refused (with a message, no sky). */
void MEAPI RRenderSkydomeCreate(RRender *const rc, const char *name, int tileU, int tileV);

/** Addition: show Karma's debug lines (MeDebugDraw.h: MdtWorldSetDebugDrawing's contacts,
 *  McduDebugDraw*'s shapes and boxes) in this context: MeDebugDrawAPI.line collects the lines drawn
 *  between two frames and the next frame shows them (one context at a time: the hook is
 *  process-wide). MEFALSE stops it and silences the hook. */
void MEAPI RRenderSetDebugDrawing(RRender *rc, MeBool on);

/* ---- lights -------------------------------------------------------------------------------- */

/** Switch a light on: the ambient light, directional lights 1 and 2, the point light. */
void MEAPI RLightSwitchOn(RRender *rc, RRenderLight light);
/** Switch a light off. */
void MEAPI RLightSwitchOff(RRender *rc, RRenderLight light);

/* ---- camera -------------------------------------------------------------------------------- */

/** Orbit the look-at point at distance `dist` (≥ 0.01), rotation θ about y from +z and elevation φ. */
void MEAPI RCameraSetView(RRender *rc, AcmeReal dist, AcmeReal theta, AcmeReal phi);
/** The point the camera looks at. */
void MEAPI RCameraSetLookAt(RRender *rc, const AcmeVector3 lookAt);
/** The point the camera looks at. */
void MEAPI RCameraGetLookAt(RRender *rc, AcmeVector3 camlookat);
/** Place the camera at `position` looking at `lookAt` (distance, θ and φ follow). */
void MEAPI RCameraSetLookAtAndPosition(RRender *rc, const MeVector3 lookAt, const MeVector3 position);
/** The camera's position in the world. */
void MEAPI RCameraGetPosition(RRender *rc, AcmeVector3 pos);
/** Distance from the look-at point. */
AcmeReal MEAPI RCameraGetDistance(RRender *rc);
/** Elevation φ (rad). */
AcmeReal MEAPI RCameraGetElevation(RRender *rc);
/** Rotation θ (rad). */
AcmeReal MEAPI RCameraGetRotation(RRender *rc);
/** Set the elevation φ (rad, kept within ±(π/2 − 0.001)). */
void MEAPI RCameraSetElevation(RRender *rc, const MeReal elevation);
/** The camera's up vector in the world. */
void MEAPI RCameraGetUp(RRender *rc, AcmeVector3 up);
/** The world-to-eye matrix (Karma's row convention). */
void MEAPI RCameraGetMatrix(RRender *rc, MeMatrix4Ptr m);
/** Half of the vertical field of view (rad, in (0, π/2)). */
void MEAPI RCameraSetFov(RRender *rc, AcmeReal fov);
/** Move the look-at point (and the camera) by dist along the camera's right vector. */
void MEAPI RCameraPanX(RRender *rc, AcmeReal dist);
/** Move the look-at point by dist along the world's up (y). */
void MEAPI RCameraPanY(RRender *rc, AcmeReal dist);
/** Move the look-at point by dist along the view direction projected on the ground. */
void MEAPI RCameraPanZ(RRender *rc, AcmeReal dist);
/** Add d_theta to the rotation θ. */
void MEAPI RCameraRotateAngle(RRender *rc, AcmeReal d_theta);
/** Add d_phi to the elevation φ. */
void MEAPI RCameraRotateElevation(RRender *rc, AcmeReal d_phi);
/** Move dist closer to the look-at point (the distance stays ≥ 0.01). */
void MEAPI RCameraZoom(RRender *rc, AcmeReal dist);
/** Recompute the camera and projection matrices (the setters above call it). */
void MEAPI RCameraUpdate(RRender *rc);
/** Set θ, the rotation about y from +z (rad); rejects a non-finite value. */
void MEAPI RCameraSetRotation(RRender *rc, const MeReal rotation);
/** Set the camera's distance from the look-at point (m, at least 0.01); rejects a non-finite value. */
void MEAPI RCameraSetOffset(RRender *rc, const MeReal offset);
/** Unit vector (world) along which the camera looks, read from the camera matrix. */
void MEAPI RCameraGetLookDir(RRender *rc, AcmeVector3 dir);
/** Set the world → eye matrix directly (copied; rejects non-finite entries); the next camera move
 *  (or RCameraUpdate) recomputes it from the orbit. */
void MEAPI RCameraSetMatrix(RRender *rc, MeMatrix4Ptr m);
/** The orbit camera's preset views: the camera on the named side of the look-at point. */
typedef enum {
    kRCameraFront, /**< on +z, looking along −z */
    kRCameraBack,  /**< on −z */
    kRCameraLeft,  /**< on −x */
    kRCameraRight, /**< on +x */
    kRCameraTop,   /**< above (+y), looking down */
    kRCameraBottom /**< below (−y) */
} RCameraPreset;
/** Put the camera on a preset side of the look-at point, distance and look-at kept (new: 1.2's
 *  header has no preset function); rejects an unknown preset. */
void MEAPI RCameraSetPreset(RRender *rc, RCameraPreset preset);
/** Parallel projection (on) or perspective (off); orthographic shows the height the perspective shows
 *  at the look-at point, whatever the depth (new, not in 1.2's header). */
void MEAPI RCameraSetOrthographic(RRender *rc, MeBool on);
/** Whether the projection is orthographic. */
MeBool MEAPI RCameraIsOrthographic(RRender *rc);

/* ---- input callbacks ----------------------------------------------------------------------- */

/** Called when the Up arrow is pressed (Karma's Up button). */
void MEAPI RRenderSetUpCallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Called when the Down arrow is pressed (Karma's Down button). */
void MEAPI RRenderSetDownCallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Called when the Left arrow is pressed (Karma's Left button). */
void MEAPI RRenderSetLeftCallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Called when the Right arrow is pressed (Karma's Right button). */
void MEAPI RRenderSetRightCallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Called when w is pressed (Karma's Up2 button). */
void MEAPI RRenderSetUp2CallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Called when s is pressed (Karma's Down2 button). */
void MEAPI RRenderSetDown2CallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Called when a is pressed (Karma's Left2 button). */
void MEAPI RRenderSetLeft2CallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Called when d is pressed (Karma's Right2 button). */
void MEAPI RRenderSetRight2CallBack(RRender *rc, RButtonPressCallBack func, void *userdata);
/** Action N (0–5): keys h, m, Enter, Space, o, p by default. N out of range is reported and ignored. */
void MEAPI RRenderSetActionNCallBack(RRender *rc, int N, RButtonPressCallBack func, void *userdata);
/** The key of action N (2–5 only; a printable character). */
void MEAPI RRenderSetActionNKey(RRender *rc, const unsigned int N, const char key);
/** Mouse events with Ctrl, Shift or Alt held go to `func` (without a modifier the mouse moves the camera). */
void MEAPI RRenderSetMouseCallBack(RRender *rc, RMouseCallBack func, void *userdata);

/* ---- callbacks with help text (1.2's ...WithText) ------------------------------------------- */
/* `text` (NULL: none) is shown in the help (F1) after the application's lines as "key - text"; the
 * string is kept, not copied, as in 1.2: it must live as long as the callback is set. */

void MEAPI RRenderSetUpCallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
void MEAPI RRenderSetDownCallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
void MEAPI RRenderSetLeftCallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
void MEAPI RRenderSetRightCallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
void MEAPI RRenderSetUp2CallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
void MEAPI RRenderSetDown2CallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
void MEAPI RRenderSetLeft2CallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
void MEAPI RRenderSetRight2CallBackWithText(RRender *rc, RButtonPressCallBack func, void *userdata, char *text);
/** Action N (0–5) with help text; N out of range is reported (ME_ERR_ARGUMENT_RANGE) and ignored. */
void MEAPI RRenderSetActionNCallBackWithText(RRender *rc, int N, RButtonPressCallBack func, void *userdata,
                                             char *text);
void MEAPI RRenderSetMouseCallBackWithText(RRender *rc, RMouseCallBack func, void *userdata, char *text);
/** The joystick's callback (kept and shown in the help; no joystick is read here yet). */
void MEAPI RRenderSetJoystickCallBackWithText(RRender *rc, RJoystickCallBack func, void *userdata, char *text);
/** The joystick's callback without text. */
void MEAPI RRenderSetJoystickCallBack(RRender *rc, RJoystickCallBack func, void *userdata);

/* ---- 1.2's camera views -------------------------------------------------------------------- */
/* The camera on one side of the look-at point, distance kept (RCameraSetPreset); the keypad keys
 * 1, 3, 7 (front, right, top; with Ctrl back, left, bottom) and 5 (orthographic on and off) are this
 * library's additions to the key map. */

void MEAPI RCameraSetFrontView(RRender *rc);
void MEAPI RCameraSetBackView(RRender *rc);
void MEAPI RCameraSetLeftView(RRender *rc);
void MEAPI RCameraSetRightView(RRender *rc);
void MEAPI RCameraSetTopView(RRender *rc);
void MEAPI RCameraSetBottomView(RRender *rc);
/** Parallel projection on (RCameraSetOrthographic(rc, 1)); RCameraSetView or RCameraSetOrthographic(rc, 0)
 *  does not undo it, only the latter. */
void MEAPI RCameraSetOrthographicView(RRender *rc);

/* ---- context settings 1.2 had -------------------------------------------------------------- */
/** Background colour (RGBA, each in [0, 1]); a NULL or non-finite colour is refused. */
void MEAPI RRenderSetBackgroundColor(RRender *rc, const float color[4]);
/** Sides of spheres, cylinders and cones made from now on (3 … 256; else refused, ME_ERR_ARGUMENT_RANGE). */
void MEAPI RRenderSetSphereResolution(RRender *rc, int res);
/** Sides of spheres, cylinders and cones made from now on (24 by default); 0 for a NULL context. */
int MEAPI RRenderGetSphereResolution(RRender *rc);

/* ---- native lines (RNLine) and immediate lines (RLineAdd) ----------------------------------- */
/* Segments drawn with GL lines, every native and immediate line of a context in one draw, unlit in
 * their colours, depth-tested with the 3D list. The signatures of RNLine* follow
 * RGraphicLineCreate's (1.2's header is not at hand: see docs/viewer.md). */

/** A native line from origin to end (local to `matrix` when not NULL, which it follows each frame:
 *  a body's or model's transform), in the 3D list. NULL with a message for a NULL context, end or
 *  colour (ME_ERR_NULL_ARGUMENT) or a non-finite end (ME_ERR_NONFINITE_ARGUMENT). The context owns
 *  it: RNLineDestroy, RNLineDelete, or RRenderContextDestroy frees it. */
RNLine *MEAPI RNLineCreate(RRender *rc, AcmeReal origin[3], AcmeReal end[3], const float color[4],
                           MeMatrix4Ptr matrix);
/** Move a line's ends. Returns 0, or −1 with a message (ends kept) for a NULL or non-finite end. */
int MEAPI RNLineMoveEnds(RNLine *line, AcmeReal *origin, AcmeReal *end);
/** Recolour a line (RGBA); a NULL or non-finite colour is refused. */
void MEAPI RNLineSetColor(RNLine *line, const float color[4]);
/** Draw the line again (after RNLineRemoveFromList); a line of another context is refused
 *  (ME_ERR_FOREIGN_HANDLE). */
void MEAPI RNLineAddToList(RRender *rc, RNLine *line);
/** Stop drawing the line (kept; RNLineAddToList shows it again). */
void MEAPI RNLineRemoveFromList(RRender *rc, RNLine *line);
/** Take the line out of the list and free it. */
void MEAPI RNLineDelete(RRender *rc, RNLine *line);
/** Free the line (out of its context's list first). */
void MEAPI RNLineDestroy(RNLine *line);
/** A world-space line in the colour (r, g, b) until RLineRemoveAll (1.2's demos draw their debug lines
 *  with it between two RLineRemoveAll). A non-finite end or colour is refused. */
void MEAPI RLineAdd(RRender *rc, MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b);
/** Forget every line RLineAdd gave. */
void MEAPI RLineRemoveAll(RRender *rc);

/* ---- particle systems ---------------------------------------------------------------------- */
/* Drawn in one instanced draw a system: each particle a disc of diameter tri_size facing the camera
 * (the texture's square when textured), unlit, depth-tested; particles at non-finite positions
 * are skipped. */

/** A particle system of numParticles at `positions` (the caller's array, read each frame; kept, not
 *  copied), texture id tex_id (−1 none), in no list. NULL with a message for a negative count, NULL
 *  positions with particles, a NULL colour, a size not finite and > 0, or an id that is not a texture
 *  (only checked when drawn: an unknown id draws untextured). */
RParticleSystem *MEAPI RParticleSystemNew(int numParticles, MeVector3 *positions, int tex_id, const float color[4],
                                          AcmeReal size);
/** RParticleSystemNew with the texture loaded from tex_filename (NULL: none), put in rc's list.
 *  NULL with a message as RParticleSystemNew, or when the texture cannot be loaded. */
RParticleSystem *MEAPI RParticleSystemCreate(RRender *rc, int numParticles, MeVector3 *positions, char *tex_filename,
                                             const float color[4], AcmeReal tri_size);
/** Free a system (out of its list first). */
void MEAPI RParticleSystemDestroy(RParticleSystem *ps);
/** Draw the system with rc (at the end of its list); one in another context's list is refused
 *  (ME_ERR_FOREIGN_HANDLE). */
void MEAPI RParticleSystemAddToList(RRender *rc, RParticleSystem *ps);
/** Stop drawing the system (kept). */
void MEAPI RParticleSystemRemoveFromList(RRender *rc, RParticleSystem *ps);

ME_EXTERN_C_END

#endif /* ME_VIEWER_H */
