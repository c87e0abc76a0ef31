/* Matrix capping (MdtLOD.h): rows over MdtWorldSetMaxMatrixSize are dropped in Karma's order --
 * friction rows first, then body-body contacts, then body-world contacts, shallowest first -- joints
 * never, at least one contact per group; the importance callback replaces the order; a capped stack
 * still stands. */
#include "karma_test.h"
#include "karma_contacts.h"

#include <karma/Mdt.h>

/* Boxes A and B on the ground joined by a ball joint, box C on A: one partition of
 * 3 (joint) + 3 groups x 4 contacts x 3 rows = 39 rows. */
enum { A, B, C, GROUPS = 3, PER = 4, FULL = 3 + GROUPS * PER * 3 };

typedef struct Scene {
    MdtWorldID world;
    MdtBodyID box[3];
    MdtContactGroupID group[GROUPS]; /* A-world, B-world, C-A */
    MdtContactID contact[GROUPS][PER];
    MdtBSJointID joint;
    MdtContactParams params;
} Scene;

/* Penetrations: world contacts shallow and interleaved, body-body contacts deeper. */
static const double pen[GROUPS][PER] = {
    {0.001, 0.002, 0.003, 0.004}, {0.0015, 0.0025, 0.0035, 0.0045}, {0.01, 0.02, 0.03, 0.04}};

static MdtBodyID boxAt(MdtWorldID w, MeReal x, MeReal z)
{
    MdtBodyID b = MdtBodyCreate(w);
    MeMatrix3 I;
    MdtMakeInertiaTensorBox(1, 1, 1, 1, I);
    MdtBodySetInertiaTensor(b, I);
    MdtBodySetPosition(b, x, 0, z);
    MdtBodyEnable(b);
    return b;
}

static void build(Scene *s, int handMade)
{
    s->world = MdtWorldCreate(8, 32, 1, 1);
    MdtWorldSetGravity(s->world, 0, 0, -9.81f);
    MdtWorldSetAutoDisable(s->world, MEFALSE);
    karma_contact_params_friction(&s->params, 0.6f);
    s->box[A] = boxAt(s->world, 0, 0.5f);
    s->box[B] = boxAt(s->world, 1.5f, 0.5f);
    s->box[C] = boxAt(s->world, 0, 1.5f);
    MdtBodyID other[GROUPS] = {NULL, NULL, s->box[A]};
    MdtBodyID self[GROUPS] = {s->box[A], s->box[B], s->box[C]};
    for (int g = 0; g < GROUPS; g++) {
        s->group[g] = MdtContactGroupCreate(s->world);
        MdtContactGroupSetBodies(s->group[g], self[g], other[g]);
        MdtContactGroupEnable(s->group[g]);
        for (int k = 0; k < PER; k++) {
            s->contact[g][k] = MdtContactGroupCreateContact(s->group[g]);
            if (!handMade)
                continue;
            MeVector3 p;
            MdtBodyGetPosition(self[g], p);
            MdtContactSetParams(s->contact[g][k], &s->params);
            MdtContactSetPosition(s->contact[g][k], p[0] + (k & 1 ? 0.5f : -0.5f), p[1] + (k & 2 ? 0.5f : -0.5f),
                                  p[2] - 0.5f);
            MdtContactSetNormal(s->contact[g][k], 0, 0, 1); /* body 1 below pushes body 0 up */
            MdtContactSetPenetration(s->contact[g][k], (MeReal)pen[g][k]);
        }
    }
    s->joint = MdtBSJointCreate(s->world);
    MdtBSJointSetBodies(s->joint, s->box[A], s->box[B]);
    MdtBSJointSetPosition(s->joint, 0.75f, 0, 0.5f);
    MdtBSJointEnable(s->joint);
}

static int rowsOf(MdtContactID c) { return MdtConstraintGetRowCount(MdtContactQuaConstraint(c)); }

