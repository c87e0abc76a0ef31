/* Aggregates and geometry instances, asserted on geometry:
 *  - the API and its coded errors (full, bad index, bad transform, cycle and depth, no mass, in use);
 *  - an aggregate of two boxes on a plane gives the two boxes' own contacts, each tagged with its
 *    element's child instance; the swapped pair gives the negated normals;
 *  - mass properties against closed forms: a dumbbell of two boxes, one offset and rotated box by the
 *    parallel axis theorem, a nested aggregate;
 *  - line segments: the first element hit, either way along the segment, nested;
 *  - nested transforms: a leaf instance's world transform is relTM(inner) relTM(outer) model;
 *  - random poses: against primitives, a plane, a convex mesh, every terrain type and another aggregate,
 *    the contacts are exactly the union of the element pairs' contacts (unit normals, tags, AABB);
 *  - rest: an L-shaped aggregate body stands still on a plane and on a triangle mesh. */
#include "karma_test.h"
#include "karma_pairs.h"
#include "karma_terrain.h"
#include "karma_mcd_reference.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#include <karma/karma.h>

#define TOL_CONTACT ME_R(0.01)
#define MAXC 32

static McdFrameworkID fwNew(int instances)
{
    McdFrameworkID fw = karma_pairs_framework(instances);
    McdAggregateRegisterInteractions(fw);
    return fw;
}

static McdModelID modelAt(McdGeometryID g, MeMatrix4 tm) { return karma_model_at(g, tm, TOL_CONTACT / 2); }

static McdRequest bigRequest = {MAXC, 0};

/* Contacts of (m1, m2), up to `max`, with room for MAXC asked of the pair. */
static int intersect(McdModelID m1, McdModelID m2, McdContact *c, int max)
{
    return karma_intersect(m1, m2, &bigRequest, c, max);
}

static void pose(MeMatrix4 tm, double ax, double ay, double az, double x, double y, double z)
{
    MeMatrix4TMFromEulerAnglesAndPosition(tm, (MeReal)ax, (MeReal)ay, (MeReal)az, (MeReal)x, (MeReal)y, (MeReal)z);
}

/* ---- API and errors --------------------------------------------------------------------------- */

static void api_and_errors(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = fwNew(16);
    McdGeometryID box = McdBoxCreate(fw, 1, 1, 1), sphere = McdSphereCreate(fw, ME_R(0.5));
    MeMatrix4 tm, bad;
    pose(tm, 0, 0, 0.3, 1, 2, 3);

    assert_null(McdAggregateCreate(fw, 0));
    assert_int_equal(karma_last_code(), ME_ERR_ARGUMENT_RANGE);
    McdAggregateID a = McdAggregateCreate(fw, 2);
    assert_non_null(a);
    assert_int_equal(McdGeometryGetTypeId(a), kMcdGeometryTypeAggregate);
    assert_int_equal(McdAggregateGetTypeId(), 8);
    assert_string_equal(McdGeometryGetTypeName(a), "Aggregate");
    assert_int_equal(McdAggregateGetElementCountMax(a), 2);
    assert_int_equal(McdAggregateGetElementCount(a), 0);

    assert_int_equal(McdAggregateAddElement(a, box, tm), 0);
    assert_int_equal(McdAggregateAddElement(a, box, tm), 1); /* shared: one geometry in two slots */
    assert_int_equal(McdGeometryGetReferenceCount(box), 2);
    assert_int_equal(McdAggregateGetElementCount(a), 2);
    assert_ptr_equal(McdAggregateGetElementGeometry(a, 1), box);
    assert_near(McdAggregateGetElementTransformPtr(a, 0)[3][1], 2, 0);

    /* full */
    assert_int_equal(McdAggregateAddElement(a, sphere, tm), -1);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_FULL);
    /* bad index: out of range, then an empty slot */
    McdAggregateRemoveElement(a, 2);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_INDEX);
    assert_null(McdAggregateGetElementGeometry(a, -1));
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_INDEX);
    McdAggregateRemoveElement(a, 0);
    assert_int_equal(McdGeometryGetReferenceCount(box), 1);
    McdAggregateRemoveElement(a, 0);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_INDEX);
    assert_int_equal(McdAggregateGetElementCount(a), 1);
    assert_null(McdAggregateGetElementGeometry(a, 0));
    assert_null(McdAggregateGetElementTransformPtr(a, 0));

    /* bad transforms: NaN, sheared, out of range; no state change */
    MeMatrix4Copy(bad, tm);
    bad[3][0] = NAN;
    assert_int_equal(McdAggregateAddElement(a, sphere, bad), -1);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_TRANSFORM);
    MeMatrix4Copy(bad, tm);
    bad[0][1] += ME_R(0.2);
    assert_int_equal(McdAggregateAddElement(a, sphere, bad), -1);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_TRANSFORM);
    MeMatrix4Copy(bad, tm);
    bad[3][2] = ME_R(1e9);
    assert_int_equal(McdAggregateAddElement(a, sphere, bad), -1);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_TRANSFORM);
    assert_int_equal(McdAggregateGetElementCount(a), 1);
    assert_int_equal(McdGeometryGetReferenceCount(sphere), 0);

    /* cycles: itself, and an aggregate that holds it */
    assert_int_equal(McdAggregateAddElement(a, a, tm), -1);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_CYCLE);
    McdAggregateID outer = McdAggregateCreate(fw, 1);
    assert_int_equal(McdAggregateAddElement(outer, a, tm), 0);
    assert_int_equal(McdAggregateAddElement(a, outer, tm), -1);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_CYCLE);
    /* depth: a chain of 16 single-element aggregates is the deepest accepted */
    McdGeometryID chain = sphere;
    int level;
    for (level = 0; level < 20; level++) {
        McdAggregateID next = McdAggregateCreate(fw, 1);
        if (McdAggregateAddElement(next, chain, tm) < 0) {
            assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_CYCLE);
            McdGeometryDestroy(next);
            break;
        }
        chain = next;
    }
    assert_int_equal(level, 16);

    /* in use: an element's geometry, an aggregate inside another, an aggregate of a model */
    McdGeometryDestroy(box);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_IN_USE);
    McdGeometryDestroy(a);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_IN_USE);
    McdModelID m = McdModelCreate(outer);
    McdGeometryDestroy(outer);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_IN_USE);
    McdModelDestroy(m);
    McdAggregateDestroy(outer);
    assert_true(McdGeometryIsValid(a));
    assert_int_equal(McdGeometryGetReferenceCount(a), 0);

    /* no mass: an empty aggregate, one with a plane */
    McdAggregateID empty = McdAggregateCreate(fw, 3);
    MeMatrix3 I;
    MeReal v;
    assert_int_not_equal(McdAggregateGetMassProperties(empty, NULL, I, &v), 0);
    assert_int_equal(karma_last_code(), ME_ERR_MCD_AGGREGATE_MASS);
    assert_int_not_equal(McdGeometryGetMassProperties(empty, NULL, I, &v), 0);
    McdAggregateAddElement(empty, McdPlaneCreate(fw), tm);
    McdAggregateAddElement(empty, McdBoxCreate(fw, 1, 1, 1), tm);
    assert_int_not_equal(McdAggregateGetMassProperties(empty, NULL, I, &v), 0);

    /* wrong type */
    assert_int_equal(McdAggregateAddElement(box, sphere, tm), -1);
    assert_int_equal(karma_last_code(), ME_ERR_WRONG_HANDLE_KIND);
    McdTerm(fw);
}

