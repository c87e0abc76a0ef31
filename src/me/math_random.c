/* math_random.c -- MeRealRandomInRange: the library's own deterministic pseudo-random generator.
 *
 * Karma's version called rand(); the C library's generator differs between platforms and is shared
 * with the application, so scenes built from "random" numbers would not be reproducible. This is a
 * 64-bit xorshift* generator (Marsaglia 2003; Vigna 2016) with global state, seeded through
 * splitmix64 so that neighbouring seeds give unrelated sequences. The state is atomic, advanced by
 * compare-and-swap: threads drawing at once each get a distinct number of the one sequence (which
 * thread gets which depends on timing; a reproducible scene draws from one thread). */
#include <stdatomic.h>

#include <karma/MeMath.h>

static _Atomic uint64_t randomState = 0x9E3779B97F4A7C15ull; /* = seed 0 mixed, see MeRealRandomSeed */

/* splitmix64 finaliser: spreads any seed (including 0) into a non-zero xorshift state. */
static uint64_t MixSeed(uint64_t z)
{
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z = z ^ (z >> 31);
    return z ? z : 0x9E3779B97F4A7C15ull;
}

static uint64_t NextRandom(void)
{
    uint64_t old = atomic_load_explicit(&randomState, memory_order_relaxed), next;
    do {
        next = old;
        next ^= next >> 12;
        next ^= next << 25;
        next ^= next >> 27;
    } while (!atomic_compare_exchange_weak_explicit(&randomState, &old, next, memory_order_relaxed,
                                                    memory_order_relaxed));
    return next * 0x2545F4914F6CDD1Dull;
}

void MeRealRandomSeed(MeU32 seed)
{
    atomic_store_explicit(&randomState, MixSeed((uint64_t)seed), memory_order_relaxed);
}

MeReal MeRealRandomInRange(MeReal start, MeReal end)
{
    /* Take as many top bits as the mantissa holds, so the unit value is exact and < 1. */
#if KARMA_DOUBLE
    MeReal unit = (MeReal)(NextRandom() >> 11) * ME_R(1.1102230246251565e-16); /* 2^-53 */
#else
    MeReal unit = (MeReal)(NextRandom() >> 40) * ME_R(5.9604644775390625e-08); /* 2^-24 */
#endif
    return start + (end - start) * unit;
}
