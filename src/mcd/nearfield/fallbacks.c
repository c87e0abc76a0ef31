/* fallbacks.c -- counting the pair tests that fell back (McdNfCountFallback), so that each framework
 * gets exactly its own tests' fallbacks, whatever threads test pairs at once (internal). */
#include <stdatomic.h>
#ifndef __STDC_NO_THREADS__
#include <threads.h>
#endif

#include "nearfield.h"

/* A fallback is counted in a tally of the thread that counted it, and the dispatcher takes its own
 * thread's tally for its framework after each test: the tally holds the testing thread's own
 * fallbacks only, so the count a framework gets is exact however many threads test pairs at once.
 * A process-wide number of tallies not yet taken lets the common path (no fallback anywhere) skip
 * the table with one load; the dispatcher also drops its thread's tally before a test, which holds
 * fallbacks of pair tests run outside any framework (McdNfCollide, internal calls). No thread-local
 * storage (the core would need the dynamic loader's TLS support): a small table keyed by the C11
 * thread, under a spin lock, touched only while some thread has a fallback not yet taken. */
#ifdef __STDC_NO_THREADS__
typedef int Thread; /* without C11 threads: one tally (exact while one thread tests pairs at a time) */
static Thread currentThread(void) { return 0; }
static int sameThread(Thread a, Thread b) { return a == b; }
#else
typedef thrd_t Thread;
static Thread currentThread(void) { return thrd_current(); }
static int sameThread(Thread a, Thread b) { return thrd_equal(a, b); }
#endif

/* Threads that may hold fallbacks not yet taken at once; beyond them (never seen) the fallbacks go
 * to one shared tally that the next taker takes. */
#define TALLY_THREADS 64

typedef struct Tally {
    Thread thread;
    unsigned long count; /* 0: the entry is free */
} Tally;

static Tally tallies[TALLY_THREADS];
static unsigned long unowned;
static atomic_int pending; /* tallies (and unowned) not zero: changed under the lock */
static atomic_ulong total;  /* every fallback counted, all threads */
static atomic_flag tallyLock = ATOMIC_FLAG_INIT;

static void lockTallies(void)
{
    while (atomic_flag_test_and_set_explicit(&tallyLock, memory_order_acquire))
        ;
}

static void unlockTallies(void) { atomic_flag_clear_explicit(&tallyLock, memory_order_release); }

/* The tally of `self`, or (claim) a free entry made its own; NULL when there is none. Under the lock. */
static Tally *tallyOf(Thread self, MeBool claim)
{
    Tally *unused = NULL;
    for (int i = 0; i < TALLY_THREADS; i++) {
        if (tallies[i].count && sameThread(tallies[i].thread, self))
            return &tallies[i];
        if (!tallies[i].count && !unused)
            unused = &tallies[i];
    }
    if (!claim || !unused)
        return NULL;
    unused->thread = self;
    return unused;
}

void McdNfCountFallback(void)
{
    lockTallies();
    Tally *t = tallyOf(currentThread(), METRUE);
    unsigned long *count = t ? &t->count : &unowned;
    if ((*count)++ == 0)
        atomic_fetch_add(&pending, 1);
    unlockTallies();
    atomic_fetch_add(&total, 1);
}

unsigned long McdNfFallbackCount(void) { return atomic_load(&total); }

unsigned long McdNfTakeFallbacks(void)
{
    if (!atomic_load_explicit(&pending, memory_order_relaxed)) /* no thread has any: nothing to look up */
        return 0;
    lockTallies();
    Tally *t = tallyOf(currentThread(), MEFALSE);
    const unsigned long mine = t ? t->count : 0, n = mine + unowned;
    atomic_fetch_sub(&pending, (mine != 0) + (unowned != 0));
    unowned = 0;
    if (t)
        t->count = 0;
    unlockTallies();
    return n;
}
