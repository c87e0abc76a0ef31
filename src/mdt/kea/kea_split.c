/* kea_split.c -- one large partition over several workers (kea_iterative.h, "the split solve"): the
 * workspace, the colouring of the blocks (and of SM's packs), the chunks, and how items are handed
 * to the caller's workers (KeaTaskHook, kea.h). The sweep colour by colour is in kea_iterative.c,
 * SM's chunked loops in kea_subspace.c.
 *
 * Why the result does not depend on the workers: within a colour no two blocks share a body, and a
 * block step reads and writes only its own rows, its two bodies' velocity changes and the problem's
 * data, so the order in which a colour's blocks are taken changes no bit; whatever is summed over
 * several blocks or rows is summed per fixed chunk and the chunks added in their order. The world's
 * velocity change (dv[nb], all zero) is read by every block on the world and written by none. SM's
 * packs (four contacts, up to eight bodies) are coloured on their own for its scatter, the same way. */
#include <stdint.h>
#include <string.h>

#include "kea_contact_packs.h"

static KeaBlockScratch KeaScratchLayout(KeaArena *arena, int cap)
{
    KeaBlockScratch s;
    s.localW = KEA_ALLOC(arena, MeReal, cap);
    s.localR = KEA_ALLOC(arena, MeReal, cap);
    s.localLo = KEA_ALLOC(arena, MeReal, cap);
    s.localHi = KEA_ALLOC(arena, MeReal, cap);
    s.localX = KEA_ALLOC(arena, MeReal, cap);
    s.localD = KEA_ALLOC(arena, MeReal, cap);
    s.localLink = KEA_ALLOC(arena, int, cap);
    s.dense = KeaDenseWorkCreate(arena, cap);
    return s;
}

int KeaSplitWorkers(const KeaTaskHook *hook)
{
    if (!hook->run || hook->workers <= 1)
        return 1;
    return hook->workers < KEA_MAX_WORKERS ? hook->workers : KEA_MAX_WORKERS;
}

void KeaSplitLayout(KeaArena *arena, int n, int nb, int workers, KeaSplit *split)
{
    const int cap = KeaBlockCap(n, KEA_MAX_BLOCK_ROWS);
    int k;
    split->order = KEA_ALLOC(arena, int, n);
    split->colour = KEA_ALLOC(arena, int, n);
    split->pairs = (int(*)[2])KeaArenaAlloc(arena, sizeof(int[2]) * (size_t)n);
    split->unitStart = KEA_ALLOC(arena, int, n + 1);
    split->unitOrder = KEA_ALLOC(arena, int, n);
    split->colourBytes = KeaColourMemoryRequired(nb);
    split->colourWork = KeaArenaAlloc(arena, split->colourBytes);
    split->chunkStart = KEA_ALLOC(arena, int, n / KEA_SPLIT_CHUNK + KEA_COLOUR_COUNT + 2);
    split->chunks = KEA_ALLOC(arena, KeaSplitChunk, n / KEA_SPLIT_CHUNK + KEA_COLOUR_COUNT + 1);
    split->partial = KEA_ALLOC(arena, MeReal, n / KEA_SPLIT_PIECES + 1 + (n / 12 + 1) / KEA_SPLIT_PACKS + 1);
    split->blockUnit = KEA_ALLOC(arena, int, n);
    split->pieceOrder = KEA_ALLOC(arena, int, n);
    split->pieceChunk = KEA_ALLOC(arena, int, n / KEA_SPLIT_PIECES + KEA_COLOUR_COUNT + 2);
    split->packBodies = KEA_ALLOC(arena, int, 2 * KEA_PACK_LANES * (n / 12 + 1)); /* the packs: kea_blocks.c */
    split->packColour = KEA_ALLOC(arena, int, n / 12 + 1);
    split->packOrder = KEA_ALLOC(arena, int, n / 12 + 1);
    split->packChunk = KEA_ALLOC(arena, int, (n / 12 + 1) / KEA_SPLIT_PACKS + KEA_COLOUR_COUNT + 2);
    split->scratch = KEA_ALLOC(arena, KeaBlockScratch, workers);
    split->works = KEA_ALLOC(arena, KeaIterativeWork, workers);
    for (k = 1; k < workers; ++k) { /* worker 0 uses the work's own */
        const KeaBlockScratch s = KeaScratchLayout(arena, cap);
        if (split->scratch)
            split->scratch[k] = s;
    }
}

int KeaSplits(int n, const KeaParameters *params)
{
    return params->splitRows > 0 && n >= params->splitRows && KeaSelectPath(n, params) != KeaPathDirect;
}

