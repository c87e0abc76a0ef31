/* MdtContact.h -- a contact point between two bodies (or a body and the world).
 *
 * Sign conventions (as Karma): the normal is a unit vector pointing from body 1 towards body 0 (the
 * direction in which body 0 is pushed; body 1 is pushed the other way): a ball (body 0) on the
 * world (body 1 NULL) with y up has the normal (0, 1, 0). The penetration is positive when the
 * bodies overlap. A collision system's McdContact (normal from model 2 towards model 1, separation
 * < 0 when penetrating) converts with normal as is and penetration = −separation.
 * Contacts are normally members of an MdtContactGroup (one per touching pair, see
 * MdtContactGroup.h); a stand-alone contact is a constraint of its own (MdtContactCreate, then
 * MdtContactSetBodies and MdtContactEnable).
 * Rows: 1 (frictionless), 2 (1D friction) or 3 (2D friction), see MdtContactParams.h. */
#ifndef MDT_CONTACT_H
#define MDT_CONTACT_H

#include "MdtConstraint.h"
#include "MdtContactParams.h"

ME_EXTERN_C_BEGIN

/** A new disabled stand-alone contact, or NULL when the constraint pool is full. */
ME_API MdtContactID MdtContactCreate(MdtWorldID w);
/** Restore the defaults: position 0, normal (0,1,0), direction (0,1,0), penetration 0, params reset. */
ME_API void MdtContactReset(MdtContactID c);
/** The contact as a generic constraint (same object, no check, no ownership change). */
ME_API MdtConstraintID MdtContactQuaConstraint(MdtContactID c);
/** The constraint as a contact, or NULL when it is not one (an invalid ID is reported). */
ME_API MdtContactID MdtConstraintDCastContact(MdtConstraintID c);

/** Contact point, world frame. */
ME_API void MdtContactSetPosition(MdtContactID c, MeReal x, MeReal y, MeReal z);
/** Contact point, world frame (m); NULL p refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtContactGetPosition(MdtContactID c, MeVector3 p);
/** Normal from body 1 towards body 0 (normalised here; a zero vector is refused). */
ME_API void MdtContactSetNormal(MdtContactID c, MeReal x, MeReal y, MeReal z);
/** Unit normal from body 1 towards body 0; NULL n refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtContactGetNormal(MdtContactID c, MeVector3 n);
/** Overlap depth (> 0 when penetrating), m. */
ME_API void MdtContactSetPenetration(MdtContactID c, MeReal p);
/** Overlap depth (m, > 0 when penetrating); 0 for an invalid ID. */
ME_API MeReal MdtContactGetPenetration(MdtContactID c);
/** Primary friction direction (made perpendicular to the normal; used with the UseDirection
 *  option, else a direction is chosen). The secondary is primary × normal (as Karma). */
ME_API void MdtContactSetDirection(MdtContactID c, MeReal x, MeReal y, MeReal z);
/** Primary friction direction (unit, world frame); NULL d refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtContactGetDirection(MdtContactID c, MeVector3 d);
/** Velocity of the world's surface at this contact (body 1 NULL; sets the UseWorldVelocity option). */
ME_API void MdtContactSetWorldVelocity(MdtContactID c, MeReal vx, MeReal vy, MeReal vz);
/** Velocity of the world's surface at the contact (m/s); NULL v refused. */
ME_API void MdtContactGetWorldVelocity(MdtContactID c, MeVector3 v);
/** The contact's parameters (a pointer into the contact: change them in place). */
ME_API MdtContactParamsID MdtContactGetParams(MdtContactID c);
/** Copy parameters into the contact. */
ME_API void MdtContactSetParams(MdtContactID c, const MdtContactParams *p);
/** MdtContactSetParams, MdtContactSetPosition (m), MdtContactSetNormal and MdtContactSetPenetration (m)
 *  with one handle check, for a bridge writing a collision's contact: each field checked as its setter
 *  would, a bad one skipped and reported in that setter's name, the others set; NULL position or
 *  normal refused (ME_ERR_NULL_ARGUMENT) with nothing set. */