/* ---- two boxes on a plane ---------------------------------------------------------------------- */

/* Whether c (with tags) is in the set s[0..n): same point, normal, separation to tol. */
static MeBool hasContact(const McdContact *s, int n, const McdContact *c, double tol, MeBool checkTags)
{
    for (int i = 0; i < n; i++) {
        if (MeVector3Distance(s[i].position, c->position) <= tol && MeVector3Distance(s[i].normal, c->normal) <= tol &&
            fabs(s[i].separation - c->separation) <= tol &&
            (!checkTags || (s[i].element1 == c->element1 && s[i].element2 == c->element2)))
            return METRUE;
    }
    return MEFALSE;
}

static void two_boxes_on_plane(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew(16);
    McdGeometryID b1 = McdBoxCreate(fw, 2, 1, 1), b2 = McdBoxCreate(fw, 1, 1, ME_R(0.5));
    McdAggregateID a = McdAggregateCreate(fw, 4);
    MeMatrix4 r1, r2, tm, t1, t2, id;
    pose(r1, 0, 0, 0, -1, 0, 0.5);
    pose(r2, 0, 0, 0.7, 1.5, 0.5, 0.25);
    assert_int_equal(McdAggregateAddElement(a, b1, r1), 0);
    assert_int_equal(McdAggregateAddElement(a, b2, r2), 1);
    pose(tm, 0, 0, 0.4, 3, -2, -0.01); /* both boxes 1 cm into the plane */
    MeMatrix4TMMakeIdentity(id);
    McdModelID ma = modelAt(a, tm), plane = modelAt(McdPlaneCreate(fw), id);
    MeMatrix4TMCompound(t1, r1, tm);
    MeMatrix4TMCompound(t2, r2, tm);
    McdModelID m1 = modelAt(b1, t1), m2 = modelAt(b2, t2);

    McdGeometryInstanceID root = McdModelGetGeometryInstance(ma);
    McdGeometryInstanceID c0 = McdGeometryInstanceGetChild(root, 0), c1 = McdGeometryInstanceGetChild(root, 1);
    assert_non_null(c0);
    assert_non_null(c1);
    assert_non_null(McdGeometryInstanceGetChild(root, 3)); /* empty slots have instances, but no geometry */
    assert_null(McdGeometryInstanceGetGeometry(McdGeometryInstanceGetChild(root, 3)));
    assert_int_equal(McdGeometryInstanceGetGeometryType(McdGeometryInstanceGetChild(root, 2)), kMcdGeometryTypeNull);
    assert_null(McdGeometryInstanceGetChild(root, 4));
    assert_ptr_equal(McdGeometryInstanceGetGeometry(c0), b1);
    assert_int_equal(McdGeometryInstanceGetGeometryType(c1), kMcdGeometryTypeBox);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            assert_near(McdGeometryInstanceGetTransformPtr(c0)[i][j], t1[i][j], 1e-6);
            assert_near(McdGeometryInstanceGetTransformPtr(c1)[i][j], t2[i][j], 1e-6);
        }

    McdContact ca[MAXC], cb[MAXC], cs[MAXC];
    int na = intersect(ma, plane, ca, 8);
    int n1 = intersect(m1, plane, cb, MAXC);
    for (int k = 0; k < n1; k++)
        cb[k].element1 = c0;
    int n2 = intersect(m2, plane, cb + n1, MAXC - n1);
    for (int k = n1; k < n1 + n2; k++)
        cb[k].element1 = c1;
    assert_int_equal(n1, 4);
    assert_int_equal(n2, 4);
    assert_int_equal(na, 8);
    for (int k = 0; k < na; k++) {
        assert_true(hasContact(cb, n1 + n2, &ca[k], 1e-6, METRUE));
        assert_near(ca[k].normal[2], 1, 1e-6);
        assert_near(ca[k].separation, -0.01, 1e-5);
    }
    /* the swapped pair: the same points, normals negated, the tag on the other side */
    int ns = intersect(plane, ma, cs, 8);
    assert_int_equal(ns, 8);
    for (int k = 0; k < ns; k++) {
        McdContact c = cs[k];
        MeVector3Scale(c.normal, -1);
        void *e = c.element1;
        c.element1 = c.element2;
        c.element2 = e;
        assert_true(hasContact(ca, na, &c, 1e-6, METRUE));
    }
    /* the default request keeps four, spread over both boxes, the deepest first */
    McdModelPairID pair = McdModelPairCreate(ma, plane);
    McdIntersectResult r = {0};
    r.contacts = cs;
    r.contactMaxCount = MAXC;
    McdHello(pair);
    McdIntersect(pair, &r);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    assert_int_equal(r.contactCount, 4);
    int fromFirst = 0;
    for (int k = 0; k < 4; k++) {
        assert_true(hasContact(ca, na, &cs[k], 0, METRUE));
        fromFirst += cs[k].element1 == (void *)c0;
    }
    assert_true(fromFirst > 0 && fromFirst < 4);
    assert_int_equal(r.touch, 1);

    /* cost: the aggregate's pair against the two boxes' pairs (printed, not asserted: machines differ) */
    McdModelPairID pa = McdModelPairCreate(ma, plane), p1 = McdModelPairCreate(m1, plane),
                   p2 = McdModelPairCreate(m2, plane);
    McdHello(pa);
    McdHello(p1);
    McdHello(p2);
    const int reps = 20000;
    clock_t tick0 = clock();
    for (int i = 0; i < reps; i++)
        McdIntersect(pa, &r);
    clock_t tick1 = clock();
    for (int i = 0; i < reps; i++) {
        McdIntersect(p1, &r);
        McdIntersect(p2, &r);
    }
    clock_t tick2 = clock();
    printf("two-box aggregate on a plane: %.2f us per pair test, the two boxes' pairs %.2f us\n",
           1e6 * (double)(tick1 - tick0) / CLOCKS_PER_SEC / reps, 1e6 * (double)(tick2 - tick1) / CLOCKS_PER_SEC / reps);
    McdGoodbye(pa);
    McdGoodbye(p1);
    McdGoodbye(p2);
    McdModelPairDestroy(pa);
    McdModelPairDestroy(p1);
    McdModelPairDestroy(p2);
    McdTerm(fw);
}

