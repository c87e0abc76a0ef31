/* MdtContactGroup.h -- the contacts between one pair of bodies (or a body and the world), as one
 * constraint.
 *
 * A collision system (the bridge) creates a group when two models first touch, refreshes its contacts
 * every step while they stay in contact, and destroys it when they part. Because the group persists,
 * its contacts keep last step's impulses, which start the next solve (warm starting): contact k of
 * the group is assumed to be the continuation of last step's contact k, so refresh contacts in a
 * stable order (reuse the group's existing contacts before creating new ones, as Karma's bridge did).
 * Rows: the sum of its contacts' rows. */
#ifndef MDT_CONTACT_GROUP_H
#define MDT_CONTACT_GROUP_H

#include "MdtConstraint.h"
#include "MdtContact.h"

ME_EXTERN_C_BEGIN

/** A new disabled, empty contact group, or NULL when the constraint pool is full. */
ME_API MdtContactGroupID MdtContactGroupCreate(MdtWorldID w);
/** Destroy the group and its contacts. */
ME_API void MdtContactGroupDestroy(MdtContactGroupID g);
/** Destroy the contacts, keep the group. */
ME_API void MdtContactGroupReset(MdtContactGroupID g);
/** The group as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtContactGroupQuaConstraint(MdtContactGroupID g);
/** The constraint as a contact group, or NULL when it is not one. */
ME_API MdtContactGroupID MdtConstraintDCastContactGroup(MdtConstraintID c);

/** The group's contacts in order: the first, and the one after `c` (NULL after the last). */
ME_API MdtContactID MdtContactGroupGetFirstContact(MdtContactGroupID g);
/** The group's contact after c, or NULL after the last; c not in g refused (ME_ERR_BAD_STATE). */
ME_API MdtContactID MdtContactGroupGetNextContact(MdtContactGroupID g, MdtContactID c);
/** Add a stand-alone (disabled) contact to the end of the group; it takes the group's bodies. */
ME_API void MdtContactGroupAppendContact(MdtContactGroupID g, MdtContactID c);
/** Take a contact out of the group (it becomes a disabled stand-alone contact). */
ME_API void MdtContactGroupRemoveContact(MdtContactGroupID g, MdtContactID c);
/** A new contact at the end of the group (params reset), or NULL when the pool is full. */
ME_API MdtContactID MdtContactGroupCreateContact(MdtContactGroupID g);
/** Destroy a contact of the group; c not in g (ME_ERR_BAD_STATE) or during the step (ME_ERR_WORLD_LOCKED) refused. */
ME_API void MdtContactGroupDestroyContact(MdtContactGroupID g, MdtContactID c);
/** Whether the group's bodies are in the opposite order from its generator's models. */
ME_API MeBool MdtContactGroupIsSwapped(MdtContactGroupID g);
/** Record that the group's bodies are in the opposite order from its generator's models. */
ME_API void MdtContactGroupSetSwapped(MdtContactGroupID g, MeBool swapped);
/** The group's first `max` (>= 0) contacts in order and, when `positions` is not NULL, their world
 *  positions (m), with one handle check for the group (a bridge refreshing it each step); returns how
 *  many were written. Invalid group, NULL `contacts` or negative `max` refused (0). */
ME_API int MdtContactGroupGetContactsAndPositions(MdtContactGroupID g, MdtContactID *contacts, MeVector3 *positions,
                                                  int max);
/** A collision point for MdtContactGroupSetFromCollisions: position (m), normal from body 1 towards
 *  body 0 (made unit) and penetration (m; > 0: overlap). */
typedef struct MdtCollisionPoint {
    MeVector3 position, normal;
    MeReal penetration;
} MdtCollisionPoint;
/** Refresh the group's contacts from n (>= 0) collision points with one handle check (a bridge, each
 *  step): point i takes the group's old contact nearest to it (greedy, in order, so that the warm
 *  start follows the point) or a new one appended to the group, the old contacts no point took are
 *  destroyed, and each point's contact is set as MdtContactSetFromCollision would with `params`;
 *  out[i] receives point i's contact. Returns how many points got a contact (fewer than n when the
 *  constraint pool is full, reported). Invalid group, NULL argument, negative n or a world in its
 *  step refused (0, nothing changed). */
ME_API int MdtContactGroupSetFromCollisions(MdtContactGroupID g, const MdtContactParams *params,
                                            const MdtCollisionPoint *points, int n, MdtContactID *out);
/** Number of contacts in the group; 0 for an invalid ID. */
ME_API int MdtContactGroupGetCount(MdtContactGroupID g);
/** Sum of the contacts' normal forces in the last step, N. */
ME_API MeReal MdtContactGroupGetNormalForce(MdtContactGroupID g);
/** What created the group (the bridge stores its model pair). */
ME_API void MdtContactGroupSetGenerator(MdtContactGroupID g, void *generator);
/** The generator pointer set by MdtContactGroupSetGenerator (not owned by the group); NULL if none. */
ME_API void *MdtContactGroupGetGenerator(MdtContactGroupID g);

#define MdtContactGroupEnable(g) MdtConstraintEnable(MdtContactGroupQuaConstraint(g))
#define MdtContactGroupDisable(g) MdtConstraintDisable(MdtContactGroupQuaConstraint(g))
#define MdtContactGroupIsEnabled(g) MdtConstraintIsEnabled(MdtContactGroupQuaConstraint(g))
#define MdtContactGroupSetBodies(g, b1, b2) MdtConstraintSetBodies(MdtContactGroupQuaConstraint(g), (b1), (b2))
#define MdtContactGroupGetBody(g, i) MdtConstraintGetBody(MdtContactGroupQuaConstraint(g), (i))
#define MdtContactGroupGetWorld(g) MdtConstraintGetWorld(MdtContactGroupQuaConstraint(g))
#define MdtContactGroupGetForce(g, i, f) MdtConstraintGetForce(MdtContactGroupQuaConstraint(g), (i), (f))
#define MdtContactGroupGetTorque(g, i, t) MdtConstraintGetTorque(MdtContactGroupQuaConstraint(g), (i), (t))
#define MdtContactGroupSetSortKey(g, k) MdtConstraintSetSortKey(MdtContactGroupQuaConstraint(g), (k))
#define MdtContactGroupGetSortKey(g) MdtConstraintGetSortKey(MdtContactGroupQuaConstraint(g))
#define MdtContactGroupSetUserData(g, d) MdtConstraintSetUserData(MdtContactGroupQuaConstraint(g), (d))
#define MdtContactGroupGetUserData(g) MdtConstraintGetUserData(MdtContactGroupQuaConstraint(g))

/* Karma 1.2's name (without "Get") for the group's torque on body i. */
#define MdtContactGroupTorque(g, i, t) MdtContactGroupGetTorque((g), (i), (t))

ME_EXTERN_C_END

#endif /* MDT_CONTACT_GROUP_H */
