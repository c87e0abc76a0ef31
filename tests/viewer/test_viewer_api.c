/* test_viewer_api.c -- the viewer's API without drawing (the null renderer, -null): Karma's defaults
 * (camera, lights, window), the camera's matrices against geometry, RRun with -timeout, pause and
 * single step, the PC key map, the primitives' triangle lists (on their surfaces, normals outward,
 * fronts counter-clockwise), and bad input reported with a code and no change. */
#include "karma_test.h"

#include <string.h>

#include <MeViewer.h>

#include "RInternal.h"
#include "viewer_null_context.h"
#include "viewer_project.h"

#define PI 3.14159265358979323846

static RRender *nullContext(const char *extra1, const char *extra2)
{
    int left;
    RRender *rc = viewerNullContext(extra1, extra2, &left);
    assert_non_null(rc);
    assert_int_equal(left, 1); /* the viewer's options were eaten, the program name kept */
    return rc;
}

static void project(RRender *rc, const double p[3], double ndc[3])
{
    viewerProject(rc, p, ndc);
}

/* "WxH" sizes: whole numbers 1 to 8192 each, nothing else; a refusal writes nothing. */
static void test_parse_size(void **state)
{
    (void)state;
    int w = -1, h = -1;
    assert_true(RRenderParseSize("1280x720", &w, &h));
    assert_int_equal(w, 1280);
    assert_int_equal(h, 720);
    assert_true(RRenderParseSize("8192x1", &w, &h));
    assert_int_equal(w, 8192);
    assert_int_equal(h, 1);
    const char *bad[] = {"", "x", "640", "640x", "x480", "0x480", "640x0", "8193x2", "640x480x", "-4x4", "64 x64"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        w = h = 7;
        assert_false(RRenderParseSize(bad[i], &w, &h));
        assert_int_equal(w, 7);
        assert_int_equal(h, 7);
    }
}

static void test_karma_defaults(void **state)
{
    RRender *rc = nullContext(NULL, NULL);
    int w, h;
    RRenderGetSize(rc, &w, &h);
    assert_int_equal(w, 640);
    assert_int_equal(h, 448);
    AcmeVector3 at, pos;
    RCameraGetLookAt(rc, at);
    RCameraGetPosition(rc, pos);
    assert_near(at[0], 0, 0), assert_near(at[1], 0, 0), assert_near(at[2], 1, 0);
    assert_near(RCameraGetDistance(rc), 15, 0);
    assert_near(RCameraGetRotation(rc), 0, 0);
    assert_near(RCameraGetElevation(rc), 0, 0);
    /* θ = φ = 0: the camera is on +z of the look-at point. */
    assert_near(pos[0], 0, 1e-6), assert_near(pos[1], 0, 1e-6), assert_near(pos[2], 16, 1e-5);
    assert_near(rc->m_Fov, PI / 6, 1e-6);
    assert_near(rc->m_AspectRatio, 640.0 / 448.0, 1e-6);
    /* Lights: ambient 0.2 on; directional 1 on with Karma's direction and colours; 2 and point off. */
    assert_true(rc->m_bUseAmbientLight);
    assert_near(rc->m_rgbAmbientLightColor[0], 0.2, 1e-6);
    assert_true(rc->m_DirectLight1.m_bUseLight);
    assert_near(rc->m_DirectLight1.m_Direction[0], 0.86, 1e-6);
    assert_near(rc->m_DirectLight1.m_Direction[1], 0.26, 1e-6);
    assert_near(rc->m_DirectLight1.m_Direction[2], 0.43, 1e-6);
    assert_near(rc->m_DirectLight1.m_rgbAmbient[1], 0.7, 1e-6);
    assert_near(rc->m_DirectLight1.m_rgbDiffuse[1], 0.6, 1e-6);
    assert_near(rc->m_DirectLight1.m_rgbSpecular[1], 0.5, 1e-6);
    assert_false(rc->m_DirectLight2.m_bUseLight);
    assert_false(rc->m_PointLight.m_bUseLight);
    assert_near(rc->m_PointLight.m_AttenuationConstant, 1, 0);
    assert_near(rc->m_backgroundColour[0], 0, 0);
    RLightSwitchOn(rc, kRDirect2);
    assert_true(rc->m_DirectLight2.m_bUseLight);
    RLightSwitchOff(rc, kRAmbient);
    assert_false(rc->m_bUseAmbientLight);
    RRenderContextDestroy(rc);
}

