/* The simulation check: a NaN or infinity injected into one partition is reported
 * (ME_ERR_NONFINITE_STATE), handed to the sim-error callback, and contained: the partition is put back
 * to its pose at the start of the step, stopped and disabled, while every other partition simulates
 * bit for bit as it would in a world without the bad one. */
#include "karma_test.h"
#include "karma_contacts.h"

#include <string.h>

#include <karma/Mdt.h>

enum { LINKS = 4, COLUMN = 3, STEPS = 120, INJECT = 30 };

typedef struct Scene {
    MdtWorldID world;
    MdtBodyID link[LINKS], box[COLUMN], bad, freeBody;
    MdtContactGroupID group[COLUMN], badGround;
    MdtContactParams params;
} Scene;

static const MeVector3 half = {0.5f, 0.5f, 0.5f}, up = {0, 0, 1};

static MdtBodyID boxAt(MdtWorldID w, MeReal x, MeReal z)
{
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetPosition(b, x, 0, z);
    MdtBodyEnable(b);
    return b;
}

/* A swinging chain and a column (the healthy partitions); with `withBad`, also a box on the ground and
 * a free body, the partitions that will fail. */
static void build(Scene *s, int withBad)
{
    memset(s, 0, sizeof *s);
    s->world = MdtWorldCreate(16, 32, 1, 1);
    MdtWorldSetGravity(s->world, 0, 0, -9.81f);
    MdtWorldSetAutoDisable(s->world, MEFALSE);
    karma_contact_params_friction(&s->params, 0.5f);
    for (int i = 0; i < LINKS; i++) {
        s->link[i] = boxAt(s->world, (MeReal)(i + 1), 10);
        MdtBSJointID j = MdtBSJointCreate(s->world);
        MdtBSJointSetBodies(j, s->link[i], i ? s->link[i - 1] : NULL);
        MdtBSJointSetPosition(j, (MeReal)i, 0, 10);
        MdtBSJointEnable(j);
    }
    for (int i = 0; i < COLUMN; i++) {
        s->box[i] = boxAt(s->world, 5, 0.5f + (MeReal)i);
        s->group[i] = MdtContactGroupCreate(s->world);
        MdtContactGroupSetBodies(s->group[i], s->box[i], i ? s->box[i - 1] : NULL);
        MdtContactGroupEnable(s->group[i]);
    }
    if (!withBad)
        return;
    s->bad = boxAt(s->world, -5, 0.5f);
    s->badGround = MdtContactGroupCreate(s->world);
    MdtContactGroupSetBodies(s->badGround, s->bad, NULL);
    MdtContactGroupEnable(s->badGround);
    s->freeBody = boxAt(s->world, -10, 5);
}

static void step(Scene *s)
{
    for (int i = 0; i < COLUMN; i++) {
        if (i == 0)
            karma_box_on_plane(s->group[0], s->box[0], half, up, 0, &s->params);
        else
            karma_box_on_box(s->group[i], s->box[i], s->box[i - 1], half, &s->params);
    }
    if (s->bad)
        karma_box_on_plane(s->badGround, s->bad, half, up, 0, &s->params);
    MdtWorldStep(s->world, ME_R(1.0) / 60);
}

/* Hash of the healthy partitions' state. */
static uint64_t healthyHash(const Scene *s)
{
    uint64_t h = KARMA_HASH_INIT;
    MdtBodyID bodies[LINKS + COLUMN];
    memcpy(bodies, s->link, sizeof s->link);
    memcpy(bodies + LINKS, s->box, sizeof s->box);
    for (int i = 0; i < LINKS + COLUMN; i++) {
        h = karma_hash_bytes(h, MdtBodyGetTransformPtr(bodies[i]), sizeof(MeMatrix4));
        h = karma_hash_bytes(h, MdtBodyGetLinearVelocityPtr(bodies[i]), 3 * sizeof(MeReal));
        h = karma_hash_bytes(h, MdtBodyGetAngularVelocityPtr(bodies[i]), 3 * sizeof(MeReal));
    }
    return h;
}

typedef struct Seen {
    int calls;
    MdtSimError last;
    MdtBodyID firstBody;
    MeVector3 badVelocity; /* as the callback saw it */
} Seen;

static void onSimError(MdtWorldID w, const MdtSimError *e, void *data)
{
    Seen *seen = data;
    (void)w;
    seen->calls++;
    seen->last = *e;
    seen->firstBody = e->bodies[0];
    MdtBodyGetLinearVelocity(e->bodies[0], seen->badVelocity);
    /* The world is locked during the callback. */
    assert_null(MdtBodyCreate(w));
}

