/* A newcomer's mistakes get messages that name them: a pool the universe made names the
 * MstUniverseSizes field to raise and is reported once, not every step (the rest are counted); the
 * message names the function the application called; a world that can move nothing says why, once,
 * at a level shown by default, and MdtWorldSetHints silences it; a mass far from the world's scale
 * says what to set. */
#include "karma_test.h"

#include <string.h>

#include <karma/MeMemory.h>
#include <karma/karma.h>

#define STEP (ME_R(1.0) / 60)

/* Every message the handler saw: code, function and text. */
#define MAX_SEEN 64
static struct {
    MeErrorCode code;
    char function[64];
    char text[512];
} seen[MAX_SEEN];
static int seenCount;

static void record(const MeMessageInfo *info, void *user)
{
    (void)user;
    if (seenCount < MAX_SEEN) {
        seen[seenCount].code = info->code;
        snprintf(seen[seenCount].function, sizeof seen[0].function, "%s", info->function);
        snprintf(seen[seenCount].text, sizeof seen[0].text, "%s", info->text);
    }
    seenCount++;
}

static int setup(void **state)
{
    (void)state;
    MeSetMessageHandler(record, NULL, NULL);
    MeSetMessageLevel(ME_LEVEL_WARNING); /* the default: what a newcomer sees */
    MeMessageResetCounts();
    seenCount = 0;
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    MeSetMessageHandler(NULL, NULL, NULL);
    return 0;
}

/* How many messages with `code` the handler saw; the last one's index in *last. */
static int shown(MeErrorCode code, int *last)
{
    int n = 0;
    for (int i = 0; i < seenCount && i < MAX_SEEN; i++)
        if (seen[i].code == code) {
            n++;
            if (last)
                *last = i;
        }
    return n;
}

/* A universe with `spheres` unit spheres resting side by side on the ground plane z = 0 (the axes do
 * not matter here), with the given pair and constraint pool sizes. */
static MstUniverseID sphereFloor(int spheres, unsigned int pairs, unsigned int constraints)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.collisionPairsMaxCount = pairs;
    sizes.dynamicConstraintsMaxCount = constraints;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, ME_R(-9.81));
    static MeMatrix4 ground = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    assert_non_null(MstFixedModelCreate(u, McdPlaneCreate(MstUniverseGetFramework(u)), ground));
    McdGeometryID ball = McdSphereCreate(MstUniverseGetFramework(u), ME_R(0.5));
    for (int i = 0; i < spheres; i++) {
        McdModelID m = MstModelAndBodyCreate(u, ball, 1000 / (ME_R(4.0) / 3 * ME_PI * ME_R(0.125)));
        assert_non_null(m);
        MdtBodySetPosition(McdModelGetBody(m), (MeReal)(i % 5) * 3, (MeReal)(i / 5) * 3, ME_R(0.49));
    }
    return u;
}

/* The space's pair pool, too small for the spheres' pairs with the ground: the message names
 * MstUniverseSizes.collisionPairsMaxCount and MstUniverseStep, once in 100 steps; every step's loss
 * is still counted. */
static void universe_pair_pool_names_the_sizes_field_once(void **state)
{
    (void)state;
    MstUniverseID u = sphereFloor(20, 8, 500);
    for (int i = 0; i < 100; i++)
        MstUniverseStep(u, STEP);
    int last = -1;
    assert_int_equal(shown(ME_ERR_POOL_FULL, &last), 1);
    assert_string_equal(seen[last].function, "MstUniverseStep");
    assert_non_null(strstr(seen[last].text, "raise MstUniverseSizes.collisionPairsMaxCount"));
    assert_non_null(strstr(seen[last].text, "later losses are counted"));
    assert_true(MeMessageGetCount(ME_ERR_POOL_FULL) >= 100); /* lost every step, counted every step */
    MstUniverseDestroy(u);
}

/* The constraint pool, too small for the contacts: named by its MstUniverseSizes field, once. */
static void universe_contact_pool_names_the_sizes_field_once(void **state)
{
    (void)state;
    MstUniverseID u = sphereFloor(20, 500, 10);
    for (int i = 0; i < 100; i++)
        MstUniverseStep(u, STEP);
    int last = -1;
    assert_int_equal(shown(ME_ERR_POOL_FULL, &last), 1);
    assert_string_equal(seen[last].function, "MstUniverseStep");
    assert_non_null(strstr(seen[last].text, "raise MstUniverseSizes.dynamicConstraintsMaxCount"));
    assert_null(strstr(seen[last].text, "MdtWorldCreate"));
    assert_true(MeMessageGetCount(ME_ERR_POOL_FULL) >= 100);
    MstUniverseDestroy(u);
}

/* The same pools made directly name the creation call's parameter; the bridge stepped by the
 * application names MstBridgeUpdateContacts. */
