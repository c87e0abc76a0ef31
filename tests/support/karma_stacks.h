/* karma_stacks.h -- scenes of bodies resting on a ground plane, for the stacking tests: a universe
 * on the plane z = 0 under gravity and the bodies placed in it, each with where it was placed (what
 * the tests measure drift and sway from). */
#ifndef KARMA_STACKS_H
#define KARMA_STACKS_H

#include <karma/Mst.h>

typedef struct KarmaStack {
    MstUniverseID u;
    int count, max;
    MdtBodyID *bodies;   /* in the order placed */
    MeVector3 *start;    /* each body's centre as placed (m) */
} KarmaStack;

/** A universe of the given sizes with gravity 9.81 m/s² down z, auto-disable off (the contacts must
 *  hold the bodies up by themselves), a fixed plane z = 0, and its default contact: 2D friction,
 *  normal-force model, coefficient mu; room for max bodies. */
void karma_stack_init(KarmaStack *s, const MstUniverseSizes *sizes, MeReal mu, int max);
/** A body of geometry g and density (kg/m³) centred at (x, y, z), recorded with its start; the test
 *  fails when the stack is full or the universe refuses it. */
MdtBodyID karma_stack_add(KarmaStack *s, McdGeometryID g, MeReal density, MeReal x, MeReal y, MeReal z);
/** Destroy the universe and free the lists. */
void karma_stack_free(KarmaStack *s);

#endif /* KARMA_STACKS_H */
