/* McduRequestTable: the request for a pair chosen by its models' request IDs, symmetric, installed
 * through the hello callback as 1.2's programs do; out-of-range IDs and a missing table reported. */
#include "karma_test.h"

#include <karma/Mcd.h>
#include <karma/McdBox.h>
#include <karma/McduRequestTable.h>
#include <karma/MeMath.h>

static void table_entries(void **state)
{
    (void)state;
    karma_capture_messages();
    McdRequest base = {7, 1};
    McduRequestTable *t = McduRequestTableInit(3, &base);
    assert_non_null(t);
    assert_int_equal(t->idCount, 3);
    assert_int_equal(t->size, 6);
    assert_int_equal(McduRequestTableGetRequestPtr(2, 1)->contactMaxCount, 7);
    McdRequest few = {1, 0};
    McduRequestTableSetRequest(2, 0, &few);
    assert_ptr_equal(McduRequestTableGetRequestPtr(0, 2), McduRequestTableGetRequestPtr(2, 0));
    assert_int_equal(McduRequestTableGetRequestPtr(0, 2)->contactMaxCount, 1);
    assert_int_equal(McduRequestTableGetRequestPtr(1, 2)->contactMaxCount, 7);
    McduRequestTableGetRequestPtr(1, 1)->contactMaxCount = 3; /* 1.2's samples change entries in place */
    assert_int_equal(McduRequestTableGetRequestPtr(1, 1)->contactMaxCount, 3);
    assert_int_equal(McduRequestTableGetRequestPtr(0, 0)->contactMaxCount, 7);
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McduRequestTableGetRequestPtr(3, 0)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, McduRequestTableSetRequest(-1, 0, &few));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McduRequestTableInit(0, NULL)));
    McduRequestTableTerm();
    assert_reports(ME_ERR_BAD_STATE, assert_null(McduRequestTableGetRequestPtr(0, 0)));
    /* NULL request: Karma's default of 4 contacts */
    McduRequestTableInit(1, NULL);
    assert_int_equal(McduRequestTableGetRequestPtr(0, 0)->contactMaxCount, 4);
    McduRequestTableTerm();
}

/* Two boxes resting face on face (4 contacts by default): as two "debris" models (request ID 1) they
 * get the table's one contact; McdHello applies the table through McduHelloRequestTableCB. */
static void hello_callback_applies_table(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 4, 0, 1);
    McdPrimitivesRegisterInteractions(fw);
    McdGeometryID g = McdBoxCreate(fw, 2, 2, 2);
    McdModelID a = McdModelCreate(g), b = McdModelCreate(g);
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(b), 0, 0, 1.9);
    McdModelUpdate(a);
    McdModelUpdate(b);
    McduRequestTableInit(2, NULL);
    McdRequest one = {1, 0};
    McduRequestTableSetRequest(1, 1, &one);
    McdSetHelloCallback(fw, McduHelloRequestTableCB);
    McdModelPairID p = McdModelPairCreate(a, b);
    McdHello(p);
    assert_ptr_equal(McdModelPairGetRequestPtr(p), McduRequestTableGetRequestPtr(0, 0));
    McdContact contacts[4];
    McdIntersectResult r;
    r.contacts = contacts;
    r.contactMaxCount = 4;
    assert_true(McdIntersect(p, &r));
    assert_int_equal(r.contactCount, 4);
    McdGoodbye(p);
    McdModelSetRequestID(a, 1);
    McdModelSetRequestID(b, 1);
    McdHello(p);
    assert_ptr_equal(McdModelPairGetRequestPtr(p), McduRequestTableGetRequestPtr(1, 1));
    McdRequest copy = {0, 0};
    McduRequestTableGetRequest(p, &copy);
    assert_int_equal(copy.contactMaxCount, 1);
    assert_true(McdIntersect(p, &r));
    assert_int_equal(r.contactCount, 1);
    McdGoodbye(p);
    /* an ID outside the table: reported, the pair keeps its request */
    McdModelSetRequestID(b, 5);
    McdModelPairSetRequestPtr(p, NULL);
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdHello(p));
    assert_ptr_equal(McdModelPairGetRequestPtr(p), McdFrameworkGetDefaultRequestPtr(fw));
    McdGoodbye(p);
    McdModelPairDestroy(p);
    McdSetHelloCallback(fw, NULL);
    McduRequestTableTerm();
    McdModelDestroy(a);
    McdModelDestroy(b);
    McdGeometryDestroy(g);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(table_entries),
        cmocka_unit_test(hello_callback_applies_table),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
