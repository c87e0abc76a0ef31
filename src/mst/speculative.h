/* speculative.h -- the bridge's rule for a pair's points apart (decision C23; speculative.c). */
#ifndef MST_SPECULATIVE_H
#define MST_SPECULATIVE_H

#include <karma/McdContact.h>
#include <karma/McdModelPair.h>
#include <karma/MdtTypes.h>

/** Multiple of |g| a point may gain towards the other body in a step: a body held by its supports
 *  while the other falls, or turning about a support (a plank's free end falls at 1.5 g). */
#define MST_SPECULATIVE_GRAVITY ME_R(2.0)

/** Share of the pair's contact tolerance within which a point apart is always kept. */
#define MST_SPECULATIVE_FLOOR ME_R(0.5)

/** Keep, in order at the front of `contacts`, the pair's points that touch or whose gap can close
 *  within a step of h at a conservative bound of the approach speed of the pair's bodies
 *  (models->bodyData: model 1's and model 2's, NULL for the world), or lie within MST_SPECULATIVE_FLOOR
 *  of its contact tolerance; returns how many. h <= 0 (the step not known), or a torque
 *  applied to either body, keeps every point. */
int MstSpeculativeKeep(MdtWorldID world, McdModelPairID pair, const McdModelPairModelInfo *models, MeReal h,
                       McdContact *contacts, int n);

#endif /* MST_SPECULATIVE_H */
