/* MePool (capacity, generations, high water), MeChunk (doubling, growth reports), MeProfile. */
#include "karma_test.h"

#include <karma/MeChunk.h>
#include <karma/MePool.h>
#include <karma/MeProfile.h>

typedef struct Thing {
    double x;
    int tag;
} Thing;

static void pool_hands_out_and_recycles(void **state)
{
    (void)state;
    MePool pool;
    assert_true(MePoolInit(&pool, 3, sizeof(Thing), 32, "maxThings", 0));
    Thing *a = MePoolGetStruct(&pool), *b = MePoolGetStruct(&pool), *c = MePoolGetStruct(&pool);
    assert_non_null(a);
    assert_non_null(b);
    assert_non_null(c);
    assert_int_equal((uintptr_t)a % 32, 0);
    assert_int_equal((uintptr_t)b % 32, 0);
    assert_null(MePoolGetStruct(&pool)); /* full */
    assert_int_equal(MePoolGetUsed(&pool), 3);
    assert_int_equal(MePoolGetUnused(&pool), 0);
    assert_int_equal(MePoolGetHighWater(&pool), 3);

    int ib = MePoolIndexOf(&pool, b);
    MeU32 genLive = MePoolSlotGeneration(&pool, ib);
    assert_true(MePoolSlotIsLive(&pool, ib));
    assert_true(genLive & 1u);
    MePoolPutStruct(&pool, b);
    assert_false(MePoolSlotIsLive(&pool, ib));
    assert_int_not_equal(MePoolSlotGeneration(&pool, ib), genLive);
    MePoolPutStruct(&pool, b); /* releasing twice is ignored */
    assert_int_equal(MePoolGetUsed(&pool), 2);

    Thing *d = MePoolGetStruct(&pool); /* the freed slot comes back, with a new generation */
    assert_ptr_equal(d, b);
    assert_int_equal(d->tag, 0); /* zeroed */
    assert_int_not_equal(MePoolSlotGeneration(&pool, ib), genLive);
    assert_int_equal(MePoolGetHighWater(&pool), 3);

    assert_int_equal(MePoolIndexOf(&pool, (char *)a + 1), -1);
    assert_int_equal(MePoolIndexOf(&pool, &pool), -1);
    MePoolDeset(&pool);
    assert_int_equal(MePoolGetUsed(&pool), 0);
    assert_false(MePoolSlotIsLive(&pool, 0));
    MePoolDestroy(&pool);
}

static void chunk_doubles_and_reports(void **state)
{
    (void)state;
    karma_capture_messages();
    MeChunk chunk;
    MeChunkInitNamed(&chunk, "test");
    void *m = MeChunkGetMem(&chunk, 100);
    assert_non_null(m);
    assert_int_equal(MeChunkGetCurrentSize(&chunk), ME_CHUNK_DEFAULT_SIZE);
    assert_int_equal(MeMessageGetCount(ME_ERR_CHUNK_GROWTH), 1);
    assert_true(MeChunkIsInUse(&chunk));
    assert_reports(ME_ERR_BAD_STATE, assert_null(MeChunkGetMem(&chunk, 10)));
    MeChunkPutMem(&chunk, m);
    m = MeChunkGetMem(&chunk, 5000);
    assert_int_equal(MeChunkGetCurrentSize(&chunk), 8192);
    assert_int_equal(MeChunkGetMaxSize(&chunk), 5000);
    assert_int_equal(MeMessageGetCount(ME_ERR_CHUNK_GROWTH), 2);
    MeChunkPutMem(&chunk, m);
    m = MeChunkGetMem(&chunk, 3000); /* fits: no growth */
    MeChunkPutMem(&chunk, m);
    assert_int_equal(MeMessageGetCount(ME_ERR_CHUNK_GROWTH), 2);
    assert_true(MeChunkSetAuto(&chunk, 20000));
    assert_int_equal(MeChunkGetCurrentSize(&chunk), 32768);
    MeChunkTerm(&chunk);
}

static double fakeNow;
static double fakeTimer(void) { return fakeNow; }

static void profile_times_sections(void **state)
{
    (void)state;
    MeProfile p;
    MeProfileInit(&p);
    MeProfileSetTimer(&p, fakeTimer);
    fakeNow = 10;
    MeProfileFrameStart(&p);
    MeProfileSectionStart(&p, "Dynamics");
    fakeNow = 10.5;
    MeProfileSectionStart(&p, "Solve");
    fakeNow = 10.75;
    MeProfileSectionEnd(&p, "Solve");
    MeProfileSectionStart(&p, "Solve");
    fakeNow = 11.0;
    MeProfileSectionEnd(&p, "Solve");
    MeProfileSectionEnd(&p, "Dynamics");
    MeProfileFrameEnd(&p);
    MeProfileFrameStart(&p); /* the frame just ended becomes "last frame" */
    assert_near(MeProfileGetSectionFrameTime(&p, "Dynamics"), 1.0, 1e-12);
    assert_near(MeProfileGetSectionFrameTime(&p, "Solve"), 0.5, 1e-12);
    assert_int_equal(MeProfileGetSection(&p, "Solve")->calls, 2);
    assert_near(MeProfileGetSectionTotal(&p, "Solve"), 0.5, 1e-12);
    assert_int_equal(MeProfileGetSectionCount(&p), 2);
    assert_null(MeProfileGetSection(&p, "Nope"));

    karma_capture_messages();
    MeProfileSectionStart(&p, "A");
    assert_reports(ME_ERR_PROFILE_NESTING, MeProfileSectionEnd(&p, "B"));
    MeProfileSectionEnd(&p, "A");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pool_hands_out_and_recycles),
        cmocka_unit_test(chunk_doubles_and_reports),
        cmocka_unit_test(profile_times_sections),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
