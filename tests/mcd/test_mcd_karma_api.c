/* Karma 1.2's Mcd names and signatures: struct type names in declarations, the same-name functions
 * in 1.2's form (filter before result, term actions, pointers from McdBoxGetRadii and
 * McdModelGetRelativeTransform, 0 for success from GetMassProperties), the renamed accessors, the
 * per-type plumbing, McdFrameworkDestroyAllModelsAndGeometries, model and pair hooks, containers and
 * the ...Each helpers, each called as a 1.2 program calls it. */
#include "karma_test.h"

#include <string.h>

#include <karma/Mcd.h>
#include <karma/McdPrimitives.h>
#include <karma/MeMath.h>

/* ---- struct names and 1.2-shaped calls ---------------------------------------------------------- */

static int termCalls;
static McdFramework *termSeen;
static void termAction(McdFrameworkID fw) /* Karma's McdTermAction: the framework only */
{
    termCalls++;
    termSeen = fw;
}

static void struct_names_and_term_action(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFramework *fw = McdInit(0, 10, 0, 1); /* 1.2 programs declare the struct types */
    McdGeometry *g = McdSphereCreate(fw, 1);
    McdModel *m = McdModelCreate(g);
    McdSpace *s = McdSpaceAxisSortCreate(fw, McdAllAxes, 4, 4);
    assert_non_null(fw);
    assert_ptr_equal(McdModelGetGeometry(m), g);
    McdFrameworkRegisterTermAction(fw, termAction);
    McdSpaceDestroy(s);
    McdModelDestroy(m);
    McdGeometryDestroy(g);
    termCalls = 0;
    McdTerm(fw);
    assert_int_equal(termCalls, 1);
    assert_ptr_equal(termSeen, fw);
}

static int filterCalls;
static int onlyTagged(McdModelID model, void *filterData)
{
    filterCalls++;
    return McdModelGetUserData(model) == filterData;
}

/* McdSpaceGetLineSegFirstEnabledIntersection(space, a, b, filterCB, data, result): two spheres on
 * the segment; the filter's data picks the far one. */
static void line_segment_filter_order(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 10, 0, 1);
    McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 4, 4);
    McdGeometryID ball = McdSphereCreate(fw, 1);
    McdModelID near = McdModelCreate(ball), far = McdModelCreate(ball);
    McdModelGetTransformPtr(near)[3][0] = 5;
    McdModelGetTransformPtr(far)[3][0] = 10;
    int tag;
    McdModelSetUserData(far, &tag);
    McdSpaceInsertModel(space, near);
    McdSpaceInsertModel(space, far);
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    MeReal a[3] = {0, 0, 0}, b[3] = {20, 0, 0};
    McdLineSegIntersectResult result;
    assert_int_equal(McdSpaceGetLineSegFirstEnabledIntersection(space, a, b, onlyTagged, &tag, &result), 1);
    assert_ptr_equal(result.model, far);
    assert_near(result.distance, 9, 1e-5);
    assert_true(filterCalls >= 2);
    assert_int_equal(McdSpaceGetLineSegFirstIntersection(space, a, b, &result), 1);
    assert_ptr_equal(result.model, near);
    McdSpaceDestroy(space);
    McdTerm(fw);
}

