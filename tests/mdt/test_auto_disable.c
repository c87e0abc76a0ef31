/* Auto-disable of whole partitions: a resting stack goes to sleep as one partition once every body is
 * at rest and past the alive window; a partition with one moving body stays awake; a new constraint
 * from an enabled body wakes the sleeping partition it reaches (the partitioner enables it). */
#include "karma_test.h"
#include "karma_contacts.h"

#include <karma/Mdt.h>

#include <math.h>

static const MeVector3 half = {0.5f, 0.5f, 0.5f}, up = {0, 0, 1};
static int enabledCalls, disabledCalls;
static void onEnable(MdtBodyID b, void *d)
{
    (void)b;
    (void)d;
    enabledCalls++;
}
static void onDisable(MdtBodyID b, void *d)
{
    (void)b;
    (void)d;
    disabledCalls++;
}

typedef struct Stack {
    MdtWorldID world;
    MdtBodyID box[2];
    MdtContactGroupID group[2];
    MdtContactParams params;
} Stack;

static void build(Stack *s)
{
    s->world = MdtWorldCreate(8, 16, 1, 1);
    MdtWorldSetGravity(s->world, 0, 0, -9.81f);
    MdtWorldSetBodyEnableCallback(s->world, onEnable, NULL);
    MdtWorldSetBodyDisableCallback(s->world, onDisable, NULL);
    karma_contact_params_friction(&s->params, 0.6f);
    for (int i = 0; i < 2; i++) {
        s->box[i] = MdtBodyCreate(s->world);
        MdtBodySetPosition(s->box[i], 0, 0, 0.5f + (MeReal)i);
        MdtBodyEnable(s->box[i]);
        s->group[i] = MdtContactGroupCreate(s->world);
        MdtContactGroupSetBodies(s->group[i], s->box[i], i ? s->box[0] : NULL);
        MdtContactGroupEnable(s->group[i]);
    }
}

static void step(Stack *s)
{
    karma_box_on_plane(s->group[0], s->box[0], half, up, 0, &s->params);
    karma_box_on_box(s->group[1], s->box[1], s->box[0], half, &s->params);
    MdtWorldStep(s->world, ME_R(1.0) / 60);
}

static void resting_stack_sleeps_and_a_new_constraint_wakes_it(void **state)
{
    (void)state;
    Stack s;
    enabledCalls = disabledCalls = 0;
    build(&s);
    int steps = 0;
    while ((MdtBodyIsEnabled(s.box[0]) || MdtBodyIsEnabled(s.box[1])) && steps < 600) {
        step(&s);
        steps++;
        /* One partition: the boxes sleep together or not at all. */
        assert_int_equal(MdtBodyIsEnabled(s.box[0]), MdtBodyIsEnabled(s.box[1]));
    }
    double t = steps / 60.0;
    print_message("two-box stack at rest: disabled together after %d steps (%.3f s; alive window %.2f s)\n", steps, t,
                  (double)MdtWorldGetAutoDisableAliveTime(s.world));
    assert_true(t > MdtWorldGetAutoDisableAliveTime(s.world));
    assert_true(t < 1.0);
    assert_int_equal(disabledCalls, 2);
    /* Asleep, its contact group still enabled: nothing is simulated, nothing moves. */
    MeVector3 p0, p;
    MdtBodyGetPosition(s.box[1], p0);
    for (int i = 0; i < 30; i++)
        step(&s);
    MdtBodyGetPosition(s.box[1], p);
    assert_memory_equal(p, p0, sizeof p);
    MdtWorldCounters c;
    MdtWorldGetCounters(s.world, &c);
    assert_int_equal(c.partitions, 0);

    /* A falling ball hooked to the top box by a ball joint: the partitioner reaches the top box through
     * the joint and the bottom box through the contacts, and enables both. */
    MdtBodyID ball = MdtBodyCreate(s.world);
    MdtBodySetPosition(ball, 1, 0, 2);
    MdtBodyEnable(ball);
    MdtBSJointID hook = MdtBSJointCreate(s.world);
    MdtBSJointSetBodies(hook, ball, s.box[1]);
    MdtBSJointSetPosition(hook, 0.5f, 0, 1.5f);
    MdtBSJointEnable(hook);
    int before = enabledCalls;
    step(&s);
    assert_true(MdtBodyIsEnabled(s.box[0]));
    assert_true(MdtBodyIsEnabled(s.box[1]));
    assert_int_equal(enabledCalls - before, 2);
    assert_int_equal(MdtBodyGetPartition(s.box[0]), MdtBodyGetPartition(ball));
    /* The ball pulls on the stack, which keeps it awake while it swings. */
    for (int i = 0; i < 60; i++)
        step(&s);
    assert_true(MdtBodyIsEnabled(s.box[1]));
    MdtBodyGetPosition(ball, p);
    print_message("woken by a new joint: %d bodies enabled by the partitioner; ball now at z = %.3f m\n",
                  enabledCalls - before, p[2]);
    MdtWorldDestroy(s.world);
}

