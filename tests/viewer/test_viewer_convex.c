/* test_viewer_convex.c -- convex meshes, aggregates and terrain drawn from their collision geometry,
 * checked on the picture (headless, EGL on Mesa): the projected centre of a convex hull and of each
 * element of an aggregate (nested aggregates included) lands on pixels of its colour, the gap between
 * two elements does not, and the elements follow the model when it moves and turns. The triangles
 * themselves are checked against the geometry: every hull vertex carries its polygon's outward
 * normal, a triangle mesh and a height field give their own triangles; triangle strips become a list
 * of one winding, and a scaled box spans its new sizes. */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/MeMath.h>
#include <karma/McdAggregate.h>
#include <karma/McdConvexMesh.h>
#include <karma/McdGeometryInstance.h>
#include <karma/McdRGHeightField.h>
#include <karma/McdTriangleList.h>
#include <karma/McdTriangleMesh.h>

#include "RConvex.h"
#include "RInternal.h"
#include "viewer_project.h"

#define W 320
#define H 200

static RRender *rc;
static McdFrameworkID fw;
static unsigned char rgba[W * H * 4];

static const float red[4] = {1, 0.1f, 0.1f, 1}, blue[4] = {0.1f, 0.2f, 1, 1};

static int setup(void **state)
{
    karma_capture_messages();
    fw = McdInit(0, 16, 64, 1);
    McdPrimitivesRegisterInteractions(fw);
    rc = RRenderContextCreateHeadless(W, H);
    if (!rc)
        fprintf(stderr, "no headless OpenGL 3.3 context: install libegl-mesa0 and libgl1-mesa-dri (.ci/run does)\n");
    const AcmeVector3 at = {0, 0, 0};
    if (rc) {
        RCameraSetLookAt(rc, at);
        RCameraSetView(rc, 9, 0, 0); /* from +z: x to the right, y up */
    }
    return rc && fw ? 0 : -1;
}

static int teardown(void **state)
{
    RRenderContextDestroy(rc);
    McdTerm(fw);
    return 0;
}

static void draw(void)
{
    RRenderDrawFrame(rc);
    assert_int_equal(RRenderReadPixels(rc, rgba), 0);
}

/* Whether the pixel where world point p projects has the chromaticity of `color`. */
static int isColour(const double p[3], const float color[4])
{
    double ndc[3];
    assert_true(viewerProject(rc, p, ndc) > 0);
    int x = (int)floor((ndc[0] + 1) / 2 * W), y = (int)floor((1 - ndc[1]) / 2 * H);
    assert_true(x >= 0 && x < W && y >= 0 && y < H);
    const unsigned char *q = rgba + 4 * ((size_t)y * W + (size_t)x);
    double s = q[0] + q[1] + q[2] + 1e-9, t = color[0] + color[1] + color[2], d = 0;
    for (int k = 0; k < 3; k++)
        d += (q[k] / s - color[k] / t) * (q[k] / s - color[k] / t);
    return q[0] + q[1] + q[2] > 30 && sqrt(d) < 0.1;
}

static void identity(MeMatrix4 m)
{
    memset(m, 0, sizeof(MeMatrix4));
    for (int k = 0; k < 4; k++)
        m[k][k] = 1;
}

/* A hull of 8 corners of a box of half sides a, b, c, centred on the origin. */
static McdConvexMeshID boxHull(MeReal a, MeReal b, MeReal c)
{
    MeVector3 v[8];
    for (int i = 0; i < 8; i++)
        MeVector3Set(v[i], i & 1 ? a : -a, i & 2 ? b : -b, i & 4 ? c : -c);
    return McdConvexMeshCreateHull(fw, (const MeVector3 *)v, 8, 0);
}

