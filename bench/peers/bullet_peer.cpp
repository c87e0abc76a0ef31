/* bullet_peer.cpp -- the benchmark scenes in Bullet 3.24 (Debian's libbullet, single precision).
 *
 * btDiscreteDynamicsWorld with Bullet's defaults: btDbvtBroadphase, btDefaultCollisionConfiguration,
 * btSequentialImpulseConstraintSolver with 10 iterations (its default), warm starting, split impulse
 * and the default collision margins (0.04 m, inside box extents). Mass properties are the scene's
 * (BenchBodyInertia: uniform solids). Every body and the ground has
 * friction 0.6 and restitution 0; the pair's friction is the smaller of the two (Bullet multiplies
 * them by default, which would make it 0.36). Joints: btPoint2PointConstraint for ball joints,
 * btHingeConstraint built from frames for hinges, with Bullet's default limit softness; jointed
 * bodies do not collide with each other.
 *
 * Two variants:
 *   si10          Bullet's defaults, sleeping (deactivation) included: bodies at rest for 2 s sleep
 *   si10-nosleep  the same with deactivation disabled on every body, so the solver holds every stack
 *                 for the whole run (closest to ODE, which does not auto-disable by default)
 *
 * Motors (b2spinner, b2tumbler): btHingeConstraint::enableAngularMotor with the scene's speed and its
 * torque bound times the step (Bullet bounds the motor's impulse); initial velocities (b2smash):
 * setLinearVelocity.
 *
 * The timed step is one stepSimulation(h, 0): exactly one internal step of h, collision included. */
#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "bench_bullet.h"
#include "bench_harness.h"

