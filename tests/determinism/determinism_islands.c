/* determinism_islands.c -- the golden hash of a scene of many islands, for the threaded step (issue
 * 17, point 5): every stage that runs on several workers gets work to split.
 *
 * - 12 stacks of three boxes on the ground (contacts: the bridge's pair tests, rows, solves);
 * - 6 chains of five hinged links hanging from the world, each hinge with limits that are reached
 *   only now and then (a hinge writes fewer rows than its bound most steps: the threaded pack moves
 *   partitions' rows together);
 * - 2 pendulums held by a user constraint (whose function the step calls on the stepping thread);
 * - 40 balls dropped apart onto the ground (many one-body partitions: prediction and integration).
 *
 * Friction bounded by the normal force (linked rows), and the scene run twice: with the world's
 * solver choice (small partitions: the exact path) and forced onto the iterative path (which reads
 * the declared contacts), so that every step-global row index the threaded pack rewrites is used.
 *
 * Built on the public API (MstUniverse). tests/cmake/determinism.cmake builds it against the -O0 and
 * -O2 cores and, with tests/determinism/threaded_worlds.c, on pools of 2 and 4 threads: one golden
 * hash per precision for all of them. KARMA_DETERMINISM_PRINT=1 prints the new value after a change
 * on purpose, KARMA_DETERMINISM_TRACE=1 the chained hash at each sample. */
#include <stdlib.h>

#include "karma_test.h"

#include <karma/karma.h>

#define STEPS 240
#define HASH_EVERY 10
#define STACKS 12
#define STACK_HEIGHT 3
#define CHAINS 6
#define LINKS 5
#define PENDULUMS 2
#define BALLS 40
#define BODIES (STACKS * STACK_HEIGHT + CHAINS * LINKS + PENDULUMS + BALLS)

#if KARMA_DOUBLE
#  define GOLDEN_DIRECT 0xcd8d0ac7680ca9a9ull
#  define GOLDEN_ITERATIVE 0x0970c90e2a2becb9ull
#else
#  define GOLDEN_DIRECT 0xe29f5bdc645091ebull
#  define GOLDEN_ITERATIVE 0x7813518459c0d562ull
#endif

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

/* A pendulum's rod: the bob's distance from its pivot (the constraint struct) held at its length. */
typedef struct Rod {
    MeVector3 pivot;
    MeReal length;
} Rod;

static int rodRow(MdtUserConstraintID j, MdtUserConstraintRow *rows, int maxRows, const MdtBclSolverParameters *params,
                  void *data)
{
    (void)maxRows;
    (void)params;
    const Rod *rod = data;
    MeVector3 p;
    MdtBodyGetPosition(MdtConstraintGetBody(MdtUserConstraintQuaConstraint(j), 0), p);
    MeVector3Subtract(p, p, rod->pivot);
    MeReal len = MeVector3Normalize(p);
    MeVector3Copy(rows[0].linear0, p); /* d|p|/dt = n·v */
    rows[0].error = len - rod->length;
    return 1;
}

static MdtBodyID addBody(MstUniverseID u, McdGeometryID g, MeReal x, MeReal y, MeReal z)
{
    McdModelID m = MstModelAndBodyCreate(u, g, 400);
    assert_non_null(m);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetPosition(b, x, y, z);
    return b;
}

static Rod rods[PENDULUMS];

