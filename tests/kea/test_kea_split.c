/* test_kea_split.c -- one large partition solved over several workers (KeaParameters.splitRows,
 * KeaTaskHook; src/mdt/kea/kea_split.c): the same bits for any number of workers and any order or
 * assignment of a colour's chunks (task hooks that reverse, shuffle, or run them on real threads),
 * against the solve with no hook; a different sweep order from the unsplit solve, but the same LCP
 * solution at convergence; the unsplit sweep where a friction link leaves its block; and the
 * workspace it needs. */
#include <pthread.h>
#include <stdatomic.h>

#include "karma_test.h"

#include "kea_test_problems.h"

#include "mdt/kea/kea_colour.h"
#include "mdt/kea/kea_contact_packs.h"
#include "mdt/kea/kea_internal.h"

/* A partition like a pile's: contacts between random bodies and the world, every 30th on body 0 (so
 * that it has a contact in every colour and the overflow colour is used), and joint rows in blocks of
 * two, every third block with its half 0 on the world. */
static void make_pile(KtProblem *t, uint64_t seed, int nContacts, int nb)
{
    KtRng rng = kt_rng(seed);
    const int nJoint = 40, first = 3 * nContacts;
    int i, k;
    kt_random_contacts(t, &rng, nContacts, nJoint, nb, 0.5, 1e-2);
    for (i = 0; i < nContacts; i += 30)
        for (k = 0; k < 3; ++k) {
            t->rowBodies[3 * i + k][0] = 0;
            if (t->rowBodies[3 * i + k][1] == 0) {
                t->rowBodies[3 * i + k][1] = KEA_WORLD;
                memset(t->J[3 * i + k].lin1, 0, sizeof t->J[3 * i + k].lin1);
                memset(t->J[3 * i + k].ang1, 0, sizeof t->J[3 * i + k].ang1);
            }
        }
    for (i = first; i + 1 < first + nJoint; i += 2) {
        if ((i - first) % 6 == 0) {
            t->rowBodies[i][0] = KEA_WORLD;
            t->rowBodies[i][1] = kt_int(&rng, nb);
            for (k = 0; k < 3; ++k) {
                t->J[i].lin1[k] = (MeReal)kt_range(&rng, -1, 1);
                t->J[i].ang1[k] = (MeReal)kt_range(&rng, -1, 1);
            }
        }
        t->rowBodies[i + 1][0] = t->rowBodies[i][0];
        t->rowBodies[i + 1][1] = t->rowBodies[i][1];
        for (k = 0; k < 3; ++k) {
            t->J[i + 1].lin1[k] = t->rowBodies[i][1] >= 0 ? (MeReal)kt_range(&rng, -1, 1) : ME_R(0.0);
            t->J[i + 1].ang1[k] = t->rowBodies[i][1] >= 0 ? (MeReal)kt_range(&rng, -1, 1) : ME_R(0.0);
        }
    }
}

/* ---- task hooks ----------------------------------------------------------------------------- */

typedef enum Schedule { InOrder, Reversed, Shuffled, Threads, Nothing } Schedule;

typedef struct Hook {
    Schedule schedule;
    int workers;
    int perStage;    /* KeaTaskHook.perStage */
    KtRng rng;
    int calls;       /* run calls with more than one item */
    int workerSeen[KEA_MAX_WORKERS];
} Hook;

/* Items one at a time, in order, reversed or shuffled, each on a worker chosen by the schedule. */
static void runSerial(Hook *h, KeaTaskFn task, int items, void *data)
{
    int order[4096], i;
    assert_true(items <= 4096);
    for (i = 0; i < items; ++i)
        order[i] = h->schedule == Reversed ? items - 1 - i : i;
    if (h->schedule == Shuffled)
        for (i = items - 1; i > 0; --i) {
            const int j = kt_int(&h->rng, i + 1), swap = order[i];
            order[i] = order[j];
            order[j] = swap;
        }
    for (i = 0; i < items; ++i) {
        const int worker = h->schedule == Shuffled ? kt_int(&h->rng, h->workers) : order[i] % h->workers;
        h->workerSeen[worker] = 1;
        task(order[i], order[i] + 1, worker, data);
    }
}

