/* The bridge's mechanics: material table, contact groups following the pairs' lives, body order with
 * world models, callbacks, freeze/unfreeze linkage, universe sizes and bad input. */
#include "karma_test.h"

#include <string.h>

#include <karma/karma.h>

#include "karma_ground.h"

/* A universe with gravity along −z and a ground plane at z = 0. */
typedef KarmaGround Scene;

static void sceneInit(Scene *s)
{
    karma_ground_init(s, 500); /* the bodies here are of a few hundred kilograms: ε scales with 1/massScale */
}

static McdModelID sphereAt(Scene *s, MeReal r, MeReal x, MeReal y, MeReal z)
{
    McdModelID m = MstModelAndBodyCreate(s->u, McdSphereCreate(s->fw, r), 1000);
    assert_non_null(m);
    MdtBodySetPosition(McdModelGetBody(m), x, y, z);
    return m;
}

static void universe_defaults(void **state)
{
    (void)state;
    MstUniverseSizes d = MstUniverseDefaultSizes;
    assert_int_equal(d.dynamicBodiesMaxCount, 100);
    assert_int_equal(d.dynamicConstraintsMaxCount, 500);
    assert_int_equal(d.materialsMaxCount, 10);
    assert_int_equal(d.collisionModelsMaxCount, 100);
    assert_int_equal(d.collisionPairsMaxCount, 500);
    assert_int_equal(d.collisionUserGeometryTypesMaxCount, 0);
    assert_int_equal(d.collisionGeometryInstancesMaxCount, 100);
    assert_true(d.lengthScale == 1 && d.massScale == 1);
    karma_capture_messages();
    d.materialsMaxCount = 0;
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_null(MstUniverseCreate(&d)));
    d = MstUniverseDefaultSizes;
    d.lengthScale = -1;
    assert_reports(ME_ERR_SCALE_NOT_POSITIVE, assert_null(MstUniverseCreate(&d)));
}

static void material_table_is_symmetric(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    assert_int_equal(MstBridgeGetDefaultMaterial(), 0);
    assert_int_equal(MstBridgeGetMaterialCount(s.b), 1);
    MstMaterialID a = MstBridgeGetNewMaterial(s.b), c = MstBridgeGetNewMaterial(s.b);
    assert_int_equal(a, 1);
    assert_int_equal(c, 2);
    MdtContactParamsID p = MstBridgeGetContactParams(s.b, a, c);
    assert_ptr_equal(p, MstBridgeGetContactParams(s.b, c, a));
    assert_ptr_not_equal(p, MstBridgeGetContactParams(s.b, a, a));
    /* Karma's default pair: frictionless. */
    assert_int_equal(MdtContactParamsGetType(p), MdtContactTypeFrictionZero);
    karma_capture_messages();
    assert_reports(ME_ERR_MST_MATERIAL, assert_null(MstBridgeGetContactParams(s.b, 0, 3)));
    assert_reports(ME_ERR_MST_MATERIAL, assert_null(MstBridgeGetContactParams(s.b, MST_MATERIAL_INVALID, 0)));
    for (int i = 3; i < 10; i++)
        assert_int_equal(MstBridgeGetNewMaterial(s.b), i);
    assert_reports(ME_ERR_POOL_FULL, assert_int_equal(MstBridgeGetNewMaterial(s.b), MST_MATERIAL_INVALID));
    MstUniverseDestroy(s.u);
    assert_reports(ME_ERR_INVALID_HANDLE, MstUniverseStep(s.u, 0.01f));
}

static MdtContactGroupID groupOf(MdtBodyID body)
{
    for (MdtConstraintID c = MdtBodyGetFirstConstraint(body); c; c = MdtBodyGetNextConstraint(body, c)) {
        MdtContactGroupID g = MdtConstraintDCastContactGroup(c);
        if (g)
            return g;
    }
    return NULL;
}

/* A ball resting on the ground: the world model is model 1 of the pair (lower sort key) but the group
 * has the ball as body 0, the world as body 1, and its normal points from the ground up into the ball
 * (from body 1 towards body 0: the direction in which the ball is pushed). */
