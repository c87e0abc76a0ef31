/* Every joint's Jacobian rows against finite differences of its constraint functions, at random poses,
 * random frames and random velocities (body 1 a body or the world): J·v must equal dφ/dt. */
#include "karma_test.h"
#include "karma_jacobian.h"

#include <karma/Mdt.h>

static MdtWorldID world;
static MdtBodyID a, b;

static int setup(void **state)
{
    (void)state;
    world = MdtWorldCreate(4, 8, 1, 1);
    a = MdtBodyCreate(world);
    b = MdtBodyCreate(world);
    MeRealRandomSeed(11);
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    MdtWorldDestroy(world);
    return 0;
}

static MeReal rnd(void) { return MeRealRandomInRange(-1, 1); }

/* Random attachment points and frames in both bodies. */
static void randomFrames(MdtConstraintID c)
{
    for (unsigned int i = 0; i < 2; i++) {
        MdtConstraintBodySetPositionRel(c, i, 0.5f * rnd(), 0.5f * rnd(), 0.5f * rnd());
        MdtConstraintBodySetAxesRel(c, i, rnd(), rnd(), rnd(), rnd(), rnd(), rnd());
    }
}

typedef void (*Configure)(MdtConstraintID c, int trial);

/* Worst finite-difference error over 200 random poses; asserts `minRows` ≤ rows ≤ `maxRows`, with
 * `maxRows` reached. */
static double check(const char *name, MdtConstraintID c, Configure configure, int minRows, int maxRows)
{
    double worst = 0;
    int fewest = 99, most = 0;
    for (int trial = 0; trial < 200; trial++) {
        karma_random_pose(a, 1);
        karma_random_pose(b, 1);
        MdtConstraintSetBodies(c, a, trial % 4 == 0 ? NULL : b);
        randomFrames(c);
        if (configure)
            configure(c, trial);
        int rows;
        worst = fmax(worst, karma_jacobian_error(c, &rows));
        fewest = rows < fewest ? rows : fewest;
        most = rows > most ? rows : most;
    }
    print_message("%-14s rows %d..%d, worst |J v - dphi/dt| / (1 + |J v|) = %.2e\n", name, fewest, most, worst);
    assert_true(fewest >= minRows);
    assert_int_equal(most, maxRows); /* the fullest case was reached */
    assert_true(worst < ME_TOL(1e-6, 2e-2));
    MdtConstraintDestroy(c);
    return worst;
}

static void universal(void **s)
{
    (void)s;
    check("Universal", MdtUniversalQuaConstraint(MdtUniversalCreate(world)), NULL, 4, 4);
}

static void linear1(void **s)
{
    (void)s;
    check("Linear1", MdtLinear1QuaConstraint(MdtLinear1Create(world)), NULL, 1, 1);
}

static void linear2(void **s)
{
    (void)s;
    check("Linear2", MdtLinear2QuaConstraint(MdtLinear2Create(world)), NULL, 2, 2);
}

static void fixedPathConfigure(MdtConstraintID c, int trial)
{
    (void)trial;
    MdtFixedPathSetVelocity(MdtConstraintDCastFixedPath(c), 1, rnd(), rnd(), rnd());
}

static void fixedpath(void **s)
{
    (void)s;
    check("FixedPath", MdtFixedPathQuaConstraint(MdtFixedPathCreate(world)), fixedPathConfigure, 3, 3);
}

static void angular3Configure(MdtConstraintID c, int trial)
{
    MdtAngular3ID j = MdtConstraintDCastAngular3(c);
    MdtAngular3EnableRotation(j, trial % 2 ? METRUE : MEFALSE);
    MdtAngular3SetStiffness(j, trial % 3 ? MEINFINITY : 50);
}

static void angular3(void **s)
{
    (void)s;
    check("Angular3", MdtAngular3QuaConstraint(MdtAngular3Create(world)), angular3Configure, 2, 3);
}

static void spring6Configure(MdtConstraintID c, int trial)
{
    MdtSpring6ID j = MdtConstraintDCastSpring6(c);
    for (unsigned int k = 0; k < 3; k++) {
        MdtSpring6SetLinearStiffness(j, k, (MeReal)(10 * (k + 1) * (trial % 2)));
        MdtSpring6SetLinearDamping(j, k, 1);
        MdtSpring6SetAngularStiffness(j, k, (MeReal)(5 * (k + 1)));
    }
}

static void spring6(void **s)
{
    (void)s;
    check("Spring6", MdtSpring6QuaConstraint(MdtSpring6Create(world)), spring6Configure, 6, 6);
}