/* Pointers into geometries and models: they follow later changes and stay put. */
static void returned_pointers(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 10, 0, 1);
    McdBoxID box = McdBoxCreate(fw, 2, 4, 6);
    MeReal *r = McdBoxGetRadii(box);
    assert_near(r[1], 2, 0);
    McdBoxSetDimensions(box, 8, 8, 8);
    assert_near(r[1], 4, 0); /* the same storage */
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, assert_null(McdBoxGetRadii(McdSphereCreate(fw, 1))));

    McdModelID m = McdModelCreate(box);
    assert_null(McdModelGetRelativeTransform(m));
    MeMatrix4 rel;
    MeMatrix4TMMakeIdentity(rel);
    MeMatrix4TMSetPosition(rel, 0, 1, 0);
    McdModelSetRelativeTransform(m, rel);
    MeMatrix4Ptr p = McdModelGetRelativeTransform(m);
    assert_non_null(p);
    assert_near(p[3][1], 1, 0);
    /* Karma's pointer form: the relative transform is read from the caller's matrix at each update and
     * the geometry-to-world transform written to compoundTM. */
    MeMatrix4 relTM, refTM, compound;
    MeMatrix4TMMakeIdentity(relTM);
    MeMatrix4TMSetPosition(relTM, 0, 0, 2);
    MeMatrix4TMMakeIdentity(refTM);
    MeMatrix4TMSetPosition(refTM, 1, 0, 0);
    McdModelSetRelativeTransformPtrs(m, relTM, refTM, compound, 0);
    McdModelUpdate(m);
    assert_near(compound[3][0], 1, 0);
    assert_near(compound[3][2], 2, 0);
    relTM[3][2] = 5;
    McdModelUpdate(m);
    assert_near(compound[3][2], 5, 0);
    MeMatrix4Ptr relOut, refOut;
    McdModelGetRelativeTransformPtrs(m, &relOut, &refOut);
    assert_ptr_equal(relOut, relTM);
    assert_ptr_equal(refOut, refTM);
    MeMatrix3 I;
    MeReal v;
    assert_int_equal(McdGeometryGetMassProperties(box, NULL, I, &v), 0); /* 0: success, as 1.2 */
    assert_near(v, 512, 1e-3);
    assert_int_not_equal(McdGeometryGetMassProperties(McdPlaneCreate(fw), NULL, I, &v), 0);
    McdTerm(fw);
}

static void renamed_and_new_framework_calls(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(2, 10, 0, 1);
    assert_int_equal(McdFrameworkGetRegisteredTypeCount(fw), kMcdGeometryBuiltInTypes);
    assert_string_equal(McdFrameworkGetTypeName(fw, kMcdGeometryTypeSphyl), "Sphyl");
    assert_true(McdFrameworkTypeIsRegistered(fw, kMcdGeometryTypeBox));
    assert_true(McdFrameworkTypeIsRegistered(fw, kMcdGeometryTypeConvexMesh));
    assert_true(McdFrameworkTypeIsRegistered(fw, kMcdGeometryTypeAggregate));
    assert_true(McdFrameworkTypeIsValid(fw, kMcdGeometryBuiltInTypes + 1)); /* room for 2 user types */
    assert_false(McdFrameworkTypeIsValid(fw, kMcdGeometryBuiltInTypes + 2));
    McdFrameworkShowTypes(fw);
    McdFrameworkPrintInteractionTable(fw);
    /* The default request can be the application's. */
    McdRequest mine = {1, 0};
    McdFrameworkSetDefaultRequestPtr(fw, &mine);
    assert_ptr_equal(McdFrameworkGetDefaultRequestPtr(fw), &mine);
    McdFrameworkSetDefaultRequestPtr(fw, NULL);
    assert_int_equal(McdFrameworkGetDefaultRequestPtr(fw)->contactMaxCount, 4);
    /* "No test" warned flag, either order. */
    assert_int_equal(McdFrameworkGetInteractionsWarned(fw, kMcdGeometryTypeBox, kMcdGeometryTypeSphere), 0);
    McdFrameworkSetInteractionsWarned(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox, 1);
    assert_int_equal(McdFrameworkGetInteractionsWarned(fw, kMcdGeometryTypeBox, kMcdGeometryTypeSphere), 1);
    /* Geometry names, references. */
    McdGeometryID g = McdSphereCreate(fw, 1);
    assert_int_equal(McdGeometryGetType(g), kMcdGeometryTypeSphere);
    McdModelID m = McdModelCreate(g);
    McdGeometryIncrementReferenceCount(g);
    assert_int_equal(McdGeometryGetReferenceCount(g), 2);
    McdModelDestroy(m);
    assert_reports(ME_ERR_MCD_IN_USE, McdGeometryDestroy(g)); /* the application's hold */
    McdGeometryDecrementReferenceCount(g);
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdGeometryDecrementReferenceCount(g));
    McdGeometrySetReferenceCount(g, 3);
    assert_int_equal(McdGeometryGetReferenceCount(g), 3);
    McdGeometrySetReferenceCount(g, 0);
    McdGeometryDestroy(g);
    assert_false(McdGeometryIsValid(g));
    McdTerm(fw);
}

/* ---- per-type plumbing ------------------------------------------------------------------------- */

