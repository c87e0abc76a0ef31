/* determinism_iterative.c -- golden hashes of two scenes that run Kea's iterative path
 * (src/mdt/kea/kea_iterative.h and the files it lists), the safety net for restructuring it: a
 * change that claims unchanged trajectories must keep both hashes bit-identical.
 *
 * - pile: 125 bodies (spheres, boxes, capsules, cylinders) dropped in a loose lattice onto a ground
 *   plane and onto each other;
 * - pyramid: 28 boxes in seven rows (bricks set off by half a block, 1 cm apart) on the ground.
 *
 * Both scenes are built here on the public API (MstUniverse: space, nearfield tests, bridge, contact
 * groups, world), not taken from demos/, and the world is forced onto the iterative solver with
 * MdtWorldSetLCPSolver(MdtLCPSolverIterative), so no partition takes the direct path whatever its size
 * (the test asserts it from MdtWorldGetSolverStats). tests/cmake/determinism.cmake builds this file
 * against the -O0 and the -O2 copy of the core library; the float and double configurations of
 * `make test` each build both.
 *
 * The hash: FNV-1a over every body's state (position, quaternion, velocities, enabled flag, in pool
 * order), taken every HASH_EVERY steps and chained. Each scene runs twice in one process and both runs
 * must give the golden value of the precision.
 *
 * If a hash changes on purpose, run with KARMA_DETERMINISM_PRINT=1 to print the new values;
 * KARMA_DETERMINISM_TRACE=1 prints the chained hash at each sample, to find where two builds diverge. */
#include <stdlib.h>

#include "karma_test.h"

#include <karma/karma.h>

#define HASH_EVERY 10

#ifndef KARMA_TEST_SPLIT
#  define KARMA_TEST_SPLIT 0
#endif

#if KARMA_TEST_SPLIT
/* determinism_split (determinism.cmake): the same scenes with every partition of at least SPLIT_ROWS
 * rows split over the workers (MdtWorldSetPartitionSplitRows: coloured sweeps), built at -O0 and -O2
 * and run on pools of 2 and 4 threads; the colours' order makes trajectories of their own, the same
 * for every worker count. */
#  define SPLIT_ROWS 100
#  if KARMA_DOUBLE
#    define GOLDEN_PILE 0x894850519a70cc9bull
#    define GOLDEN_PYRAMID 0xf140f4cb7ac97a00ull
#  else
#    define GOLDEN_PILE 0x3754208c55bfc075ull
#    define GOLDEN_PYRAMID 0xeca3657439583c36ull
#  endif
#elif KARMA_DOUBLE
#  define GOLDEN_PILE 0x9abb8530cec79ba2ull
#  define GOLDEN_PYRAMID 0x556ebf0be8c9902full
#else
#  define GOLDEN_PILE 0xd684f69c2606518cull
#  define GOLDEN_PYRAMID 0xbbd9388a53783e81ull
#endif

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

/** What a run saw, beyond its hash: the scene must really run the iterative path with many contacts. */
typedef struct RunStats {
    int mostContacts;       /**< most contacts the bridge made in one step */
    int iterativePartitions; /**< partitions solved iteratively, summed over steps */
    int directPartitions;   /**< partitions solved exactly, summed over steps (must stay 0) */
    int mostRowsInPartition;
    int splitPartitions;    /**< partitions split over the workers, summed over steps */
} RunStats;

/** A universe with z up, gravity 9.81 m/s², a ground plane and Coulomb friction mu everywhere. */
static MstUniverseID makeUniverse(unsigned bodies, unsigned constraints, MeReal mu)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = bodies;
    sizes.collisionModelsMaxCount = bodies + 1;
    sizes.collisionGeometryInstancesMaxCount = bodies + 1;
    sizes.dynamicConstraintsMaxCount = constraints;
    sizes.collisionPairsMaxCount = constraints;
    sizes.massScale = 10;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, 0, ME_R(-9.81));
    MdtWorldSetLCPSolver(w, MdtLCPSolverIterative);
    MdtWorldSetAutoDisable(w, MEFALSE); /* every step solves the whole scene */
#if KARMA_TEST_SPLIT
    MdtWorldSetPartitionSplitRows(w, SPLIT_ROWS);
#endif
    McdFrameworkID fw = MstUniverseGetFramework(u);
    assert_non_null(MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM));
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, mu);
    return u;
}

static MdtBodyID addBody(MstUniverseID u, McdGeometryID g, MeReal density, MeReal x, MeReal y, MeReal z)
{
    McdModelID m = MstModelAndBodyCreate(u, g, density);
    assert_non_null(m);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetPosition(b, x, y, z);
    return b;
}

