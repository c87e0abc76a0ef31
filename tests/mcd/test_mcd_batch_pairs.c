/* McdBatchIntersectEach (1.2's resumable batch: 1 when done, 0 to call again; frozen pairs skipped)
 * and McdModelPairManager (hello -> staying -> goodbye -> gone, handed out as the space does). */
#include "karma_test.h"

#include <karma/Mcd.h>
#include <karma/McdBatch.h>
#include <karma/McdModelPairManager.h>
#include <karma/MeMath.h>

/* Four unit boxes in a row 1.9 apart along x: three touching neighbours, 4 contacts each. */
typedef struct Row {
    McdFrameworkID fw;
    McdSpaceID space;
    McdGeometryID box;
    McdModelID m[4];
} Row;

static void rowCreate(Row *row)
{
    row->fw = McdInit(0, 8, 0, 1);
    McdPrimitivesRegisterInteractions(row->fw);
    row->space = McdSpaceAxisSortCreate(row->fw, McdAllAxes, 8, 16);
    row->box = McdBoxCreate(row->fw, 2, 2, 2);
    for (int i = 0; i < 4; i++) {
        row->m[i] = McdModelCreate(row->box);
        MeMatrix4TMSetPosition(McdModelGetTransformPtr(row->m[i]), (MeReal)(1.9 * i), 0, 0);
        McdSpaceInsertModel(row->space, row->m[i]);
    }
    McdSpaceEndChanges(row->space);
}

static void rowDestroy(Row *row)
{
    McdSpaceBeginChanges(row->space);
    for (int i = 0; i < 4; i++)
        McdSpaceRemoveModel(row->m[i]);
    McdSpaceDestroy(row->space);
    for (int i = 0; i < 4; i++)
        McdModelDestroy(row->m[i]);
    McdGeometryDestroy(row->box);
    McdTerm(row->fw);
}

static void batch_intersect_each(void **state)
{
    (void)state;
    karma_capture_messages();
    Row row;
    rowCreate(&row);
    McdModelPair *array[8];
    McdModelPairContainer pairs;
    McdModelPairContainerInit(&pairs, array, 8);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(row.space, &it);
    McdSpaceGetPairs(row.space, &it, &pairs);
    assert_int_equal(McdModelPairContainerGetHelloCount(&pairs), 3);
    McdHelloEach(&pairs);
    McdBatchContext *b = McdBatchContextCreate(row.fw);
    assert_non_null(b);
    McdIntersectResult results[8];
    McdContact contacts[16];
    int resultCount = -1, contactCount = -1;
    /* room for two pairs' contacts per call: 2 results, then the last */
    assert_int_equal(McdBatchIntersectEach(b, &pairs, results, &resultCount, 8, contacts, &contactCount, 8), 0);
    assert_int_equal(resultCount, 2);
    assert_int_equal(contactCount, 8);
    assert_ptr_equal(results[0].pair, array[pairs.helloFirst]);
    assert_true(results[1].touch);
    assert_ptr_equal(results[1].contacts, contacts + 4);
    assert_int_equal(McdBatchIntersectEach(b, &pairs, results, &resultCount, 8, contacts, &contactCount, 8), 1);
    assert_int_equal(resultCount, 1);
    assert_int_equal(contactCount, 4);
    assert_ptr_equal(results[0].pair, array[pairs.helloFirst + 2]);
    /* one call with room for all; then with results limited to 1 per call */
    assert_int_equal(McdBatchIntersectEach(b, &pairs, results, &resultCount, 8, contacts, &contactCount, 16), 1);
    assert_int_equal(resultCount, 3);
    assert_int_equal(McdBatchIntersectEach(b, &pairs, results, &resultCount, 1, contacts, &contactCount, 16), 0);
    McdBatchContextReset(b); /* abandon: the next call starts over */
    assert_int_equal(McdBatchIntersectEach(b, &pairs, results, &resultCount, 8, contacts, &contactCount, 16), 1);
    assert_int_equal(resultCount, 3);
    /* two frozen models: their pair is skipped */
    McdSpaceFreezeModel(row.m[0]);
    McdSpaceFreezeModel(row.m[1]);
    assert_int_equal(McdBatchIntersectEach(b, &pairs, results, &resultCount, 8, contacts, &contactCount, 16), 1);
    assert_int_equal(resultCount, 2);
    /* arrays too small for a single pair: reported, no endless loop */
    assert_reports(ME_ERR_ARGUMENT_RANGE,
                   assert_int_equal(McdBatchIntersectEach(b, &pairs, results, &resultCount, 8, contacts, &contactCount, 2), 1));
    McdBatchContextRelease(b);
    McdBatchContextDestroy(b);
    McdGoodbyeEach(&pairs);
    McdSpaceBeginChanges(row.space);
    McdSpaceUnfreezeModel(row.m[0]);
    McdSpaceUnfreezeModel(row.m[1]);
    rowDestroy(&row);
}

