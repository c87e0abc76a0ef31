/* karma_contacts.h -- hand-made box contacts for dynamics tests (see karma_contacts.c). */
#ifndef KARMA_CONTACTS_H
#define KARMA_CONTACTS_H

#include <karma/MdtContactGroup.h>

/** Reset p and make it 2D Coulomb friction with coefficient mu. */
void karma_contact_params_friction(MdtContactParams *p, MeReal mu);

/** Four contacts between the box's face nearest the plane {x : x·up = planeOffset} and the plane
 *  (the world). The group's body 0 must be the box, body 1 NULL. */
void karma_box_on_plane(MdtContactGroupID g, MdtBodyID box, const MeVector3 halfExtents, const MeVector3 up,
                        MeReal planeOffset, const MdtContactParams *params);

/** Four contacts between the top box's lower face and the bottom box's upper face (equal boxes).
 *  The group's body 0 must be `top`, body 1 `bottom`. */
void karma_box_on_box(MdtContactGroupID g, MdtBodyID top, MdtBodyID bottom, const MeVector3 halfExtents,
                      const MdtContactParams *params);

#endif
