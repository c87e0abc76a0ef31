/* kea_colour.c -- graph colouring of a partition's constraints by body (kea_colour.h).
 *
 * One mask per body, bit c set when colour c holds the body; a constraint takes the lowest colour
 * set in neither of its bodies' masks (the lowest bit clear in the OR of their masks), and sets it
 * in both. The world has no mask: any number of constraints of one colour may hold a body to the
 * world, since the world's velocity is never written. Greedy first-fit in the constraints' order: a
 * constraint sharing bodies with d others gets a colour below d + 1, so a chain takes two colours
 * and a grid of stacked boxes a handful; a constraint whose bodies together already hold every colour
 * goes to the overflow colour (possible with fewer than KEA_COLOUR_COUNT constraints on each body). The same for items of more bodies (KeaColourItems:
 * SM's packs of four contacts, up to eight bodies). A mask per body (an OR and a bit search per
 * constraint): a colour is found in a few operations however many colours are tried. */
#include <stdint.h>
#include <string.h>

#include "kea_colour.h"
#include "kea.h"

_Static_assert(KEA_COLOUR_WORLD == KEA_WORLD, "the colouring takes Kea's rows' body indices as they are");
_Static_assert(KEA_COLOUR_COUNT < 32, "a body's colours are the bits of a 32-bit mask");

/* The colours a mask may hold. */
#define ALL_COLOURS ((uint32_t)((1u << KEA_COLOUR_COUNT) - 1u))

size_t KeaColourMemoryRequired(int bodyCount)
{
    return bodyCount > 0 ? sizeof(uint32_t) * (size_t)bodyCount : 0;
}

/* Size: the input (bodies, count, bodyCount), the caller's workspace (pointer and size) and the three
 * outputs, each an array the caller owns (Kea's split solve keeps them in its arena). */
int KeaColourConstraints(const int (*bodies)[2], int count, int bodyCount, void *workspace, size_t workspaceBytes,
                         int *colour, int *order, int *colourStart)
{
    return KeaColourItems(count > 0 ? &bodies[0][0] : NULL, 2, count, bodyCount, workspace, workspaceBytes, colour,
                          order, colourStart);
}

/* The lowest colour set in `available` (the colours an item may still take; not 0). */
static int lowestColour(uint32_t available)
{
#if defined(__GNUC__)
    return __builtin_ctz(available);
#else
    int c = 0;
    while (!((available >> c) & 1u))
        c++;
    return c;
#endif
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
    uint32_t *masks = workspace;
    if (bodyCount > 0)
        memset(masks, 0, sizeof(uint32_t) * (size_t)bodyCount);
    int counts[KEA_COLOUR_COUNT + 1] = {0};
    int used = 0;
    for (int i = 0; i < count; i++) {
        const int *item = bodies + (size_t)i * (size_t)perItem;
        uint32_t taken = 0;
        for (int k = 0; k < perItem; k++)
            if (item[k] != KEA_COLOUR_WORLD)
                taken |= masks[item[k]];
        const uint32_t available = ~taken & ALL_COLOURS;
        const int c = available ? lowestColour(available) : KEA_COLOUR_OVERFLOW;
        if (c < KEA_COLOUR_COUNT) {
            for (int k = 0; k < perItem; k++)
                if (item[k] != KEA_COLOUR_WORLD)
                    masks[item[k]] |= (uint32_t)1u << c;
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