static void group_lives_with_the_intersection(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    McdModelSetSortKey(s.ground, 0);
    McdModelID ball = sphereAt(&s, 0.5f, 0, 0, 0.495f);
    McdModelSetSortKey(ball, 1);
    MdtBodyID body = McdModelGetBody(ball);
    MstUniverseStep(s.u, 1.0f / 60);
    MdtContactGroupID g = groupOf(body);
    assert_non_null(g);
    assert_ptr_equal(MdtConstraintGetBody(MdtContactGroupQuaConstraint(g), 0), body);
    assert_null(MdtConstraintGetBody(MdtContactGroupQuaConstraint(g), 1));
    assert_int_equal(MdtContactGroupGetCount(g), 1);
    MeVector3 n;
    MdtContactGetNormal(MdtContactGroupGetFirstContact(g), n);
    printf("ball on plane: normal (%.3f %.3f %.3f), penetration %.4f\n", (double)n[0], (double)n[1], (double)n[2],
           (double)MdtContactGetPenetration(MdtContactGroupGetFirstContact(g)));
    assert_near(n[2], 1, 1e-5);
    assert_true(MdtContactGroupIsSwapped(g)); /* model 1 is the ground: the pair was turned round */
    /* Lift the ball clear: the group goes when the models stop intersecting... */
    MdtBodySetPosition(body, 0, 0, 0.6f);
    MdtBodySetLinearVelocity(body, 0, 0, 0);
    MstUniverseStep(s.u, 1.0f / 60);
    assert_null(groupOf(body));
    /* ...and comes back when they touch again; moving far away (Goodbye) removes it too. */
    MdtBodySetPosition(body, 0, 0, 0.49f);
    MstUniverseStep(s.u, 1.0f / 60);
    assert_non_null(groupOf(body));
    MdtBodySetPosition(body, 0, 0, 50);
    MstUniverseStep(s.u, 1.0f / 60);
    assert_null(groupOf(body));
    assert_int_equal(MdtWorldGetTotalConstraints(s.w), 0);
    MstUniverseDestroy(s.u);
}

/* The conversion carries each McdContact's position, normal (body 1 towards body 0) and penetration
 * (the negated separation) into the group's MdtContact, and the material's parameters; a pair that
 * stays reuses its contact and refreshes all of it. */
static void conversion_carries_the_geometry(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    MstMaterialID rubber = MstBridgeGetNewMaterial(s.b);
    MdtContactParamsSetFriction(MstBridgeGetContactParams(s.b, 0, rubber), 0.75f);
    McdModelID ball = sphereAt(&s, 0.5f, 0.3f, -0.2f, 0.49f);
    McdModelSetMaterial(ball, rubber);
    MdtBodyID body = McdModelGetBody(ball);
    McdSpaceID space = MstUniverseGetSpace(s.u);
    const MeReal heights[2] = {0.49f, 0.47f};
    MdtContactID first = NULL;
    for (int k = 0; k < 2; k++) {
        MdtBodySetPosition(body, 0.3f, -0.2f, heights[k]);
        McdSpaceUpdateAll(space);
        MstBridgeUpdateContacts(s.b, space, s.w);
        MdtContactGroupID g = groupOf(body);
        assert_non_null(g);
        assert_int_equal(MdtContactGroupGetCount(g), 1);
        MdtContactID c = MdtContactGroupGetFirstContact(g);
        if (k == 0)
            first = c;
        else
            assert_ptr_equal(c, first); /* reused: warm start follows the point */
        MeVector3 p, n;
        MdtContactGetPosition(c, p);
        MdtContactGetNormal(c, n);
        assert_near(p[0], 0.3, 1e-5);
        assert_near(p[1], -0.2, 1e-5);
        assert_true(p[2] > -0.05 && p[2] < 0.05);
        assert_near(n[0], 0, 1e-6);
        assert_near(n[1], 0, 1e-6);
        assert_near(n[2], 1, 1e-6);
        assert_near(MdtContactGetPenetration(c), 0.5 - heights[k], 1e-5);
        assert_near(MdtContactParamsGetPrimaryFriction(MdtContactGetParams(c)), 0.75, 0);
    }
    MstUniverseDestroy(s.u);
}

/* The sense of a bridge-made contact, in both orders of the pair's models: a ball dropped onto the
 * ground from 5 cm gets a contact whose normal is +z (the ground pushes the ball up), with the ball as
 * body 0 whether the ground is model 1 (the pair turned round, normals negated) or model 2 (copied as
 * they are); it lands and stays on the ground, never sinking more than a few millimetres. */
