/* determinism_topple.c -- the golden-hash test of the whole pipeline: the demos' Topple scene (six
 * stacks of blocks on a plane with friction, four balls shot at them: collision space, nearfield
 * tests, bridge, contact groups with warm start, partitions, auto-disable, the iterative solver)
 * gives bit-identical states run after run, at -O0 and at -O2, equal to a hash recorded here.
 *
 * tests/cmake/determinism.cmake builds this file together with the demo sources (every demos/ source file) twice,
 * against the -O0 and the -O2 copy of the core library. Each program runs the scene twice and
 * compares the FNV-1a hash of every body's state (position, quaternion, linear and angular velocity,
 * enabled flag), chained over every step, with the golden value of its precision.
 *
 * If the hash changes on purpose (a change to the scene, the collision code or the solver), run the
 * program with KARMA_DETERMINISM_PRINT=1 to print the new value; KARMA_DETERMINISM_TRACE=1 prints
 * the hash after each step, to find where two builds diverge. */
#include <stdlib.h>

#include "karma_test.h"

#include <karma/karma.h>

#include "demo.h"

#define STEPS 600 /* 10 s: the stacks settle, then the four balls are shot at 2, 3, 4 and 5 s */

#if KARMA_DOUBLE
#  define GOLDEN_HASH 0x8636b519d8f1a3c6ull
#else
#  define GOLDEN_HASH 0x66a348830f36a006ull
#endif

static uint64_t runTopple(MeBool trace, int *contactsSeen)
{
    const DemoScene *scene = DemoSceneFind("topple");
    assert_non_null(scene);
    DemoInstance demo;
    assert_true(DemoCreate(scene, &demo));
    uint64_t hash = KARMA_HASH_INIT;
    *contactsSeen = 0;
    for (int step = 0; step < STEPS; step++) {
        DemoStep(&demo, scene->defaultStepSize);
        hash = karma_hash_world(hash, demo.world);
        int contacts = MstBridgeGetLastContactCount(MstUniverseGetBridge(demo.universe));
        if (contacts > *contactsSeen)
            *contactsSeen = contacts;
        if (trace)
            printf("step %3d hash 0x%016llx enabled bodies %d contacts %d\n", step, (unsigned long long)hash,
                   MdtWorldGetEnabledBodies(demo.world), contacts);
    }
    DemoDestroy(&demo);
    return hash;
}

static void topple_same_hash_twice_and_golden(void **state)
{
    (void)state;
    karma_capture_messages();
    MeBool trace = getenv("KARMA_DETERMINISM_TRACE") != NULL;
    int contacts1 = 0, contacts2 = 0;
    uint64_t first = runTopple(trace, &contacts1);
    uint64_t second = runTopple(MEFALSE, &contacts2);
    print_message("topple: state hash after %d steps 0x%016llx (run 1), 0x%016llx (run 2), golden 0x%016llx (%s); "
                  "most contacts in a step %d\n",
                  STEPS, (unsigned long long)first, (unsigned long long)second, (unsigned long long)GOLDEN_HASH,
                  KARMA_DOUBLE ? "double" : "float", contacts1);
    if (getenv("KARMA_DETERMINISM_PRINT"))
        printf("#  define GOLDEN_HASH 0x%016llxull\n", (unsigned long long)first);
    assert_int_equal(karma_warning_count(), 0);
    assert_true(contacts1 > 50); /* the scene really exercises contacts */
    assert_true(first == second);
    assert_true(first == GOLDEN_HASH);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(topple_same_hash_twice_and_golden),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
