/* The rest of Karma 1.2's Mdt API: MdtContactSetNext on a group's list, MdtKeaMemoryRequired against
 * what a solve uses, the matrix-size log, 1.2's partition counts and MdtBodyIsMovingTest, contact
 * drawing, the Kea debug request, the chunk getters, the MdtCHECK macros, the MdtBcl max-row macros
 * against the constraint types, and the contact-parameter struct under 1.2's tag. */
#include "karma_test.h"

#include <stddef.h>

#include <karma/Mdt.h>
#include <karma/MdtAlignment.h>
#include <karma/MdtBcl.h>
#include <karma/MdtCheckMacros.h>
#include <karma/MdtKea.h>
#include <karma/MdtPartition.h>
#include <karma/MeDebugDraw.h>

#include "mdt/constraint.h"

/* The contacts of a group, in list order; returns how many. */
static int groupList(MdtContactGroupID g, MdtContactID *out, int max)
{
    int n = 0;
    for (MdtContactID c = MdtContactGroupGetFirstContact(g); c && n < max; c = MdtContactGetNext(c))
        out[n++] = c;
    return n;
}

static void contact_set_next_relinks_the_group(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 16, 1, 1);
    MdtBodyID b = MdtBodyCreate(w);
    MdtContactGroupID g = MdtContactGroupCreate(w);
    MdtContactGroupSetBodies(g, b, NULL);
    MdtContactID c1 = MdtContactGroupCreateContact(g), c2 = MdtContactGroupCreateContact(g);
    MdtContactID c3 = MdtContactGroupCreateContact(g), s = MdtContactCreate(w);
    MdtContactID list[8];

    MdtContactSetNext(c1, s); /* a stand-alone contact goes in after c1 */
    assert_int_equal(groupList(g, list, 8), 4);
    assert_ptr_equal(list[1], s);
    assert_ptr_equal(list[2], c2);
    assert_ptr_equal(MdtContactGetContactGroup(s), g);
    assert_int_equal(MdtContactGroupGetCount(g), 4);

    MdtContactSetNext(c1, c3); /* a member moves */
    assert_int_equal(groupList(g, list, 8), 4);
    assert_ptr_equal(list[1], c3);
    assert_ptr_equal(list[2], s);
    assert_ptr_equal(list[3], c2);

    MdtContactSetNext(c3, NULL); /* c3 becomes the last: s and c2 leave */
    assert_int_equal(groupList(g, list, 8), 2);
    assert_int_equal(MdtContactGroupGetCount(g), 2);
    assert_null(MdtContactGetNext(c3));
    assert_null(MdtContactGetContactGroup(c2));
    assert_null(MdtContactGetContactGroup(s));
    assert_false(MdtContactIsEnabled(s));
    MdtContactGroupAppendContact(g, c2); /* the group's last is c3's successor again */
    assert_int_equal(groupList(g, list, 8), 3);
    assert_ptr_equal(list[2], c2);

    karma_capture_messages();
    assert_reports(ME_ERR_BAD_STATE, MdtContactSetNext(s, c1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtContactSetNext(c1, c1));
    MdtContactGroupID other = MdtContactGroupCreate(w);
    MdtContactGroupSetBodies(other, b, NULL);
    MdtContactID o1 = MdtContactGroupCreateContact(other);
    assert_reports(ME_ERR_BAD_STATE, MdtContactSetNext(c1, o1));
    MdtWorldDestroy(w);
}

/* A world with three partitions: a chain of three balls hanging from the world by ball joints, a
 * hinged pair, and a free body. */
