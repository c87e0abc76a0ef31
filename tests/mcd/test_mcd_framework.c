/* Mcd framework: McdInit defaults, user geometry types, the interaction table (one way round, swap at
 * hello, coverage of every primitive pair), unregistered pairs, reference counting, bad input. */
#include "karma_test.h"

#include <string.h>

#include <karma/Mcd.h>

#include "mcd/framework.h"

/* ---- a fake pair test: one contact at the midpoint of the two origins, normal 2 -> 1 ------------ */
static int fakeCalls;
static int fakeFirstType;
static int fakeTest(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, MeReal tolerance,
                    McdContact *contacts, int maxContacts, void **cache)
{
    (void)g2, (void)tolerance, (void)maxContacts;
    fakeCalls++;
    fakeFirstType = g1->type;
    *cache = &fakeCalls;
    memset(contacts, 0, sizeof *contacts);
    MeVector3Subtract(contacts[0].normal, tm1[3], tm2[3]);
    MeVector3Normalize(contacts[0].normal);
    contacts[0].separation = -ME_R(0.1);
    contacts[0].element1 = (void *)tm1; /* tags to check the exchange of elements on swap */
    contacts[0].element2 = (void *)tm2;
    return 1;
}
static int releases;
static void fakeRelease(void *cache)
{
    assert_ptr_equal(cache, &fakeCalls);
    releases++;
}

/* Term actions run newest first, while the framework's objects are still alive. */
static int termOrder[20], termCount;
static McdModelID termModel;
static void termAction(McdFrameworkID fw, void *data)
{
    assert_true(McdFrameworkIsValid(fw));
    assert_true(McdModelIsValid(termModel));
    termOrder[termCount++] = *(int *)data;
}

static void term_actions(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 2, 0, 1);
    termModel = McdModelCreate(McdSphereCreate(fw, 1));
    static int tags[17];
    for (int i = 0; i < 16; i++) {
        tags[i] = i;
        assert_true(McdFrameworkAddTermAction(fw, termAction, &tags[i]));
    }
    assert_reports(ME_ERR_POOL_FULL, assert_false(McdFrameworkAddTermAction(fw, termAction, &tags[16])));
    termCount = 0;
    McdTerm(fw);
    assert_int_equal(termCount, 16);
    for (int i = 0; i < 16; i++)
        assert_int_equal(termOrder[i], 15 - i);
}

static void init_defaults_and_term(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(2, 10, 5, 2);
    assert_non_null(fw);
    assert_true(McdFrameworkIsValid(fw));
    assert_near(McdFrameworkGetLengthScale(fw), 2, 0);
    assert_near(McdFrameworkGetDefaultContactTolerance(fw), 0.005 * 2, 1e-7);
    printf("default contact tolerance at lengthScale 2: %g\n", (double)McdFrameworkGetDefaultContactTolerance(fw));
    McdRequest *rq = McdFrameworkGetDefaultRequestPtr(fw);
    assert_int_equal(rq->contactMaxCount, 4);
    assert_int_equal(McdFrameworkGetRegisteredTypeCount(fw), kMcdGeometryBuiltInTypes);
    assert_string_equal(McdFrameworkGetTypeName(fw, kMcdGeometryTypeCone), "Cone");
    assert_string_equal(McdFrameworkGetTypeName(fw, kMcdGeometryTypeConvexMesh), "ConvexMesh");
    assert_string_equal(McdFrameworkGetTypeName(fw, kMcdGeometryTypeTriangleList), "TriangleList");
    assert_string_equal(McdFrameworkGetTypeName(fw, kMcdGeometryTypeAggregate), "Aggregate");
    assert_true(McdPrimitivesRegisterTypes(fw));
    assert_int_equal(McdPrimitivesGetTypeCount(), 7);
    McdGeometryID s = McdSphereCreate(fw, 1);
    McdModelID m = McdModelCreate(s);
    assert_int_equal(McdFrameworkGetModelCount(fw), 1);
    McdTerm(fw);
    assert_false(McdFrameworkIsValid(fw));
    assert_false(McdModelIsValid(m));
    assert_false(McdGeometryIsValid(s));
    assert_reports(ME_ERR_INVALID_HANDLE, McdSphereGetRadius(s));
    assert_reports(ME_ERR_SCALE_NOT_POSITIVE, assert_null(McdInit(0, 1, 0, 0)));
    assert_reports(ME_ERR_SCALE_NOT_POSITIVE, assert_null(McdInit(0, 1, 0, NAN)));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdInit(-1, 1, 0, 1)));
}

