/* test_viewer_pictures.c -- the pictures, checked as a person would look at them, drawn headless
 * (EGL on Mesa, no display): every registry scene at its first and last frame is neither blank nor
 * uniform; for a few scenes the centre of each body, projected with the camera's matrices, lands on
 * pixels of that body's colour; the ground and the sky are where the camera says; a graphic follows
 * the body it was given; shadows fall away from the key light; textures (BMP, PNG) show; the
 * performance bar is drawn. The test fails, never skips, when no headless context can be made. */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>

#include "RInternal.h"
#include "demo_view.h"
#include "viewer_project.h"
#include "viewer_two_colour_png.h"

/* Small pictures keep the software renderer fast; the checks do not depend on the size. */
#define W 320
#define H 200

typedef struct Picture {
    unsigned char rgba[W * H * 4];
} Picture;

static RRender *rc;
static Picture picture;

static int setup(void **state)
{
    karma_capture_messages();
    rc = RRenderContextCreateHeadless(W, H);
    if (!rc)
        fprintf(stderr, "no headless OpenGL 3.3 context: install libegl-mesa0 and libgl1-mesa-dri (.ci/run does)\n");
    return rc ? 0 : -1;
}

static int teardown(void **state)
{
    RRenderContextDestroy(rc);
    return 0;
}

static void draw(void)
{
    RRenderDrawFrame(rc);
    assert_int_equal(RRenderReadPixels(rc, picture.rgba), 0);
}

/* Window pixel of world point p; returns 0 when it is behind the camera or off the picture. */
static int project(const double p[3], int *px, int *py)
{
    double ndc[3];
    if (viewerProject(rc, p, ndc) <= 0)
        return 0;
    *px = (int)floor((ndc[0] + 1) / 2 * W);
    *py = (int)floor((1 - ndc[1]) / 2 * H);
    return *px >= 0 && *px < W && *py >= 0 && *py < H;
}

static const unsigned char *pixel(int x, int y)
{
    return picture.rgba + 4 * ((size_t)y * W + (size_t)x);
}

/* Chromaticity: the colour with its brightness divided out, so lit and shaded faces of one body compare equal. */
static void chroma(const double rgb[3], double out[3])
{
    double s = rgb[0] + rgb[1] + rgb[2] + 1e-9;
    for (int k = 0; k < 3; k++)
        out[k] = rgb[k] / s;
}

static double chromaDistance(const unsigned char *p, const float color[4])
{
    double a[3] = {p[0], p[1], p[2]}, b[3] = {color[0], color[1], color[2]}, ca[3], cb[3];
    chroma(a, ca);
    chroma(b, cb);
    return sqrt((ca[0] - cb[0]) * (ca[0] - cb[0]) + (ca[1] - cb[1]) * (ca[1] - cb[1]) + (ca[2] - cb[2]) * (ca[2] - cb[2]));
}

/* Neither blank nor uniform: at least two colours each cover a thousandth of the picture (the free
 * bodies fly in an empty sky),
 * and the brightness varies. */
static void assertNotUniform(const char *what)
{
    double sum = 0, sum2 = 0;
    unsigned char first[3];
    memcpy(first, picture.rgba, 3);
    long differ = 0;
    for (int i = 0; i < W * H; i++) {
        const unsigned char *p = picture.rgba + 4 * i;
        double l = 0.3 * p[0] + 0.59 * p[1] + 0.11 * p[2];
        sum += l, sum2 += l * l;
        if (abs(p[0] - first[0]) + abs(p[1] - first[1]) + abs(p[2] - first[2]) > 24)
            differ++;
    }
    double mean = sum / (W * H), sd = sqrt(fmax(sum2 / (W * H) - mean * mean, 0));
    if (!(sd > 2 && differ > W * H / 1000 && differ < W * H - W * H / 1000))
        fail_msg("%s: picture is blank or uniform (brightness %.1f ± %.1f, %ld pixels differ from the first)", what,
                 mean, sd, differ);
}