static MdtWorldID threePartitions(void)
{
    MdtWorldID w = MdtWorldCreate(8, 8, 1, 1);
    MdtWorldSetGravity(w, 0, -9.81f, 0);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID prev = NULL;
    for (int i = 0; i < 3; i++) {
        MdtBodyID b = MdtBodyCreate(w);
        MdtBodySetPosition(b, 0, -(MeReal)(i + 1), 0);
        MdtBodyEnable(b);
        MdtBSJointID j = MdtBSJointCreate(w);
        MdtBSJointSetBodies(j, b, prev);
        MdtBSJointSetPosition(j, 0, -(MeReal)i, 0);
        MdtBSJointEnable(j);
        prev = b;
    }
    MdtBodyID h0 = MdtBodyCreate(w), h1 = MdtBodyCreate(w), free = MdtBodyCreate(w);
    MdtBodySetPosition(h0, 10, 0, 0);
    MdtBodySetPosition(h1, 11, 0, 0);
    MdtBodySetPosition(free, -10, 0, 0);
    MdtBodySetAngularVelocity(h1, 0, 0, 1);
    MdtBodyEnable(h0);
    MdtBodyEnable(h1);
    MdtBodyEnable(free);
    MdtHingeID h = MdtHingeCreate(w);
    MdtHingeSetBodies(h, h0, h1);
    MdtHingeSetPosition(h, 10.5f, 0, 0);
    MdtHingeSetAxis(h, 0, 0, 1);
    MdtHingeEnable(h);
    return w;
}

static void kea_memory_required_covers_what_a_solve_uses(void **state)
{
    (void)state;
    MdtWorldID w = threePartitions();
    assert_int_equal(MdtWorldGetMaxMemoryPoolUsed(w), 0);
    MdtWorldStep(w, 0.01f);
    int n = MdtWorldGetPartitionCount(w);
    assert_int_equal(n, 3);
    int rows[3], maxRows = 0, bodies = 0;
    for (int p = 0; p < n; p++) {
        MdtPartitionInfo info;
        MdtWorldGetPartitionInfo(w, p, &info);
        rows[p] = info.rows;
        bodies += info.bodies;
        if (info.rows > maxRows)
            maxRows = info.rows;
    }
    assert_int_equal(maxRows, 9); /* the chain: three ball joints */
    int used = MdtWorldGetMaxMemoryPoolUsed(w);
    assert_true(used > 0);
    assert_int_equal((size_t)used, MeChunkGetMaxSize(MdtWorldGetKeaPoolChunk(w)));
    int estimate = MdtKeaMemoryRequired(rows, n, maxRows, bodies);
    assert_true(estimate >= used);
    assert_true(2 * estimate <= 3 * used); /* within 50%: an estimate of this solve, not a blanket bound */
    assert_int_equal(MdtKeaMemoryRequired(NULL, n, maxRows, bodies), estimate);
    /* No rows, nothing to solve; more rows, more memory. */
    assert_int_equal(MdtKeaMemoryRequired(NULL, 0, 0, 0), 0);
    assert_true(MdtKeaMemoryRequired(NULL, 1, 4 * maxRows, bodies) > estimate);
    karma_capture_messages();
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(MdtKeaMemoryRequired(NULL, -1, 0, 0), -1));
    int tooMany[1] = {10};
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(MdtKeaMemoryRequired(tooMany, 1, 9, 4), -1));
    MdtWorldDestroy(w);
}

static void cpu_resources_and_cache_calls(void **state)
{
    (void)state;
    MeCPUResources r = MdtKeaQueryCPUResources();
    assert_non_null(r);
    assert_ptr_equal(r, MdtKeaQueryCPUResources());
    int data[4] = {1, 2, 3, 4};
    MdtFlushCache(0);
    MdtSyncDCache(data, data + 4);
    MdtInvalidDCache(data, data + 4);
    assert_int_equal(data[3], 4); /* no-ops: memory is untouched */
}

static void matrix_size_log_counts_partitions_by_rows(void **state)
{
    (void)state;
    MdtWorldID w = threePartitions();
    int log[4] = {7, 7, 7, 7};
    MdtWorldSetMatrixSizeLog(w, log, 4);
    assert_int_equal(log[0] + log[1] + log[2] + log[3], 0); /* zeroed */
    MdtWorldStep(w, 0.01f);
    MdtWorldStep(w, 0.01f);
    /* 1.2's entries: 0 rows (the free body) -> 0; 5 rows (the hinge) -> 2; 9 rows (the chain) -> 3. */
    assert_int_equal(log[0], 2);
    assert_int_equal(log[1], 0);
    assert_int_equal(log[2], 2);
    assert_int_equal(log[3], 2);
    int small[2];
    MdtWorldSetMatrixSizeLog(w, small, 2); /* the last entry takes every larger one */
    MdtWorldStep(w, 0.01f);
    assert_int_equal(small[0], 1);
    assert_int_equal(small[1], 2);
    MdtWorldSetMatrixSizeLog(w, NULL, 0);
    MdtWorldStep(w, 0.01f);
    assert_int_equal(small[1], 2);
    karma_capture_messages();
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetMatrixSizeLog(w, NULL, 3));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetMatrixSizeLog(w, small, -1));
    MdtWorldDestroy(w);
}

