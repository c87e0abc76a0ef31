/* Limits under load: a pendulum (bob 1 kg, 1 m below its pivot, gravity 9.81) pushed sideways against
 * a ConeLimit or a Skeletal joint's cone comes to rest on the cone; a twisting torque stops at the
 * Skeletal twist limit; a soft cone settles where the spring balances the load. */
#include "karma_test.h"

#include <karma/Mdt.h>

#define G 9.81

typedef struct Rig {
    MdtWorldID w;
    MdtBodyID bob;
} Rig;

/* `drag` (N·s/m) lets a bob that slides along a limit come to rest. */
static Rig makeRig(double drag)
{
    Rig r;
    r.w = MdtWorldCreate(2, 4, 1, 1);
    MdtWorldSetGravity(r.w, 0, 0, (MeReal)-G);
    MdtWorldSetAutoDisable(r.w, MEFALSE);
    r.bob = MdtBodyCreate(r.w);
    MdtBodySetSphericalInertiaTensor(r.bob, 0.01f);
    MdtBodySetPosition(r.bob, 0, 0, -1);
    MdtBodySetLinearVelocityDamping(r.bob, (MeReal)drag);
    MdtBodyEnable(r.bob);
    return r;
}

/* Swing angle of the bob from the downward vertical, and its azimuth (0 = +x, π/2 = −y, as the
 * Skeletal frame below: orthogonal +x, third axis −y). */
static double swing(const Rig *r, double *azimuth)
{
    MeVector3 p;
    MdtBodyGetPosition(r->bob, p);
    if (azimuth)
        *azimuth = atan2(-p[1], p[0]);
    return atan2(sqrt(p[0] * p[0] + p[1] * p[1]), -p[2]);
}

/* The elliptical cone's half-angle at azimuth φ (a circle when the two angles are equal). */
static double ellipse(double ap, double as, double phi)
{
    return 1 / sqrt(pow(cos(phi) / ap, 2) + pow(sin(phi) / as, 2));
}

/* Half-angles of the cone the pushes below measure against. */
static double coneP = 3.2, coneS = 3.2;

/* Step `seconds` at 60 Hz pushing the bob with (fx, fy) N (and torque tz about z); returns the largest
 * excess of the swing over the cone (coneP, coneS) seen. */
static double push(Rig *r, double fx, double fy, double tz, double seconds)
{
    double worst = -1;
    for (int i = 0; i < (int)(seconds * 60); i++) {
        MdtBodyAddForce(r->bob, (MeReal)fx, (MeReal)fy, 0);
        MdtBodyAddTorque(r->bob, 0, 0, (MeReal)tz);
        MdtWorldStep(r->w, ME_R(1.0) / 60);
        double phi, theta = swing(r, &phi);
        worst = fmax(worst, theta - ellipse(coneP, coneS, phi));
    }
    return worst;
}

static MdtConeLimitID addCone(Rig *r, double halfAngle)
{
    MdtBSJointID bs = MdtBSJointCreate(r->w);
    MdtBSJointSetBodies(bs, r->bob, NULL);
    MdtBSJointSetPosition(bs, 0, 0, 0);
    MdtBSJointEnable(bs);
    MdtConeLimitID c = MdtConeLimitCreate(r->w);
    MdtConeLimitSetBodies(c, r->bob, NULL);
    MdtConeLimitSetAxis(c, 0, 0, -1);
    MdtConeLimitSetConeHalfAngle(c, (MeReal)halfAngle);
    MdtConeLimitEnable(c);
    return c;
}

static void cone_limit_holds_a_pushed_pendulum(void **s)
{
    (void)s;
    Rig r = makeRig(1);
    MdtConeLimitID c = addCone(&r, 0.4);
    coneP = coneS = 0.4;
    /* Pushed along x with 3 m g: free, it would rest at atan(3) = 1.25 rad. */
    double worst = push(&r, 3 * G, 0, 0, 3);
    double rest = swing(&r, NULL);
    print_message("ConeLimit 0.4 rad: at rest %.4f rad, largest excess %.4f rad, limit reports %.4f rad, rows %d\n",
                  rest, worst, MdtConeLimitGetAngle(c), MdtConeLimitGetRowCount(c));
    assert_near(rest, 0.4, 0.005);
    assert_true(worst < 0.02);
    assert_int_equal(MdtConeLimitGetRowCount(c), 1);
    /* The push turns round the vertical: the bob runs along the cone's rim. */
    double rim = -1;
    for (int i = 0; i < 240; i++) {
        double a = i * 2 * 3.14159265358979 / 240;
        rim = fmax(rim, push(&r, 3 * G * cos(a), 3 * G * sin(a), 0, 1.0 / 60));
    }
    print_message("ConeLimit 0.4 rad, push turning once round in 4 s: largest excess %.4f rad, now %.4f rad\n", rim,
                  swing(&r, NULL));
    assert_true(rim < 0.02);
    /* Released: it hangs inside the cone and the limit writes no row. */
    push(&r, 0, 0, 0, 3);
    print_message("released: swing %.4f rad, rows %d\n", swing(&r, NULL), MdtConeLimitGetRowCount(c));
    assert_int_equal(MdtConeLimitGetRowCount(c), 0);
    MdtWorldDestroy(r.w);
}