static void bridge_normal_pushes_the_ball_up_in_both_orders(void **state)
{
    (void)state;
    for (int groundFirst = 0; groundFirst < 2; groundFirst++) {
        Scene s;
        sceneInit(&s);
        McdModelSetSortKey(s.ground, groundFirst ? 0 : 1);
        McdModelID ball = sphereAt(&s, 0.5f, 0, 0, 0.55f);
        McdModelSetSortKey(ball, groundFirst ? 1 : 0);
        MdtBodyID body = McdModelGetBody(ball);
        double lowest = 1e9;
        MdtContactGroupID g = NULL;
        MeVector3 n = {0, 0, 0};
        for (int i = 0; i < 120; i++) {
            MstUniverseStep(s.u, 1.0f / 60);
            MeVector3 p;
            MdtBodyGetPosition(body, p);
            lowest = fmin(lowest, p[2]);
            if (!g && (g = groupOf(body)) != NULL) {
                MdtContactGetNormal(MdtContactGroupGetFirstContact(g), n);
                assert_ptr_equal(MdtConstraintGetBody(MdtContactGroupQuaConstraint(g), 0), body);
                assert_null(MdtConstraintGetBody(MdtContactGroupQuaConstraint(g), 1));
                assert_int_equal(MdtContactGroupIsSwapped(g), groundFirst);
            }
        }
        MeVector3 p, v;
        MdtBodyGetPosition(body, p);
        MdtBodyGetLinearVelocity(body, v);
        printf("ground model %d: normal (%.3f %.3f %.3f), lowest centre %.5f, after 2 s z %.5f, vz %.1e\n",
               groundFirst ? 1 : 2, (double)n[0], (double)n[1], (double)n[2], lowest, (double)p[2], (double)v[2]);
        assert_non_null(g);
        assert_near(n[0], 0, 1e-6);
        assert_near(n[1], 0, 1e-6);
        assert_near(n[2], 1, 1e-6);
        assert_true(lowest > 0.5 - 0.005);
        assert_near(p[2], 0.5, 0.005);
        assert_near(v[2], 0, 1e-3);
        MstUniverseDestroy(s.u);
    }
}

/* The bridge's one-call contact update (MdtContactSetFromCollision) checks each field as its own
 * setter does: a non-finite or zero field is reported and skipped, the others are set. */
static void collision_update_skips_bad_fields_one_by_one(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(4, 8, 1, 1);
    MdtBodyID b = MdtBodyCreate(w);
    MdtContactID c = MdtContactCreate(w);
    MdtContactSetBodies(c, b, NULL);
    MdtContactParams params;
    MdtContactParamsReset(&params);
    MdtContactParamsSetFriction(&params, 0.25f);
    const MeReal pos[3] = {1, 2, 3}, normal[3] = {0, 0, 2}, down[3] = {0, 0, -2}, nanPos[3] = {1, NAN, 3},
                 zero[3] = {0, 0, 0};
    MeVector3 p, n;
    MdtContactSetFromCollision(c, &params, pos, down, 0.01f); /* all good; normal made unit */
    MdtContactGetPosition(c, p);
    MdtContactGetNormal(c, n);
    assert_true(p[0] == 1 && p[1] == 2 && p[2] == 3);
    assert_true(n[0] == 0 && n[1] == 0 && n[2] == -1);
    assert_near(MdtContactGetPenetration(c), 0.01, 1e-7);
    assert_near(MdtContactParamsGetPrimaryFriction(MdtContactGetParams(c)), 0.25, 0);
    /* a NaN position: reported as MdtContactSetPosition would, the rest still set */
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtContactSetFromCollision(c, &params, nanPos, normal, 0.02f));
    MdtContactGetPosition(c, p);
    MdtContactGetNormal(c, n);
    assert_true(p[1] == 2 && n[2] == 1);
    assert_near(MdtContactGetPenetration(c), 0.02, 1e-7);
    /* a zero normal and a NaN penetration: both reported, position set */
    assert_reports(ME_ERR_ZERO_AXIS, MdtContactSetFromCollision(c, &params, normal, zero, 0.03f));
    MdtContactGetPosition(c, p);
    assert_true(p[2] == 2);
    assert_reports(ME_ERR_NONFINITE_ARGUMENT, MdtContactSetFromCollision(c, &params, pos, normal, NAN));
    assert_near(MdtContactGetPenetration(c), 0.03, 1e-7);
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtContactSetFromCollision(c, NULL, pos, normal, 0.04f));
    assert_near(MdtContactGetPenetration(c), 0.04, 1e-7);
    /* NULL position or normal, or a bad contact ID: refused, nothing set */
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtContactSetFromCollision(c, &params, NULL, normal, 0.05f));
    assert_reports(ME_ERR_NULL_ARGUMENT, MdtContactSetFromCollision(c, &params, pos, NULL, 0.05f));
    assert_near(MdtContactGetPenetration(c), 0.04, 1e-7);
    MdtContactDestroy(c);
    assert_reports(ME_ERR_INVALID_HANDLE, MdtContactSetFromCollision(c, &params, pos, normal, 0.05f));
    MdtWorldDestroy(w);
}

/* The bridge's one-call read of a group: its contacts in the group's order with their positions, at
 * most `max`; positions optional; a bad group, a NULL array or a negative max refused. */
