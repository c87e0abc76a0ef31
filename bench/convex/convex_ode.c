/* convex_ode.c -- the convex and terrain scenes (convex_scenes.h) in ODE 0.16 (Debian's libode, double
 * precision), as bench/peers/ode_peer.c's quickstep20 variant: dWorldQuickStep with 20 iterations,
 * ERP 0.2, CFM 1e-5, a hash space, up to 4 contacts per pair, dContactApprox1 with mu 0.6, auto-disable
 * off. Shapes: dConvex made of the hull's faces (the hull is built by Karma's McdConvexMeshCreateHull
 * from the same points: ODE takes planes and polygons, not points), dTriMesh over the same vertices and
 * indices, dHeightfield of the same heights (ODE's field is y-up and centred: it is turned by +90
 * degrees about x, local z onto world -y, so its rows are stored in reverse), dBox, dSphere, dCapsule.
 * Its cells then split on the same diagonal as the mesh's (vertical rays hit the measure's surface).
 * The mesh is preprocessed for face angles, which ODE's convex-trimesh collider (libccd) requires.
 * The pair test: dCollide on the two dConvex geoms of each pose, up to 4 contacts. */
#include <karma/karma.h>
#include <ode/ode.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_ode.h"
#include "convex_scenes.h"

/* A hull's faces for dCreateConvex (the arrays must outlive the geom). */
typedef struct OdeHull {
    dReal *planes;
    dReal *points;
    unsigned *polygons;
    unsigned planeCount, pointCount;
} OdeHull;

static McdFrameworkID hullFramework;

static int make_ode_hull(const CvxHull *h, OdeHull *o)
{
    if (!hullFramework) {
        hullFramework = McdInit(0, 16, 0, 1);
        McdPrimitivesRegisterInteractions(hullFramework);
    }
    MeVector3 p[64];
    for (int k = 0; k < h->count; k++)
        for (int c = 0; c < 3; c++)
            p[k][c] = (MeReal)h->p[k][c];
    McdConvexMeshID g = McdConvexMeshCreateHull(hullFramework, (const MeVector3 *)p, h->count, 0);
    if (!g)
        return 0;
    int nv = McdConvexMeshGetVertexCount(g), nf = McdConvexMeshGetPolygonCount(g), total = 0;
    MeVector3 *v = malloc((size_t)nv * sizeof *v);
    for (int i = 0; i < nv; i++)
        McdConvexMeshGetVertex(g, i, v[i]);
    for (int f = 0; f < nf; f++)
        total += 1 + McdConvexMeshGetPolygonVertexCount(g, f);
    o->pointCount = (unsigned)nv;
    o->planeCount = (unsigned)nf;
    o->points = malloc((size_t)3 * nv * sizeof *o->points);
    o->planes = malloc((size_t)4 * nf * sizeof *o->planes);
    o->polygons = malloc((size_t)total * sizeof *o->polygons);
    for (int i = 0; i < nv; i++)
        for (int c = 0; c < 3; c++)
            o->points[3 * i + c] = v[i][c];
    unsigned *poly = o->polygons;
    for (int f = 0; f < nf; f++) {
        int n = McdConvexMeshGetPolygonVertexCount(g, f);
        MeVector3 normal, first;
        McdConvexMeshGetPolygonNormal(g, f, normal);
        McdConvexMeshGetPolygonVertex(g, f, 0, first);
        for (int c = 0; c < 3; c++)
            o->planes[4 * f + c] = normal[c];
        o->planes[4 * f + 3] = MeVector3Dot(normal, first);
        *poly++ = (unsigned)n;
        for (int k = 0; k < n; k++) {
            const MeReal *q = McdConvexMeshGetPolygonVertexPtr(g, f, k);
            int found = 0;
            for (int i = 0; i < nv; i++)
                if (v[i][0] == q[0] && v[i][1] == q[1] && v[i][2] == q[2]) {
                    found = i;
                    break;
                }
            *poly++ = (unsigned)found;
        }
    }
    free(v);
    McdGeometryDestroy(g);
    return 1;
}

static void free_ode_hull(OdeHull *o)
{
    free(o->planes);
    free(o->points);
    free(o->polygons);
}

typedef struct OdeWorld {
    const CvxScene *scene;
    BenchOde ode;
    dBodyID *bodies;
    OdeHull *hulls;
    dTriMeshDataID mesh;
    dHeightfieldDataID field;
    dReal *vertices;
    dTriIndex *indices;
    double *heights;
} OdeWorld;

