/* test_viewer_karma12_demo_calls.c -- every R* call Karma 1.2's demos and tutorials make, written as
 * they make them (their headers, argument forms, 1.2's struct fields), in one program: a ramp demo
 * after 1.2's Friction example that also calls what the others call (Bounce, Cubes, ManyPendulums,
 * FixedPath, BallnChain, TriangleList's vertex helper, Topple's shooting...). That it compiles against
 * the viewer's headers is the first check; then it runs headless as a person would start it
 * (-headless -size -timeout): the tick runs every frame, the debug lines 1.2's demos route through
 * RLineAdd are drawn, the help lists the callbacks' texts, and the picture is not blank. */
#include "karma_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* As a 1.2 demo includes them. */
#include <MeMath.h>
#include <MeViewer.h>
#include <MeApp.h>
#include <RGeometry.h>
#include <RGeometryUtils.h>
#include <Mst.h>
#include "MeDebugDraw.h"

#include "RInternal.h"
#include "viewer_two_colour_png.h"

/* Globals and callbacks are static here only for this build's -Wmissing-prototypes; a demo's are not. */
#define HELPSIZE (4)
static char *help[HELPSIZE] = {"$ACTION2 - reset", "$ACTION1 - toggle options menu",
                        "$UP/$DOWN - increase/decrease ramp angle", "$MOUSE - mouse force"};

static MeVector3 boxSize = {1, 1, 1};
static float boxColor[4] = {1, 1, 0, 1};
static float rampColor[4] = {0, 0, 1, 1};
static float ColRed[4] = {1, 0, 0, 1};

static MstUniverseID universe;
static McdSpaceID space;
static MdtWorldID world;
static McdFrameworkID framework;
static McdGeometryID planeGeom, boxGeom, ballGeom;
static McdModelID plane, box, ball;
static RGraphic *boxG, *ballG, *groundG, *lineG, *text, *triG;
static RNLine *nline;
static RParticleSystem *particles;
static MeVector3 particlePositions[16];
static RRender *rc;
static RMenu *menu, *submenu;
static MeApp *meapp;
static MeReal step = (MeReal)(0.03);
static int ticks, resets, shots, tilts;
static MeReal gravityValue = -9.8f;

static MeALIGNDATA(MeMatrix4, groundTM, 16) = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, -1, 0, 1}};

static void MEAPI simpleDraw(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b)
{
    RLineAdd(rc, start, end, r, g, b);
}

static void MEAPI tick(RRender *r, void *userdata)
{
    (void)userdata;
    RLineRemoveAll(r);
    MeAppStep(meapp);
    MstUniverseStep(universe, step);
    RGraphicSetColor(boxG, ticks % 2 ? boxColor : ColRed); /* as Cubes colours by partition */
    MeVector3 a = {0, 0, 0}, b;
    MdtBodyGetPosition(McdModelGetBody(ball), b);
    RGraphicLineMoveEnds(lineG, a, b);
    RNLineMoveEnds(nline, a, b);
    ticks++;
}

static void MEAPI reset(RRender *r, void *userData) { (void)r, (void)userData, resets++; }
static void MEAPI shoot(RRender *r, void *userData) { (void)r, (void)userData, shots++; }
static void MEAPI increaseTilt(RRender *r, void *userData) { (void)r, (void)userData, tilts++; }
static void MEAPI decreaseTilt(RRender *r, void *userData) { (void)r, (void)userData, tilts--; }
static void MEAPI toggleDrawing(MeBool on) { MdtWorldSetDebugDrawing(world, on ? MdtDebugDrawContacts : 0); }
static void MEAPI setGravity(MeReal g) { gravityValue = g; }

static void MEAPI_CDECL cleanup(void)
{
    MeAppDestroy(meapp);
    RMenuDestroy(submenu);
    RMenuDestroy(menu);
    RParticleSystemDestroy(particles);
    RNLineDestroy(nline);
    RRenderContextDestroy(rc);
    MstUniverseDestroy(universe);
}