/* The look-at point projects to the centre; a point tan(fov)·distance above it (along the camera's
 * up) to the top edge, one aspect·tan(fov)·distance to the right to the right edge; depth grows. */
static void test_camera_matrices_are_the_geometry(void **state)
{
    RRender *rc = nullContext("-size", "800x400");
    const AcmeVector3 target = {1, 2, 3};
    RCameraSetLookAt(rc, target);
    RCameraSetView(rc, 10, ME_R(0.7), ME_R(0.4));
    AcmeVector3 pos, up;
    RCameraGetPosition(rc, pos);
    /* θ from +z in the x–z plane, φ elevation. */
    assert_near(pos[0], 1 + 10 * sin(0.7) * cos(0.4), 1e-4);
    assert_near(pos[1], 2 + 10 * sin(0.4), 1e-4);
    assert_near(pos[2], 3 + 10 * cos(0.7) * cos(0.4), 1e-4);
    double ndc[3], p[3] = {1, 2, 3};
    project(rc, p, ndc);
    assert_near(ndc[0], 0, 1e-5), assert_near(ndc[1], 0, 1e-5);
    RCameraGetUp(rc, up);
    double t = tan(PI / 6) * 10, a = 800.0 / 400.0;
    double top[3] = {1 + t * up[0], 2 + t * up[1], 3 + t * up[2]};
    project(rc, top, ndc);
    assert_near(ndc[0], 0, 1e-5), assert_near(ndc[1], 1, 1e-4);
    /* right = forward × up */
    double f[3] = {1 - pos[0], 2 - pos[1], 3 - pos[2]};
    double r[3] = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]};
    double lr = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    double right[3] = {1 + a * t * r[0] / lr, 2 + a * t * r[1] / lr, 3 + a * t * r[2] / lr};
    project(rc, right, ndc);
    assert_near(ndc[0], 1, 1e-4), assert_near(ndc[1], 0, 1e-4);
    double nearer[3] = {(1 + pos[0]) / 2, (2 + pos[1]) / 2, (3 + pos[2]) / 2}, zNear[3];
    project(rc, p, ndc);
    project(rc, nearer, zNear);
    assert_true(zNear[2] < ndc[2]);
    /* Zoom, orbit, elevation, pan move the camera as their names say. */
    RCameraZoom(rc, 4);
    assert_near(RCameraGetDistance(rc), 6, 1e-5);
    RCameraZoom(rc, 100);
    assert_near(RCameraGetDistance(rc), 0.01, 1e-6);
    RCameraRotateAngle(rc, ME_R(0.3));
    assert_near(RCameraGetRotation(rc), 1.0, 1e-5);
    RCameraRotateElevation(rc, 10);
    assert_true(RCameraGetElevation(rc) < PI / 2 && RCameraGetElevation(rc) > 1.5);
    RCameraPanY(rc, 2);
    AcmeVector3 at;
    RCameraGetLookAt(rc, at);
    assert_near(at[1], 4, 1e-5);
    const MeVector3 look = {0, 0, 0}, from = {0, 3, 4};
    RCameraSetLookAtAndPosition(rc, look, from);
    assert_near(RCameraGetDistance(rc), 5, 1e-5);
    assert_near(RCameraGetElevation(rc), asin(0.6), 1e-5);
    assert_near(RCameraGetRotation(rc), 0, 1e-6);
    RRenderContextDestroy(rc);
}

