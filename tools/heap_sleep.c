/* heap_sleep -- the heap of tests/mst/test_heap_sleep.c (boxes of edges 0.9 to 1.1 m dropped at random
 * orientations onto the ground, 16 to a layer) built from other seeds and sizes: per heap, the time it
 * takes to sleep and the largest speed and angular speed a body had at the step before it was put to
 * sleep, against the test's bounds (asleep within 25 s, 0.3 m/s, 0.3 rad/s). Seed 17 with 120 boxes is
 * the test's own heap. A check that settling is no worse than before needs many heaps: one heap is
 * chaotic, and any change to contacts or the solver gives it another trajectory.
 *
 *   heap_sleep [firstSeed [lastSeed [boxes]]]     defaults 17 17 120
 *
 * Prints one line per heap and a summary: how many heaps broke a bound, the mean sleep time and the
 * largest figures. Exits 0. */
#include <karma/karma.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define STEP (ME_R(1.0) / 60)
#define SLEEP_LIMIT_S 25.0
#define SPEED_BOUND 0.3
#define SPIN_BOUND 0.3
#define EDGE_JITTER 0.1

static double uniform(unsigned long long *state) /* [-1, 1), the test's generator */
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 4503599627370496.0 - 1.0;
}

/* The test's heap (buildHeap in tests/mst/test_heap_sleep.c) of `n` boxes from seed `seed`. */
static MstUniverseID buildHeap(int n, unsigned long long seed, MdtBodyID *body)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 1;
    sizes.dynamicBodiesMaxCount = n;
    sizes.collisionModelsMaxCount = n + 1;
    sizes.collisionPairsMaxCount = 10 * n;
    sizes.dynamicConstraintsMaxCount = 30 * n;
    MstUniverseID u = MstUniverseCreate(&sizes);
    if (!u)
        return NULL;
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, ME_R(-9.81));
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    McdFrameworkID fw = MstUniverseGetFramework(u);
    MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM);
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.6));
    unsigned long long rng = seed;
    for (int i = 0; i < n; i++) {
        const int layer = i / 16, j = i % 16;
        const MeReal x = (MeReal)(((j % 4) - 1.5) * 1.6 + 0.1 * uniform(&rng));
        const MeReal y = (MeReal)(((j / 4) - 1.5) * 1.6 + 0.1 * uniform(&rng));
        double axis[3] = {uniform(&rng), uniform(&rng), uniform(&rng)};
        const double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]) + 1e-9;
        const double half = 0.5 * 3.14159265358979 * uniform(&rng);
        const MeReal edge[3] = {(MeReal)(1.0 + EDGE_JITTER * uniform(&rng)), (MeReal)(1.0 + EDGE_JITTER * uniform(&rng)),
                                (MeReal)(1.0 + EDGE_JITTER * uniform(&rng))};
        McdModelID m = MstModelAndBodyCreate(u, McdBoxCreate(fw, edge[0], edge[1], edge[2]), 1);
        body[i] = McdModelGetBody(m);
        MdtBodySetPosition(body[i], x, y, (MeReal)(1.0 + 1.6 * layer));
        MdtBodySetQuaternion(body[i], (MeReal)cos(half), (MeReal)(sin(half) * axis[0] / len),
                             (MeReal)(sin(half) * axis[1] / len), (MeReal)(sin(half) * axis[2] / len));
    }
    return u;
}

typedef struct Outcome {
    double time;            /* s until every body slept, -1 when not within SLEEP_LIMIT_S */
    double speed, spin;     /* the largest at the step before a body was put to sleep */
    int fastSleeps;         /* bodies put to sleep over a bound */
} Outcome;

static Outcome settle(MstUniverseID u, int n, MdtBodyID *body)
{
    Outcome o = {-1, 0, 0, 0};
    MdtWorldID w = MstUniverseGetWorld(u);
    double *lastSpeed = malloc(sizeof(double) * (size_t)n), *lastSpin = malloc(sizeof(double) * (size_t)n);
    MeBool *was = malloc(sizeof(MeBool) * (size_t)n);
    for (int step = 1; step <= (int)(SLEEP_LIMIT_S * 60 + 0.5); step++) {
        for (int i = 0; i < n; i++) {
            MeVector3 v, av;
            MdtBodyGetLinearVelocity(body[i], v);
            MdtBodyGetAngularVelocity(body[i], av);
            lastSpeed[i] = MeVector3Magnitude(v);
            lastSpin[i] = MeVector3Magnitude(av);
            was[i] = MdtBodyIsEnabled(body[i]);
        }
        MstUniverseStep(u, STEP);
        for (int i = 0; i < n; i++)
            if (was[i] && !MdtBodyIsEnabled(body[i])) {
                o.speed = fmax(o.speed, lastSpeed[i]);
                o.spin = fmax(o.spin, lastSpin[i]);
                o.fastSleeps += lastSpeed[i] >= SPEED_BOUND || lastSpin[i] >= SPIN_BOUND;
            }
        if (MdtWorldGetEnabledBodies(w) == 0) {
            o.time = step / 60.0;
            break;
        }
    }
    free(lastSpeed);
    free(lastSpin);
    free(was);
    return o;
}

int main(int argc, char **argv)
{
    const unsigned long long first = argc > 1 ? strtoull(argv[1], NULL, 10) : 17;
    const unsigned long long last = argc > 2 ? strtoull(argv[2], NULL, 10) : first;
    const int n = argc > 3 ? atoi(argv[3]) : 120;
    if (n < 1 || last < first) {
        fprintf(stderr, "usage: heap_sleep [firstSeed [lastSeed [boxes]]]\n");
        return 2;
    }
    MdtBodyID *body = malloc(sizeof(MdtBodyID) * (size_t)n);
    int heaps = 0, broken = 0, awake = 0;
    double sumTime = 0, maxSpeed = 0, maxSpin = 0;
    for (unsigned long long seed = first; seed <= last; seed++) {
        MstUniverseID u = buildHeap(n, seed, body);
        if (!u)
            return 1;
        const Outcome o = settle(u, n, body);
        const int bad = o.time < 0 || o.speed >= SPEED_BOUND || o.spin >= SPIN_BOUND;
        printf("seed %llu boxes %d: asleep %.2f s, at sleep %.3f m/s %.3f rad/s, %d bodies over a bound%s\n", seed, n,
               o.time, o.speed, o.spin, o.fastSleeps, bad ? "  BROKEN" : "");
        heaps++;
        broken += bad;
        awake += o.time < 0;
        sumTime += o.time < 0 ? SLEEP_LIMIT_S : o.time;
        maxSpeed = fmax(maxSpeed, o.speed);
        maxSpin = fmax(maxSpin, o.spin);
        MstUniverseDestroy(u);
    }
    printf("%s, %d heaps of %d: %d broke a bound (%d still awake at %.0f s); mean time to sleep %.2f s; "
           "largest at sleep %.3f m/s %.3f rad/s\n",
           sizeof(MeReal) == sizeof(double) ? "double" : "float", heaps, n, broken, awake, SLEEP_LIMIT_S,
           sumTime / heaps, maxSpeed, maxSpin);
    free(body);
    return 0;
}