/* Real threads: workers - 1 started per call and the caller, each taking items from a shared cursor. */
typedef struct ThreadRun {
    KeaTaskFn task;
    void *data;
    int items;
    atomic_int next;
} ThreadRun;

typedef struct ThreadArg {
    ThreadRun *run;
    int worker;
} ThreadArg;

static void *threadMain(void *p)
{
    const ThreadArg *arg = p;
    int item;
    while ((item = atomic_fetch_add(&arg->run->next, 1)) < arg->run->items)
        arg->run->task(item, item + 1, arg->worker, arg->run->data);
    return NULL;
}

static void runThreads(Hook *h, KeaTaskFn task, int items, void *data)
{
    pthread_t threads[KEA_MAX_WORKERS];
    ThreadArg args[KEA_MAX_WORKERS];
    ThreadRun run;
    int k;
    run.task = task;
    run.data = data;
    run.items = items;
    atomic_init(&run.next, 0);
    for (k = 0; k < h->workers; ++k) {
        args[k].run = &run;
        args[k].worker = k;
        h->workerSeen[k] = 1;
    }
    for (k = 1; k < h->workers; ++k)
        assert_int_equal(pthread_create(&threads[k], NULL, threadMain, &args[k]), 0);
    threadMain(&args[0]);
    for (k = 1; k < h->workers; ++k)
        pthread_join(threads[k], NULL);
}

static void runHook(KeaTaskFn task, int items, int minRange, void *data, void *user)
{
    Hook *h = user;
    assert_true(minRange >= 1);
    h->calls++;
    if (h->schedule == Nothing) /* a task system that ran none of the team's items */
        return;
    if (h->schedule == Threads)
        runThreads(h, task, items, data);
    else
        runSerial(h, task, items, data);
}

/* ---- solving -------------------------------------------------------------------------------- */

typedef struct Result {
    MeReal x[8192];
    KeaBodyVelocity dv[1024];
    KeaStats stats;
} Result;

/* KeaSolve with a workspace of exactly what it asks for, the split's included. */
static KeaStatus solve(const KtProblem *t, const KeaParameters *params, Result *out)
{
    const size_t bytes = KeaMemoryRequired(t->p.nRows, t->p.nBodies, KeaSelectPath(t->p.nRows, params)) +
                         KeaSplitMemoryRequired(t->p.nRows, t->p.nBodies, params);
    void *work = malloc(bytes);
    KeaStatus status;
    assert_true(t->p.nRows <= 8192 && t->p.nBodies <= 1024);
    memset(out, 0, sizeof *out);
    status = KeaSolve(&t->p, params, work, bytes, out->x, out->dv, &out->stats);
    free(work);
    return status;
}

/* A hook of that schedule, worker count and chunking (KeaTaskHook.perStage), its shuffle seeded. */
static Hook hook_of(Schedule schedule, int workers, int perStage, uint64_t seed)
{
    Hook hook;
    memset(&hook, 0, sizeof hook);
    hook.schedule = schedule;
    hook.workers = workers;
    hook.perStage = perStage;
    hook.rng = kt_rng(seed);
    return hook;
}

static KeaParameters split_params(Hook *hook)
{
    KeaParameters p = kt_params(KeaPathIterative);
    p.splitRows = 1;
    if (hook) {
        p.tasks.run = runHook;
        p.tasks.user = hook;
        p.tasks.workers = hook->workers;
        p.tasks.perStage = hook->perStage;
    }
    return p;
}