/* Presets put the camera on their axis, at its distance, looking at the look-at point; the look
 * direction is the matrix's; SetOffset, SetRotation and SetMatrix round-trip. */
static void test_camera_presets_offset_matrix(void **state)
{
    karma_capture_messages();
    RRender *rc = nullContext(NULL, NULL);
    const AcmeVector3 target = {1, -2, 3};
    RCameraSetLookAt(rc, target);
    RCameraSetView(rc, 8, ME_R(0.9), ME_R(0.3));
    static const double axis[6][3] = {{0, 0, 1}, {0, 0, -1}, {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    const RCameraPreset presets[6] = {kRCameraFront, kRCameraBack, kRCameraLeft,
                                      kRCameraRight, kRCameraTop,  kRCameraBottom};
    for (int k = 0; k < 6; k++) {
        RCameraSetPreset(rc, presets[k]);
        AcmeVector3 pos, dir, at;
        RCameraGetPosition(rc, pos);
        RCameraGetLookDir(rc, dir);
        RCameraGetLookAt(rc, at);
        double ndc[3], p[3] = {target[0], target[1], target[2]};
        project(rc, p, ndc);
        assert_near(ndc[0], 0, 1e-5), assert_near(ndc[1], 0, 1e-5);
        assert_near(RCameraGetDistance(rc), 8, 1e-5);
        for (int i = 0; i < 3; i++) {
            assert_near(at[i], target[i], 1e-6);
            /* On the axis (top and bottom within the elevation's 1 mrad margin from the pole). */
            assert_near(pos[i], target[i] + 8 * axis[k][i], 1e-2);
            assert_near(dir[i], -axis[k][i], 2e-3);
        }
    }
    /* Top looks down: the ground's +x is to the right on the picture, as in the front view. */
    RCameraSetPreset(rc, kRCameraTop);
    double ndc[3], px[3] = {target[0] + 1, target[1], target[2]};
    project(rc, px, ndc);
    assert_true(ndc[0] > 0.01);
    assert_reports(ME_ERR_ARGUMENT_RANGE, RCameraSetPreset(rc, (RCameraPreset)6));
    AcmeVector3 pos;
    RCameraGetPosition(rc, pos);
    assert_near(pos[1], target[1] + 8, 1e-2); /* unchanged */

    RCameraSetOffset(rc, ME_R(12.5));
    assert_near(RCameraGetDistance(rc), 12.5, 1e-6);
    RCameraSetRotation(rc, ME_R(-0.4));
    assert_near(RCameraGetRotation(rc), -0.4, 1e-6);
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RCameraSetOffset(rc, (MeReal)NAN));
    assert_near(RCameraGetDistance(rc), 12.5, 1e-6);

    /* SetMatrix then GetMatrix gives the same matrix back, and the look direction follows it. */
    RCameraSetView(rc, 5, ME_R(0.2), ME_R(0.1));
    MeMatrix4 m, back;
    RCameraGetMatrix(rc, m);
    RCameraSetView(rc, 7, ME_R(2.0), ME_R(-0.5));
    RCameraSetMatrix(rc, m);
    RCameraGetMatrix(rc, back);
    assert_memory_equal(m, back, sizeof m);
    AcmeVector3 dir;
    RCameraGetLookDir(rc, dir);
    double t = 0.2, ph = 0.1;
    assert_near(dir[0], -sin(t) * cos(ph), 1e-5);
    assert_near(dir[1], -sin(ph), 1e-5);
    assert_near(dir[2], -cos(t) * cos(ph), 1e-5);
    m[3][1] = (MeReal)INFINITY;
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RCameraSetMatrix(rc, m));
    RCameraGetMatrix(rc, m);
    assert_memory_equal(m, back, sizeof m);
    RRenderContextDestroy(rc);
}