static MstUniverseID buildScene(MeBool iterative)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = BODIES;
    sizes.collisionModelsMaxCount = BODIES + 1;
    sizes.collisionGeometryInstancesMaxCount = BODIES + 1;
    sizes.dynamicConstraintsMaxCount = 1000;
    sizes.collisionPairsMaxCount = 1000;
    MstUniverseID u = MstUniverseCreate(&sizes);
    assert_non_null(u);
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, 0, ME_R(-9.81));
    MdtWorldSetAutoDisable(w, MEFALSE);
    if (iterative)
        MdtWorldSetLCPSolver(w, MdtLCPSolverIterative);
    McdFrameworkID fw = MstUniverseGetFramework(u);
    assert_non_null(MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM));
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.6));

    McdGeometryID box = McdBoxCreate(fw, ME_R(0.4), ME_R(0.4), ME_R(0.4));
    for (int s = 0; s < STACKS; s++)
        for (int k = 0; k < STACK_HEIGHT; k++)
            addBody(u, box, ME_R(1.5) * (MeReal)(s % 4) + ME_R(0.03) * (MeReal)k, ME_R(1.5) * (MeReal)(s / 4),
                    ME_R(0.2) + ME_R(0.41) * (MeReal)k);

    /* Chains along x at y = 6, hanging from z = 4 and released at 40° from the vertical. */
    McdGeometryID link = McdBoxCreate(fw, ME_R(0.1), ME_R(0.1), ME_R(0.4));
    for (int c = 0; c < CHAINS; c++) {
        MdtBodyID previous = NULL;
        MeReal x0 = ME_R(1.2) * (MeReal)c, s = ME_R(0.643), co = ME_R(0.766);
        for (int k = 0; k < LINKS; k++) {
            MeReal along = ME_R(0.2) + ME_R(0.4) * (MeReal)k;
            MdtBodyID b = addBody(u, link, x0, ME_R(6.0) + s * along, ME_R(4.0) - co * along);
            MeMatrix3 R;
            MeMatrix3FromEulerAngles(R, ME_R(0.698), 0, 0);
            MdtBodySetOrientation(b, R);
            MdtHingeID h = MdtHingeCreate(w);
            MdtHingeSetBodies(h, b, previous);
            MeReal top = along - ME_R(0.2);
            MdtHingeSetPosition(h, x0, ME_R(6.0) + s * top, ME_R(4.0) - co * top);
            MdtHingeSetAxis(h, 1, 0, 0);
            MdtLimitID l = MdtHingeGetLimit(h);
            MdtSingleLimitSetStop(MdtLimitGetLowerLimit(l), ME_R(-0.5));
            MdtSingleLimitSetStop(MdtLimitGetUpperLimit(l), ME_R(0.5));
            MdtLimitActivateLimits(l, METRUE);
            MdtHingeEnable(h);
            previous = b;
        }
    }

    McdGeometryID ball = McdSphereCreate(fw, ME_R(0.15));
    for (int k = 0; k < PENDULUMS; k++) {
        MeVector3Set(rods[k].pivot, ME_R(-3.0), ME_R(2.0) * (MeReal)k, ME_R(3.0));
        rods[k].length = ME_R(1.0);
        MdtBodyID bob = addBody(u, ball, ME_R(-2.4), ME_R(2.0) * (MeReal)k, ME_R(2.2));
        MdtUserConstraintID j = MdtUserConstraintCreate(w);
        MdtUserConstraintSetBodies(j, bob, NULL);
        MdtUserConstraintSetAddConstraintFunction(j, rodRow);
        MdtUserConstraintSetConstraintStruct(j, &rods[k]);
        MdtUserConstraintEnable(j);
    }
    for (int k = 0; k < BALLS; k++)
        addBody(u, ball, ME_R(-6.0) + ME_R(0.5) * (MeReal)(k % 8), ME_R(-3.0) - ME_R(0.5) * (MeReal)(k / 8),
                ME_R(0.5) + ME_R(0.07) * (MeReal)k);
    return u;
}

/* Run the scene; returns the hash chained every HASH_EVERY steps. Counts the steps with contacts and
 * with more than one partition of rows, so that the scene cannot pass without the work it is for. */
static uint64_t runScene(MeBool iterative, MeBool trace, int *mostContacts, int *mostPartitions)
{
    MstUniverseID u = buildScene(iterative);
    MdtWorldID w = MstUniverseGetWorld(u);
    uint64_t hash = KARMA_HASH_INIT;
    *mostContacts = *mostPartitions = 0;
    for (int step = 1; step <= STEPS; step++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        MdtSolverStats s;
        MdtWorldGetSolverStats(w, &s);
        int contacts = MstBridgeGetLastContactCount(MstUniverseGetBridge(u));
        if (contacts > *mostContacts)
            *mostContacts = contacts;
        if (s.partitions > *mostPartitions)
            *mostPartitions = s.partitions;
        if (step % HASH_EVERY == 0) {
            hash = karma_hash_world(hash, w);
            if (trace)
                printf("step %3d hash 0x%016llx contacts %d rows %d\n", step, (unsigned long long)hash, contacts,
                       s.rows);
        }
    }
    MstUniverseDestroy(u);
    return hash;
}

static void checkScene(const char *name, MeBool iterative, uint64_t golden)
{
    karma_capture_messages();
    const MeBool trace = getenv("KARMA_DETERMINISM_TRACE") != NULL;
    int contacts1, partitions1, contacts2, partitions2;
    uint64_t first = runScene(iterative, trace, &contacts1, &partitions1);
    uint64_t second = runScene(iterative, MEFALSE, &contacts2, &partitions2);
    print_message("%s: hash 0x%016llx (run 1), 0x%016llx (run 2), golden 0x%016llx (%s); most contacts %d, "
                  "most partitions with rows %d\n",
                  name, (unsigned long long)first, (unsigned long long)second, (unsigned long long)golden,
                  KARMA_DOUBLE ? "double" : "float", contacts1, partitions1);
    if (getenv("KARMA_DETERMINISM_PRINT"))
        printf("#  define GOLDEN_%s 0x%016llxull\n", name, (unsigned long long)first);
    /* Contacts under every stack and ball, a row partition per stack, chain and pendulum at least. */
    assert_true(contacts1 >= 4 * (STACKS * STACK_HEIGHT + BALLS / 2));
    assert_true(partitions1 >= STACKS + CHAINS + PENDULUMS);
    assert_true(first == second);
    assert_true(first == golden);
    assert_int_equal(karma_warning_count(), 0);
}

static void islands_exact_path_same_hash_twice_and_golden(void **state)
{
    (void)state;
    checkScene("DIRECT", MEFALSE, GOLDEN_DIRECT);
}

static void islands_iterative_path_same_hash_twice_and_golden(void **state)
{
    (void)state;
    checkScene("ITERATIVE", METRUE, GOLDEN_ITERATIVE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(islands_exact_path_same_hash_twice_and_golden),
        cmocka_unit_test(islands_iterative_path_same_hash_twice_and_golden),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