static void assert_same_bits(const KtProblem *t, const Result *a, const Result *b)
{
    assert_memory_equal(a->x, b->x, sizeof(MeReal) * (size_t)t->p.nRows);
    assert_memory_equal(a->dv, b->dv, sizeof(KeaBodyVelocity) * (size_t)t->p.nBodies);
    assert_int_equal(a->stats.iterations, b->stats.iterations);
    assert_int_equal(a->stats.subspaceSteps, b->stats.subspaceSteps);
    assert_int_equal(a->stats.subspaceSkipped, b->stats.subspaceSkipped);
    assert_int_equal(a->stats.pivots, b->stats.pivots);
    assert_int_equal(a->stats.colours, b->stats.colours);
    assert_memory_equal(&a->stats.residual, &b->stats.residual, sizeof(MeReal));
}

static int differ(const MeReal *a, const MeReal *b, int n) { return memcmp(a, b, sizeof(MeReal) * (size_t)n) != 0; }

/* Every schedule, worker count and assignment of chunks to workers gives the serial split solve's
 * bits: impulses, velocity changes, sweeps, SM steps, pivots and residual. Per stage (a run call per
 * colour and SM loop) the schedules reverse, shuffle and reassign a stage's chunks; as a team (one
 * run call a solve, kea_split.c), run in order the first item does everything, on real threads the
 * helpers take whichever chunks they reach first, and a task system that runs no item leaves the
 * solve to the caller. */
static void any_schedule_gives_the_same_bits(void **state)
{
    static Result reference, other;
    const Schedule schedules[] = {InOrder, Reversed, Shuffled, Shuffled, Threads, Threads, InOrder, Threads, Threads,
                                  Nothing};
    const int workers[] = {3, 4, 5, 2, 4, 2, 3, 4, 2, 3};
    const int perStage[] = {1, 1, 1, 1, 1, 1, 0, 0, 0, 0};
    int seed, s, overflowSeen = 0;
    (void)state;
    for (seed = 0; seed < 4; ++seed) {
        KtProblem t;
        KeaParameters inline_ = split_params(NULL);
        make_pile(&t, 31000 + (uint64_t)seed, 1500 + 300 * seed, 300 + 50 * seed);
        assert_int_not_equal(solve(&t, &inline_, &reference), KeaStatusBadInput);
        assert_true(reference.stats.colours > 2);
        assert_true(reference.stats.subspaceSteps > 0); /* SM ran: its packs' chunks (1500+ contacts: 12+) too */
        overflowSeen |= reference.stats.colours > KEA_COLOUR_COUNT;
        for (s = 0; s < (int)(sizeof schedules / sizeof schedules[0]); ++s) {
            Hook hook = hook_of(schedules[s], workers[s], perStage[s], 77 + (uint64_t)s);
            KeaParameters params;
            params = split_params(&hook);
            solve(&t, &params, &other);
            if (perStage[s]) {
                assert_true(hook.calls > reference.stats.iterations); /* several chunks of a colour went out */
                assert_true(hook.workerSeen[1]);                      /* to a worker other than 0 */
            } else {
                assert_int_equal(hook.calls, 2); /* one task for the rows' check, one for the solve */
            }
            assert_same_bits(&t, &reference, &other);
        }
        kt_free(&t);
    }
    assert_true(overflowSeen); /* some problem used the overflow colour */
}

/* The coarse correction (KeaParameters.deflation, kea_deflation.c) runs on the solve's own thread:
 * a split solve with it gives the serial split solve's bits on any schedule and worker count. */
static void deflation_gives_the_same_bits_on_any_schedule(void **state)
{
    static Result reference, other;
    const Schedule schedules[] = {InOrder, Shuffled, Threads, Threads};
    const int workers[] = {2, 4, 4, 2};
    const int perStage[] = {1, 1, 1, 0};
    KtProblem t;
    KeaParameters params = split_params(NULL);
    int s;
    (void)state;
    make_pile(&t, 31007, 1500, 300);
    params.deflation = 1;
    assert_int_not_equal(solve(&t, &params, &reference), KeaStatusBadInput);
    for (s = 0; s < 4; ++s) {
        Hook hook = hook_of(schedules[s], workers[s], perStage[s], 91 + (uint64_t)s);
        params = split_params(&hook);
        params.deflation = 1;
        solve(&t, &params, &other);
        assert_same_bits(&t, &reference, &other);
    }
    kt_free(&t);
}