/* ---- mass properties ----------------------------------------------------------------------------- */

static void mass_properties(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew(0);
    /* a dumbbell: unit cubes centred at x = -1.5 and +2.5 (one rotated: a cube's tensor is isotropic) */
    McdGeometryID cube = McdBoxCreate(fw, 1, 1, 1);
    McdAggregateID a = McdAggregateCreate(fw, 2);
    MeMatrix4 r1, r2, rel;
    pose(r1, 0, 0, 0, -1.5, 0, 0);
    pose(r2, 0.3, 0.5, 0.7, 2.5, 0, 0);
    McdAggregateAddElement(a, cube, r1);
    McdAggregateAddElement(a, cube, r2);
    MeMatrix3 I;
    MeReal v;
    assert_int_equal(McdGeometryGetMassProperties(a, rel, I, &v), 0);
    /* com at 0.5; each cube I0 = 1/6, offsets 2 => Iyy = Izz = 2 (1/6 + 4) */
    assert_near(v, 2, 1e-5);
    assert_near(rel[3][0], 0.5, 1e-6);
    assert_near(rel[3][1], 0, 1e-6);
    assert_near(rel[0][0], 1, 0); /* the aggregate's axes */
    assert_near(I[0][0], 2.0 / 6, 1e-5);
    assert_near(I[1][1], 2 * (1.0 / 6 + 4), 1e-4);
    assert_near(I[2][2], 2 * (1.0 / 6 + 4), 1e-4);
    assert_near(I[0][1], 0, 1e-5);
    assert_near(I[0][2], 0, 1e-5);
    assert_near(I[1][2], 0, 1e-5);

    /* one box 1 x 2 x 3 at offset p, rotated 90 degrees about z: x and y swap their moments */
    McdGeometryID box = McdBoxCreate(fw, 1, 2, 3);
    McdAggregateID one = McdAggregateCreate(fw, 1);
    MeMatrix4 r;
    pose(r, 0, 0, ME_PI / 2, 0.3, -0.2, 4);
    McdAggregateAddElement(one, box, r);
    assert_int_equal(McdAggregateGetMassProperties(one, rel, I, &v), 0);
    double m = 6, ix = m * (4 + 9) / 12.0, iy = m * (1 + 9) / 12.0, iz = m * (1 + 4) / 12.0;
    assert_near(v, 6, 1e-5);
    assert_near(rel[3][0], 0.3, 1e-6);
    assert_near(rel[3][1], -0.2, 1e-6);
    assert_near(rel[3][2], 4, 1e-6);
    assert_near(I[0][0], iy, 1e-4);
    assert_near(I[1][1], ix, 1e-4);
    assert_near(I[2][2], iz, 1e-4);
    assert_near(I[0][1], 0, 1e-5);

    /* a general rotation: the tensor is R^T I R; nested in another aggregate at an offset d, the parallel
     * axis theorem for the pair (with the cube at the origin) */
    pose(r, 0.4, -0.9, 1.3, 0, 0, 0);
    McdAggregateID rot = McdAggregateCreate(fw, 1);
    McdAggregateAddElement(rot, box, r);
    assert_int_equal(McdAggregateGetMassProperties(rot, rel, I, &v), 0);
    double Ib[3] = {ix, iy, iz};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0;
            for (int k = 0; k < 3; k++)
                s += r[k][i] * Ib[k] * r[k][j];
            assert_near(I[i][j], s, 1e-4);
        }
    McdAggregateID nest = McdAggregateCreate(fw, 2);
    MeMatrix4 d, o;
    pose(d, 0, 0, 0, 0, 3, 0);
    pose(o, 0, 0, 0, 0, 0, 0);
    McdAggregateAddElement(nest, rot, d);
    McdAggregateAddElement(nest, cube, o);
    MeMatrix3 In;
    assert_int_equal(McdAggregateGetMassProperties(nest, rel, In, &v), 0);
    double com = 6 * 3.0 / 7; /* masses 6 at y = 3 and 1 at y = 0 */
    assert_near(v, 7, 1e-5);
    assert_near(rel[3][1], com, 1e-5);
    double dy1 = 3 - com, dy2 = -com;
    double parallel = 6 * dy1 * dy1 + 1 * dy2 * dy2;
    assert_near(In[0][0], I[0][0] + 1.0 / 6 + parallel, 1e-4);
    assert_near(In[1][1], I[1][1] + 1.0 / 6, 1e-4);
    assert_near(In[2][2], I[2][2] + 1.0 / 6 + parallel, 1e-4);
    assert_near(In[0][1], I[0][1], 1e-4); /* the offset is along y: no product of inertia added */
    McdTerm(fw);
}

