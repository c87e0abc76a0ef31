/* MeViewerTypes.h -- the types of Karma's viewer (the R* API of MeViewer.h): the render context,
 * graphics, lights, callbacks and input enumerations, under Karma 1.2's names.
 *
 * Matrices follow Karma's convention (rows are axes, the last row is the translation; a point p is
 * transformed as p·M). The camera's m_CamMatrix takes world to eye coordinates and m_ProjMatrix eye
 * to clip coordinates, so clip = p·m_CamMatrix·m_ProjMatrix (OpenGL's clip space, −w ≤ x, y, z ≤ w). */
#ifndef ME_VIEWER_TYPES_H
#define ME_VIEWER_TYPES_H

#include <karma/MePrecision.h>
#include <karma/MeCall.h>

ME_EXTERN_C_BEGIN

/** Which renderer a context uses: a window with OpenGL, no drawing at all (-null), or an offscreen
 *  OpenGL surface without a display (-headless; this library's addition, through EGL). */
typedef enum {
    kRDefault,
    kROpenGL,
    kRD3D,
    kRPs2,
    kRPs2HiG,
    kRXbox,
    kRNull,
    kRBenchmark,
    kRHeadless
} RRenderType;

/** The four lights of a context. */
typedef enum { kRAmbient, kRDirect1, kRDirect2, kRPoint } RRenderLight;

/** The drawing state of a graphic: composite matrix, material colours (RGBA), vertex count,
 *  texture (−1 none), wireframe flag and specular exponent. */
typedef struct RObjectHeader {
    MeMatrix4 m_Matrix;          /**< local-to-world matrix used for drawing (m_pLWMatrix copied in each frame) */
    float m_ColorAmbient[4];
    float m_ColorDiffuse[4];
    float m_ColorSpecular[4];
    float m_ColorEmissive[4];
    int m_nNumVertices;
    int m_nTextureID;
    int m_bIsWireFrame;
    AcmeReal m_SpecularPower;
} RObjectHeader;

/** One vertex of a triangle list: position, normal, texture coordinates (local frame). */
typedef struct RObjectVertex {
    AcmeReal m_X, m_Y, m_Z;
    AcmeReal m_NX, m_NY, m_NZ;
    AcmeReal m_U, m_V;
} RObjectVertex;

struct RGraphicPrivate;

/** A drawable: a triangle list (or lines, or text) with a header, linked in a render list. */
typedef struct RGraphic *RGraphicPtr;
typedef struct RGraphic {
    RObjectHeader *m_pObject;    /**< drawing state */
    RObjectVertex *m_pVertices;  /**< m_nMaxNumVertices vertices; m_pObject->m_nNumVertices are drawn */
    RGraphicPtr m_pNext;         /**< next in its render list */
    int m_nMaxNumVertices;
    MeMatrix4Ptr m_pLWMatrix;    /**< the matrix the graphic follows (a body's or model's TM), or NULL */
    struct RGraphicPrivate *m_private; /**< GPU buffers and kind; owned by the viewer */
} RGraphic;

/** A directional light: direction towards the light, on/off, colours. */
typedef struct RDirectLight {
    AcmeReal m_Direction[3];
    int m_bUseLight;
    AcmeReal m_rgbAmbient[3];
    AcmeReal m_rgbDiffuse[3];
    AcmeReal m_rgbSpecular[3];
} RDirectLight;

/** A point light with constant, linear and quadratic attenuation. */
typedef struct RPointLight {
    AcmeReal m_Position[3];
    int m_bUseLight;
    float m_rgbAmbient[3];
    float m_rgbDiffuse[3];
    float m_rgbSpecular[3];
    AcmeReal m_AttenuationConstant;
    AcmeReal m_AttenuationLinear;
    AcmeReal m_AttenuationQuadratic;
} RPointLight;

/** Options read from the command line by RRenderContextCreate. */
typedef struct RRenderOptions {
    RRenderType m_renderType;
    MeBool m_bDisplayHelpOnConsole;
    MeBool m_bWireFrame;
    MeBool m_bTextures;
    MeBool m_bCalibrateTimer;
} RRenderOptions;

typedef struct RRenderCallBacks *RRenderCallBacksPtr;
struct RRenderPrivate;

/** A render context: camera, lights, render lists, callbacks and the window or offscreen surface. */
typedef struct RRender {
    MeMatrix4 m_CamMatrix;       /**< world → eye (see the top of this file) */
    MeMatrix4 m_ProjMatrix;      /**< eye → clip */
    RDirectLight m_DirectLight1;
    RDirectLight m_DirectLight2;
    RPointLight m_PointLight;
    AcmeReal m_rgbAmbientLightColor[4];
    AcmeReal m_backgroundColour[4];
    AcmeReal m_CameraLookAt[3];
    RGraphic *m_pRG_First;       /**< the 3D render list */
    RGraphic *m_pRG_First2D;     /**< the 2D render list (text, rectangles) */
    int m_bUseAmbientLight;
    int m_bForceDirectLight1Update;
    int m_bForceDirectLight2Update;
    int m_bForcePointLightUpdate;
    int m_bPause;
    int m_bQuitNextFrame;
    AcmeReal m_CameraDist;       /**< distance from the look-at point (m) */
    AcmeReal m_CameraTheta;      /**< rotation about y, in the x–z plane from +z (rad) */
    AcmeReal m_CameraPhi;        /**< elevation above the x–z plane (rad) */
    AcmeReal m_AspectRatio;      /**< width / height */
    AcmeReal m_Fov;              /**< half of the vertical field of view (rad) */
    RRenderCallBacksPtr m_pCallBacks;
    char m_AppName[40];
    unsigned int m_nTimeout;     /**< frames before RRun returns (0: never) */
    int m_bProfiling;
    RRenderOptions m_options;
    int m_sphereRes;             /**< sides of spheres, cylinders and cones */
    struct RRenderPrivate *m_private; /**< window or surface, GL objects; owned by the viewer */
} RRender;

