/* karma_contacts.h -- hand-made box contacts for dynamics tests and benchmarks (see karma_contacts.c).
 * Plain C on the public API (no test framework). The box functions return 0 when the constraint pool
 * is full, else 1. */
#ifndef KARMA_CONTACTS_H
#define KARMA_CONTACTS_H

#include <karma/MdtContactGroup.h>

/** Reset p and make it 2D Coulomb friction with coefficient mu. */
void karma_contact_params_friction(MdtContactParams *p, MeReal mu);

/** Four contacts between the box's face nearest the plane {x : x·up = planeOffset} and the plane
 *  (the world). The group's body 0 must be the box, body 1 NULL. */
int karma_box_on_plane(MdtContactGroupID g, MdtBodyID box, const MeVector3 halfExtents, const MeVector3 up,
                       MeReal planeOffset, const MdtContactParams *params);

/** Four contacts between the top box's lower face and the bottom box's upper face (equal boxes).
 *  The group's body 0 must be `top`, body 1 `bottom`. */
int karma_box_on_box(MdtContactGroupID g, MdtBodyID top, MdtBodyID bottom, const MeVector3 halfExtents,
                     const MdtContactParams *params);

/** Four contacts on the overlap of the top box's lower face with the bottom box's upper face, for
 *  boxes of any sizes whose faces are (nearly) parallel: bricks laid with an offset, a plank on a
 *  block. The group's body 0 must be `top`, body 1 `bottom`. */
int karma_box_on_box_clipped(MdtContactGroupID g, MdtBodyID top, const MeVector3 topHalf, MdtBodyID bottom,
                             const MeVector3 bottomHalf, const MdtContactParams *params);

#endif