static void per_type_names(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 10, 0, 1);
    McdSphereRegisterType(fw);
    McdBoxRegisterType(fw);
    McdSphereBoxPlaneRegisterTypes(fw);
    McdSphereBoxPlaneRegisterInteractions(fw);
    assert_true(McdBoxBoxRegisterInteraction(fw));
    assert_int_equal(McdSphereGetTypeId(), kMcdGeometryTypeSphere);
    assert_int_equal(McdConeGetTypeId(), kMcdGeometryTypeCone);
    assert_int_equal(McdNullGetTypeId(), kMcdGeometryTypeNull);
    McdSphereID s = McdSphereCreate(fw, 2);
    assert_string_equal(McdSphereGetTypeName(s), "Sphere");
    MeVector3 c;
    MeReal r;
    McdSphereGetBSphere(s, c, &r);
    assert_near(r, 2, 0);
    MeMatrix4 rel;
    MeMatrix3 I;
    MeReal v;
    assert_int_equal(McdSphereGetMassProperties(s, rel, I, &v), 0);
    assert_near(v, 4.0 / 3.0 * ME_PI * 8, 1e-4);
    assert_near(I[0][0], 0.4 * v * 4, 1e-3);
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    const MeReal colour[3] = {1, 0, 0};
    McdSphereDebugDraw(s, tm, colour);
    /* A geometry of another type is refused, and not destroyed. */
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, McdBoxDestroy(s));
    assert_true(McdGeometryIsValid(s));
    McdSphereDestroy(s);
    assert_false(McdGeometryIsValid(s));
    /* A per-pair intersect, after McdHello as in Karma. */
    McdModelID a = McdModelCreate(McdSphereCreate(fw, 1)), b = McdModelCreate(McdSphereCreate(fw, 1));
    McdModelGetTransformPtr(b)[3][0] = ME_R(1.5);
    McdModelUpdate(a);
    McdModelUpdate(b);
    McdModelPairID pair = McdModelPairCreate(a, b);
    McdHello(pair);
    McdContact contacts[4];
    McdIntersectResult result;
    result.contacts = contacts;
    result.contactMaxCount = 4;
    assert_true(McdSphereSphereIntersect(pair, &result));
    assert_int_equal(result.contactCount, 1);
    assert_near(contacts[0].separation, -0.5, 1e-5);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    McdTerm(fw);
}

/* ---- models: callbacks, request ids, velocities, body data ------------------------------------ */

static int updateCalls, intersectCalls;
static void onUpdate(McdModel *m)
{
    updateCalls++;
    McdModelUpdate(m); /* an update inside the callback does not call it again */
}
static void onIntersect(McdModel *m, McdIntersectResult *result)
{
    (void)m;
    intersectCalls += result->contactCount;
}

static void model_hooks(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 10, 0, 1);
    McdPrimitivesRegisterInteractions(fw);
    McdModelID a = McdModelCreate(McdBoxCreate(fw, 1, 1, 1)), b = McdModelCreate(McdSphereCreate(fw, 1));
    assert_int_equal(McdModelGetGeometryType(a), kMcdGeometryTypeBox);
    assert_int_equal(McdModelGetRequestID(a), McdModelGetDefaultRequestID());
    McdModelSetRequestID(a, 3);
    assert_int_equal(McdModelGetRequestID(a), 3);
    assert_reports(ME_ERR_ARGUMENT_RANGE, McdModelSetRequestID(a, -1));
    MeVector3 vl = {1, 2, 3}, va = {0, 0, 1};
    McdModelSetLinearVelocityPtr(a, vl);
    McdModelSetAngularVelocityPtr(a, va);
    assert_ptr_equal(McdModelGetLinearVelocityPtr(a), vl);
    assert_ptr_equal(McdModelGetAngularVelocityPtr(a), va);
    int body;
    McdModelSetBodyData(a, &body);
    assert_ptr_equal(McdModelGetBodyData(a), &body);
    McdModelSetUpdateCallback(a, onUpdate);
    assert_ptr_equal(McdModelGetUpdateCallback(a), onUpdate);
    McdModelUpdate(a);
    assert_int_equal(updateCalls, 1);
    McdModelSetIntersectCallback(b, onIntersect);
    assert_ptr_equal(McdModelGetIntersectCallback(b), onIntersect);
    McdModelGetTransformPtr(b)[3][0] = ME_R(1.2);
    McdModelUpdate(b);
    McdModelPairID pair = McdModelPairCreate(a, b);
    McdHello(pair);
    McdContact contacts[4];
    McdIntersectResult result = {0};
    result.contacts = contacts;
    result.contactMaxCount = 4;
    McdIntersect(pair, &result);
    assert_true(result.touch);
    assert_int_equal(intersectCalls, result.contactCount);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    McdModelReset(a);
    assert_null(McdModelGetUpdateCallback(a));
    assert_null(McdModelGetLinearVelocityPtr(a));
    assert_int_equal(McdModelGetRequestID(a), 0);
    McdTerm(fw);
}