static void test_every_scene_first_and_last_frame(void **state)
{
    for (int s = 0; s < DemoSceneCount(); s++) {
        const DemoScene *scene = DemoSceneAt(s);
        DemoInstance demo;
        DemoView view;
        assert_true(DemoCreate(scene, &demo));
        assert_true(DemoViewCreate(&view, rc, &demo));
        assert_true(view.count > 0);
        char what[64];
        snprintf(what, sizeof what, "%s, first frame", scene->name);
        draw();
        assertNotUniform(what);
        for (int i = 0; i < scene->defaultSteps; i++)
            DemoStep(&demo, scene->defaultStepSize);
        snprintf(what, sizeof what, "%s, last frame", scene->name);
        DemoViewFrame(&view, &demo); /* as `karma render` does: the scene where it is now */
        draw();
        if (demo.universe) {
            assertNotUniform(what);
        } else {
            /* Bodies without geometry (free bodies) end up hundreds of metres apart, a pixel each:
             * every one must still be in the picture. */
            for (int i = 0; i < view.count; i++) {
                MeVector3 x;
                MdtBodyGetPosition(view.body[i], x);
                double p[3] = {x[0], x[1], x[2]};
                int px, py;
                assert_true(project(p, &px, &py));
            }
        }
        DemoViewDestroy(&view);
        DemoDestroy(&demo);
    }
    assert_int_equal(karma_warning_count(), 0);
}

/* Every body of the view whose projected centre is on the picture: the pixels there (a 3 × 3
 * majority, for antialiased edges) have that body's colour and no other body's or the ground's. */
static int checkCentres(const DemoView *view, const char *what)
{
    int checked = 0;
    for (int i = 0; i < view->count; i++) {
        if (!view->body[i])
            continue;
        MeVector3 x;
        MdtBodyGetPosition(view->body[i], x);
        double p[3] = {x[0], x[1], x[2]};
        int px, py;
        if (!project(p, &px, &py))
            continue;
        float mine[4];
        DemoViewColor(view, i, mine);
        int votes = 0;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                int qx = px + dx < 0 ? 0 : px + dx >= W ? W - 1 : px + dx;
                int qy = py + dy < 0 ? 0 : py + dy >= H ? H - 1 : py + dy;
                const unsigned char *q = pixel(qx, qy);
                double best = chromaDistance(q, mine);
                int nearest = 1;
                for (int j = 0; j < view->count; j++) {
                    float other[4];
                    DemoViewColor(view, j, other);
                    if (memcmp(other, mine, sizeof other) && chromaDistance(q, other) < best)
                        nearest = 0;
                }
                double sky[3] = {rc->m_backgroundColour[0], rc->m_backgroundColour[1], rc->m_backgroundColour[2]};
                const float skyColor[4] = {(float)sky[0], (float)sky[1], (float)sky[2], 1};
                if (chromaDistance(q, skyColor) < best)
                    nearest = 0;
                votes += nearest && best < 0.12; /* lit faces saturate a little towards white */
            }
        if (votes < 5) {
            const unsigned char *q = pixel(px, py);
            RRenderSavePNG(rc, "viewer_failure.png"); /* to look at */
            fail_msg("%s: body %d projects to (%d, %d), whose colour (%d, %d, %d) is not its own (%.2f, %.2f, %.2f)", what,
                     i, px, py, q[0], q[1], q[2], (double)mine[0], (double)mine[1], (double)mine[2]);
        }
        checked++;
    }
    return checked;
}

static void test_bodies_are_where_the_physics_puts_them(void **state)
{
    /* Scenes whose bodies do not hide one another's centres. */
    static const char *const names[] = {"twospheres", "bounce", "drop", "hinge"};
    for (size_t s = 0; s < sizeof names / sizeof names[0]; s++) {
        const DemoScene *scene = DemoSceneFind(names[s]);
        assert_non_null(scene);
        DemoInstance demo;
        DemoView view;
        assert_true(DemoCreate(scene, &demo));
        assert_true(DemoViewCreate(&view, rc, &demo));
        char what[64];
        snprintf(what, sizeof what, "%s, first frame", scene->name);
        draw();
        assert_true(checkCentres(&view, what) >= 1);
        for (int i = 0; i < scene->defaultSteps; i++)
            DemoStep(&demo, scene->defaultStepSize);
        snprintf(what, sizeof what, "%s, last frame", scene->name);
        DemoViewFrame(&view, &demo);
        draw();
        assert_true(checkCentres(&view, what) >= 1);
        DemoViewDestroy(&view);
        DemoDestroy(&demo);
    }
}