/* Orthographic: a square's projected size does not change with its depth; perspective's does; the
 * look-at plane keeps its scale when switching. */
static void test_camera_orthographic(void **state)
{
    RRender *rc = nullContext(NULL, NULL);
    const AcmeVector3 target = {0, 0, 0};
    RCameraSetLookAt(rc, target);
    RCameraSetView(rc, 10, ME_R(0.5), ME_R(0.2));
    AcmeVector3 up, dir;
    RCameraGetUp(rc, up);
    RCameraGetLookDir(rc, dir);
    double size[2][3];
    for (int ortho = 0; ortho < 2; ortho++) {
        RCameraSetOrthographic(rc, (MeBool)ortho);
        assert_int_equal(RCameraIsOrthographic(rc), ortho);
        for (int k = 0; k < 3; k++) {
            double depth = 4.0 * (k - 1); /* square 1 m tall, 4 m nearer, at, 4 m farther */
            double lo[3], hi[3], a[3], b[3];
            for (int i = 0; i < 3; i++)
                lo[i] = depth * dir[i], hi[i] = lo[i] + up[i];
            project(rc, lo, a);
            project(rc, hi, b);
            size[ortho][k] = b[1] - a[1];
        }
    }
    assert_true(size[0][0] > 1.5 * size[0][2]);          /* perspective: nearer is bigger */
    assert_near(size[1][0], size[1][1], 1e-5);           /* orthographic: the same at every depth */
    assert_near(size[1][2], size[1][1], 1e-5);
    assert_near(size[1][1], size[0][1], 1e-5);           /* and the same as perspective at the look-at */
    assert_near(size[1][1], 1 / (10 * tan(PI / 6)), 1e-5);
    RCameraSetOrthographic(rc, 0);
    assert_int_equal(RCameraIsOrthographic(rc), 0);
    RRenderContextDestroy(rc);
}

static int ticks;
static void MEAPI countTick(RRender *rc, void *userdata)
{
    ticks++;
    if (userdata && ticks == 3)
        RRenderQuit(rc);
}

static void test_run_timeout_pause_single_step(void **state)
{
    RRender *rc = nullContext("-timeout", "7");
    assert_int_equal(rc->m_nTimeout, 7);
    ticks = 0;
    RRun(rc, countTick, NULL);
    assert_int_equal(ticks, 7);
    /* RRenderQuit ends the loop after the current frame. */
    ticks = 0;
    RRun(rc, countTick, &ticks);
    assert_int_equal(ticks, 3);
    /* Paused: frames run, the callback does not; a single step calls it once. "Paused" is shown. */
    ticks = 0;
    RRenderSetPause(rc, 1);
    assert_non_null(rc->m_pRG_First2D);
    assert_string_equal(rc->m_pRG_First2D->m_private->text, "Paused");
    RRun(rc, countTick, NULL);
    assert_int_equal(ticks, 0);
    RRenderSingleStep(rc);
    RRun(rc, countTick, NULL);
    assert_int_equal(ticks, 1);
    /* F8 pauses and steps once; Ctrl+F8 resumes. */
    RRenderSetPause(rc, 0);
    RInputKey(rc, RKEY_F8, 0);
    assert_true(rc->m_bPause);
    ticks = 0;
    RRun(rc, countTick, NULL);
    assert_int_equal(ticks, 1);
    RInputKey(rc, RKEY_F8, RCONTROL);
    assert_false(rc->m_bPause);
    assert_null(rc->m_pRG_First2D);
    RRun(rc, countTick, NULL);
    assert_int_equal(ticks, 8);
    RRenderContextDestroy(rc);
}

static int pressed[16];
static void MEAPI onPress(RRender *rc, void *userdata)
{
    pressed[*(int *)userdata]++;
}