static void test_convex_hull_polygons_and_flat_normals(void **state)
{
    /* A triangular prism: 2 triangles and 3 quads, 8 triangles. */
    MeVector3 v[6] = {{0, 1, -0.5f}, {-0.9f, -0.5f, -0.5f}, {0.9f, -0.5f, -0.5f},
                      {0, 1, 0.5f},  {-0.9f, -0.5f, 0.5f},  {0.9f, -0.5f, 0.5f}};
    McdConvexMeshID hull = McdConvexMeshCreateHull(fw, (const MeVector3 *)v, 6, 0);
    assert_non_null(hull);
    MeMatrix4 tm;
    identity(tm);
    RGraphic *g = RGraphicConvexCreate(rc, hull, red, tm);
    assert_non_null(g);
    int expect = 0;
    for (int i = 0; i < McdConvexMeshGetPolygonCount(hull); i++)
        expect += 3 * (McdConvexMeshGetPolygonVertexCount(hull, i) - 2);
    assert_int_equal(expect, 3 * 8);
    assert_int_equal(g->m_pObject->m_nNumVertices, expect);
    /* Each triangle is flat: its three normals equal, unit, along its edges' cross product (outward:
     * away from the centroid (0, 0, 0) -- the prism's centroid is at y = 0). */
    for (int t = 0; t < expect / 3; t++) {
        const RObjectVertex *a = &g->m_pVertices[3 * t], *b = a + 1, *c = a + 2;
        double e1[3] = {b->m_X - a->m_X, b->m_Y - a->m_Y, b->m_Z - a->m_Z};
        double e2[3] = {c->m_X - a->m_X, c->m_Y - a->m_Y, c->m_Z - a->m_Z};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        assert_true(l > 1e-3);
        for (int k = 0; k < 3; k++) {
            const RObjectVertex *p = a + k;
            double dot = (p->m_NX * n[0] + p->m_NY * n[1] + p->m_NZ * n[2]) / l;
            assert_float_equal(dot, 1, 1e-5);
        }
        double out = a->m_NX * a->m_X + a->m_NY * a->m_Y + a->m_NZ * a->m_Z;
        assert_true(out > 0);
    }
    /* On the picture, at x = -1.5: its centre red, the sky beside it not; it follows its matrix. */
    tm[3][0] = ME_R(-1.5);
    draw();
    const double centre[3] = {-1.5, 0, 0}, beside[3] = {-3, 0, 0}, moved[3] = {1.5, 1, 0};
    assert_true(isColour(centre, red));
    assert_false(isColour(beside, red));
    tm[3][0] = ME_R(1.5), tm[3][1] = 1;
    draw();
    assert_true(isColour(moved, red));
    assert_false(isColour(centre, red));
    RGraphicDelete(rc, g, 0);
    assert_null(rc->m_pRG_First);
    /* Refused: another geometry type, NULL. */
    McdGeometryID sphere = McdSphereCreate(fw, 1);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, g = RGraphicConvexCreate(rc, sphere, red, NULL));
    assert_null(g);
    assert_reports(ME_ERR_NULL_ARGUMENT, g = RGraphicConvexCreate(rc, NULL, red, NULL));
    assert_null(rc->m_pRG_First);
    McdGeometryDestroy(sphere);
    McdGeometryDestroy(hull);
}

/* An aggregate: a box hull at (-1.1, 0, 0), a sphere at (1.1, 0, 0) and a nested aggregate at
 * (0, 1.2, 0) holding a box turned a quarter about z. */
typedef struct Scene {
    McdGeometryID hull, sphere, box, inner, outer;
    McdModelID model;
} Scene;

static void sceneCreate(Scene *s)
{
    MeMatrix4 rel;
    s->hull = boxHull(ME_R(0.5), ME_R(0.5), ME_R(0.5));
    s->sphere = McdSphereCreate(fw, ME_R(0.5));
    s->box = McdBoxCreate(fw, ME_R(0.4), ME_R(1.0), ME_R(0.4)); /* turned: 1.0 along x */
    s->inner = McdAggregateCreate(fw, 2);
    s->outer = McdAggregateCreate(fw, 4);
    identity(rel);
    rel[0][0] = rel[1][1] = 0, rel[0][1] = 1, rel[1][0] = -1; /* a quarter about z */
    assert_true(McdAggregateAddElement(s->inner, s->box, rel) >= 0);
    identity(rel);
    rel[3][0] = ME_R(-1.1);
    assert_true(McdAggregateAddElement(s->outer, s->hull, rel) >= 0);
    rel[3][0] = ME_R(1.1);
    assert_true(McdAggregateAddElement(s->outer, s->sphere, rel) >= 0);
    rel[3][0] = 0, rel[3][1] = ME_R(1.2);
    assert_true(McdAggregateAddElement(s->outer, s->inner, rel) >= 0);
    s->model = McdModelCreate(s->outer);
    assert_non_null(s->model);
    McdModelUpdate(s->model);
}