/* One step of the hand-made scene with the given cap; returns the partition's rows. */
static int capOnce(Scene *s, int cap, MdtWorldCounters *counters)
{
    build(s, 1);
    if (cap)
        MdtWorldSetMaxMatrixSize(s->world, cap);
    MdtWorldStep(s->world, ME_R(1.0) / 60);
    MdtWorldGetCounters(s->world, counters);
    assert_int_equal(MdtConstraintGetRowCount(MdtBSJointQuaConstraint(s->joint)), 3); /* joints never */
    for (int g = 0; g < GROUPS; g++) {
        int kept = 0;
        for (int k = 0; k < PER; k++)
            kept += rowsOf(s->contact[g][k]) > 0;
        assert_true(kept >= 1); /* at least one contact per group */
    }
    assert_int_equal(counters->droppedRows, FULL - counters->rows);
    return counters->rows;
}

/* Rows each contact kept, as a string "group:rows..." for the messages. */
static void describe(const Scene *s, char *out)
{
    for (int g = 0; g < GROUPS; g++) {
        *out++ = "ABC"[g];
        *out++ = ':';
        for (int k = 0; k < PER; k++)
            *out++ = (char)('0' + rowsOf(s->contact[g][k]));
        *out++ = ' ';
    }
    out[-1] = 0;
}

static void drops_in_karmas_order(void **state)
{
    (void)state;
    Scene s;
    MdtWorldCounters c;
    char text[64];
    /* Uncapped: all 39 rows. */
    assert_int_equal(capOnce(&s, 0, &c), FULL);
    assert_int_equal(MdtWorldGetMaxMatrixSize(s.world), MDT_MATRIX_SIZE_UNCAPPED);
    MdtWorldDestroy(s.world);

    /* Cap 30: friction goes first, body-body contacts before world ones, shallowest first: C's three
     * shallowest, then A's and B's shallowest (interleaved by depth). 39 - 5*2 = 29 rows. */
    assert_int_equal(capOnce(&s, 30, &c), 29);
    describe(&s, text);
    print_message("cap 30: %d rows (%d dropped), rows per contact %s\n", c.rows, c.droppedRows, text);
    int expect30[GROUPS][PER] = {{1, 3, 3, 3}, {1, 3, 3, 3}, {1, 1, 1, 3}};
    for (int g = 0; g < GROUPS; g++)
        for (int k = 0; k < PER; k++)
            assert_int_equal(rowsOf(s.contact[g][k]), expect30[g][k]);
    assert_int_equal(c.cappedPartitions, 1);
    MdtPartitionInfo info;
    MdtWorldGetPartitionInfo(s.world, 0, &info);
    assert_int_equal(info.rows, 29);
    assert_int_equal(info.droppedRows, 10);
    MdtWorldDestroy(s.world);

    /* Cap 15: every friction row goes, no contact. */
    assert_int_equal(capOnce(&s, 15, &c), 15);
    describe(&s, text);
    print_message("cap 15: %d rows, rows per contact %s\n", c.rows, text);
    for (int g = 0; g < GROUPS; g++)
        for (int k = 0; k < PER; k++)
            assert_int_equal(rowsOf(s.contact[g][k]), 1);
    MdtWorldDestroy(s.world);

    /* Cap 10: then whole contacts: C's three shallowest (the deepest is C's keeper), then the
     * shallowest world contacts, A's 0.001 and B's 0.0015. */
    assert_int_equal(capOnce(&s, 10, &c), 10);
    describe(&s, text);
    print_message("cap 10: %d rows, rows per contact %s\n", c.rows, text);
    int expect10[GROUPS][PER] = {{0, 1, 1, 1}, {0, 1, 1, 1}, {0, 0, 0, 1}};
    for (int g = 0; g < GROUPS; g++)
        for (int k = 0; k < PER; k++)
            assert_int_equal(rowsOf(s.contact[g][k]), expect10[g][k]);
    MdtWorldDestroy(s.world);

    /* Cap 1: cannot be met: the joint and one contact per group (each group's deepest) remain. */
    assert_int_equal(capOnce(&s, 1, &c), 3 + GROUPS);
    describe(&s, text);
    print_message("cap 1: %d rows (joint + one contact per group), rows per contact %s\n", c.rows, text);
    for (int g = 0; g < GROUPS; g++)
        assert_int_equal(rowsOf(s.contact[g][PER - 1]), 1);
    MdtWorldDestroy(s.world);
}

