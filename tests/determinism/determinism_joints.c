/* determinism_joints.c -- the golden-hash test of the constraint layer: every joint family, limits
 * and motors, a box sliding on hand-made contacts with friction and a ball bouncing with restitution,
 * each in a partition of its own, give bit-identical states run after run, at -O0 and at -O2, equal
 * to a hash recorded here per precision (built twice by tests/cmake/determinism.cmake, like
 * determinism_scene.c).
 *
 * If the hash changes on purpose, run with KARMA_DETERMINISM_PRINT=1 to print the new values. */
#include <stdlib.h>
#include <string.h>

#include "karma_contacts.h"
#include "karma_test.h"

#include <karma/karma.h>

#define STEPS 240
#define STEP_SIZE (ME_R(1.0) / 60)

#if KARMA_DOUBLE
#  define GOLDEN_HASH 0x6617416eec7443e9ull
#else
#  define GOLDEN_HASH 0x4ad65e45e3b55c1eull
#endif

typedef struct Scene {
    MdtWorldID world;
    MdtFixedPathID path;
    MdtContactGroupID slide, bounce;
    MdtBodyID box, ball;
    MdtContactParams boxParams, ballParams;
} Scene;

static MdtBodyID bodyAt(Scene *s, MeReal x, MeReal y, MeReal z)
{
    MdtBodyID b = MdtBodyCreate(s->world);
    MdtBodySetPosition(b, x, y, z);
    MdtBodyEnable(b);
    return b;
}

/* A user row: keep the body's height at z = 1 (a horizontal plane for its centre). */
static int heightRow(MdtUserConstraintID j, MdtUserConstraintRow *rows, int maxRows,
                     const MdtBclSolverParameters *params, void *data)
{
    (void)params;
    (void)maxRows;
    MdtBodyID b = MdtConstraintGetBody(MdtUserConstraintQuaConstraint(j), 0);
    MeVector3 p;
    MdtBodyGetPosition(b, p);
    memset(rows, 0, sizeof rows[0]);
    rows[0].linear0[2] = 1;
    rows[0].error = p[2] - *(MeReal *)data;
    rows[0].lo = -MEINFINITY;
    rows[0].hi = MEINFINITY;
    rows[0].stiffness = rows[0].damping = MEINFINITY;
    return 1;
}

static MeReal userHeight = 1;