static void sceneDestroy(Scene *s)
{
    McdModelDestroy(s->model);
    McdGeometryDestroy(s->outer);
    McdGeometryDestroy(s->inner);
    McdGeometryDestroy(s->box);
    McdGeometryDestroy(s->sphere);
    McdGeometryDestroy(s->hull);
}

/* The world point of aggregate-frame point p under the model's transform. */
static void world(const McdModelID m, const double p[3], double out[3])
{
    const MeReal(*t)[4] = (const MeReal(*)[4])McdModelGetTransformPtr(m);
    for (int j = 0; j < 3; j++)
        out[j] = p[0] * t[0][j] + p[1] * t[1][j] + p[2] * t[2][j] + t[3][j];
}

static void checkElements(const Scene *s, const char *what)
{
    const double centres[3][3] = {{-1.1, 0, 0}, {1.1, 0, 0}, {0, 1.2, 0}};
    const double gaps[2][3] = {{-0.3, -0.3, 0}, {0.3, -0.3, 0}}; /* between the elements: sky */
    draw();
    for (int i = 0; i < 3; i++) {
        double p[3];
        world(s->model, centres[i], p);
        if (!isColour(p, blue))
            fail_msg("%s: element %d's centre (%.2f, %.2f, %.2f) is not blue", what, i, p[0], p[1], p[2]);
    }
    /* The turned box of the nested aggregate reaches 0.5 along x, only 0.2 along y. */
    const double along[2][3] = {{0.4, 1.2, 0}, {0, 1.2 + 0.4, 0}};
    double p[3];
    world(s->model, along[0], p);
    assert_true(isColour(p, blue));
    world(s->model, along[1], p);
    assert_false(isColour(p, blue));
    for (int i = 0; i < 2; i++) {
        world(s->model, gaps[i], p);
        if (isColour(p, blue))
            fail_msg("%s: the gap %d between elements is blue", what, i);
    }
}

static void test_aggregate_model_element_by_element(void **state)
{
    Scene s;
    sceneCreate(&s);
    RGraphic *g = RGraphicCreateFromModel(rc, s.model, (float *)blue);
    assert_non_null(g);
    int graphics = 0;
    for (RGraphic *e = rc->m_pRG_First; e; e = e->m_pNext)
        graphics++;
    assert_int_equal(graphics, 1 + 3); /* the model's (no vertices) and one a drawn element */
    checkElements(&s, "at the origin");
    /* The model moves and turns a quarter about z: the elements go with it at the next update. */
    MeReal(*t)[4] = (MeReal(*)[4])McdModelGetTransformPtr(s.model);
    t[0][0] = t[1][1] = 0, t[0][1] = 1, t[1][0] = -1;
    t[3][0] = ME_R(0.5), t[3][1] = ME_R(-0.3);
    McdModelUpdate(s.model);
    checkElements(&s, "moved and turned");
    const double before[3] = {-1.1, 0, 0};
    assert_false(isColour(before, blue)); /* nothing left where the hull was */
    /* Colour and deletion go to every element. */
    RGraphicSetColor(g, red);
    draw();
    double p[3];
    const double sphere[3] = {1.1, 0, 0};
    world(s.model, sphere, p);
    assert_true(isColour(p, red));
    RGraphicDelete(rc, g, 0);
    assert_null(rc->m_pRG_First);
    sceneDestroy(&s);
}

