/* test_viewer_meg.c -- Karma 1.2's object files (.meg) without drawing (the null renderer):
 * RGraphicSave then RGraphicLoadMEG gives the same vertices; RGraphicCreate normalises and scales
 * (a saved box scaled by (2, 1, 1) spans twice its width); RGraphicNormalize fits [-1, 1]; and every
 * kind of bad file (missing, empty, truncated, non-numeric, NaN, counts that disagree) gets
 * ME_ERR_VIEWER_BAD_MEG and NULL. */
#include "karma_test.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include <MeViewer.h>

#include "RInternal.h"
#include "viewer_null_context.h"

static const float red[4] = {1, 0, 0, 1};

static RRender *nullContext(void)
{
    int left;
    RRender *rc = viewerNullContext(NULL, NULL, &left);
    assert_non_null(rc);
    return rc;
}

/** The graphic's vertex bounds along each local axis. */
static void bounds(const RGraphic *rg, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++)
        lo[k] = INFINITY, hi[k] = -INFINITY;
    for (int i = 0; i < rg->m_pObject->m_nNumVertices; i++) {
        const RObjectVertex *v = &rg->m_pVertices[i];
        const double x[3] = {v->m_X, v->m_Y, v->m_Z};
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], x[k]), hi[k] = fmax(hi[k], x[k]);
    }
}

