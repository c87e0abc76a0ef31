/* test_viewer_lines.c -- Karma 1.2's native lines (RNLine*), immediate lines (RLineAdd) and particle
 * systems (RParticleSystem*) as a person sees them (headless): each lies on the pixels where the
 * camera's matrices project it, in its colour, and nowhere else; moving, recolouring, listing and
 * deleting show on the next frame; a box in front hides a line; particles follow the application's
 * array; bad input is reported with a code and changes nothing. */
#include "karma_test.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "RInternal.h"
#include "viewer_project.h"
#include "viewer_two_colour_png.h"

#define W 200
#define H 140

static unsigned char rgba[W * H * 4];

static RRender *blackContext(void)
{
    RRender *rc = RRenderContextCreateHeadless(W, H);
    assert_non_null(rc);
    const float black[4] = {0, 0, 0, 1};
    RRenderSetBackgroundColor(rc, black);
    return rc;
}

static void draw(RRender *rc)
{
    RRenderDrawFrame(rc);
    assert_int_equal(RRenderReadPixels(rc, rgba), 0);
}

/* The pixel (column, row from the top) a world point projects to. */
static void pixelOf(RRender *rc, const double p[3], int *x, int *y)
{
    double ndc[3];
    assert_true(viewerProject(rc, p, ndc) > 0);
    *x = (int)floor((ndc[0] * 0.5 + 0.5) * W);
    *y = (int)floor((0.5 - ndc[1] * 0.5) * H);
    assert_true(*x >= 1 && *x < W - 1 && *y >= 1 && *y < H - 1);
}

/* Whether a pixel within one of (x, y) is mostly of colour c (each channel 0 or 1): the channels that
 * are 1 above 100, those that are 0 below 60 (a one-pixel line is blended at its edges). */
static int colourNear(int x, int y, const float c[3])
{
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            const unsigned char *p = rgba + 4 * ((y + dy) * W + x + dx);
            int ok = 1;
            for (int k = 0; k < 3; k++)
                ok &= c[k] > 0.5f ? p[k] > 100 : p[k] < 60;
            if (ok)
                return 1;
        }
    return 0;
}

/* How many of the 7 interior points a + t(b − a), t = 1/8 … 7/8, show colour c. */
static int pointsOnSegment(RRender *rc, const double a[3], const double b[3], const float c[3])
{
    int n = 0;
    for (int i = 1; i <= 7; i++) {
        double t = i / 8.0, p[3] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
        int x, y;
        pixelOf(rc, p, &x, &y);
        n += colourNear(x, y, c);
    }
    return n;
}

/* Pixels of the whole picture that are not black. */
static int litPixels(void)
{
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += rgba[4 * i] > 30 || rgba[4 * i + 1] > 30 || rgba[4 * i + 2] > 30;
    return n;
}

/* The picture's pixel (RGBA) where the world point p projects. */
static const unsigned char *pixelAt(RRender *rc, const double p[3])
{
    int x, y;
    pixelOf(rc, p, &x, &y);
    return rgba + 4 * (y * W + x);
}

/* A test's end: with everything it drew taken away the next frame is black, nothing was reported on
 * the way, and the context goes. */
static void assertBlankAndQuietThenDestroy(RRender *rc)
{
    draw(rc);
    assert_int_equal(litPixels(), 0);
    assert_int_equal(karma_warning_count(), 0);
    RRenderContextDestroy(rc);
}

static const float red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, blue[4] = {0, 0, 1, 1};

