/* The common constraint API of docs/karma12.md §5.3 that the joint tests do not reach: user data, world, sort
 * key, validity, enable/disable, iteration over a world's and a body's constraints, frames set in
 * world coordinates per body, moving world attachments (MdtConstraintSetWorldLinearVelocity /
 * AngularVelocity); and the parts of MdtLimit (§5.5) beyond stops and motors: the lock, the position
 * offset, the overshoot. */
#include "karma_test.h"

#include <karma/Mdt.h>

#include "karma_rotor.h"

#define PI 3.14159265358979323846
static const double G = 9.81, H = 1.0 / 60;

static void countCB(MdtConstraintID c, void *data)
{
    (void)c;
    ++*(int *)data;
}

static void common_accessors_and_iteration(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(4, 8, 1, 1);
    MdtWorldSetGravity(w, 0, 0, (MeReal)-G);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
    MdtBodySetPosition(a, 0, 0, -1);
    MdtBodySetPosition(b, 3, 0, -1);
    MdtBodyEnable(a);
    MdtBodyEnable(b);
    MdtBSJointID ja = MdtBSJointCreate(w);
    MdtHingeID jb = MdtHingeCreate(w);
    MdtSpringID ab = MdtSpringCreate(w);
    MdtConstraintID ca = MdtBSJointQuaConstraint(ja), cb = MdtHingeQuaConstraint(jb), cab = MdtSpringQuaConstraint(ab);
    MdtBSJointSetBodies(ja, a, NULL);
    MdtHingeSetBodies(jb, b, NULL);
    MdtSpringSetBodies(ab, a, b);

    /* user data, world, sort key, type checks */
    int tag = 7;
    assert_null(MdtConstraintGetUserData(ca));
    MdtConstraintSetUserData(ca, &tag);
    assert_ptr_equal(MdtConstraintGetUserData(ca), &tag);
    assert_ptr_equal(MdtConstraintGetWorld(cb), w);
    assert_int_equal(MdtConstraintGetSortKey(cb), 0);
    MdtConstraintSetSortKey(cb, 42);
    assert_int_equal(MdtConstraintGetSortKey(cb), 42);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtConstraintSetSortKey(cb, -1));
    assert_int_equal(MdtConstraintGetSortKey(cb), 42);
    assert_true(MdtConstraintDCastBSJoint(ca) == ja);
    assert_null(MdtConstraintDCastBSJoint(cb));
    assert_null(MdtConstraintDCastLinear1(cb));
    assert_null(MdtConstraintDCastLinear2(ca));
    assert_null(MdtConstraintDCastContact(ca));
    assert_null(MdtConstraintDCastContactGroup(ca));

    /* Frames per body in world coordinates, read back in world and body coordinates: body b sits at
     * (3, 0, −1), unrotated. */
    MdtConstraintBodySetPosition(cb, 0, 3, 0, 0);
    MdtConstraintBodySetPosition(cb, 1, 3, 0, 0);
    MdtConstraintBodySetAxes(cb, 0, 0, 1, 0, 0, 0, 1);
    MdtConstraintBodySetAxes(cb, 1, 0, 1, 0, 0, 0, 1);
    MeVector3 p, q, o;
    MdtConstraintBodyGetPositionRel(cb, 0, p);
    assert_near(p[0], 0, 1e-6);
    assert_near(p[2], 1, 1e-6);
    MdtConstraintGetPosition(cb, p);
    assert_near(p[0], 3, 1e-6);
    assert_near(p[2], 0, 1e-6);
    MdtConstraintBodyGetAxis(cb, 0, q);
    assert_near(q[1], 1, 1e-6);
    MdtConstraintGetAxes(cb, q, o);
    assert_near(q[1], 1, 1e-6);
    assert_near(o[2], 1, 1e-6);
    MdtConstraintBodyGetAxesRel(cb, 1, q, o);
    assert_near(q[1], 1, 1e-6);
    MdtBSJointSetPosition(ja, 0, 0, 0);

    /* Iteration: three constraints in the world, two on body a. */
    int n = 0;
    for (MdtConstraintID c = MdtConstraintGetFirst(w); c; c = MdtConstraintGetNext(c))
        n++;
    assert_int_equal(n, 3);
    n = 0;
    MdtWorldForAllConstraints(w, countCB, &n);
    assert_int_equal(n, 3);
    n = 0;
    MdtBodyForAllConstraints(a, countCB, &n);
    assert_int_equal(n, 2);

    /* Disabled constraints apply nothing: both bodies fall freely. Enabled, they hold. */
    assert_false(MdtConstraintIsEnabled(ca));
    MdtWorldStep(w, (MeReal)H);
    MeVector3 v, f;
    MdtBodyGetLinearVelocity(a, v);
    MdtConstraintGetForce(ca, 0, f);
    assert_near(v[2], -G * H, 1e-6);
    assert_near(f[2], 0, 0);
    MdtBodySetLinearVelocity(a, 0, 0, 0);
    MdtBodySetLinearVelocity(b, 0, 0, 0);
    MdtBodySetPosition(a, 0, 0, -1);
    MdtBodySetPosition(b, 3, 0, -1);
    MdtConstraintEnable(ca);
    MdtConstraintEnable(cb);
    assert_true(MdtConstraintIsEnabled(ca) && MdtConstraintIsEnabled(cb));
    for (int i = 0; i < 60; i++)
        MdtWorldStep(w, (MeReal)H);
    MdtBodyGetLinearVelocity(a, v);
    MdtConstraintGetForce(ca, 0, f);
    print_message("hanging on its ball joint: v %.1e m/s, joint force (%.1e, %.1e, %.5f) N (m g up)\n", v[2], f[0],
                  f[1], f[2]);
    assert_near(v[2], 0, 1e-4);
    assert_rel(f[2], G, 1e-3);
    MdtConstraintDisable(cb);
    assert_false(MdtConstraintIsEnabled(cb));

    /* Body-level bulk operations, destroy and validity. */
    MdtBodyDisableConstraints(a);
    assert_false(MdtConstraintIsEnabled(ca));
    MdtBodyDestroyConstraints(a);
    assert_false(MdtConstraintIsValid(ca));
    assert_false(MdtConstraintIsValid(cab));
    assert_true(MdtConstraintIsValid(cb));
    n = 0;
    MdtWorldForAllConstraints(w, countCB, &n);
    assert_int_equal(n, 1);
    assert_reports(ME_ERR_INVALID_HANDLE, MdtConstraintEnable(ca));
    assert_int_equal(MdtConstraintGetType(ca), -1);
    MdtWorldDestroy(w);
}