/* A body of the partition that keeps moving keeps the whole partition awake. */
static void one_moving_body_keeps_its_partition_awake(void **state)
{
    (void)state;
    Stack s;
    build(&s);
    MdtBodySetAngularVelocity(s.box[1], 0, 0, 1); /* the top box spins on the bottom one, frictionless */
    MdtContactParamsSetType(&s.params, MdtContactTypeFrictionZero);
    for (int i = 0; i < 120; i++)
        step(&s);
    MeVector3 w;
    MdtBodyGetAngularVelocity(s.box[1], w);
    print_message("top box spinning at %.3f rad/s after 2 s: both boxes %s\n", w[2],
                  MdtBodyIsEnabled(s.box[0]) ? "awake" : "asleep");
    assert_true(MdtBodyIsEnabled(s.box[0]));
    assert_true(MdtBodyIsEnabled(s.box[1]));
    assert_near(w[2], 1, 1e-3);
    MdtWorldDestroy(s.world);
}

/* ---- the averaging time (MdtWorldSetAutoDisableAveragingTime, src/mdt/rest_window.c) ------------- */

/* A lone body in a world without gravity, pushed by `force` (N, along x, 1 kg) from velocity v0 (m/s);
 * the step at which it was disabled (0 if never) within `steps` steps of 1/60 s. `alternate` flips the
 * force's sign every step (a body shaken in place: its velocity alternates, its mean does not grow). */
static int stepsToSleep(MeReal averagingTime, MeReal v0, MeReal force, MeBool alternate, int steps)
{
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtWorldSetAutoDisableAveragingTime(w, averagingTime);
    MdtWorldSetAutoDisableAccelerationThreshold(w, ME_R(0.01)); /* |a| < 0.1 m/s² */
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetMass(b, 1);
    MdtBodyEnable(b);
    MdtBodySetLinearVelocity(b, v0, 0, 0);
    int slept = 0;
    for (int i = 1; i <= steps && !slept; i++) {
        MdtBodyAddForce(b, alternate && (i % 2) ? -force : force, 0, 0);
        MdtWorldStep(w, ME_R(1.0) / 60);
        if (!MdtBodyIsEnabled(b))
            slept = i;
    }
    MdtWorldDestroy(w);
    return slept;
}

/* Steady motion is judged as Karma 1.2 judges it, averaged or not: a body coasting at a squared speed
 * 10 % over the threshold (0.02) never sleeps, 10 % under it sleeps once the window is full; a body
 * under a constant acceleration 10 % over the threshold (squared 0.011 against 0.01) stays awake while
 * its speed is still under that threshold (1.2 s), 10 % under it sleeps. */
static void steady_motion_is_judged_as_in_karma_12(void **state)
{
    (void)state;
    const MeReal over = MeSqrt(ME_R(0.022)), under = MeSqrt(ME_R(0.018));
    const MeReal push = MeSqrt(ME_R(0.011)), pushUnder = MeSqrt(ME_R(0.009));
    const MeReal times[2] = {MDTWORLD_DEFAULT_AVERAGING_TIME, 0};
    for (int k = 0; k < 2; k++) {
        const MeReal t = times[k];
        const int coastOver = stepsToSleep(t, over, 0, MEFALSE, 180);
        const int coastUnder = stepsToSleep(t, under, 0, MEFALSE, 180);
        const int pushedOver = stepsToSleep(t, 0, push, MEFALSE, 72);
        const int pushedUnder = stepsToSleep(t, 0, pushUnder, MEFALSE, 72);
        print_message("averaging %.1f s: coasting over / under the speed threshold: asleep at step %d / %d; "
                      "accelerating over / under: %d / %d (0: awake)\n",
                      (double)t, coastOver, coastUnder, pushedOver, pushedUnder);
        assert_int_equal(coastOver, 0);
        assert_int_equal(pushedOver, 0);
        /* the alive window (12 steps), and with averaging the window's 8 blocks of 4 steps */
        const int latest = t > 0 ? 34 : 14;
        assert_true(coastUnder > 12 && coastUnder <= latest);
        assert_true(pushedUnder > 12 && pushedUnder <= latest);
    }
}