/* The split sweep goes colour by colour, so its result after the default 10 sweeps differs from the
 * unsplit sweep's (the check above could not fail if the colours were not used); run to convergence
 * both reach the partition's one solution (eps > 0: a strictly convex QP). */
static void split_changes_the_order_not_the_solution(void **state)
{
    static Result split, plain;
    KtProblem t;
    KeaParameters params = split_params(NULL), unsplit = kt_params(KeaPathIterative);
    int i;
    double worst = 0.0, scale = 0.0;
    (void)state;
    make_pile(&t, 32000, 200, 60);
    solve(&t, &params, &split);
    solve(&t, &unsplit, &plain);
    assert_int_equal(plain.stats.colours, 0);
    assert_true(differ(split.x, plain.x, t.p.nRows));
    params.maxIterations = unsplit.maxIterations = 3000;
    params.tolerance = unsplit.tolerance = ME_R(0.0);
    solve(&t, &params, &split);
    solve(&t, &unsplit, &plain);
    assert_near(split.stats.residual, 0.0, ME_TOL(1e-7, 2e-3));
    assert_near(plain.stats.residual, 0.0, ME_TOL(1e-7, 2e-3));
    for (i = 0; i < t.p.nRows; ++i) {
        worst = fmax(worst, fabs((double)split.x[i] - (double)plain.x[i]));
        scale = fmax(scale, fabs((double)plain.x[i]));
    }
    print_message("split vs unsplit at convergence: largest impulse difference %.3g of %.3g\n", worst, scale);
    assert_near(worst / scale, 0.0, ME_TOL(1e-7, 2e-3));
    kt_free(&t);
}

/* Scalar PGS (maxBlockRows 1) makes each friction row a block of its own, linked to its normal row's
 * block: the sweeps are not split (a row's bounds would read another block of its colour) and the
 * solve is the unsplit one, bit for bit (its set-up's loops, split or not, give the same bits). */
static void links_across_blocks_keep_the_plain_sweep(void **state)
{
    static Result split, plain;
    KtProblem t;
    Hook hook;
    KeaParameters params, unsplit = kt_params(KeaPathIterative);
    (void)state;
    memset(&hook, 0, sizeof hook);
    hook.schedule = Reversed;
    hook.workers = 3;
    hook.perStage = 1;
    params = split_params(&hook);
    params.maxBlockRows = unsplit.maxBlockRows = 1;
    make_pile(&t, 33000, 100, 30);
    solve(&t, &params, &split);
    solve(&t, &unsplit, &plain);
    assert_int_equal(split.stats.colours, 0);
    assert_true(hook.calls <= 4); /* the rows' check, the set-up's row and block loops, the warm start beside
                                   * the colouring that gave up */
    assert_same_bits(&t, &split, &plain);
    kt_free(&t);
}