/* ---- moving world attachments ---- */
/* A 1 kg body held at its centre by a ball joint to the world whose anchor the application moves along
 * x at 1 m/s (zero gravity). Told the anchor's velocity, the joint keeps the body on it (error at rounding
 * level, velocity 1); only moved, it lags by the step's error correction, v h / γ. */
static double trackMovingAnchor(int tellVelocity, double *speed)
{
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetLinearVelocity(b, 1, 0, 0);
    MdtBodyEnable(b);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, b, NULL);
    MdtBSJointSetPosition(j, 0, 0, 0);
    MdtConstraintID c = MdtBSJointQuaConstraint(j);
    if (tellVelocity)
        MdtConstraintSetWorldLinearVelocity(c, 1, 0, 0);
    MdtBSJointEnable(j);
    double worst = 0;
    for (int i = 1; i <= 120; i++) {
        MdtWorldStep(w, (MeReal)H);
        MdtConstraintBodySetPosition(c, 1, (MeReal)(i * H), 0, 0); /* where the anchor is now */
        MeVector3 p;
        MdtBodyGetPosition(b, p);
        worst = fmax(worst, fabs(p[0] - i * H));
    }
    MeVector3 v, lv;
    MdtBodyGetLinearVelocity(b, v);
    *speed = v[0];
    MdtConstraintGetWorldLinearVelocity(c, lv);
    assert_true(lv[0] == (tellVelocity ? 1 : 0));
    MdtWorldDestroy(w);
    return worst;
}

