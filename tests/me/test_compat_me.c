/* Karma 1.2's Me API as 1.2 programs use it: MeMemoryAPI as a global table read at every call, the
 * general-matrix and index helpers of MeMath.h, the message kinds and their hooks, the global
 * profiler, simple files, MePoolx and the pool tables, chunks with an alignment, MeMisc, MeBounding
 * and MeDebugDraw. */
#define _POSIX_C_SOURCE 200809L
#include "karma_test.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <karma/karma.h>
#include <karma/MeBounding.h>
#include <karma/MeDebugDraw.h>
#include <karma/MeMisc.h>
#include <karma/MePoolx.h>
#include <karma/MeSimpleFile.h>

/* ------------------------------------------------------------------------------ MeMemoryAPI */

static int countedCreates;
static void *MEAPI countingCreate(size_t bytes)
{
    countedCreates++;
    return MeMemoryGetDefaultAPI()->create(bytes);
}

static void memory_api_assignment_reaches_every_allocation(void **state)
{
    MeMemoryAPIStruct saved = MeMemoryAPI;
    MdtWorldID w;
    void *p;
    (void)state;
    MeMemoryAPI.create = countingCreate; /* 1.2's way: assign a field before any Karma call */
    w = MdtWorldCreate(10, 10, 1, 1);
    assert_non_null(w);
    assert_true(countedCreates > 0);
    p = MeMemoryAPI.create(32);
    assert_non_null(p);
    MeMemoryAPI.destroy(p);
    MdtWorldDestroy(w);
    MeMemoryAPI = saved;
    assert_ptr_equal(MeMemoryGetAPI(), &MeMemoryAPI);
}

static void memory_align_macros(void **state)
{
    char buffer[200];
    MeMemoryQUADALIGNEDALLOCA(scratch, MeReal, 8)
    (void)state;
    assert_int_equal((MeUintPtr)MeMemoryQUADALIGN(buffer + 1) % 16, 0);
    assert_true((char *)MeMemoryQUADALIGN(buffer + 1) - (buffer + 1) < 16);
    assert_int_equal((MeUintPtr)MeMemory64ALIGN(buffer + 3) % 64, 0);
    assert_int_equal((MeUintPtr)scratch % 16, 0);
    scratch[7] = 1;
    MeMemoryQUADALIGNEDFREEA(scratch);
}

/* ------------------------------------------------------------------------------------ MeMath */

static void general_matrices_are_column_major(void **state)
{
    /* B = [1 2 3; 4 5 6] (2 x 3), C = [1 0; 0 1; 1 1] (3 x 2), column-major. */
    const MeReal B[6] = {1, 4, 2, 5, 3, 6};
    const MeReal C[6] = {1, 0, 1, 0, 1, 1};
    MeReal A[4], T[6], BT[6], A2[4];
    (void)state;
    MeMatrixMultiply(A, 2, 3, 2, B, C); /* [4 5; 10 11] */
    assert_near(A[0], 4, 0);
    assert_near(A[1], 10, 0);
    assert_near(A[2], 5, 0);
    assert_near(A[3], 11, 0);
    MeMatrixTranspose(T, 3, 2, B); /* T = B^T, 3 x 2: [1 4; 2 5; 3 6] */
    assert_near(T[0], 1, 0);
    assert_near(T[1], 2, 0);
    assert_near(T[2], 3, 0);
    assert_near(T[3], 4, 0);
    assert_near(T[5], 6, 0);
    MeMatrixTranspose(BT, 3, 2, B);
    MeMatrixMultiplyT1(A2, 2, 3, 2, BT, C); /* (B^T)^T C = B C */
    assert_memory_equal(A, A2, sizeof A);
}