/* A graphic given a body's matrix follows the body: moved by 1.5 m, the body is drawn at its new place
 * and the old place shows the ground again. */
static void test_graphic_follows_its_body(void **state)
{
    DemoInstance demo;
    DemoView view;
    assert_true(DemoCreate(DemoSceneFind("bounce"), &demo));
    assert_true(DemoViewCreate(&view, rc, &demo));
    MdtBodyID ball = NULL;
    int index = -1;
    for (int i = 0; i < view.count; i++)
        if (view.body[i])
            ball = view.body[i], index = i;
    assert_non_null(ball);
    MdtBodySetPosition(ball, 0, ME_R(0.25), 0);
    DemoViewFrame(&view, &demo); /* then the camera stays: only the body moves */
    draw();
    assert_true(checkCentres(&view, "ball at the origin") == 1);
    MdtBodySetPosition(ball, ME_R(1.5), ME_R(0.25), 0);
    draw();
    assert_true(checkCentres(&view, "ball moved") == 1);
    double old[3] = {0, 0.25, 0};
    int px, py;
    assert_true(project(old, &px, &py));
    float mine[4];
    DemoViewColor(&view, index, mine);
    assert_true(chromaDistance(pixel(px, py), mine) > 0.1);
    DemoViewDestroy(&view);
    DemoDestroy(&demo);
}

/* Only a ground plane, seen from a known camera: ground below the horizon where the camera says, in
 * alternating light and dark cells of the size asked for; the background above it. */
static void test_ground_and_sky_where_the_camera_says(void **state)
{
    const float grey[4] = {0.8f, 0.8f, 0.8f, 1};
    RGraphic *ground = RGraphicGroundPlaneCreate(rc, 40, 20, grey, 0); /* cells of 2 m */
    const AcmeReal sky[3] = {ME_R(0.1), ME_R(0.2), ME_R(0.6)};
    for (int k = 0; k < 3; k++)
        rc->m_backgroundColour[k] = sky[k];
    const AcmeVector3 at = {0, 0, 0};
    RCameraSetLookAt(rc, at);
    RCameraSetView(rc, 12, ME_R(0.3), ME_R(0.35));
    draw();
    /* Cell centres (1, 0, 1) and (3, 0, 1) are in neighbouring cells: both grey, different brightness. */
    double a[3] = {1, 0, 1}, b[3] = {3, 0, 1}, c[3] = {3, 0, 3};
    int ax, ay, bx, by, cx, cy;
    assert_true(project(a, &ax, &ay) && project(b, &bx, &by) && project(c, &cx, &cy));
    const unsigned char *pa = pixel(ax, ay), *pb = pixel(bx, by), *pc = pixel(cx, cy);
    for (int k = 1; k < 3; k++) {
        assert_true(abs(pa[k] - pa[0]) <= 3);
        assert_true(abs(pb[k] - pb[0]) <= 3);
    }
    assert_true(abs(pa[0] - pb[0]) > 20);      /* neighbours differ */
    assert_true(abs(pa[0] - pc[0]) <= 3);      /* diagonal cells agree */
    /* 400 m away, 5° above the horizon straight ahead: the background colour exactly. */
    AcmeVector3 eye;
    RCameraGetPosition(rc, eye);
    double up[3] = {eye[0] - 400 * cos(0.09) * sin(0.3), eye[1] + 400 * sin(0.09), eye[2] - 400 * cos(0.09) * cos(0.3)};
    int ux, uy;
    assert_true(project(up, &ux, &uy));
    const unsigned char *pu = pixel(ux, uy);
    assert_int_equal(pu[0], (int)lround(0.1 * 255));
    assert_int_equal(pu[1], (int)lround(0.2 * 255));
    assert_int_equal(pu[2], (int)lround(0.6 * 255));
    /* The ground's far edge (20 m away along −z): just in front of it ground, just behind it sky. */
    double inside[3] = {0, 0, -19.5}, outside[3] = {0, 0, -20.5};
    int ix, iy, ox, oy;
    assert_true(project(inside, &ix, &iy) && project(outside, &ox, &oy));
    assert_true(abs(pixel(ix, iy)[2] - pixel(ix, iy)[0]) <= 3);
    assert_true(pixel(ox, oy)[2] > pixel(ox, oy)[0] + 60);
    RGraphicDelete(rc, ground, 0);
}