/** Step u `steps` times, chaining the world hash every HASH_EVERY steps. */
static uint64_t runUniverse(MstUniverseID u, int steps, MeBool trace, RunStats *stats)
{
    MdtWorldID w = MstUniverseGetWorld(u);
    uint64_t hash = KARMA_HASH_INIT;
    *stats = (RunStats){0};
    for (int step = 1; step <= steps; step++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        MdtSolverStats s;
        MdtWorldGetSolverStats(w, &s);
        stats->iterativePartitions += s.iterativePartitions;
        stats->directPartitions += s.directPartitions;
        stats->splitPartitions += s.splitPartitions;
        if (s.maxPartitionRows > stats->mostRowsInPartition)
            stats->mostRowsInPartition = s.maxPartitionRows;
        int contacts = MstBridgeGetLastContactCount(MstUniverseGetBridge(u));
        if (contacts > stats->mostContacts)
            stats->mostContacts = contacts;
        if (step % HASH_EVERY == 0) {
            hash = karma_hash_world(hash, w);
            if (trace)
                printf("step %3d hash 0x%016llx contacts %d rows %d\n", step, (unsigned long long)hash, contacts,
                       s.rows);
        }
    }
    return hash;
}

#define PILE_COLUMNS 5
#define PILE_LAYERS 5 /* 5 x 5 x 5 = 125 bodies */
#define PILE_STEPS 300

/** 125 bodies of four shapes in a 5 x 5 lattice of columns, 0.45 m apart (closer than the bodies'
 *  sizes allow once they spread), layers 0.5 m apart, each body turned a little: they fall together
 *  onto the plane and onto each other. */
static uint64_t runPile(MeBool trace, RunStats *stats, MeReal *lowest)
{
    MstUniverseID u = makeUniverse(PILE_COLUMNS * PILE_COLUMNS * PILE_LAYERS, 3000, ME_R(0.5));
    McdFrameworkID fw = MstUniverseGetFramework(u);
    McdGeometryID shapes[4] = {McdSphereCreate(fw, ME_R(0.2)), McdBoxCreate(fw, ME_R(0.35), ME_R(0.3), ME_R(0.25)),
                               McdSphylCreate(fw, ME_R(0.12), ME_R(0.25)), McdCylinderCreate(fw, ME_R(0.16), ME_R(0.3))};
    MdtBodyID bodies[PILE_COLUMNS * PILE_COLUMNS * PILE_LAYERS];
    int n = 0;
    for (int k = 0; k < PILE_LAYERS; k++)
        for (int i = 0; i < PILE_COLUMNS; i++)
            for (int j = 0; j < PILE_COLUMNS; j++) {
                int shape = (i + 2 * j + 3 * k) % 4;
                MeReal x = (MeReal)(i - 2) * ME_R(0.45) + ME_R(0.05) * (MeReal)(k % 2);
                MeReal y = (MeReal)(j - 2) * ME_R(0.45) - ME_R(0.04) * (MeReal)(k % 3);
                MdtBodyID b = addBody(u, shapes[shape], 500, x, y, ME_R(0.4) + ME_R(0.5) * (MeReal)k);
                MeMatrix3 R;
                MeMatrix3FromEulerAngles(R, ME_R(0.3) * (MeReal)i, ME_R(0.2) * (MeReal)j, ME_R(0.1) * (MeReal)k);
                MdtBodySetOrientation(b, R);
                bodies[n++] = b;
            }
    uint64_t hash = runUniverse(u, PILE_STEPS, trace, stats);
    *lowest = 1e9f;
    for (int i = 0; i < n; i++) {
        MeVector3 p;
        MdtBodyGetPosition(bodies[i], p);
        if (p[2] < *lowest)
            *lowest = p[2];
    }
    MstUniverseDestroy(u);
    return hash;
}

#define PYRAMID_ROWS 7 /* 7 + 6 + ... + 1 = 28 boxes */
#define PYRAMID_STEPS 300
#define BRICK_X ME_R(0.5)
#define BRICK_Y ME_R(0.4)
#define BRICK_Z ME_R(0.3)
#define BRICK_GAP ME_R(0.01)

/** A two-dimensional pyramid of bricks, each row set off by half a brick, 1 cm between neighbours and
 *  between rows; it settles and must stand. Returns the largest drift of a brick from its start. */