static void soft_cone_limit_balances_the_load(void **s)
{
    (void)s;
    const double alpha = 0.3, k = 20, F = 2 * G;
    /* No drag here: the step's implicit drag also scales the applied forces by 1 / (1 + h c / m), which
     * would move the balance (docs/step.md, "Drag is implicit"). */
    Rig r = makeRig(0);
    MdtConeLimitID c = addCone(&r, alpha);
    MdtConeLimitSetStiffness(c, (MeReal)k);
    MdtConeLimitSetDamping(c, 4);
    push(&r, F, 0, 0, 6);
    double early = swing(&r, NULL);
    push(&r, F, 0, 0, 6);
    double rest = swing(&r, NULL);
    /* Torques about the pivot: F L cos θ − m g L sin θ = k (θ − α); solve by bisection. */
    double lo = alpha, hi = 1.5;
    for (int i = 0; i < 60; i++) {
        double m = (lo + hi) / 2;
        if (F * cos(m) - G * sin(m) - k * (m - alpha) > 0)
            lo = m;
        else
            hi = m;
    }
    print_message("soft ConeLimit (k 20, d 4): at 6 s %.4f rad, at 12 s %.4f rad vs torque balance %.4f rad\n", early,
                  rest, lo);
    assert_near(rest, lo, 0.01);
    MdtWorldDestroy(r.w);
}

static MdtSkeletalID addSkeletal(Rig *r, double primary, double secondary, double twist)
{
    MdtSkeletalID j = MdtSkeletalCreate(r->w);
    MdtSkeletalSetBodies(j, r->bob, NULL);
    MdtSkeletalSetPosition(j, 0, 0, 0);
    MdtSkeletalSetAxes(j, 0, 0, -1, 1, 0, 0); /* bone and cone axis down; primary angle towards +x */
    MdtSkeletalSetConePrimaryLimitAngle(j, (MeReal)primary);
    MdtSkeletalSetConeSecondaryLimitAngle(j, (MeReal)secondary);
    MdtSkeletalSetTwistLimitAngle(j, (MeReal)twist);
    MdtSkeletalEnable(j);
    return j;
}

static void skeletal_cone_is_an_ellipse(void **s)
{
    (void)s;
    const double ap = 0.5, as = 0.25;
    const double dirs[3][2] = {{1, 0}, {0, -1}, {0.7071, -0.7071}};
    coneP = ap;
    coneS = as;
    for (int i = 0; i < 3; i++) {
        Rig r = makeRig(1);
        MdtSkeletalID j = addSkeletal(&r, ap, as, 3);
        double worst = push(&r, 3 * G * dirs[i][0], 3 * G * dirs[i][1], 0, 3);
        double phi, theta = swing(&r, &phi);
        /* On the ellipse (θ cos φ / α_p)² + (θ sin φ / α_s)² = 1, i.e. θ = θ_max(φ). */
        double thetaMax = ellipse(ap, as, phi);
        print_message("Skeletal cone (0.5, 0.25), push (%.2f, %.2f): rests at %.4f rad, azimuth %.3f; ellipse there "
                      "%.4f rad; largest excess %.4f; swing reported %.4f\n",
                      dirs[i][0], dirs[i][1], theta, phi, thetaMax, worst, MdtSkeletalGetSwingAngle(j));
        assert_near(theta, thetaMax, 0.003);
        assert_true(worst < 0.02);
        assert_near(MdtSkeletalGetSwingAngle(j), theta, 1e-3);
        MdtWorldDestroy(r.w);
    }
}