static void group_contacts_and_positions_in_order(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(4, 8, 1, 1);
    MdtContactGroupID g = MdtContactGroupCreate(w);
    MdtContactID made[3];
    for (int i = 0; i < 3; i++) {
        made[i] = MdtContactGroupCreateContact(g);
        MdtContactSetPosition(made[i], (MeReal)i, 10 + (MeReal)i, 0);
    }
    MdtContactID got[3] = {NULL, NULL, NULL};
    MeVector3 where[3];
    assert_int_equal(MdtContactGroupGetContactsAndPositions(g, got, where, 3), 3);
    for (int i = 0; i < 3; i++) {
        assert_ptr_equal(got[i], made[i]);
        assert_true(where[i][0] == (MeReal)i && where[i][1] == 10 + (MeReal)i && where[i][2] == 0);
    }
    got[1] = NULL;
    assert_int_equal(MdtContactGroupGetContactsAndPositions(g, got, NULL, 1), 1);
    assert_ptr_equal(got[0], made[0]);
    assert_null(got[1]); /* room for one: only one written */
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(MdtContactGroupGetContactsAndPositions(g, NULL, where, 3), 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(MdtContactGroupGetContactsAndPositions(g, got, where, -1), 0));
    MdtContactGroupDestroy(g);
    assert_reports(ME_ERR_INVALID_HANDLE, assert_int_equal(MdtContactGroupGetContactsAndPositions(g, got, where, 3), 0));
    MdtWorldDestroy(w);
}

/* A group refreshed from collision points in one call: each point takes the nearest old contact not
 * yet taken (its warm start with it), a point with none left gets a new contact appended, old
 * contacts no point took are destroyed; the fields are set as MdtContactSetFromCollision sets them;
 * a full constraint pool stops at the point it could not serve; bad arguments are refused. */
static void group_refresh_takes_the_nearest_old_contacts(void **state)
{
    (void)state;
    karma_capture_messages();
    MdtWorldID w = MdtWorldCreate(4, 5, 1, 1); /* room for the group and four contacts */
    MdtContactGroupID g = MdtContactGroupCreate(w);
    MdtContactID made[3];
    for (int i = 0; i < 3; i++) {
        made[i] = MdtContactGroupCreateContact(g);
        MdtContactSetPosition(made[i], (MeReal)i, 0, 0);
    }
    MdtContactParams params;
    MdtContactParamsReset(&params);
    MdtContactParamsSetFriction(&params, 3);
    MdtCollisionPoint points[4] = {{{2.1f, 0, 0}, {0, 0, 2}, 0.01f}, {{0.1f, 0, 0}, {0, 1, 0}, 0.02f}};
    MdtContactID out[4] = {NULL, NULL, NULL, NULL};
    assert_int_equal(MdtContactGroupSetFromCollisions(g, &params, points, 2, out), 2);
    assert_ptr_equal(out[0], made[2]);
    assert_ptr_equal(out[1], made[0]);
    assert_false(MdtConstraintIsValid(MdtContactQuaConstraint(made[1]))); /* no point took it */
    MdtContactID got[3];
    assert_int_equal(MdtContactGroupGetContactsAndPositions(g, got, NULL, 3), 2);
    assert_ptr_equal(got[0], made[0]); /* the group's order kept */
    assert_ptr_equal(got[1], made[2]);
    MeVector3 p, n;
    MdtContactGetPosition(made[2], p);
    MdtContactGetNormal(made[2], n);
    assert_true(p[0] == 2.1f && n[0] == 0 && n[1] == 0 && n[2] == 1); /* the normal made unit */
    assert_true(MdtContactGetPenetration(made[2]) == (MeReal)0.01f);
    assert_near(MdtContactParamsGetPrimaryFriction(MdtContactGetParams(made[0])), 3, 0);
    /* four points on three old contacts: each takes the nearest one left, the last a new one */
    MdtCollisionPoint more[5] = {{{0, 0, 0}, {0, 1, 0}, 0}, {{9, 0, 0}, {0, 1, 0}, 0}, {{2, 0, 0}, {0, 1, 0}, 0},
                                 {{8, 0, 0}, {0, 1, 0}, 0}, {{7, 0, 0}, {0, 1, 0}, 0}};
    MdtContactID extra = MdtContactGroupCreateContact(g);
    MdtContactSetPosition(extra, 100, 0, 0);
    assert_int_equal(MdtContactGroupSetFromCollisions(g, &params, more, 4, out), 4);
    assert_ptr_equal(out[0], made[0]);
    assert_ptr_equal(out[1], made[2]); /* nearer to (9, 0, 0) than extra */
    assert_ptr_equal(out[2], extra);
    assert_true(out[3] && out[3] != made[0] && out[3] != made[2] && out[3] != extra);
    assert_int_equal(MdtContactGroupGetCount(g), 4);
    /* a fifth point finds the pool full: the four served, the fifth left out */
    assert_reports(ME_ERR_POOL_FULL, assert_int_equal(MdtContactGroupSetFromCollisions(g, &params, more, 5, out), 4));
    assert_int_equal(MdtContactGroupGetCount(g), 4);
    /* bad arguments: nothing changed */
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(MdtContactGroupSetFromCollisions(g, NULL, more, 1, out), 0));
    assert_reports(ME_ERR_NULL_ARGUMENT, assert_int_equal(MdtContactGroupSetFromCollisions(g, &params, NULL, 1, out), 0));
    assert_reports(ME_ERR_ARGUMENT_RANGE, assert_int_equal(MdtContactGroupSetFromCollisions(g, &params, more, -1, out), 0));
    assert_int_equal(MdtContactGroupGetCount(g), 4);
    MdtContactGroupDestroy(g);
    assert_reports(ME_ERR_INVALID_HANDLE, assert_int_equal(MdtContactGroupSetFromCollisions(g, &params, more, 1, out), 0));
    MdtWorldDestroy(w);
}