static void buildScene(Scene *s)
{
    memset(s, 0, sizeof *s);
    s->world = MdtWorldCreate(40, 80, ME_R(1.0), ME_R(1.0));
    assert_non_null(s->world);
    MdtWorldSetGravity(s->world, 0, 0, ME_R(-9.81));
    MdtWorldSetAutoDisable(s->world, MEFALSE);
    MdtWorldID w = s->world;

    /* Ball and socket pendulum with a cone limit. */
    MdtBodyID a = bodyAt(s, ME_R(0.8), 0, ME_R(-0.6));
    MdtBSJointID bs = MdtBSJointCreate(w);
    MdtBSJointSetBodies(bs, a, NULL);
    MdtBSJointSetPosition(bs, 0, 0, 0);
    MdtBSJointEnable(bs);
    MdtConeLimitID cone = MdtConeLimitCreate(w);
    MdtConstraintSetBodies(MdtConeLimitQuaConstraint(cone), a, NULL);
    MdtConstraintSetAxis(MdtConeLimitQuaConstraint(cone), 0, 0, -1);
    MdtConeLimitSetConeHalfAngle(cone, ME_R(0.5));
    MdtConstraintEnable(MdtConeLimitQuaConstraint(cone));

    /* Hinge with a motor and hard stops. */
    MdtBodyID h = bodyAt(s, ME_R(3.5), 0, 0);
    MdtHingeID hinge = MdtHingeCreate(w);
    MdtHingeSetBodies(hinge, h, NULL);
    MdtHingeSetPosition(hinge, 3, 0, 0);
    MdtHingeSetAxis(hinge, 0, 1, 0);
    MdtLimitID hl = MdtHingeGetLimit(hinge);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(hl), ME_R(-0.8));
    MdtSingleLimitSetStop(MdtLimitGetUpperLimit(hl), ME_R(0.8));
    MdtSingleLimitSetRestitution(MdtLimitGetUpperLimit(hl), ME_R(0.4));
    MdtLimitActivateLimits(hl, METRUE);
    MdtLimitSetLimitedForceMotor(hl, 2, 4);
    MdtHingeEnable(hinge);

    /* Prismatic with a soft lower stop. */
    MdtBodyID p = bodyAt(s, 6, 0, 0);
    MdtPrismaticID pr = MdtPrismaticCreate(w);
    MdtPrismaticSetBodies(pr, p, NULL);
    MdtPrismaticSetAxis(pr, ME_R(0.3), 0, -1);
    MdtLimitID pl = MdtPrismaticGetLimit(pr);
    MdtSingleLimitSetStop(MdtLimitGetLowerLimit(pl), ME_R(-0.5));
    MdtSingleLimitSetStiffness(MdtLimitGetLowerLimit(pl), 200);
    MdtSingleLimitSetDamping(MdtLimitGetLowerLimit(pl), 5);
    MdtLimitActivateLimits(pl, METRUE);
    MdtPrismaticEnable(pr);

    /* Universal joint between two bodies, the first on a hinge to the world. */
    MdtBodyID u0 = bodyAt(s, 9, 0, 0), u1 = bodyAt(s, 9, 0, ME_R(-1.0));
    MdtHingeID uh = MdtHingeCreate(w);
    MdtHingeSetBodies(uh, u0, NULL);
    MdtHingeSetPosition(uh, 9, 0, 0);
    MdtHingeSetAxis(uh, 0, 0, 1);
    MdtLimitSetLimitedForceMotor(MdtHingeGetLimit(uh), 3, 50);
    MdtHingeEnable(uh);
    MdtUniversalID uj = MdtUniversalCreate(w);
    MdtConstraintSetBodies(MdtUniversalQuaConstraint(uj), u1, u0);
    MdtConstraintSetPosition(MdtUniversalQuaConstraint(uj), 9, 0, ME_R(-0.5));
    MdtConstraintEnable(MdtUniversalQuaConstraint(uj));

    /* Angular3 spring holding a tilted body upright, Linear1 plane and Linear2 rail. */
    MdtBodyID g = bodyAt(s, 12, 0, 0);
    MdtBodySetAngularVelocity(g, 1, ME_R(0.5), 0);
    MdtAngular3ID a3 = MdtAngular3Create(w);
    MdtConstraintSetBodies(MdtAngular3QuaConstraint(a3), g, NULL);
    MdtAngular3SetStiffness(a3, 30);
    MdtAngular3SetDamping(a3, ME_R(0.5));
    MdtConstraintEnable(MdtAngular3QuaConstraint(a3));
    MdtLinear1ID l1 = MdtLinear1Create(w);
    MdtConstraintSetBodies(MdtLinear1QuaConstraint(l1), g, NULL);
    MdtConstraintSetAxis(MdtLinear1QuaConstraint(l1), 0, ME_R(0.2), 1);
    MdtConstraintEnable(MdtLinear1QuaConstraint(l1));
    MdtBodyID r = bodyAt(s, 15, 0, 0);
    MdtLinear2ID l2 = MdtLinear2Create(w);
    MdtConstraintSetBodies(MdtLinear2QuaConstraint(l2), r, NULL);
    MdtLinear2SetDirection(l2, 1, 0, ME_R(-0.5));
    MdtConstraintEnable(MdtLinear2QuaConstraint(l2));

    /* Car wheel on a chassis held by an RPRO joint to the world (target: a slow yaw). */
    MdtBodyID chassis = bodyAt(s, 18, 0, 0), wheel = bodyAt(s, 18, ME_R(0.8), ME_R(-0.3));
    MdtRPROJointID rp = MdtRPROJointCreate(w);
    MdtConstraintSetBodies(MdtRPROJointQuaConstraint(rp), chassis, NULL);
    MeVector4 q = {ME_R(0.99875), 0, 0, ME_R(0.05)};
    MdtRPROJointSetRelativeQuaternion(rp, q);
    MdtRPROJointSetAngularStrength(rp, 40, 40, 40);
    MdtConstraintEnable(MdtRPROJointQuaConstraint(rp));
    MdtCarWheelID cw = MdtCarWheelCreate(w);
    MdtConstraintSetBodies(MdtCarWheelQuaConstraint(cw), chassis, wheel);
    MdtConstraintSetPosition(MdtCarWheelQuaConstraint(cw), 18, ME_R(0.8), ME_R(-0.3));
    MdtCarWheelSetSuspension(cw, 400, 10, ME_R(0.001), ME_R(-0.2), ME_R(0.2), 0);
    MdtCarWheelSetHingeLimitedForceMotor(cw, 10, 5);
    MdtConstraintEnable(MdtCarWheelQuaConstraint(cw));

    /* Skeletal shoulder, Spring6 and a Spring between two bodies, FixedPath on a moving anchor. */
    MdtBodyID sk = bodyAt(s, 21, ME_R(0.5), ME_R(-0.5));
    MdtSkeletalID skj = MdtSkeletalCreate(w);
    MdtConstraintSetBodies(MdtSkeletalQuaConstraint(skj), sk, NULL);
    MdtConstraintSetPosition(MdtSkeletalQuaConstraint(skj), 21, 0, 0);
    MdtConstraintSetAxes(MdtSkeletalQuaConstraint(skj), 0, 0, -1, 1, 0, 0);
    MdtConstraintEnable(MdtSkeletalQuaConstraint(skj));
    MdtBodyID s6 = bodyAt(s, 24, 0, ME_R(-0.2));
    MdtSpring6ID sp6 = MdtSpring6Create(w);
    MdtConstraintSetBodies(MdtSpring6QuaConstraint(sp6), s6, NULL);
    MdtConstraintSetPosition(MdtSpring6QuaConstraint(sp6), 24, 0, 0);
    for (unsigned axis = 0; axis < 3; axis++) {
        MdtSpring6SetLinearStiffness(sp6, axis, 100 + 20 * (MeReal)axis);
        MdtSpring6SetLinearDamping(sp6, axis, 1);
        MdtSpring6SetAngularStiffness(sp6, axis, 10);
        MdtSpring6SetAngularDamping(sp6, axis, ME_R(0.1));
    }
    MdtConstraintEnable(MdtSpring6QuaConstraint(sp6));
    MdtBodyID m0 = bodyAt(s, 27, 0, 0), m1 = bodyAt(s, 27, 0, ME_R(-1.0));
    MdtBSJointID top = MdtBSJointCreate(w);
    MdtBSJointSetBodies(top, m0, NULL);
    MdtBSJointSetPosition(top, 27, 0, 0);
    MdtBSJointEnable(top);
    MdtSpringID spr = MdtSpringCreate(w);
    MdtConstraintSetBodies(MdtSpringQuaConstraint(spr), m1, m0);
    MdtSpringSetPosition(spr, 0, 27, 0, ME_R(-1.0));
    MdtSpringSetPosition(spr, 1, 27, 0, 0);
    MdtSpringSetStiffness(spr, 150);
    MdtSpringSetDamping(spr, 2);
    MdtConstraintEnable(MdtSpringQuaConstraint(spr));
    MdtBodyID fp = bodyAt(s, 30, 0, -1);
    s->path = MdtFixedPathCreate(w);
    MdtConstraintSetBodies(MdtFixedPathQuaConstraint(s->path), fp, NULL);
    MdtFixedPathSetPosition(s->path, 0, 0, 0, 1);
    MdtFixedPathSetPosition(s->path, 1, 30, 0, 0);
    MdtConstraintEnable(MdtFixedPathQuaConstraint(s->path));

    /* A user constraint keeping a thrown body's centre at z = 1. */
    MdtBodyID ub = bodyAt(s, 33, 0, 1);
    MdtBodySetLinearVelocity(ub, 1, 2, 3);
    MdtUserConstraintID uc = MdtUserConstraintCreate(w);
    MdtConstraintSetBodies(MdtUserConstraintQuaConstraint(uc), ub, NULL);
    MdtUserConstraintSetMaxRows(uc, 1);
    MdtUserConstraintSetAddConstraintFunction(uc, heightRow);
    MdtUserConstraintSetConstraintStruct(uc, &userHeight);
    MdtConstraintEnable(MdtUserConstraintQuaConstraint(uc));

    /* A box sliding to a stop on hand-made contacts (friction) and a ball bouncing (restitution). */
    s->box = bodyAt(s, 36, 0, ME_R(0.5));
    MdtBodySetLinearVelocity(s->box, 3, 1, 0);
    s->slide = MdtContactGroupCreate(w);
    MdtConstraintSetBodies(MdtContactGroupQuaConstraint(s->slide), s->box, NULL);
    MdtConstraintEnable(MdtContactGroupQuaConstraint(s->slide));
    karma_contact_params_friction(&s->boxParams, ME_R(0.4));
    s->ball = bodyAt(s, 40, 0, 2);
    s->bounce = MdtContactGroupCreate(w);
    MdtConstraintSetBodies(MdtContactGroupQuaConstraint(s->bounce), s->ball, NULL);
    MdtConstraintEnable(MdtContactGroupQuaConstraint(s->bounce));
    MdtContactParamsReset(&s->ballParams);
    MdtContactParamsSetRestitution(&s->ballParams, ME_R(0.7));
    assert_non_null(MdtContactGroupCreateContact(s->bounce));
}

