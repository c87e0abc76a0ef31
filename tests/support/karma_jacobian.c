/* karma_jacobian.c -- checks a constraint's Jacobian rows against finite differences of its
 * constraint functions: for each row, J·v must equal dφ/dt when the bodies move with velocities v.
 * Central differences: the bodies are moved by ±dt/2 along their current velocities (orientation by
 * the exact rotation), φ is read from the rows at each pose, and the pose is restored afterwards. */
#include <string.h>

#include "karma_test.h"
#include "karma_jacobian.h"
#include "mdt/constraint.h"
#include "mdt/world.h"

typedef struct Pose {
    MeVector3 com;
    MeVector4 q;
} Pose;

static void savePose(const MdtBodyData *b, Pose *p)
{
    MeVector3Set(p->com, b->comTM[3][0], b->comTM[3][1], b->comTM[3][2]);
    MeVector4Copy(p->q, b->q);
}

static void restorePose(MdtBodyData *b, const Pose *p)
{
    MeVector4Copy(b->q, p->q);
    MdtBodyUpdateTransforms(b, p->com);
}

static void movePose(MdtBodyData *b, const Pose *p, MeReal dt)
{
    MeVector3 com;
    for (int k = 0; k < 3; k++)
        com[k] = p->com[k] + dt * b->vel[k];
    MeVector4Copy(b->q, p->q);
    if (dt >= 0) {
        MeQuaternionFiniteRotation(b->q, b->velrot, dt);
    } else {
        MeVector3 back;
        MeVector3MultiplyScalar(back, b->velrot, -1);
        MeQuaternionFiniteRotation(b->q, back, -dt);
    }
    MdtBodyUpdateTransforms(b, com);
}

static int captureAt(MdtConstraintData *c, Pose poses[2], MeReal dt, MdtRow *rows)
{
    for (int i = 0; i < 2; i++)
        if (c->body[i])
            movePose(c->body[i], &poses[i], dt);
    int n = MdtConstraintCaptureRows(c, rows, KARMA_JACOBIAN_MAX_ROWS, ME_R(1.0) / 60);
    for (int i = 0; i < 2; i++)
        if (c->body[i])
            restorePose(c->body[i], &poses[i]);
    return n;
}

static MeReal dot3(const MeReal *a, const MeReal *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

double karma_jacobian_error(MdtConstraintID id, int *rowsChecked)
{
    MdtConstraintData *c = MdtConstraintFromID(id, __func__);
    assert_non_null(c);
    Pose poses[2];
    for (int i = 0; i < 2; i++)
        if (c->body[i])
            savePose(c->body[i], &poses[i]);
    static MdtRow now[KARMA_JACOBIAN_MAX_ROWS], plus[KARMA_JACOBIAN_MAX_ROWS], minus[KARMA_JACOBIAN_MAX_ROWS];
    const MeReal dt = ME_TOL(1e-6, 2e-3);
    int n = captureAt(c, poses, 0, now);
    int np = captureAt(c, poses, dt / 2, plus);
    int nm = captureAt(c, poses, -dt / 2, minus);
    assert_int_equal(np, n);
    assert_int_equal(nm, n);
    double worst = 0;
    for (int k = 0; k < n; k++) {
        const MdtRow *r = &now[k];
        MeReal jv = dot3(r->lin0, c->body[0]->vel) + dot3(r->ang0, c->body[0]->velrot);
        if (c->body[1])
            jv += dot3(r->lin1, c->body[1]->vel) + dot3(r->ang1, c->body[1]->velrot);
        double fd = ((double)plus[k].error - (double)minus[k].error) / (double)dt;
        double err = fabs(fd - (double)jv) / (1 + fabs((double)jv));
        if (err > worst)
            worst = err;
    }
    if (rowsChecked)
        *rowsChecked = n;
    return worst;
}

void karma_random_pose(MdtBodyID b, double spread)
{
    MeVector3 axis = {MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1), MeRealRandomInRange(-1, 1)};
    MeVector4 q;
    MeQuaternionMake(q, axis, MeRealRandomInRange(-3, 3));
    MdtBodySetQuaternion(b, q[0], q[1], q[2], q[3]);
    MdtBodySetPosition(b, (MeReal)spread * MeRealRandomInRange(-1, 1), (MeReal)spread * MeRealRandomInRange(-1, 1),
                       (MeReal)spread * MeRealRandomInRange(-1, 1));
    MdtBodySetLinearVelocity(b, MeRealRandomInRange(-2, 2), MeRealRandomInRange(-2, 2), MeRealRandomInRange(-2, 2));
    MdtBodySetAngularVelocity(b, MeRealRandomInRange(-3, 3), MeRealRandomInRange(-3, 3), MeRealRandomInRange(-3, 3));
}