static void pools_made_directly_name_the_creation_parameter(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(1, 1, 1, 1);
    assert_non_null(MdtBodyCreate(w));
    assert_null(MdtBodyCreate(w));
    int last = -1;
    assert_int_equal(shown(ME_ERR_POOL_FULL, &last), 1);
    assert_string_equal(seen[last].function, "MdtBodyCreate");
    assert_non_null(strstr(seen[last].text, "raise maxBodies in MdtWorldCreate"));
    MdtWorldDestroy(w);

    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = 1;
    sizes.materialsMaxCount = 1;
    MstUniverseID u = MstUniverseCreate(&sizes);
    McdGeometryID ball = McdSphereCreate(MstUniverseGetFramework(u), 1);
    assert_non_null(MstModelAndBodyCreate(u, ball, 1));
    assert_null(MstModelAndBodyCreate(u, ball, 1));
    assert_int_equal(shown(ME_ERR_POOL_FULL, &last), 2);
    assert_non_null(strstr(seen[last].text, "raise MstUniverseSizes.dynamicBodiesMaxCount"));
    assert_int_equal(MstBridgeGetNewMaterial(MstUniverseGetBridge(u)), MST_MATERIAL_INVALID);
    assert_int_equal(shown(ME_ERR_POOL_FULL, &last), 3);
    assert_string_equal(seen[last].function, "MstBridgeGetNewMaterial");
    assert_non_null(strstr(seen[last].text, "raise MstUniverseSizes.materialsMaxCount"));
    MstUniverseDestroy(u);

    /* The parts stepped by hand: the bridge's message names the bridge's update. */
    u = sphereFloor(20, 500, 10);
    seenCount = 0;
    for (int i = 0; i < 10; i++) {
        McdSpaceUpdateAll(MstUniverseGetSpace(u));
        MstBridgeUpdateContacts(MstUniverseGetBridge(u), MstUniverseGetSpace(u), MstUniverseGetWorld(u));
        MdtWorldStep(MstUniverseGetWorld(u), STEP);
    }
    assert_int_equal(shown(ME_ERR_POOL_FULL, &last), 1);
    assert_string_equal(seen[last].function, "MstBridgeUpdateContacts");
    MstUniverseDestroy(u);

    /* Karma 1.2's lower level by hand (the space's pairs, MstHandleTransitions, MstHandleCollisions):
     * once, naming MstHandleCollisions; the world's caller name is left as it was. */
    u = sphereFloor(20, 500, 10);
    McdSpaceID space = MstUniverseGetSpace(u);
    MdtWorldID world = MstUniverseGetWorld(u);
    McdModelPairContainer *pairs = McdModelPairContainerCreate(500);
    seenCount = 0;
    for (int i = 0; i < 10; i++) {
        McdSpaceUpdateAll(space);
        McdSpaceEndChanges(space);
        McdSpacePairIterator it;
        McdSpacePairIteratorBegin(space, &it);
        McdModelPairContainerReset(pairs);
        McdSpaceGetPairs(space, &it, pairs);
        MstHandleTransitions(pairs, space, world, MstUniverseGetBridge(u));
        MstHandleCollisions(pairs, space, world, MstUniverseGetBridge(u));
        McdSpaceBeginChanges(space);
        MdtWorldStep(world, STEP);
    }
    assert_int_equal(shown(ME_ERR_POOL_FULL, &last), 1);
    assert_string_equal(seen[last].function, "MstHandleCollisions");
    assert_null(MdtWorldGetCallerName(world));
    McdModelPairContainerDestroy(pairs);
    MstUniverseDestroy(u);
}

/* Bodies left disabled: one hint, shown at the default level, naming MdtBodyEnable. */
static void hint_when_no_body_is_enabled(void **state)
{
    (void)state;
    assert_true(MeErrorCodeLevel(ME_ERR_NO_BODY_ENABLED) >= MeGetMessageLevel());
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetGravity(w, 0, ME_R(-9.81), 0);
    MdtWorldStep(w, STEP); /* an empty world: nothing to say */
    assert_int_equal(seenCount, 0);
    MdtBodyID b = MdtBodyCreate(w);
    MdtBodySetPosition(b, 0, 10, 0);
    for (int i = 0; i < 10; i++)
        MdtWorldStep(w, STEP);
    int last = -1;
    assert_int_equal(shown(ME_ERR_NO_BODY_ENABLED, &last), 1);
    assert_string_equal(seen[last].function, "MdtWorldStep");
    assert_non_null(strstr(seen[last].text, "MdtBodyEnable"));
    assert_non_null(strstr(seen[last].text, "MdtWorldSetHints"));
    assert_int_equal(seenCount, 1);
    MdtWorldDestroy(w);

    /* The same world after the body fell asleep (auto-disable) says nothing: it moved. */
    w = MdtWorldCreate(4, 4, 1, 1);
    b = MdtBodyCreate(w);
    MdtBodyEnable(b);
    MdtBodySetLinearVelocity(b, ME_R(0.001), 0, 0);
    seenCount = 0;
    for (int i = 0; i < 600; i++)
        MdtWorldStep(w, STEP);
    assert_false(MdtBodyIsEnabled(b));
    assert_int_equal(seenCount, 0);
    MdtWorldDestroy(w);
}

/* Gravity left at zero with enabled bodies on which nothing acts: one hint naming MdtWorldSetGravity;
 * gravity, a velocity, a force or MdtWorldSetHints(w, MEFALSE) each keep it quiet. */