static void rproConfigure(MdtConstraintID c, int trial)
{
    (void)trial;
    MdtRPROJointID j = MdtConstraintDCastRPROJoint(c);
    MeVector3 axis = {rnd(), rnd(), rnd()}, w = {rnd(), rnd(), rnd()};
    MeVector4 q;
    MeQuaternionMake(q, axis, 3 * rnd());
    MdtRPROJointSetRelativeQuaternion(j, q);
    MdtRPROJointSetAngularVelocity(j, w);
    MeQuaternionMake(q, w, 3 * rnd());
    MdtRPROJointSetAttachmentQuaternion(j, q[0], q[1], q[2], q[3], 0);
}

static void rpro(void **s)
{
    (void)s;
    check("RPROJoint", MdtRPROJointQuaConstraint(MdtRPROJointCreate(world)), rproConfigure, 6, 6);
}

static void coneConfigure(MdtConstraintID c, int trial)
{
    MdtConeLimitID j = MdtConstraintDCastConeLimit(c);
    MdtConeLimitSetConeHalfAngle(j, 0.2f);
    if (trial % 2) {
        MdtConeLimitSetStiffness(j, 100);
        MdtConeLimitSetDamping(j, 2);
    }
}

static void conelimit(void **s)
{
    (void)s;
    check("ConeLimit", MdtConeLimitQuaConstraint(MdtConeLimitCreate(world)), coneConfigure, 0, 1);
}

static void skeletalConfigure(MdtConstraintID c, int trial)
{
    MdtSkeletalID j = MdtConstraintDCastSkeletal(c);
    MdtSkeletalSetConePrimaryLimitAngle(j, 0.2f);
    MdtSkeletalSetConeSecondaryLimitAngle(j, 0.1f);
    MdtSkeletalSetTwistLimitAngle(j, 0.05f);
    MdtSkeletalSetConeLimitOption(j, (MdtSkeletalConeOption)(trial % 4));
    MdtSkeletalSetTwistLimitOption(j, (MdtSkeletalTwistOption)((trial / 4) % 3));
    MdtSkeletalEnableCombinedLimits(j, (trial / 12) % 2 ? METRUE : MEFALSE);
}

static void skeletal(void **s)
{
    (void)s;
    check("Skeletal", MdtSkeletalQuaConstraint(MdtSkeletalCreate(world)), skeletalConfigure, 3, 6);
}

/* A user row: body 0's attachment point at distance 0.7 from body 1's (the point on body 1 moves too). */
static int distanceRow(MdtUserConstraintID j, MdtUserConstraintRow *rows, int maxRows,
                       const MdtBclSolverParameters *params, void *data)
{
    (void)maxRows;
    (void)params;
    (void)data;
    MdtConstraintID c = MdtUserConstraintQuaConstraint(j);
    MeVector3 p0, p1, c0, c1 = {0, 0, 0}, n, r0, r1;
    MdtConstraintBodyGetPosition(c, 0, p0);
    MdtConstraintBodyGetPosition(c, 1, p1);
    MdtBodyGetCenterOfMassPosition(MdtConstraintGetBody(c, 0), c0);
    if (MdtConstraintGetBody(c, 1))
        MdtBodyGetCenterOfMassPosition(MdtConstraintGetBody(c, 1), c1);
    else
        MeVector3Copy(c1, p1);
    MeVector3Subtract(n, p0, p1);
    MeReal len = MeVector3Normalize(n);
    MeVector3Subtract(r0, p0, c0);
    MeVector3Subtract(r1, p1, c1);
    MeVector3Copy(rows[0].linear0, n);
    MeVector3Cross(rows[0].angular0, r0, n);
    MeVector3MultiplyScalar(rows[0].linear1, n, -1);
    MeVector3Cross(rows[0].angular1, n, r1);
    rows[0].error = len - 0.7f;
    return 1;
}

static void userConfigure(MdtConstraintID c, int trial)
{
    (void)trial;
    MdtUserConstraintSetAddConstraintFunction(MdtConstraintDCastUserConstraint(c), distanceRow);
}

static void user(void **s)
{
    (void)s;
    check("UserConstraint", MdtUserConstraintQuaConstraint(MdtUserConstraintCreate(world)), userConfigure, 1, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(universal), cmocka_unit_test(linear1),   cmocka_unit_test(linear2),
        cmocka_unit_test(fixedpath), cmocka_unit_test(angular3),  cmocka_unit_test(spring6),
        cmocka_unit_test(rpro),      cmocka_unit_test(conelimit), cmocka_unit_test(skeletal),
        cmocka_unit_test(user),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, setup, teardown);
}