/* A body shaken in place (its velocity alternates between 0 and 0.1 m/s: one step's acceleration is
 * 6 m/s², its mean is nothing) never sleeps under 1.2's last-step test and sleeps when averaged: the
 * heap's case in miniature. */
static void shaking_in_place_sleeps_only_when_averaged(void **state)
{
    (void)state;
    const MeReal kick = ME_R(0.1) * 60; /* N on 1 kg: 0.1 m/s in one step */
    const int averaged = stepsToSleep(MDTWORLD_DEFAULT_AVERAGING_TIME, ME_R(0.05), kick, METRUE, 180);
    const int lastStep = stepsToSleep(0, ME_R(0.05), kick, METRUE, 180);
    print_message("shaken in place: asleep at step %d averaged, %d judged by the last step (0: awake)\n", averaged,
                  lastStep);
    assert_true(averaged > 0 && averaged <= 40);
    assert_int_equal(lastStep, 0);
}

/* The setting: default, read back, rejected when negative or not finite (message, no change); the
 * body's window restarts when its velocity is set, so a body set moving is judged on its new motion. */
static void averaging_time_setting(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    assert_true(MdtWorldGetAutoDisableAveragingTime(w) == MDTWORLD_DEFAULT_AVERAGING_TIME);
    MdtWorldSetAutoDisableAveragingTime(w, ME_R(0.25));
    assert_true(MdtWorldGetAutoDisableAveragingTime(w) == ME_R(0.25));
    karma_capture_messages();
    assert_reports(ME_ERR_NEGATIVE_VALUE, MdtWorldSetAutoDisableAveragingTime(w, -1));
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtWorldSetAutoDisableAveragingTime(w, (MeReal)NAN));
    assert_true(MdtWorldGetAutoDisableAveragingTime(w) == ME_R(0.25));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtWorldGetAutoDisableAveragingTime(NULL));
    MdtWorldSetAutoDisableAveragingTime(w, MDTWORLD_DEFAULT_AVERAGING_TIME);
    /* At rest for 2 s, then set moving at 0.5 m/s just before the step that would have judged it. */
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodyEnable(b);
    MdtWorldSetAutoDisable(w, MEFALSE);
    for (int i = 0; i < 120; i++)
        MdtWorldStep(w, ME_R(1.0) / 60);
    MdtWorldSetAutoDisable(w, METRUE);
    MdtBodySetLinearVelocity(b, ME_R(0.5), 0, 0);
    MdtWorldStep(w, ME_R(1.0) / 60);
    assert_true(MdtBodyIsEnabled(b)); /* its quiet past does not put it to sleep moving */
    MdtWorldDestroy(w);
}

/* No rest window is kept while auto-disable is off (the step skips it), so switching auto-disable on
 * starts every body's window afresh: a body that rested for 2 s with it off is judged on what follows,
 * and sleeps once a whole window (8 blocks of 4 steps) has passed, not at the first step. */
static void switching_auto_disable_on_starts_the_windows_afresh(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodyEnable(b);
    MdtWorldSetAutoDisable(w, MEFALSE);
    for (int i = 0; i < 120; i++)
        MdtWorldStep(w, ME_R(1.0) / 60);
    assert_true(MdtBodyIsEnabled(b));
    MdtWorldSetAutoDisable(w, METRUE);
    MdtWorldSetAutoDisable(w, METRUE); /* already on: the window it is filling is kept */
    int slept = 0;
    for (int i = 1; i <= 60 && !slept; i++) {
        MdtWorldStep(w, ME_R(1.0) / 60);
        if (!MdtBodyIsEnabled(b))
            slept = i;
    }
    print_message("asleep %d steps after auto-disable was switched on\n", slept);
    assert_true(slept >= 32 && slept <= 36);
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(resting_stack_sleeps_and_a_new_constraint_wakes_it),
        cmocka_unit_test(one_moving_body_keeps_its_partition_awake),
        cmocka_unit_test(steady_motion_is_judged_as_in_karma_12),
        cmocka_unit_test(shaking_in_place_sleeps_only_when_averaged),
        cmocka_unit_test(averaging_time_setting),
        cmocka_unit_test(switching_auto_disable_on_starts_the_windows_afresh),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