static void test_pc_key_map(void **state)
{
    static int ids[16];
    RRender *rc = nullContext(NULL, NULL);
    for (int i = 0; i < 16; i++)
        ids[i] = i;
    RRenderSetUpCallBack(rc, onPress, &ids[0]);
    RRenderSetDownCallBack(rc, onPress, &ids[1]);
    RRenderSetLeftCallBack(rc, onPress, &ids[2]);
    RRenderSetRightCallBack(rc, onPress, &ids[3]);
    RRenderSetUp2CallBack(rc, onPress, &ids[4]);
    RRenderSetDown2CallBack(rc, onPress, &ids[5]);
    RRenderSetLeft2CallBack(rc, onPress, &ids[6]);
    RRenderSetRight2CallBack(rc, onPress, &ids[7]);
    for (int n = 0; n < 6; n++)
        RRenderSetActionNCallBack(rc, n, onPress, &ids[8 + n]);
    memset(pressed, 0, sizeof pressed);
    const int keys[14] = {RKEY_UP, RKEY_DOWN, RKEY_LEFT, RKEY_RIGHT, 'W', 'S', 'A', 'D', 'H', 'M', RKEY_ENTER, ' ', 'O', 'P'};
    for (int i = 0; i < 14; i++) {
        RInputKey(rc, keys[i], 0);
        for (int j = 0; j < 14; j++)
            assert_int_equal(pressed[j], j <= i);
    }
    /* Actions 2–5 can take other keys; the old key then does nothing. */
    RRenderSetActionNKey(rc, 3, 'x');
    RInputKey(rc, 'X', 0);
    assert_int_equal(pressed[11], 2);
    RInputKey(rc, ' ', 0);
    assert_int_equal(pressed[11], 2);
    /* + and − zoom, Esc quits. */
    double d = RCameraGetDistance(rc);
    RInputKey(rc, RKEY_KP_ADD, 0);
    assert_true(RCameraGetDistance(rc) < d);
    RInputKey(rc, RKEY_ESCAPE, 0);
    assert_true(rc->m_bQuitNextFrame);
    RRenderContextDestroy(rc);
}

static int mouseEvents, lastX, lastModifiers;
static void MEAPI onMouse(RRender *rc, int x, int y, int modifiers, RMouseButtonWhich which, RMouseButtonEvent event,
                          void *userdata)
{
    mouseEvents++, lastX = x, lastModifiers = modifiers;
}

static void test_mouse_orbits_or_goes_to_the_application(void **state)
{
    RRender *rc = nullContext(NULL, NULL);
    RRenderSetMouseCallBack(rc, onMouse, NULL);
    mouseEvents = 0;
    double theta = RCameraGetRotation(rc);
    RInputMouseButton(rc, 100, 100, 0, kRLeftButton, kRNewlyPressed);
    RInputMouseMove(rc, 150, 100, 0, 1);
    assert_true(RCameraGetRotation(rc) < theta); /* dragged right: the scene turns with the mouse */
    assert_int_equal(mouseEvents, 0);
    RInputMouseButton(rc, 150, 100, 0, kRLeftButton, kRNewlyReleased);
    RInputMouseButton(rc, 200, 120, RCONTROL, kRLeftButton, kRNewlyPressed);
    RInputMouseMove(rc, 210, 120, RCONTROL, 1);
    assert_int_equal(mouseEvents, 2);
    assert_int_equal(lastX, 210);
    assert_int_equal(lastModifiers, RCONTROL);
    RRenderContextDestroy(rc);
}

/* Every vertex on the surface (signed distance ~ 0), normals unit and outward, triangles wound
 * counter-clockwise seen from outside (their edge cross product along the normal). */
