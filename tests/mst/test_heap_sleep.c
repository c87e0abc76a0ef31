/* Settled heaps sleep, and wake without a jump (issue 17 point 6).
 *
 * 120 boxes of sizes jittered by 10 % dropped at random orientations onto the ground form one heap, a
 * single partition. The iterative solver leaves its bodies some velocity noise (far less since
 * decision K49: bench/RESULTS.md, "Settled heaps"), which judged by the last step alone (Karma 1.2's
 * test, MdtWorldSetAutoDisableAveragingTime(w, 0)) can keep a heap awake. Averaged over the default
 * time it sleeps within a stated time, no body put to sleep while visibly moving (twenty heaps:
 * tests/cmake/heap_sleep.cmake). Tapped
 * once asleep, the heap wakes and carries on without a jump: at the wake step and after, no body's
 * velocity changes more than the tap and one step of gravity explain. */
#include "karma_test.h"

#include <math.h>

#include <karma/karma.h>

#include "karma_heap.h"

#define HEAP 120
#define STEP (ME_R(1.0) / 60)
#define SLEEP_LIMIT_S 25.0 /* the stated time: the heap is asleep 25 s after the drop */
#define GRAVITY ME_R(9.81)

typedef struct Heap {
    MstUniverseID u;
    MdtWorldID w;
    MdtBodyID body[HEAP];
} Heap;

/* The heap of tests/support/karma_heap.c from seed 17 (tools/heap_sleep builds it from other seeds:
 * the heap is chaotic, and this one is one draw of many). */
static void buildHeap(Heap *h, MeReal averagingTime)
{
    h->u = karma_heap_build(HEAP, 17, h->body);
    assert_non_null(h->u);
    h->w = MstUniverseGetWorld(h->u);
    for (int i = 0; i < HEAP; i++)
        assert_non_null(h->body[i]);
    assert_true(MdtWorldGetAutoDisable(h->w));
    assert_true(MdtWorldGetAutoDisableAveragingTime(h->w) == MDTWORLD_DEFAULT_AVERAGING_TIME);
    MdtWorldSetAutoDisableAveragingTime(h->w, averagingTime);
}

static MeReal speed(MdtBodyID b)
{
    MeVector3 v;
    MdtBodyGetLinearVelocity(b, v);
    return MeVector3Magnitude(v);
}

static MeReal angularSpeed(MdtBodyID b)
{
    MeVector3 v;
    MdtBodyGetAngularVelocity(b, v);
    return MeVector3Magnitude(v);
}

/* Steps until every body is asleep or `limit` seconds pass; returns the time taken (or -1). The
 * largest speed and angular speed a body had at the end of the step before it was put to sleep go
 * to *sleepSpeed and *sleepSpin. */
static double stepUntilAsleep(Heap *h, double limit, MeReal *sleepSpeed, MeReal *sleepSpin)
{
    MeReal lastSpeed[HEAP], lastSpin[HEAP];
    *sleepSpeed = *sleepSpin = 0;
    for (int step = 1; step <= (int)(limit * 60 + 0.5); step++) {
        for (int i = 0; i < HEAP; i++) {
            lastSpeed[i] = speed(h->body[i]);
            lastSpin[i] = angularSpeed(h->body[i]);
        }
        MeBool wasEnabled[HEAP];
        for (int i = 0; i < HEAP; i++)
            wasEnabled[i] = MdtBodyIsEnabled(h->body[i]);
        MstUniverseStep(h->u, STEP);
        for (int i = 0; i < HEAP; i++)
            if (wasEnabled[i] && !MdtBodyIsEnabled(h->body[i])) {
                *sleepSpeed = lastSpeed[i] > *sleepSpeed ? lastSpeed[i] : *sleepSpeed;
                *sleepSpin = lastSpin[i] > *sleepSpin ? lastSpin[i] : *sleepSpin;
            }
        if (MdtWorldGetEnabledBodies(h->w) == 0)
            return step / 60.0;
    }
    return -1;
}

/* Averaged over the default time, the settled heap sleeps within SLEEP_LIMIT_S, and no body was put to
 * sleep moving faster than 0.3 m/s or 0.3 rad/s at that step (the solver's jitter in a heap reaches
 * about 0.2; a body falling or tumbling for real would be well over). */