static void partition_info_has_karma_counts(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 16, 1, 1);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID a = MdtBodyCreate(w), b = MdtBodyCreate(w);
    MdtBodySetPosition(b, 1, 0, 0);
    MdtBodyEnable(a);
    MdtBodyEnable(b);
    MdtHingeID h = MdtHingeCreate(w);
    MdtHingeSetBodies(h, a, b);
    MdtHingeSetPosition(h, 0.5f, 0, 0);
    MdtHingeEnable(h);
    MdtContactGroupID g = MdtContactGroupCreate(w);
    MdtContactGroupSetBodies(g, a, NULL);
    MdtContactID c1 = MdtContactGroupCreateContact(g), c2 = MdtContactGroupCreateContact(g);
    MdtContactParamsSetType(MdtContactGetParams(c1), MdtContactTypeFriction2D);
    (void)c2;
    MdtContactGroupEnable(g);
    MdtContactID s = MdtContactCreate(w);
    MdtContactSetBodies(s, b, NULL);
    MdtContactEnable(s);
    MdtWorldStep(w, 0.01f);
    assert_int_equal(MdtWorldGetPartitionCount(w), 1);
    MdtPartitionInfo info;
    MdtWorldGetPartitionInfo(w, 0, &info);
    assert_int_equal(info.contactCount, 3);
    assert_int_equal(info.jointCount, 1);
    assert_int_equal(info.constraints, 3);
    assert_int_equal(info.bodies, 2);
    /* Hinge 5, a 2D-friction contact 3, two frictionless contacts 1 each. */
    assert_int_equal(info.rowCount, 10);
    assert_int_equal(info.rows, 10);
    /* The same counts by hand, as a 1.2 program adds them. */
    MdtPartitionInfo mine;
    mine.rowCount = 99;
    MdtPartInfoReset(&mine);
    assert_int_equal(mine.rowCount + mine.contactCount + mine.jointCount + mine.constraints, 0);
    MdtPartInfoAddConstraint(&mine, MdtHingeQuaConstraint(h));
    MdtPartInfoAddConstraint(&mine, MdtContactGroupQuaConstraint(g));
    MdtPartInfoAddConstraint(&mine, MdtContactQuaConstraint(s));
    assert_int_equal(mine.rowCount, info.rowCount);
    assert_int_equal(mine.contactCount, info.contactCount);
    assert_int_equal(mine.jointCount, info.jointCount);
    assert_int_equal(mine.bodies, 0); /* left alone */
    MdtWorldDestroy(w);
}

static void body_is_moving_test_uses_the_thresholds(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodyEnable(b);
    MdtPartitionParams p;
    MdtWorldSetAutoDisableVelocityThreshold(w, 0.25f);
    MdtWorldSetAutoDisableAliveTime(w, 0.5f);
    MdtWorldGetPartitionParams(w, &p);
    assert_true(p.autoDisable);
    assert_true(p.vel_thresh == 0.25f && p.alive_time_thresh == 0.5f);
    assert_true(p.velrot_thresh == MdtWorldGetAutoDisableAngularVelocityThreshold(w));
    assert_true(p.acc_thresh == MdtWorldGetAutoDisableAccelerationThreshold(w));
    assert_int_equal(p.maxMatrixSize, MdtWorldGetMaxMatrixSize(w));
    assert_int_equal(p.debugOptions, 0);
    /* Enabled for one step of 0.01 s: moving until the alive window has passed, whatever its speed. */
    MdtWorldStep(w, 0.01f);
    assert_true(MdtBodyIsMovingTest(b, &p));
    p.alive_time_thresh = 0;
    assert_false(MdtBodyIsMovingTest(b, &p));
    MdtBodySetLinearVelocity(b, 0.4f, 0.3f, 0); /* squared speed 0.25 */
    p.vel_thresh = 0.24f;
    assert_true(MdtBodyIsMovingTest(b, &p));
    p.vel_thresh = 0.26f;
    assert_false(MdtBodyIsMovingTest(b, &p));
    MdtBodySetAngularVelocity(b, 0, 1, 0);
    assert_true(MdtBodyIsMovingTest(b, &p));
    karma_capture_messages();
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtBodyIsMovingTest(b, NULL));
    MdtWorldDestroy(w);
}