/* ---- a user geometry type: an axis-aligned cube of half side `h` (data points at h) ---------- */
static int userDestroyed;
static void cubeDestroy(McdGeometryID g, void *data)
{
    (void)g;
    *(MeReal *)data = -1;
    userDestroyed++;
}
static void cubeAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 lo, MeVector3 hi)
{
    (void)g;
    MeReal h = *(MeReal *)data;
    for (int j = 0; j < 3; j++) {
        MeReal e = h * (fabs(tm[0][j]) + fabs(tm[1][j]) + fabs(tm[2][j]));
        lo[j] = tm[3][j] - e;
        hi[j] = tm[3][j] + e;
    }
}
static void cubeBSphere(McdGeometryID g, void *data, MeVector3 c, MeReal *r)
{
    (void)g;
    MeVector3Set(c, 0, 0, 0);
    *r = *(MeReal *)data * MeSqrt(3);
}
static void cubeSupport(McdGeometryID g, void *data, const MeVector3 d, MeVector3 p)
{
    (void)g;
    MeReal h = *(MeReal *)data;
    for (int i = 0; i < 3; i++)
        p[i] = d[i] < 0 ? -h : h;
}
static void cubeMass(McdGeometryID g, void *data, MeMatrix4 rel, MeMatrix3 I, MeReal *v)
{
    (void)g;
    MeReal h = *(MeReal *)data, side = 2 * h;
    MeMatrix4TMMakeIdentity(rel);
    *v = side * side * side;
    memset(I, 0, sizeof(MeMatrix3));
    I[0][0] = I[1][1] = I[2][2] = *v * side * side / 6;
}

/* Slab test of the local segment against the cube [-h, h]^3: entry parameter and face normal. */
static int cubeLineSeg(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t, MeVector3 normal)
{
    (void)g;
    MeReal h = *(MeReal *)data, t0 = 0, t1 = 1;
    int axis = -1;
    MeReal sign = 0;
    for (int i = 0; i < 3; i++) {
        MeReal d = p1[i] - p0[i];
        if (d == 0) {
            if (p0[i] < -h || p0[i] > h)
                return 0;
            continue;
        }
        MeReal a = (-h - p0[i]) / d, b = (h - p0[i]) / d, s = -1;
        if (a > b) {
            MeReal x = a;
            a = b, b = x, s = 1;
        }
        if (a > t0)
            t0 = a, axis = i, sign = s;
        if (b < t1)
            t1 = b;
        if (t0 > t1)
            return 0;
    }
    *t = t0;
    MeVector3Set(normal, 0, 0, 0);
    if (axis >= 0)
        normal[axis] = sign;
    return 1;
}

/* The application's cube-sphere test: closest point of the cube to the sphere's centre. */
static int cubeSphere(McdGeometryID g1, void *data1, MeMatrix4 tm1, McdGeometryID g2, void *data2, MeMatrix4 tm2,
                      MeReal tolerance, McdContact *contacts, int maxContacts)
{
    (void)g1, (void)maxContacts;
    assert_int_equal(McdGeometryGetTypeId(g2), kMcdGeometryTypeSphere);
    MeReal h = *(MeReal *)data1, r = ((MeReal *)data2)[0]; /* built-in data: McdSphereData (radius) */
    MeVector3 c, q, w;
    MeMatrix4TMInverseTransform(c, tm1, tm2[3]);
    for (int i = 0; i < 3; i++)
        q[i] = c[i] < -h ? -h : c[i] > h ? h : c[i];
    MeMatrix4TMTransform(w, tm1, q);
    MeVector3Subtract(contacts[0].normal, w, tm2[3]); /* from the sphere (g2) towards the cube (g1) */
    MeReal d = MeVector3Normalize(contacts[0].normal);
    contacts[0].separation = d - r;
    MeVector3Copy(contacts[0].position, w);
    return contacts[0].separation <= tolerance;
}