/* ---- line segments --------------------------------------------------------------------------- */

static void line_segment_first_hit(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew(16);
    McdGeometryID s = McdSphereCreate(fw, ME_R(0.5)), b = McdBoxCreate(fw, 1, 1, 1);
    McdAggregateID inner = McdAggregateCreate(fw, 1), a = McdAggregateCreate(fw, 2);
    MeMatrix4 r1, r2, tm;
    pose(r1, 0, 0, 0, 0, 0, 0);
    pose(r2, 0, 0, 0, 3, 0, 0);
    McdAggregateAddElement(inner, b, r1);
    McdAggregateAddElement(a, s, r1);
    McdAggregateAddElement(a, inner, r2); /* the box 3 m along x, through a nested aggregate */
    pose(tm, 0, 0, 0, 10, 0, 0);
    McdModelID m = modelAt(a, tm);
    McdLineSegIntersectResult res;
    MeVector3 p0 = {5, 0, 0}, p1 = {15, 0, 0};
    assert_int_equal(McdLineSegIntersect(m, p0, p1, &res), 1);
    assert_ptr_equal(res.model, m);
    assert_near(res.position[0], 9.5, 1e-5); /* the sphere first */
    assert_near(res.normal[0], -1, 1e-5);
    assert_near(res.distance, 4.5, 1e-5);
    assert_int_equal(McdLineSegIntersect(m, p1, p0, &res), 1);
    assert_near(res.position[0], 13.5, 1e-5); /* the box first from the other end */
    assert_near(res.normal[0], 1, 1e-5);
    assert_near(res.distance, 1.5, 1e-5);
    MeVector3 q0 = {11.5, 0, 0}, q1 = {12, 0, 0}; /* between the two: a miss */
    assert_int_equal(McdLineSegIntersect(m, q0, q1, &res), 0);
    McdTerm(fw);
}

/* ---- nested transforms ------------------------------------------------------------------------- */