typedef double (*Distance)(const double p[3]);
static double r0 = 0.7, h0 = 1.2;
static double sphereDistance(const double p[3]) { return sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - r0; }
static double boxDistance(const double p[3])
{
    double h[3] = {0.5, 1.0, 1.5}, m = -1e9;
    for (int k = 0; k < 3; k++)
        m = fmax(m, fabs(p[k]) - h[k]);
    return m;
}
static double cylinderDistance(const double p[3])
{
    return fmax(sqrt(p[0] * p[0] + p[1] * p[1]) - r0, fabs(p[2]) - h0 / 2);
}
static double sphylDistance(const double p[3])
{
    double z = fmax(fabs(p[2]) - h0 / 2, 0);
    return sqrt(p[0] * p[0] + p[1] * p[1] + z * z) - r0;
}
static double torusDistance(const double p[3])
{
    double q = sqrt(p[0] * p[0] + p[1] * p[1]) - 2.0;
    return sqrt(q * q + p[2] * p[2]) - 0.5;
}
static double coneDistance(const double p[3]) /* base r0 at z = −0.3, apex at z = 0.9 */
{
    double r = sqrt(p[0] * p[0] + p[1] * p[1]), H = 1.2, s = sqrt(r0 * r0 + H * H);
    double side = (r * H + (p[2] - 0.9) * r0) / s; /* distance to the slant line's infinite cone */
    return fmax(side, -0.3 - p[2]);
}

static void checkMesh(RGraphic *g, Distance distance, double tol, const double centre[3])
{
    assert_non_null(g);
    int n = g->m_pObject->m_nNumVertices;
    assert_true(n > 0 && n % 3 == 0);
    for (int i = 0; i < n; i += 3) {
        double p[3][3], nrm[3] = {0, 0, 0};
        for (int k = 0; k < 3; k++) {
            const RObjectVertex *v = &g->m_pVertices[i + k];
            p[k][0] = v->m_X, p[k][1] = v->m_Y, p[k][2] = v->m_Z;
            double vn[3] = {v->m_NX, v->m_NY, v->m_NZ};
            assert_near(sqrt(vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2]), 1, 1e-5);
            assert_near(distance(p[k]), 0, tol);
            double out = 0;
            for (int j = 0; j < 3; j++)
                nrm[j] += vn[j];
            if (centre) { /* convex: outward is away from a centre */
                for (int j = 0; j < 3; j++)
                    out += vn[j] * (p[k][j] - centre[j]);
                assert_true(out > -1e-6);
            } else { /* else along the distance's gradient */
                double grad[3], q[3];
                for (int j = 0; j < 3; j++) {
                    memcpy(q, p[k], sizeof q);
                    q[j] += 1e-6;
                    grad[j] = (distance(q) - distance(p[k])) / 1e-6;
                    out += vn[j] * grad[j];
                }
                assert_true(out > 0.99);
            }
        }
        double a[3], b[3];
        for (int j = 0; j < 3; j++)
            a[j] = p[1][j] - p[0][j], b[j] = p[2][j] - p[0][j];
        double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double area = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (area > 1e-9) /* degenerate triangles at the poles have no winding */
            assert_true(c[0] * nrm[0] + c[1] * nrm[1] + c[2] * nrm[2] > 0);
    }
}