static int perContactCalls, perPairCalls, intersectCalls;
static void countIntersect(McdIntersectResult *r)
{
    (void)r;
    intersectCalls++;
}
static MeBool dropContacts(McdIntersectResult *r, McdContact *c, MdtContactID d)
{
    (void)r;
    (void)c;
    (void)d;
    perContactCalls++;
    return MEFALSE;
}
static MeBool keepPair(McdIntersectResult *r, MdtContactGroupID g)
{
    (void)r;
    (void)g;
    perPairCalls++;
    return METRUE;
}

/* Callbacks run per material pair; a per-contact callback that drops everything makes the ball fall
 * through the floor; parameters are copied into each contact. */
static void callbacks_and_parameters(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    MstMaterialID rubber = MstBridgeGetNewMaterial(s.b);
    MdtContactParamsID p = MstBridgeGetContactParams(s.b, 0, rubber);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFriction(p, 7);
    McdModelID ball = sphereAt(&s, 0.5f, 0, 0, 0.49f);
    McdModelSetMaterial(ball, rubber);
    MstBridgeSetIntersectCB(s.b, rubber, 0, countIntersect);
    MstBridgeSetPerPairCB(s.b, rubber, 0, keepPair);
    assert_ptr_equal(MstBridgeGetPerPairCB(s.b, 0, rubber), keepPair);
    MstUniverseStep(s.u, 1.0f / 60);
    MdtContactGroupID g = groupOf(McdModelGetBody(ball));
    assert_non_null(g);
    MdtContactParamsID cp = MdtContactGetParams(MdtContactGroupGetFirstContact(g));
    assert_int_equal(MdtContactParamsGetType(cp), MdtContactTypeFriction2D);
    assert_near(MdtContactParamsGetPrimaryFriction(cp), 7, 0);
    assert_int_equal(intersectCalls, 1);
    assert_int_equal(perPairCalls, 1);
    MstBridgeSetPerContactCB(s.b, 0, rubber, dropContacts);
    for (int i = 0; i < 60; i++)
        MstUniverseStep(s.u, 1.0f / 60);
    MeVector3 pos;
    MdtBodyGetPosition(McdModelGetBody(ball), pos);
    printf("contacts dropped by callback: %d calls, ball at z = %.3f after 1 s\n", perContactCalls, (double)pos[2]);
    assert_true(perContactCalls >= 1);
    assert_true(pos[2] < -1);
    MstUniverseStep(s.u, 1.0f / 60);
    MstUniverseDestroy(s.u);
}

/* An intersect callback may hand the bridge as many contacts as the buffer the user set: here a
 * 17 x 17 grid (289 contacts, more than any fixed inner limit the bridge once had: 64 old contacts
 * matched per group, 256 converted per pair) spread over the lower face of a box resting on the
 * ground, the face's corners taken from the box-plane test's own contacts. Every step must convert
 * all of them into one group of exactly that many contacts (the old ones reused, none left over),
 * and together they must carry the box's weight. */
#define GRID 17
static void contactGrid(McdIntersectResult *r)
{
    if (r->contactCount < 4 || r->contactMaxCount < GRID * GRID)
        return;
    MeReal lo[2] = {MEINFINITY, MEINFINITY}, hi[2] = {-MEINFINITY, -MEINFINITY};
    for (int i = 0; i < r->contactCount; i++)
        for (int k = 0; k < 2; k++) {
            const MeReal x = r->contacts[i].position[k];
            lo[k] = x < lo[k] ? x : lo[k];
            hi[k] = x > hi[k] ? x : hi[k];
        }
    const McdContact corner = r->contacts[0];
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            McdContact *c = &r->contacts[i * GRID + j];
            *c = corner;
            c->position[0] = lo[0] + (hi[0] - lo[0]) * (MeReal)i / (GRID - 1);
            c->position[1] = lo[1] + (hi[1] - lo[1]) * (MeReal)j / (GRID - 1);
        }
    r->contactCount = GRID * GRID;
}

