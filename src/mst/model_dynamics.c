/* model_dynamics.c -- the McdModelDynamics functions that are more than a shortcut (MstModelDynamics.h). */
#include <karma/MdtBody.h>
#include <karma/McdModel.h>
#include <karma/MstModelDynamics.h>

#include "../me/check.h"

/* The model's body, or NULL, reported in `function`'s name, when the model has none (a bad model
 * ID is reported by McdModelGetBody). */
static MdtBodyID bodyOf(McdModelID model, const char *function)
{
    MdtBodyID body = McdModelGetBody(model);
    if (!body && McdModelIsValid(model))
        ME_REPORT_IN(function, ME_ERR_BAD_STATE, "the model has no dynamics body; call ignored");
    return body;
}

void McdModelDynamicsReset(McdModelID model)
{
    MdtBodyID body = bodyOf(model, __func__);
    if (!body)
        return;
    MdtBodySetPosition(body, 0, 0, 0);
    MdtBodySetQuaternion(body, 1, 0, 0, 0);
    MdtBodySetLinearVelocity(body, 0, 0, 0);
    MdtBodySetAngularVelocity(body, 0, 0, 0);
}

void McdModelDynamicsSetDamping(McdModelID model, MeReal linearDamping, MeReal angularDamping)
{
    MdtBodyID body = bodyOf(model, __func__);
    if (!body)
        return;
    MdtBodySetLinearVelocityDamping(body, linearDamping);
    MdtBodySetAngularVelocityDamping(body, angularDamping);
}
