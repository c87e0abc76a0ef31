/* The rest of Karma 1.2's Mst API: MstBridgeStepAll (the universe's step, refused for a bare
 * bridge) and MstMaterialID as 1.2's unsigned type with MST_MATERIAL_INVALID. */
#include "karma_test.h"

#include <karma/Mst.h>

/* A ball dropped onto a plane in a fresh universe; returns the universe. */
static MstUniverseID dropBall(McdModelID *ball)
{
    static MeMatrix4 ground = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* plane normal +y */
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    MdtWorldSetGravity(u->world, 0, -9.81f, 0);
    MstFixedModelCreate(u, McdPlaneCreate(u->frame), ground);
    *ball = MstModelAndBodyCreate(u, McdSphereCreate(u->frame, 0.5f), 1);
    MdtBodySetPosition(McdModelGetBody(*ball), 0, 2, 0);
    return u;
}

static void bridge_step_all_is_the_universe_step(void **state)
{
    (void)state;
    McdModelID a, b;
    MstUniverseID ua = dropBall(&a), ub = dropBall(&b);
    for (int i = 0; i < 200; i++) {
        MstUniverseStep(ua, 0.01f);
        MstBridgeStepAll(ub->bridge, 0.01f);
    }
    MeVector3 pa, pb;
    MdtBodyGetPosition(McdModelGetBody(a), pa);
    MdtBodyGetPosition(McdModelGetBody(b), pb);
    assert_memory_equal(pa, pb, sizeof pa); /* bit for bit */
    assert_true(pa[1] < 1.9f);                /* it fell */
    MstUniverseDestroy(ua);
    MstUniverseDestroy(ub);

    /* A bridge made by hand knows no space or world. */
    McdFrameworkID fw = McdInit(0, 10, 10, 1);
    MstBridgeID bare = MstBridgeCreate(fw, 2);
    karma_capture_messages();
    assert_reports(ME_ERR_BAD_STATE, MstBridgeStepAll(bare, 0.01f));
    MstBridgeDestroy(bare);
    assert_reports(ME_ERR_INVALID_HANDLE, MstBridgeStepAll(bare, 0.01f));
    McdTerm(fw);
}

static void material_ids_are_unsigned(void **state)
{
    (void)state;
    MstMaterialID probe = 0;
    probe -= 1; /* unsigned arithmetic, as in 1.2 */
    assert_true(probe > 0);
    assert_true(probe == MST_MATERIAL_INVALID);
    McdFrameworkID fw = McdInit(0, 10, 10, 1);
    MstBridgeID b = MstBridgeCreate(fw, 2);
    MstMaterialID m = MstBridgeGetNewMaterial(b);
    assert_true(m == 1);
    karma_capture_messages();
    assert_reports(ME_ERR_POOL_FULL, assert_true(MstBridgeGetNewMaterial(b) == MST_MATERIAL_INVALID));
    assert_reports(ME_ERR_MST_MATERIAL, assert_null(MstBridgeGetContactParams(b, MST_MATERIAL_INVALID, 0)));
    assert_reports(ME_ERR_MST_MATERIAL, assert_null(MstBridgeGetContactParams(b, 0, 2)));
    assert_non_null(MstBridgeGetContactParams(b, m, MstBridgeGetDefaultMaterial()));
    MstBridgeDestroy(b);
    McdTerm(fw);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bridge_step_all_is_the_universe_step),
        cmocka_unit_test(material_ids_are_unsigned),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