static void contact_buffer_size_is_the_only_limit(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    MdtWorldSetAutoDisable(s.w, MEFALSE); /* the pair is tested every step */
    MstBridgeSetContactBufferSize(s.b, GRID * GRID);
    MstBridgeSetIntersectCB(s.b, 0, 0, contactGrid);
    McdModelID box = MstModelAndBodyCreate(s.u, McdBoxCreate(s.fw, 1, 1, 0.2f), 500);
    assert_non_null(box);
    MdtBodyID body = McdModelGetBody(box);
    MdtBodySetPosition(body, 0, 0, 0.0995f); /* resting, half a millimetre into the ground */
    const double weight = (double)MdtBodyGetMass(body) * 9.81;
    karma_capture_messages();
    double force = 0;
    for (int step = 0; step < 60; step++) {
        MstUniverseStep(s.u, 1.0f / 60);
        MdtContactGroupID g = groupOf(body);
        assert_non_null(g);
        assert_int_equal(MstBridgeGetLastContactCount(s.b), GRID * GRID);
        assert_int_equal(MdtContactGroupGetCount(g), GRID * GRID);
        force = (double)MdtContactGroupGetNormalForce(g);
    }
    MeVector3 v;
    MdtBodyGetLinearVelocity(body, v);
    print_message("%d contacts on one pair: normal force %.2f N for a weight of %.2f N, |v| %.2e m/s\n", GRID * GRID,
                  force, weight, (double)MeVector3Magnitude(v));
    assert_int_equal(karma_warning_count(), 0);
    assert_rel(force, weight, 0.02);
    assert_true(MeVector3Magnitude(v) < 1e-2f);
    MstUniverseDestroy(s.u);
}

/* A ball that comes to rest is disabled and its model frozen; a push wakes both. */
static void freeze_follows_disable(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    MdtContactParamsID p = MstBridgeGetContactParams(s.b, 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, 0.6f);
    McdModelID ball = sphereAt(&s, 0.5f, 0, 0, 0.6f);
    MdtBodyID body = McdModelGetBody(ball);
    int steps = 0;
    while (MdtBodyIsEnabled(body) && steps < 600) {
        MstUniverseStep(s.u, 1.0f / 60);
        steps++;
    }
    printf("ball came to rest and was disabled after %d steps\n", steps);
    assert_false(MdtBodyIsEnabled(body));
    assert_true(McdSpaceModelIsFrozen(ball));
    MeVector3 pos;
    MdtBodyGetPosition(body, pos);
    assert_near(pos[2], 0.5, 0.01);
    MdtBodyEnable(body);
    assert_false(McdSpaceModelIsFrozen(ball));
    MdtBodyAddImpulse(body, 1000, 0, 0); /* 1.9 m/s for the 523 kg ball */
    for (int i = 0; i < 30; i++)
        MstUniverseStep(s.u, 1.0f / 60);
    MdtBodyGetPosition(body, pos);
    assert_true(pos[0] > 0.5);
    assert_near(pos[2], 0.5, 0.01);
    MstUniverseDestroy(s.u);
}

static void model_and_body_helpers(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    McdModelID box = MstModelAndBodyCreate(s.u, McdBoxCreate(s.fw, 1, 2, 3), 500);
    assert_non_null(box);
    MdtBodyID body = McdModelGetBody(box);
    assert_true(MdtBodyIsEnabled(body));
    assert_near(MdtBodyGetMass(body), 500 * 6, 1e-3);
    MeMatrix3 I;
    MdtBodyGetInertiaTensor(body, I);
    const double m = 3000;
    printf("box 1x2x3 at 500 kg/m^3: mass %.1f, Ixx %.2f (expected %.2f)\n", (double)MdtBodyGetMass(body),
           (double)I[0][0], m * (4 + 9) / 12);
    assert_rel(I[0][0], m * (4 + 9) / 12, 1e-5);
    assert_rel(I[1][1], m * (1 + 9) / 12, 1e-5);
    assert_rel(I[2][2], m * (1 + 4) / 12, 1e-5);
    assert_ptr_equal(McdModelGetTransformPtr(box), MdtBodyGetTransformPtr(body));
    karma_capture_messages();
    assert_reports(ME_ERR_MASS_NOT_POSITIVE, assert_null(MstModelAndBodyCreate(s.u, McdSphereCreate(s.fw, 1), 0)));
    assert_reports(ME_ERR_MCD_DEGENERATE_GEOMETRY,
                   assert_null(MstModelAndBodyCreate(s.u, McdPlaneCreate(s.fw), 1)));
    int bodies = MdtWorldGetTotalBodies(s.w);
    MstModelAndBodyDestroy(box);
    assert_int_equal(MdtWorldGetTotalBodies(s.w), bodies - 1);
    assert_false(McdModelIsValid(box));
    MstUniverseDestroy(s.u);
}