static void test_native_lines_on_their_projected_pixels(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = blackContext();
    draw(rc);
    assert_int_equal(litPixels(), 0);
    /* A red line in the world, a green one local to a matrix (turned a quarter about z, moved). */
    AcmeReal a[3] = {-4, 2, 1}, b[3] = {4, 2.5, 1};
    RNLine *r = RNLineCreate(rc, a, b, red, NULL);
    MeMatrix4 tm = {{0, 1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {-3, -1, 0, 1}};
    AcmeReal la[3] = {-2, 0, 0}, lb[3] = {2, 0, 0}; /* along local x: world y, from (−3, −3) to (−3, 1) */
    RNLine *g = RNLineCreate(rc, la, lb, green, tm);
    assert_non_null(r);
    assert_non_null(g);
    draw(rc);
    const double ra[3] = {-4, 2, 1}, rb[3] = {4, 2.5, 1}, ga[3] = {-3, -3, 0}, gb[3] = {-3, 1, 0};
    assert_int_equal(pointsOnSegment(rc, ra, rb, red), 7);
    assert_int_equal(pointsOnSegment(rc, ga, gb, green), 7);
    /* Thin: the lines cover a few hundred pixels, not the picture. */
    int lit = litPixels();
    assert_true(lit > 100 && lit < 1000);
    /* The matrix moves: the green line follows it at the next frame. */
    tm[3][0] = 3;
    draw(rc);
    const double ga2[3] = {3, -3, 0}, gb2[3] = {3, 1, 0};
    assert_int_equal(pointsOnSegment(rc, ga2, gb2, green), 7);
    assert_int_equal(pointsOnSegment(rc, ga, gb, green), 0);
    /* Moved ends, a new colour. */
    AcmeReal c[3] = {-4, -2, 1}, d[3] = {2, -2.5, 1};
    assert_int_equal(RNLineMoveEnds(r, c, d), 0);
    RNLineSetColor(r, blue);
    draw(rc);
    const double rc0[3] = {-4, -2, 1}, rd[3] = {2, -2.5, 1};
    assert_int_equal(pointsOnSegment(rc, rc0, rd, blue), 7);
    assert_int_equal(pointsOnSegment(rc, ra, rb, red), 0);
    assert_int_equal(pointsOnSegment(rc, ra, rb, blue), 0);
    /* Out of the list: not drawn; back: drawn. */
    RNLineRemoveFromList(rc, r);
    draw(rc);
    assert_int_equal(pointsOnSegment(rc, rc0, rd, blue), 0);
    RNLineAddToList(rc, r);
    draw(rc);
    assert_int_equal(pointsOnSegment(rc, rc0, rd, blue), 7);
    /* Depth-tested: a white box between the camera and the line's middle hides it there. */
    MeMatrix4 boxTm = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {-1, -2.25, 4, 1}};
    RGraphic *box = RGraphicBoxCreate(rc, 1, 1, 1, (const float[4]){1, 1, 1, 1}, boxTm);
    draw(rc);
    const double mid[3] = {-1, -2.25, 1};
    int x, y;
    pixelOf(rc, mid, &x, &y);
    assert_false(colourNear(x, y, blue));
    assert_true(pointsOnSegment(rc, rc0, rd, blue) >= 4);
    RGraphicDelete(rc, box, 0);
    /* Deleted and destroyed: nothing left. */
    RNLineDelete(rc, r);
    RNLineDestroy(g);
    assertBlankAndQuietThenDestroy(rc);
}

/* RLineAdd's lines stay until RLineRemoveAll, as 1.2's demos use them for MeDebugDrawAPI.line. */
static void test_immediate_lines_until_removed(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = blackContext();
    MeVector3 a = {-3, 0, 1}, b = {3, 1, 1}, c = {-3, -2, 1}, d = {3, -3, 1};
    RLineAdd(rc, a, b, 1, 1, 0);
    RLineAdd(rc, c, d, 0, 1, 1);
    draw(rc);
    const double da[3] = {-3, 0, 1}, db[3] = {3, 1, 1}, dc[3] = {-3, -2, 1}, dd[3] = {3, -3, 1};
    const float yellow[3] = {1, 1, 0}, cyan[3] = {0, 1, 1};
    assert_int_equal(pointsOnSegment(rc, da, db, yellow), 7);
    assert_int_equal(pointsOnSegment(rc, dc, dd, cyan), 7);
    draw(rc); /* still there a frame later */
    assert_int_equal(pointsOnSegment(rc, da, db, yellow), 7);
    RLineRemoveAll(rc);
    draw(rc);
    assert_int_equal(litPixels(), 0);
    /* Many: they grow their buffer and are all drawn. */
    for (int i = 0; i < 500; i++) {
        MeVector3 p = {-4 + 0.016 * i, -3, 1}, q = {-4 + 0.016 * i, 3, 1};
        RLineAdd(rc, p, q, 1, 0, 0);
    }
    float *ends = NULL;
    int capacity = 0;
    assert_int_equal(RNLineGather(rc, &ends, &capacity), 1000);
    free(ends);
    draw(rc);
    const double sa[3] = {-2, -2, 1}, sb[3] = {0, 2, 1};
    assert_int_equal(pointsOnSegment(rc, sa, sb, red), 7);
    RRenderContextDestroy(rc);
}

/* Multisampled (4×): a slanted line's pixels are partly covered along its edges, so between black
 * and its colour; without antialiasing every pixel would be one or the other. */