/* A body held by an Angular3 joint to a world frame the application turns about z at 2 rad/s. */
static double trackTurningFrame(int tellVelocity, double *rate)
{
    const double omega = 2;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetAngularVelocity(b, 0, 0, (MeReal)omega);
    MdtBodyEnable(b);
    MdtAngular3ID j = MdtAngular3Create(w);
    MdtAngular3SetBodies(j, b, NULL);
    MdtConstraintID c = MdtAngular3QuaConstraint(j);
    MdtConstraintSetAxes(c, 1, 0, 0, 0, 1, 0);
    if (tellVelocity)
        MdtConstraintSetWorldAngularVelocity(c, 0, 0, (MeReal)omega);
    MdtAngular3Enable(j);
    double worst = 0;
    for (int i = 1; i <= 120; i++) {
        MdtWorldStep(w, (MeReal)H);
        double a = omega * i * H;
        MdtConstraintBodySetAxes(c, 1, (MeReal)cos(a), (MeReal)sin(a), 0, (MeReal)-sin(a), (MeReal)cos(a), 0);
        MeMatrix3 R;
        MdtBodyGetOrientation(b, R); /* row 0: the body's x axis in the world */
        double err = fabs(atan2(R[0][1], R[0][0]) - remainder(a, 2 * PI));
        worst = fmax(worst, fmin(err, 2 * PI - err));
    }
    MeVector3 om, av;
    MdtBodyGetAngularVelocity(b, om);
    *rate = om[2];
    MdtConstraintGetWorldAngularVelocity(c, av);
    assert_true(av[2] == (tellVelocity ? (MeReal)omega : 0));
    MdtWorldDestroy(w);
    return worst;
}

static void moving_world_attachments(void **state)
{
    (void)state;
    double speed, lagSpeed, rate, lagRate;
    double err = trackMovingAnchor(1, &speed), lag = trackMovingAnchor(0, &lagSpeed);
    const double gamma = 0.2; /* the world's default */
    print_message("anchor moving at 1 m/s: with its velocity the body follows within %.1e m at %.6f m/s; without, "
                  "it lags %.4f m (v h / gamma = %.4f)\n",
                  err, speed, lag, H / gamma);
    assert_true(err < ME_TOL(1e-9, 1e-5));
    assert_near(speed, 1, ME_TOL(1e-9, 1e-5));
    assert_rel(lag, H / gamma, 0.02);
    double aerr = trackTurningFrame(1, &rate), alag = trackTurningFrame(0, &lagRate);
    print_message("world frame turning at 2 rad/s: with its angular velocity the body follows within %.1e rad at "
                  "%.6f rad/s; without, it lags %.4f rad (w h / gamma = %.4f)\n",
                  aerr, rate, alag, 2 * H / gamma);
    assert_true(aerr < 1e-3);
    assert_near(rate, 2, 1e-3);
    assert_rel(alag, 2 * H / gamma, 0.02);
}

