/* Sleeping and waking through the whole pipeline: two piles of boxes far apart come to rest, are
 * auto-disabled and their models frozen; a ball shot into one pile wakes exactly that pile (the
 * partition it touches), while the other stays disabled and frozen. */
#include "karma_test.h"

#include <math.h>

#include <karma/karma.h>

#define EDGE ME_R(0.5)
#define PILE 6 /* a pyramid of 3 + 2 + 1 boxes */

typedef struct Scene {
    MstUniverseID u;
    MdtWorldID w;
    McdModelID piles[2][PILE];
} Scene;

static void buildPile(Scene *s, int k, MeReal x0, McdGeometryID box)
{
    int n = 0;
    for (int row = 0; row < 3; row++)
        for (int i = 0; i < 3 - row; i++) {
            McdModelID m = MstModelAndBodyCreate(s->u, box, 1000);
            assert_non_null(m);
            MeReal x = x0 + ((MeReal)i - (MeReal)(2 - row) / 2) * EDGE * ME_R(1.02);
            MdtBodySetPosition(McdModelGetBody(m), x, 0, EDGE / 2 + (MeReal)row * EDGE);
            s->piles[k][n++] = m;
        }
}

/* How many of pile k's bodies are enabled, and how many of its models are frozen. */
static void pileState(const Scene *s, int k, int *enabled, int *frozen)
{
    *enabled = *frozen = 0;
    for (int i = 0; i < PILE; i++) {
        *enabled += MdtBodyIsEnabled(McdModelGetBody(s->piles[k][i])) ? 1 : 0;
        *frozen += McdSpaceModelIsFrozen(s->piles[k][i]) ? 1 : 0;
    }
}

static void ball_wakes_only_the_pile_it_hits(void **state)
{
    (void)state;
    Scene s;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 125; /* the boxes' mass (0.5 m cubes at 1000 kg/m³) */
    s.u = MstUniverseCreate(&sizes);
    assert_non_null(s.u);
    s.w = MstUniverseGetWorld(s.u);
    MdtWorldSetGravity(s.w, 0, 0, ME_R(-9.81));
    assert_true(MdtWorldGetAutoDisable(s.w)); /* Karma's default */
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    McdFrameworkID fw = MstUniverseGetFramework(s.u);
    assert_non_null(MstFixedModelCreate(s.u, McdPlaneCreate(fw), groundTM));
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(s.u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.6));
    McdGeometryID box = McdBoxCreate(fw, EDGE, EDGE, EDGE);
    buildPile(&s, 0, -10, box);
    buildPile(&s, 1, 10, box);
    karma_capture_messages();

    /* Both piles settle and fall asleep. */
    int steps = 0, enabled[2], frozen[2];
    while (MdtWorldGetEnabledBodies(s.w) > 0 && steps < 1200) {
        MstUniverseStep(s.u, ME_R(1.0) / 60);
        steps++;
    }
    for (int k = 0; k < 2; k++)
        pileState(&s, k, &enabled[k], &frozen[k]);
    printf("both piles asleep after %d steps (%.2f s): enabled %d + %d, frozen %d + %d of %d + %d\n", steps,
           steps / 60.0, enabled[0], enabled[1], frozen[0], frozen[1], PILE, PILE);
    assert_true(steps < 1200);
    for (int k = 0; k < 2; k++) {
        assert_int_equal(enabled[k], 0);
        assert_int_equal(frozen[k], PILE);
    }
    /* Asleep, the piles stand where they were built (they settled by the contacts' compliance only). */
    MeVector3 top;
    MdtBodyGetPosition(McdModelGetBody(s.piles[0][PILE - 1]), top);
    assert_near(top[2], EDGE * ME_R(2.5), 0.01);

    /* A ball rolls into pile 0's bottom row along +x. */
    McdModelID ball = MstModelAndBodyCreate(s.u, McdSphereCreate(fw, ME_R(0.25)), 2000);
    assert_non_null(ball);
    MdtBodyID ballBody = McdModelGetBody(ball);
    MdtBodySetPosition(ballBody, -14, 0, ME_R(0.25));
    MdtBodySetLinearVelocity(ballBody, 8, 0, 0);
    int hitStep = -1, wokenStep = -1;
    for (int i = 0; i < 120; i++) {
        MstUniverseStep(s.u, ME_R(1.0) / 60);
        pileState(&s, 0, &enabled[0], &frozen[0]);
        pileState(&s, 1, &enabled[1], &frozen[1]);
        if (hitStep < 0 && enabled[0] > 0)
            hitStep = i;
        if (wokenStep < 0 && enabled[0] == PILE && frozen[0] == 0)
            wokenStep = i;
        /* The other pile never wakes, and its models stay frozen. */
        assert_int_equal(enabled[1], 0);
        assert_int_equal(frozen[1], PILE);
    }
    MeVector3 x;
    MdtBodyGetPosition(ballBody, x);
    printf("ball reached pile 0 at step %d, whole pile awake and unfrozen at step %d (ball now at x = %.2f); "
           "pile 1: %d enabled, %d of %d frozen throughout\n",
           hitStep, wokenStep, (double)x[0], enabled[1], frozen[1], PILE);
    /* The ball has (14 - 10 - 0.77 - 0.25) m = 2.98 m to go: 22 steps at 8 m/s, 31 at the 5.7 m/s (5/7 of
     * it) it keeps once ground friction has made it roll. */
    assert_true(hitStep >= 20 && hitStep <= 32);
    assert_true(wokenStep >= 0 && wokenStep <= hitStep + 1);
    assert_int_equal(karma_warning_count(), 0);
    MstUniverseDestroy(s.u);
}

/* A body disabled by the application right after being placed is frozen where it is, not where its
 * model was inserted (at the origin): a ball dropped on it lands on it and wakes it. */
static void body_disabled_before_first_step_is_frozen_in_place(void **state)
{
    (void)state;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 125;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, ME_R(-9.81));
    McdFrameworkID fw = MstUniverseGetFramework(u);
    McdModelID box = MstModelAndBodyCreate(u, McdBoxCreate(fw, EDGE, EDGE, EDGE), 1000);
    assert_non_null(box);
    MdtBodySetPosition(McdModelGetBody(box), 5, 0, 0);
    MdtBodyDisable(McdModelGetBody(box));
    assert_true(McdSpaceModelIsFrozen(box));
    McdModelID ball = MstModelAndBodyCreate(u, McdSphereCreate(fw, ME_R(0.2)), 1000);
    assert_non_null(ball);
    MdtBodySetPosition(McdModelGetBody(ball), 5, 0, 1);
    int touched = -1;
    for (int i = 0; i < 60 && touched < 0; i++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        if (MstBridgeGetLastContactCount(MstUniverseGetBridge(u)) > 0)
            touched = i;
    }
    MeVector3 x;
    MdtBodyGetPosition(McdModelGetBody(ball), x);
    printf("ball dropped on a box disabled before the first step: contact at step %d, ball at z = %.3f, box %s\n",
           touched, (double)x[2], MdtBodyIsEnabled(McdModelGetBody(box)) ? "woken" : "asleep");
    /* Free fall of 1 - 0.25 - 0.2 = 0.55 m takes 0.33 s: about 20 steps. */
    assert_true(touched >= 15 && touched <= 25);
    assert_true(x[2] > ME_R(0.4));
    MstUniverseDestroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ball_wakes_only_the_pile_it_hits),
        cmocka_unit_test(body_disabled_before_first_step_is_frozen_in_place),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