/* The picture can be written: a PNG file with the right signature and size fields. */
static void test_png_written(void **state)
{
    const float red[4] = {1, 0, 0, 1};
    RGraphic *box = RGraphicBoxCreate(rc, 1, 1, 1, red, NULL);
    draw();
    assert_int_equal(RRenderSavePNG(rc, "viewer_test.png"), 0);
    FILE *f = fopen("viewer_test.png", "rb");
    assert_non_null(f);
    unsigned char head[24];
    assert_int_equal(fread(head, 1, sizeof head, f), sizeof head);
    fclose(f);
    assert_memory_equal(head, "\x89PNG\r\n\x1a\n", 8);
    assert_int_equal((head[16] << 24) | (head[17] << 16) | (head[18] << 8) | head[19], W);
    assert_int_equal((head[20] << 24) | (head[21] << 16) | (head[22] << 8) | head[23], H);
    RGraphicDelete(rc, box, 0);
}

/* A graphic outlives the context that drew it (taken out of the lists first): it is freed without
 * that context, and another context can draw it; the first context's pictures are not disturbed. */
static void test_graphic_outlives_its_context(void **state)
{
    const float red[4] = {1, 0, 0, 1};
    RRender *other = RRenderContextCreateHeadless(64, 48);
    assert_non_null(other);
    RGraphic *box = RGraphicBoxCreate(other, 2, 2, 2, red, NULL);
    RRenderDrawFrame(other);
    RGraphicRemoveFromList(other, box, 0);
    RRenderContextDestroy(other);
    /* Drawn now by the test's context, at its look-at point. */
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    const AcmeVector3 at = {0, 0, 0};
    RCameraSetLookAt(rc, at);
    RCameraSetView(rc, 10, 0, 0);
    RGraphicSetTransformPtr(box, tm);
    RGraphicAddToList(rc, box, 0);
    draw();
    const unsigned char *centre = pixel(W / 2, H / 2);
    assert_true(centre[0] > 100 && centre[1] < 40 && centre[2] < 40);
    RGraphicDelete(rc, box, 0);
    RGraphicDestroy(NULL);
}

/* Paused, the picture says so at the top right (Karma's place for it): bright text on the dark
 * background there, and nothing there once resumed. */
static int brightPixelsTopRight(void)
{
    int count = 0;
    for (int y = 0; y < H * 20 / 448; y++)
        for (int x = W * 570 / 640; x < W; x++)
            count += pixel(x, y)[0] > 80;
    return count;
}

static void test_paused_is_shown(void **state)
{
    const AcmeReal black[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        rc->m_backgroundColour[k] = black[k];
    RRenderSetPause(rc, 1);
    draw();
    assert_true(brightPixelsTopRight() > 10);
    RRenderSetPause(rc, 0);
    draw();
    assert_int_equal(brightPixelsTopRight(), 0);
}

/* Mean brightness of the 5 × 5 pixels about world point p (on the picture). */
static double brightnessAt(const double p[3])
{
    int px, py;
    assert_true(project(p, &px, &py));
    double sum = 0;
    for (int dy = -2; dy <= 2; dy++)
        for (int dx = -2; dx <= 2; dx++) {
            const unsigned char *q = pixel(px + dx, py + dy);
            sum += 0.3 * q[0] + 0.59 * q[1] + 0.11 * q[2];
        }
    return sum / 25;
}

/* The key light (directional light 1) casts shadows: a box 1 m above the ground darkens the ground
 * where the ray from its centre away from the light meets it, c − l·(c_y / l_y), and not the point
 * as far on the other side; with the light turned round, the other way round. Each pixel is
 * compared with itself in a picture without the box, so the checkerboard does not matter. */
static void test_shadow_falls_away_from_the_key_light(void **state)
{
    const float grey[4] = {0.8f, 0.8f, 0.8f, 1}, red[4] = {1, 0.2f, 0.2f, 1};
    RGraphic *ground = RGraphicGroundPlaneCreate(rc, 40, 20, grey, 0);
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, ME_R(1.0), 0, 1}};
    RGraphic *box = RGraphicBoxCreate(rc, ME_R(0.8), ME_R(0.8), ME_R(0.8), red, tm);
    const AcmeVector3 at = {0, 0, 0};
    RCameraSetLookAt(rc, at);
    RCameraSetView(rc, 14, ME_R(0.2), ME_R(1.1));
    AcmeReal *dir = rc->m_DirectLight1.m_Direction, saved[3] = {dir[0], dir[1], dir[2]};
    const double c[3] = {0, 1, 0};
    for (int turn = 0; turn < 2; turn++) {
        double sign = turn ? -1 : 1;
        dir[0] = (AcmeReal)(sign * 0.86), dir[1] = ME_R(0.26), dir[2] = (AcmeReal)(sign * 0.43);
        double n = sqrt(0.86 * 0.86 + 0.26 * 0.26 + 0.43 * 0.43), l[3] = {sign * 0.86 / n, 0.26 / n, sign * 0.43 / n};
        double t = c[1] / l[1];
        double shadow[3] = {c[0] - t * l[0], 0, c[2] - t * l[2]}, lit[3] = {-shadow[0], 0, -shadow[2]};
        draw();
        double withShadow = brightnessAt(shadow), withLit = brightnessAt(lit);
        RGraphicRemoveFromList(rc, box, 0);
        draw();
        double bareShadow = brightnessAt(shadow), bareLit = brightnessAt(lit);
        RGraphicAddToList(rc, box, 0);
        if (!(withShadow < 0.85 * bareShadow && fabs(withLit - bareLit) < 2))
            fail_msg("light %+.0f: ground at the shadow %.1f (%.1f without the box), on the other side %.1f (%.1f)", sign,
                     withShadow, bareShadow, withLit, bareLit);
    }
    memcpy(dir, saved, sizeof saved);
    RGraphicDelete(rc, box, 0);
    RGraphicDelete(rc, ground, 0);
}