/* A demo's main, as 1.2's are written; returns what RRun's program would. */
static int demoMain(int argc, const char *argv[])
{
    float color[4];
    MstUniverseSizes sizes;
    MeCommandLineOptions *options;

    options = MeCommandLineOptionsCreate(argc, argv);
    rc = RRenderContextCreate(options, 0, !MEFALSE);
    MeCommandLineOptionsDestroy(options);
    if (!rc)
        return 1;

    sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = 100;
    sizes.dynamicConstraintsMaxCount = 600;
    sizes.materialsMaxCount = 2;
    sizes.collisionModelsMaxCount = 100;
    sizes.collisionPairsMaxCount = 600;
    sizes.collisionUserGeometryTypesMaxCount = 0;
    sizes.collisionGeometryInstancesMaxCount = 0;
    universe = MstUniverseCreate(&sizes);
    space = MstUniverseGetSpace(universe);
    world = MstUniverseGetWorld(universe);
    framework = MstUniverseGetFramework(universe);
    MdtWorldSetGravity(world, 0, gravityValue, 0);
    MdtWorldSetAutoDisable(world, 0);

    MeDebugDrawAPI.line = simpleDraw;
    toggleDrawing(1);

    planeGeom = McdPlaneCreate(framework);
    plane = MstFixedModelCreate(universe, planeGeom, groundTM);
    boxGeom = McdBoxCreate(framework, boxSize[0], boxSize[1], boxSize[2]);
    box = MstModelAndBodyCreate(universe, boxGeom, 1.0f);
    MdtBodySetPosition(McdModelGetBody(box), 0, 0, 0);
    ballGeom = McdSphereCreate(framework, 0.5f);
    ball = MstModelAndBodyCreate(universe, ballGeom, 1.0f);
    MdtBodySetPosition(McdModelGetBody(ball), 2, 1, 0);

    boxG = RGraphicBoxCreate(rc, boxSize[0], boxSize[1], boxSize[2], boxColor, McdModelGetTransformPtr(box));
    RGraphicSetWireframe(boxG, 1);
    assert_true(RGraphicIsWireframe(boxG));
    RGraphicSetWireframe(boxG, 0);
    ballG = RGraphicCreateFromModel(rc, ball, rampColor);
    RPerformanceBarCreate(rc);

    color[0] = color[1] = color[2] = color[3] = 1;
    groundG = RGraphicGroundPlaneCreate(rc, 30.0f, 30, color, -1);
    RGraphicSetTexture(rc, groundG, "checkerboard");
    RGraphicSphereCreate(rc, 0.3f, ColRed, 0);
    RGraphicCylinderCreate(rc, 0.2f, 1, color, 0);
    RGraphicConeCreate(rc, 0.3f, 0.5f, 0.5f, color, 0);
    RGraphicTorusCreate(rc, 0.1f, 0.5f, color, 0);
    RGraphicFrustumCreate(rc, 0.3f, 0.2f, 0, 1, 12, color, 0);
    RGraphicSphylCreate(rc, 0.2f, 1, color, 0);
    RGraphicSquareCreate(rc, 2, color, 0);
    RGraphic2DRectangleCreate(rc, 10, 10, 50, 20, ColRed);

    /* TriangleList's way: an empty graphic filled vertex by vertex. */
    {
        MeVector3 v[3] = {{-1, 0, 2}, {1, 0, 2}, {0, 1, 2}}, normal = {0, 0, 1};
        int i;
        triG = RGraphicCreateEmpty(3);
        for (i = 0; i < 3; i++)
            RSetVertex(&triG->m_pVertices[i], v[i], normal, 0, 0);
        triG->m_pObject->m_nTextureID = -1;
        RGraphicSetColor(triG, color);
        triG->m_pObject->m_bIsWireFrame = 0;
        triG->m_pLWMatrix = 0;
        MeMatrix4TMMakeIdentity((MeMatrix4Ptr)triG->m_pObject->m_Matrix);
        RGraphicAddToList(rc, triG, 0);
    }
    {
        MeVector3 a = {0, 0, 0}, b = {1, 1, 1};
        float white[4] = {1, 1, 1, 1};
        lineG = RGraphicLineCreate(rc, a, b, white, 0);
        nline = RNLineCreate(rc, a, b, ColRed, 0);
        RNLineSetColor(nline, boxColor);
        RNLineRemoveFromList(rc, nline);
        RNLineAddToList(rc, nline);
    }
    {
        int i;
        for (i = 0; i < 16; i++)
            MeVector3Set(particlePositions[i], -4 + 0.5f * i, 3, 0);
        particles = RParticleSystemCreate(rc, 16, particlePositions, 0, ColRed, 0.2f);
    }
    text = RGraphicTextCreate(rc, "FixedPath example", 20, 400, ColRed);

    meapp = MeAppCreate(world, space, rc);
    RRenderSkydomeCreate(rc, "skydome", 2, 1);

    /* CONTROLS, with and without text. */
    RRenderSetActionNCallBack(rc, 2, reset, 0);
    RRenderSetActionNCallBackWithText(rc, 3, shoot, 0, "shoot");
    RRenderSetActionNKey(rc, 4, 'k');
    RRenderSetUpCallBackWithText(rc, increaseTilt, 0, "tilt up");
    RRenderSetDownCallBack(rc, decreaseTilt, 0);
    RRenderSetLeftCallBack(rc, decreaseTilt, 0);
    RRenderSetRightCallBack(rc, increaseTilt, 0);
    RRenderSetUp2CallBack(rc, increaseTilt, 0);
    RRenderSetDown2CallBack(rc, decreaseTilt, 0);
    RRenderSetLeft2CallBack(rc, decreaseTilt, 0);
    RRenderSetRight2CallBack(rc, increaseTilt, 0);
    RRenderSetMouseCallBackWithText(rc, MeAppMousePickCB, (void *)meapp, "drag");

    RRenderSetWindowTitle(rc, "Friction example");
    RRenderSetAppName(rc, "Friction");
    RRenderCreateUserHelp(rc, help, HELPSIZE);
    RRenderToggleUserHelp(rc);

    RCameraSetView(rc, 12, 0, ME_PI / 8);
    {
        MeVector3 lookAt = {0, 0, 0}, position = {0, 4, 12};
        RCameraSetLookAt(rc, lookAt);
        RCameraZoom(rc, 2.0f);
        RCameraRotateElevation(rc, (MeReal)0.25);
        RCameraRotateAngle(rc, (MeReal)0.1);
        RCameraSetLookAtAndPosition(rc, lookAt, position);
        RCameraSetFrontView(rc);
        RCameraSetOrthographicView(rc);
        RCameraSetOrthographic(rc, MEFALSE);
    }
    RLightSwitchOff(rc, kRDirect2);
    RLightSwitchOn(rc, kRAmbient);

    menu = RMenuCreate(rc, "Options Menu");
    submenu = RMenuCreate(rc, "Physics");
    RMenuAddToggleEntry(menu, "Draw Contacts", toggleDrawing, 1);
    RMenuAddValueEntry(submenu, "Gravity", setGravity, 0, -20, 1, gravityValue);
    RMenuAddSubmenuEntry(menu, "Physics", submenu);
    RRenderSetDefaultMenu(rc, menu);
    {
        char out[64];
        RParseText(rc, "$ACTION2 resets $APPNAME", out, sizeof out);
        assert_string_equal(out, "Enter resets Friction");
    }

    /* The user reads the help (paused) and closes it. */
    assert_true(rc->m_bPause);
    RRenderToggleUserHelp(rc);
    assert_false(rc->m_bPause);

    RRun(rc, tick, 0);
    return 0;
}

