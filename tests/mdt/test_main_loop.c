/* The public stages of the step (MdtMainLoop.h): an application-written step from the stages gives a
 * bit-identical simulation to MdtWorldStep; stages out of order are refused; partitions can be
 * inspected between stages; a body's contacts can be iterated (D9). */
#include "karma_test.h"
#include "karma_contacts.h"

#include <string.h>

#include <karma/Mdt.h>

enum { LINKS = 5, COLUMN = 3 };

typedef struct Scene {
    MdtWorldID world;
    MdtBodyID link[LINKS], box[COLUMN], lone, sleeper, thrown;
    MdtContactGroupID group[COLUMN], sleeperGround;
    MdtBSJointID joint[LINKS];
    MdtContactParams params;
} Scene;

static const MeVector3 half = {0.5f, 0.5f, 0.5f}, up = {0, 0, 1};

static MdtBodyID boxAt(MdtWorldID w, MeReal x, MeReal y, MeReal z)
{
    MdtBodyID b = MdtBodyCreate(w);
    MeMatrix3 I;
    MdtMakeInertiaTensorBox(1, 1, 1, 1, I);
    MdtBodySetInertiaTensor(b, I);
    MdtBodySetPosition(b, x, y, z);
    MdtBodyEnable(b);
    return b;
}

/* A swinging chain, a column of boxes, a box that goes to sleep, a free body thrown upwards. */
static void build(Scene *s)
{
    s->world = MdtWorldCreate(32, 64, 1, 1);
    MdtWorldSetGravity(s->world, 0, 0, -9.81f);
    karma_contact_params_friction(&s->params, 0.6f);
    for (int i = 0; i < LINKS; i++) {
        s->link[i] = MdtBodyCreate(s->world);
        MdtBodySetPosition(s->link[i], (MeReal)(i + 1), 0, 10);
        MdtBodyEnable(s->link[i]);
        s->joint[i] = MdtBSJointCreate(s->world);
        MdtBSJointSetBodies(s->joint[i], s->link[i], i ? s->link[i - 1] : NULL);
        MdtBSJointSetPosition(s->joint[i], (MeReal)i, 0, 10);
        MdtBSJointEnable(s->joint[i]);
    }
    for (int i = 0; i < COLUMN; i++) {
        s->box[i] = boxAt(s->world, 5, 0, 0.5f + (MeReal)i);
        s->group[i] = MdtContactGroupCreate(s->world);
        MdtContactGroupSetBodies(s->group[i], s->box[i], i ? s->box[i - 1] : NULL);
        MdtContactGroupEnable(s->group[i]);
    }
    s->sleeper = boxAt(s->world, -5, 0, 0.5f);
    s->sleeperGround = MdtContactGroupCreate(s->world);
    MdtContactGroupSetBodies(s->sleeperGround, s->sleeper, NULL);
    MdtContactGroupEnable(s->sleeperGround);
    s->thrown = boxAt(s->world, 10, 0, 1);
    MdtBodySetLinearVelocity(s->thrown, 1, 0, 5);
    MdtBodySetAngularVelocity(s->thrown, 0.3f, 2, 0);
}

static void refreshContacts(Scene *s)
{
    for (int i = 0; i < COLUMN; i++) {
        if (i == 0)
            karma_box_on_plane(s->group[0], s->box[0], half, up, 0, &s->params);
        else
            karma_box_on_box(s->group[i], s->box[i], s->box[i - 1], half, &s->params);
    }
    karma_box_on_plane(s->sleeperGround, s->sleeper, half, up, 0, &s->params);
}

/* The step written by an application from the public stages, optional ones included. */
static void stagedStep(MdtWorldID w, MeReal h)
{
    MdtWorldStepBegin(w, h);
    MdtWorldUpdatePartitions(w);
    MdtAutoDisablePartitions(w);
    MdtLODPartitions(w);
    MdtPack(w);
    MdtKeaSolve(w);
    MdtKeaIntegrate(w);
    MdtUnpack(w);
    MdtWorldStepEnd(w);
}

static uint64_t hashScene(const Scene *s)
{
    uint64_t h = KARMA_HASH_INIT;
    for (MdtBodyID b = MdtBodyGetFirst(s->world); b; b = MdtBodyGetNext(b)) {
        MeVector3 v;
        MeVector4 q;
        MeMatrix4Ptr tm = MdtBodyGetTransformPtr(b);
        h = karma_hash_bytes(h, tm, sizeof(MeMatrix4));
        MdtBodyGetQuaternion(b, q);
        h = karma_hash_bytes(h, q, sizeof q);
        MdtBodyGetLinearVelocity(b, v);
        h = karma_hash_bytes(h, v, sizeof v);
        MdtBodyGetAngularVelocity(b, v);
        h = karma_hash_bytes(h, v, sizeof v);
        MeBool e = MdtBodyIsEnabled(b);
        h = karma_hash_bytes(h, &e, sizeof e);
    }
    for (int i = 0; i < LINKS; i++) {
        MeVector3 f;
        MdtConstraintGetForce(MdtBSJointQuaConstraint(s->joint[i]), 0, f);
        h = karma_hash_bytes(h, f, sizeof f);
    }
    return h;
}