size_t KeaSplitMemoryRequired(int nRows, int nBodies, const KeaParameters *params)
{
    KeaArena counter = {NULL, 0, 0};
    KeaSplit split;
    if (!params || nRows < 0 || nBodies < 0 || !KeaSplits(nRows, params))
        return 0;
    KeaSplitLayout(&counter, nRows, nBodies, KeaSplitWorkers(&params->tasks), &split);
    return counter.used + KEA_ALIGN; /* + the alignment gap after the iterative path's layout */
}

/* Colour the blocks by their bodies (partition-local; the world in no colour), a unit at a time: a
 * run of consecutive blocks on one body pair (a contact group's points, a joint's blocks) is one
 * unit, coloured once and swept in one chunk in its order, so that a pair's four contact points do
 * not take four colours. No block writes the world's dv (kea_iterative.h, KeaBlockScatterHalf1), so
 * the world joins no colour. Then the chunks: each colour's units in runs of at least KEA_SPLIT_CHUNK blocks.
 * Returns 0 (not split) when a friction link leaves its block: that row would read a bound another
 * block of its colour may be writing. */
int KeaSplitColour(const KeaProblem *problem, KeaIterativeWork *w, KeaSplit *split)
{
    const int n = problem->nRows, nb = problem->nBodies;
    int b, i, c, k, u, units = 0, pos = 0;
    if (problem->link)
        for (i = 0; i < n; ++i)
            if (problem->link[i] >= 0 && w->rowBlock[problem->link[i]] != w->rowBlock[i])
                return 0;
    for (b = 0; b < w->nBlocks; ++b) {
        const int s = w->blockStart[b];
        const int b0 = problem->rowBodies[s][0], b1 = problem->rowBodies[s][1];
        if (units == 0 || split->pairs[units - 1][0] != b0 || split->pairs[units - 1][1] != b1) {
            split->pairs[units][0] = b0;
            split->pairs[units][1] = b1;
            split->unitStart[units++] = b;
        }
    }
    split->unitStart[units] = w->nBlocks;
    split->colours = KeaColourConstraints((const int(*)[2])split->pairs, units, nb, split->colourWork,
                                          split->colourBytes, split->colour, split->unitOrder, split->colourStart);
    if (split->colours < 0)
        return 0; /* not reached: the bodies are in range and the workspace sized for them */
    /* the units' blocks in colour order; colourStart and the chunks by block position */
    k = 0;
    for (c = 0; c <= KEA_COLOUR_COUNT; ++c) {
        const int first = split->colourStart[c], last = split->colourStart[c + 1];
        int chunkBlocks = KEA_SPLIT_CHUNK;
        split->colourStart[c] = pos;
        split->colourChunk[c] = k;
        for (i = first; i < last; ++i) {
            u = split->unitOrder[i];
            if (chunkBlocks >= KEA_SPLIT_CHUNK) {
                split->chunkStart[k++] = pos;
                chunkBlocks = 0;
            }
            for (b = split->unitStart[u]; b < split->unitStart[u + 1]; ++b) {
                split->blockUnit[b] = u;
                split->order[pos++] = b;
            }
            chunkBlocks += split->unitStart[u + 1] - split->unitStart[u];
        }
    }
    split->colourStart[KEA_COLOUR_COUNT + 1] = pos;
    split->colourChunk[KEA_COLOUR_COUNT + 1] = k;
    split->chunkStart[k] = w->nBlocks;
    split->nChunks = k;
    return 1;
}

/* The workers' copies of the work as it is now (the sweep's state lives in the arrays they share),
 * each with its own block scratch; worker 0 keeps the work's own. */
void KeaSplitWorks(const KeaIterativeWork *w, KeaSplit *split)
{
    const int workers = KeaSplitWorkers(&split->hook);
    int k;
    for (k = 0; k < workers; ++k) {
        KeaIterativeWork *c = &split->works[k];
        *c = *w;
        if (k == 0)
            continue;
        c->localW = split->scratch[k].localW;
        c->localR = split->scratch[k].localR;
        c->localLo = split->scratch[k].localLo;
        c->localHi = split->scratch[k].localHi;
        c->localX = split->scratch[k].localX;
        c->localD = split->scratch[k].localD;
        c->localLink = split->scratch[k].localLink;
        c->dense = split->scratch[k].dense;
    }
}

