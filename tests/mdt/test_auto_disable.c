/* Auto-disable of whole partitions: a resting stack goes to sleep as one partition once every body is
 * at rest and past the alive window; a partition with one moving body stays awake; a new constraint
 * from an enabled body wakes the sleeping partition it reaches (the partitioner enables it). */
#include "karma_test.h"
#include "karma_contacts.h"

#include <karma/Mdt.h>

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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(resting_stack_sleeps_and_a_new_constraint_wakes_it),
        cmocka_unit_test(one_moving_body_keeps_its_partition_awake),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