/* Graphics of equal vertices are drawn together (one instanced draw) but each with its own matrix
 * and colour: three equal boxes in three colours, each centre shows its own. */
static void test_equal_meshes_keep_their_own_place_and_colour(void **state)
{
    const float colors[3][4] = {{1, 0.1f, 0.1f, 1}, {0.1f, 1, 0.1f, 1}, {0.1f, 0.1f, 1, 1}};
    MeMatrix4 tm[3];
    RGraphic *boxes[3];
    for (int i = 0; i < 3; i++) {
        memset(tm[i], 0, sizeof tm[i]);
        for (int k = 0; k < 4; k++)
            tm[i][k][k] = 1;
        tm[i][3][0] = (MeReal)(2 * (i - 1));
        boxes[i] = RGraphicBoxCreate(rc, 1, 1, 1, colors[i], tm[i]);
    }
    const AcmeVector3 at = {0, 0, 0};
    RCameraSetLookAt(rc, at);
    RCameraSetView(rc, 10, 0, ME_R(0.2));
    draw();
    for (int i = 0; i < 3; i++) {
        double p[3] = {2.0 * (i - 1), 0, 0};
        int px, py;
        assert_true(project(p, &px, &py));
        if (chromaDistance(pixel(px, py), colors[i]) > 0.1)
            fail_msg("box %d at (%d, %d) is not its colour", i, px, py);
    }
    for (int i = 0; i < 3; i++)
        RGraphicDelete(rc, boxes[i], 0);
}

/* The performance bar as drawn: 2, 4, 6 and 2 ms of collision, dynamics, rendering and idle time
 * laid end to end from x = 20 of the virtual screen at 12 units a millisecond, each in its colour
 * (orange, green, blue, grey), on the bar's row at the bottom. */
static void test_performance_bar_drawn(void **state)
{
    for (int k = 0; k < 3; k++)
        rc->m_backgroundColour[k] = 0;
    assert_non_null(RPerformanceBarCreate(rc));
    RPerformanceBarUpdate(rc, 2, 4, 6, 2);
    draw();
    const double ms[4] = {1, 4.5, 9, 13};
    const float colors[4][4] = {{1, 0.55f, 0.1f, 1}, {0.2f, 0.8f, 0.3f, 1}, {0.3f, 0.5f, 1, 1}, {0.6f, 0.6f, 0.6f, 1}};
    int y = (int)(432.0 / 448 * H);
    for (int k = 0; k < 4; k++) {
        int x = (int)((20 + 12 * ms[k]) / 640 * W);
        const unsigned char *p = pixel(x, y);
        if (chromaDistance(p, colors[k]) > 0.03 || p[0] + p[1] + p[2] < 100)
            fail_msg("bar part %d at (%d, %d) is (%d, %d, %d)", k, x, y, p[0], p[1], p[2]);
    }
    const unsigned char *beyond = pixel((int)((20 + 12 * 15.0) / 640 * W), y);
    assert_true(beyond[0] + beyond[1] + beyond[2] < 10); /* 14 ms in all: background after it */
    RPerformanceBarDestroy(rc);
}