static void test_lines_are_antialiased(void **state)
{
    (void)state;
    RRender *rc = blackContext();
    AcmeReal a[3] = {-5, -3, 1}, b[3] = {5, 2, 1};
    RNLine *line = RNLineCreate(rc, a, b, red, NULL);
    draw(rc);
    int full = 0, partial = 0;
    for (int i = 0; i < W * H; i++) {
        int r = rgba[4 * i];
        full += r >= 215;
        partial += r > 40 && r < 215;
    }
    assert_true(full > 20);
    assert_true(partial > 20);
    RNLineDestroy(line);
    RRenderContextDestroy(rc);
}

static void test_lines_refuse_bad_input(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = blackContext();
    AcmeReal a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, nan3[3] = {0, NAN, 0};
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RNLineCreate(NULL, a, b, red, NULL)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RNLineCreate(rc, a, NULL, red, NULL)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RNLineCreate(rc, a, b, NULL, NULL)));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, assert_null(RNLineCreate(rc, nan3, b, red, NULL)));
    RNLine *line = RNLineCreate(rc, a, b, red, NULL);
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, assert_int_equal(RNLineMoveEnds(line, a, nan3), -1));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(RNLineMoveEnds(line, NULL, b), -1));
    const float nanColour[4] = {1, NAN, 0, 1};
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RNLineSetColor(line, nanColour));
    /* Nothing changed: the line's one segment is where and what it was. */
    float *ends = NULL;
    int capacity = 0;
    assert_int_equal(RNLineGather(rc, &ends, &capacity), 2);
    const float want[2 * R_LINE_FLOATS] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 1};
    assert_memory_equal(ends, want, sizeof want);
    /* Another context's line is refused by this one's list. */
    RRender *other = blackContext();
    assert_reports(ME_ERR_FOREIGN_HANDLE, RNLineRemoveFromList(other, line));
    assert_reports(ME_ERR_FOREIGN_HANDLE, RNLineDelete(other, line));
    assert_int_equal(RNLineGather(rc, &ends, &capacity), 2);
    RRenderContextDestroy(other);
    MeVector3 p = {0, 0, 0}, q = {INFINITY, 0, 0};
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RLineAdd(rc, p, q, 1, 0, 0));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, RLineAdd(rc, p, p, NAN, 0, 0));
    assert_reports(ME_ERR_NULL_ARGUMENT, RLineAdd(NULL, p, p, 1, 0, 0));
    assert_int_equal(RNLineGather(rc, &ends, &capacity), 2);
    free(ends);
    /* The line is still the context's when it goes (freed with it: ASan would say otherwise). */
    RRenderContextDestroy(rc);
}

static void test_particles_at_their_positions(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = blackContext();
    MeVector3 positions[3] = {{-3, 1, 1}, {0, -1.5, 1}, {3, 2, 1}};
    const float magenta[4] = {1, 0, 1, 1};
    RParticleSystem *ps = RParticleSystemCreate(rc, 3, positions, NULL, magenta, ME_R(0.8));
    assert_non_null(ps);
    assert_int_equal(ps->m_nTextureID, -1);
    draw(rc);
    for (int i = 0; i < 3; i++) {
        const double p[3] = {positions[i][0], positions[i][1], positions[i][2]};
        const unsigned char *px = pixelAt(rc, p);
        assert_true(px[0] > 240 && px[1] < 15 && px[2] > 240); /* unlit: the colour itself */
        /* 0.8 m across: 0.6 m away (beyond the disc's radius of 0.4) is black. */
        const double off[3] = {p[0] + 0.6, p[1], p[2]};
        assert_int_equal(pixelAt(rc, off)[0], 0);
    }
    /* A disc: its area on the picture is π r² in pixels (the projection's scale at depth 15). */
    double pxPerMetre = rc->m_ProjMatrix[1][1] * 0.5 * H / 15.0;
    double disc = 3.14159265358979 * pow(0.4 * pxPerMetre, 2);
    assert_near(litPixels(), 3 * disc, 0.2 * 3 * disc);
    /* The application moves a particle: the next frame shows it there. */
    positions[0][0] = -1, positions[0][1] = 3;
    draw(rc);
    const double moved[3] = {-1, 3, 1}, was[3] = {-3, 1, 1};
    assert_true(pixelAt(rc, moved)[0] > 240);
    assert_int_equal(pixelAt(rc, was)[0], 0);
    /* A particle at a non-finite position is skipped, the others drawn. */
    positions[1][0] = NAN;
    draw(rc);
    assert_true(pixelAt(rc, moved)[0] > 240);
    assert_near(litPixels(), 2 * disc, 0.2 * 2 * disc);
    /* Out of the list: not drawn. */
    RParticleSystemRemoveFromList(rc, ps);
    draw(rc);
    assert_int_equal(litPixels(), 0);
    RParticleSystemAddToList(rc, ps);
    draw(rc);
    int shown = litPixels();
    assert_true(shown > 0);
    /* The F12 menu's "Particles" (its eighth entry) turns them off, and on again (the menu shows
     * again at the entry it was left at). */
    for (int on = 0; on < 2; on++) {
        RInputKey(rc, RKEY_F12, 0);
        for (int i = 0; i < (on ? 0 : 7); i++)
            RInputKey(rc, RKEY_DOWN, 0);
        RInputKey(rc, RKEY_RIGHT, 0);
        RInputKey(rc, RKEY_F12, 0); /* the menu hidden again */
        assert_int_equal(rc->m_private->noParticles, !on);
        assert_null(rc->m_private->menuShown);
        draw(rc);
        assert_int_equal(litPixels(), on ? shown : 0);
    }
    RParticleSystemDestroy(ps);
    assertBlankAndQuietThenDestroy(rc);
}