static void place(MdtBodyID b, MeReal x, MeReal y, MeReal z)
{
    MdtBodySetPosition(b, x, y, z);
    MdtBodySetLinearVelocity(b, 0, 0, 0);
    MdtBodySetAngularVelocity(b, 0, 0, 0);
}

static int rowsLastStep(MdtWorldID w)
{
    MdtWorldCounters c;
    MdtWorldGetCounters(w, &c);
    return c.rows;
}

/* A ball at distance d from the corner (1, 1, 6) of a fixed 2 m cube centred at (0, 0, 5), along the
 * cube's diagonal: the surfaces are d − 0.5 apart, and the boxes overlap for every d below ~0.87. */
static void nearCorner(MdtBodyID ball, double d)
{
    const double u = d / sqrt(3.0);
    place(ball, (MeReal)(1 + u), (MeReal)(1 + u), (MeReal)(6 + u));
}

/* How long the bridge keeps a pair's contact group (decision M3, User Guide ch. 2): from the first
 * step the models intersect until the pair says Goodbye. A step without contacts (the models apart
 * while their boxes overlap, or a per-pair callback returning 0) leaves the group empty and disabled:
 * it adds no rows, joins no bodies into a partition and wakes nothing; contacts coming back refill the
 * same group. Gravity is off in these scenes, and the ground lies far below. */
static void group_kept_while_the_boxes_overlap(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    MdtWorldSetGravity(s.w, 0, 0, 0);
    MeMatrix4 tm;
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMSetPosition(tm, 0, 0, 5);
    assert_non_null(MstFixedModelCreate(s.u, McdBoxCreate(s.fw, 2, 2, 2), tm));
    MdtBodyID ball = McdModelGetBody(sphereAt(&s, 0.5f, 0, 0, 0));
    /* touching (0.01 deep): a group with a contact */
    nearCorner(ball, 0.49);
    MstUniverseStep(s.u, ME_R(1.0) / 60);
    MdtContactGroupID g = groupOf(ball);
    assert_non_null(g);
    assert_int_equal(MdtContactGroupGetCount(g), 1);
    assert_true(MdtConstraintIsEnabled(MdtContactGroupQuaConstraint(g)));
    /* lifted 0.05 clear, the boxes still overlapping: the same group, empty, adding no rows */
    nearCorner(ball, 0.55);
    MstUniverseStep(s.u, ME_R(1.0) / 60);
    printf("apart by 0.05, boxes overlapping: group %s, %d contacts, %s; rows solved %d\n",
           groupOf(ball) ? "kept" : "gone", groupOf(ball) ? MdtContactGroupGetCount(groupOf(ball)) : -1,
           MdtConstraintIsEnabled(MdtContactGroupQuaConstraint(g)) ? "enabled" : "disabled", rowsLastStep(s.w));
    assert_ptr_equal(groupOf(ball), g);
    assert_int_equal(MdtContactGroupGetCount(g), 0);
    assert_false(MdtConstraintIsEnabled(MdtContactGroupQuaConstraint(g)));
    assert_int_equal(rowsLastStep(s.w), 0);
    MeVector3 v;
    MdtBodyGetLinearVelocity(ball, v);
    assert_true(v[0] == 0 && v[1] == 0 && v[2] == 0); /* nothing pushed it */
    /* touching again: the same group refilled and enabled */
    nearCorner(ball, 0.495);
    MstUniverseStep(s.u, ME_R(1.0) / 60);
    assert_ptr_equal(groupOf(ball), g);
    assert_int_equal(MdtContactGroupGetCount(g), 1);
    assert_true(MdtConstraintIsEnabled(MdtContactGroupQuaConstraint(g)));
    /* the boxes apart (Goodbye): the group is destroyed */
    nearCorner(ball, 2);
    MstUniverseStep(s.u, ME_R(1.0) / 60);
    assert_null(groupOf(ball));
    assert_false(MdtConstraintIsValid(MdtContactGroupQuaConstraint(g)));
    assert_int_equal(MdtWorldGetTotalConstraints(s.w), 0);
    MstUniverseDestroy(s.u);
}