ME_API void MdtContactSetFromCollision(MdtContactID c, const MdtContactParams *params, const MeVector3 position,
                                       const MeVector3 normal, MeReal penetration);
/** Velocity of body 0's material point relative to body 1's (or to the moving world) at the contact. */
ME_API void MdtContactGetRelativeVelocity(MdtContactID c, MeVector3 v);
/** Normal force (N) the contact applied in the last step (≥ 0 unless adhesive). */
ME_API MeReal MdtContactGetNormalForce(MdtContactID c);
/** Importance for matrix capping (larger is kept first). */
ME_API void MdtContactSetImportance(MdtContactID c, MeReal importance);
/** Importance for matrix capping (MdtContactSetImportance); 0 for an invalid ID. */
ME_API MeReal MdtContactGetImportance(MdtContactID c);
/** Next contact in the same group, or NULL. */
ME_API MdtContactID MdtContactGetNext(MdtContactID c);
/** Karma 1.2's link setter (deprecated in 1.2), on the list of c's contact group: nc (a stand-alone
 *  contact, or one of the same group) is placed just after c, the contacts that followed c now
 *  following nc; NULL makes c the group's last contact, the ones after it leaving the group as
 *  disabled stand-alone contacts. Refused for a stand-alone c (ME_ERR_BAD_STATE). */
ME_API void MdtContactSetNext(MdtContactID c, MdtContactID nc);
/** The group the contact belongs to, or NULL. */
ME_API MdtContactGroupID MdtContactGetContactGroup(MdtContactID c);

/** The contacts touching a body (decision D9): those of its contact groups, in group order, and its
 *  stand-alone contacts, following the body's constraint list. NULL after the last; `c` must be a
 *  contact of body `b`. Do not destroy contacts while iterating. */
ME_API MdtContactID MdtBodyGetFirstContact(MdtBodyID b);
/** The contact after c among those touching b, or NULL; c not touching b refused (ME_ERR_BAD_STATE). */
ME_API MdtContactID MdtBodyGetNextContact(MdtBodyID b, MdtContactID c);

#define MdtContactDestroy(c) MdtConstraintDestroy(MdtContactQuaConstraint(c))
#define MdtContactEnable(c) MdtConstraintEnable(MdtContactQuaConstraint(c))
#define MdtContactDisable(c) MdtConstraintDisable(MdtContactQuaConstraint(c))
#define MdtContactIsEnabled(c) MdtConstraintIsEnabled(MdtContactQuaConstraint(c))
#define MdtContactSetBodies(c, b1, b2) MdtConstraintSetBodies(MdtContactQuaConstraint(c), (b1), (b2))
#define MdtContactGetBody(c, i) MdtConstraintGetBody(MdtContactQuaConstraint(c), (i))
#define MdtContactGetForce(c, i, f) MdtConstraintGetForce(MdtContactQuaConstraint(c), (i), (f))
#define MdtContactGetTorque(c, i, t) MdtConstraintGetTorque(MdtContactQuaConstraint(c), (i), (t))
#define MdtContactGetUserData(c) MdtConstraintGetUserData(MdtContactQuaConstraint(c))
#define MdtContactSetUserData(c, d) MdtConstraintSetUserData(MdtContactQuaConstraint(c), (d))
#define MdtContactGetWorld(c) MdtConstraintGetWorld(MdtContactQuaConstraint(c))

/* Karma 1.2's names for the sort key. */
#define MdtContactSetSortKey(c, k) MdtConstraintSetSortKey(MdtContactQuaConstraint(c), (k))
#define MdtContactGetSortKey(c) MdtConstraintGetSortKey(MdtContactQuaConstraint(c))

ME_EXTERN_C_END

#endif /* MDT_CONTACT_H */