/* The split's workspace: none unless it applies; without it KeaSolve refuses (nothing solved). */
static void split_workspace(void **state)
{
    static Result r;
    KtProblem t;
    Hook hook;
    KeaParameters params, none = kt_params(KeaPathIterative);
    size_t bytes;
    void *work;
    (void)state;
    memset(&hook, 0, sizeof hook);
    hook.workers = 4;
    params = split_params(&hook);
    make_pile(&t, 34000, 100, 30);
    assert_int_equal(KeaSplitMemoryRequired(t.p.nRows, t.p.nBodies, &none), 0);
    assert_false(KeaSplits(t.p.nRows, &none));
    assert_true(KeaSplits(t.p.nRows, &params));
    assert_true(KeaSplitMemoryRequired(t.p.nRows, t.p.nBodies, &params) > 0);
    /* more workers, more scratch */
    params.tasks.workers = 1;
    bytes = KeaSplitMemoryRequired(t.p.nRows, t.p.nBodies, &params);
    params.tasks.workers = 4;
    assert_true(KeaSplitMemoryRequired(t.p.nRows, t.p.nBodies, &params) > bytes);
    params.splitRows = t.p.nRows + 1; /* too few rows */
    assert_int_equal(KeaSplitMemoryRequired(t.p.nRows, t.p.nBodies, &params), 0);
    params.splitRows = 1;
    params.path = KeaPathDirect; /* the direct path is never split */
    assert_int_equal(KeaSplitMemoryRequired(t.p.nRows, t.p.nBodies, &params), 0);
    params.path = KeaPathIterative;
    bytes = KeaMemoryRequired(t.p.nRows, t.p.nBodies, KeaPathIterative);
    work = malloc(bytes);
    assert_int_equal(KeaSolve(&t.p, &params, work, bytes, r.x, r.dv, &r.stats), KeaStatusWorkspaceTooSmall);
    free(work);
    kt_free(&t);
}

/* SM's pack scatter in a split solve (KeaSplitPacks, KeaPacksScatterSplit): packs on random bodies,
 * many on the world (nb: a box on the ground, an empty lane), one body in more packs than colours.
 * Every pack is in one colour and one chunk of it (at most KEA_SPLIT_PACKS packs); a colour's packs
 * share no body but the world; scattering colour by colour gives the same bits whether each colour's
 * chunks and packs run forwards or backwards (what lets a colour's chunks go to any worker), and
 * the world's velocity change is never written (several packs of a colour may hold it). */