static void index_helpers_and_sorting(void **state)
{
    MeReal a[3] = {3, 1, 2}, zeros[4] = {0, 0, 0, 0};
    MeI32 index[3];
    MeMatrix3 m = {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}};
    MeVector3 A0, A1, A2, v = {1, 2, 3}, u = {-1, 4, 2}, out, cross;
    int n, r, c, seen[10] = {0};
    (void)state;
    assert_int_equal(MinIndex(a), 1);
    Sort3(index, a);
    assert_int_equal(index[0], 1);
    assert_int_equal(index[1], 2);
    assert_int_equal(index[2], 0);
    for (n = 0; n < 3; n++) {
        assert_int_equal(NextMod3(n), (n + 1) % 3);
        assert_int_equal(PrevMod3(n), (n + 2) % 3);
        assert_int_equal(NextModN(n, 3), (n + 1) % 3);
        assert_int_equal(PrevModN(n, 3), (n + 2) % 3);
    }
    assert_int_equal(NextMod4(3), 0);
    assert_int_equal(PrevMod4(0), 3);
    assert_int_equal(NextMod2(1), 0);
    assert_int_equal(MeMathCEIL4(5), 8);
    assert_int_equal(MeMathCEIL16(16), 16);
    assert_int_equal(MeMathCEILN(12, 13), 24);
    assert_int_equal(MeMathFLOOR4(7), 4);
    assert_true(MeRealArrayIsZero(zeros, 4));
    zeros[3] = ME_R(1e-30);
    assert_false(MeRealArrayIsZero(zeros, 4));
    /* Packed upper triangle of a 4 x 4 matrix: the 10 indices are 0..9, each once, row by row. */
    assert_int_equal(MeUpperDiagonalSize(4), 10);
    for (r = 0; r < 4; r++)
        for (c = r; c < 4; c++) {
            seen[MeUpperDiagonalIndex(r, c, 4)]++;
            assert_int_equal(MeSymUpperDiagonalIndex(c, r, 4), MeUpperDiagonalIndex(r, c, 4));
        }
    for (n = 0; n < 10; n++)
        assert_int_equal(seen[n], 1);
    assert_int_equal(MeSuperDiagonalSize(4), 6);
    assert_int_equal(MeSuperDiagonalIndex(0, 1, 4), 0);
    assert_int_equal(MeSuperDiagonalIndex(2, 3, 4), 5);
    assert_int_equal(MeSymSuperDiagonalIndex(3, 1, 4), MeSuperDiagonalIndex(1, 3, 4));
    MeMatrix3SwapColumns(m, 0, 2);
    assert_near(m[1][0], 6, 0);
    assert_near(m[1][2], 4, 0);
    /* 1.2's cross matrix: rows scaled by factor; u * [A0; A1; A2] = factor (v x u). */
    MeMatrix3CrossFromVector(A0, A1, A2, v, ME_R(2.0));
    for (n = 0; n < 3; n++)
        out[n] = u[0] * A0[n] + u[1] * A1[n] + u[2] * A2[n];
    MeVector3Cross(cross, v, u);
    MeVector3Scale(cross, ME_R(2.0));
    assert_near(out[0], cross[0], 1e-5);
    assert_near(out[1], cross[1], 1e-5);
    assert_near(out[2], cross[2], 1e-5);
}

/* ---------------------------------------------------------------------------------- messages */

static char shown[256];
static void MEAPI captureShow(const int level, const char *const string)
{
    (void)level;
    snprintf(shown, sizeof shown, "%s", string);
}

static int handled;
static void MEAPI countingHandler(const int level, const char *const format, va_list ap)
{
    (void)level;
    (void)format;
    (void)ap;
    handled++;
}

static void message_kinds_and_hooks(void **state)
{
    MeShow previousShow;
    MeHandler previousHandler;
    unsigned long before;
    (void)state;
    MeSetMessageHandler(NULL, NULL, NULL); /* the default handler writes through the Show hooks */
    previousShow = MeSetWarningShow(captureShow);
    MeWarning(2, "tyre %d is flat", 3);
    assert_non_null(strstr(shown, "tyre 3 is flat"));
    shown[0] = '\0';
    MeSetLogShow(captureShow);
    MeSetMessageLevel(ME_LEVEL_INFO); /* information is not shown by default */
    MeLog(0, "logged %s", "line");
    assert_non_null(strstr(shown, "logged line"));
    MeSetMessageLevel(ME_LEVEL_WARNING);
    assert_ptr_equal(MeSetWarningShow(previousShow), captureShow);
    MeSetLogShow(NULL);
    /* A replaced kind handler takes the call; NULL restores the default. */
    previousHandler = MeSetInfoHandler(countingHandler);
    assert_ptr_equal(previousHandler, MeHandlerInfo);
    MeInfo(0, "to the counter");
    assert_int_equal(handled, 1);
    MeSetInfoHandler(NULL);
    assert_ptr_equal(MeInfoHandler, MeHandlerInfo);
    /* The verbosity cut-off drops messages above it. */
    before = MeMessageGetCount(ME_ERR_USER_MESSAGE);
    MeWarningLevel = 1;
    MeWarning(5, "too verbose");
    assert_int_equal(MeMessageGetCount(ME_ERR_USER_MESSAGE), before);
    MeWarningLevel = 1000;
    ME_REPORT(MeWarning(0, "compiled out without _MECHECK"));
    {
        char path[] = "a/b/c.c";
        assert_string_equal(MeShortenPath(path), "c.c");
    }
}