/* A 2 × 1 BMP written by hand (24-bit, rows bottom up, padded to 4 bytes): left red, right blue. */
static void writeBmp(const char *path)
{
    unsigned char file[62] = {'B', 'M', 62, 0, 0, 0, 0, 0, 0, 0, 54, 0, 0, 0, /* size, offset of the pixels */
                              40, 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 1, 0, 24, 0}; /* 2 × 1, 1 plane, 24 bits */
    const unsigned char pixels[8] = {0, 0, 255, 255, 0, 0, 0, 0};                 /* BGR red, BGR blue, padding */
    memcpy(file + 54, pixels, sizeof pixels);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(file, 1, sizeof file, f), sizeof file);
    fclose(f);
}

/* Textures as Karma names them (no extension: .bmp, then .png) multiply the graphic's colour at its
 * texture coordinates: a white box's front face (u along x) shows the image's red left half on the
 * left and its blue right half on the right, from the BMP and from the PNG alike; -notextures
 * (m_bTextures off) shows the box white; an unreadable file is refused and changes nothing. */
static void test_textures_bmp_and_png(void **state)
{
    writeBmp("viewer_texture_bmp.bmp");
    assert_int_equal(viewerWriteTwoColourPng("viewer_texture_png.png"), 0); /* the same picture */
    const float white[4] = {1, 1, 1, 1}, red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
    for (int k = 0; k < 3; k++)
        rc->m_backgroundColour[k] = 0;
    const AcmeVector3 at = {0, 0, 0};
    RCameraSetLookAt(rc, at);
    RCameraSetView(rc, 8, 0, 0);
    const char *names[2] = {"viewer_texture_bmp", "viewer_texture_png"};
    for (int i = 0; i < 2; i++) {
        RGraphic *box = RGraphicBoxCreate(rc, 2, 2, 2, white, NULL);
        int id = RGraphicSetTexture(rc, box, names[i]);
        assert_true(id >= 0);
        assert_int_equal(RRenderTextureCreate(rc, names[i]), id); /* the same name: the same texture */
        draw();
        double left[3] = {-0.5, 0, 1}, right[3] = {0.5, 0, 1};
        int lx, ly, rx, ry;
        assert_true(project(left, &lx, &ly) && project(right, &rx, &ry));
        if (chromaDistance(pixel(lx, ly), red) > 0.1 || chromaDistance(pixel(rx, ry), blue) > 0.1)
            fail_msg("%s: left (%d, %d, %d), right (%d, %d, %d)", names[i], pixel(lx, ly)[0], pixel(lx, ly)[1],
                     pixel(lx, ly)[2], pixel(rx, ry)[0], pixel(rx, ry)[1], pixel(rx, ry)[2]);
        rc->m_options.m_bTextures = MEFALSE;
        draw();
        assert_true(chromaDistance(pixel(lx, ly), white) < 0.05 && chromaDistance(pixel(rx, ry), white) < 0.05);
        rc->m_options.m_bTextures = METRUE;
        assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(RGraphicSetTexture(rc, box, "no_such_texture"), -1));
        assert_int_equal(box->m_pObject->m_nTextureID, id);
        RGraphicDelete(rc, box, 0);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_scene_first_and_last_frame),
        cmocka_unit_test(test_bodies_are_where_the_physics_puts_them),
        cmocka_unit_test(test_graphic_follows_its_body),
        cmocka_unit_test(test_ground_and_sky_where_the_camera_says),
        cmocka_unit_test(test_png_written),
        cmocka_unit_test(test_graphic_outlives_its_context),
        cmocka_unit_test(test_paused_is_shown),
        cmocka_unit_test(test_shadow_falls_away_from_the_key_light),
        cmocka_unit_test(test_equal_meshes_keep_their_own_place_and_colour),
        cmocka_unit_test(test_textures_bmp_and_png),
        cmocka_unit_test(test_performance_bar_drawn),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