/* ---- pairs, containers, ...Each --------------------------------------------------------------- */

static int helloCalls;
static McdRequest oneContact = {1, 0};
static void onHello(McdModelPair *pair)
{
    helloCalls++;
    McdModelPairSetRequestPtr(pair, &oneContact);
}

static void pairs_containers_and_each(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 20, 0, 1);
    McdPrimitivesRegisterInteractions(fw);
    McdSetHelloCallback(fw, onHello);
    assert_ptr_equal(McdGetHelloCallback(fw), onHello);
    McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 8, 16);
    int spaceTag;
    McdSpaceSetUserData(space, &spaceTag);
    assert_ptr_equal(McdSpaceGetUserData(space), &spaceTag);
    McdGeometryID plane = McdPlaneCreate(fw), box = McdBoxCreate(fw, 1, 1, 1);
    McdModelID ground = McdModelCreate(plane);
    McdModelID boxes[3];
    McdSpaceInsertModel(space, ground);
    for (int i = 0; i < 3; i++) {
        boxes[i] = McdModelCreate(box);
        MeMatrix4Ptr tm = McdModelGetTransformPtr(boxes[i]);
        tm[3][0] = (MeReal)(3 * i);
        tm[3][2] = ME_R(0.45); /* sunk 0.05 into the plane z = 0 */
        McdSpaceInsertModel(space, boxes[i]);
    }
    McdSpaceUpdateAll(space);
    McdSpaceEndChanges(space);
    McdModelPair *storage[8];
    McdModelPairContainer pairs;
    McdModelPairContainerInit(&pairs, storage, 8);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(space, &it);
    assert_false(McdSpaceGetPairs(space, &it, &pairs));
    assert_int_equal(McdModelPairContainerGetHelloCount(&pairs), 3);
    McdModelPairContainerPrintStats(&pairs);
    McdGoodbyeEach(&pairs);
    McdHelloEach(&pairs);
    assert_int_equal(helloCalls, 3);
    McdModelID m1, m2;
    McdModelPairGetModels(pairs.array[pairs.helloFirst], &m1, &m2);
    assert_true(m1 == ground || m2 == ground);
    const char *n1, *n2;
    McdModelPairGetGeometryNames(pairs.array[pairs.helloFirst], &n1, &n2);
    assert_true(strcmp(n1, "Plane") == 0 || strcmp(n2, "Plane") == 0);
    int pairTag;
    McdModelPairSetUserData(pairs.array[pairs.helloFirst], &pairTag);
    assert_ptr_equal(McdModelPairGetUserData(pairs.array[pairs.helloFirst]), &pairTag);
    assert_ptr_equal(McdModelPairGetRequestPtr(pairs.array[pairs.helloFirst]), &oneContact);
    /* Room for two results: the first call says "call again", the second finishes. */
    McdModelPairContainerIterator pit;
    McdModelPairContainerIteratorInit(&pit, &pairs);
    McdIntersectResult results[2];
    McdContact contacts[8];
    int nr, nc, total = 0, calls = 0;
    MeBool more;
    do {
        more = McdIntersectEach(&pairs, &pit, results, 2, &nr, contacts, 8, &nc);
        for (int i = 0; i < nr; i++) {
            assert_true(results[i].touch);
            assert_int_equal(results[i].contactCount, 1); /* the hello callback's request */
        }
        total += nr;
        calls++;
    } while (more);
    assert_int_equal(total, 3);
    assert_int_equal(calls, 2);
    /* Remove the middle pair: the hellos close up in order. */
    McdModelPairID last = pairs.array[pairs.helloFirst + 2];
    McdModelPairContainerRemovePair(&pairs, &pairs.array[pairs.helloFirst + 1]);
    assert_int_equal(McdModelPairContainerGetHelloCount(&pairs), 2);
    assert_ptr_equal(pairs.array[pairs.helloFirst + 1], last);
    McdSpaceBeginChanges(space);
    /* Everything goes at once, models still in the space (11 of Karma's samples do this). */
    McdFrameworkDestroyAllModelsAndGeometries(fw);
    assert_int_equal(McdFrameworkGetModelCount(fw), 0);
    assert_int_equal(McdFrameworkGetGeometryCount(fw), 0);
    assert_int_equal(McdSpaceGetModelCount(space), 0);
    assert_false(McdModelIsValid(boxes[0]));
    McdSpaceEndChanges(space); /* the three pairs say goodbye */
    McdSpacePairIteratorBegin(space, &it);
    McdModelPairContainerReset(&pairs);
    McdSpaceGetPairs(space, &it, &pairs);
    assert_int_equal(McdModelPairContainerGetGoodbyeCount(&pairs), 3);
    assert_int_equal(McdModelPairContainerGetHelloCount(&pairs) + McdModelPairContainerGetStayingCount(&pairs), 0);
    McdSpaceDestroy(space);
    McdTerm(fw);
}

