/* convex_bullet.cpp -- the convex and terrain scenes (convex_scenes.h) in Bullet 3.24 (Debian's
 * libbullet, single precision), as a Bullet user writes them: btDiscreteDynamicsWorld with
 * btDbvtBroadphase, btDefaultCollisionConfiguration, btSequentialImpulseConstraintSolver (10
 * iterations, its default), deactivation disabled on every body (as Karma's auto-disable is off),
 * friction 0.6 for every body and the floor (pair: the smaller), restitution 0, default margins
 * (0.04 m: outside a btConvexHullShape's points, inside box extents). Shapes: btConvexHullShape from
 * the same points (Bullet keeps every point; with --poly also initializePolyhedralFeatures, which
 * makes hull-hull contacts whole clipped manifolds), btBvhTriangleMeshShape over a
 * btTriangleIndexVertexArray of the same vertices and indices, btHeightfieldTerrainShape (float
 * heights, up axis z, flipQuadEdges so that its cells split along the same diagonal as the mesh's and
 * Mcd's) moved by the centring Bullet applies; btBoxShape, btSphereShape, btCapsuleShapeZ.
 * The timed step is stepSimulation(h, 0). The pair test: the dispatcher's algorithm for each pair,
 * found once; each test clears its manifold and calls processCollision. */
#include <btBulletDynamicsCommon.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "bench_bullet.h"
#include "convex_scenes.h"

namespace {

bool gPoly = false;

btConvexHullShape *make_hull(const CvxHull &h)
{
    btConvexHullShape *s = new btConvexHullShape();
    for (int k = 0; k < h.count; k++)
        s->addPoint(btVector3(btScalar(h.p[k][0]), btScalar(h.p[k][1]), btScalar(h.p[k][2])), false);
    s->recalcLocalAabb();
    if (gPoly)
        s->initializePolyhedralFeatures();
    return s;
}

struct BulletWorld : BenchBulletWorld {
    const CvxScene *scene = nullptr;
    std::vector<btCollisionShape *> shapes;
    std::vector<btRigidBody *> bodies;
    btRigidBody *floor = nullptr;
    std::vector<float> heights;
    std::vector<float> vertices;
    btTriangleIndexVertexArray *mesh = nullptr;
};

void *bullet_create(const CvxScene *s)
{
    BulletWorld *w = new BulletWorld;
    w->scene = s;
    bench_bullet_open(w, btVector3(0, 0, btScalar(-s->gravity)), 10);

    btCollisionShape *floorShape;
    btTransform floorPose;
    floorPose.setIdentity();
    if (s->floor == CVX_GROUND) {
        floorShape = new btStaticPlaneShape(btVector3(0, 0, 1), 0);
    } else if (s->floor == CVX_FIELD) {
        int n = s->side;
        w->heights.resize((size_t)n * n);
        float lo = 1e30f, hi = -1e30f;
        for (int i = 0; i < n * n; i++) {
            w->heights[i] = float(s->heights[i]);
            lo = std::fmin(lo, w->heights[i]);
            hi = std::fmax(hi, w->heights[i]);
        }
        floorShape = new btHeightfieldTerrainShape(n, n, w->heights.data(), lo, hi, 2, true);
        /* Bullet centres the field on its box: put vertex (0, 0) back at (0, 0) */
        floorPose.setOrigin(btVector3(btScalar(0.5 * (n - 1)), btScalar(0.5 * (n - 1)), btScalar(0.5 * (lo + hi))));
    } else {
        int n = s->side;
        w->vertices.resize((size_t)3 * n * n);
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                w->vertices[3 * (j * n + i) + 0] = float(i);
                w->vertices[3 * (j * n + i) + 1] = float(j);
                w->vertices[3 * (j * n + i) + 2] = float(s->heights[j * n + i]);
            }
        w->mesh = new btTriangleIndexVertexArray(s->triangleCount, s->indices, 3 * (int)sizeof(int), n * n,
                                                 w->vertices.data(), 3 * (int)sizeof(float));
        floorShape = new btBvhTriangleMeshShape(w->mesh, true);
    }
    w->shapes.push_back(floorShape);
    {
        btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, floorShape);
        info.m_startWorldTransform = floorPose;
        info.m_friction = btScalar(s->friction);
        info.m_restitution = 0;
        w->floor = new btRigidBody(info);
        w->world->addRigidBody(w->floor);
    }
    for (int i = 0; i < s->bodyCount; i++) {
        const CvxBody &b = s->bodies[i];
        btCollisionShape *shape;
        switch (b.shape) {
        case CVX_BOX:
            shape = new btBoxShape(btVector3(btScalar(b.size[0]), btScalar(b.size[1]), btScalar(b.size[2])));
            break;
        case CVX_SPHERE:
            shape = new btSphereShape(btScalar(b.size[0]));
            break;
        case CVX_CAPSULE:
            shape = new btCapsuleShapeZ(btScalar(b.size[0]), btScalar(2 * b.size[1]));
            break;
        case CVX_HULL:
        default:
            shape = make_hull(s->hulls[b.hull]);
            break;
        }
        w->shapes.push_back(shape);
        btVector3 inertia(btScalar(b.inertia[0]), btScalar(b.inertia[1]), btScalar(b.inertia[2]));
        btRigidBody::btRigidBodyConstructionInfo info(btScalar(b.mass), nullptr, shape, inertia);
        btTransform pose;
        pose.setOrigin(btVector3(btScalar(b.pos[0]), btScalar(b.pos[1]), btScalar(b.pos[2])));
        pose.setRotation(btQuaternion(btScalar(b.quat[1]), btScalar(b.quat[2]), btScalar(b.quat[3]), btScalar(b.quat[0])));
        info.m_startWorldTransform = pose;
        info.m_friction = btScalar(s->friction);
        info.m_restitution = 0;
        btRigidBody *body = new btRigidBody(info);
        body->setActivationState(DISABLE_DEACTIVATION);
        w->world->addRigidBody(body);
        w->bodies.push_back(body);
    }
    return w;
}

