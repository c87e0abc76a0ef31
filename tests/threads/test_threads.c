/* Independent universes on separate threads (Karma's promise: one world, space or universe per
 * thread, no locking by the application). THREADS identical scenes (boxes and spheres falling onto a
 * plane and coming to rest in contact with each other) are each built and stepped on a thread of
 * their own, all at once; every one must end in exactly the state (bit for bit) of the same scene run
 * alone on the main thread. Run under ThreadSanitizer by the `tsan` configuration of
 * tests/run_configs.sh, which also proves the library's shared state (the ID registry, the memory
 * and message counters) free of data races. (POSIX threads: ThreadSanitizer does not see C11's
 * thrd_create.) */
#include "karma_test.h"

#include <string.h>
#include <pthread.h>

#include <karma/karma.h>

#define THREADS 4
#define BOXES 6
#define SPHERES 6
#define BODIES (BOXES + SPHERES)
#define STEPS 300
/* Per body: position, quaternion, linear and angular velocity. */
#define STATE_REALS (BODIES * (3 + 4 + 3 + 3))

typedef struct Scene {
    MeReal state[STATE_REALS];
    int ok; /* the scene was built and stepped without a NULL ID */
} Scene;

static McdModelID addBody(MstUniverseID u, McdGeometryID g, MeReal x, MeReal y, MeReal z)
{
    McdModelID m = MstModelAndBodyCreate(u, g, ME_R(1.0));
    if (m)
        MdtBodySetPosition(McdModelGetBody(m), x, y, z);
    return m;
}

/* Build, step and record one scene; everything it touches is its own. */
static void runScene(Scene *scene)
{
    MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* plane normal +y */
    MdtBodyID bodies[BODIES];
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    MstUniverseID u;
    McdFrameworkID fw;
    McdGeometryID box, ball;
    int i, n = 0, k = 0;

    scene->ok = 0;
    sizes.dynamicBodiesMaxCount = BODIES;
    sizes.collisionModelsMaxCount = BODIES + 1;
    sizes.dynamicConstraintsMaxCount = 16 * BODIES;
    sizes.collisionPairsMaxCount = 8 * BODIES;
    u = MstUniverseCreate(&sizes);
    if (!u)
        return;
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, ME_R(-9.81), 0);
    fw = MstUniverseGetFramework(u);
    if (!MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM))
        return;
    box = McdBoxCreate(fw, ME_R(0.5), ME_R(0.5), ME_R(0.5));
    ball = McdSphereCreate(fw, ME_R(0.3));
    /* Two staggered columns, so bodies land on each other and tip over. */
    for (i = 0; i < BODIES; i++) {
        MeReal x = (i % 2) ? ME_R(0.2) * (MeReal)(i % 3) : ME_R(-0.15);
        McdModelID m = addBody(u, i < BOXES ? box : ball, x, ME_R(0.5) + ME_R(0.7) * (MeReal)i, ME_R(0.1) * (MeReal)(i % 4));
        if (!m)
            return;
        bodies[n++] = McdModelGetBody(m);
    }
    for (i = 0; i < STEPS; i++)
        MstUniverseStep(u, ME_R(1.0) / 60);
    for (i = 0; i < BODIES; i++) {
        MdtBodyGetPosition(bodies[i], &scene->state[k]);
        MdtBodyGetQuaternion(bodies[i], &scene->state[k + 3]);
        MdtBodyGetLinearVelocity(bodies[i], &scene->state[k + 7]);
        MdtBodyGetAngularVelocity(bodies[i], &scene->state[k + 10]);
        k += 13;
    }
    MstUniverseDestroy(u);
    scene->ok = 1;
}

static void *sceneThread(void *arg)
{
    runScene(arg);
    return NULL;
}

static void universes_on_threads_match_the_single_thread_run(void **state)
{
    Scene reference, scenes[THREADS];
    pthread_t threads[THREADS];
    int i, round;
    (void)state;

    runScene(&reference);
    assert_true(reference.ok);
    /* The bodies fell and came to rest above the plane: a scene that did something. */
    for (i = 0; i < BODIES; i++) {
        assert_true(reference.state[13 * i + 1] > ME_R(0.1));
        assert_true(reference.state[13 * i + 1] < ME_R(3.0));
    }

    /* Twice: creation, stepping and destruction interleave differently each round. */
    for (round = 0; round < 2; round++) {
        memset(scenes, 0, sizeof scenes);
        for (i = 0; i < THREADS; i++)
            assert_int_equal(pthread_create(&threads[i], NULL, sceneThread, &scenes[i]), 0);
        for (i = 0; i < THREADS; i++)
            assert_int_equal(pthread_join(threads[i], NULL), 0);
        for (i = 0; i < THREADS; i++) {
            assert_true(scenes[i].ok);
            assert_memory_equal(scenes[i].state, reference.state, sizeof reference.state);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(universes_on_threads_match_the_single_thread_run),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