/* ---- limit lock, offset, overshoot (on the rotor of karma_rotor.h, inertia 0.5) ---- */
static void limit_lock_offset_and_overshoot(void **state)
{
    (void)state;
    /* A rigid lock at 0.5 rad pulls the rotor there and holds it against 2 N m. */
    KarmaRotor r = karma_rotor_make(0.5);
    MdtLimitSetLock(r.l, 0.5f, MEINFINITY);
    MdtLimitActivateLock(r.l, METRUE);
    assert_true(MdtLimitIsLocked(r.l));
    for (int i = 0; i < 120; i++) {
        MdtBodyAddTorque(r.b, 0, 0, 2);
        MdtWorldStep(r.w, (MeReal)H);
    }
    MeVector3 t;
    MdtHingeGetTorque(r.j, 0, t);
    print_message("lock at 0.5 rad under 2 N m: angle %.6f rad, rate %.1e, lock torque %.5f N m\n",
                  MdtLimitGetPosition(r.l), MdtLimitGetVelocity(r.l), t[2]);
    assert_near(MdtLimitGetPosition(r.l), 0.5, 1e-3);
    assert_near(MdtLimitGetVelocity(r.l), 0, 1e-3);
    assert_rel(t[2], -2, 1e-3);
    /* A lock of at most 1 N m gives way: the rotor turns at (2 − 1) / I. */
    MdtLimitSetLock(r.l, 0.5f, 1);
    double w0 = 0;
    for (int i = 0; i < 60; i++) {
        if (i == 30)
            w0 = MdtLimitGetVelocity(r.l);
        MdtBodyAddTorque(r.b, 0, 0, 2);
        MdtWorldStep(r.w, (MeReal)H);
    }
    double accel = (MdtLimitGetVelocity(r.l) - w0) / (30 * H);
    print_message("lock capped at 1 N m under 2 N m: acceleration %.5f rad/s^2 ((2 - 1) / 0.5 = 2)\n", accel);
    assert_rel(accel, 2, 1e-3);
    MdtWorldDestroy(r.w);

    /* The offset shifts the reported coordinate only; stops are in the reported coordinate. */
    r = karma_rotor_make(0.5);
    assert_false(MdtLimitPositionIsCalculated(r.l)); /* Karma's flag; the coordinate is tracked anyway */
    MdtLimitCalculatePosition(r.l, METRUE);
    assert_true(MdtLimitPositionIsCalculated(r.l));
    MdtLimitSetPosition(r.l, 1);
    assert_near(MdtLimitGetPosition(r.l), 1, 1e-6);
    MdtLimitActivateLimits(r.l, METRUE);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(r.l), -5);
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(r.l), 1.3f);
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(r.l), 0);
    MdtBodySetAngularVelocity(r.b, 0, 0, 1);
    for (int i = 0; i < 60; i++)
        MdtWorldStep(r.w, (MeReal)H);
    MeMatrix3 R;
    MdtBodyGetOrientation(r.b, R);
    double turned = atan2(R[0][1], R[0][0]);
    print_message("offset 1 rad, upper stop at 1.3: reported %.5f rad, body turned %.5f rad (0.3), overshoot %.1e\n",
                  MdtLimitGetPosition(r.l), turned, MdtLimitGetOvershoot(r.l));
    assert_near(MdtLimitGetPosition(r.l), 1.3, 1e-3);
    assert_near(turned, 0.3, 1e-3);
    assert_near(MdtLimitGetOvershoot(r.l), 0, 1e-3);
    /* A soft upper stop (k 20, d 5) pressed by 2 N m settles past the stop by T / k = 0.1 rad: the
     * overshoot reads it. */
    MdtSingleLimitSetStiffness(MdtLimitGetUpperLimit(r.l), 20);
    MdtSingleLimitSetDamping(MdtLimitGetUpperLimit(r.l), 5);
    for (int i = 0; i < 600; i++) {
        MdtBodyAddTorque(r.b, 0, 0, 2);
        MdtWorldStep(r.w, (MeReal)H);
    }
    print_message("soft stop at 1.3 (k 20) under 2 N m: reported %.5f rad, overshoot %.5f rad (T / k = 0.1)\n",
                  MdtLimitGetPosition(r.l), MdtLimitGetOvershoot(r.l));
    assert_near(MdtLimitGetOvershoot(r.l), 0.1, 1e-3);
    assert_near(MdtLimitGetPosition(r.l), 1.4, 1e-3);
    /* MdtLimitResetState clears the measured state, keeping the settings. */
    MdtLimitResetState(r.l);
    assert_true(MdtLimitIsActive(r.l));
    assert_near(MdtSingleLimitGetStop(MdtLimitGetUpperLimit(r.l)), 1.3, 1e-6);
    MdtWorldDestroy(r.w);
}

/* ---- Angular2 mode ---- */
/* An Angular3 joint to the world with rotation enabled about its primary axis z (Angular2): a spin about
 * z is free (kept, 2 rows), one about x is stopped; a torque about z turns the body at T / I. */