static void scriptStep(Scene *s, int step)
{
    /* The fixed path's anchor circles at 1 rad/s, radius 0.3. */
    MeReal t = (MeReal)step * STEP_SIZE;
    MdtFixedPathSetPosition(s->path, 1, 30 + ME_R(0.3) * MeCos(t), ME_R(0.3) * MeSin(t), 0);
    MdtFixedPathSetVelocity(s->path, 1, ME_R(-0.3) * MeSin(t), ME_R(0.3) * MeCos(t), 0);
    const MeVector3 half = {ME_R(0.5), ME_R(0.5), ME_R(0.5)}, up = {0, 0, 1};
    karma_box_on_plane(s->slide, s->box, half, up, 0, &s->boxParams);
    MeVector3 b;
    MdtBodyGetPosition(s->ball, b);
    MdtContactID c = MdtContactGroupGetFirstContact(s->bounce);
    MdtContactSetParams(c, &s->ballParams);
    MdtContactSetPosition(c, b[0], b[1], 0);
    MdtContactSetNormal(c, 0, 0, 1); /* the ground pushes the ball (body 0) up */
    MdtContactSetPenetration(c, ME_R(0.25) - b[2]);
}

static uint64_t runScene(MeBool trace)
{
    Scene s;
    buildScene(&s);
    uint64_t hash = KARMA_HASH_INIT;
    int bounces = 0;
    MeReal lastVz = 0;
    for (int step = 0; step < STEPS; step++) {
        scriptStep(&s, step);
        MdtWorldStep(s.world, STEP_SIZE);
        MeVector3 bv;
        MdtBodyGetLinearVelocity(s.ball, bv);
        if (lastVz < ME_R(-0.5) && bv[2] > ME_R(0.3))
            bounces++;
        lastVz = bv[2];
        for (MdtBodyID b = MdtBodyGetFirst(s.world); b; b = MdtBodyGetNext(b)) {
            MeVector3 x, v, w;
            MeVector4 q;
            MdtBodyGetPosition(b, x);
            MdtBodyGetQuaternion(b, q);
            MdtBodyGetLinearVelocity(b, v);
            MdtBodyGetAngularVelocity(b, w);
            hash = karma_hash_bytes(hash, x, sizeof x);
            hash = karma_hash_bytes(hash, q, sizeof q);
            hash = karma_hash_bytes(hash, v, sizeof v);
            hash = karma_hash_bytes(hash, w, sizeof w);
        }
        if (trace)
            printf("step %3d hash 0x%016llx\n", step, (unsigned long long)hash);
    }
    /* The scene did what it should: the box stopped sliding, the ball bounced. */
    MeVector3 v, x;
    MdtBodyGetLinearVelocity(s.box, v);
    assert_true(MeVector3Magnitude(v) < ME_R(0.01));
    MdtBodyGetPosition(s.ball, x);
    assert_true(x[2] > ME_R(0.2));
    assert_true(bounces >= 2);
    MdtWorldDestroy(s.world);
    return hash;
}