void bullet_step(void *world)
{
    BulletWorld *w = static_cast<BulletWorld *>(world);
    w->world->stepSimulation(btScalar(w->scene->step), 0);
}

int bullet_contacts(void *world)
{
    return bench_bullet_contacts(static_cast<BulletWorld *>(world));
}

void bullet_read(void *world, double (*pos)[3], double (*quat)[4])
{
    BulletWorld *w = static_cast<BulletWorld *>(world);
    for (size_t i = 0; i < w->bodies.size(); i++) {
        const btTransform &t = w->bodies[i]->getWorldTransform();
        btQuaternion q = t.getRotation();
        for (int k = 0; k < 3; k++)
            pos[i][k] = t.getOrigin()[k];
        quat[i][0] = q.w(), quat[i][1] = q.x(), quat[i][2] = q.y(), quat[i][3] = q.z();
    }
}

void bullet_destroy(void *world)
{
    BulletWorld *w = static_cast<BulletWorld *>(world);
    for (btRigidBody *b : w->bodies) {
        w->world->removeRigidBody(b);
        delete b;
    }
    w->world->removeRigidBody(w->floor);
    delete w->floor;
    for (btCollisionShape *s : w->shapes)
        delete s;
    delete w->mesh;
    bench_bullet_close(w);
    delete w;
}

/* ---- the pair test ---- */
struct BulletPairs {
    const CvxPairSet *set = nullptr;
    btDefaultCollisionConfiguration *config = nullptr;
    btCollisionDispatcher *dispatcher = nullptr;
    std::vector<btConvexHullShape *> hulls;
    std::vector<btCollisionObject *> objects;
    std::vector<btCollisionAlgorithm *> algorithms;
    btDispatcherInfo info;
};