/* ---- debug drawing ------------------------------------------------------------------------- */
typedef struct Line {
    MeVector3 start, end;
    MeReal r, g, b;
} Line;
static Line lines[8];
static int lineCount;

static void MEAPI recordLine(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b)
{
    if (lineCount < 8) {
        Line *l = &lines[lineCount];
        MeVector3Copy(l->start, start);
        MeVector3Copy(l->end, end);
        l->r = r;
        l->g = g;
        l->b = b;
    }
    lineCount++;
}

static void debug_drawing_draws_contacts_and_forces(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 4, 1, 1);
    MdtWorldSetAutoDisable(w, MEFALSE);
    MdtBodyID ball = MdtBodyCreate(w); /* 1 kg overlapping the world: the contact pushes it out */
    MdtBodyEnable(ball);
    MdtContactGroupID g = MdtContactGroupCreate(w);
    MdtContactGroupSetBodies(g, ball, NULL);
    MdtContactID c = MdtContactGroupCreateContact(g);
    MdtContactSetPosition(c, 0, -0.5f, 0);
    MdtContactSetNormal(c, 0, 1, 0);
    MdtContactSetPenetration(c, 0.01f);
    MdtContactGroupEnable(g);
    MeDebugLineFuncPtr previous = MeDebugDrawAPI.line;
    MeDebugDrawAPI.line = recordLine;
    lineCount = 0;
    MdtWorldStep(w, 0.01f);
    assert_int_equal(lineCount, 0); /* off by default */

    MdtWorldSetDebugDrawing(w, MdtDebugDrawContacts);
    MdtWorldStep(w, 0.01f);
    assert_int_equal(lineCount, 1);
    MeVector3 n;
    MdtContactGetNormal(c, n);
    const MeReal len = 1 + 50 * MdtContactGetPenetration(c);
    assert_true(lines[0].r == 1 && lines[0].g == 0 && lines[0].b == 0);
    assert_true(fabs(lines[0].start[1] + 0.5) < 1e-6);
    for (int k = 0; k < 3; k++)
        assert_true(fabs(lines[0].end[k] - (lines[0].start[k] + len * n[k])) < 1e-5);

    lineCount = 0;
    MdtWorldSetDebugDrawing(w, MdtDebugDrawContacts | MdtDebugDrawContactForce);
    MeVector3 v0, v1, f, groupForce;
    MdtBodySetLinearVelocity(ball, 0, 0, 0); /* at rest, overlapping: the contact must push */
    MdtBodyGetLinearVelocity(ball, v0);
    MdtWorldStep(w, 0.01f);
    assert_int_equal(lineCount, 2);
    /* The only force on the 1 kg ball is the contact's: f = m dv / h; the group's force is the same. */
    MdtBodyGetLinearVelocity(ball, v1);
    MdtContactGroupGetForce(g, 0, groupForce);
    for (int k = 0; k < 3; k++)
        f[k] = (v1[k] - v0[k]) / 0.01f;
    assert_true(MeVector3Magnitude(f) > 0.1f); /* the contact pushes the overlap out */
    assert_true(lines[1].g == 1 && lines[1].r == 0);
    for (int k = 0; k < 3; k++) {
        assert_true(fabs(lines[1].end[k] - (lines[1].start[k] + f[k])) < 1e-2);
        assert_true(fabs(groupForce[k] - f[k]) < 1e-2);
    }

    karma_capture_messages();
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetDebugDrawing(w, (MdtDebugDrawOptions)0x10));
    MdtWorldReCreate(w); /* back to the default: no drawing */
    lineCount = 0;
    MdtWorldStep(w, 0.01f);
    assert_int_equal(lineCount, 0);
    MeDebugDrawAPI.line = previous;
    MdtWorldDestroy(w);
}