static void nested_transforms(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew(16);
    McdGeometryID b = McdBoxCreate(fw, ME_R(0.5), 1, 2);
    McdAggregateID inner = McdAggregateCreate(fw, 2), outer = McdAggregateCreate(fw, 3);
    MeMatrix4 ri, ro, tm, expect, tmp, id;
    pose(ri, 0, 0, ME_PI / 2, 1, 0, 0);
    pose(ro, ME_PI / 2, 0, 0, 0, 2, 0);
    McdAggregateAddElement(inner, b, ri);
    MeMatrix4 up;
    pose(up, 0, 0, 0, 0, 0, 3);
    McdAggregateAddElement(outer, b, up); /* the shared box straight in the outer too, 3 m up */
    McdAggregateAddElement(outer, inner, ro);
    pose(tm, 0.3, 0.2, 0.1, 5, 6, 7);
    McdModelID m = modelAt(outer, tm);
    MeMatrix4TMCompound(tmp, ri, ro);
    MeMatrix4TMCompound(expect, tmp, tm);
    McdGeometryInstanceID root = McdModelGetGeometryInstance(m);
    McdGeometryInstanceID leaf = McdGeometryInstanceGetChild(McdGeometryInstanceGetChild(root, 1), 0);
    assert_non_null(leaf);
    assert_int_equal(McdGeometryInstanceGetGeometryType(McdGeometryInstanceGetChild(root, 1)), kMcdGeometryTypeAggregate);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            assert_near(McdGeometryInstanceGetTransformPtr(leaf)[i][j], expect[i][j], 1e-5);
    /* the leaf's AABB is its box's there; the model's contains it */
    MeVector3 lo, hi, blo, bhi, mlo, mhi;
    McdGeometryInstanceGetAABB(leaf, lo, hi);
    McdGeometryGetAABB(b, expect, blo, bhi);
    McdModelGetAABB(m, mlo, mhi);
    for (int j = 0; j < 3; j++) {
        assert_near(lo[j], blo[j], 1e-5);
        assert_near(hi[j], bhi[j], 1e-5);
        assert_true(mlo[j] <= lo[j] && mhi[j] >= hi[j]);
    }
    /* the application's array receives the leaf's transform at each update */
    MeMatrix4 mine;
    McdGeometryInstanceSetTransformPtr(leaf, mine);
    assert_ptr_equal(McdGeometryInstanceGetTransformPtr(leaf), (MeMatrix4Ptr)mine);
    MeMatrix4Ptr mtm = McdModelGetTransformPtr(m);
    mtm[3][0] += 1;
    McdModelUpdate(m);
    assert_near(mine[3][0], expect[3][0] + 1, 1e-5);
    /* contacts with a plane name the leaf: drop the model so only the nested box touches */
    MeMatrix4TMMakeIdentity(id);
    McdModelID plane = modelAt(McdPlaneCreate(fw), id);
    MeVector3 lowest;
    MeVector3 down = {0, 0, -1};
    McdGeometryInstanceMaximumPoint(leaf, down, lowest);
    MeVector3 other;
    McdGeometryInstanceMaximumPoint(McdGeometryInstanceGetChild(root, 0), down, other);
    assert_true(lowest[2] < other[2] - ME_R(0.1)); /* this pose puts the nested box lowest */
    mtm[3][2] -= lowest[2] + ME_R(0.005);
    McdModelUpdate(m);
    McdContact c[MAXC];
    int n = intersect(m, plane, c, MAXC);
    assert_true(n > 0);
    for (int k = 0; k < n; k++) {
        assert_ptr_equal(c[k].element1, leaf);
        assert_null(c[k].element2);
        assert_near(c[k].separation, -0.005, 1e-4);
    }
    /* the rest of the instance API on a child and the root */
    McdGeometryInstanceID top = McdGeometryInstanceGetChild(root, 0);
    McdGeometryInstanceSetMaterial(leaf, 7);
    McdGeometryInstanceSetMaterial(root, 3);
    assert_int_equal(McdGeometryInstanceGetMaterial(leaf), 7);
    assert_int_equal(McdModelGetMaterial(m), 3);
    MeVector3 centre;
    MeReal radius;
    McdGeometryInstanceGetBSphere(leaf, centre, &radius);
    for (int j = 0; j < 3; j++)
        assert_near(centre[j], McdGeometryInstanceGetTransformPtr(leaf)[3][j], 1e-6); /* a box: its centre */
    assert_near(radius, 0.5 * sqrt(0.25 + 1 + 4), 1e-5);
    assert_false(McdGeometryInstanceOverlap(leaf, top)); /* 3 m apart */
    assert_true(McdGeometryInstanceOverlap(leaf, root));
    MeMatrix4 later;
    MeMatrix4Copy(later, McdGeometryInstanceGetTransformPtr(leaf));
    later[3][2] += 10;
    MeVector3 slo, shi, nlo, nhi;
    McdGeometryInstanceGetAABB(leaf, nlo, nhi);
    McdGeometryInstanceUpdateAABB(leaf, later, 1); /* swept: from here to 10 m up */
    McdGeometryInstanceGetAABB(leaf, slo, shi);
    assert_near(slo[2], nlo[2], 1e-5);
    assert_near(shi[2], nhi[2] + 10, 1e-5);
    assert_near(slo[0], nlo[0], 1e-5);
    McdGeometryInstanceReset(leaf);
    assert_int_equal(McdGeometryInstanceGetMaterial(leaf), 0);
    assert_ptr_not_equal(McdGeometryInstanceGetTransformPtr(leaf), (MeMatrix4Ptr)mine); /* its own again */
    McdGeometryInstanceSetTransformPtr(leaf, mine);
    /* the root refuses what belongs to the model */
    karma_capture_messages();
    McdGeometryInstanceSetTransformPtr(root, mine);
    assert_int_equal(karma_last_code(), ME_ERR_BAD_STATE);
    McdGeometryInstanceSetGeometry(leaf, b);
    assert_int_equal(karma_last_code(), ME_ERR_BAD_STATE);
    /* removing an element drops its subtree at the next update */
    McdAggregateRemoveElement(outer, 1);
    McdModelUpdate(m);
    assert_null(McdGeometryInstanceGetChild(McdGeometryInstanceGetChild(root, 1), 0));
    assert_null(McdGeometryInstanceGetGeometry(leaf)); /* its slot went back to the pool: a stale ID */
    assert_int_equal(karma_last_code(), ME_ERR_INVALID_HANDLE);
    McdTerm(fw);
}

