/* kea_colour.c -- graph colouring of a partition's constraints by body (kea_colour.h).
 *
 * One bit set of bodies per colour; a constraint takes the first colour whose set holds neither of its
 * bodies, and adds them. The world belongs to no set: any number of constraints of one colour may hold
 * a body to the world, since the world's velocity is never written. Greedy first-fit in the
 * constraints' order: a constraint sharing bodies with d others gets a colour below d + 1, so a chain
 * takes two colours and a grid of stacked boxes a handful; only a body with more than
 * KEA_COLOUR_COUNT constraints sends some of them to the overflow colour. The same for items of more
 * bodies (KeaColourItems: SM's packs of four contacts, up to eight bodies). */
#include <stdint.h>
#include <string.h>

#include "kea_colour.h"
#include "kea.h"

_Static_assert(KEA_COLOUR_WORLD == KEA_WORLD, "the colouring takes Kea's rows' body indices as they are");

#define WORD_BITS 64

static size_t wordsFor(int bodyCount) { return ((size_t)bodyCount + WORD_BITS - 1) / WORD_BITS; }

size_t KeaColourMemoryRequired(int bodyCount)
{
    return bodyCount > 0 ? sizeof(uint64_t) * wordsFor(bodyCount) * KEA_COLOUR_COUNT : 0;
}

/* Whether body b (or the world) is free in the set. */
static int isFree(const uint64_t *set, int b)
{
    return b == KEA_COLOUR_WORLD || !(set[b / WORD_BITS] & ((uint64_t)1 << (b % WORD_BITS)));
}

static void take(uint64_t *set, int b)
{
    if (b != KEA_COLOUR_WORLD)
        set[b / WORD_BITS] |= (uint64_t)1 << (b % WORD_BITS);
}

/* Size: the input (bodies, count, bodyCount), the caller's workspace (pointer and size) and the three
 * outputs, each an array the caller owns (Kea's split solve keeps them in its arena). */
int KeaColourConstraints(const int (*bodies)[2], int count, int bodyCount, void *workspace, size_t workspaceBytes,
                         int *colour, int *order, int *colourStart)
{
    return KeaColourItems(count > 0 ? &bodies[0][0] : NULL, 2, count, bodyCount, workspace, workspaceBytes, colour,
                          order, colourStart);
}

/* Whether every body of an item (or the world) is free in the set. */
static int allFree(const uint64_t *set, const int *item, int perItem)
{
    for (int k = 0; k < perItem; k++)
        if (!isFree(set, item[k]))
            return 0;
    return 1;
}

/* Size: KeaColourConstraints' parameters and the bodies per item. */
int KeaColourItems(const int *bodies, int perItem, int count, int bodyCount, void *workspace, size_t workspaceBytes,
                   int *colour, int *order, int *colourStart)
{
    if (count < 0 || perItem < 1 || bodyCount < 0 || workspaceBytes < KeaColourMemoryRequired(bodyCount))
        return -1;
    for (int i = 0; i < count * perItem; i++)
        if (bodies[i] != KEA_COLOUR_WORLD && (bodies[i] < 0 || bodies[i] >= bodyCount))
            return -1;
    const size_t words = wordsFor(bodyCount);
    uint64_t *sets = workspace;
    if (words > 0)
        memset(sets, 0, sizeof(uint64_t) * words * KEA_COLOUR_COUNT);
    int counts[KEA_COLOUR_COUNT + 1] = {0};
    int used = 0;
    for (int i = 0; i < count; i++) {
        const int *item = bodies + (size_t)i * (size_t)perItem;
        int c = 0;
        while (c < KEA_COLOUR_COUNT && !allFree(sets + (size_t)c * words, item, perItem))
            c++;
        if (c < KEA_COLOUR_COUNT) {
            for (int k = 0; k < perItem; k++)
                take(sets + (size_t)c * words, item[k]);
            if (c + 1 > used)
                used = c + 1;
        }
        colour[i] = c;
        counts[c]++;
    }
    /* Counting sort by colour: stable, so each colour keeps the constraints' own order. */
    colourStart[0] = 0;
    for (int c = 0; c <= KEA_COLOUR_COUNT; c++)
        colourStart[c + 1] = colourStart[c] + counts[c];
    int next[KEA_COLOUR_COUNT + 1];
    memcpy(next, colourStart, sizeof next);
    for (int i = 0; i < count; i++)
        order[next[colour[i]]++] = i;
    return used;
}
