/* bench_bullet.h -- a Bullet world as every Bullet bench driver sets it up (bench/peers' and
 * bench/convex's): btDiscreteDynamicsWorld over btDbvtBroadphase, btDefaultCollisionConfiguration and
 * btSequentialImpulseConstraintSolver, the scene's gravity and solver iterations, and a pair's
 * friction the smaller of its two bodies' (Bullet multiplies them by default). Header only: the
 * drivers are single C++ files. */
#ifndef BENCH_BULLET_H
#define BENCH_BULLET_H

#include <btBulletDynamicsCommon.h>

#include <cmath>

struct BenchBulletWorld {
    btDefaultCollisionConfiguration *config = nullptr;
    btCollisionDispatcher *dispatcher = nullptr;
    btDbvtBroadphase *broadphase = nullptr;
    btSequentialImpulseConstraintSolver *solver = nullptr;
    btDiscreteDynamicsWorld *world = nullptr;
};

/** The pair's friction: the smaller coefficient. */
inline btScalar bench_bullet_min_friction(const btCollisionObject *a, const btCollisionObject *b)
{
    return std::fmin(a->getFriction(), b->getFriction());
}

/** Create the world with gravity (m/s²) and the solver's iteration count; installs the smaller-
 *  friction rule (a global of Bullet's). */
inline void bench_bullet_open(BenchBulletWorld *w, const btVector3 &gravity, int iterations)
{
    w->config = new btDefaultCollisionConfiguration();
    w->dispatcher = new btCollisionDispatcher(w->config);
    w->broadphase = new btDbvtBroadphase();
    w->solver = new btSequentialImpulseConstraintSolver();
    w->world = new btDiscreteDynamicsWorld(w->dispatcher, w->broadphase, w->solver, w->config);
    w->world->setGravity(gravity);
    w->world->getSolverInfo().m_numIterations = iterations;
    gCalculateCombinedFrictionCallback = bench_bullet_min_friction;
}

/** Contact points in the dispatcher's manifolds (the last step's contacts). */
inline int bench_bullet_contacts(const BenchBulletWorld *w)
{
    int n = 0;
    for (int i = 0; i < w->dispatcher->getNumManifolds(); i++)
        n += w->dispatcher->getManifoldByIndexInternal(i)->getNumContacts();
    return n;
}

/** Delete the world and its parts; the bodies, shapes and constraints must be removed first. */
inline void bench_bullet_close(BenchBulletWorld *w)
{
    delete w->world;
    delete w->solver;
    delete w->broadphase;
    delete w->dispatcher;
    delete w->config;
    *w = BenchBulletWorld();
}

#endif /* BENCH_BULLET_H */