void *pairs_create(const CvxPairSet *p)
{
    BulletPairs *k = new BulletPairs;
    k->set = p;
    k->config = new btDefaultCollisionConfiguration();
    k->dispatcher = new btCollisionDispatcher(k->config);
    for (int i = 0; i < p->hullCount; i++)
        k->hulls.push_back(make_hull(p->hulls[i]));
    for (int i = 0; i < p->count; i++) {
        for (int s = 0; s < 2; s++) {
            btCollisionObject *o = new btCollisionObject();
            o->setCollisionShape(k->hulls[p->hull[i][s]]);
            btTransform t;
            t.setOrigin(btVector3(btScalar(p->pos[i][s][0]), btScalar(p->pos[i][s][1]), btScalar(p->pos[i][s][2])));
            t.setRotation(btQuaternion(btScalar(p->quat[i][s][1]), btScalar(p->quat[i][s][2]), btScalar(p->quat[i][s][3]),
                                       btScalar(p->quat[i][s][0])));
            o->setWorldTransform(t);
            k->objects.push_back(o);
        }
        btCollisionObject *a = k->objects[2 * i], *b = k->objects[2 * i + 1];
        btCollisionObjectWrapper wa(nullptr, a->getCollisionShape(), a, a->getWorldTransform(), -1, -1);
        btCollisionObjectWrapper wb(nullptr, b->getCollisionShape(), b, b->getWorldTransform(), -1, -1);
        k->algorithms.push_back(k->dispatcher->findAlgorithm(&wa, &wb, nullptr, BT_CONTACT_POINT_ALGORITHMS));
    }
    return k;
}

void pairs_run(void *pw, int rounds, long *contacts, long *touching)
{
    BulletPairs *k = static_cast<BulletPairs *>(pw);
    btManifoldArray manifolds;
    for (int round = 0; round < rounds; round++)
        for (int i = 0; i < k->set->count; i++) {
            btCollisionObject *a = k->objects[2 * i], *b = k->objects[2 * i + 1];
            btCollisionObjectWrapper wa(nullptr, a->getCollisionShape(), a, a->getWorldTransform(), -1, -1);
            btCollisionObjectWrapper wb(nullptr, b->getCollisionShape(), b, b->getWorldTransform(), -1, -1);
            btManifoldResult result(&wa, &wb);
            manifolds.resize(0);
            k->algorithms[i]->getAllContactManifolds(manifolds);
            for (int m = 0; m < manifolds.size(); m++)
                manifolds[m]->clearManifold();
            k->algorithms[i]->processCollision(&wa, &wb, k->info, &result);
            manifolds.resize(0);
            k->algorithms[i]->getAllContactManifolds(manifolds);
            int n = 0;
            for (int m = 0; m < manifolds.size(); m++)
                for (int c = 0; c < manifolds[m]->getNumContacts(); c++)
                    n += manifolds[m]->getContactPoint(c).getDistance() <= 0;
            *contacts += n;
            *touching += n > 0;
        }
}

void pairs_destroy(void *pw)
{
    BulletPairs *k = static_cast<BulletPairs *>(pw);
    for (btCollisionAlgorithm *a : k->algorithms) {
        a->~btCollisionAlgorithm();
        k->dispatcher->freeCollisionAlgorithm(a);
    }
    for (btCollisionObject *o : k->objects)
        delete o;
    for (btConvexHullShape *h : k->hulls)
        delete h;
    delete k->dispatcher;
    delete k->config;
    delete k;
}

} // namespace

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (std::strcmp(argv[i], "--poly") == 0)
            gPoly = true;
    static CvxEngine bullet = {"bullet", "btDiscreteDynamicsWorld, SI 10 iterations, no sleeping, default margins",
                               bullet_create, bullet_step, bullet_contacts, bullet_read, bullet_destroy,
                               pairs_create, pairs_run, pairs_destroy};
    if (gPoly)
        bullet.name = "bullet-poly";
    return CvxMain(argc, argv, &bullet);
}