static void test_aggregate_geometry_as_one_graphic(void **state)
{
    Scene s;
    sceneCreate(&s);
    MeMatrix4 tm;
    identity(tm);
    tm[3][1] = ME_R(-0.5);
    RGraphic *g = RGraphicAggregateCreate(rc, s.outer, (float *)blue, tm);
    assert_non_null(g);
    assert_null(rc->m_pRG_First->m_pNext); /* one graphic: the elements' graphics went */
    RGraphic *hull = RGraphicConvexCreate(rc, s.hull, NULL, NULL), *box = RGraphicBoxCreate(rc, ME_R(0.4), 1, ME_R(0.4), NULL, NULL),
             *sphere = RGraphicSphereCreate(rc, ME_R(0.5), NULL, NULL);
    assert_int_equal(g->m_pObject->m_nNumVertices, hull->m_pObject->m_nNumVertices +
                                                       box->m_pObject->m_nNumVertices +
                                                       sphere->m_pObject->m_nNumVertices);
    RGraphicDelete(rc, hull, 0), RGraphicDelete(rc, box, 0), RGraphicDelete(rc, sphere, 0);
    /* Its vertices span the elements as placed: x in [-1.6, 1.6] (the sphere's sides to 2 %), y in
     * [-0.5, 1.4] (the turned box: 0.2 above 1.2). */
    double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
    for (int i = 0; i < g->m_pObject->m_nNumVertices; i++) {
        const RObjectVertex *v = &g->m_pVertices[i];
        double q[3] = {v->m_X, v->m_Y, v->m_Z};
        for (int k = 0; k < 3; k++)
            lo[k] = fmin(lo[k], q[k]), hi[k] = fmax(hi[k], q[k]);
    }
    assert_float_equal(lo[0], -1.6, 1e-5);
    assert_float_equal(hi[0], 1.6, 0.02);
    assert_float_equal(lo[1], -0.5, 1e-5);
    assert_float_equal(hi[1], 1.2 + 0.2, 1e-5);
    draw();
    const double centres[3][3] = {{-1.1, -0.5, 0}, {1.1, -0.5, 0}, {0, 0.7, 0}};
    for (int i = 0; i < 3; i++)
        assert_true(isColour(centres[i], blue));
    RGraphicDelete(rc, g, 0);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, g = RGraphicAggregateCreate(rc, s.sphere, (float *)blue, NULL));
    assert_null(g);
    sceneDestroy(&s);
}

static int noTriangles(McdModelPair *pair, McdUserTriangle *t, MeVector3 pos, MeReal radius, int max)
{
    (void)pair, (void)t, (void)pos, (void)radius, (void)max;
    return 0;
}

static void test_terrain_triangles(void **state)
{
    /* A triangle mesh of two triangles (a square of side 2 in z = 0, one tilted corner). */
    MeVector3 v[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, ME_R(0.5)}, {-1, 1, 0}};
    int idx[6] = {0, 1, 2, 0, 2, 3};
    McdGeometryID mesh = McdTriangleMeshCreate(fw, (const MeVector3 *)v, 4, idx, 2);
    assert_non_null(mesh);
    McdModelID m = McdModelCreate(mesh);
    RGraphic *g = RGraphicCreateFromModel(rc, m, (float *)red);
    assert_non_null(g);
    assert_int_equal(g->m_pObject->m_nNumVertices, 6);
    for (int t = 0; t < 2; t++) {
        MeVector3 a, b, c;
        int flags;
        assert_true(McdTriangleMeshGetTriangle(mesh, t, a, b, c, &flags));
        const MeReal *corner[3] = {a, b, c};
        for (int k = 0; k < 3; k++) {
            const RObjectVertex *p = &g->m_pVertices[3 * t + k];
            assert_float_equal(p->m_X, corner[k][0], 0);
            assert_float_equal(p->m_Y, corner[k][1], 0);
            assert_float_equal(p->m_Z, corner[k][2], 0);
            assert_true(p->m_NZ > 0.9f); /* counter-clockwise from +z: facing the camera */
        }
    }
    draw();
    const double inside[3] = {0.3, -0.3, 0.1}, outside[3] = {1.6, 0, 0};
    assert_true(isColour(inside, red));
    assert_false(isColour(outside, red));
    RGraphicDelete(rc, g, 0);
    McdModelDestroy(m);
    McdGeometryDestroy(mesh);

    /* A height field of 3 × 2 vertices: 2 cells, 4 triangles, heights where the field has them. */
    MeReal h[6] = {0, ME_R(0.2), ME_R(0.4), ME_R(0.1), ME_R(0.3), ME_R(0.5)};
    McdGeometryID field = McdRGHeightFieldCreate(fw, h, 3, 2, 1, 2, -1, -1);
    assert_non_null(field);
    g = RGraphicCreateFromGeometry(rc, field, (float *)red);
    assert_non_null(g);
    assert_int_equal(g->m_pObject->m_nNumVertices, 12);
    for (int i = 0; i < 12; i++) {
        const RObjectVertex *p = &g->m_pVertices[i];
        int ix = (int)lround(p->m_X + 1), iy = (int)lround((p->m_Y + 1) / 2);
        assert_float_equal(p->m_Z, h[iy * 3 + ix], 1e-6);
        assert_true(p->m_NZ > 0.9f);
    }
    RGraphicDelete(rc, g, 0);
    McdGeometryDestroy(field);

    /* A triangle list has no triangles of its own: refused with a message. */
    MeVector3 lo = {-1, -1, -1}, hi = {1, 1, 1};
    McdGeometryID list = McdTriangleListCreate(fw, lo, hi, 4, noTriangles);
    assert_non_null(list);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, g = RGraphicCreateFromGeometry(rc, list, (float *)red));
    assert_null(g);
    McdGeometryDestroy(list);
}