namespace {

struct BulletWorld : BenchBulletWorld {
    const BenchScene *scene = nullptr;
    std::vector<btCollisionShape *> shapes;
    std::vector<btRigidBody *> bodies; /* all scene bodies, fixed ones included, then the ground */
    std::vector<btTypedConstraint *> joints;
};

btVector3 to_bt(const double v[3]) { return btVector3(btScalar(v[0]), btScalar(v[1]), btScalar(v[2])); }

btTransform body_transform(const BenchBody &b)
{
    btQuaternion q(btScalar(b.quat[1]), btScalar(b.quat[2]), btScalar(b.quat[3]), btScalar(b.quat[0]));
    return btTransform(q, to_bt(b.pos));
}

/* mass 0: static. The inertia is the scene's (uniform solids), not Bullet's own estimate. */
btRigidBody *add_body(BulletWorld *w, btCollisionShape *shape, double mass, const btVector3 &inertia,
                      const btTransform &pose, double friction, bool sleep)
{
    btRigidBody::btRigidBodyConstructionInfo info(btScalar(mass), nullptr, shape, inertia);
    info.m_startWorldTransform = pose;
    info.m_friction = btScalar(friction);
    info.m_restitution = 0;
    btRigidBody *body = new btRigidBody(info);
    if (!sleep && mass > 0)
        body->setActivationState(DISABLE_DEACTIVATION);
    w->world->addRigidBody(body);
    w->shapes.push_back(shape);
    w->bodies.push_back(body);
    return body;
}

/* A hinge frame in a body: origin at the anchor, z along the axis; both frames share one world
 * basis, so the hinge angle is zero at the initial pose. */
btTransform hinge_frame(const btTransform &body, const btVector3 &anchor, const btMatrix3x3 &worldBasis)
{
    btTransform inv = body.inverse();
    return btTransform(inv.getBasis() * worldBasis, inv * anchor);
}

void bullet_destroy(void *world)
{
    BulletWorld *w = static_cast<BulletWorld *>(world);
    if (!w)
        return;
    for (btTypedConstraint *j : w->joints) {
        w->world->removeConstraint(j);
        delete j;
    }
    for (btRigidBody *b : w->bodies) {
        w->world->removeRigidBody(b);
        delete b;
    }
    for (btCollisionShape *s : w->shapes)
        delete s;
    bench_bullet_close(w);
    delete w;
}

void *bullet_create(const BenchScene *scene, bool sleep)
{
    BulletWorld *w = new BulletWorld;
    w->scene = scene;
    bench_bullet_open(w, to_bt(scene->gravity), 10); /* the pair's friction: the smaller (all are 0.6) */
    for (int i = 0; i < scene->bodyCount; i++) {
        const BenchBody &b = scene->bodies[i];
        btCollisionShape *shape;
        switch (b.shape) {
        case BENCH_SPHERE:
            shape = new btSphereShape(btScalar(b.size[0]));
            break;
        case BENCH_CAPSULE: /* along local z, as the scene's (btCapsuleShape's axis is y) */
            shape = new btCapsuleShapeZ(btScalar(b.size[0]), btScalar(2 * b.size[1]));
            break;
        case BENCH_BOX:
        default:
            shape = new btBoxShape(to_bt(b.size));
            break;
        }
        double inertia[3] = {0, 0, 0};
        if (!b.fixed)
            BenchBodyInertia(&b, inertia);
        btRigidBody *body = add_body(w, shape, b.fixed ? 0.0 : b.mass, to_bt(inertia), body_transform(b),
                                     scene->friction, sleep);
        if (!b.fixed)
            body->setLinearVelocity(to_bt(b.vel));
    }
    if (scene->hasGround) { /* the scenes are y-up: the plane y = 0 */
        btTransform identity;
        identity.setIdentity();
        add_body(w, new btStaticPlaneShape(btVector3(0, 1, 0), 0), 0.0, btVector3(0, 0, 0), identity,
                 scene->friction, sleep);
    }
    for (int k = 0; k < scene->jointCount; k++) {
        const BenchJoint &bj = scene->joints[k];
        btRigidBody *a = w->bodies[size_t(bj.body[0])];
        btRigidBody *b = bj.body[1] >= 0 ? w->bodies[size_t(bj.body[1])] : nullptr;
        btVector3 anchor = to_bt(bj.anchor);
        btTypedConstraint *c;
        if (bj.type == BENCH_BALL) {
            btVector3 pa = a->getCenterOfMassTransform().inverse() * anchor;
            c = b ? new btPoint2PointConstraint(*a, *b, pa, b->getCenterOfMassTransform().inverse() * anchor)
                  : new btPoint2PointConstraint(*a, pa);
        } else {
            btVector3 axis = to_bt(bj.axis).normalized();
            btVector3 p = std::fabs(axis.x()) < 0.9 ? btVector3(1, 0, 0) : btVector3(0, 1, 0);
            p = (p - axis * axis.dot(p)).normalized();
            btVector3 q = axis.cross(p);
            btMatrix3x3 basis(p.x(), q.x(), axis.x(), p.y(), q.y(), axis.y(), p.z(), q.z(), axis.z());
            btTransform fa = hinge_frame(a->getCenterOfMassTransform(), anchor, basis);
            btHingeConstraint *h;
            if (b)
                h = new btHingeConstraint(*a, *b, fa, hinge_frame(b->getCenterOfMassTransform(), anchor, basis));
            else
                h = new btHingeConstraint(*a, fa);
            /* Bullet's hinge angle is that of A relative to B (measured here): the opposite of the
             * scene's, so the limits swap and change sign. */
            if (bj.limited)
                h->setLimit(btScalar(-bj.hi), btScalar(-bj.lo));
            /* the motor drives A relative to B, the scene's sense; its bound is an impulse per step */
            if (bj.motor)
                h->enableAngularMotor(true, btScalar(bj.motorSpeed), btScalar(bj.motorTorque * scene->step));
            c = h;
        }
        w->world->addConstraint(c, true);
        w->joints.push_back(c);
    }
    return w;
}

void *bullet_create_sleep(const BenchScene *scene) { return bullet_create(scene, true); }
void *bullet_create_nosleep(const BenchScene *scene) { return bullet_create(scene, false); }

int bullet_step(void *world, const char **)
{
    BulletWorld *w = static_cast<BulletWorld *>(world);
    w->world->stepSimulation(btScalar(w->scene->step), 0);
    return 0;
}

int bullet_contacts(void *world)
{
    return bench_bullet_contacts(static_cast<BulletWorld *>(world));
}

void bullet_read(void *world, double (*pos)[3], double (*quat)[4])
{
    BulletWorld *w = static_cast<BulletWorld *>(world);
    for (int i = 0; i < w->scene->bodyCount; i++) {
        const btTransform &t = w->bodies[size_t(i)]->getCenterOfMassTransform();
        btQuaternion q = t.getRotation();
        for (int k = 0; k < 3; k++)
            pos[i][k] = double(t.getOrigin()[k]);
        quat[i][0] = double(q.getW());
        quat[i][1] = double(q.getX());
        quat[i][2] = double(q.getY());
        quat[i][3] = double(q.getZ());
    }
}

} // namespace

int main(int argc, char **argv)
{
    static const BenchEngine engines[] = {
        {"bullet", "si10", "sequential impulse, 10 iterations, defaults (sleeping on), friction min(0.6, 0.6)",
         bullet_create_sleep, bullet_step, bullet_contacts, bullet_read, bullet_destroy, nullptr},
        {"bullet", "si10-nosleep", "as si10 with deactivation disabled", bullet_create_nosleep, bullet_step,
         bullet_contacts, bullet_read, bullet_destroy, nullptr},
    };
    return BenchMain(argc, argv, engines, int(sizeof engines / sizeof engines[0]));
}