static void test_primitives_are_their_shapes(void **state)
{
    RRender *rc = nullContext(NULL, NULL);
    const float red[4] = {1, 0, 0, 1};
    const double origin[3] = {0, 0, 0};
    RGraphic *sphere = RGraphicSphereCreate(rc, ME_R(0.7), red, NULL);
    checkMesh(sphere, sphereDistance, 1e-5, origin);
    /* Its coarser copies (drawn when it is small on the picture) are the same sphere, in fewer triangles. */
    for (int k = 0, n = sphere->m_pObject->m_nNumVertices; k < R_LOD_LEVELS; k++) {
        RGraphic *lod = sphere->m_private->lod[k];
        checkMesh(lod, sphereDistance, 1e-5, origin);
        assert_true(lod->m_pObject->m_nNumVertices < n / 2);
        n = lod->m_pObject->m_nNumVertices;
    }
    assert_near(sphere->m_private->lodExtent, 0.7, 1e-6);
    checkMesh(RGraphicBoxCreate(rc, 1, 2, 3, red, NULL), boxDistance, 1e-5, origin);
    checkMesh(RGraphicCylinderCreate(rc, ME_R(0.7), ME_R(1.2), red, NULL), cylinderDistance, 1e-5, origin);
    RGraphic *sphyl = RGraphicSphylCreate(rc, ME_R(0.7), ME_R(1.2), red, NULL);
    checkMesh(sphyl, sphylDistance, 1e-5, origin);
    for (int k = 0; k < R_LOD_LEVELS; k++)
        checkMesh(sphyl->m_private->lod[k], sphylDistance, 1e-5, origin);
    checkMesh(RGraphicTorusCreate(rc, ME_R(0.5), 2, red, NULL), torusDistance, 1e-5, NULL);
    const double axis[3] = {0, 0, 0.1};
    checkMesh(RGraphicConeCreate(rc, ME_R(0.7), ME_R(0.9), ME_R(0.3), red, NULL), coneDistance, 1e-5, axis);
    /* The ground: in x–z at y_position, facing up. */
    RGraphic *ground = RGraphicGroundPlaneCreate(rc, 20, 10, red, ME_R(-1.5));
    assert_non_null(ground);
    assert_near(ground->m_pObject->m_Matrix[3][1], -1.5, 0);
    for (int i = 0; i < 6; i++) {
        assert_near(ground->m_pVertices[i].m_Y, 0, 0);
        assert_near(ground->m_pVertices[i].m_NY, 1, 0);
        assert_near(fabs(ground->m_pVertices[i].m_X), 10, 1e-6);
    }
    /* Lines move; text keeps its string; colours and matrices are the graphic's. */
    AcmeReal a[3] = {0, 0, 0}, b[3] = {1, 2, 3};
    RGraphic *line = RGraphicLineCreate(rc, a, b, red, NULL);
    b[2] = 7;
    assert_int_equal(RGraphicLineMoveEnds(line, a, b), 0);
    assert_near(line->m_pVertices[1].m_Z, 7, 0);
    assert_int_equal(RGraphicLineMoveEnds(ground, a, b), -1);
    RGraphic *text = RGraphicTextCreate(rc, "Paused", 575, 0, red);
    assert_ptr_equal(rc->m_pRG_First2D, text);
    float c[4], blue[4] = {0, 0, 1, ME_R(0.5)};
    RGraphicSetColor(line, blue);
    RGraphicGetColor(line, c);
    assert_memory_equal(c, blue, sizeof c);
    MeMatrix4 tm;
    RGraphicSetTransformPtr(line, tm);
    assert_ptr_equal(line->m_pLWMatrix, tm);
    /* Out of the list and back; deleting takes it out. */
    RGraphicRemoveFromList(rc, line, 0);
    for (RGraphic *it = rc->m_pRG_First; it; it = it->m_pNext)
        assert_ptr_not_equal(it, line);
    RGraphicAddToList(rc, line, 0);
    RGraphicDelete(rc, line, 0);
    for (RGraphic *it = rc->m_pRG_First; it; it = it->m_pNext)
        assert_ptr_not_equal(it, line);
    RRenderContextDestroy(rc);
}