static void user_geometry_type(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(2, 5, 0, 1);
    McdGeometryTypeDesc desc = {"Cube", cubeDestroy, cubeAABB, cubeBSphere, cubeSupport, cubeMass, NULL, NULL};
    int type = McdFrameworkRegisterUserGeometryType(fw, &desc);
    assert_int_equal(type, kMcdGeometryBuiltInTypes);
    assert_string_equal(McdFrameworkGetTypeName(fw, type), "Cube");
    /* The same cube with the protocol's line-segment test. */
    McdGeometryTypeDesc segDesc = desc;
    segDesc.typeName = "SegCube";
    segDesc.lineSegIntersect = cubeLineSeg;
    int segType = McdFrameworkRegisterUserGeometryType(fw, &segDesc);
    assert_int_equal(segType, kMcdGeometryBuiltInTypes + 1);
    /* Room for two user types only. */
    assert_reports(ME_ERR_POOL_FULL, assert_int_equal(McdFrameworkRegisterUserGeometryType(fw, &desc), -1));
    McdGeometryTypeDesc bad = desc;
    bad.maximumPoint = NULL;
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(McdFrameworkRegisterUserGeometryType(fw, &bad), -1));

    MeReal half = ME_R(0.5);
    McdGeometryID g = McdUserGeometryCreate(fw, type, &half);
    assert_non_null(g);
    assert_int_equal(McdGeometryGetTypeId(g), type);
    assert_string_equal(McdGeometryGetTypeName(g), "Cube");
    assert_ptr_equal(McdUserGeometryGetData(g), &half);
    /* The generic API dispatches through the user's protocol. */
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMSetPosition(tm, 1, 2, 3);
    MeVector3 lo, hi, dir = {1, -1, 1}, p;
    McdGeometryGetAABB(g, tm, lo, hi);
    assert_near(lo[0], 0.5, 1e-6);
    assert_near(hi[2], 3.5, 1e-6);
    McdGeometryMaximumPoint(g, tm, dir, p);
    assert_near(p[0], 1.5, 1e-6);
    assert_near(p[1], 1.5, 1e-6);
    MeMatrix3 I;
    MeReal v;
    assert_int_equal(McdGeometryGetMassProperties(g, NULL, I, &v), 0);
    assert_near(v, 1, 1e-6);
    assert_near(I[1][1], 1.0 / 6, 1e-6);
    /* A model of a user geometry: updates use its AABB; segments never hit (no function given). */
    McdModelID m = McdModelCreate(g);
    McdModelSetContactTolerance(m, 0);
    MeMatrix4Ptr own = McdModelGetTransformPtr(m);
    MeMatrix4TMSetPosition(own, 1, 2, 3);
    McdModelUpdate(m);
    McdModelGetAABB(m, lo, hi);
    assert_near(hi[1], 2.5, 1e-6);
    McdLineSegIntersectResult r;
    MeVector3 a = {-5, 2, 3}, b = {5, 2, 3};
    assert_int_equal(McdLineSegIntersect(m, a, b, &r), 0);
    /* With the protocol's segment test: the hit in the world through the model's transform, turned
     * 90 deg about z at (1, 2, 3). A segment along world -y from y = 5 enters the cube's face at
     * y = 2.5 (local +x after the turn), 2.5 along a 10-long segment: t 0.25, distance 2.5. */
    MeReal segHalf = ME_R(0.5);
    McdModelID sm = McdModelCreate(McdUserGeometryCreate(fw, segType, &segHalf));
    McdModelSetContactTolerance(sm, 0);
    MeMatrix4TMFromEulerAnglesAndPosition(McdModelGetTransformPtr(sm), 0, 0, ME_PI_2, 1, 2, 3);
    McdModelUpdate(sm);
    MeVector3 s0 = {ME_R(1.1), 5, ME_R(3.2)}, s1 = {ME_R(1.1), -5, ME_R(3.2)};
    assert_int_equal(McdLineSegIntersect(sm, s0, s1, &r), 1);
    assert_ptr_equal(r.model, sm);
    assert_near(r.position[0], 1.1, 1e-5);
    assert_near(r.position[1], 2.5, 1e-5);
    assert_near(r.position[2], 3.2, 1e-5);
    assert_near(r.normal[0], 0, 1e-5);
    assert_near(r.normal[1], 1, 1e-5);
    assert_near(r.normal[2], 0, 1e-5);
    assert_near(r.distance, 2.5, 1e-5);
    printf("user type %d: line segment hit at (%.4f, %.4f, %.4f), normal (%.3f, %.3f, %.3f), distance %.5f\n", segType,
           (double)r.position[0], (double)r.position[1], (double)r.position[2], (double)r.normal[0],
           (double)r.normal[1], (double)r.normal[2], (double)r.distance);
    MeVector3 s2 = {ME_R(1.6), 5, 3}, s3 = {ME_R(1.6), -5, 3}; /* passes beside it */
    assert_int_equal(McdLineSegIntersect(sm, s2, s3, &r), 0);
    McdModelDestroy(sm);
    /* A pair test of the application's: registered (Cube, Sphere), used for (Sphere, Cube) too. */
    assert_true(McdFrameworkSetUserInteraction(fw, type, kMcdGeometryTypeSphere, cubeSphere));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_false(McdFrameworkSetUserInteraction(fw, type, type + 2, cubeSphere)));
    McdModelID ball = McdModelCreate(McdSphereCreate(fw, ME_R(0.25)));
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(ball), 1, 2, ME_R(3.6)); /* 0.1 above the cube, overlapping 0.15 */
    McdModelUpdate(ball);
    McdModelPairID pair = McdModelPairCreate(ball, m);
    McdHello(pair);
    assert_int_equal(pair->swapped, 1);
    McdContact contact;
    McdIntersectResult result = {0};
    result.contacts = &contact;
    result.contactMaxCount = 1;
    assert_true(McdIntersect(pair, &result));
    assert_near(contact.separation, -0.15, 1e-5);
    assert_near(result.normal[2], 1, 1e-6); /* model 2 (cube) towards model 1 (ball): up */
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    McdModelDestroy(ball);
    /* Refcount: refused while used, then destroyed through the user's destroy. */
    assert_reports(ME_ERR_MCD_IN_USE, McdGeometryDestroy(g));
    assert_true(McdGeometryIsValid(g));
    McdModelDestroy(m);
    assert_int_equal(McdGeometryGetReferenceCount(g), 0);
    McdGeometryDestroy(g);
    assert_false(McdGeometryIsValid(g));
    assert_int_equal(userDestroyed, 1);
    assert_near(half, -1, 0);
    /* McdTerm destroys what is left, through the protocol too. */
    half = ME_R(0.5);
    McdUserGeometryCreate(fw, type, &half);
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(McdUserGeometryCreate(fw, type + 2, &half)));
    McdTerm(fw);
    assert_int_equal(userDestroyed, 3); /* the two cubes left, and SegCube's */
    printf("user type %d registered, dispatched and destroyed through its protocol\n", type);
}