static void kea_debug_request_is_kept_and_file_requests_reported(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtKeaDebugDataRequest quiet = {0, NULL, 0, NULL, 0, NULL, 0, NULL, 3, 0, 0};
    karma_capture_messages();
    MdtWorldSetKeaDebugRequest(w, quiet);
    assert_int_equal(karma_warning_count(), 0);
    MdtKeaDebugDataRequest dump = quiet;
    dump.writeKeaOutputData = 1;
    dump.writeKeaOutputDataFilename = "keaOutput.txt";
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtWorldSetKeaDebugRequest(w, dump));
    MdtWorldDestroy(w);
}

static void chunk_getters_name_the_world_scratch(void **state)
{
    (void)state;
    MdtWorldID w = threePartitions();
    MdtWorldStep(w, 0.01f);
    MeChunk *pool = MdtWorldGetKeaPoolChunk(w), *parts = MdtWorldGetPartitionOutputChunk(w);
    MeChunk *rows = MdtWorldGetKeaConstraintsChunk(w);
    assert_non_null(pool);
    assert_true(pool != parts && parts != rows && pool != rows);
    assert_ptr_equal(MdtWorldGetKeaTMChunk(w), rows);
    assert_true(MeChunkGetMaxSize(parts) > 0 && MeChunkGetMaxSize(rows) > 0);
    assert_false(MeChunkIsInUse(pool));
    karma_capture_messages();
    MdtWorldDestroy(w);
    assert_reports(ME_ERR_INVALID_HANDLE, assert_null(MdtWorldGetKeaPoolChunk(w)));
}

static void check_macros_report_in_the_callers_name(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtBodyID b = MdtBodyCreate(w), gone = MdtBodyCreate(w);
    MdtBodyDestroy(gone);
    MdtHingeID h = MdtHingeCreate(w);
    MdtBSJointID j = MdtBSJointCreate(w);
    karma_capture_messages();
    MdtCHECKWORLD(w, "MyFunction");
    MdtCHECKBODY(b, "MyFunction");
    MdtCHECKBODY_NULL_OK((MdtBodyID)NULL, "MyFunction");
    MdtCHECKHINGE(h, "MyFunction");
    MdtCHECKCONSTRAINT(MdtBSJointQuaConstraint(j), "MyFunction");
    MdtCHECKBODYINDEX(1, "MyFunction");
    MdtCHECKLIMITINDEX3(2, "MyFunction");
    assert_int_equal(karma_warning_count(), 0);
    assert_reports(ME_ERR_WRONG_HANDLE_KIND, MdtCHECKHINGE((MdtHingeID)(void *)j, "MyFunction"));
    assert_string_equal(karma_last_function(), "MyFunction");
    assert_reports(ME_ERR_INVALID_HANDLE, MdtCHECKBODY(gone, "Other"));
    assert_string_equal(karma_last_function(), "Other");
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtCHECKBODY((MdtBodyID)NULL, "MyFunction"));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtCHECKCONTACTPARAMS((MdtContactParamsID)NULL, "MyFunction"));
    assert_reports(ME_ERR_BODY_INDEX, MdtCHECKBODYINDEX(2, "MyFunction"));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MdtCHECKLIMITINDEX3(3, "MyFunction"));
    MdtHingeSetBodies(h, b, NULL);
    MdtCHECKCONSTRAINTBODIES_NULL_OK(h, "MyFunction");
    assert_int_equal(karma_warning_count(), 3 + 3);
    assert_reports(ME_ERR_BAD_STATE, MdtCHECKCONSTRAINTBODIES(h, "MyFunction"));
    MdtWorldDestroy(w);
    assert_reports(ME_ERR_INVALID_HANDLE, MdtCHECKWORLD(w, "MyFunction"));
}

