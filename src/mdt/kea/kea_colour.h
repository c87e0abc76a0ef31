/* kea_colour.h -- graph colouring of a partition's constraints by body (internal; issue 17 point 5).
 *
 * Constraints of one colour share no body, so a Gauss-Seidel sweep may update them at the same time on
 * several workers, colour after colour with a barrier between: every body's velocity is written by at
 * most one constraint of a colour. The colouring depends only on the constraints' order and bodies,
 * never on the number of workers, so a sweep in colour order is the same for any worker count
 * (docs/step.md, "Splitting one large partition"). Box2D v3's graph colouring does the same with 24
 * colours; a constraint that finds none free goes to the overflow colour, swept on one worker. */
#ifndef KEA_COLOUR_H
#define KEA_COLOUR_H

#include <stddef.h>

/** Colours before the overflow colour. */
#define KEA_COLOUR_COUNT 24
/** The colour of a constraint that shares a body with some constraint of every other colour. */
#define KEA_COLOUR_OVERFLOW KEA_COLOUR_COUNT
/** A body index meaning the world (static: it joins no colour), Kea's KEA_WORLD. */
#define KEA_COLOUR_WORLD (-1)

/** Bytes of workspace KeaColourConstraints needs for a partition of `bodyCount` bodies. */
size_t KeaColourMemoryRequired(int bodyCount);

/** Colour `count` constraints, constraint i joining bodies[i][0] and bodies[i][1] (partition-local
 *  indices in [0, bodyCount), or KEA_COLOUR_WORLD), greedily in their order: each takes the lowest
 *  colour that holds neither of its bodies yet. Writes colour[i] (0 .. KEA_COLOUR_OVERFLOW), `order`
 *  (the constraints sorted by colour, in their own order within a colour) and colourStart[0 ..
 *  KEA_COLOUR_COUNT + 1] (colour c is order[colourStart[c] .. colourStart[c + 1])). Returns the number
 *  of colours in use, the overflow colour not counted, or -1, writing nothing, for a body index out of
 *  range or a workspace smaller than KeaColourMemoryRequired(bodyCount). */
int KeaColourConstraints(const int (*bodies)[2], int count, int bodyCount, void *workspace, size_t workspaceBytes,
                         int *colour, int *order, int *colourStart);

/** The same for items of `perItem` bodies each (>= 1): item i's are bodies[perItem i .. perItem i +
 *  perItem - 1] (a body may repeat within an item); an item takes the lowest colour that holds none of
 *  them. KeaColourConstraints is this with perItem 2. Returns as it, or -1 for perItem < 1. */
int KeaColourItems(const int *bodies, int perItem, int count, int bodyCount, void *workspace, size_t workspaceBytes,
                   int *colour, int *order, int *colourStart);

#endif /* KEA_COLOUR_H */