static McdModelID placedModel(McdGeometryID g, MeReal x, MeReal y, MeReal z)
{
    McdModelID m = McdModelCreate(g);
    MeMatrix4TMSetPosition(McdModelGetTransformPtr(m), x, y, z);
    McdModelUpdate(m);
    return m;
}

static void interaction_table_one_way_and_swap(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fwId = McdInit(0, 8, 0, 1);
    McdFrameworkData *fw = McdFrameworkFromID(fwId, "test");
    /* Registered for (Box, Sphere) only. */
    assert_true(McdFrameworkSetInteractionWithCache(fw, kMcdGeometryTypeBox, kMcdGeometryTypeSphere, fakeTest,
                                                    fakeRelease, "test"));
    assert_non_null(McdFrameworkGetInteraction(fw, kMcdGeometryTypeBox, kMcdGeometryTypeSphere));
    assert_null(McdFrameworkGetInteraction(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox));
    assert_true(McdFrameworkHasInteraction(fw, kMcdGeometryTypeSphere, kMcdGeometryTypeBox));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_false(McdFrameworkSetInteraction(fw, kMcdGeometryTypeBox, 99, fakeTest, "test")));

    McdModelID sphere = placedModel(McdSphereCreate(fwId, 1), 0, 0, 0);
    McdModelID box = placedModel(McdBoxCreate(fwId, 1, 1, 1), 3, 0, 0);
    /* Pair (sphere, box): the test takes the box first, so the pair is swapped. */
    McdModelPairID pair = McdModelPairCreate(sphere, box);
    McdHello(pair);
    assert_int_equal(pair->swapped, 1);
    assert_true(pair->testIndex >= 0);
    McdContact contacts[4];
    McdIntersectResult result = {0};
    result.contacts = contacts;
    result.contactMaxCount = 4;
    fakeCalls = 0;
    assert_true(McdIntersect(pair, &result));
    assert_int_equal(fakeCalls, 1);
    assert_int_equal(fakeFirstType, kMcdGeometryTypeBox);
    assert_int_equal(result.contactCount, 1);
    /* Normals are model 2 -> model 1 whatever the order of the test: box (+x) -> sphere (0). */
    assert_near(contacts[0].normal[0], -1, 1e-6);
    assert_near(result.normal[0], -1, 1e-6);
    assert_non_null(contacts[0].element1);
    MeMatrix4 sphereTM;
    McdModelGetWorldTransform(sphere, sphereTM);
    assert_near(((MeReal(*)[4])contacts[0].element1)[3][0], sphereTM[3][0], 0); /* element1 belongs to model 1 */
    McdGoodbye(pair);
    assert_int_equal(releases, 1);
    assert_null(pair->cache);
    /* The same pair the other way round is not swapped and gives the opposite normal. */
    McdModelPairReset(pair, box, sphere);
    McdHello(pair);
    assert_int_equal(pair->swapped, 0);
    McdIntersect(pair, &result);
    assert_near(result.normal[0], 1, 1e-6);
    McdGoodbye(pair);
    /* Request caps the contact count; contactMaxCount 0 gives none. */
    McdRequest one = {0, 0};
    pair->request = &one;
    McdHello(pair);
    McdIntersect(pair, &result);
    assert_int_equal(result.contactCount, 0);
    McdGoodbye(pair);
    /* Both models destroyed after the test cached something (MstModelAndBodyDestroy's order): the
     * goodbye still releases the cache, through the framework McdHello recorded, without a message. */
    pair->request = NULL;
    McdHello(pair);
    assert_ptr_equal(pair->framework, fwId);
    McdIntersect(pair, &result);
    assert_non_null(pair->cache);
    int releasesBefore = releases;
    unsigned long warnings = karma_warning_count();
    McdModelDestroy(sphere);
    McdModelDestroy(box);
    McdGoodbye(pair);
    assert_int_equal(releases, releasesBefore + 1);
    assert_null(pair->cache);
    assert_int_equal(pair->testIndex, -1);
    assert_int_equal(karma_warning_count(), warnings);
    McdModelPairDestroy(pair);
    McdTerm(fwId);
}