/* Each MdtBclGETMAXROWS macro is the most rows its type writes here. */
static void bcl_max_rows_match_the_constraint_types(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 32, 1, 1);
    const struct {
        MdtConstraintID c;
        int macro;
    } types[] = {
        {MdtBSJointQuaConstraint(MdtBSJointCreate(w)), MdtBclGETMAXROWSBSJOINT},
        {MdtHingeQuaConstraint(MdtHingeCreate(w)), MdtBclGETMAXROWSHINGE},
        {MdtPrismaticQuaConstraint(MdtPrismaticCreate(w)), MdtBclGETMAXROWSPRISMATIC},
        {MdtCarWheelQuaConstraint(MdtCarWheelCreate(w)), MdtBclGETMAXROWSCARWHEEL},
        {MdtContactQuaConstraint(MdtContactCreate(w)), MdtBclGETMAXROWSCONTACT},
        {MdtFixedPathQuaConstraint(MdtFixedPathCreate(w)), MdtBclGETMAXROWSFIXEDPATH},
        {MdtRPROJointQuaConstraint(MdtRPROJointCreate(w)), MdtBclGETMAXROWSRPROJOINT},
        {MdtUniversalQuaConstraint(MdtUniversalCreate(w)), MdtBclGETMAXROWSUNIVERSAL},
        {MdtSkeletalQuaConstraint(MdtSkeletalCreate(w)), MdtBclGETMAXROWSSKELETAL},
        {MdtLinear1QuaConstraint(MdtLinear1Create(w)), MdtBclGETMAXROWSLINEAR1},
        {MdtLinear2QuaConstraint(MdtLinear2Create(w)), MdtBclGETMAXROWSLINEAR2},
        {MdtAngular3QuaConstraint(MdtAngular3Create(w)), MdtBclGETMAXROWSANGULAR3},
        {MdtSpring6QuaConstraint(MdtSpring6Create(w)), MdtBclGETMAXROWSSPRING6},
        {MdtSpringQuaConstraint(MdtSpringCreate(w)), MdtBclGETMAXROWSSPRING},
        {MdtConeLimitQuaConstraint(MdtConeLimitCreate(w)), MdtBclGETMAXROWSCONELIMIT},
    };
    int most = 0;
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++) {
        const MdtConstraintData *c = MdtConstraintFromID(types[i].c, __func__);
        assert_non_null(c);
        assert_int_equal(c->cls->maxRows, types[i].macro);
        if (c->cls->maxRows > most)
            most = c->cls->maxRows;
    }
    assert_int_equal(most, MdtBclGETMAXROWS);
    MdtUserConstraintID u = MdtUserConstraintCreate(w);
    assert_int_equal(MdtUserConstraintGetMaxRows(u), MdtBclGETMAXROWS);
    MdtWorldDestroy(w);
}

/* 1.2's programs name the parameters `struct MdtBclContactParams` or `MdtBclContactParams`. */
static void contact_params_under_karma_tag(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(2, 2, 1, 1);
    MdtContactID c = MdtContactCreate(w);
    struct MdtBclContactParams *p = MdtContactGetParams(c);
    MdtBclContactParams *q = p;
    MdtContactParams *r = q;
    r->restitution = 0.5f;
    assert_true(MdtContactParamsGetRestitution(p) == 0.5f);
    /* 1.2's field order. */
    assert_true(offsetof(MdtBclContactParams, type) < offsetof(MdtBclContactParams, model1));
    assert_true(offsetof(MdtBclContactParams, model2) < offsetof(MdtBclContactParams, options));
    assert_true(offsetof(MdtBclContactParams, options) < offsetof(MdtBclContactParams, restitution));
    assert_true(offsetof(MdtBclContactParams, max_adhesive_force) < offsetof(MdtBclContactParams, friction1));
    assert_true(offsetof(MdtBclContactParams, slip1) < offsetof(MdtBclContactParams, friction2));
    assert_true(offsetof(MdtBclContactParams, slip2) < offsetof(MdtBclContactParams, slide1));
    MdtWorldDestroy(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(contact_set_next_relinks_the_group),
        cmocka_unit_test(kea_memory_required_covers_what_a_solve_uses),
        cmocka_unit_test(cpu_resources_and_cache_calls),
        cmocka_unit_test(matrix_size_log_counts_partitions_by_rows),
        cmocka_unit_test(partition_info_has_karma_counts),
        cmocka_unit_test(body_is_moving_test_uses_the_thresholds),
        cmocka_unit_test(debug_drawing_draws_contacts_and_forces),
        cmocka_unit_test(kea_debug_request_is_kept_and_file_requests_reported),
        cmocka_unit_test(chunk_getters_name_the_world_scratch),
        cmocka_unit_test(check_macros_report_in_the_callers_name),
        cmocka_unit_test(bcl_max_rows_match_the_constraint_types),
        cmocka_unit_test(contact_params_under_karma_tag),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
