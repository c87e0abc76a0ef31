/* MdtConstraint.h -- what every constraint (joint, contact, contact group) has in common.
 *
 * A constraint joins body 0 to body 1, or body 0 to the world when body 1 is NULL. It is created
 * disabled by Mdt<Type>Create(world), attached with MdtConstraintSetBodies, placed with positions
 * and axes (set the bodies first: positions and axes given in world coordinates are converted into
 * each body's frame at the moment they are set, and move with the bodies afterwards), and enabled.
 * Each type's own functions are named Mdt<Type><Verb>; the common ones below work on the
 * MdtConstraintID that Mdt<Type>QuaConstraint returns.
 *
 * After each step the constraint knows the force and torque it applied to each body (world frame,
 * torque about the body's centre of mass), for breakage, sound or damage. */
#ifndef MDT_CONSTRAINT_H
#define MDT_CONSTRAINT_H

#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/* ---- lifecycle ---------------------------------------------------------------------------- */
/** Destroy a constraint (a contact group destroys its contacts too). */
ME_API void MdtConstraintDestroy(MdtConstraintID c);
/** Include the constraint in the next step; one with no body yet refused (ME_ERR_BAD_STATE). */
ME_API void MdtConstraintEnable(MdtConstraintID c);
/** Leave the constraint out of the step (its force and torque are cleared); invalid ID refused. */
ME_API void MdtConstraintDisable(MdtConstraintID c);
/** Whether the constraint takes part in the step; MEFALSE for an invalid ID. */
ME_API MeBool MdtConstraintIsEnabled(MdtConstraintID c);
/** Whether `c` is a live constraint ID (no message). */
ME_API MeBool MdtConstraintIsValid(MdtConstraintID c);
/** The constraint's type, or -1 for an invalid ID. */
ME_API int MdtConstraintGetType(MdtConstraintID c);
/** Type name ("Hinge", "ContactGroup"...). */
ME_API const char *MdtConstraintGetTypeName(MdtConstraintID c);

/* ---- accessors ---------------------------------------------------------------------------- */
/** Body 0 or 1 (NULL = the world). */
ME_API MdtBodyID MdtConstraintGetBody(MdtConstraintID c, unsigned int bodyindex);
/** The application pointer of MdtConstraintSetUserData (not owned by Karma); NULL if none. */
ME_API void *MdtConstraintGetUserData(MdtConstraintID c);
/** The world that owns the constraint; NULL for an invalid ID (ME_ERR_INVALID_HANDLE). */
ME_API MdtWorldID MdtConstraintGetWorld(MdtConstraintID c);
/** Force (N) and torque (N·m, about the COM) the constraint applied to body `bodyindex` during the
 *  last step, world frame. Zero before the first step and for a disabled constraint. */
ME_API void MdtConstraintGetForce(MdtConstraintID c, unsigned int bodyindex, MeVector3 f);
/** Torque (N·m, about the COM, world frame) applied to body bodyindex in the last step; NULL t refused. */
ME_API void MdtConstraintGetTorque(MdtConstraintID c, unsigned int bodyindex, MeVector3 t);
/** Attachment point on body 0, world frame. */
ME_API void MdtConstraintGetPosition(MdtConstraintID c, MeVector3 p);
/** Attachment point on a body, world frame / that body's frame. */
ME_API void MdtConstraintBodyGetPosition(MdtConstraintID c, unsigned int bodyindex, MeVector3 p);
/** Attachment point on body bodyindex in that body's frame (m); NULL p or index > 1 refused. */
ME_API void MdtConstraintBodyGetPositionRel(MdtConstraintID c, unsigned int bodyindex, MeVector3 p);
/** Primary axis of a body's constraint frame, world frame. */
ME_API void MdtConstraintBodyGetAxis(MdtConstraintID c, unsigned int bodyindex, MeVector3 a);
/** Primary and orthogonal axes of body 0's frame, world frame. */
ME_API void MdtConstraintGetAxes(MdtConstraintID c, MeVector3 p, MeVector3 o);
/** Primary and orthogonal axes of body bodyindex's constraint frame, world frame; NULL or index > 1 refused. */
ME_API void MdtConstraintBodyGetAxes(MdtConstraintID c, unsigned int bodyindex, MeVector3 p, MeVector3 o);
/** The same axes in body bodyindex's own frame; NULL p, o or index > 1 (ME_ERR_BODY_INDEX) refused. */
ME_API void MdtConstraintBodyGetAxesRel(MdtConstraintID c, unsigned int bodyindex, MeVector3 p, MeVector3 o);
/** The constraint's determinism order key; 0 for an invalid ID. */
ME_API MeI32 MdtConstraintGetSortKey(MdtConstraintID c);
/** Rows the constraint added to the solver in the last step. */
ME_API int MdtConstraintGetRowCount(MdtConstraintID c);
/** Velocity of the world at the attachment (m/s); NULL lv refused (ME_ERR_NULL_ARGUMENT). */
ME_API void MdtConstraintGetWorldLinearVelocity(MdtConstraintID c, MeVector3 lv);
/** Angular velocity of the world at the attachment (rad/s); NULL av refused. */
ME_API void MdtConstraintGetWorldAngularVelocity(MdtConstraintID c, MeVector3 av);

/* Karma's old names. */
#define MdtConstraintGetAxis(c, a) MdtConstraintBodyGetAxis((c), 1, (a))
#define MdtConstraintGetBothAxes(c, p, o) MdtConstraintGetAxes((c), (p), (o))
#define MdtConstraintBodyGetBothAxes(c, b, p, o) MdtConstraintBodyGetAxes((c), (b), (p), (o))