static void setVertex(RObjectVertex *v, double x, double y, double z)
{
    memset(v, 0, sizeof *v);
    v->m_X = (AcmeReal)x, v->m_Y = (AcmeReal)y, v->m_Z = (AcmeReal)z, v->m_NZ = 1;
}

/* RConvertTriStripToTriList, as 1.2 built hulls: a strip of 4 and one of 3 give 3 triangles, every
 * one counter-clockwise seen from +z like the strip's first; too many for the graphic is refused.
 * RGraphicScale: a unit cube scaled (2, 3, 4) spans those sizes, normals still unit and on the axes. */
static void test_strips_and_scaling(void **state)
{
    RObjectVertex strips[7];
    setVertex(&strips[0], 0, 0, 0), setVertex(&strips[1], 1, 0, 0), setVertex(&strips[2], 0, 1, 0);
    setVertex(&strips[3], 1, 1, 0);
    setVertex(&strips[4], 2, 0, 0), setVertex(&strips[5], 3, 0, 0), setVertex(&strips[6], 2, 1, 0);
    int size[2] = {4, 3}, start[2] = {0, 4};
    RGraphic *g = RGraphicCreateEmpty(9);
    RConvertTriStripToTriList(g, strips, size, start, 2);
    assert_int_equal(g->m_pObject->m_nNumVertices, 9);
    double area = 0;
    for (int t = 0; t < 3; t++) {
        const RObjectVertex *a = &g->m_pVertices[3 * t], *b = a + 1, *c = a + 2;
        double z = (b->m_X - a->m_X) * (c->m_Y - a->m_Y) - (b->m_Y - a->m_Y) * (c->m_X - a->m_X);
        assert_true(z > 0);
        area += z / 2;
    }
    assert_float_equal(area, 1.5, 1e-6); /* the quad and the triangle: nothing lost or doubled */
    RGraphic *small = RGraphicCreateEmpty(5);
    assert_reports(ME_ERR_ARGUMENT_RANGE, RConvertTriStripToTriList(small, strips, size, start, 2));
    assert_int_equal(small->m_pObject->m_nNumVertices, 5);
    RGraphicDestroy(small);
    RGraphicDestroy(g);

    g = RGraphicBoxCreate(rc, 1, 1, 1, red, NULL);
    RGraphicScale(g, 2, 3, 4);
    for (int i = 0; i < g->m_pObject->m_nNumVertices; i++) {
        const RObjectVertex *v = &g->m_pVertices[i];
        assert_float_equal(fabs(v->m_X), 1, 1e-6);
        assert_float_equal(fabs(v->m_Y), 1.5, 1e-6);
        assert_float_equal(fabs(v->m_Z), 2, 1e-6);
        assert_float_equal(fabs(v->m_NX) + fabs(v->m_NY) + fabs(v->m_NZ), 1, 1e-6);
    }
    assert_reports(ME_ERR_ARGUMENT_RANGE, RGraphicScale(g, 1, 0, 1));
    assert_float_equal(fabs(g->m_pVertices[0].m_Y), 1.5, 1e-6);
    RGraphicDelete(rc, g, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_convex_hull_polygons_and_flat_normals),
        cmocka_unit_test(test_aggregate_model_element_by_element),
        cmocka_unit_test(test_aggregate_geometry_as_one_graphic),
        cmocka_unit_test(test_terrain_triangles),
        cmocka_unit_test(test_strips_and_scaling),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
