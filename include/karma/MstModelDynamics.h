/* MstModelDynamics.h -- a collision model's dynamics body: linking, resetting, and Karma 1.2's
 * shortcuts that act on the body of a model (McdModelDynamics...). Each shortcut is the MdtBody call
 * on McdModelGetBody(m); a model without a body gives a NULL body ID, which the MdtBody function
 * reports (ME_ERR_NULL_ARGUMENT) and ignores. */
#ifndef MST_MODEL_DYNAMICS_H
#define MST_MODEL_DYNAMICS_H

#include "McdTypes.h"
#include "MdtBody.h"
#include "MdtTypes.h"

ME_EXTERN_C_BEGIN

/** Link a model to a body (NULL: the model is part of the world). The model's transform pointer
 *  becomes the body's transform. */
ME_API void McdModelSetBody(McdModelID model, MdtBodyID body);
/** The body linked by McdModelSetBody (not owned by the model), or NULL for a world part or an invalid ID. */
ME_API MdtBodyID McdModelGetBody(McdModelID model);

/** Put the model's body back at the origin with the identity orientation and no velocity (the User
 *  Guide's "Resetting"); a model without a body is reported (ME_ERR_BAD_STATE). */
ME_API void McdModelDynamicsReset(McdModelID model);

/* Shortcuts onto the model's body. */
#define McdModelDynamicsEnable(m) MdtBodyEnable(McdModelGetBody(m))
#define McdModelDynamicsDisable(m) MdtBodyDisable(McdModelGetBody(m))
#define McdModelDynamicsIsEnabled(m) MdtBodyIsEnabled(McdModelGetBody(m))
#define McdModelDynamicsSetTransform(m, tm) MdtBodySetTransform(McdModelGetBody(m), (tm))
#define McdModelDynamicsSetPosition(m, x, y, z) MdtBodySetPosition(McdModelGetBody(m), (x), (y), (z))
#define McdModelDynamicsSetQuaternion(m, qw, qx, qy, qz)                                               \
    MdtBodySetQuaternion(McdModelGetBody(m), (qw), (qx), (qy), (qz))
#define McdModelDynamicsSetLinearVelocity(m, vx, vy, vz)                                               \
    MdtBodySetLinearVelocity(McdModelGetBody(m), (vx), (vy), (vz))
#define McdModelDynamicsSetAngularVelocity(m, wx, wy, wz)                                              \
    MdtBodySetAngularVelocity(McdModelGetBody(m), (wx), (wy), (wz))
/** Linear and angular velocity damping of the model's body. */
ME_API void McdModelDynamicsSetDamping(McdModelID model, MeReal linearDamping, MeReal angularDamping);
#define McdModelDynamicsGetPosition(m, p) MdtBodyGetPosition(McdModelGetBody(m), (p))
#define McdModelDynamicsGetQuaternion(m, q) MdtBodyGetQuaternion(McdModelGetBody(m), (q))
#define McdModelDynamicsGetLinearVelocity(m, v) MdtBodyGetLinearVelocity(McdModelGetBody(m), (v))
#define McdModelDynamicsGetAngularVelocity(m, w) MdtBodyGetAngularVelocity(McdModelGetBody(m), (w))
#define McdModelDynamicsAddForce(m, fx, fy, fz) MdtBodyAddForce(McdModelGetBody(m), (fx), (fy), (fz))
#define McdModelDynamicsGetForce(m, f) MdtBodyGetForce(McdModelGetBody(m), (f))
#define McdModelDynamicsAddTorque(m, tx, ty, tz) MdtBodyAddTorque(McdModelGetBody(m), (tx), (ty), (tz))
#define McdModelDynamicsGetTorque(m, t) MdtBodyGetTorque(McdModelGetBody(m), (t))

ME_EXTERN_C_END

#endif /* MST_MODEL_DYNAMICS_H */