static void joints_same_hash_twice_and_golden(void **state)
{
    (void)state;
    karma_capture_messages();
    uint64_t first = runScene(getenv("KARMA_DETERMINISM_TRACE") != NULL);
    uint64_t second = runScene(MEFALSE);
    print_message("joint scene hash after %d steps: 0x%016llx (run 1), 0x%016llx (run 2), golden 0x%016llx (%s)\n",
                  STEPS, (unsigned long long)first, (unsigned long long)second, (unsigned long long)GOLDEN_HASH,
                  KARMA_DOUBLE ? "double" : "float");
    if (getenv("KARMA_DETERMINISM_PRINT"))
        printf("#  define GOLDEN_HASH 0x%016llxull\n", (unsigned long long)first);
    /* Three joints of the scene start metres from what they hold their bodies to (the Linear2 rail,
     * the RPRO joint of the car chassis and the fixed path), so the first step flings those bodies at
     * tens to hundreds of m/s: each run reports exactly those three energy jumps (docs/step.md), and
     * nothing else. */
    assert_int_equal(MeMessageGetCount(ME_ERR_ENERGY_JUMP), 6);
    assert_int_equal(karma_warning_count(), 6);
    assert_true(first == second);
    assert_true(first == GOLDEN_HASH);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(joints_same_hash_twice_and_golden),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