/* A textured system: the texture's square (left half red, right half blue) times the colour. */
static void test_textured_particles(void **state)
{
    (void)state;
    karma_capture_messages();
    assert_int_equal(viewerWriteTwoColourPng("viewer_particle.png"), 0);
    RRender *rc = blackContext();
    MeVector3 one[1] = {{0, 0, 1}};
    const float white[4] = {1, 1, 1, 1};
    RParticleSystem *ps = RParticleSystemCreate(rc, 1, one, "viewer_particle", white, 2);
    assert_non_null(ps);
    assert_true(ps->m_nTextureID >= 0);
    draw(rc);
    const double left[3] = {-0.6, 0, 1}, right[3] = {0.6, 0, 1}, corner[3] = {-0.9, 0.9, 1};
    const unsigned char *px = pixelAt(rc, left);
    assert_true(px[0] > 200 && px[2] < 40);
    px = pixelAt(rc, right);
    assert_true(px[2] > 200 && px[0] < 40);
    px = pixelAt(rc, corner); /* a square, not a disc: the corner is the texture's (red and blue blended there) */
    assert_true(px[0] + px[2] > 200 && px[1] < 40);
    RRenderContextDestroy(rc); /* frees the listed system */
}

static void test_particles_refuse_bad_input(void **state)
{
    (void)state;
    karma_capture_messages();
    RRender *rc = blackContext();
    MeVector3 p[2] = {{0, 0, 0}, {1, 0, 0}};
    const float white[4] = {1, 1, 1, 1};
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(RParticleSystemCreate(rc, -1, p, NULL, white, 1)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(RParticleSystemCreate(rc, 2, p, NULL, white, 0)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(RParticleSystemCreate(rc, 2, p, NULL, white, NAN)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RParticleSystemCreate(rc, 2, NULL, NULL, white, 1)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RParticleSystemCreate(rc, 2, p, NULL, NULL, 1)));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_null(RParticleSystemCreate(NULL, 2, p, NULL, white, 1)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(RParticleSystemCreate(rc, 2, p, "no_such_texture", white, 1)));
    assert_null(rc->m_private->particles); /* nothing listed */
    RParticleSystem *ps = RParticleSystemNew(2, p, -1, white, 1);
    assert_non_null(ps);
    assert_null(ps->m_pRender); /* New lists nothing */
    RParticleSystemAddToList(rc, ps);
    RParticleSystemAddToList(rc, ps); /* twice: listed once */
    assert_ptr_equal(rc->m_private->particles, ps);
    assert_null(ps->m_pNextSystem);
    RRender *other = blackContext();
    assert_reports(ME_ERR_FOREIGN_HANDLE, RParticleSystemAddToList(other, ps));
    assert_null(other->m_private->particles);
    RRenderContextDestroy(other);
    RParticleSystemDestroy(ps);
    assert_null(rc->m_private->particles);
    RRenderContextDestroy(rc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_native_lines_on_their_projected_pixels),
        cmocka_unit_test(test_immediate_lines_until_removed),
        cmocka_unit_test(test_lines_are_antialiased),
        cmocka_unit_test(test_lines_refuse_bad_input),
        cmocka_unit_test(test_particles_at_their_positions),
        cmocka_unit_test(test_textured_particles),
        cmocka_unit_test(test_particles_refuse_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