/* ---- the team: one task for the whole solve ----------------------------------------------------
 * A hand-out through the caller's task system per colour and sweep and per SM loop would cost a
 * wake-up of the workers each, some hundreds a step. So the solve hands out one task of `workers`
 * items (KeaSplitDrive): the first item to start becomes the driver and runs the whole solve; the
 * others become helpers, which wait (spinning) for the driver to publish a stage (a chunked loop:
 * KeaSplitRun), claim its items through an atomic cursor, run them, and return when the driver is
 * done, as Box2D v3's solver stages do. The driver never waits for a helper to arrive, only for the
 * items helpers have claimed, so a task system that runs the items one after the other (or fewer
 * at once than `workers`) is served too: the first item does all the work, the others find the
 * solve done. Which worker runs an item changes no bit (kea_iterative.h). */

/* Busy-wait hint (the helpers and the driver spin between stages). */
static inline void KeaSpinPause(void)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    __builtin_ia32_pause();
#endif
}

/* Claim and run items of stage `generation` while it has unclaimed ones; the cursor word holds the
 * generation in its high half and the next item in its low half, so that a claim on a stage that
 * has since ended fails. */
static void KeaTeamWork(KeaTeam *team, unsigned generation, int worker)
{
    for (;;) {
        uint64_t word = atomic_load_explicit(&team->cursor, memory_order_acquire);
        KeaTaskFn task;
        void *data;
        int next;
        const KeaTeamStage *stage = &team->stage[generation & 1];
        if ((unsigned)(word >> 32) != generation)
            return;
        next = (int)(word & 0xffffffffu);
        task = atomic_load_explicit(&stage->task, memory_order_relaxed);
        data = atomic_load_explicit(&stage->data, memory_order_relaxed);
        if (next >= atomic_load_explicit(&stage->items, memory_order_relaxed))
            return;
        if (!atomic_compare_exchange_weak_explicit(&team->cursor, &word, word + 1, memory_order_acq_rel,
                                                   memory_order_acquire))
            continue;
        task(next, next + 1, worker, data);
        atomic_fetch_add_explicit(&team->completed, 1, memory_order_release);
    }
}

/* The driver publishes a stage, works on it and waits until every item has run. */
static void KeaTeamPublish(KeaTeam *team, KeaTaskFn task, int items, void *data)
{
    /* Stage g + 1 goes to the slot stage g - 1 used: a helper still reading that one holds an ended
     * generation, so its claim fails; stage g's slot, which a helper may be claiming from, is left
     * alone (one slot would let a helper check stage g's cursor against stage g + 1's item count). */
    KeaTeamStage *stage = &team->stage[(team->generation + 1) & 1];
    atomic_store_explicit(&stage->task, task, memory_order_relaxed);
    atomic_store_explicit(&stage->data, data, memory_order_relaxed);
    atomic_store_explicit(&stage->items, items, memory_order_relaxed);
    atomic_store_explicit(&team->completed, 0, memory_order_relaxed);
    ++team->generation;
    atomic_store_explicit(&team->cursor, (uint64_t)team->generation << 32, memory_order_release);
    KeaTeamWork(team, team->generation, team->driverWorker);
    while (atomic_load_explicit(&team->completed, memory_order_acquire) < items)
        KeaSpinPause();
}

/* The team's task: the first item to start drives the solve, the others help until it is done. */
static void KeaTeamTask(int start, int end, int worker, void *data)
{
    KeaTeam *team = data;
    int item;
    for (item = start; item < end; ++item) {
        unsigned seen = 0;
        if (!atomic_exchange_explicit(&team->driving, 1, memory_order_acq_rel)) {
            team->driverWorker = worker;
            team->drive(team->driveData);
            atomic_store_explicit(&team->done, 1, memory_order_release);
            continue;
        }
        while (!atomic_load_explicit(&team->done, memory_order_acquire)) {
            const unsigned generation =
                (unsigned)(atomic_load_explicit(&team->cursor, memory_order_acquire) >> 32);
            if (generation != seen) {
                KeaTeamWork(team, generation, worker);
                seen = generation;
            } else {
                KeaSpinPause();
            }
        }
    }
}

void KeaSplitDrive(KeaSplit *split, void (*drive)(void *), void *data)
{
    KeaTeam team;
    int k;
    split->team = NULL;
    if (split->hook.workers <= 1 || split->hook.perStage) {
        drive(data);
        return;
    }
    team.drive = drive;
    team.driveData = data;
    team.generation = 0;
    team.driverWorker = 0;
    atomic_init(&team.cursor, 0);
    atomic_init(&team.completed, 0);
    for (k = 0; k < 2; ++k) {
        atomic_init(&team.stage[k].items, 0);
        atomic_init(&team.stage[k].task, NULL);
        atomic_init(&team.stage[k].data, NULL);
    }
    atomic_init(&team.driving, 0);
    atomic_init(&team.done, 0);
    split->team = &team;
    split->hook.run(KeaTeamTask, split->hook.workers, 1, &team, split->hook.user);
    split->team = NULL;
    if (!atomic_load_explicit(&team.driving, memory_order_acquire))
        drive(data); /* the task system ran no item: the solve runs here */
}

