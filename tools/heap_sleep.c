/* heap_sleep -- the heap of tests/mst/test_heap_sleep.c (boxes of edges 0.9 to 1.1 m dropped at random
 * orientations onto the ground, 16 to a layer) built from other seeds and sizes: per heap, the time it
 * takes to sleep and the largest speed and angular speed a body had at the step before it was put to
 * sleep, against the test's bounds (asleep within 25 s, 0.3 m/s, 0.3 rad/s). Seed 17 with 120 boxes is
 * the test's own heap. A check that settling is no worse than before needs many heaps: one heap is
 * chaotic, and any change to contacts or the solver gives it another trajectory.
 *
 *   heap_sleep [firstSeed [lastSeed [boxes [maxAwake]]]]     defaults 17 17 120
 *
 * Prints one line per heap and a summary: how many heaps broke a bound, the mean sleep time and the
 * largest figures. Exits 0, or, given maxAwake (the check of tests/cmake/heap_sleep.cmake), 1 when a
 * body was put to sleep over a bound or more than maxAwake heaps were still awake at 25 s. */
#include <karma/karma.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "karma_heap.h"

#define STEP (ME_R(1.0) / 60)
#define SLEEP_LIMIT_S 25.0
#define SPEED_BOUND 0.3
#define SPIN_BOUND 0.3

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
    const int maxAwake = argc > 4 ? atoi(argv[4]) : -1;
    if (n < 1 || last < first) {
        fprintf(stderr, "usage: heap_sleep [firstSeed [lastSeed [boxes [maxAwake]]]]\n");
        return 2;
    }
    MdtBodyID *body = malloc(sizeof(MdtBodyID) * (size_t)n);
    int heaps = 0, broken = 0, awake = 0, fastSleeps = 0;
    double sumTime = 0, maxSpeed = 0, maxSpin = 0;
    for (unsigned long long seed = first; seed <= last; seed++) {
        MstUniverseID u = karma_heap_build(n, seed, body);
        if (!u)
            return 1;
        const Outcome o = settle(u, n, body);
        const int bad = o.time < 0 || o.speed >= SPEED_BOUND || o.spin >= SPIN_BOUND;
        printf("seed %llu boxes %d: asleep %.2f s, at sleep %.3f m/s %.3f rad/s, %d bodies over a bound%s\n", seed, n,
               o.time, o.speed, o.spin, o.fastSleeps, bad ? "  BROKEN" : "");
        heaps++;
        broken += bad;
        awake += o.time < 0;
        fastSleeps += o.fastSleeps;
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
    if (maxAwake >= 0 && (fastSleeps > 0 || awake > maxAwake)) {
        printf("FAILED: %d bodies put to sleep over a bound (none allowed), %d heaps awake at %.0f s (at most %d)\n",
               fastSleeps, awake, SLEEP_LIMIT_S, maxAwake);
        return 1;
    }
    return 0;
}