static void stages_match_world_step_bit_for_bit(void **state)
{
    (void)state;
    Scene a, b;
    build(&a);
    build(&b);
    const MeReal h = ME_R(1.0) / 60;
    int sameEvery = 1;
    for (int step = 0; step < 240; step++) {
        refreshContacts(&a);
        refreshContacts(&b);
        MdtWorldStep(a.world, h);
        stagedStep(b.world, h);
        sameEvery &= hashScene(&a) == hashScene(&b);
    }
    MdtWorldCounters ca, cb;
    MdtWorldGetCounters(a.world, &ca);
    MdtWorldGetCounters(b.world, &cb);
    MeVector3 pa, pb;
    MdtBodyGetPosition(a.link[LINKS - 1], pa);
    MdtBodyGetPosition(b.link[LINKS - 1], pb);
    print_message("staged vs MdtWorldStep: 240 steps, states %s; chain end at (%.4f, %.4f, %.4f); sleeper %s; "
                  "%d partitions, %d rows in the last step\n",
                  sameEvery ? "bit-identical" : "DIFFER", pa[0], pa[1], pa[2],
                  MdtBodyIsEnabled(b.sleeper) ? "awake" : "asleep", cb.partitions, cb.rows);
    assert_true(sameEvery);
    assert_memory_equal(pa, pb, sizeof pa);
    assert_int_equal(ca.steps, 240);
    assert_int_equal(cb.steps, 240);
    assert_int_equal(ca.rows, cb.rows);
    /* The scene did something: the chain swung down, the sleeper slept, the column stood. */
    assert_true(pa[2] < 9);
    assert_false(MdtBodyIsEnabled(b.sleeper));
    MdtBodyGetPosition(b.box[COLUMN - 1], pb);
    assert_near(pb[0], 5, 1e-3);
    /* Each stage was timed once per step, in the same sections as MdtWorldStep's. */
    const char *sections[] = {"Dynamics", "Partition", "AutoDisable", "LOD", "Pack", "Solve", "Integrate", "Unpack"};
    for (unsigned i = 0; i < sizeof sections / sizeof sections[0]; i++)
        assert_int_equal(MeProfileGetSection(MdtWorldGetProfile(b.world), sections[i])->calls, 240);
    MdtWorldDestroy(a.world);
    MdtWorldDestroy(b.world);
}

static void stages_out_of_order_are_refused(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    build(&s);
    refreshContacts(&s);
    const MeReal h = ME_R(1.0) / 60;
    assert_reports(ME_ERR_BAD_STATE, MdtPack(s.world)); /* no step begun */
    assert_reports(ME_ERR_BAD_STATE, MdtWorldStepEnd(s.world));
    assert_reports(ME_ERR_STEP_SIZE, MdtWorldStepBegin(s.world, -h));
    MdtWorldStepBegin(s.world, h);
    assert_reports(ME_ERR_WORLD_LOCKED, MdtWorldStepBegin(s.world, h));
    assert_reports(ME_ERR_WORLD_LOCKED, MdtWorldStep(s.world, h));
    assert_reports(ME_ERR_WORLD_LOCKED, MdtBodyCreate(s.world));
    assert_reports(ME_ERR_BAD_STATE, MdtPack(s.world)); /* before the partitions */
    MdtWorldUpdatePartitions(s.world);
    assert_reports(ME_ERR_BAD_STATE, MdtWorldUpdatePartitions(s.world)); /* twice */
    /* Inspect the partitions: chain, column, sleeper, thrown body, in (sort key, slot) order. */
    assert_int_equal(MdtWorldGetPartitionCount(s.world), 4);
    MdtPartitionInfo info;
    MdtWorldGetPartitionInfo(s.world, 0, &info);
    assert_int_equal(info.bodies, LINKS);
    assert_int_equal(info.constraints, LINKS);
    assert_int_equal(info.rows, 0); /* not packed yet */
    assert_ptr_equal(MdtWorldGetPartitionBody(s.world, 0, 0), s.link[0]);
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldGetPartitionInfo(s.world, 4, &info));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldGetPartitionBody(s.world, 0, LINKS));
    /* The optional stages may be skipped. */
    MdtPack(s.world);
    assert_reports(ME_ERR_BAD_STATE, MdtLODPartitions(s.world)); /* too late */
    MdtWorldGetPartitionInfo(s.world, 0, &info);
    assert_int_equal(info.rows, 3 * LINKS);
    MdtWorldGetPartitionInfo(s.world, 1, &info);
    assert_int_equal(info.bodies, COLUMN);
    assert_int_equal(info.rows, COLUMN * 4 * 3);
    assert_reports(ME_ERR_BAD_STATE, MdtKeaIntegrate(s.world)); /* solve first */
    MdtKeaSolve(s.world);
    MdtKeaIntegrate(s.world);
    assert_reports(ME_ERR_BAD_STATE, MdtWorldStepEnd(s.world)); /* unpack first */
    MdtUnpack(s.world);
    MdtWorldStepEnd(s.world);
    MdtWorldCounters c;
    MdtWorldGetCounters(s.world, &c);
    assert_int_equal(c.steps, 1);
    assert_non_null(MdtBodyCreate(s.world)); /* unlocked again */
    MdtWorldDestroy(s.world);
}