static void friction_ratio_protects_the_most_important(void **state)
{
    (void)state;
    Scene s;
    build(&s, 1);
    MdtLODParams p;
    MdtWorldGetLODParams(s.world, &p);
    p.frictionRatio = 0.5f; /* the 6 most important friction contacts keep friction until dropped */
    MdtWorldSetLODParams(s.world, &p);
    MdtWorldSetMaxMatrixSize(s.world, 15);
    MdtWorldStep(s.world, ME_R(1.0) / 60);
    MdtWorldCounters c;
    MdtWorldGetCounters(s.world, &c);
    char text[64];
    describe(&s, text);
    print_message("cap 15, frictionRatio 0.5: %d rows, rows per contact %s\n", c.rows, text);
    /* Friction off the 6 least important (12 rows: 27 left), then whole contacts in order: C 0.01,
     * 0.02, 0.03, A 0.001, B 0.0015, A 0.002 (1 row each), B 0.0025 and A 0.003 (3 rows each). */
    assert_int_equal(c.rows, 15);
    int expect[GROUPS][PER] = {{0, 0, 0, 3}, {0, 0, 3, 3}, {0, 0, 0, 3}};
    for (int g = 0; g < GROUPS; g++)
        for (int k = 0; k < PER; k++)
            assert_int_equal(rowsOf(s.contact[g][k]), expect[g][k]);
    MdtWorldDestroy(s.world);
}

/* An approaching body's contacts matter more: B falling at 2 m/s onto its contacts adds
 * normVelBias x 2 = 13 to their importance, so A's world contacts go first. */
static void approach_speed_raises_importance(void **state)
{
    (void)state;
    Scene s;
    build(&s, 1);
    MdtBodySetLinearVelocity(s.box[B], 0, 0, -2);
    MdtWorldSetMaxMatrixSize(s.world, 10);
    MdtWorldStep(s.world, ME_R(1.0) / 60);
    char text[64];
    describe(&s, text);
    print_message("cap 10, box B approaching at 2 m/s: rows per contact %s\n", text);
    int expect[GROUPS][PER] = {{0, 0, 1, 1}, {1, 1, 1, 1}, {0, 0, 0, 1}};
    for (int g = 0; g < GROUPS; g++)
        for (int k = 0; k < PER; k++)
            assert_int_equal(rowsOf(s.contact[g][k]), expect[g][k]);
    MdtWorldDestroy(s.world);
}

/* Importance by callback: here world contacts count for less than body-body ones. */
static MeReal worldLast(MdtContactID c, void *data)
{
    (*(int *)data)++;
    MdtContactGroupID g = MdtContactGetContactGroup(c);
    return MdtContactGetPenetration(c) + (MdtContactGroupGetBody(g, 1) ? 100 : 0);
}

