/* Conservation in a free cluster (issue 17, b2smash): with no gravity, no ground and no damping,
 * contact impulses are internal (equal and opposite, at one point on both bodies), so the total linear
 * momentum and the angular momentum about a fixed point must be kept to rounding while a block of
 * touching boxes, asleep, is struck off-centre by a heavier cube with friction: no impulse may act on
 * one side only (a sleeping body treated as static, a per-body cap or clamp). Cubes have isotropic
 * inertia, so dropping the gyroscopic term (Karma's default) keeps L = Σ m x × v + I ω exactly, and the
 * update x⁺ = x + h v⁺ keeps Σ m x × v from step to step. */
#include "karma_test.h"

#include <karma/karma.h>
#include <math.h>

enum { NX = 4, NY = 4, NZ = 3, BLOCK = NX * NY * NZ, BODIES = BLOCK + 1 };

typedef struct Cluster {
    MstUniverseID universe;
    MdtBodyID body[BODIES]; /* body[0] the striker */
} Cluster;

static void cluster_create(Cluster *c)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = BODIES;
    sizes.collisionModelsMaxCount = BODIES;
    sizes.collisionPairsMaxCount = 20 * BODIES;
    sizes.dynamicConstraintsMaxCount = 80 * BODIES; /* 26 neighbours in a block: never full */
    c->universe = MstUniverseCreate(&sizes);
    assert_non_null(c->universe);
    MdtWorldSetGravity(MstUniverseGetWorld(c->universe), 0, 0, 0);
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(c->universe), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.6));
    McdFrameworkID fw = MstUniverseGetFramework(c->universe);
    const MeReal d = ME_R(0.4);
    McdGeometryID small = McdBoxCreate(fw, d, d, d), big = McdBoxCreate(fw, 2 * d, 2 * d, 2 * d);
    /* The striker, 4 times the density, 4 m from the block along z, off-centre in x and y. */
    McdModelID m = MstModelAndBodyCreate(c->universe, big, 4);
    c->body[0] = McdModelGetBody(m);
    MdtBodySetPosition(c->body[0], ME_R(0.23), ME_R(-0.31), -2 * d - ME_R(4.0));
    MdtBodySetLinearVelocity(c->body[0], ME_R(0.2), 0, ME_R(2.5));
    MdtBodySetAngularVelocity(c->body[0], 0, ME_R(0.5), ME_R(0.3));
    int n = 1;
    for (int i = 0; i < NX; i++)
        for (int j = 0; j < NY; j++)
            for (int k = 0; k < NZ; k++) {
                m = MstModelAndBodyCreate(c->universe, small, 1);
                c->body[n] = McdModelGetBody(m);
                MdtBodySetPosition(c->body[n++], d * ((MeReal)i - ME_R(1.5)), d * ((MeReal)j - ME_R(1.5)),
                                   d * (MeReal)k);
            }
}

/* Total linear momentum P and angular momentum L about the origin, summed in double. */
static void momenta(const Cluster *c, double P[3], double L[3])
{
    for (int k = 0; k < 3; k++)
        P[k] = L[k] = 0;
    for (int i = 0; i < BODIES; i++) {
        MeVector3 x, v, w;
        MeMatrix3 I;
        MdtBodyGetPosition(c->body[i], x);
        MdtBodyGetLinearVelocity(c->body[i], v);
        MdtBodyGetAngularVelocity(c->body[i], w);
        MdtBodyGetInertiaTensor(c->body[i], I);
        double m = MdtBodyGetMass(c->body[i]);
        double mv[3] = {m * v[0], m * v[1], m * v[2]};
        for (int k = 0; k < 3; k++) {
            P[k] += mv[k];
            L[k] += (double)I[k][k] * w[k]; /* isotropic: I is a multiple of the identity */
        }
        L[0] += x[1] * mv[2] - x[2] * mv[1];
        L[1] += x[2] * mv[0] - x[0] * mv[2];
        L[2] += x[0] * mv[1] - x[1] * mv[0];
    }
}

static double norm(const double a[3]) { return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

static double gap(const double a[3], const double b[3])
{
    double d[3] = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    return norm(d);
}

static void struck_sleeping_block_keeps_momentum(void **state)
{
    (void)state;
    Cluster c;
    cluster_create(&c);
    MeMatrix3 I;
    MdtBodyGetInertiaTensor(c.body[1], I);
    assert_near(I[0][1], 0, 1e-12);
    assert_rel(I[0][0], I[2][2], 1e-6); /* the angular momentum below relies on cubes */
    double P0[3], L0[3], P[3], L[3];
    momenta(&c, P0, L0);
    /* Scale of L: the momentum's arm (the cluster's size, 2 m) times |P|. */
    const double pScale = norm(P0), lScale = 2 * pScale;
    const double tol = ME_TOL(1e-12, 2e-6);
    const MeReal h = ME_R(1.0) / 60;
    int asleepBeforeImpact = 0, awakeAfter = 0;
    double firstContactSpeed = -1;
    for (int n = 0; n < 240; n++) {
        int asleep = 0;
        for (int i = 1; i < BODIES; i++)
            asleep += !MdtBodyIsEnabled(c.body[i]);
        MstUniverseStep(c.universe, h);
        momenta(&c, P, L);
        assert_true(gap(P, P0) <= tol * pScale);
        assert_true(gap(L, L0) <= tol * lScale);
        MeVector3 v;
        MdtBodyGetLinearVelocity(c.body[0], v);
        if (firstContactSpeed < 0 && v[2] < ME_R(2.49)) {
            firstContactSpeed = v[2];
            asleepBeforeImpact = asleep;
        }
    }
    for (int i = 1; i < BODIES; i++)
        awakeAfter += MdtBodyIsEnabled(c.body[i]);
    /* The block slept when it was struck, and the blow reached it: momentum went into it. */
    assert_true(firstContactSpeed > 0);
    assert_true(asleepBeforeImpact > BLOCK / 2);
    assert_true(awakeAfter > 0);
    double blockMomentum = 0;
    for (int i = 1; i < BODIES; i++) {
        MeVector3 v;
        MdtBodyGetLinearVelocity(c.body[i], v);
        blockMomentum += MdtBodyGetMass(c.body[i]) * v[2];
    }
    assert_true(blockMomentum > 0.2 * P0[2]);
    MstUniverseDestroy(c.universe);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(struck_sleeping_block_keeps_momentum),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
