/* karma_pairs.h -- one model pair's contacts for the collision tests: a model placed at a transform,
 * and the contacts of (m1, m2) through Karma's per-pair calls (McdHello / McdIntersect / McdGoodbye),
 * the way an application without a space asks for them. */
#ifndef KARMA_PAIRS_H
#define KARMA_PAIRS_H

#include <karma/Mcd.h>
#include <karma/MeMath.h>

/** A framework of `instances` geometry instances (McdInit(0, 64, instances, 1)) with the primitive
 *  types and their pair tests registered; the test asserts it was made. */
McdFrameworkID karma_pairs_framework(int instances);
/** A model of g at the world transform tm (copied), with the given contact tolerance, updated. */
McdModelID karma_model_at(McdGeometryID g, MeMatrix4 tm, MeReal contactTolerance);
/** The contacts of (m1, m2), at most max, written to c; request (may be NULL: the pair's default)
 *  is set on the pair before the test. Returns the contact count. */
int karma_intersect(McdModelID m1, McdModelID m2, McdRequest *request, McdContact *c, int max);

#endif /* KARMA_PAIRS_H */