static void near_callback(void *data, dGeomID g1, dGeomID g2)
{
    OdeWorld *w = data;
    if (!dGeomGetBody(g1) && !dGeomGetBody(g2))
        return;
    bench_ode_collide(&w->ode, g1, g2);
}

static void ode_destroy(void *world)
{
    OdeWorld *w = world;
    bench_ode_close(&w->ode);
    if (w->mesh)
        dGeomTriMeshDataDestroy(w->mesh);
    if (w->field)
        dGeomHeightfieldDataDestroy(w->field);
    for (int i = 0; i < w->scene->bodyCount; i++)
        free_ode_hull(&w->hulls[i]);
    free(w->hulls);
    free(w->bodies);
    free(w->vertices);
    free(w->indices);
    free(w->heights);
    free(w);
}

static void *ode_create(const CvxScene *s)
{
    OdeWorld *w = calloc(1, sizeof *w);
    w->scene = s;
    bench_ode_open(&w->ode, 0, 0, -s->gravity, 20, s->friction);
    w->bodies = calloc((size_t)s->bodyCount, sizeof *w->bodies);
    w->hulls = calloc((size_t)s->bodyCount, sizeof *w->hulls);
    int n = s->side;
    if (s->floor == CVX_GROUND) {
        dCreatePlane(w->ode.space, 0, 0, 1, 0);
    } else if (s->floor == CVX_MESH) {
        w->vertices = malloc((size_t)3 * n * n * sizeof *w->vertices);
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                dReal *v = w->vertices + 3 * (j * n + i);
                v[0] = i, v[1] = j, v[2] = s->heights[j * n + i];
            }
        w->indices = malloc((size_t)3 * s->triangleCount * sizeof *w->indices);
        for (int k = 0; k < 3 * s->triangleCount; k++)
            w->indices[k] = (dTriIndex)s->indices[k];
        w->mesh = dGeomTriMeshDataCreate();
        dGeomTriMeshDataBuildDouble(w->mesh, w->vertices, 3 * sizeof(dReal), n * n, w->indices,
                                    3 * s->triangleCount, 3 * sizeof(dTriIndex));
        /* ODE's convex-trimesh collider (libccd) asks for the face angles */
        dGeomTriMeshDataPreprocess2(w->mesh, 1U << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES, NULL);
        dCreateTriMesh(w->ode.space, w->mesh, NULL, NULL, NULL);
    } else {
        /* ODE's sample (x, row) is at local (x - c, h, row - c), c = (n - 1) / 2; turned +90 degrees
         * about x and moved by (c, c, 0), local z goes to world y = c - (row - c): row = n - 1 - j */
        w->heights = malloc((size_t)n * n * sizeof *w->heights);
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++)
                w->heights[(n - 1 - j) * n + i] = s->heights[j * n + i];
        w->field = dGeomHeightfieldDataCreate();
        dGeomHeightfieldDataBuildDouble(w->field, w->heights, 0, n - 1, n - 1, n, n, 1, 0, 1, 0);
        dGeomID g = dCreateHeightfield(w->ode.space, w->field, 1);
        dMatrix3 R;
        dRFromAxisAndAngle(R, 1, 0, 0, 1.57079632679489661923);
        dGeomSetRotation(g, R);
        dGeomSetPosition(g, 0.5 * (n - 1), 0.5 * (n - 1), 0);
    }
    for (int i = 0; i < s->bodyCount; i++) {
        const CvxBody *b = &s->bodies[i];
        dGeomID g;
        switch (b->shape) {
        case CVX_BOX:
            g = dCreateBox(w->ode.space, 2 * b->size[0], 2 * b->size[1], 2 * b->size[2]);
            break;
        case CVX_SPHERE:
            g = dCreateSphere(w->ode.space, b->size[0]);
            break;
        case CVX_CAPSULE:
            g = dCreateCapsule(w->ode.space, b->size[0], 2 * b->size[1]);
            break;
        case CVX_HULL:
        default:
            if (!make_ode_hull(&s->hulls[b->hull], &w->hulls[i])) {
                ode_destroy(w);
                return NULL;
            }
            g = dCreateConvex(w->ode.space, w->hulls[i].planes, w->hulls[i].planeCount, w->hulls[i].points,
                              w->hulls[i].pointCount, w->hulls[i].polygons);
            break;
        }
        dBodyID body = dBodyCreate(w->ode.world);
        dMass m;
        dMassSetParameters(&m, b->mass, 0, 0, 0, b->inertia[0], b->inertia[1], b->inertia[2], 0, 0, 0);
        dBodySetMass(body, &m);
        dBodySetPosition(body, b->pos[0], b->pos[1], b->pos[2]);
        dQuaternion q = {b->quat[0], b->quat[1], b->quat[2], b->quat[3]};
        dBodySetQuaternion(body, q);
        dGeomSetBody(g, body);
        w->bodies[i] = body;
    }
    return w;
}