static void writeFile(const char *name, const char *text)
{
    FILE *f = fopen(name, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* A box of 1 x 2 x 3 (off-centre, to show loading keeps the frame) saved and loaded back: every
 * field of every vertex equal, bit for bit. */
static void test_save_then_load_round_trips(void **state)
{
    (void)state;
    RRender *rc = nullContext();
    RGraphic *box = RGraphicBoxCreate(rc, 1, 2, 3, red, NULL);
    assert_non_null(box);
    MeVector3 offset = {(MeReal)0.1, (MeReal)-7.3, (MeReal)1e-3};
    RGraphicTranslateVertices(rc, box, offset);
    assert_int_equal(RGraphicSave(box, "meg_test_box.meg"), 0);
    RGraphic *back = RGraphicLoadMEG("meg_test_box.meg");
    assert_non_null(back);
    assert_int_equal(back->m_pObject->m_nNumVertices, box->m_pObject->m_nNumVertices);
    assert_int_equal(back->m_private->inList, 0); /* loading lists nothing */
    for (int i = 0; i < box->m_pObject->m_nNumVertices; i++) {
        const RObjectVertex *a = &box->m_pVertices[i], *b = &back->m_pVertices[i];
        assert_true(a->m_X == b->m_X && a->m_Y == b->m_Y && a->m_Z == b->m_Z);
        assert_true(a->m_NX == b->m_NX && a->m_NY == b->m_NY && a->m_NZ == b->m_NZ);
        assert_true(a->m_U == b->m_U && a->m_V == b->m_V);
    }
    RGraphicDestroy(back);
    RRenderContextDestroy(rc);
    remove("meg_test_box.meg");
}

/* RGraphicCreate normalises (the box fits [-1, 1] on each axis) then scales: (2, 1, 1) makes it
 * 4 wide, 2 high, 2 deep; keeping the aspect ratio, a 1 x 2 x 3 box becomes 2/3 x 4/3 x 2, then x2
 * in x. It is in the 3D list, coloured and following the matrix. */
static void test_create_normalises_and_scales(void **state)
{
    (void)state;
    RRender *rc = nullContext();
    RGraphic *box = RGraphicBoxCreate(rc, 1, 2, 3, red, NULL);
    assert_int_equal(RGraphicSave(box, "meg_test_box2.meg"), 0);
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {5, 6, 7, 1}};
    const float green[4] = {0, 1, 0, 1};
    RGraphic *stretched = RGraphicCreate(rc, "meg_test_box2.meg", 2, 1, 1, green, tm, 0, 0);
    assert_non_null(stretched);
    double lo[3], hi[3];
    bounds(stretched, lo, hi);
    const double free_[3] = {4, 2, 2};
    for (int k = 0; k < 3; k++) {
        assert_near(hi[k] - lo[k], free_[k], 1e-5);
        assert_near(hi[k] + lo[k], 0, 1e-5); /* centred */
    }
    assert_int_equal(stretched->m_private->inList, 1);
    assert_ptr_equal(stretched->m_pLWMatrix, (MeMatrix4Ptr)tm);
    float c[4];
    RGraphicGetColor(stretched, c);
    assert_true(c[1] == 1 && c[0] == 0);

    RGraphic *kept = RGraphicCreate(rc, "meg_test_box2.meg", 2, 1, 1, green, NULL, 0, 1);
    bounds(kept, lo, hi);
    const double aspect[3] = {2 * 2.0 / 3, 4.0 / 3, 2};
    for (int k = 0; k < 3; k++)
        assert_near(hi[k] - lo[k], aspect[k], 1e-5);
    /* Normals stay unit and outward after the unequal scale: a face's normal points away from the centre. */
    for (int i = 0; i < stretched->m_pObject->m_nNumVertices; i++) {
        const RObjectVertex *v = &stretched->m_pVertices[i];
        assert_near(sqrt(v->m_NX * v->m_NX + v->m_NY * v->m_NY + v->m_NZ * v->m_NZ), 1, 1e-5);
        assert_true(v->m_NX * v->m_X + v->m_NY * v->m_Y + v->m_NZ * v->m_Z > 0);
    }
    RRenderContextDestroy(rc);
    remove("meg_test_box2.meg");
}

/* RGraphicNormalize: an off-centre 4 x 1 x 0.5 box becomes centred, 2 x 2 x 2 (each axis) or
 * 2 x 0.5 x 0.25 (aspect kept); a flat square keeps its flat axis flat (no division by 0). */
static void test_normalize_sizes(void **state)
{
    (void)state;
    RRender *rc = nullContext();
    MeVector3 offset = {3, -2, 10};
    double lo[3], hi[3];
    for (int keep = 0; keep <= 1; keep++) {
        RGraphic *box = RGraphicBoxCreate(rc, 4, 1, (AcmeReal)0.5, red, NULL);
        RGraphicTranslateVertices(rc, box, offset);
        RGraphicNormalize(box, keep);
        bounds(box, lo, hi);
        const double want[2][3] = {{2, 2, 2}, {2, 0.5, 0.25}};
        for (int k = 0; k < 3; k++) {
            assert_near(hi[k] - lo[k], want[keep][k], 1e-5);
            assert_near(hi[k] + lo[k], 0, 1e-5);
        }
    }
    RGraphic *square = RGraphicSquareCreate(rc, 3, red, NULL);
    RGraphicNormalize(square, 0);
    bounds(square, lo, hi);
    assert_near(hi[0] - lo[0], 2, 1e-6);
    assert_near(hi[1] - lo[1], 2, 1e-6);
    assert_true(hi[2] == 0 && lo[2] == 0);
    assert_reports(ME_ERR_NULL_ARGUMENT, RGraphicNormalize(NULL, 1));
    RRenderContextDestroy(rc);
}

/* A hand-written file in 1.2's layout (labels without ':' skipped, any white space) loads. */
static void test_hand_written_file(void **state)
{
    (void)state;
    writeFile("meg_test_hand.meg", "object triangle\nVertices:3\n"
                                   "v0 x:0 y:0 z:0 nx:0 ny:0 nz:1 u:0 v:0\n"
                                   "v1 x:1 y:0 z:0 nx:0 ny:0 nz:1 u:1 v:0\n"
                                   "v2 x:0 y:2.5e0 z:0 nx:0 ny:0 nz:1 u:0 v:1\n");
    RGraphic *rg = RGraphicLoadMEG("meg_test_hand.meg");
    assert_non_null(rg);
    assert_int_equal(rg->m_pObject->m_nNumVertices, 3);
    assert_true(rg->m_pVertices[2].m_Y == (AcmeReal)2.5 && rg->m_pVertices[1].m_U == 1);
    RGraphicDestroy(rg);
    remove("meg_test_hand.meg");
}

/* Each bad file: a coded message, NULL, and nothing listed. */
static void test_bad_files_are_refused(void **state)
{
    (void)state;
    RRender *rc = nullContext();
    static const char *const bad[] = {
        "",                                         /* empty: no count */
        "just words",                               /* no count */
        "Vertices:abc ",                            /* non-numeric count */
        "Vertices:0 ",                              /* zero */
        "Vertices:-3 ",                             /* negative */
        "Vertices:4 ",                              /* not a multiple of 3 */
        "Vertices:3.5 ",                            /* not whole */
        "Vertices:99999999999999999999 ",           /* absurd */
        "Vertices:3 x:0 y:0 z:0 nx:0 ny:0 nz:1 u:0 v:0 x:1 y:0", /* truncated */
        "Vertices:3 x:0 y:0 z:zero nx:0 ny:0 nz:1", /* non-numeric */
        "Vertices:3 x:1.0abc",                      /* trailing garbage */
        "Vertices:3 x:nan",                         /* NaN */
        "Vertices:3 x:inf",                         /* infinite */
        "Vertices:3 x:1e300",                       /* beyond float (or fine in double: then too few) */
        "Vertices:3 x:",                            /* nothing after ':' */
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
        writeFile("meg_test_bad.meg", bad[i]);
        RGraphic *rg = (RGraphic *)1;
        assert_reports(ME_ERR_VIEWER_BAD_MEG, rg = RGraphicLoadMEG("meg_test_bad.meg"));
        assert_null(rg);
        assert_reports(ME_ERR_VIEWER_BAD_MEG, rg = RGraphicCreate(rc, "meg_test_bad.meg", 1, 1, 1, red, NULL, 0, 0));
        assert_null(rg);
    }
    /* A NUL byte after a whole valid triangle: not text, refused rather than read up to the NUL. */
    static const char withNul[] = "Vertices:3 x:0 y:0 z:0 nx:0 ny:0 nz:1 u:0 v:0 x:1 y:0 z:0 nx:0 ny:0 nz:1 u:0 v:0 "
                                  "x:0 y:1 z:0 nx:0 ny:0 nz:1 u:0 v:0 \0 x:1";
    FILE *nul = fopen("meg_test_bad.meg", "wb");
    assert_non_null(nul);
    fwrite(withNul, 1, sizeof withNul - 1, nul);
    fclose(nul);
    {
        RGraphic *g = (RGraphic *)1;
        assert_reports(ME_ERR_VIEWER_BAD_MEG, g = RGraphicLoadMEG("meg_test_bad.meg"));
        assert_null(g);
    }
    /* More vertices than the count says. */
    char more[1024] = "Vertices:3 ";
    for (int v = 0; v < 4; v++)
        strcat(more, "x:0 y:0 z:0 nx:0 ny:0 nz:1 u:0 v:0 ");
    writeFile("meg_test_bad.meg", more);
    RGraphic *rg = (RGraphic *)1;
    assert_reports(ME_ERR_VIEWER_BAD_MEG, rg = RGraphicLoadMEG("meg_test_bad.meg"));
    assert_null(rg);
    remove("meg_test_bad.meg");
    assert_null(rc->m_pRG_First); /* nothing listed */

    assert_reports(ME_ERR_VIEWER_BAD_MEG, rg = RGraphicLoadMEG("meg_test_no_such_file.meg"));
    assert_null(rg);
    assert_reports(ME_ERR_NULL_ARGUMENT, rg = RGraphicLoadMEG(NULL));
    assert_null(rg);
    assert_reports(ME_ERR_NULL_ARGUMENT, rg = RGraphicCreate(NULL, "x.meg", 1, 1, 1, red, NULL, 0, 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, rg = RGraphicCreate(rc, "x.meg", 0, 1, 1, red, NULL, 0, 0));
    assert_null(rg);
    /* Saving: not a triangle list, nowhere to write. */
    RGraphic *box = RGraphicBoxCreate(rc, 1, 1, 1, red, NULL);
    AcmeReal a[3] = {0, 0, 0}, b[3] = {1, 0, 0};
    RGraphic *line = RGraphicLineCreate(rc, a, b, red, NULL);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, assert_int_equal(RGraphicSave(line, "meg_test_line.meg"), -1));
    assert_reports(ME_ERR_VIEWER_BAD_MEG, assert_int_equal(RGraphicSave(box, "no/such/dir/box.meg"), -1));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(RGraphicSave(NULL, "x.meg"), -1));
    RRenderContextDestroy(rc);
}