/* ------------------------------------------------------------------------------ the profiler */

static volatile double sink;
static void spin(void)
{
    int i;
    for (i = 0; i < 200000; i++)
        sink += 1e-9 * i;
}

static void global_profiler_times_sections(void **state)
{
    MeProfileTimerMode mode = {0, kMeProfileCounterModeCache, NULL, NULL};
    (void)state;
    MeProfileStartTiming(mode, kMeProfileDontLog);
    MeProfileStartFrame();
    MeProfileStartSection("Collision", 0);
    spin();
    MeProfileEndSection("Collision");
    MeProfileStartSection("Dynamics", 1); /* autoStop: ended by the next section start */
    spin();
    MeProfileStartSection("Rendering", 0);
    MeProfileEndSection("Rendering");
    MeProfileStopTimers();
    MeProfileEndFrame();
    assert_true(MeProfileGetSectionTime("Collision") > 0);
    assert_true(MeProfileGetSectionTime("Dynamics") > 0);
    assert_true(MeProfileGetSectionTime("Dynamics") >= MeProfileGetSectionTime("Rendering"));
    assert_true(MeProfileGetSectionTime("nothing") == 0);
    assert_near(MeProfileGetAllSectionTime(),
                MeProfileGetSectionTime("Collision") + MeProfileGetSectionTime("Dynamics") +
                    MeProfileGetSectionTime("Rendering"),
                1e-3);
    assert_true(MeProfileGetClockSpeed() > 0);
    /* Stopped: sections are ignored. */
    MeProfileStopTiming();
    MeProfileStartFrame();
    MeProfileStartSection("Collision", 0);
    MeProfileEndSection("Collision");
    MeProfileEndFrame();
    assert_true(MeProfileGetSectionTime("Collision") == 0);
    MeProfileStartTiming(mode, kMeProfileDontLog);
}

/* ------------------------------------------------------------------------------------- files */

static void simple_files_read_write_and_search(void **state)
{
    char dir[] = "/tmp/karma_files_XXXXXX";
    char cwd[512], text[] = "Karma 1.2 resource\n", got[64];
    char *whole;
    int f, size = 0;
    (void)state;
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_non_null(mkdtemp(dir));
    assert_int_equal(chdir(dir), 0);
    assert_int_equal(mkdir("Resources", 0777), 0);
    f = MeOpen("Resources/box.ka", kMeOpenModeWRONLY);
    assert_true(f >= 0);
    assert_int_equal(MeWrite(f, text, (int)strlen(text)), (int)strlen(text));
    assert_int_equal(MeClose(f), 0);
    assert_true(MeOpen("box.ka", kMeOpenModeRDONLY) < 0);
    f = MeOpenWithSearch("box.ka", kMeOpenModeRDBINARY); /* found under Resources/ */
    assert_true(f >= 0);
    assert_int_equal(MeLseek(f, 6, kMeSeekSET), 6);
    assert_int_equal(MeRead(f, got, 3), 3);
    assert_memory_equal(got, "1.2", 3);
    assert_int_equal(MeLseek(f, 0, kMeSeekSET), 0);
    whole = MeLoadWholeFileHandle(f, &size);
    assert_non_null(whole);
    assert_int_equal(size, (int)strlen(text));
    assert_string_equal(whole, text);
    MeMemoryAPI.destroy(whole);
    MeClose(f);
    assert_string_equal(MeGetDefaultFileLocation(0), "");
    assert_string_equal(MeGetDefaultFileLocation(1), "Resources/");
    assert_null(MeGetDefaultFileLocation(1000));
    f = MeOpen("copy.ka", kMeOpenModeWRONLY);
    MeSaveWholeFileHandle(f, text, (int)strlen(text));
    MeClose(f);
    f = MeOpenWithSearch("copy.ka", kMeOpenModeRDONLY);
    assert_int_equal(MeRead(f, got, sizeof got), (int)strlen(text));
    MeClose(f);
    unlink("copy.ka");
    unlink("Resources/box.ka");
    rmdir("Resources");
    assert_int_equal(chdir(cwd), 0);
    rmdir(dir);
}

/* ------------------------------------------------------------------------- pools and chunks */