void KeaSplitRun(const KeaSplit *split, KeaTaskFn task, int items, void *data)
{
    if (items <= 0)
        return;
    if (split->team && items > 1)
        KeaTeamPublish(split->team, task, items, data);
    else if (split->hook.perStage && split->hook.workers > 1 && items > 1)
        split->hook.run(task, items, 1, data, split->hook.user);
    else
        task(0, items, 0, data);
}

/* SM's scatter order: the free list's pieces by the colour of their block's unit, each colour's in
 * free-list order, cut into chunks of at least KEA_SPLIT_PIECES pieces at a change of unit (a unit's
 * pieces write the same two bodies: one chunk runs them in order). */
void KeaSplitPieces(const KeaIterativeWork *w, KeaSplit *split)
{
    int counts[KEA_COLOUR_COUNT + 1], next[KEA_COLOUR_COUNT + 1];
    int c, k, j, chunks = 0;
    memset(counts, 0, sizeof counts);
    for (k = 0; k < w->nPieces; ++k)
        ++counts[split->colour[split->blockUnit[w->rowBlock[w->pieces[k].row]]]];
    next[0] = 0;
    for (c = 0; c < KEA_COLOUR_COUNT; ++c)
        next[c + 1] = next[c] + counts[c];
    for (k = 0; k < w->nPieces; ++k)
        split->pieceOrder[next[split->colour[split->blockUnit[w->rowBlock[w->pieces[k].row]]]]++] = k;
    j = 0;
    for (c = 0; c <= KEA_COLOUR_COUNT; ++c) {
        const int end = j + counts[c];
        int inChunk = KEA_SPLIT_PIECES, lastUnit = -1;
        split->pieceColourChunk[c] = chunks;
        for (; j < end; ++j) {
            const int unit = split->blockUnit[w->rowBlock[w->pieces[split->pieceOrder[j]].row]];
            if (inChunk >= KEA_SPLIT_PIECES && unit != lastUnit) {
                split->pieceChunk[chunks++] = j;
                inChunk = 0;
            }
            ++inChunk;
            lastUnit = unit;
        }
    }
    split->pieceColourChunk[KEA_COLOUR_COUNT + 1] = chunks;
    split->pieceChunk[chunks] = w->nPieces;
}

/* The packs' colouring: a pack's eight halves' bodies, the world (nb: a contact on the ground, a lane
 * with no contact) as none, so that any number of a colour's packs may hold bodies to the world (the
 * split scatter writes nothing to it, KeaPacksScatterSplit). Each colour's packs in pack order, cut
 * every KEA_SPLIT_PACKS packs: no two share a body, so neither their order nor the cut changes a bit. */
void KeaSplitPacks(const KeaIterativeWork *w, KeaSplit *split)
{
    int k, h, l, c, j, chunks = 0;
    int start[KEA_COLOUR_COUNT + 2];
    for (k = 0; k < w->nPacks; ++k)
        for (h = 0; h < 2; ++h)
            for (l = 0; l < KEA_PACK_LANES; ++l) {
                const int b = w->packs[k].body[h][l];
                split->packBodies[2 * KEA_PACK_LANES * k + KEA_PACK_LANES * h + l] = b == w->nb ? KEA_COLOUR_WORLD : b;
            }
    if (KeaColourItems(split->packBodies, 2 * KEA_PACK_LANES, w->nPacks, w->nb, split->colourWork, split->colourBytes,
                       split->packColour, split->packOrder, start) < 0) {
        /* not reached (the bodies are in range, the workspace sized for them): all packs overflow, serial */
        for (k = 0; k < w->nPacks; ++k)
            split->packOrder[k] = k;
        for (c = 0; c <= KEA_COLOUR_COUNT; ++c)
            start[c] = 0;
        start[KEA_COLOUR_COUNT + 1] = w->nPacks;
    }
    for (c = 0; c <= KEA_COLOUR_COUNT; ++c) {
        split->packColourChunk[c] = chunks;
        for (j = start[c]; j < start[c + 1]; j += KEA_SPLIT_PACKS)
            split->packChunk[chunks++] = j;
    }
    split->packColourChunk[KEA_COLOUR_COUNT + 1] = chunks;
    split->packChunk[chunks] = w->nPacks;
}