static void unregistered_pair_warned_once(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = McdInit(0, 8, 0, 1);
    McdModelID a = placedModel(McdSphereCreate(fw, 1), 0, 0, 0);
    McdModelID b = placedModel(McdSphereCreate(fw, 1), ME_R(1.5), 0, 0);
    McdModelID c = placedModel(McdCylinderCreate(fw, 1, 1), 0, ME_R(1.5), 0);
    McdModelID n = placedModel(McdNullCreate(fw), 0, 0, 0);
    McdModelPair pair;
    memset(&pair, 0, sizeof pair);
    McdModelPairReset(&pair, a, b);
    assert_true(McdNearby(&pair));
    assert_reports(ME_ERR_MCD_NO_INTERACTION, McdHello(&pair));
    McdContact contacts[4];
    McdIntersectResult result = {0};
    result.contacts = contacts;
    result.contactMaxCount = 4;
    assert_false(McdIntersect(&pair, &result));
    assert_int_equal(result.contactCount, 0);
    McdGoodbye(&pair);
    unsigned long before = MeMessageGetCount(ME_ERR_MCD_NO_INTERACTION);
    McdHello(&pair); /* same type pair: not reported again */
    McdModelPairReset(&pair, c, a);
    assert_reports(ME_ERR_MCD_NO_INTERACTION, McdHello(&pair)); /* a new type pair is */
    McdModelPairReset(&pair, a, c);
    McdHello(&pair); /* ... once, whichever order */
    McdModelPairReset(&pair, n, a);
    McdHello(&pair); /* null geometries touch nothing, silently */
    assert_int_equal(MeMessageGetCount(ME_ERR_MCD_NO_INTERACTION) - before, 1);
    /* Models of two frameworks never make a pair. */
    McdFrameworkID other = McdInit(0, 2, 0, 1);
    McdModelID foreign = placedModel(McdSphereCreate(other, 1), 0, 0, 0);
    assert_reports(ME_ERR_FOREIGN_HANDLE, assert_null(McdModelPairCreate(a, foreign)));
    McdModelPairReset(&pair, a, foreign);
    assert_reports(ME_ERR_FOREIGN_HANDLE, McdHello(&pair));
    McdTerm(other);
    printf("missing pair tests reported %lu times for 2 type pairs, 5 hellos\n",
           MeMessageGetCount(ME_ERR_MCD_NO_INTERACTION));
    McdTerm(fw);
}