static uint64_t runPyramid(MeBool trace, RunStats *stats, MeReal *drift)
{
    MstUniverseID u = makeUniverse(PYRAMID_ROWS * (PYRAMID_ROWS + 1) / 2, 1000, ME_R(0.6));
    McdGeometryID brick = McdBoxCreate(MstUniverseGetFramework(u), BRICK_X, BRICK_Y, BRICK_Z);
    MdtBodyID bodies[PYRAMID_ROWS * (PYRAMID_ROWS + 1) / 2];
    MeVector3 start[PYRAMID_ROWS * (PYRAMID_ROWS + 1) / 2];
    int n = 0;
    for (int row = 0; row < PYRAMID_ROWS; row++)
        for (int i = 0; i < PYRAMID_ROWS - row; i++) {
            MeReal x = ((MeReal)i - (MeReal)(PYRAMID_ROWS - row - 1) / 2) * (BRICK_X + BRICK_GAP);
            MeReal z = BRICK_Z / 2 + (MeReal)row * (BRICK_Z + BRICK_GAP);
            bodies[n] = addBody(u, brick, 400, x, 0, z);
            MeVector3Set(start[n], x, 0, z);
            n++;
        }
    uint64_t hash = runUniverse(u, PYRAMID_STEPS, trace, stats);
    *drift = 0;
    for (int i = 0; i < n; i++) {
        MeVector3 p;
        MdtBodyGetPosition(bodies[i], p);
        MeReal d = MeVector3Distance(p, start[i]);
        if (d > *drift)
            *drift = d;
    }
    MstUniverseDestroy(u);
    return hash;
}

static void report(const char *name, uint64_t first, uint64_t second, uint64_t golden, const RunStats *s)
{
    print_message("%s: hash 0x%016llx (run 1), 0x%016llx (run 2), golden 0x%016llx (%s); most contacts %d, "
                  "iterative partitions %d, direct %d, split %d, largest partition %d rows\n",
                  name, (unsigned long long)first, (unsigned long long)second, (unsigned long long)golden,
                  KARMA_DOUBLE ? "double" : "float", s->mostContacts, s->iterativePartitions, s->directPartitions,
                  s->splitPartitions, s->mostRowsInPartition);
    if (getenv("KARMA_DETERMINISM_PRINT"))
        printf("#  define GOLDEN_%s 0x%016llxull\n", name, (unsigned long long)first);
}

static void pile_iterative_same_hash_twice_and_golden(void **state)
{
    (void)state;
    karma_capture_messages();
    RunStats s1, s2;
    MeReal lowest1, lowest2;
    uint64_t first = runPile(getenv("KARMA_DETERMINISM_TRACE") != NULL, &s1, &lowest1);
    uint64_t second = runPile(MEFALSE, &s2, &lowest2);
    report("PILE", first, second, GOLDEN_PILE, &s1);
    assert_int_equal(karma_warning_count(), 0);
    /* The scene really runs the iterative path on a big contact problem, and nothing else. */
    assert_true(s1.mostContacts > 300);
    assert_true(s1.iterativePartitions > PILE_STEPS);
    assert_int_equal(s1.directPartitions, 0);
    assert_true(s1.mostRowsInPartition > 300);
    assert_true(KARMA_TEST_SPLIT ? s1.splitPartitions > PILE_STEPS / 2 : s1.splitPartitions == 0);
    /* Nothing fell through the ground: the lowest body point is its centre, at least 0.1 m up less
     * a few centimetres of penetration. */
    assert_true(lowest1 > ME_R(0.05));
    assert_true(first == second);
    assert_true(first == GOLDEN_PILE);
}

static void pyramid_iterative_same_hash_twice_and_golden(void **state)
{
    (void)state;
    karma_capture_messages();
    RunStats s1, s2;
    MeReal drift1, drift2;
    uint64_t first = runPyramid(getenv("KARMA_DETERMINISM_TRACE") != NULL, &s1, &drift1);
    uint64_t second = runPyramid(MEFALSE, &s2, &drift2);
    report("PYRAMID", first, second, GOLDEN_PYRAMID, &s1);
    assert_int_equal(karma_warning_count(), 0);
    assert_true(s1.mostContacts >= 4 * 28);
    assert_true(s1.iterativePartitions >= PYRAMID_STEPS);
    assert_int_equal(s1.directPartitions, 0);
    /* Split at every step but the first: the bricks start 1 cm apart at rest, and points apart that
     * cannot close their gap within the step do not join them yet (decision C23). */
    assert_true(KARMA_TEST_SPLIT ? s1.splitPartitions >= PYRAMID_STEPS - 1 : s1.splitPartitions == 0);
    /* The pyramid stands: the bricks settle by the 1 cm gaps and a little penetration, no more. */
    assert_true(drift1 < ME_R(0.1));
    assert_true(first == second);
    assert_true(first == GOLDEN_PYRAMID);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pile_iterative_same_hash_twice_and_golden),
        cmocka_unit_test(pyramid_iterative_same_hash_twice_and_golden),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