/* ---- an instance pool too small ---------------------------------------------------------------- */

static void instance_pool_too_small(void **state)
{
    (void)state;
    karma_capture_messages();
    McdFrameworkID fw = fwNew(1);
    McdAggregateID a = McdAggregateCreate(fw, 2);
    MeMatrix4 r1, r2, id;
    pose(r1, 0, 0, 0, -1, 0, 0.49);
    pose(r2, 0, 0, 0, 1, 0, 0.49);
    McdAggregateAddElement(a, McdBoxCreate(fw, 1, 1, 1), r1);
    McdAggregateAddElement(a, McdBoxCreate(fw, 1, 1, 1), r2);
    MeMatrix4TMMakeIdentity(id);
    McdModelID m = modelAt(a, id);
    assert_int_equal(karma_last_code(), ME_ERR_POOL_FULL);
    McdModelID plane = modelAt(McdPlaneCreate(fw), id);
    McdContact c[MAXC];
    int n = intersect(m, plane, c, MAXC);
    assert_int_equal(n, 8); /* contacts all the same, without tags */
    for (int k = 0; k < n; k++)
        assert_null(c[k].element1);
    assert_null(McdGeometryInstanceGetChild(McdModelGetGeometryInstance(m), 0));
    McdTerm(fw);
}

/* ---- random poses: the union of the element pairs ---------------------------------------------- */

/* The contacts of an aggregate model against `other` must be the contacts each element (a model of
 * its own at the element's world transform) makes with it, tagged with the element's instance. */
static int elementContacts(McdFrameworkID fw, McdGeometryID g, MeMatrix4 tm, McdGeometryInstanceID ins,
                           McdModelID other, MeBool otherFirst, McdContact *out, int room)
{
    (void)fw;
    if (McdGeometryGetTypeId(g) == kMcdGeometryTypeAggregate) {
        int n = 0;
        for (int i = 0; i < McdAggregateGetElementCountMax(g); i++) {
            McdGeometryID e = McdAggregateGetElementGeometry(g, i);
            if (!e)
                continue;
            MeMatrix4 ctm;
            MeMatrix4TMCompound(ctm, McdAggregateGetElementTransformPtr(g, i), tm);
            n += elementContacts(fw, e, ctm, McdGeometryInstanceGetChild(ins, i), other, otherFirst, out + n,
                                 room - n);
        }
        return n;
    }
    McdModelID m = modelAt(g, tm);
    int n = otherFirst ? intersect(other, m, out, room) : intersect(m, other, out, room);
    for (int k = 0; k < n; k++) {
        if (otherFirst)
            out[k].element2 = ins;
        else
            out[k].element1 = ins;
    }
    McdModelDestroy(m);
    return n;
}