static void heap_sleeps_within_the_stated_time(void **state)
{
    (void)state;
    Heap h;
    buildHeap(&h, MDTWORLD_DEFAULT_AVERAGING_TIME);
    MeReal sleepSpeed, sleepSpin;
    const double t = stepUntilAsleep(&h, SLEEP_LIMIT_S, &sleepSpeed, &sleepSpin);
    int onGround = 0;
    for (int i = 0; i < HEAP; i++) {
        MeVector3 x;
        MdtBodyGetPosition(h.body[i], x);
        onGround += x[2] < ME_R(1.0);
    }
    printf("heap of %d boxes asleep after %.2f s (limit %.0f s); at sleep the fastest body moved at %.3f m/s, "
           "%.3f rad/s; %d bodies in the bottom metre\n",
           HEAP, t, SLEEP_LIMIT_S, (double)sleepSpeed, (double)sleepSpin, onGround);
    assert_true(t > 0);
    assert_true(sleepSpeed < ME_R(0.3));
    assert_true(sleepSpin < ME_R(0.3));
    assert_true(onGround > HEAP / 3); /* it fell and spread into a heap (not asleep in mid-air) */
    MstUniverseDestroy(h.u);
}

/* The heap asleep, one box on top is tapped sideways (0.5 m/s). Everything it touches wakes (one
 * partition); at the wake step and the next ten (1/6 s) no body's velocity changes in one step by more
 * than the tap (0.5 m/s) plus one step of gravity (g h = 0.16 m/s), and at the wake step the woken
 * bodies other than the tapped one stay where they slept (no sag, no pop: under 1 cm). The contacts
 * of a sleeping heap keep their impulses, so the woken solve starts warm. (Later the awake heap has
 * the iterative solver's own jitter again, the noise that the averaging time lets it sleep through.) */
static void tapped_heap_wakes_without_a_jump(void **state)
{
    (void)state;
    Heap h;
    buildHeap(&h, MDTWORLD_DEFAULT_AVERAGING_TIME);
    MeReal sleepSpeed, sleepSpin;
    assert_true(stepUntilAsleep(&h, SLEEP_LIMIT_S, &sleepSpeed, &sleepSpin) > 0);
    int top = 0;
    MeVector3 rest[HEAP];
    for (int i = 0; i < HEAP; i++) {
        MdtBodyGetPosition(h.body[i], rest[i]);
        if (rest[i][2] > rest[top][2])
            top = i;
    }
    const MeReal tap = ME_R(0.5);
    MdtBodyEnable(h.body[top]);
    MdtBodySetLinearVelocity(h.body[top], tap, 0, 0);
    MeVector3 before[HEAP], beforeW[HEAP];
    for (int i = 0; i < HEAP; i++) {
        MdtBodyGetLinearVelocity(h.body[i], before[i]);
        MdtBodyGetAngularVelocity(h.body[i], beforeW[i]);
    }
    const MeReal bound = tap + GRAVITY * STEP;
    MeReal worstJump = 0, worstSpin = 0, worstDrift = 0;
    int woken = 0;
    for (int step = 0; step <= 10; step++) {
        MstUniverseStep(h.u, STEP);
        if (step == 0)
            woken = MdtWorldGetEnabledBodies(h.w);
        for (int i = 0; i < HEAP; i++) {
            MeVector3 v, w, d, x;
            MdtBodyGetLinearVelocity(h.body[i], v);
            MdtBodyGetAngularVelocity(h.body[i], w);
            MeVector3Subtract(d, v, before[i]);
            worstJump = MeVector3Magnitude(d) > worstJump ? MeVector3Magnitude(d) : worstJump;
            MeVector3Subtract(d, w, beforeW[i]);
            worstSpin = MeVector3Magnitude(d) > worstSpin ? MeVector3Magnitude(d) : worstSpin;
            MeVector3Copy(before[i], v);
            MeVector3Copy(beforeW[i], w);
            if (step == 0 && i != top && MdtBodyIsEnabled(h.body[i])) {
                MdtBodyGetPosition(h.body[i], x);
                MeVector3Subtract(d, x, rest[i]);
                worstDrift = MeVector3Magnitude(d) > worstDrift ? MeVector3Magnitude(d) : worstDrift;
            }
        }
    }
    printf("tapped the top box at %.2f m/s: %d bodies woke; the largest one-step change of any body's "
           "velocity at the wake step and the next ten %.3f m/s (bound %.3f), of angular velocity %.3f rad/s; "
           "the woken bodies moved %.4f m at the wake step\n",
           (double)tap, woken, (double)worstJump, (double)bound, (double)worstSpin, (double)worstDrift);
    assert_true(woken > 1);
    assert_true(worstJump <= bound);
    assert_true(worstDrift < ME_R(0.01));
    MstUniverseDestroy(h.u);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(heap_sleeps_within_the_stated_time),
        cmocka_unit_test(tapped_heap_wakes_without_a_jump),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