static void test_a_karma12_demo_compiles_and_runs(void **state)
{
    (void)state;
    karma_capture_messages();
    /* The demos' textures (not shipped): two-colour stand-ins by their names. */
    assert_int_equal(viewerWriteTwoColourPng("checkerboard.png"), 0);
    assert_int_equal(viewerWriteTwoColourPng("skydome.png"), 0);
    const char *argv[] = {"friction", "-headless", "-size", "160x100", "-timeout", "40"};
    assert_int_equal(demoMain(6, argv), 0);
    assert_int_equal(ticks, 40);
    assert_int_equal(karma_warning_count(), 0);
    /* The help listed the texts given with the callbacks. */
    RRenderToggleUserHelp(rc);
    int found = 0;
    for (int i = 0; i < rc->m_private->helpTextCount; i++) {
        const char *t = rc->m_private->helpText[i]->m_private->text;
        found += strcmp(t, "Space - shoot") == 0 || strcmp(t, "Up arrow - tilt up") == 0 ||
                 strcmp(t, "Ctrl or Shift + mouse - drag") == 0;
    }
    assert_int_equal(found, 3);
    RRenderToggleUserHelp(rc);
    /* The keys reach the callbacks, Space the one given with text. */
    RInputKey(rc, ' ', 0);
    RInputKey(rc, RKEY_ENTER, 0);
    RInputKey(rc, RKEY_UP, 0);
    assert_int_equal(shots, 1);
    assert_int_equal(resets, 1);
    assert_int_equal(tilts, 1);
    /* The box rests on the ground: MdtWorldSetDebugDrawing's contact lines went through RLineAdd and
     * are there to draw (RLineRemoveAll only clears them at the next tick), with the native line. */
    float *ends = NULL;
    int capacity = 0;
    int n = RNLineGather(rc, &ends, &capacity);
    free(ends);
    assert_true(n > 2);
    assert_int_equal(rc->m_private->immediateEnds, n - 2);
    /* The last frame drawn is a picture, not a blank. */
    unsigned char rgba[160 * 100 * 4];
    assert_int_equal(RRenderReadPixels(rc, rgba), 0);
    int differ = 0;
    for (int i = 1; i < 160 * 100; i++)
        differ += memcmp(rgba, rgba + 4 * i, 3) != 0;
    assert_true(differ > 160 * 100 / 10);
    cleanup();
}