static void random_poses(void **state)
{
    (void)state;
    McdFrameworkID fw = fwNew(64);
    MeMatrix4 r;
    /* an aggregate of a sphere, a box, a sphyl, a cylinder and a nested aggregate of a convex box */
    McdAggregateID a = McdAggregateCreate(fw, 5), inner = McdAggregateCreate(fw, 1);
    MeVector3 pts[8];
    for (int i = 0; i < 8; i++)
        MeVector3Set(pts[i], (i & 1) ? ME_R(0.3) : ME_R(-0.3), (i & 2) ? ME_R(0.2) : ME_R(-0.2),
                     (i & 4) ? ME_R(0.25) : ME_R(-0.25));
    pose(r, 0.2, 0, 0.5, 0.2, 0.6, 0);
    McdAggregateAddElement(inner, McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, 8, 0), r);
    pose(r, 0, 0, 0, 0.7, 0, 0);
    McdAggregateAddElement(a, McdSphereCreate(fw, ME_R(0.4)), r);
    pose(r, 0.3, 0.1, 0, -0.6, 0, 0.1);
    McdAggregateAddElement(a, McdBoxCreate(fw, ME_R(0.6), ME_R(0.5), ME_R(0.8)), r);
    pose(r, ME_PI / 2, 0, 0, 0, -0.7, 0);
    McdAggregateAddElement(a, McdSphylCreate(fw, ME_R(0.2), ME_R(0.6)), r);
    pose(r, 0, 0.4, 0, 0, 0, 0.7);
    McdAggregateAddElement(a, McdCylinderCreate(fw, ME_R(0.25), ME_R(0.4)), r);
    pose(r, 0, 0, 0, 0, 0, -0.5);
    McdAggregateAddElement(a, inner, r);

    /* the others: primitives, a convex mesh, a plane, the terrains, another aggregate */
    McdAggregateID a2 = McdAggregateCreate(fw, 2);
    pose(r, 0, 0, 0, 0.4, 0, 0);
    McdAggregateAddElement(a2, McdBoxCreate(fw, ME_R(0.5), ME_R(0.5), ME_R(0.5)), r);
    pose(r, 0, 0, 0, -0.4, 0, 0);
    McdAggregateAddElement(a2, McdSphereCreate(fw, ME_R(0.3)), r);
    McdTriangleMeshID mesh = karma_floor_mesh(fw, 3, 6, 0.3, 7);
    McdGeometryID others[] = {McdBoxCreate(fw, 1, ME_R(0.7), ME_R(0.5)), McdSphereCreate(fw, ME_R(0.5)),
                              McdSphylCreate(fw, ME_R(0.3), 1), McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, 8, 0),
                              McdPlaneCreate(fw), mesh, karma_floor_field(fw, 3, 6),
                              karma_floor_list(fw, mesh), a2};
    const int nOthers = (int)(sizeof others / sizeof others[0]);
    RefRng rng = {12345};
    long contactsSeen = 0;
    int posesWithContacts = 0;
    for (int trial = 0; trial < 1800; trial++) {
        int which = trial % nOthers;
        McdGeometryID og = others[which];
        int type = McdGeometryGetTypeId(og);
        MeMatrix4 tma, tmo;
        MeBool flat = type == kMcdGeometryTypePlane || type == kMcdGeometryTypeTriangleMesh ||
                      type == kMcdGeometryTypeRGHeightField || type == kMcdGeometryTypeTriangleList;
        if (flat) {
            MeMatrix4TMMakeIdentity(tmo);
            ref_random_tm(&rng, tma, ref_uniform(&rng, -1, 1), ref_uniform(&rng, -1, 1), ref_uniform(&rng, -0.2, 1.2));
        } else {
            ref_random_tm(&rng, tma, 0, 0, 0);
            ref_random_tm(&rng, tmo, ref_uniform(&rng, -1.6, 1.6), ref_uniform(&rng, -1.6, 1.6),
                          ref_uniform(&rng, -1.6, 1.6));
        }
        McdModelID ma = modelAt(a, tma), mo = modelAt(og, tmo);
        McdGeometryInstanceID root = McdModelGetGeometryInstance(ma);
        for (int swapped = 0; swapped < 2; swapped++) {
            McdContact got[MAXC], want[MAXC];
            int n = swapped ? intersect(mo, ma, got, MAXC) : intersect(ma, mo, got, MAXC);
            int nw;
            if (type == kMcdGeometryTypeAggregate) { /* both sides recurse: pair every leaf of a with mo's */
                nw = 0;
                McdGeometryInstanceID oroot = McdModelGetGeometryInstance(mo);
                for (int j = 0; j < 2; j++) {
                    MeMatrix4 otm;
                    MeMatrix4TMCompound(otm, McdAggregateGetElementTransformPtr(og, j), tmo);
                    McdModelID leafModel = modelAt(McdAggregateGetElementGeometry(og, j), otm);
                    int k0 = nw;
                    nw += elementContacts(fw, a, tma, root, leafModel, (MeBool)swapped, want + nw, MAXC - nw);
                    for (int k = k0; k < nw; k++) {
                        if (swapped)
                            want[k].element1 = McdGeometryInstanceGetChild(oroot, j);
                        else
                            want[k].element2 = McdGeometryInstanceGetChild(oroot, j);
                    }
                    McdModelDestroy(leafModel);
                }
            } else {
                nw = elementContacts(fw, a, tma, root, mo, (MeBool)swapped, want, MAXC);
            }
            /* The same bits when the element pairs run in the order the pair's models do; swapped, a
             * test such as box-box runs with its geometries the other way round: rounding apart. */
            const double tol = swapped ? ME_TOL(1e-9, 2e-5) : 0;
            assert_int_equal(n, nw);
            for (int k = 0; k < n; k++) {
                assert_near(MeVector3Magnitude(got[k].normal), 1, 1e-5);
                assert_true(hasContact(want, nw, &got[k], tol, METRUE));
                assert_non_null(swapped ? got[k].element2 : got[k].element1);
            }
            contactsSeen += n;
            posesWithContacts += n > 0;
        }
        /* the aggregate's AABB holds every element's */
        MeVector3 lo, hi;
        McdGeometryGetAABB(a, tma, lo, hi);
        for (int i = 0; i < 5; i++) {
            MeVector3 elo, ehi;
            McdGeometryInstanceGetAABB(McdGeometryInstanceGetChild(root, i), elo, ehi);
            for (int j = 0; j < 3; j++)
                assert_true(lo[j] <= elo[j] && hi[j] >= ehi[j]);
        }
        McdModelDestroy(ma);
        McdModelDestroy(mo);
    }
    printf("aggregate random poses: %d of 3600 pair tests touched, %ld contacts, all equal to the elements'\n",
           posesWithContacts, contactsSeen);
    assert_true(posesWithContacts > 1000);
    McdTerm(fw);
}

/* ---- rest: an L-shaped aggregate body -------------------------------------------------------- */