static void skeletal_twist_limit_holds(void **s)
{
    (void)s;
    Rig r = makeRig(1);
    MdtSkeletalID j = addSkeletal(&r, 0.5, 0.5, 0.3);
    coneP = coneS = 0.5;
    double worst = 0;
    for (int i = 0; i < 180; i++) {
        push(&r, 2 * G, 0, 0.5, 1.0 / 60); /* swung against the cone and twisted */
        worst = fmax(worst, fabs(MdtSkeletalGetTwistAngle(j)));
    }
    double twist = MdtSkeletalGetTwistAngle(j), theta = swing(&r, NULL);
    print_message("Skeletal twist limit 0.3 rad under 0.5 N m while swung to %.4f rad: twist %.4f rad, largest "
                  "%.4f rad, rows %d\n",
                  theta, twist, worst, MdtSkeletalGetRowCount(j));
    assert_near(fabs(twist), 0.3, 0.005); /* the torque is about +z, the bone points down: twist < 0 */
    assert_true(worst < 0.3 + 0.02);
    assert_near(theta, 0.5, 0.006);
    assert_int_equal(MdtSkeletalGetRowCount(j), 5);
    /* Zeroing the twist here makes the present twist 0; the torque then turns it 0.3 further. */
    MdtSkeletalZeroTwist(j);
    double zeroed = MdtSkeletalGetTwistAngle(j);
    push(&r, 2 * G, 0, 0.5, 3);
    print_message("after MdtSkeletalZeroTwist: twist %.2e rad; after 3 s more: %.4f rad\n", zeroed,
                  MdtSkeletalGetTwistAngle(j));
    assert_near(zeroed, 0, 1e-4);
    assert_near(fabs(MdtSkeletalGetTwistAngle(j)), 0.3, 0.005);
    /* Combined limits: one limit row at most (the more violated), so the other may drift while it is
     * left out: both still hold, more loosely. */
    MdtSkeletalEnableCombinedLimits(j, METRUE);
    MdtSkeletalZeroTwist(j);
    double worstCombined = 0;
    for (int i = 0; i < 180; i++) {
        push(&r, 2 * G, 0, 0.5, 1.0 / 60);
        worstCombined = fmax(worstCombined, fmax(fabs(MdtSkeletalGetTwistAngle(j)) - 0.3, swing(&r, NULL) - 0.5));
        assert_true(MdtSkeletalGetRowCount(j) <= 4);
    }
    print_message("combined limits: largest excess over a limit %.4f rad, rows %d\n", worstCombined,
                  MdtSkeletalGetRowCount(j));
    assert_true(worstCombined < 0.06);
    MdtWorldDestroy(r.w);
}

static void skeletal_slot_and_fixed_cones(void **s)
{
    (void)s;
    Rig r = makeRig(1);
    MdtSkeletalID j = addSkeletal(&r, 0.5, 0.25, 3);
    MdtSkeletalSetConeLimitOption(j, MdtSkeletalConeOptionSlot);
    push(&r, 3 * G, 3 * G, 0, 3);
    MeVector3 p;
    MdtBodyGetPosition(r.bob, p);
    print_message("Slot cone, push (1, 1): bob at (%.4f, %.4f, %.4f), swing %.4f rad (slot end 0.5)\n", p[0], p[1],
                  p[2], swing(&r, NULL));
    assert_near(p[1], 0, 2e-3);
    assert_near(swing(&r, NULL), 0.5, 0.006);
    /* Fixed: the bone is locked along the cone's axis (straight down), however it is pushed. */
    MdtSkeletalSetConeLimitOption(j, MdtSkeletalConeOptionFixed);
    push(&r, 0, 0, 0, 1);
    push(&r, -3 * G, 3 * G, 0, 2);
    print_message("Fixed cone pushed (-1, 1) for 2 s: swing %.4f rad, rows %d\n", swing(&r, NULL),
                  MdtSkeletalGetRowCount(j));
    assert_near(swing(&r, NULL), 0, 2e-3);
    assert_int_equal(MdtSkeletalGetRowCount(j), 5);
    MdtWorldDestroy(r.w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(cone_limit_holds_a_pushed_pendulum), cmocka_unit_test(soft_cone_limit_balances_the_load),
        cmocka_unit_test(skeletal_cone_is_an_ellipse),        cmocka_unit_test(skeletal_twist_limit_holds),
        cmocka_unit_test(skeletal_slot_and_fixed_cones),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