/* ---- mutators ----------------------------------------------------------------------------- */
/** Attach to bodies b1 (body 0, required) and b2 (body 1; NULL = the world). Positions and axes
 *  keep the values they hold in each body's frame, so set them after attaching (the world-frame
 *  setters convert with the new bodies' current poses). Disable the constraint before changing
 *  the bodies of an enabled one. */
ME_API void MdtConstraintSetBodies(MdtConstraintID c, MdtBodyID b1, MdtBodyID b2);
/** Attach an application pointer (not owned, never freed by Karma); invalid ID refused. */
ME_API void MdtConstraintSetUserData(MdtConstraintID c, void *d);
/** Attachment point in world coordinates, for both bodies. */
ME_API void MdtConstraintSetPosition(MdtConstraintID c, MeReal x, MeReal y, MeReal z);
/** Attachment point on one body, world coordinates / that body's frame. */
ME_API void MdtConstraintBodySetPosition(MdtConstraintID c, unsigned int bodyindex, MeReal x, MeReal y, MeReal z);
/** Attachment point on body bodyindex, in its frame (m); NaN or infinite, index > 1 (ME_ERR_BODY_INDEX) refused. */
ME_API void MdtConstraintBodySetPositionRel(MdtConstraintID c, unsigned int bodyindex, MeReal x, MeReal y,
                                            MeReal z);
/** Primary axis in world coordinates, for both bodies (an orthogonal axis is chosen). */
ME_API void MdtConstraintSetAxis(MdtConstraintID c, MeReal px, MeReal py, MeReal pz);
/** Primary and orthogonal axes in world coordinates, for both bodies. The orthogonal axis is made
 *  exactly perpendicular to the primary. */
ME_API void MdtConstraintSetAxes(MdtConstraintID c, MeReal px, MeReal py, MeReal pz, MeReal ox, MeReal oy,
                                 MeReal oz);
/** Primary and orthogonal axes of body bodyindex's frame, world coordinates; NaN or index > 1 refused. */
ME_API void MdtConstraintBodySetAxes(MdtConstraintID c, unsigned int bodyindex, MeReal px, MeReal py, MeReal pz,
                                     MeReal ox, MeReal oy, MeReal oz);
/** Primary and orthogonal axes of body bodyindex's frame, in its frame; NaN or index > 1 refused. */
ME_API void MdtConstraintBodySetAxesRel(MdtConstraintID c, unsigned int bodyindex, MeReal px, MeReal py,
                                        MeReal pz, MeReal ox, MeReal oy, MeReal oz);
/** Order key for determinism (0 ... 2^31−1). */
ME_API void MdtConstraintSetSortKey(MdtConstraintID c, MeI32 key);
/** Velocity of the world at the attachment (a joint to a moving platform): the constraint holds
 *  body 0 relative to a world frame moving at this linear / angular velocity. */
ME_API void MdtConstraintSetWorldLinearVelocity(MdtConstraintID c, MeReal vx, MeReal vy, MeReal vz);
/** Angular velocity of the world at the attachment (rad/s); NaN or infinite refused. */
ME_API void MdtConstraintSetWorldAngularVelocity(MdtConstraintID c, MeReal ax, MeReal ay, MeReal az);

#define MdtConstraintSetBothAxis(c, px, py, pz, ox, oy, oz) MdtConstraintSetAxes((c), (px), (py), (pz), (ox), (oy), (oz))
#define MdtConstraintBodySetBothAxis(c, b, px, py, pz, ox, oy, oz)                                     \
    MdtConstraintBodySetAxes((c), (b), (px), (py), (pz), (ox), (oy), (oz))

/* ---- iteration ---------------------------------------------------------------------------- */
/** Constraints of a world in slot order (contacts inside groups are reached through their group). */
ME_API MdtConstraintID MdtConstraintGetFirst(MdtWorldID w);
/** The constraint after c in slot order (contacts in groups skipped), or NULL after the last. */
ME_API MdtConstraintID MdtConstraintGetNext(MdtConstraintID c);
/** Call cb(constraint, ccbdata) for each constraint of the world in slot order; NULL cb refused. */
ME_API void MdtWorldForAllConstraints(MdtWorldID w, MdtConstraintIteratorCBPtr cb, void *ccbdata);
/** Constraints attached to a body. */
ME_API MdtConstraintID MdtBodyGetFirstConstraint(MdtBodyID b);
/** The constraint after c among those attached to b, or NULL after the last (or for a bad ID). */
ME_API MdtConstraintID MdtBodyGetNextConstraint(MdtBodyID b, MdtConstraintID c);
/** Call cb(constraint, ccbdata) for each constraint attached to b; NULL cb refused. */
ME_API void MdtBodyForAllConstraints(MdtBodyID b, MdtConstraintIteratorCBPtr cb, void *ccbdata);
/** Disable every constraint attached to the body (contact groups included). */
ME_API void MdtBodyDisableConstraints(MdtBodyID b);
/** Destroy every constraint attached to the body (contact groups included). */
ME_API void MdtBodyDestroyConstraints(MdtBodyID b);
/** Only the contact groups attached to the body. */
ME_API void MdtBodyDisableContacts(MdtBodyID b);
/** Destroy only the contact groups attached to the body (and their contacts). */
ME_API void MdtBodyDestroyContacts(MdtBodyID b);

ME_EXTERN_C_END

#endif /* MDT_CONSTRAINT_H */