/* As 1.2's aggregate helper and scene loader use them: RGraphicCombine puts a second graphic's
 * triangles where a relative transform places them, RGraphicTranslateVertices moves a mesh. */
static void test_combine_and_translate(void **state)
{
    (void)state;
    karma_capture_messages();
    const char *argv[] = {"combine", "-null"};
    MeCommandLineOptions *options = MeCommandLineOptionsCreate(2, argv);
    RRender *r = RRenderContextCreate(options, 0, !MEFALSE);
    MeCommandLineOptionsDestroy(options);
    float white[4] = {1, 1, 1, 1}, red[4] = {1, 0, 0, 1};
    MeMatrix4 bodyTM;
    MeMatrix4TMMakeIdentity(bodyTM);
    RGraphic *a = RGraphicBoxCreate(r, 1, 1, 1, white, bodyTM);
    RGraphic *b = RGraphicBoxCreate(r, 2, 1, 1, red, 0);
    /* The element turned a quarter about y (its x becomes −z) and moved 3 along x. */
    MeMatrix4 elemTM = {{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {3, 0, 0, 1}};
    RGraphic *c = RGraphicCombine(r, a, b, elemTM);
    assert_non_null(c);
    assert_int_equal(c->m_pObject->m_nNumVertices, 72);
    assert_ptr_equal(c->m_pLWMatrix, bodyTM); /* follows what the first followed */
    float colour[4];
    RGraphicGetColor(c, colour);
    assert_near(colour[1], 1, 1e-7); /* the first's colour */
    for (int i = 0; i < 36; i++) {
        const RObjectVertex *v = &c->m_pVertices[36 + i], *s = &b->m_pVertices[i];
        assert_near(v->m_X, 3 + s->m_Z, 1e-6); /* p·M: x' = z + 3, z' = −x */
        assert_near(v->m_Y, s->m_Y, 1e-6);
        assert_near(v->m_Z, -s->m_X, 1e-6);
        assert_near(v->m_NX, s->m_NZ, 1e-6);
        assert_near(v->m_NZ, -s->m_NX, 1e-6);
        assert_memory_equal(&c->m_pVertices[i], &a->m_pVertices[i], sizeof(RObjectVertex));
    }
    /* The element's extent along z is now its 2 m length. */
    double zmin = 1e9, zmax = -1e9;
    for (int i = 36; i < 72; i++) {
        zmin = c->m_pVertices[i].m_Z < zmin ? c->m_pVertices[i].m_Z : zmin;
        zmax = c->m_pVertices[i].m_Z > zmax ? c->m_pVertices[i].m_Z : zmax;
    }
    assert_near(zmax - zmin, 2, 1e-6);
    RGraphicDelete(r, a, 0);
    RGraphicDelete(r, b, 0);
    MeVector3 offset = {0, -0.5, 2};
    RObjectVertex before = c->m_pVertices[40];
    RGraphicTranslateVertices(r, c, offset);
    assert_near(c->m_pVertices[40].m_X, before.m_X, 1e-6);
    assert_near(c->m_pVertices[40].m_Y, before.m_Y - 0.5, 1e-6);
    assert_near(c->m_pVertices[40].m_Z, before.m_Z + 2, 1e-6);
    MeVector3 bad = {0, NAN, 0};
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RGraphicTranslateVertices(r, c, bad));
    assert_near(c->m_pVertices[40].m_Y, before.m_Y - 0.5, 1e-6);
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RGraphicCombine(r, c, NULL, elemTM)));
    RGraphic *label = RGraphicTextCreate(r, "text", 0, 0, white);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, assert_null(RGraphicCombine(r, c, label, elemTM)));
    RRenderContextDestroy(r);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_karma12_demo_compiles_and_runs),
        cmocka_unit_test(test_combine_and_translate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