/* A partition lists its bodies in (sort key, slot) order whatever order the search met them in: five
 * bodies joined b4-b3, b3-b0, b0-b2, b2-b1 are met as b0 b3 b2 b4 b1; then with sort keys; then with
 * one of them asleep (woken by the partitioner) and a constraint with a sort key. */
static void partitions_list_bodies_in_sort_key_then_slot_order(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(8, 8, 1, 1);
    MdtBodyID b[5];
    static const int pairs[4][2] = {{4, 3}, {3, 0}, {0, 2}, {2, 1}};
    MdtBSJointID j[4];
    for (int i = 0; i < 5; i++) {
        b[i] = boxAt(w, (MeReal)i, 0, 0);
        MdtBodySetSortKey(b[i], 1);
    }
    for (int i = 0; i < 4; i++) {
        j[i] = MdtBSJointCreate(w);
        MdtBSJointSetBodies(j[i], b[pairs[i][0]], b[pairs[i][1]]);
        MdtBSJointSetPosition(j[i], 0, 0, 0);
        MdtBSJointEnable(j[i]);
    }
    static const int orders[3][5] = {{0, 1, 2, 3, 4}, {4, 0, 2, 3, 1}, {4, 0, 2, 3, 1}};
    for (int round = 0; round < 3; round++) {
        if (round == 1) {
            MdtBodySetSortKey(b[4], 0);
            MdtBodySetSortKey(b[1], 5);
        }
        if (round == 2) {
            MdtBodyDisable(b[3]);
            MdtConstraintSetSortKey(MdtBSJointQuaConstraint(j[2]), 7);
        }
        MdtWorldStepBegin(w, ME_R(1.0) / 60);
        MdtWorldUpdatePartitions(w);
        assert_int_equal(MdtWorldGetPartitionCount(w), 1);
        for (int i = 0; i < 5; i++)
            assert_ptr_equal(MdtWorldGetPartitionBody(w, 0, i), b[orders[round][i]]);
        MdtPack(w);
        MdtKeaSolve(w);
        MdtKeaIntegrate(w);
        MdtUnpack(w);
        MdtWorldStepEnd(w);
        assert_true(MdtBodyIsEnabled(b[3]));
    }
    MdtWorldDestroy(w);
}

static int countContacts(MdtBodyID b)
{
    int n = 0;
    for (MdtContactID c = MdtBodyGetFirstContact(b); c; c = MdtBodyGetNextContact(b, c)) {
        MdtContactGroupID g = MdtContactGetContactGroup(c);
        MdtBodyID b0 = g ? MdtContactGroupGetBody(g, 0) : MdtContactGetBody(c, 0);
        MdtBodyID b1 = g ? MdtContactGroupGetBody(g, 1) : MdtContactGetBody(c, 1);
        assert_true(b0 == b || b1 == b);
        n++;
    }
    return n;
}

static void body_contact_iteration(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    build(&s);
    refreshContacts(&s);
    /* box[1]: 4 contacts below (its group), 4 above (box[2]'s group); add a stand-alone contact and an
     * empty group; the joints of the chain are not contacts. */
    MdtContactID alone = MdtContactCreate(s.world);
    MdtContactSetBodies(alone, s.box[1], s.lone = boxAt(s.world, 6, 0, 1.5f));
    MdtContactGroupID empty = MdtContactGroupCreate(s.world);
    MdtContactGroupSetBodies(empty, s.box[1], s.lone);
    assert_int_equal(countContacts(s.box[1]), 9);
    assert_int_equal(countContacts(s.box[0]), 8);
    assert_int_equal(countContacts(s.lone), 1);
    assert_int_equal(countContacts(s.link[0]), 0);
    assert_null(MdtBodyGetFirstContact(s.thrown));
    /* A contact of another body is refused. */
    MdtContactID other = MdtContactGroupGetFirstContact(s.sleeperGround);
    assert_reports(ME_ERR_BAD_STATE, MdtBodyGetNextContact(s.box[1], other));
    MdtWorldDestroy(s.world);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(stages_match_world_step_bit_for_bit),
        cmocka_unit_test(stages_out_of_order_are_refused),
        cmocka_unit_test(body_contact_iteration),
        cmocka_unit_test(partitions_list_bodies_in_sort_key_then_slot_order),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