static void importance_callback_replaces_the_order(void **state)
{
    (void)state;
    Scene s;
    build(&s, 1);
    int calls = 0;
    MdtWorldSetContactImportanceCB(s.world, worldLast, &calls);
    MdtWorldSetMaxMatrixSize(s.world, 10);
    MdtWorldStep(s.world, ME_R(1.0) / 60);
    char text[64];
    describe(&s, text);
    print_message("cap 10 with a callback favouring body-body contacts: rows per contact %s (%d calls)\n", text,
                  calls);
    assert_int_equal(calls, GROUPS * PER);
    int expect[GROUPS][PER] = {{0, 0, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    for (int g = 0; g < GROUPS; g++)
        for (int k = 0; k < PER; k++)
            assert_int_equal(rowsOf(s.contact[g][k]), expect[g][k]);
    /* NULL restores the formula. */
    MdtWorldSetContactImportanceCB(s.world, NULL, NULL);
    MdtWorldStep(s.world, ME_R(1.0) / 60);
    assert_int_equal(calls, GROUPS * PER);
    MdtWorldDestroy(s.world);
}

/* The same stack with contacts from its geometry, capped at 20 rows, stands like the uncapped one. */
static double runStack(int cap, double *jointGap, int *maxRows)
{
    Scene s;
    build(&s, 0);
    if (cap)
        MdtWorldSetMaxMatrixSize(s.world, cap);
    const MeVector3 half = {0.5f, 0.5f, 0.5f}, up = {0, 0, 1};
    MeVector3 c0, c;
    MdtBodyGetPosition(s.box[C], c0);
    double drift = 0;
    *jointGap = 0;
    *maxRows = 0;
    for (int step = 0; step < 300; step++) {
        karma_box_on_plane(s.group[0], s.box[A], half, up, 0, &s.params);
        karma_box_on_plane(s.group[1], s.box[B], half, up, 0, &s.params);
        karma_box_on_box(s.group[2], s.box[C], s.box[A], half, &s.params);
        MdtWorldStep(s.world, ME_R(1.0) / 60);
        MdtWorldCounters counters;
        MdtWorldGetCounters(s.world, &counters);
        if (counters.rows > *maxRows)
            *maxRows = counters.rows;
        MdtBodyGetPosition(s.box[C], c);
        drift = fmax(drift, sqrt((c[0] - c0[0]) * (c[0] - c0[0]) + (c[1] - c0[1]) * (c[1] - c0[1]) +
                                 (c[2] - c0[2]) * (c[2] - c0[2])));
        MeVector3 p0, p1;
        MdtConstraintBodyGetPosition(MdtBSJointQuaConstraint(s.joint), 0, p0);
        MdtConstraintBodyGetPosition(MdtBSJointQuaConstraint(s.joint), 1, p1);
        *jointGap = fmax(*jointGap, sqrt((p0[0] - p1[0]) * (p0[0] - p1[0]) + (p0[1] - p1[1]) * (p0[1] - p1[1]) +
                                         (p0[2] - p1[2]) * (p0[2] - p1[2])));
    }
    MdtWorldDestroy(s.world);
    return drift;
}

static void capped_stack_still_stands(void **state)
{
    (void)state;
    double gapFull, gapCapped;
    int rowsFull, rowsCapped;
    double driftFull = runStack(0, &gapFull, &rowsFull);
    double driftCapped = runStack(20, &gapCapped, &rowsCapped);
    print_message("stack, 5 s: uncapped %d rows, top drift %.2e m, joint gap %.2e m; capped at 20: %d rows, "
                  "top drift %.2e m, joint gap %.2e m\n",
                  rowsFull, driftFull, gapFull, rowsCapped, driftCapped, gapCapped);
    assert_int_equal(rowsFull, FULL);
    assert_true(rowsCapped <= 20);
    assert_true(driftCapped < 0.01);
    assert_true(gapCapped < 1e-3);
}

static void settings_are_checked(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtLODParams p, q;
    MdtWorldGetLODParams(w, &p);
    assert_near(p.frictionRatio, 0, 0);
    assert_near(p.zeroRowBonus, 150, 0);
    assert_near(p.toWorldBonus, 100, 0);
    assert_near(p.rowCountBias, 40, 0);
    assert_near(p.penetrationBias, 15, 0);
    assert_near(p.normVelBias, 6.5, 0);
    assert_near(p.nonAutoBonus, 40, 0);
    q = p;
    q.frictionRatio = 2;
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetLODParams(w, &q));
    q.frictionRatio = (MeReal)NAN;
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtWorldSetLODParams(w, &q));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetMaxMatrixSize(w, 0));
    assert_int_equal(MdtWorldGetMaxMatrixSize(w), MDT_MATRIX_SIZE_UNCAPPED);
    MdtWorldSetMaxMatrixSize(w, 36);
    assert_int_equal(MdtWorldGetMaxMatrixSize(w), 36);
    MdtWorldReCreate(w); /* back to the defaults */
    assert_int_equal(MdtWorldGetMaxMatrixSize(w), MDT_MATRIX_SIZE_UNCAPPED);
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(drops_in_karmas_order),
        cmocka_unit_test(friction_ratio_protects_the_most_important),
        cmocka_unit_test(approach_speed_raises_importance),
        cmocka_unit_test(importance_callback_replaces_the_order),
        cmocka_unit_test(capped_stack_still_stands),
        cmocka_unit_test(settings_are_checked),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
