/* Destroying a model that touches another (MstModelAndBodyDestroy) while the universe runs: the pair's
 * goodbye arrives at the next step with the destroyed model's ID; the bridge releases the pair
 * without reporting it (issue 15, found by the soak: McdGoodbye reported ME_ERR_INVALID_HANDLE). */
#include "karma_test.h"

#include <karma/karma.h>

static void destroying_touching_models_reports_nothing(void **state)
{
    (void)state;
    karma_capture_messages();
    MstUniverseID u = MstUniverseCreate(&MstUniverseDefaultSizes);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, 0, ME_R(-9.81));
    McdFrameworkID fw = MstUniverseGetFramework(u);
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    assert_non_null(MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM));
    McdGeometryID box = McdBoxCreate(fw, 1, 1, 1);
    McdModelID m[3];
    for (int i = 0; i < 3; i++) {
        m[i] = MstModelAndBodyCreate(u, box, 1);
        MdtBodySetPosition(McdModelGetBody(m[i]), 0, 0, ME_R(0.5) + ME_R(0.99) * (MeReal)i); /* a touching stack */
    }
    for (int n = 0; n < 10; n++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    assert_true(MstBridgeGetLastContactCount(MstUniverseGetBridge(u)) > 0);
    /* The middle one touches both others and the top one touches it; two destroyed in one step. */
    MstModelAndBodyDestroy(m[1]);
    MstModelAndBodyDestroy(m[2]);
    for (int n = 0; n < 60; n++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    assert_int_equal(karma_warning_count(), 0);
    /* The bottom box still rests on the ground. */
    MeVector3 p;
    MdtBodyGetPosition(McdModelGetBody(m[0]), p);
    assert_near(p[2], 0.5, 0.02);
    MstUniverseDestroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(destroying_touching_models_reports_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