static void angular2_frees_the_primary_axis(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetSphericalInertiaTensor(b, 0.5f);
    MdtBodySetAngularVelocity(b, 2, 0, 3);
    MdtBodyEnable(b);
    MdtAngular3ID j = MdtAngular3Create(w);
    MdtAngular3SetBodies(j, b, NULL);
    MdtAngular3SetAxis(j, 0, 0, 1);
    MdtAngular3EnableRotation(j, METRUE);
    assert_true(MdtAngular3RotationIsEnabled(j));
    MdtAngular3Enable(j);
    for (int i = 0; i < 60; i++)
        MdtWorldStep(w, (MeReal)H);
    MeVector3 om;
    MdtBodyGetAngularVelocity(b, om);
    MeMatrix3 R;
    MdtBodyGetOrientation(b, R); /* row 2: the body's z axis, which must stay the world's */
    print_message("Angular2 about z: after 1 s spin (%.1e, %.1e, %.5f) rad/s (0, 0, 3), z axis tilt %.1e, rows %d\n",
                  om[0], om[1], om[2], sqrt(R[2][0] * R[2][0] + R[2][1] * R[2][1]), MdtAngular3GetRowCount(j));
    assert_int_equal(MdtAngular3GetRowCount(j), 2);
    assert_near(om[0], 0, 1e-4);
    assert_near(om[1], 0, 1e-4);
    assert_near(om[2], 3, ME_TOL(1e-9, 1e-5));
    assert_true(sqrt(R[2][0] * R[2][0] + R[2][1] * R[2][1]) < 1e-3);
    for (int i = 0; i < 60; i++) {
        MdtBodyAddTorque(b, 0, 0, 1);
        MdtWorldStep(w, (MeReal)H);
    }
    MdtBodyGetAngularVelocity(b, om);
    print_message("Angular2 under 1 N m about z for 1 s: spin %.5f rad/s (3 + T t / I = 5)\n", om[2]);
    assert_near(om[2], 5, ME_TOL(1e-9, 1e-4));
    MdtWorldDestroy(w);
}

/* ---- contact group destroy callback ---- */
typedef struct Destroyed {
    int calls;
    MdtContactGroupID last;
} Destroyed;

static void onGroupDestroyed(MdtContactGroupID g, void *data)
{
    Destroyed *d = (Destroyed *)data;
    d->calls++;
    d->last = g;
    assert_true(MdtConstraintIsValid(MdtContactGroupQuaConstraint(g))); /* still readable in the callback */
}

static void contact_group_destroy_callback(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 16, 1, 1);
    Destroyed seen = {0, NULL};
    MdtWorldSetContactGroupDestroyCallback(w, onGroupDestroyed, &seen);
    MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
    MdtContactGroupID g1 = MdtContactGroupCreate(w), g2 = MdtContactGroupCreate(w), g3 = MdtContactGroupCreate(w);
    MdtContactGroupSetBodies(g1, a, NULL);
    MdtContactGroupSetBodies(g2, a, b);
    MdtContactGroupSetBodies(g3, b, NULL);
    MdtContactGroupCreateContact(g2);
    MdtBSJointID j = MdtBSJointCreate(w);
    MdtBSJointSetBodies(j, a, b);
    /* By the application. */
    MdtContactGroupDestroy(g1);
    assert_int_equal(seen.calls, 1);
    assert_ptr_equal(seen.last, g1);
    /* With a body's contacts (not its joints). */
    MdtBodyDestroyContacts(a);
    assert_int_equal(seen.calls, 2);
    assert_ptr_equal(seen.last, g2);
    assert_true(MdtConstraintIsValid(MdtBSJointQuaConstraint(j)));
    /* With the body: its remaining group goes too. */
    MdtBodyDestroy(b);
    assert_int_equal(seen.calls, 3);
    assert_ptr_equal(seen.last, g3);
    print_message("contact group destroy callback: %d calls (destroy, body contacts, body)\n", seen.calls);
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(common_accessors_and_iteration),
        cmocka_unit_test(moving_world_attachments),
        cmocka_unit_test(limit_lock_offset_and_overshoot),
        cmocka_unit_test(angular2_frees_the_primary_axis),
        cmocka_unit_test(contact_group_destroy_callback),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