static void ode_step(void *world)
{
    OdeWorld *w = world;
    w->ode.contacts = 0;
    dSpaceCollide(w->ode.space, w, near_callback);
    dWorldQuickStep(w->ode.world, w->scene->step);
    dJointGroupEmpty(w->ode.contactGroup);
}

static int ode_contacts(void *world) { return ((OdeWorld *)world)->ode.contacts; }

static void ode_read(void *world, double (*pos)[3], double (*quat)[4])
{
    OdeWorld *w = world;
    for (int i = 0; i < w->scene->bodyCount; i++) {
        const dReal *p = dBodyGetPosition(w->bodies[i]), *q = dBodyGetQuaternion(w->bodies[i]);
        for (int k = 0; k < 3; k++)
            pos[i][k] = p[k];
        for (int k = 0; k < 4; k++)
            quat[i][k] = q[k];
    }
}

/* ---- the pair test ---- */
typedef struct OdePairs {
    const CvxPairSet *set;
    OdeHull *hulls;
    dGeomID (*geoms)[2];
} OdePairs;

static void *pairs_create(const CvxPairSet *p)
{
    OdePairs *k = calloc(1, sizeof *k);
    k->set = p;
    k->hulls = calloc((size_t)p->hullCount, sizeof *k->hulls);
    for (int i = 0; i < p->hullCount; i++)
        make_ode_hull(&p->hulls[i], &k->hulls[i]);
    k->geoms = malloc((size_t)p->count * sizeof *k->geoms);
    for (int i = 0; i < p->count; i++)
        for (int s = 0; s < 2; s++) {
            OdeHull *h = &k->hulls[p->hull[i][s]];
            dGeomID g = dCreateConvex(0, h->planes, h->planeCount, h->points, h->pointCount, h->polygons);
            dGeomSetPosition(g, p->pos[i][s][0], p->pos[i][s][1], p->pos[i][s][2]);
            dQuaternion q = {p->quat[i][s][0], p->quat[i][s][1], p->quat[i][s][2], p->quat[i][s][3]};
            dGeomSetQuaternion(g, q);
            k->geoms[i][s] = g;
        }
    return k;
}

static void pairs_run(void *pw, int rounds, long *contacts, long *touching)
{
    OdePairs *k = pw;
    dContactGeom c[BENCH_ODE_MAX_CONTACTS];
    for (int round = 0; round < rounds; round++)
        for (int i = 0; i < k->set->count; i++) {
            int n = dCollide(k->geoms[i][0], k->geoms[i][1], BENCH_ODE_MAX_CONTACTS, c, sizeof c[0]);
            *contacts += n;
            *touching += n > 0;
        }
}

static void pairs_destroy(void *pw)
{
    OdePairs *k = pw;
    for (int i = 0; i < k->set->count; i++)
        for (int s = 0; s < 2; s++)
            dGeomDestroy(k->geoms[i][s]);
    for (int i = 0; i < k->set->hullCount; i++)
        free_ode_hull(&k->hulls[i]);
    free(k->hulls);
    free(k->geoms);
    free(k);
}

int main(int argc, char **argv)
{
    static const CvxEngine ode = {"ode", "dWorldQuickStep 20 iterations, ERP 0.2, CFM 1e-5, dContactApprox1 mu 0.6",
                                  ode_create, ode_step, ode_contacts, ode_read, ode_destroy,
                                  pairs_create, pairs_run, pairs_destroy};
    dInitODE2(0);
    int r = CvxMain(argc, argv, &ode);
    dCloseODE();
    if (hullFramework)
        McdTerm(hullFramework);
    return r;
}
