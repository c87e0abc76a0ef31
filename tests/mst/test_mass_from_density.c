/* Mass properties from a density are set all or nothing (found by tests/fuzz/fuzz_api.c): a density
 * whose mass is representable but whose inertia is not (its determinant underflows) used to leave a
 * new body with the mass set and the inertia refused, while MstModelAndBodyCreate returned the model.
 * Now the call is refused in its own name and changes nothing. */
#include "karma_test.h"

#include <karma/karma.h>

/* A density whose 1 m box has a mass MeReal holds but an inertia tensor whose determinant underflows. */
#if KARMA_DOUBLE
#  define TINY_DENSITY ME_R(1e-110)
#else
#  define TINY_DENSITY ME_R(1e-20)
#endif

static void tiny_density_refused_without_change(void **state)
{
    (void)state;
    karma_capture_messages();
    MstUniverseID u = MstUniverseCreate(&MstUniverseDefaultSizes);
    MdtWorldID w = MstUniverseGetWorld(u);
    McdGeometryID box = McdBoxCreate(MstUniverseGetFramework(u), 1, 1, 1);
    MdtWorldCounters before, after;
    MdtWorldGetCounters(w, &before);
    McdModelID m = (McdModelID)1;
    unsigned long refused = MeMessageGetCount(ME_ERR_INERTIA_INVALID);
    m = MstModelAndBodyCreate(u, box, TINY_DENSITY);
    assert_null(m);
    assert_true(MeMessageGetCount(ME_ERR_INERTIA_INVALID) > refused);
    assert_string_equal(karma_last_function(), "MstModelAndBodyCreate");
    MdtWorldGetCounters(w, &after);
    assert_int_equal(after.bodies, before.bodies);

    /* On an existing body: mass, inertia and centre of mass stay as they were. */
    m = MstModelAndBodyCreate(u, box, 1000);
    assert_non_null(m);
    MdtBodyID b = McdModelGetBody(m);
    MeMatrix3 I0, I1;
    MdtBodyGetInertiaTensor(b, I0);
    assert_reports(ME_ERR_INERTIA_INVALID, MstAutoSetMassProperties(b, m, TINY_DENSITY));
    MdtBodyGetInertiaTensor(b, I1);
    assert_near(MdtBodyGetMass(b), 1000, 1e-3);
    assert_memory_equal(I0, I1, sizeof I0);
    MstUniverseDestroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tiny_density_refused_without_change),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