static void l_shape_rests(McdGeometryID (*ground)(McdFrameworkID), const char *name)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    McdAggregateRegisterInteractions(fw);
    static MeMatrix4 id = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, ME_R(-9.81));
    MstFixedModelCreate(u, ground(fw), id);
    /* an L: a 1.2 x 0.3 x 0.3 foot along x and a 0.3 x 0.3 x 0.9 leg standing on its end */
    McdAggregateID l = McdAggregateCreate(fw, 2);
    MeMatrix4 r;
    pose(r, 0, 0, 0, 0, 0, 0);
    McdAggregateAddElement(l, McdBoxCreate(fw, ME_R(1.2), ME_R(0.3), ME_R(0.3)), r);
    pose(r, 0, 0, 0, -0.45, 0, 0.6);
    McdAggregateAddElement(l, McdBoxCreate(fw, ME_R(0.3), ME_R(0.3), ME_R(0.9)), r);
    McdModelID m = MstModelAndBodyCreate(u, l, 1000);
    MdtBodyID b = McdModelGetBody(m);
    MeVector3 com, p0, p1;
    MdtBodyGetCenterOfMassRelativePosition(b, com);
    /* volumes 0.108 at x 0, z 0 and 0.081 at x -0.45, z 0.6 */
    assert_near(com[0], -0.45 * 0.081 / 0.189, 1e-5);
    assert_near(com[2], 0.6 * 0.081 / 0.189, 1e-5);
    /* the reference: the foot alone as a box body given the L's mass, inertia and centre of mass (the
     * leg touches nothing: the same contacts must carry the same body) */
    McdModelID ref = MstModelAndBodyCreate(u, McdBoxCreate(fw, ME_R(1.2), ME_R(0.3), ME_R(0.3)), 1000);
    MdtBodyID rb = McdModelGetBody(ref);
    MeMatrix3 inertia;
    MdtBodyGetInertiaTensor(b, inertia);
    MdtBodySetCenterOfMassRelativePosition(rb, com);
    MdtBodySetMass(rb, MdtBodyGetMass(b));
    MdtBodySetInertiaTensor(rb, inertia);
    MdtBodySetPosition(rb, 0, ME_R(2.0), ME_R(0.15));
    MdtBodyEnable(rb);
    MeVector3 r0, r1;
    MdtBodyGetCenterOfMassPosition(rb, r0);
    MdtBodySetPosition(b, 0, ME_R(-2.0), ME_R(0.15));
    MdtBodyEnable(b);
    MdtBodyGetCenterOfMassPosition(b, p0);
    for (int i = 0; i < 180; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    MdtBodyGetCenterOfMassPosition(b, p1);
    MeVector4 q;
    MdtBodyGetQuaternion(b, q);
    double angle = 2 * acos(fmin(1.0, fabs((double)q[0])));
    /* at rest, not toppling slowly: two more seconds change neither position nor angle */
    for (int i = 0; i < 120; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    MeVector3 p2, w;
    MeVector4 q2;
    MdtBodyGetCenterOfMassPosition(b, p2);
    MdtBodyGetQuaternion(b, q2);
    MdtBodyGetAngularVelocity(b, w);
    double angle2 = 2 * acos(fmin(1.0, fabs((double)q2[0])));
    printf("  then 2 s more: moved %.2e m, rotation %.2e rad, angular speed %.2e rad/s\n",
           (double)MeVector3Distance(p1, p2), angle2, (double)MeVector3Magnitude(w));
    assert_true(MeVector3Distance(p1, p2) < 1e-4);
    assert_true(fabs(angle2 - angle) < 1e-4);
    assert_true(MeVector3Magnitude(w) < 1e-3);
    MeVector4 rq;
    MdtBodyGetCenterOfMassPosition(rb, r1);
    MdtBodyGetQuaternion(rb, rq);
    double rAngle = 2 * acos(fmin(1.0, fabs((double)rq[0])));
    printf("  the foot box with the L's mass: sank %.3e m (L: %.3e), rotation %.3e rad (L: %.3e)\n",
           (double)(r1[2] - r0[2]), (double)(p2[2] - p0[2]), rAngle, angle2);
    assert_near(p2[2] - p0[2], r1[2] - r0[2], 2e-5);
    assert_near(angle2, rAngle, 2e-5);
    printf("L-shaped aggregate on %s after 3 s: centre of mass moved (%.2e %.2e %.2e) m, rotation %.2e rad\n", name,
           (double)(p1[0] - p0[0]), (double)(p1[1] - p0[1]), (double)(p1[2] - p0[2]), angle);
    /* the leg is over the foot's end, 0.45 m from the centre: a wrong centre of mass or a contact lost
     * at the element boundary would tip it over (radians) */
    assert_true(fabs(p1[0] - p0[0]) < 1e-3 && fabs(p1[1] - p0[1]) < 1e-3);
    assert_true(p1[2] - p0[2] < 0.001 && p1[2] - p0[2] > -0.01);
    assert_true(angle < 5e-3);
    MstUniverseDestroy(u);
}

static McdGeometryID planeGround(McdFrameworkID fw) { return McdPlaneCreate(fw); }
static McdGeometryID meshGround(McdFrameworkID fw) { return karma_floor_mesh(fw, 4, 8, 0.3, 11); }

static void rests_on_plane(void **state)
{
    (void)state;
    l_shape_rests(planeGround, "a plane");
}

static void rests_on_mesh(void **state)
{
    (void)state;
    l_shape_rests(meshGround, "a triangle mesh");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(api_and_errors),
        cmocka_unit_test(two_boxes_on_plane),
        cmocka_unit_test(mass_properties),
        cmocka_unit_test(line_segment_first_hit),
        cmocka_unit_test(nested_transforms),
        cmocka_unit_test(instance_pool_too_small),
        cmocka_unit_test(random_poses),
        cmocka_unit_test(rests_on_plane),
        cmocka_unit_test(rests_on_mesh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
