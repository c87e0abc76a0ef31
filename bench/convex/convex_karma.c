/* convex_karma.c -- the convex and terrain scenes (convex_scenes.h) in Karma, through MstUniverse as a
 * Karma user writes it: McdConvexMeshCreateHull (fatness 0) for the hulls, McdTriangleMeshCreate for the
 * mesh, McdRGHeightFieldCreate for the height field, a plane for the ground; Karma's defaults (Kea auto,
 * ε = 0.01 / massScale with massScale 1, γ = 0.2), auto-disable off so every step does the same work,
 * 2-D friction NormalForce μ 0.6, restitution 0. The pair test: McdIntersect on a McdModelPair made
 * once per pose (McdHello), up to 4 contacts, the models moved to their poses before each round. */
#define _POSIX_C_SOURCE 199309L
#include <karma/karma.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_karma.h"
#include "convex_scenes.h"

typedef struct KarmaWorld {
    const CvxScene *scene;
    MstUniverseID universe;
    MdtBodyID *bodies;
    MeMatrix4 floorTM;
    MeReal *heights;
} KarmaWorld;

static McdGeometryID make_geometry(McdFrameworkID fw, const CvxScene *s, const CvxBody *b)
{
    switch (b->shape) {
    case CVX_SPHERE:
        return McdSphereCreate(fw, (MeReal)b->size[0]);
    case CVX_CAPSULE:
        return McdSphylCreate(fw, (MeReal)b->size[0], (MeReal)(2 * b->size[1]));
    case CVX_BOX:
        return McdBoxCreate(fw, (MeReal)(2 * b->size[0]), (MeReal)(2 * b->size[1]), (MeReal)(2 * b->size[2]));
    case CVX_HULL:
    default: {
        const CvxHull *h = &s->hulls[b->hull];
        MeVector3 p[64];
        for (int k = 0; k < h->count; k++)
            for (int c = 0; c < 3; c++)
                p[k][c] = (MeReal)h->p[k][c];
        return McdConvexMeshCreateHull(fw, (const MeVector3 *)p, h->count, 0);
    }
    }
}

static void karma_destroy(void *world)
{
    KarmaWorld *w = world;
    if (w->universe)
        MstUniverseDestroy(w->universe);
    free(w->bodies);
    free(w->heights);
    free(w);
}

static void *karma_create(const CvxScene *s)
{
    KarmaWorld *w = calloc(1, sizeof *w);
    w->scene = s;
    w->bodies = calloc((size_t)s->bodyCount, sizeof *w->bodies);
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = s->bodyCount;
    sizes.collisionModelsMaxCount = s->bodyCount + 1;
    sizes.collisionPairsMaxCount = 16 * s->bodyCount;
    sizes.dynamicConstraintsMaxCount = 8 * 5 * s->bodyCount;
    sizes.lengthScale = 1;
    sizes.massScale = 1;
    w->universe = MstUniverseCreate(&sizes);
    if (!w->universe) {
        karma_destroy(w);
        return NULL;
    }
    MdtWorldID world = MstUniverseGetWorld(w->universe);
    MdtWorldSetGravity(world, 0, 0, (MeReal)-s->gravity);
    MdtWorldSetAutoDisable(world, MEFALSE);
    bench_karma_contact_defaults(w->universe, s->friction);

    McdFrameworkID fw = MstUniverseGetFramework(w->universe);
    McdGeometryID floor = NULL;
    MeMatrix4TMMakeIdentity(w->floorTM);
    if (s->floor == CVX_GROUND) {
        floor = McdPlaneCreate(fw);
    } else {
        int n = s->side;
        w->heights = malloc((size_t)n * n * sizeof *w->heights);
        for (int i = 0; i < n * n; i++)
            w->heights[i] = (MeReal)s->heights[i];
        if (s->floor == CVX_FIELD) {
            floor = McdRGHeightFieldCreate(fw, w->heights, n, n, 1, 1, 0, 0);
        } else {
            MeVector3 *v = malloc((size_t)n * n * sizeof *v);
            for (int j = 0; j < n; j++)
                for (int i = 0; i < n; i++)
                    MeVector3Set(v[j * n + i], (MeReal)i, (MeReal)j, w->heights[j * n + i]);
            floor = McdTriangleMeshCreate(fw, (const MeVector3 *)v, n * n, s->indices, s->triangleCount);
            free(v);
        }
    }
    if (!floor || !MstFixedModelCreate(w->universe, floor, w->floorTM)) {
        karma_destroy(w);
        return NULL;
    }
    for (int i = 0; i < s->bodyCount; i++) {
        const CvxBody *b = &s->bodies[i];
        McdModelID m = bench_karma_body(w->universe, make_geometry(fw, s, b), b->mass, b->inertia, b->pos, b->quat);
        if (!m) {
            karma_destroy(w);
            return NULL;
        }
        w->bodies[i] = McdModelGetBody(m);
    }
    return w;
}