/* Mutated files (a fixed seed: bytes changed, removed and inserted, the file cut short): each loads as
 * a triangle list of finite numbers, or is refused with ME_ERR_VIEWER_BAD_MEG; never a crash (the
 * asan configuration checks every read). */
static void test_mutated_files_load_or_are_refused(void **state)
{
    (void)state;
    RRender *rc = nullContext();
    RGraphic *box = RGraphicBoxCreate(rc, 1, 2, 3, red, NULL);
    assert_int_equal(RGraphicSave(box, "meg_test_seed.meg"), 0);
    FILE *f = fopen("meg_test_seed.meg", "rb");
    assert_non_null(f);
    static char seed[65536], text[65536 + 64];
    size_t len = fread(seed, 1, sizeof seed - 1, f);
    fclose(f);
    remove("meg_test_seed.meg");
    static const char alphabet[] = "0123456789.:-+eE \n\tnaifxXV";
    unsigned long rng = 12345, loaded = 0, refused = 0;
    for (int trial = 0; trial < 200; trial++) {
        memcpy(text, seed, len);
        size_t n = len;
        for (int m = 0; m < 1 + trial % 4; m++) {
            rng = rng * 6364136223846793005ul + 1442695040888963407ul;
            size_t at = (size_t)(rng >> 33) % n;
            char c = alphabet[(rng >> 20) % (sizeof alphabet - 1)];
            switch ((rng >> 12) % 4) {
            case 0: text[at] = c; break;                                       /* change a byte */
            case 1: memmove(text + at, text + at + 1, n - at - 1), n--; break; /* remove one */
            case 2: memmove(text + at + 1, text + at, n - at), text[at] = c, n++; break; /* insert */
            default: n = at; break;                                            /* cut short */
            }
            if (n == 0)
                break;
        }
        f = fopen("meg_test_mutant.meg", "wb");
        assert_non_null(f);
        fwrite(text, 1, n, f);
        fclose(f);
        unsigned long before = MeMessageGetCount(ME_ERR_VIEWER_BAD_MEG);
        RGraphic *rg = RGraphicLoadMEG("meg_test_mutant.meg");
        if (rg) {
            loaded++;
            assert_int_equal(rg->m_pObject->m_nNumVertices % 3, 0);
            for (int i = 0; i < rg->m_pObject->m_nNumVertices; i++) {
                const RObjectVertex *v = &rg->m_pVertices[i];
                const AcmeReal x[8] = {v->m_X, v->m_Y, v->m_Z, v->m_NX, v->m_NY, v->m_NZ, v->m_U, v->m_V};
                for (int k = 0; k < 8; k++)
                    assert_true(isfinite(x[k]));
            }
            RGraphicDestroy(rg);
        } else {
            refused++;
            assert_int_equal(MeMessageGetCount(ME_ERR_VIEWER_BAD_MEG) - before, 1);
        }
    }
    remove("meg_test_mutant.meg");
    assert_true(loaded > 0 && refused > 0); /* both ways were exercised */
    RRenderContextDestroy(rc);
}

int main(void)
{
    karma_capture_messages();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_save_then_load_round_trips),
        cmocka_unit_test(test_create_normalises_and_scales),
        cmocka_unit_test(test_normalize_sizes),
        cmocka_unit_test(test_hand_written_file),
        cmocka_unit_test(test_bad_files_are_refused),
        cmocka_unit_test(test_mutated_files_load_or_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