static void packs_scatter_colour_by_colour_in_any_order(void **state)
{
    enum { NP = 150, NB = 120 };
    static KeaContactPack packs[NP];
    static _Alignas(16) MeReal v[KEA_PACK_POSITIONS * NP];
    static KeaVel4 forward[NB + 1], backward[NB + 1];
    static int packBodies[2 * KEA_PACK_LANES * NP], packColour[NP], packOrder[NP], packChunk[NP / KEA_SPLIT_PACKS + 32];
    static uint64_t colourWork[NB * KEA_COLOUR_COUNT];
    KtRng rng = kt_rng(4242);
    KeaIterativeWork w;
    KeaSplit split;
    int k, h, l, c, j, r, seen[NP] = {0}, overflow;
    (void)state;
    memset(packs, 0, sizeof packs);
    for (k = 0; k < NP; ++k) {
        KeaContactPack *p = &packs[k];
        const int pair = k % 3 == 0;
        p->lanes = k == NP - 1 ? 2 : KEA_PACK_LANES;
        for (l = 0; l < KEA_PACK_LANES; ++l) {
            const int used = l < p->lanes;
            p->body[0][l] = !used ? NB : (pair && l > 0 ? p->body[0][0] : (k < 40 && l == 0 ? 5 : kt_int(&rng, NB)));
            p->body[1][l] = !used ? NB : (pair && l > 0 ? p->body[1][0] : (kt_int(&rng, 3) == 0 ? NB : kt_int(&rng, NB)));
        }
        p->pair = pair;
        for (r = 0; r < 3; ++r)
            for (h = 0; h < 12; ++h)
                for (l = 0; l < KEA_PACK_LANES; ++l)
                    p->B[r][h][l] = (MeReal)kt_range(&rng, -1, 1);
    }
    for (j = 0; j < KEA_PACK_POSITIONS * NP; ++j)
        v[j] = (MeReal)kt_range(&rng, -1, 1);
    memset(&w, 0, sizeof w);
    memset(&split, 0, sizeof split);
    w.packs = packs;
    w.nPacks = NP;
    w.nb = NB;
    split.packBodies = packBodies;
    split.packColour = packColour;
    split.packOrder = packOrder;
    split.packChunk = packChunk;
    split.colourWork = colourWork;
    split.colourBytes = KeaColourMemoryRequired(NB);
    assert_true(split.colourBytes <= sizeof colourWork);
    KeaSplitPacks(&w, &split);
    assert_int_equal(split.packColourChunk[0], 0);
    assert_int_equal(split.packChunk[split.packColourChunk[KEA_COLOUR_COUNT + 1]], NP);
    overflow = 0;
    for (c = 0; c <= KEA_COLOUR_COUNT; ++c) {
        int held[NB] = {0};
        for (k = split.packColourChunk[c]; k < split.packColourChunk[c + 1]; ++k) {
            assert_true(split.packChunk[k] < split.packChunk[k + 1]);
            assert_true(split.packChunk[k + 1] - split.packChunk[k] <= KEA_SPLIT_PACKS);
            for (j = split.packChunk[k]; j < split.packChunk[k + 1]; ++j) {
                const int p = split.packOrder[j];
                int mine[NB + 1] = {0};
                assert_int_equal(split.packColour[p], c);
                seen[p]++;
                if (c == KEA_COLOUR_OVERFLOW) {
                    ++overflow;
                    continue;
                }
                for (h = 0; h < 2; ++h)
                    for (l = 0; l < KEA_PACK_LANES; ++l) {
                        const int b = packs[p].body[h][l];
                        if (b == NB || mine[b]++)
                            continue;
                        assert_int_equal(held[b], 0); /* no other pack of the colour holds it */
                        held[b] = 1;
                    }
            }
        }
    }
    for (k = 0; k < NP; ++k)
        assert_int_equal(seen[k], 1);
    assert_true(overflow >= 40 - KEA_COLOUR_COUNT); /* body 5's packs beyond the colours */
    /* forwards and backwards within each colour (the overflow colour, on one worker, forwards) */
    memset(forward, 0, sizeof forward);
    for (j = 0; j < 4; ++j) /* the world's entry as a sentinel: never written */
        forward[NB].lin[j] = forward[NB].ang[j] = ME_R(7.0);
    memcpy(backward, forward, sizeof forward);
    for (c = 0; c <= KEA_COLOUR_COUNT; ++c) {
        const int first = split.packChunk[split.packColourChunk[c]], last = split.packChunk[split.packColourChunk[c + 1]];
        KeaPacksScatterSplit(&w, v, forward, split.packOrder, first, last);
        if (c == KEA_COLOUR_OVERFLOW) {
            KeaPacksScatterSplit(&w, v, backward, split.packOrder, first, last);
            continue;
        }
        for (j = last - 1; j >= first; --j)
            KeaPacksScatterSplit(&w, v, backward, split.packOrder, j, j + 1);
    }
    assert_memory_equal(forward, backward, sizeof forward);
    for (j = 0; j < 4; ++j) {
        assert_true(forward[NB].lin[j] == ME_R(7.0));
        assert_true(forward[NB].ang[j] == ME_R(7.0));
    }
    for (k = 0, j = 0; k < NB; ++k)
        j += forward[k].lin[0] != ME_R(0.0);
    assert_true(j > NB / 2); /* the scatter wrote the bodies */
}

/* dv = M^-1 J^T x by ranges of bodies (the split set-up's ranges, one a worker): any cut into ranges
 * gives the whole pass's bits, each body summing its rows in row order, and a range writes only its
 * own bodies. */
