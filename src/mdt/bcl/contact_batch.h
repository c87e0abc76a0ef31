/* contact_batch.h -- what the bridge (src/mst/bridge.c) needs to refresh a contact group each step,
 * with one handle check per group and per contact instead of one per field: the same checks and the
 * same effects as the public getters and setters they stand for. Internal to the library. */
#ifndef MDT_CONTACT_BATCH_H
#define MDT_CONTACT_BATCH_H

#include <karma/MdtContactGroup.h>
#include <karma/MdtContactParams.h>

/* The group's contacts in order (at most max) and their positions; returns how many (0 for an
 * invalid group, reported in `function`, the caller's public entry point). */
int MdtContactGroupGetContactsAndPositions(MdtContactGroupID group, MdtContactID *contacts, MeVector3 *positions,
                                           int max, const char *function);

/* MdtContactSetParams, MdtContactSetPosition, MdtContactSetNormal (normal scaled by sign first) and
 * MdtContactSetPenetration on one contact, in that order: a NULL or non-finite field is skipped and
 * reported in the name of its setter, the others are set. */
void MdtContactSetFromCollision(MdtContactID contact, const MdtContactParams *params, const MeReal position[3],
                                const MeReal normal[3], MeReal sign, MeReal penetration);

#endif