static MeBool dropAll(McdIntersectResult *r, MdtContactGroupID g)
{
    (void)r, (void)g;
    return MEFALSE;
}

static void per_pair_callback_removes_the_contacts_not_the_group(void **state)
{
    (void)state;
    /* Karma's MstPerPairCBPtr: "if the callback returns 0, all contacts created for this pair will be
     * removed". The group stays (empty, disabled) until Goodbye; the balls pass through each other. */
    Scene s;
    sceneInit(&s);
    MdtWorldSetGravity(s.w, 0, 0, 0);
    MstBridgeSetPerPairCB(s.b, 0, 0, dropAll);
    MdtBodyID a = McdModelGetBody(sphereAt(&s, 0.5f, 0, 0, 10));
    MdtBodyID b = McdModelGetBody(sphereAt(&s, 0.5f, ME_R(0.9), 0, 10));
    MstUniverseStep(s.u, ME_R(1.0) / 60);
    MdtContactGroupID g = groupOf(a);
    assert_non_null(g);
    assert_int_equal(MdtContactGroupGetCount(g), 0);
    assert_false(MdtConstraintIsEnabled(MdtContactGroupQuaConstraint(g)));
    MeVector3 v;
    MdtBodyGetLinearVelocity(b, v);
    assert_true(v[0] == 0); /* no push */
    MstUniverseDestroy(s.u);
}

static void empty_group_neither_joins_nor_wakes(void **state)
{
    (void)state;
    /* Two balls touch, then are set 0.06 apart along a diagonal (their boxes still overlap, so the
     * pair stays and keeps its empty group). One spins in place and stays awake; the other, at rest,
     * is in a partition of its own and falls asleep after the alive window, and the spinning
     * neighbour's empty group does not wake it. */
    Scene s;
    sceneInit(&s);
    MdtWorldSetGravity(s.w, 0, 0, 0);
    MdtBodyID spinner = McdModelGetBody(sphereAt(&s, 0.5f, 0, 0, 10));
    MdtBodyID rester = McdModelGetBody(sphereAt(&s, 0.5f, ME_R(0.7), ME_R(0.7), 10));
    MstUniverseStep(s.u, ME_R(1.0) / 60); /* 0.99 apart: touching */
    MdtContactGroupID g = groupOf(spinner);
    assert_non_null(g);
    assert_true(MdtContactGroupGetCount(g) >= 1);
    place(spinner, 0, 0, 10);
    place(rester, ME_R(0.75), ME_R(0.75), 10); /* 1.06 apart */
    MdtBodySetAngularVelocity(spinner, 0, 0, 2);
    int asleepAt = -1;
    for (int i = 0; i < 180; i++) {
        MstUniverseStep(s.u, ME_R(1.0) / 60);
        assert_ptr_equal(groupOf(spinner), g);
        assert_int_equal(MdtContactGroupGetCount(g), 0);
        if (i == 0)
            assert_int_not_equal(MdtBodyGetPartition(spinner), MdtBodyGetPartition(rester));
        if (asleepAt < 0 && !MdtBodyIsEnabled(rester))
            asleepAt = i;
        if (asleepAt >= 0)
            assert_false(MdtBodyIsEnabled(rester)); /* never woken again */
    }
    MeVector3 w;
    MdtBodyGetAngularVelocity(spinner, w);
    printf("empty group between a spinning ball and a resting one: the resting one asleep at step %d; spinner "
           "enabled %d (spin %.3f rad/s)\n",
           asleepAt, MdtBodyIsEnabled(spinner), (double)w[2]);
    assert_true(asleepAt > 0 && asleepAt < 60);
    assert_true(MdtBodyIsEnabled(spinner));
    assert_near(w[2], 2, 1e-4);
    MstUniverseDestroy(s.u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(universe_defaults),
        cmocka_unit_test(material_table_is_symmetric),
        cmocka_unit_test(group_lives_with_the_intersection),
        cmocka_unit_test(conversion_carries_the_geometry),
        cmocka_unit_test(bridge_normal_pushes_the_ball_up_in_both_orders),
        cmocka_unit_test(group_kept_while_the_boxes_overlap),
        cmocka_unit_test(per_pair_callback_removes_the_contacts_not_the_group),
        cmocka_unit_test(empty_group_neither_joins_nor_wakes),
        cmocka_unit_test(collision_update_skips_bad_fields_one_by_one),
        cmocka_unit_test(group_contacts_and_positions_in_order),
        cmocka_unit_test(group_refresh_takes_the_nearest_old_contacts),
        cmocka_unit_test(callbacks_and_parameters),
        cmocka_unit_test(contact_buffer_size_is_the_only_limit),
        cmocka_unit_test(freeze_follows_disable),
        cmocka_unit_test(model_and_body_helpers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