static void body_ranges_give_the_whole_pass_bits(void **state)
{
    KtProblem t;
    KtRng rng = kt_rng(4242);
    KeaBodyVelocity *whole, *cut;
    MeReal *x;
    int i, k, nb;
    (void)state;
    make_pile(&t, 36000, 400, 90);
    nb = t.p.nBodies;
    whole = malloc(sizeof *whole * (size_t)nb);
    cut = malloc(sizeof *cut * (size_t)nb);
    x = malloc(sizeof *x * (size_t)t.p.nRows);
    assert_non_null(whole);
    assert_non_null(cut);
    assert_non_null(x);
    for (i = 0; i < t.p.nRows; ++i) /* a fifth of the impulses zero, as at rest: skipped */
        x[i] = kt_int(&rng, 5) == 0 ? ME_R(0.0) : (MeReal)kt_range(&rng, -2, 2);
    KeaBodyVelocityFromImpulses(&t.p, x, whole);
    for (k = 1; k <= 6; ++k) { /* k ranges, the cuts at random bodies */
        int cuts[8], j;
        memset(cut, 0xff, sizeof *cut * (size_t)nb); /* NaN everywhere: a body no range writes shows */
        cuts[0] = 0;
        cuts[k] = nb;
        for (j = 1; j < k; ++j)
            cuts[j] = cuts[j - 1] + kt_int(&rng, nb - cuts[j - 1] + 1);
        for (j = k - 1; j >= 0; --j) /* the ranges in reverse: the order changes nothing */
            KeaBodyVelocityFromImpulsesOf(&t.p, x, cut, cuts[j], cuts[j + 1]);
        assert_memory_equal(whole, cut, sizeof *cut * (size_t)nb);
    }
    memset(cut, 0xff, sizeof *cut * (size_t)nb);
    KeaBodyVelocityFromImpulsesOf(&t.p, x, cut, 10, 20); /* one range: its bodies only */
    for (i = 0; i < nb; ++i) {
        const int inside = i >= 10 && i < 20;
        assert_int_equal(memcmp(&cut[i], &whole[i], sizeof *cut) == 0, inside);
    }
    free(whole);
    free(cut);
    free(x);
    kt_free(&t);
}

/* A partition that will be split checks its rows in chunks on the workers: a bad row anywhere (here
 * in the last chunk, a NaN rhs, or an index out of range in the first) is refused on every
 * schedule, a task system that runs none of the chunks included (the rows are then checked on the
 * caller), and nothing is solved. */
static void bad_rows_are_refused_on_the_workers(void **state)
{
    static Result out;
    const Schedule schedules[] = {InOrder, Reversed, Shuffled, Threads, Nothing};
    const int perStage[] = {1, 1, 0, 0, 0};
    KtProblem t;
    int s, bad;
    (void)state;
    make_pile(&t, 37000, 1500, 300);
    assert_true(t.p.nRows > 2 * KEA_SPLIT_ROWS);
    for (bad = 0; bad < 2; ++bad) {
        const int row = bad == 0 ? t.p.nRows - 2 : 5;
        const MeReal rhs = t.rhs[row];
        const int body = t.rowBodies[row][1];
        if (bad == 0)
            t.rhs[row] = (MeReal)NAN;
        else
            t.rowBodies[row][1] = t.p.nBodies;
        for (s = 0; s < (int)(sizeof schedules / sizeof schedules[0]); ++s) {
            Hook hook = hook_of(schedules[s], 3, perStage[s], 91 + (uint64_t)s);
            KeaParameters params;
            params = split_params(&hook);
            assert_int_equal(solve(&t, &params, &out), KeaStatusBadInput);
            assert_int_equal(hook.calls, 1); /* the check went out; no solve did */
        }
        t.rhs[row] = rhs;
        t.rowBodies[row][1] = body;
    }
    kt_free(&t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(any_schedule_gives_the_same_bits),
        cmocka_unit_test(deflation_gives_the_same_bits_on_any_schedule),
        cmocka_unit_test(split_changes_the_order_not_the_solution),
        cmocka_unit_test(links_across_blocks_keep_the_plain_sweep),
        cmocka_unit_test(split_workspace),
        cmocka_unit_test(packs_scatter_colour_by_colour_in_any_order),
        cmocka_unit_test(body_ranges_give_the_whole_pass_bits),
        cmocka_unit_test(bad_rows_are_refused_on_the_workers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