static void nan_is_contained_to_its_partition(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene clean, dirty;
    build(&clean, 0);
    build(&dirty, 1);
    Seen seen = {0};
    MdtWorldSetSimErrorHandler(dirty.world, onSimError, &seen);
    assert_true(MdtWorldGetCheckSim(dirty.world));
    int identical = 1;
    MeVector3 before = {0, 0, 0}, after, v;
    MeVector3 freeBefore = {0, 0, 0};
    for (int i = 0; i < STEPS; i++) {
        if (i == INJECT) {
            /* A corrupted velocity written through the pointer API: the box's contact rows get a NaN
             * right-hand side, so the solver refuses the partition (MdtSimErrorSolver). */
            MdtBodyGetPosition(dirty.bad, before);
            MdtBodyGetLinearVelocityPtr(dirty.bad)[2] = (MeReal)NAN;
        }
        if (i == INJECT + 10) {
            /* A user force that overflows its accumulator: the free body's state becomes infinite
             * (MdtSimErrorState: it has no rows to solve). */
            MdtBodyGetPosition(dirty.freeBody, freeBefore);
            MdtBodyAddForce(dirty.freeBody, MEINFINITY, 0, 0);
            MdtBodyAddForce(dirty.freeBody, MEINFINITY, 0, 0);
        }
        unsigned long reports = MeMessageGetCount(ME_ERR_NONFINITE_STATE);
        step(&clean);
        step(&dirty);
        unsigned long now = MeMessageGetCount(ME_ERR_NONFINITE_STATE) - reports;
        assert_int_equal(now, (i == INJECT || i == INJECT + 10) ? 1 : 0);
        identical &= healthyHash(&clean) == healthyHash(&dirty);
        if (i == INJECT) {
            assert_int_equal(seen.calls, 1);
            assert_int_equal(seen.last.kind, MdtSimErrorSolver);
            assert_int_equal(seen.last.bodyCount, 1);
            assert_int_equal(seen.last.rows, 12);
            assert_ptr_equal(seen.firstBody, dirty.bad);
            assert_true(isnan(seen.badVelocity[2])); /* the callback saw the bad state */
            MdtBodyGetPosition(dirty.bad, after);
            assert_memory_equal(after, before, sizeof before); /* restored */
            MdtBodyGetLinearVelocity(dirty.bad, v);
            assert_true(v[0] == 0 && v[1] == 0 && v[2] == 0);
            assert_false(MdtBodyIsEnabled(dirty.bad));
            MdtWorldCounters c;
            MdtWorldGetCounters(dirty.world, &c);
            assert_int_equal(c.simErrors, 1);
        }
        if (i == INJECT + 10) {
            assert_int_equal(seen.calls, 2);
            assert_int_equal(seen.last.kind, MdtSimErrorState);
            assert_int_equal(seen.last.rows, 0);
            MdtBodyGetPosition(dirty.freeBody, after);
            assert_memory_equal(after, freeBefore, sizeof after);
            assert_false(MdtBodyIsEnabled(dirty.freeBody));
        }
    }
    MeVector3 top;
    MdtBodyGetPosition(dirty.link[LINKS - 1], top);
    double moved = sqrt((top[0] - LINKS) * (top[0] - LINKS) + top[1] * top[1] + (top[2] - 10) * (top[2] - 10));
    print_message("NaN at step %d in one partition, overflow at step %d in another: %d callbacks; healthy "
                  "partitions %s after %d steps (chain end moved %.3f m)\n",
                  INJECT, INJECT + 10, seen.calls, identical ? "bit-identical to the clean world" : "DIFFER", STEPS,
                  moved);
    assert_true(identical);
    assert_int_equal(seen.calls, 2);
    assert_true(moved > 0.5); /* the chain did swing */

    /* Enabled again, the failed box simulates normally: nothing non-finite was kept (warm starts). */
    MdtBodyEnable(dirty.bad);
    MdtBodyEnable(dirty.freeBody);
    for (int i = 0; i < 60; i++)
        step(&dirty);
    MdtBodyGetPosition(dirty.bad, after);
    assert_int_equal(seen.calls, 2);
    assert_true(MdtBodyIsEnabled(dirty.bad));
    assert_near(after[2], 0.5, 0.01);
    assert_near(after[0], -5, 1e-3);
    MdtWorldDestroy(clean.world);
    MdtWorldDestroy(dirty.world);
}

/* Without a callback the report is still made; the default callback prints the partition. */
static void default_callback_and_settings(void **state)
{
    (void)state;
    karma_capture_messages();
    Scene s;
    build(&s, 1);
    MdtWorldSetCheckSim(s.world, MEFALSE);
    assert_false(MdtWorldGetCheckSim(s.world));
    MdtWorldSetCheckSim(s.world, METRUE);
    MdtWorldSetSimErrorHandler(s.world, MdtDefaultSimErrorHandler, NULL);
    MdtBodyGetAngularVelocityPtr(s.bad)[0] = (MeReal)INFINITY;
    unsigned long infos = MeMessageGetCount(ME_ERR_USER_MESSAGE);
    assert_reports(ME_ERR_NONFINITE_STATE, step(&s));
    assert_true(MeMessageGetCount(ME_ERR_USER_MESSAGE) - infos >= 2); /* header + one line per body */
    assert_false(MdtBodyIsEnabled(s.bad));
    MdtWorldDestroy(s.world);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(nan_is_contained_to_its_partition),
        cmocka_unit_test(default_callback_and_settings),
    };
    MeSetMessageLevel(ME_LEVEL_WARNING);
    return cmocka_run_group_tests(tests, NULL, NULL);
}