static void poolx_hands_out_and_takes_back(void **state)
{
    int memory[4 * 3];
    MePoolx p;
    int *a, *b, *c, *d;
    (void)state;
    MePoolxInit(&p, memory, 3 * sizeof(int), 4);
    a = MePoolxGet(&p);
    b = MePoolxGetZeroed(&p);
    c = MePoolxGet(&p);
    d = MePoolxGet(&p);
    assert_non_null(d);
    assert_null(MePoolxGet(&p));
    assert_int_equal(b[0] + b[1] + b[2], 0);
    assert_true(a != b && b != c && c != d);
    MePoolxPut(&p, b);
    MePoolxPut(&p, d);
    assert_ptr_equal(MePoolxGet(&p), d);
    assert_ptr_equal(MePoolxGet(&p), b);
    assert_null(MePoolxGet(&p));
}

static void pool_tables_fixed_and_malloc(void **state)
{
    const struct MePoolAPI *tables[2] = {&MePoolFixedAPI, &MePoolMallocAPI};
    int t;
    (void)state;
    for (t = 0; t < 2; t++) {
        MePool pool;
        void *s1, *s2;
        tables[t]->init(&pool, 2, 24, 16);
        s1 = MePoolAPI.getStruct(&pool);
        s2 = MePoolAPI.getStruct(&pool);
        assert_non_null(s1);
        assert_non_null(s2);
        assert_int_equal((MeUintPtr)s1 % 16, 0);
        assert_null(MePoolAPI.getStruct(&pool));
        assert_int_equal(MePoolAPI.getUsed(&pool), 2);
        MePoolAPI.putStruct(&pool, s1);
        assert_int_equal(MePoolAPI.getUnused(&pool), 1);
        MePoolAPI.putStruct(&pool, s2);
        MePoolAPI.destroy(&pool);
    }
}

static void chunk_alignment_and_free_mode(void **state)
{
    MeChunk chunk;
    void *m;
    (void)state;
    MeChunkInit(&chunk, 128);
    assert_int_equal(MeChunkGetAlignment(&chunk), 128);
    m = MeChunkGetMem(&chunk, 1000);
    assert_int_equal((MeUintPtr)m % 128, 0);
    MeChunkPutMem(&chunk, m);
    assert_true(MeChunkGetCurrentSize(&chunk) >= 1000);
    MeChunkSetMode(&chunk, kMeChunkModeFreeOnPut);
    m = MeChunkGetMem(&chunk, 10);
    MeChunkPutMem(&chunk, m);
    assert_int_equal(MeChunkGetCurrentSize(&chunk), 0);
    MeChunkTerm(&chunk);
}

/* ------------------------------------------------------------------------ misc and bounding */

static void hsv_bounding_and_debug_draw(void **state)
{
    float rgb[3];
    MeVector3 points[5] = {{1, 0, 0}, {-1, 0, 0}, {0, 0.5f, 0}, {0, 0, 0.9f}, {0.2f, 0.2f, 0.2f}};
    MeVector3 centre, zero = {0, 0, 0};
    MeReal radius;
    int i;
    (void)state;
    MeHSVtoRGB(0, 1, 1, rgb);
    assert_near(rgb[0], 1, 1e-6);
    assert_near(rgb[1], 0, 1e-6);
    MeHSVtoRGB(480, 1, 1, rgb); /* = 120: green */
    assert_near(rgb[1], 1, 1e-6);
    assert_near(rgb[0], 0, 1e-6);
    MeHSVtoRGB(240, 0.5f, 0.8f, rgb);
    assert_near(rgb[2], 0.8, 1e-6);
    assert_near(rgb[0], 0.4, 1e-6);
    MeBoundingSphereCalc(points, 5, centre, &radius);
    for (i = 0; i < 5; i++)
        assert_true(MeVector3Distance(points[i], centre) <= radius * (1 + 1e-6));
    assert_near(radius, 1, 1e-6); /* the diameter (-1,0,0)-(1,0,0) holds the rest */
    assert_near(MeVector3Distance(centre, zero), 0, 1e-6);
    MeDebugDrawAPI.line(points[0], points[1], 1, 0, 0); /* the default hook draws nothing */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(memory_api_assignment_reaches_every_allocation),
        cmocka_unit_test(memory_align_macros),
        cmocka_unit_test(general_matrices_are_column_major),
        cmocka_unit_test(index_helpers_and_sorting),
        cmocka_unit_test(message_kinds_and_hooks),
        cmocka_unit_test(global_profiler_times_sections),
        cmocka_unit_test(simple_files_read_write_and_search),
        cmocka_unit_test(poolx_hands_out_and_takes_back),
        cmocka_unit_test(pool_tables_fixed_and_malloc),
        cmocka_unit_test(chunk_alignment_and_free_mode),
        cmocka_unit_test(hsv_bounding_and_debug_draw),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
