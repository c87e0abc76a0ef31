/* McdContact.h -- a contact point produced by a nearfield (pair) test.
 *
 * Conventions (as Karma's pair tests): the normal is a unit vector pointing from model 2 towards
 * model 1 of the pair (the direction in which model 1 must move to separate: sphere-sphere, centre 1
 * minus centre 2; a model on a plane, the plane's normal); `separation` is the signed distance between the
 * surfaces along the normal: negative when they overlap (penetration depth = -separation), positive
 * when a contact is reported early because it lies within the models' contact tolerance. */
#ifndef MCD_CONTACT_H
#define MCD_CONTACT_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

typedef struct McdContact {
    MeVector3 position; /**< world point, midway between the two surfaces */
    MeVector3 normal;   /**< unit, model 2 -> model 1 */
    MeReal separation;  /**< < 0: penetration */
    MeI16 dims;         /**< dimension of the touching features' overlap: 0 point, 1 line, 2 face */
    MeI16 pad_;
    void *element1;     /**< sub-element of model 1 (e.g. a triangle or an aggregate child), or NULL */
    void *element2;     /**< sub-element of model 2, or NULL */
} McdContact;

/** Karma 1.2's contact reduction: write to contacts_dst at most nContacts_dest (>= 0) of the
 *  nContacts_src contacts of contacts_src (the arrays must not overlap) and return how many. The
 *  deepest contact comes first, then each next one is the farthest from those already kept
 *  (distances measured in the plane perpendicular to avgNormal; NULL: in space), so the kept points
 *  spread over the contact area. Contacts closer than 0.001 x scale to a kept one are duplicates and
 *  dropped. With faceNormalsFirst non-zero, face contacts (dims 2) are taken before the others. */
ME_API int MEAPI McdContactSimplify(const MeReal *avgNormal, McdContact *contacts_src, const int nContacts_src,
                                   McdContact *contacts_dst, const int nContacts_dest, const int faceNormalsFirst,
                                   const MeReal scale);

ME_EXTERN_C_END

#endif /* MCD_CONTACT_H */