/** Near and far clipping distances of the perspective camera (m). */
#define NEARZ (0.30f)
#define FARZ (500.0f)

typedef enum { kRNewlyPressed = 1, kRStillPressed, kRNewlyReleased } RMouseButtonEvent;
typedef enum { kRLeftButton = 1, kRMiddleButton, kRRightButton } RMouseButtonWhich;
typedef enum {
    kRButtonUp, kRButtonDown, kRButtonLeft, kRButtonRight,
    kRButtonUp2, kRButtonDown2, kRButtonLeft2, kRButtonRight2,
    kRButtons
} RButtonList;

#define NUM_ACTION_CALLBACKS (6)

/* Modifier bits passed to mouse callbacks. */
#define RCONTROL (1 << 0)
#define RSHIFT (1 << 1)
#define RALT (1 << 2)

/** Called once per frame by RRun, before drawing (the application steps its physics here). */
typedef void (MEAPI *RMainLoopCallBack)(RRender *rc, void *userdata);
/** Called when a button (arrow, w/s/a/d) or action key is pressed. */
typedef void (MEAPI *RButtonPressCallBack)(RRender *rc, void *userdata);
/** Called with the joystick's position in [−1, 1]². */
typedef void (MEAPI *RJoystickCallBack)(RRender *rc, AcmeReal x, AcmeReal y, void *userdata);
/** Called for mouse events with a modifier held (window pixels, origin top left). */
typedef void (MEAPI *RMouseCallBack)(RRender *rc, int x, int y, int modifiers, RMouseButtonWhich which,
                                     RMouseButtonEvent event, void *userdata);

typedef struct RCallBackDataButton {
    RButtonPressCallBack m_CallBack;
    void *m_Userdata;
    char *m_Text;
} RCallBackDataButton;

typedef struct RCallBackDataMouse {
    RMouseCallBack m_CallBack;
    void *m_Userdata;
    char *m_Text;
} RCallBackDataMouse;

typedef struct RCallBackDataJoystick {
    RJoystickCallBack m_CallBack;
    void *m_Userdata;
    char *m_Text;
} RCallBackDataJoystick;

/** The application's callbacks: buttons, mouse, joystick, actions and the keys of actions 2–5. */
typedef struct RRenderCallBacks {
    RCallBackDataButton m_Button[kRButtons];
    RCallBackDataMouse m_Mouse;
    RCallBackDataJoystick m_Joystick;
    RCallBackDataButton m_Action[NUM_ACTION_CALLBACKS];
    unsigned char m_actionKeys[NUM_ACTION_CALLBACKS - 2];
} RRenderCallBacks;

/** A native line (RNLineCreate): a segment drawn with GL lines in one batch with the context's other
 *  native lines, unlit in its colour; its fields are the viewer's. */
typedef struct RNLine RNLine;

/** A particle system (RParticleSystemCreate, Karma 1.2's fields): m_nNumParticles discs of diameter
 *  m_TriangleSize facing the camera, centred on m_Positions (the application's array, read each frame),
 *  in the colour m_rgbAmbient, textured when m_nTextureID >= 0. */
typedef struct RParticleSystem *RPSystemPtr;
typedef struct RParticleSystem {
    float m_rgbAmbient[4];       /**< the particles' colour (RGBA) */
    float m_rgbDiffuse[4];       /**< kept as 1.2's (black but the alpha); not used in drawing */
    float m_rgbSpecular[4];
    float m_rgbEmissive[4];
    AcmeReal m_TriangleSize;     /**< diameter of each particle (m) */
    MeVector3 *m_Positions;      /**< the application's positions, m_nNumParticles of them */
    int m_nNumParticles;
    int m_nTextureID;            /**< RRenderTextureCreate's id, or −1 */
    RPSystemPtr m_pNextSystem;   /**< next in its context's list */
    struct RRender *m_pRender;   /**< the context whose list holds it, or NULL (this library's) */
} RParticleSystem;

/** An on-screen menu of toggles, values and submenus (RMenuCreate); its parts are the viewer's. */
typedef struct RMenu RMenu;
/** Called with a toggle entry's new state. */
typedef void (MEAPI *RMenuToggleCallback)(MeBool on);
/** Called with a value entry's new value. */
typedef void (MEAPI *RMenuValueCallback)(MeReal value);
/** The performance bar (RPerformanceBarCreate): collision, dynamics, rendering and idle time a frame. */
typedef struct RPerformanceBar RPerformanceBar;

ME_EXTERN_C_END

#endif /* ME_VIEWER_TYPES_H */