static void karma_step(void *world)
{
    KarmaWorld *w = world;
    MstUniverseStep(w->universe, (MeReal)w->scene->step);
}

static int karma_contacts(void *world) { return bench_karma_contact_count(((KarmaWorld *)world)->universe); }

static void karma_read(void *world, double (*pos)[3], double (*quat)[4])
{
    KarmaWorld *w = world;
    bench_karma_read(w->bodies, w->scene->bodyCount, pos, quat);
}

/* ---- the pair test ---- */
typedef struct KarmaPairs {
    const CvxPairSet *set;
    McdFrameworkID fw;
    McdModelID (*models)[2];
    McdModelPairID *pairs;
} KarmaPairs;

static void *pairs_create(const CvxPairSet *p)
{
    KarmaPairs *k = calloc(1, sizeof *k);
    k->set = p;
    k->fw = McdInit(0, 2 * p->count + 8, 0, 1);
    McdPrimitivesRegisterInteractions(k->fw);
    McdGeometryID *hull = malloc((size_t)p->hullCount * sizeof *hull);
    for (int i = 0; i < p->hullCount; i++) {
        MeVector3 v[64];
        for (int j = 0; j < p->hulls[i].count; j++)
            for (int c = 0; c < 3; c++)
                v[j][c] = (MeReal)p->hulls[i].p[j][c];
        hull[i] = McdConvexMeshCreateHull(k->fw, (const MeVector3 *)v, p->hulls[i].count, 0);
    }
    k->models = malloc((size_t)p->count * sizeof *k->models);
    k->pairs = malloc((size_t)p->count * sizeof *k->pairs);
    for (int i = 0; i < p->count; i++) {
        for (int s = 0; s < 2; s++) {
            McdModelID m = McdModelCreate(hull[p->hull[i][s]]);
            MeMatrix4Ptr tm = McdModelGetTransformPtr(m);
            MeVector4 q = {(MeReal)p->quat[i][s][0], (MeReal)p->quat[i][s][1], (MeReal)p->quat[i][s][2],
                           (MeReal)p->quat[i][s][3]};
            MeMatrix4TMMakeIdentity(tm);
            MeMatrix4TMSetRotationFromQuaternion(tm, q);
            MeMatrix4TMSetPosition(tm, (MeReal)p->pos[i][s][0], (MeReal)p->pos[i][s][1], (MeReal)p->pos[i][s][2]);
            McdModelUpdate(m);
            k->models[i][s] = m;
        }
        k->pairs[i] = McdModelPairCreate(k->models[i][0], k->models[i][1]);
        McdHello(k->pairs[i]);
    }
    free(hull);
    return k;
}

static void pairs_run(void *pw, int rounds, long *contacts, long *touching)
{
    KarmaPairs *k = pw;
    McdContact c[4];
    McdIntersectResult r;
    memset(&r, 0, sizeof r);
    r.contacts = c;
    r.contactMaxCount = 4;
    for (int round = 0; round < rounds; round++)
        for (int i = 0; i < k->set->count; i++) {
            int t = McdIntersect(k->pairs[i], &r);
            *touching += t != 0;
            *contacts += r.contactCount;
        }
}

static void pairs_destroy(void *pw)
{
    KarmaPairs *k = pw;
    for (int i = 0; i < k->set->count; i++) {
        McdGoodbye(k->pairs[i]);
        McdModelPairDestroy(k->pairs[i]);
    }
    McdTerm(k->fw);
    free(k->models);
    free(k->pairs);
    free(k);
}

int main(int argc, char **argv)
{
    static const CvxEngine karma = {
        "karma", "MstUniverseStep; Kea auto; eps 0.01, gamma 0.2; auto-disable off; 2D friction mu 0.6; hull fatness 0",
        karma_create, karma_step, karma_contacts, karma_read, karma_destroy, pairs_create, pairs_run, pairs_destroy};
    return CvxMain(argc, argv, &karma);
}