/* ---- space hooks ------------------------------------------------------------------------------ */

static int aabbCalls;
static void countingUpdate(McdModelID m, MeReal duration)
{
    assert_true(duration == 0);
    aabbCalls++;
    McdModelUpdate(m);
}
static void onPoolFull(McdModelID a, McdModelID b) { (void)a, (void)b; }

static void space_hooks(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 10, 0, 1);
    McdSpaceID space = McdSpaceAxisSortCreate(fw, McdAllAxes, 4, 4);
    McdSpaceSetPoolFullHandler(space, onPoolFull);
    assert_ptr_equal(McdSpaceGetPoolFullHandler(space), onPoolFull);
    McdSpaceSetAABBFn(space, countingUpdate);
    McdGeometryID ball = McdSphereCreate(fw, 1);
    McdModelID a = McdModelCreate(ball), b = McdModelCreate(ball);
    McdSpaceInsertModel(space, a);
    McdSpaceInsertModel(space, b);
    McdSpaceUpdateAll(space);
    assert_int_equal(aabbCalls, 2);
    /* Culling parameters changed for models already inside: the pair disappears. */
    McdCullingTable *table = McdCullingTableCreate(2);
    McdCullingTableSet(table, 0, 1, METRUE);
    McdSpaceSetModelCullingParameters(space, a, table, 0, 7);
    McdSpaceSetModelCullingParameters(space, b, table, 1, 7);
    McdSpaceEndChanges(space);
    McdModelPair *storage[4];
    McdModelPairContainer pairs;
    McdModelPairContainerInit(&pairs, storage, 4);
    McdSpacePairIterator it;
    McdSpacePairIteratorBegin(space, &it);
    McdSpaceGetPairs(space, &it, &pairs);
    assert_int_equal(McdModelPairContainerGetHelloCount(&pairs), 0);
    McdSpaceBeginChanges(space);
    McdSpaceSetModelCullingParameters(space, b, NULL, 0, 0);
    McdSpaceEndChanges(space);
    McdSpacePairIteratorBegin(space, &it);
    McdModelPairContainerReset(&pairs);
    McdSpaceGetPairs(space, &it, &pairs);
    assert_int_equal(McdModelPairContainerGetHelloCount(&pairs), 1);
    assert_true(McdSpacePairIsEnabled(a, b));
    McdSpaceBeginChanges(space);
    assert_true(McdSpaceDisablePair(a, b));
    assert_true(McdSpaceEnablePair(a, b));
    McdSpaceDestroy(space);
    McdCullingTableDestroy(table);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(struct_names_and_term_action),
        cmocka_unit_test(line_segment_filter_order),
        cmocka_unit_test(returned_pointers),
        cmocka_unit_test(renamed_and_new_framework_calls),
        cmocka_unit_test(per_type_names),
        cmocka_unit_test(model_hooks),
        cmocka_unit_test(pairs_containers_and_each),
        cmocka_unit_test(space_hooks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