static void hint_when_gravity_is_zero_and_nothing_acts(void **state)
{
    (void)state;
    MdtWorldID w = MdtWorldCreate(4, 4, 1, 1);
    MdtBodyEnable(MdtBodyCreate(w));
    for (int i = 0; i < 10; i++)
        MdtWorldStep(w, STEP);
    int last = -1;
    assert_int_equal(shown(ME_ERR_NOTHING_ACTS, &last), 1);
    assert_non_null(strstr(seen[last].text, "MdtWorldSetGravity"));
    assert_int_equal(seenCount, 1);
    MdtWorldDestroy(w);

    /* In a universe, the hint names the call the application made. */
    MstUniverseID u = MstUniverseCreate(&MstUniverseDefaultSizes);
    assert_non_null(MstModelAndBodyCreate(u, McdSphereCreate(MstUniverseGetFramework(u), 1), 1));
    seenCount = 0;
    MstUniverseStep(u, STEP);
    assert_int_equal(shown(ME_ERR_NOTHING_ACTS, &last), 1);
    assert_string_equal(seen[last].function, "MstUniverseStep");
    MstUniverseDestroy(u);

    for (int variant = 0; variant < 4; variant++) {
        seenCount = 0;
        w = MdtWorldCreate(4, 4, 1, 1);
        MdtBodyID b = MdtBodyCreate(w);
        MdtBodyEnable(b);
        if (variant == 0)
            MdtWorldSetGravity(w, 0, ME_R(-9.81), 0);
        else if (variant == 1)
            MdtBodySetAngularVelocity(b, 0, 1, 0);
        else if (variant == 2)
            MdtBodyAddForce(b, 1, 0, 0);
        else
            MdtWorldSetHints(w, MEFALSE);
        assert_int_equal(MdtWorldGetHints(w), variant != 3);
        for (int i = 0; i < 10; i++)
            MdtWorldStep(w, STEP);
        assert_int_equal(seenCount, 0);
        MdtWorldDestroy(w);
    }
}

/* A 500 kg box in a world of the default mass scale (1 kg): a warning, shown by default, naming the
 * function called and what to set, once per world. */
static void mass_far_from_the_scale_says_what_to_set(void **state)
{
    (void)state;
    assert_true(MeErrorCodeLevel(ME_ERR_MASS_SCALE) >= MeGetMessageLevel());
    MstUniverseID u = MstUniverseCreate(&MstUniverseDefaultSizes);
    MdtBodyID b = MdtBodyCreate(MstUniverseGetWorld(u));
    MdtBodySetMass(b, 500);
    MdtBodySetMass(b, 600);
    int last = -1;
    assert_int_equal(shown(ME_ERR_MASS_SCALE, &last), 1);
    assert_string_equal(seen[last].function, "MdtBodySetMass");
    assert_non_null(strstr(seen[last].text, "set MstUniverseSizes.massScale to a typical mass"));
    MstUniverseDestroy(u);
    /* Made by the universe's helper at 500 kg: the helper is named. */
    u = MstUniverseCreate(&MstUniverseDefaultSizes);
    McdGeometryID box = McdBoxCreate(MstUniverseGetFramework(u), 1, 1, 1);
    assert_non_null(MstModelAndBodyCreate(u, box, 500));
    assert_int_equal(shown(ME_ERR_MASS_SCALE, &last), 2);
    assert_string_equal(seen[last].function, "MstModelAndBodyCreate");
    MstUniverseDestroy(u);
}

/* Rejections inside helpers name the public function: a pair test for an unknown type. */
static void rejections_name_the_public_function(void **state)
{
    (void)state;
    McdFrameworkID fw = McdInit(0, 4, 0, 1);
    assert_false(McdFrameworkSetUserInteraction(fw, kMcdGeometryTypeSphere, 99, NULL));
    int last = -1;
    assert_int_equal(shown(ME_ERR_ARGUMENT_RANGE, &last), 1);
    assert_string_equal(seen[last].function, "McdFrameworkSetUserInteraction");
    McdTerm(fw);
    MePool pool;
    MePoolFixedAPI.init(&pool, 4, 0, 0);
    assert_int_equal(shown(ME_ERR_ARGUMENT_RANGE, &last), 2);
    assert_string_equal(seen[last].function, "MePoolAPI.init");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(universe_pair_pool_names_the_sizes_field_once, setup, teardown),
        cmocka_unit_test_setup_teardown(universe_contact_pool_names_the_sizes_field_once, setup, teardown),
        cmocka_unit_test_setup_teardown(pools_made_directly_name_the_creation_parameter, setup, teardown),
        cmocka_unit_test_setup_teardown(hint_when_no_body_is_enabled, setup, teardown),
        cmocka_unit_test_setup_teardown(hint_when_gravity_is_zero_and_nothing_acts, setup, teardown),
        cmocka_unit_test_setup_teardown(mass_far_from_the_scale_says_what_to_set, setup, teardown),
        cmocka_unit_test_setup_teardown(rejections_name_the_public_function, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
