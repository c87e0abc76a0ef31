/* The framework's pairFallbacks counter when the bridge tests pairs on several workers (issue 17
 * point 5's parallel pair tests): the same scene stepped serially and on pools of 2, 3 and 4 threads
 * counts exactly the same fallbacks, and exactly one per box–box test. The scene's box–box test is
 * the built-in one with one contact made a NaN (after the others, or in place of the last when they
 * fill the room): the wrapper around the pair tests drops it and counts one fallback, the same way on
 * every pool, so every run takes the same steps and tests the same pairs. On a pool the test waits
 * for another worker's test to be running too, so that tests overlap in time: a count attributed by a
 * process-wide counter read around each test (the way it was) then adds a neighbour's fallback to one
 * of two overlapping tests. */
#include "karma_test.h"
#include "karma_partitions.h"

#include <math.h>
#include <stdatomic.h>
#include <string.h>

#include <karma/karma.h>

#include <MeThreadPool.h>

#include "mcd/framework.h"

#define STACKS 16
#define STACK_BOXES 3
#define STEPS 60

static McdNearfieldFn builtInBoxBox;
/* On a pool, each test waits up to MEET_SPINS turns for a test on another worker to be running too,
 * so the workers' tests overlap in time whenever both have work. */
#define MEET_SPINS 2000000L
static int meet;
static atomic_int inTest; /* the scene's box–box tests running now */
static atomic_ulong boxBoxTests; /* the NaN contacts the scene's box–box test wrote (any thread) */

/* The built-in box–box test, then a contact with a NaN position: after its contacts, or in place of
 * the last when they fill the room. */
static int boxBoxWithANaN(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                          MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    int n = builtInBoxBox(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, cache);
    atomic_fetch_add(&inTest, 1);
    for (long i = 0; meet && atomic_load(&inTest) < 2 && i < MEET_SPINS; i++)
        ; /* wait (a while at most) for another worker's test: the two overlap */
    if (n < 0 || maxContacts < 1) {
        atomic_fetch_sub(&inTest, 1);
        return n;
    }
    const int k = n < maxContacts ? n++ : n - 1; /* after the others, or in place of the last */
    memset(&contacts[k], 0, sizeof contacts[k]);
    MeVector3Set(contacts[k].position, NAN, 0, 0);
    MeVector3Set(contacts[k].normal, 0, 1, 0);
    atomic_fetch_add(&boxBoxTests, 1);
    atomic_fetch_sub(&inTest, 1);
    return n;
}

typedef struct Run {
    unsigned long fallbacks; /* the framework's pairFallbacks after the run */
    unsigned long nanContacts; /* the NaN contacts the scene's test wrote */
    uint64_t hash;           /* every step's state */
} Run;

/* The scene stepped STEPS times on a pool of `threads` (1: serial). */
static Run runScene(int threads)
{
    Run r = {0, 0, 0};
    MstUniverseID u = karma_partitions_scene(STACKS, STACK_BOXES, 0, 0);
    assert_non_null(u);
    McdFrameworkData *fw = McdFrameworkFromID(MstUniverseGetFramework(u), "test");
    builtInBoxBox = McdFrameworkGetInteraction(fw, kMcdGeometryTypeBox, kMcdGeometryTypeBox);
    assert_non_null(builtInBoxBox);
    assert_true(McdFrameworkSetInteraction(fw, kMcdGeometryTypeBox, kMcdGeometryTypeBox, boxBoxWithANaN, "test"));
    MeThreadPool *pool = threads > 1 ? MeThreadPoolCreate(threads) : NULL;
    if (threads > 1) {
        assert_non_null(pool);
        MeThreadPoolAttachUniverse(pool, u);
        assert_int_equal(MdtWorldGetWorkerCount(MstUniverseGetWorld(u)), threads);
    }
    atomic_store(&boxBoxTests, 0);
    meet = threads > 1;
    r.hash = KARMA_HASH_INIT;
    for (int i = 0; i < STEPS; i++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        r.hash = karma_hash_world(r.hash, MstUniverseGetWorld(u));
    }
    McdFrameworkCounters k;
    McdFrameworkGetCounters(MstUniverseGetFramework(u), &k);
    r.fallbacks = k.pairFallbacks;
    r.nanContacts = atomic_load(&boxBoxTests);
    MstUniverseDestroy(u);
    MeThreadPoolDestroy(pool);
    return r;
}

static void fallbacks_are_counted_exactly_on_any_pool(void **state)
{
    (void)state;
    const Run serial = runScene(1);
    print_message("serial: %lu fallbacks for %lu NaN contacts\n", serial.fallbacks, serial.nanContacts);
    assert_true(serial.nanContacts > (unsigned long)(STACKS * STEPS)); /* stacked boxes touched, every step */
    assert_int_equal(serial.fallbacks, serial.nanContacts);
    for (int threads = 2; threads <= 4; threads++) {
        const Run pooled = runScene(threads);
        print_message("%d threads: %lu fallbacks for %lu NaN contacts\n", threads, pooled.fallbacks,
                      pooled.nanContacts);
        assert_true(pooled.hash == serial.hash); /* the same steps, so the same tests */
        assert_int_equal(pooled.nanContacts, serial.nanContacts);
        assert_int_equal(pooled.fallbacks, serial.fallbacks);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fallbacks_are_counted_exactly_on_any_pool),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