static void test_bad_input_is_reported(void **state)
{
    karma_capture_messages();
    const float red[4] = {1, 0, 0, 1};
    RRender *rc = nullContext(NULL, NULL);
    RGraphic *g;
    assert_reports(ME_ERR_ARGUMENT_RANGE, g = RGraphicBoxCreate(rc, -1, 1, 1, red, NULL));
    assert_null(g);
    assert_reports(ME_ERR_ARGUMENT_RANGE, g = RGraphicSphereCreate(rc, NAN, red, NULL));
    assert_null(g);
    assert_null(rc->m_pRG_First); /* nothing was added */
    assert_reports(ME_ERR_NULL_ARGUMENT, g = RGraphicBoxCreate(NULL, 1, 1, 1, red, NULL));
    assert_reports(ME_ERR_NULL_ARGUMENT, g = RGraphicCreateFromModel(rc, NULL, NULL));
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSetActionNCallBack(rc, 6, NULL, NULL));
    unsigned char key = rc->m_pCallBacks->m_actionKeys[0];
    assert_reports(ME_ERR_ARGUMENT_RANGE, RRenderSetActionNKey(rc, 1, 'q'));
    assert_int_equal(rc->m_pCallBacks->m_actionKeys[0], key);
    double d = RCameraGetDistance(rc);
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RCameraSetView(rc, NAN, 0, 0));
    assert_near(RCameraGetDistance(rc), d, 0);
    assert_reports(ME_ERR_ARGUMENT_RANGE, RCameraSetFov(rc, 2));
    assert_near(rc->m_Fov, PI / 6, 1e-6);
    /* Drawing or saving without a frame: the null renderer has none. */
    assert_reports(ME_ERR_BAD_STATE, assert_int_equal(RRenderSavePNG(rc, "never.png"), -1));
    RRenderContextDestroy(rc);
    /* A bad -size or -timeout: no context. */
    const char *argv[3] = {"test", "-size", "12by7"};
    MeCommandLineOptions *o = MeCommandLineOptionsCreate(3, argv);
    RRender *none;
    assert_reports(ME_ERR_ARGUMENT_RANGE, none = RRenderContextCreate(o, NULL, 0));
    assert_null(none);
    MeCommandLineOptionsDestroy(o);
    assert_reports(ME_ERR_ARGUMENT_RANGE, none = RRenderContextCreateHeadless(0, 10));
    assert_null(none);
}

/* The options object: positions, eating, values after an option. */
static void test_command_line_options(void **state)
{
    const char *argv[] = {"demo", "-timeout", "40", "-gl", "-scale", "2.5", "-name", "x"};
    MeCommandLineOptions *o = MeCommandLineOptionsCreate(8, argv);
    assert_int_equal(MeCommandLineOptionsGetPos(o, "-gl"), 3);
    assert_int_equal(MeCommandLineOptionsGetNumeric(o, "-name", METRUE), -1); /* not a number: kept */
    assert_int_equal(o->m_argc, 8);
    assert_int_equal(MeCommandLineOptionsGetNumeric(o, "-timeout", METRUE), 40);
    assert_int_equal(o->m_argc, 6);
    assert_near(MeCommandLineOptionsGetFloat(o, "-scale", MEFALSE), 2.5, 0);
    assert_string_equal(MeCommandLineOptionsGetString(o, "-name", METRUE), "x");
    const char *list[] = {"-null", "-gl", NULL};
    assert_true(MeCommandLineOptionsCheckForList(o, list, METRUE));
    assert_false(MeCommandLineOptionsCheckFor(o, "-gl", MEFALSE));
    assert_int_equal(o->m_argc, 3);
    assert_string_equal(o->p_argv[0], "demo");
    assert_string_equal(o->p_argv[1], "-scale");
    MeCommandLineOptionsDestroy(o);
    assert_null(MeCommandLineOptionsCreate(-1, argv));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_karma_defaults),
        cmocka_unit_test(test_parse_size),
        cmocka_unit_test(test_camera_matrices_are_the_geometry),
        cmocka_unit_test(test_camera_presets_offset_matrix),
        cmocka_unit_test(test_camera_orthographic),
        cmocka_unit_test(test_run_timeout_pause_single_step),
        cmocka_unit_test(test_pc_key_map),
        cmocka_unit_test(test_mouse_orbits_or_goes_to_the_application),
        cmocka_unit_test(test_primitives_are_their_shapes),
        cmocka_unit_test(test_bad_input_is_reported),
        cmocka_unit_test(test_command_line_options),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