/* Every pair among the primitives (Sphere, Box, Plane, Cylinder, Sphyl, Cone) has a test, except
 * plane-plane (static-static). Skipped while no nearfield test is registered at all. */
static void every_primitive_pair_has_a_test(void **state)
{
    (void)state;
    McdFrameworkID fwId = McdInit(0, 1, 0, 1);
    McdFrameworkData *fw = McdFrameworkFromID(fwId, "test");
    McdPrimitivesRegisterInteractions(fwId);
    static const int prims[] = {kMcdGeometryTypeSphere, kMcdGeometryTypeBox, kMcdGeometryTypePlane,
                                kMcdGeometryTypeCylinder, kMcdGeometryTypeSphyl, kMcdGeometryTypeCone};
    int covered = 0, wanted = 0, bothWays = 0;
    for (int i = 0; i < 6; i++)
        for (int j = i; j < 6; j++) {
            if (prims[i] == kMcdGeometryTypePlane && prims[j] == kMcdGeometryTypePlane)
                continue;
            wanted++;
            if (McdFrameworkHasInteraction(fw, prims[i], prims[j])) {
                covered++;
            } else {
                printf("no test for %s-%s\n", fw->types[prims[i]].typeName, fw->types[prims[j]].typeName);
            }
            if (i != j && McdFrameworkGetInteraction(fw, prims[i], prims[j]) &&
                McdFrameworkGetInteraction(fw, prims[j], prims[i]))
                bothWays++;
        }
    printf("primitive pairs with a test: %d of %d (registered both ways round: %d)\n", covered, wanted, bothWays);
    McdTerm(fwId);
    if (covered == 0)
        skip(); /* the nearfield tests are not merged yet */
    assert_int_equal(covered, wanted);
    assert_int_equal(bothWays, 0);
}

/* Every built-in pair through the public path: models, McdModelPairCreate, McdHello, McdIntersect,
 * McdGoodbye, both orders of the models. Shape 2 stands on shape 1 on the common z axis (a shape
 * stands on the plane), so the separation is the gap exactly, the normal from model 2 towards model 1:
 * -z when the lower model is model 1, +z when it is model 2. The contact tolerance is the sum of the models' (0.01 + 0.02): a gap of 0.025 gives
 * contacts, 0.035 none; a gap of -0.02 is a penetration of 0.02. */
static McdGeometryID axisGeometry(McdFrameworkID fw, int type, double *top, double *bottom)
{
    switch (type) {
    case kMcdGeometryTypeSphere: *top = *bottom = 0.5; return McdSphereCreate(fw, ME_R(0.5));
    case kMcdGeometryTypeBox: *top = *bottom = 0.3; return McdBoxCreate(fw, 1, ME_R(0.8), ME_R(0.6));
    case kMcdGeometryTypeCylinder: *top = *bottom = 0.5; return McdCylinderCreate(fw, ME_R(0.4), 1);
    case kMcdGeometryTypeSphyl: *top = *bottom = 0.7; return McdSphylCreate(fw, ME_R(0.3), ME_R(0.8));
    case kMcdGeometryTypeCone: *top = 0.75, *bottom = 0.25; return McdConeCreate(fw, 1, ME_R(0.5)); /* base at -L/4 */
    default: *top = *bottom = 0; return McdPlaneCreate(fw);
    }
}

