/* The contacts' penetration correction is bounded (MdtWorldSetMaxCorrectingVelocity, docs/step.md)
 * and the universe refuses steps below MDT_MIN_STEP_SIZE before anything runs (issue 15, point 4).
 * A 1 m box of 1000 kg starts half sunk into the ground plane: γ·depth/h would separate it at
 * 0.2 × 0.5 m × 60 /s = 6 m/s at 60 Hz and at 10,000 m/s at h = 1e-5 s. */
#include "karma_test.h"

#include <karma/karma.h>

static MstUniverseID makeUniverse(McdModelID *box)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 1000;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetAutoDisable(w, MEFALSE);
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    McdFrameworkID fw = MstUniverseGetFramework(u);
    assert_non_null(MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM));
    *box = MstModelAndBodyCreate(u, McdBoxCreate(fw, 1, 1, 1), 1000);
    assert_non_null(*box);
    MdtBodySetPosition(McdModelGetBody(*box), 0, 0, 0); /* centre on the plane: 0.5 m deep */
    return u;
}

/* Step until the box is out; return its largest upward speed. */
static double separate(MstUniverseID u, McdModelID box, MeReal h, int steps)
{
    double fastest = 0;
    for (int n = 0; n < steps; n++) {
        MstUniverseStep(u, h);
        MeVector3 v;
        MdtBodyGetLinearVelocity(McdModelGetBody(box), v);
        assert_true(isfinite(v[2]));
        fastest = fmax(fastest, (double)MeVector3Magnitude(v));
    }
    return fastest;
}

static void deep_penetration_separates_no_faster_than_the_limit(void **state)
{
    (void)state;
    karma_capture_messages();
    McdModelID box;
    /* At 60 Hz with a limit of 1 m/s (γ·depth/h alone would give 6 m/s). */
    MstUniverseID u = makeUniverse(&box);
    MdtWorldSetMaxCorrectingVelocity(MstUniverseGetWorld(u), 1);
    double fastest = separate(u, box, ME_R(1.0) / 60, 60);
    MeVector3 p;
    MdtBodyGetPosition(McdModelGetBody(box), p);
    print_message("limit 1 m/s, 60 Hz: fastest %.4f m/s, box centre at %.3f m after 1 s\n", fastest, (double)p[2]);
    assert_true(fastest <= 1 + ME_TOL(1e-9, 1e-4));
    assert_true(fastest > ME_R(0.5));   /* it was pushed out... */
    assert_true(p[2] > ME_R(0.45));     /* ...and is out, give or take the contacts' tolerance */
    MstUniverseDestroy(u);

    /* At h = 1e-5 s with the default limit (10 m/s × lengthScale). */
    u = makeUniverse(&box);
    assert_near(MdtWorldGetMaxCorrectingVelocity(MstUniverseGetWorld(u)), 10, 0);
    fastest = separate(u, box, ME_R(1e-5), 2000);
    print_message("default limit, h = 1e-5 s: fastest %.4f m/s\n", fastest);
    assert_true(fastest <= 10 + ME_TOL(1e-9, 1e-3));
    assert_true(fastest > 5);
    assert_int_equal(MeMessageGetCount(ME_ERR_NONFINITE_STATE), 0);
    MstUniverseDestroy(u);
}

static void universe_step_below_minimum_refused_before_collision(void **state)
{
    (void)state;
    karma_capture_messages();
    McdModelID box;
    MstUniverseID u = makeUniverse(&box);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldCounters c;
    assert_reports(ME_ERR_STEP_SIZE, MstUniverseStep(u, ME_R(1e-20)));
    assert_reports(ME_ERR_STEP_SIZE, MstUniverseStep(u, (MeReal)NAN));
    MdtWorldGetCounters(w, &c);
    assert_int_equal(c.steps, 0);
    assert_int_equal(MstBridgeGetLastContactCount(MstUniverseGetBridge(u)), 0); /* collision did not run */
    MeVector3 p;
    MdtBodyGetPosition(McdModelGetBody(box), p);
    assert_true(p[0] == 0 && p[1] == 0 && p[2] == 0);
    MstUniverseStep(u, MDT_MIN_STEP_SIZE);
    MdtWorldGetCounters(w, &c);
    assert_int_equal(c.steps, 1);
    assert_true(MstBridgeGetLastContactCount(MstUniverseGetBridge(u)) > 0);
    MstUniverseDestroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(deep_penetration_separates_no_faster_than_the_limit),
        cmocka_unit_test(universe_step_below_minimum_refused_before_collision),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