static int lostCalls;
static void MEAPI onLost(McdModelID a, McdModelID b)
{
    (void)a;
    (void)b;
    lostCalls++;
}

static void pair_manager_life_cycle(void **state)
{
    (void)state;
    karma_capture_messages();
    Row row;
    rowCreate(&row);
    McdModelID *m = row.m;
    McdModelPairManagerID pm = McdModelPairManagerCreate(2);
    assert_non_null(pm);
    assert_false(McdModelPairManagerActivate(pm, m[0], m[1])); /* new */
    assert_true(McdModelPairManagerActivate(pm, m[1], m[0]));  /* the same pair, either order */
    assert_false(McdModelPairManagerActivate(pm, m[1], m[2]));
    assert_int_equal(McdModelPairManagerGetSize(pm), 2);
    McdModelPairID p01 = McdModelPairManagerGetPair(pm, m[1], m[0]);
    assert_non_null(p01);
    assert_null(McdModelPairManagerGetPair(pm, m[0], m[2]));
    /* full: reported, handler called */
    McdModelPairManagerSetPoolFullHandler(pm, onLost);
    assert_ptr_equal(McdModelPairManagerGetPoolFullHandler(pm), onLost);
    lostCalls = 0;
    assert_reports(ME_ERR_POOL_FULL, assert_false(McdModelPairManagerActivate(pm, m[2], m[3])));
    assert_int_equal(lostCalls, 1);

    McdModelPair *array[4];
    McdModelPairContainer c;
    McdModelPairContainerInit(&c, array, 4);
    McdSpacePairIterator it;
    McdModelPairManagerResetIterator(pm, &it);
    assert_false(McdModelPairManagerGetPairs(pm, &it, &c));
    assert_int_equal(McdModelPairContainerGetHelloCount(&c), 2);
    assert_ptr_equal(array[c.helloFirst], p01); /* slot order */
    McdHelloEach(&c);
    McdModelPairManagerFlush(pm);
    McdModelPairManagerResetIterator(pm, &it);
    McdModelPairManagerGetPairs(pm, &it, &c);
    assert_int_equal(McdModelPairContainerGetStayingCount(&c), 2);
    McdModelPairManagerResetIterator(pm, &it);
    McdModelPairManagerGetTransitions(pm, &it, &c);
    assert_int_equal(McdModelPairContainerGetStayingCount(&c) + McdModelPairContainerGetHelloCount(&c), 0);
    /* deactivate: goodbye until the flush, then gone (the pair stays the same record meanwhile) */
    assert_true(McdModelPairManagerDeactivate(pm, m[0], m[1]));
    assert_false(McdModelPairManagerDeactivate(pm, m[0], m[1]));
    assert_ptr_equal(McdModelPairManagerGetPair(pm, m[0], m[1]), p01);
    McdModelPairManagerResetIterator(pm, &it);
    McdModelPairManagerGetTransitions(pm, &it, &c);
    assert_int_equal(McdModelPairContainerGetGoodbyeCount(&c), 1);
    assert_ptr_equal(array[c.goodbyeFirst], p01);
    McdGoodbyeEach(&c);
    McdModelPairManagerFlush(pm);
    assert_null(McdModelPairManagerGetPair(pm, m[0], m[1]));
    assert_int_equal(McdModelPairManagerGetSize(pm), 1);
    /* a hello deactivated before the flush is forgotten at once */
    McdModelPairManagerActivate(pm, m[2], m[3]);
    assert_true(McdModelPairManagerDeactivate(pm, m[3], m[2]));
    assert_int_equal(McdModelPairManagerGetSize(pm), 1);
    /* a container smaller than the pairs: call again */
    McdModelPairManagerActivate(pm, m[2], m[3]);
    McdModelPairContainerInit(&c, array, 1);
    McdModelPairManagerResetIterator(pm, &it);
    assert_true(McdModelPairManagerGetPairs(pm, &it, &c));
    assert_int_equal(McdModelPairContainerGetHelloCount(&c), 1);
    assert_false(McdModelPairManagerGetPairs(pm, &it, &c));
    assert_int_equal(McdModelPairContainerGetStayingCount(&c), 1);
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdModelPairManagerActivate(pm, m[0], m[0]));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdModelPairManagerCreate(0)));
    McdModelPairManagerDestroy(pm);
    rowDestroy(&row);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(batch_intersect_each),
        cmocka_unit_test(pair_manager_life_cycle),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