static void every_pair_through_models(void **state)
{
    (void)state;
    static const int types[] = {kMcdGeometryTypeSphere, kMcdGeometryTypeBox, kMcdGeometryTypeCylinder,
                                kMcdGeometryTypeSphyl, kMcdGeometryTypeCone, kMcdGeometryTypePlane};
    static const double gaps[] = {0.025, 0.035, -0.02};
    McdFrameworkID fw = McdInit(0, 4, 4, 1);
    assert_true(McdPrimitivesRegisterInteractions(fw));
    int pairs = 0, runs = 0;
    for (int a = 0; a < 6; a++)
        for (int b = a; b < 6; b++) {
            if (types[a] == kMcdGeometryTypePlane && types[b] == kMcdGeometryTypePlane)
                continue;
            /* lower: the plane if there is one, else a; upper: the other */
            int lowerType = types[b] == kMcdGeometryTypePlane ? types[b] : types[a];
            int upperType = types[b] == kMcdGeometryTypePlane ? types[a] : types[b];
            double lowTop, lowBottom, upTop, upBottom;
            McdGeometryID gl = axisGeometry(fw, lowerType, &lowTop, &lowBottom);
            McdGeometryID gu = axisGeometry(fw, upperType, &upTop, &upBottom);
            McdModelID lower = McdModelCreate(gl), upper = McdModelCreate(gu);
            McdModelSetContactTolerance(lower, ME_R(0.01));
            McdModelSetContactTolerance(upper, ME_R(0.02));
            McdModelUpdate(lower);
            for (int k = 0; k < 3; k++) {
                MeMatrix4TMSetPosition(McdModelGetTransformPtr(upper), 0, 0, (MeReal)(lowTop + upBottom + gaps[k]));
                McdModelUpdate(upper);
                for (int order = 0; order < 2; order++) {
                    McdModelPairID pair = order ? McdModelPairCreate(upper, lower) : McdModelPairCreate(lower, upper);
                    McdContact contacts[4];
                    McdIntersectResult result = {0};
                    result.contacts = contacts;
                    result.contactMaxCount = 4;
                    McdHello(pair);
                    assert_true(pair->testIndex >= 0);
                    McdIntersect(pair, &result);
                    double sign = order ? 1 : -1, deepest = 1e30; /* normals from model 2 towards model 1 */
                    if (gaps[k] > 0.03) {
                        assert_int_equal(result.contactCount, 0);
                        assert_false(result.touch);
                    } else {
                        assert_true(result.contactCount >= 1 && result.contactCount <= 4);
                        assert_true(result.touch);
                        assert_near(result.normal[2], sign, 1e-5);
                        for (int i = 0; i < result.contactCount; i++) {
                            assert_near(contacts[i].normal[0], 0, 1e-4);
                            assert_near(contacts[i].normal[1], 0, 1e-4);
                            assert_near(contacts[i].normal[2], sign, 1e-5);
                            deepest = fmin(deepest, contacts[i].separation);
                        }
                        assert_near(deepest, gaps[k], ME_TOL(1e-7, 2e-5));
                    }
                    McdGoodbye(pair);
                    McdModelPairDestroy(pair);
                    runs++;
                }
            }
            printf("%s on %s: gaps 0.025 / 0.035 / -0.02 through McdIntersect, both orders\n",
                   McdGeometryGetTypeName(gu), McdGeometryGetTypeName(gl));
            McdModelDestroy(lower);
            McdModelDestroy(upper);
            McdGeometryDestroy(gl);
            McdGeometryDestroy(gu);
            pairs++;
        }
    assert_int_equal(pairs, 20);
    printf("%d type pairs, %d McdIntersect calls\n", pairs, runs);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(init_defaults_and_term),
        cmocka_unit_test(term_actions),
        cmocka_unit_test(user_geometry_type),
        cmocka_unit_test(interaction_table_one_way_and_swap),
        cmocka_unit_test(unregistered_pair_warned_once),
        cmocka_unit_test(every_primitive_pair_has_a_test),
        cmocka_unit_test(every_pair_through_models),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
