/* body.c -- the MdtBody API: lifecycle, state, mass properties and force accumulators.
 *
 * Every public function resolves its ID first (a stale or foreign ID is reported and the call does
 * nothing), then validates its numbers where they enter (NaN/inf, ranges), and only then changes
 * state: a rejected call leaves the body exactly as it was. */
#include <karma/MdtDefaults.h>
#include <stdio.h>
#include <string.h>

#include "../me/check.h"
#include "../me/handle.h"
#include <karma/MdtConstraint.h>

#include "body.h"
#include "world.h"

/* A quaternion may be off unit length by this much before it is rejected (it is renormalised). */
#define QUATERNION_TOLERANCE ME_R(1e-3)
/* Rows of a rotation matrix must be orthonormal to this tolerance. */
#define ROTATION_TOLERANCE ME_R(1e-3)
/* A mass or inertia further than this factor from the world's scale gets an info message. */
#define MASS_RANGE_LIMIT ME_R(100.0)

MdtBodyData *MdtBodyFromID(MdtBodyID id, const char *function)
{
    return MeHandleResolve((uintptr_t)id, ME_HANDLE_BODY, function, "b", NULL);
}

#define BODY_OR_RETURN(b, id, ret)                                                                   \
    MdtBodyData *b = MdtBodyFromID((id), __func__);                                                      \
    if (!b)                                                                                          \
    return ret

/* ---- internal helpers --------------------------------------------------------------------- */
void MdtBodyUpdateTransforms(MdtBodyData *b, const MeVector3 comPosition)
{
    MeMatrix3 R;
    MeVector3 offsetWorld;
    MeQuaternionToR(R, b->q);
    MeMatrix3MultiplyVector(offsetWorld, R, b->comOffset);
    MeMatrix4TMMakeIdentity(b->comTM);
    MeMatrix4TMSetRotation(b->comTM, R);
    MeMatrix4TMSetPositionVector(b->comTM, comPosition);
    MeMatrix4TMMakeIdentity(b->bodyTM);
    MeMatrix4TMSetRotation(b->bodyTM, R);
    b->bodyTM[3][0] = comPosition[0] - offsetWorld[0];
    b->bodyTM[3][1] = comPosition[1] - offsetWorld[1];
    b->bodyTM[3][2] = comPosition[2] - offsetWorld[2];
}

/* out = Rᵀ · M · R: a body-frame tensor expressed in the world (R's rows are the body axes). */
static void bodyToWorldTensor(const MdtBodyData *b, MeMatrix3 M, MeMatrix3 out)
{
    MeMatrix3 R, MR;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = b->comTM[i][j];
    MeMatrix3MultiplyMatrix(MR, M, R);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[i][j] = R[0][i] * MR[0][j] + R[1][i] * MR[1][j] + R[2][i] * MR[2][j];
}

void MdtBodyWorldInverseInertia(const MdtBodyData *b, MeMatrix3 out)
{
    MeMatrix3 inv;
    memcpy(inv, b->invInertia, sizeof inv);
    bodyToWorldTensor(b, inv, out);
}

void MdtBodyWorldInertia(const MdtBodyData *b, MeMatrix3 out)
{
    MeMatrix3 I;
    if (b->nonSpherical) {
        memcpy(I, b->inertia, sizeof I);
    } else {
        MeMatrix3MakeIdentity(I);
        MeMatrix3Scale(I, (b->inertia[0][0] + b->inertia[1][1] + b->inertia[2][2]) / 3);
    }
    bodyToWorldTensor(b, I, out);
}

/* The inverse inertia in use: the full tensor, or the mean of its diagonal when spherical. */
static void updateInverseInertia(MdtBodyData *b)
{
    b->inertiaBound = (b->inertia[0][0] + b->inertia[1][1] + b->inertia[2][2]) / 3;
    if (b->nonSpherical) /* Gershgorin: no eigenvalue exceeds the largest absolute row sum */
        for (int k = 0; k < 3; k++)
            b->inertiaBound = MeMAX(b->inertiaBound, MeFabs(b->inertia[k][0]) + MeFabs(b->inertia[k][1]) +
                                                         MeFabs(b->inertia[k][2]));
    if (b->nonSpherical) {
        /* The tensor was checked positive definite when it was set. */
        memcpy(b->invInertia, b->inertia, sizeof(MeMatrix3));
        if (!MeMatrix3SymmetricInvert(b->invInertia))
            ME_ASSERT_INTERNAL(0);
    } else {
        MeReal mean = (b->inertia[0][0] + b->inertia[1][1] + b->inertia[2][2]) / 3;
        MeMatrix3MakeIdentity(b->invInertia);
        MeMatrix3Scale(b->invInertia, 1 / mean);
    }
}

void MdtBodySetEnabledInternal(MdtBodyData *b, MeBool enabled)
{
    MdtWorldData *w = b->world;
    if (b->enabled == enabled)
        return;
    b->enabled = enabled;
    if (enabled) {
        w->enabledBodyCount++;
        b->enabledTime = 0;
        MdtBodyRestWindowRestart(b);
        if (w->bodyEnableCB)
            w->bodyEnableCB((MdtBodyID)b->id, w->bodyEnableData);
    } else {
        w->enabledBodyCount--;
        b->partition = -1;
        if (w->bodyDisableCB)
            w->bodyDisableCB((MdtBodyID)b->id, w->bodyDisableData);
    }
}

static void setDefaults(MdtBodyData *b)
{
    const MdtWorldData *w = b->world;
    MeVector3 origin = {0, 0, 0};
    MeQuaternionSet(b->q, 1, 0, 0, 0);
    MeVector3Set(b->comOffset, 0, 0, 0);
    MdtBodyUpdateTransforms(b, origin);
    MeVector3Set(b->vel, 0, 0, 0);
    MeVector3Set(b->velrot, 0, 0, 0);
    MeVector3Set(b->accel, 0, 0, 0);
    MeVector3Set(b->accelrot, 0, 0, 0);
    b->mass = MDTBODY_DEFAULT_MASS * w->massScale;
    b->invMass = 1 / b->mass;
    MeMatrix3MakeIdentity(b->inertia);
    MeMatrix3Scale(b->inertia, MDTBODY_DEFAULT_INERTIA * b->mass * w->lengthScale * w->lengthScale);
    b->nonSpherical = MEFALSE;
    b->coriolis = MEFALSE;
    updateInverseInertia(b);
    b->linearDamping = MDTBODY_DEFAULT_LINEAR_DAMPING;
    b->angularDamping = MDTBODY_DEFAULT_ANGULAR_DAMPING;
    MeVector3Set(b->fastSpinAxis, MDTBODY_DEFAULT_FAST_SPIN_X, MDTBODY_DEFAULT_FAST_SPIN_Y, MDTBODY_DEFAULT_FAST_SPIN_Z);
    b->useFastSpin = MEFALSE;
    b->sortKey = 0;
    MeVector3Set(b->force, 0, 0, 0);
    MeVector3Set(b->torque, 0, 0, 0);
    MeVector3Set(b->impulse, 0, 0, 0);
    MeVector3Set(b->angularImpulse, 0, 0, 0);
    b->enabledTime = 0;
    MdtBodyRestWindowRestart(b);
    b->partition = -1;
    b->stepIndex = -1;
    b->speedWarned = MEFALSE;
    b->energyWarned = MEFALSE;
}

/* ---- lifecycle ---------------------------------------------------------------------------- */
MdtBodyID MdtBodyCreate(MdtWorldID wid)
{
    MdtWorldData *w = MdtWorldFromID(wid, __func__);
    if (!w)
        return NULL;
    if (w->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "bodies cannot be created during the world's step");
        return NULL;
    }
    MdtBodyData *b = MePoolGetStruct(&w->bodyPool);
    if (!b) {
        ME_REPORT(ME_ERR_POOL_FULL, "the world's body pool is full (%d bodies); raise %s",
                  w->bodyPool.capacity, w->bodyPool.sizeName);
        return NULL;
    }
    b->world = w;
    b->slot = MePoolIndexOf(&w->bodyPool, b);
    b->id = MeHandleOfSlot(w->ownerSlot, ME_HANDLE_BODY, b->slot);
    setDefaults(b);
    return (MdtBodyID)b->id;
}

void MdtBodyDestroy(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    MdtWorldData *w = b->world;
    if (w->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "bodies cannot be destroyed during the world's step");
        return;
    }
    /* Its constraints go with it (as in Karma): a joint to a body that no longer exists has no meaning. */
    MdtBodyDestroyConstraints(id);
    if (b->enabled)
        w->enabledBodyCount--;
    MePoolPutStruct(&w->bodyPool, b);
}

void MdtBodyReset(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    setDefaults(b);
}

MdtBodyID MdtBodyCopy(MdtBodyID id, MdtWorldID wid)
{
    BODY_OR_RETURN(b, id, NULL);
    MdtBodyID copyId = MdtBodyCreate(wid);
    if (!copyId)
        return NULL;
    MdtBodyData *c = MdtBodyFromID(copyId, __func__);
    MdtBodyData saved = *c;
    *c = *b;
    c->id = saved.id;
    c->world = saved.world;
    c->slot = saved.slot;
    c->enabled = MEFALSE;
    c->partition = -1;
    c->stepIndex = -1;
    c->firstConstraint = NULL;
    return copyId;
}

void MdtBodyEnable(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    MdtBodySetEnabledInternal(b, METRUE);
}

void MdtBodyDisable(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    MdtBodySetEnabledInternal(b, MEFALSE);
}

MeBool MdtBodyIsEnabled(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, MEFALSE);
    return b->enabled;
}

MeBool MdtBodyIsValid(MdtBodyID id) { return MeHandleIsValid((uintptr_t)id, ME_HANDLE_BODY); }

void MdtBodyLog(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    MeInfo(0, "body %p: %s, mass %g, position (%g %g %g), q (%g %g %g %g), v (%g %g %g), w (%g %g %g)",
           (void *)id, b->enabled ? "enabled" : "disabled", (double)b->mass, (double)b->bodyTM[3][0],
           (double)b->bodyTM[3][1], (double)b->bodyTM[3][2], (double)b->q[0], (double)b->q[1], (double)b->q[2],
           (double)b->q[3], (double)b->vel[0], (double)b->vel[1], (double)b->vel[2], (double)b->velrot[0],
           (double)b->velrot[1], (double)b->velrot[2]);
}

/* ---- accessors ---------------------------------------------------------------------------- */
MdtWorldID MdtBodyGetWorld(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return (MdtWorldID)b->world->id;
}

int MdtBodyGetPartition(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, -1);
    return b->partition;
}

MeMatrix4Ptr MdtBodyGetTransformPtr(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return b->bodyTM;
}

void MdtBodyGetTransform(MdtBodyID id, MeMatrix4 m)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(m, ME_NOTHING);
    memcpy(m, b->bodyTM, sizeof(MeMatrix4));
}

void *MdtBodyGetUserData(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return b->userData;
}

void *MdtBodyGetModel(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return b->model;
}

MeReal MdtBodyGetMass(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, 0);
    return b->mass;
}

void MdtBodyGetInertiaTensor(MdtBodyID id, MeMatrix3 i)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(i, ME_NOTHING);
    memcpy(i, b->inertia, sizeof(MeMatrix3));
}

void MdtBodyGetPosition(MdtBodyID id, MeVector3 p)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    MeVector3Set(p, b->bodyTM[3][0], b->bodyTM[3][1], b->bodyTM[3][2]);
}

void MdtBodyGetQuaternion(MdtBodyID id, MeVector4 q)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(q, ME_NOTHING);
    MeVector4Copy(q, b->q);
}

void MdtBodyGetOrientation(MdtBodyID id, MeMatrix3 R)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(R, ME_NOTHING);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = b->bodyTM[i][j];
}

void MdtBodyGetLinearVelocity(MdtBodyID id, MeVector3 v)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    MeVector3Copy(v, b->vel);
}

MeReal *MdtBodyGetLinearVelocityPtr(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return b->vel;
}

void MdtBodyGetAngularVelocity(MdtBodyID id, MeVector3 v)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    MeVector3Copy(v, b->velrot);
}

MeReal *MdtBodyGetAngularVelocityPtr(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return b->velrot;
}

void MdtBodyGetVelocityAtPoint(MdtBodyID id, const MeVector3 p, MeVector3 v)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    MeVector3 r, wxr;
    MeVector3Set(r, p[0] - b->comTM[3][0], p[1] - b->comTM[3][1], p[2] - b->comTM[3][2]);
    MeVector3Cross(wxr, b->velrot, r);
    MeVector3Add(v, b->vel, wxr);
}

void MdtBodyGetLinearAcceleration(MdtBodyID id, MeVector3 a)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(a, ME_NOTHING);
    MeVector3Copy(a, b->accel);
}

void MdtBodyGetAngularAcceleration(MdtBodyID id, MeVector3 a)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(a, ME_NOTHING);
    MeVector3Copy(a, b->accelrot);
}

void MdtBodyGetFastSpinAxis(MdtBodyID id, MeVector3 v)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    MeVector3Copy(v, b->fastSpinAxis);
}

MeBool MdtBodyFastSpinAxisIsEnabled(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, MEFALSE);
    return b->useFastSpin;
}

MeReal MdtBodyGetLinearVelocityDamping(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, 0);
    return b->linearDamping;
}

MeReal MdtBodyGetAngularVelocityDamping(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, 0);
    return b->angularDamping;
}

void MdtBodyGetForce(MdtBodyID id, MeVector3 f)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(f, ME_NOTHING);
    MeVector3Copy(f, b->force);
}

void MdtBodyGetTorque(MdtBodyID id, MeVector3 t)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(t, ME_NOTHING);
    MeVector3Copy(t, b->torque);
}

MeReal MdtBodyGetKineticEnergy(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, 0);
    MeMatrix3 I;
    MeVector3 Iw;
    MdtBodyWorldInertia(b, I);
    MeMatrix3MultiplyVector(Iw, I, b->velrot);
    return ME_R(0.5) * (b->mass * MeVector3Dot(b->vel, b->vel) + MeVector3Dot(b->velrot, Iw));
}

MeReal MdtBodyGetEnabledTime(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, 0);
    return b->enabledTime;
}

void MdtBodyGetCenterOfMassRelativeTransform(MdtBodyID id, MeMatrix4 t)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(t, ME_NOTHING);
    MeMatrix4TMMakeIdentity(t);
    MeMatrix4TMSetPositionVector(t, b->comOffset);
}

void MdtBodyGetCenterOfMassPosition(MdtBodyID id, MeVector3 pos)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(pos, ME_NOTHING);
    MeVector3Set(pos, b->comTM[3][0], b->comTM[3][1], b->comTM[3][2]);
}

void MdtBodyGetCenterOfMassRelativePosition(MdtBodyID id, MeVector3 pos)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(pos, ME_NOTHING);
    MeVector3Copy(pos, b->comOffset);
}

MeMatrix4Ptr MdtBodyGetCenterOfMassTransformPtr(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return b->comTM;
}

MeI32 MdtBodyGetSortKey(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, 0);
    return b->sortKey;
}

/* ---- mutators ----------------------------------------------------------------------------- */
void MdtBodySetUserData(MdtBodyID id, void *d)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    b->userData = d;
}

void MdtBodySetModel(MdtBodyID id, void *model)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    b->model = model;
}

/* Rows orthonormal and right-handed within tolerance. */
static MeBool isRotation(MeMatrix3 R)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!ME_IS_FINITE(R[i][j]))
                return MEFALSE;
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            MeReal d = MeVector3Dot(R[i], R[j]) - (i == j ? 1 : 0);
            if (MeFabs(d) > ROTATION_TOLERANCE)
                return MEFALSE;
        }
    return MeMatrix3Determinant(R) > 0;
}

static void setOrientation(MdtBodyData *b, MeMatrix3 R)
{
    MeVector3 com;
    MeVector3Set(com, b->comTM[3][0], b->comTM[3][1], b->comTM[3][2]);
    /* Keep the body frame's origin where it is: the COM moves with the new orientation. */
    MeVector3 origin, offsetWorld;
    MeVector3Set(origin, b->bodyTM[3][0], b->bodyTM[3][1], b->bodyTM[3][2]);
    MeQuaternionFromR(b->q, R);
    MeQuaternionNormalize(b->q);
    MeMatrix3 Rn;
    MeQuaternionToR(Rn, b->q);
    MeMatrix3MultiplyVector(offsetWorld, Rn, b->comOffset);
    MeVector3Add(com, origin, offsetWorld);
    MdtBodyUpdateTransforms(b, com);
}

void MdtBodySetTransform(MdtBodyID id, MeMatrix4 tm)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(tm, ME_NOTHING);
    MeMatrix3 R;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = tm[i][j];
    ME_CHECK_FINITE3(tm[3][0], tm[3][1], tm[3][2], ME_NOTHING);
    if (!isRotation(R)) {
        ME_REPORT(ME_ERR_NOT_ROTATION, "argument 'tm' has a rotation part that is not orthonormal and "
                                       "right-handed; call ignored");
        return;
    }
    b->bodyTM[3][0] = tm[3][0];
    b->bodyTM[3][1] = tm[3][1];
    b->bodyTM[3][2] = tm[3][2];
    setOrientation(b, R);
}

/* A mass far from the world's massScale makes contacts and joints soft (their ε scales with it): warn
 * once per world, in the name of the function the application called, saying what to set. A slender
 * body's inertia is far from the scale more often, and matters less: information only. */
static void checkMassRange(MdtBodyData *b, MeReal value, MeReal scale, MeBool isMass, const char *function)
{
    MdtWorldData *w = b->world;
    MeBool *reported = isMass ? &w->massRangeReported : &w->inertiaRangeReported;
    if (*reported || !(value > MASS_RANGE_LIMIT * scale || value * MASS_RANGE_LIMIT < scale))
        return;
    *reported = METRUE;
    if (w->callerName)
        function = w->callerName;
    if (isMass)
        ME_REPORT_IN(function, ME_ERR_MASS_SCALE,
                     "mass %g kg is over %g times away from the world's massScale %g kg: contacts and joints "
                     "will be soft and bodies sink into what they rest on; set %s to a typical mass of the "
                     "scene (reported once per world)", (double)value, (double)MASS_RANGE_LIMIT, (double)scale,
                     w->massScaleName);
    else
        ME_REPORT_IN(function, ME_ERR_MASS_RATIO,
                     "inertia %g is over %g times away from the world's scale %g (0.4 massScale lengthScale²): "
                     "expect poor accuracy; set %s to a typical mass of the scene (reported once per world)",
                     (double)value, (double)MASS_RANGE_LIMIT, (double)scale, w->massScaleName);
}

void MdtBodySetMass(MdtBodyID id, MeReal mass)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE(mass, ME_NOTHING);
    if (!(mass > 0)) {
        ME_REPORT(ME_ERR_MASS_NOT_POSITIVE, "argument 'mass' (%g) must be positive; call ignored", (double)mass);
        return;
    }
    checkMassRange(b, mass, b->world->massScale, METRUE, __func__);
    b->mass = mass;
    b->invMass = 1 / mass;
}

MeBool MdtInertiaTensorIsValid(MeMatrix3 I)
{
    ME_CHECK_NOT_NULL(I, MEFALSE);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (!ME_IS_FINITE(I[i][j]))
                return MEFALSE;
    MeReal scale = MeFabs(I[0][0]) + MeFabs(I[1][1]) + MeFabs(I[2][2]);
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (MeFabs(I[i][j] - I[j][i]) > ME_R(1e-4) * scale)
                return MEFALSE;
    MeReal m1 = I[0][0];
    MeReal m2 = I[0][0] * I[1][1] - I[0][1] * I[1][0];
    return m1 > 0 && m2 > 0 && MeMatrix3Determinant(I) > 0;
}

void MdtBodySetInertiaTensor(MdtBodyID id, MeMatrix3 i)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(i, ME_NOTHING);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            ME_CHECK_FINITE(i[r][c], ME_NOTHING);
    if (!MdtInertiaTensorIsValid(i)) {
        ME_REPORT(ME_ERR_INERTIA_INVALID, "argument 'i' is not a symmetric positive definite tensor; call ignored");
        return;
    }
    MeReal l = b->world->lengthScale;
    checkMassRange(b, (i[0][0] + i[1][1] + i[2][2]) / 3, ME_R(0.4) * b->world->massScale * l * l, MEFALSE,
                   __func__);
    /* Store it exactly symmetric. */
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            b->inertia[r][c] = ME_R(0.5) * (i[r][c] + i[c][r]);
    updateInverseInertia(b);
}

void MdtBodySetSphericalInertiaTensor(MdtBodyID id, MeReal i)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE(i, ME_NOTHING);
    if (!(i > 0)) {
        ME_REPORT(ME_ERR_INERTIA_INVALID, "argument 'i' (%g) must be positive; call ignored", (double)i);
        return;
    }
    MeMatrix3MakeIdentity(b->inertia);
    MeMatrix3Scale(b->inertia, i);
    updateInverseInertia(b);
}

void MdtBodySetPosition(MdtBodyID id, MeReal x, MeReal y, MeReal z)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    MeVector3 offsetWorld, com;
    MeMatrix3 R;
    MeQuaternionToR(R, b->q);
    MeMatrix3MultiplyVector(offsetWorld, R, b->comOffset);
    MeVector3Set(com, x + offsetWorld[0], y + offsetWorld[1], z + offsetWorld[2]);
    MdtBodyUpdateTransforms(b, com);
}

void MdtBodySetOrientation(MdtBodyID id, MeMatrix3 R)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(R, ME_NOTHING);
    if (!isRotation(R)) {
        ME_REPORT(ME_ERR_NOT_ROTATION, "argument 'R' is not orthonormal and right-handed; call ignored");
        return;
    }
    setOrientation(b, R);
}

void MdtBodySetQuaternion(MdtBodyID id, MeReal qw, MeReal qx, MeReal qy, MeReal qz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE(qw, ME_NOTHING);
    ME_CHECK_FINITE3(qx, qy, qz, ME_NOTHING);
    MeReal norm = MeSqrt(qw * qw + qx * qx + qy * qy + qz * qz);
    if (MeFabs(norm - 1) > QUATERNION_TOLERANCE) {
        ME_REPORT(ME_ERR_QUATERNION_NOT_UNIT,
                  "the quaternion (%g, %g, %g, %g) has length %g, not 1 within %g; call ignored", (double)qw,
                  (double)qx, (double)qy, (double)qz, (double)norm, (double)QUATERNION_TOLERANCE);
        return;
    }
    MeVector3 origin, offsetWorld, com;
    MeVector3Set(origin, b->bodyTM[3][0], b->bodyTM[3][1], b->bodyTM[3][2]);
    MeQuaternionSet(b->q, qw / norm, qx / norm, qy / norm, qz / norm);
    MeMatrix3 R;
    MeQuaternionToR(R, b->q);
    MeMatrix3MultiplyVector(offsetWorld, R, b->comOffset);
    MeVector3Add(com, origin, offsetWorld);
    MdtBodyUpdateTransforms(b, com);
}

void MdtBodySetLinearVelocity(MdtBodyID id, MeReal dx, MeReal dy, MeReal dz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(dx, dy, dz, ME_NOTHING);
    MeVector3Set(b->vel, dx, dy, dz);
    MdtBodyRestWindowRestart(b); /* its motion so far no longer says whether it is at rest */
}

void MdtBodySetAngularVelocity(MdtBodyID id, MeReal wx, MeReal wy, MeReal wz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(wx, wy, wz, ME_NOTHING);
    MeVector3Set(b->velrot, wx, wy, wz);
    MdtBodyRestWindowRestart(b);
}

static MeBool checkDamping(MeReal d, const char *function)
{
    ME_CHECK_FINITE_IN(function, d, MEFALSE);
    if (d < 0) {
        ME_REPORT_IN(function, ME_ERR_NEGATIVE_DAMPING, "argument 'd' (%g) must not be negative; call ignored",
                     (double)d);
        return MEFALSE;
    }
    return METRUE;
}

void MdtBodySetLinearVelocityDamping(MdtBodyID id, MeReal d)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    if (checkDamping(d, __func__))
        b->linearDamping = d;
}

void MdtBodySetAngularVelocityDamping(MdtBodyID id, MeReal d)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    if (checkDamping(d, __func__))
        b->angularDamping = d;
}

void MdtBodySetFastSpinAxis(MdtBodyID id, MeReal x, MeReal y, MeReal z)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    MeReal len = MeSqrt(x * x + y * y + z * z);
    if (!(len > ME_SMALL_EPSILON)) {
        ME_REPORT(ME_ERR_ZERO_AXIS, "the fast-spin axis (%g, %g, %g) has zero length; call ignored", (double)x,
                  (double)y, (double)z);
        return;
    }
    MeVector3Set(b->fastSpinAxis, x / len, y / len, z / len);
    b->useFastSpin = METRUE;
}

void MdtBodySetNoFastSpinAxis(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    b->useFastSpin = MEFALSE;
}

void MdtBodyEnableNonSphericalInertia(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    b->nonSpherical = METRUE;
    updateInverseInertia(b);
}

void MdtBodyDisableNonSphericalInertia(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    b->nonSpherical = MEFALSE;
    updateInverseInertia(b);
}

MeBool MdtBodyNonSphericalInertiaIsEnabled(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, MEFALSE);
    return b->nonSpherical;
}

void MdtBodyEnableCoriolisForce(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    b->coriolis = METRUE;
}

void MdtBodyDisableCoriolisForce(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    b->coriolis = MEFALSE;
}

MeBool MdtBodyCoriolisForceIsEnabled(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, MEFALSE);
    return b->coriolis;
}

/* Move the COM within the body: the body frame stays put, the COM frame follows. */
static void setComOffset(MdtBodyData *b, const MeVector3 offset)
{
    MeVector3 origin, offsetWorld, com;
    MeMatrix3 R;
    MeVector3Set(origin, b->bodyTM[3][0], b->bodyTM[3][1], b->bodyTM[3][2]);
    MeVector3Copy(b->comOffset, offset);
    MeQuaternionToR(R, b->q);
    MeMatrix3MultiplyVector(offsetWorld, R, b->comOffset);
    MeVector3Add(com, origin, offsetWorld);
    MdtBodyUpdateTransforms(b, com);
}

void MdtBodySetCenterOfMassRelativePosition(MdtBodyID id, const MeVector3 pos)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(pos, ME_NOTHING);
    ME_CHECK_FINITE3(pos[0], pos[1], pos[2], ME_NOTHING);
    setComOffset(b, pos);
}

void MdtBodySetCenterOfMassPosition(MdtBodyID id, const MeVector3 pos)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(pos, ME_NOTHING);
    ME_CHECK_FINITE3(pos[0], pos[1], pos[2], ME_NOTHING);
    MeVector3 rel, local;
    MeMatrix3 R;
    MeVector3Set(rel, pos[0] - b->bodyTM[3][0], pos[1] - b->bodyTM[3][1], pos[2] - b->bodyTM[3][2]);
    MeQuaternionToR(R, b->q);
    MeMatrix3TransposeMultiplyVector(local, R, rel);
    setComOffset(b, local);
}

void MdtBodySetCenterOfMassRelativeTransform(MdtBodyID id, MeMatrix4 t)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(t, ME_NOTHING);
    ME_CHECK_FINITE3(t[3][0], t[3][1], t[3][2], ME_NOTHING);
    MeVector3 offset;
    MeVector3Set(offset, t[3][0], t[3][1], t[3][2]);
    setComOffset(b, offset);
}

void MdtBodySetSortKey(MdtBodyID id, MeI32 key)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    if (key < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'key' (%ld) must lie in 0 ... 2^31-1", (long)key);
        return;
    }
    b->sortKey = key;
}

/* ---- iteration ---------------------------------------------------------------------------- */
static MdtBodyID nextLive(MdtWorldData *w, int from)
{
    for (int i = from; i < w->bodyPool.capacity; i++)
        if (MePoolSlotIsLive(&w->bodyPool, i))
            return (MdtBodyID)MeHandleOfSlot(w->ownerSlot, ME_HANDLE_BODY, i);
    return NULL;
}

MdtBodyID MdtBodyGetFirst(MdtWorldID wid)
{
    MdtWorldData *w = MdtWorldFromID(wid, __func__);
    return w ? nextLive(w, 0) : NULL;
}

MdtBodyID MdtBodyGetNext(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, NULL);
    return nextLive(b->world, b->slot + 1);
}

/* ---- forces ------------------------------------------------------------------------------- */
void MdtBodyResetForces(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    MeVector3Set(b->force, 0, 0, 0);
    MeVector3Set(b->torque, 0, 0, 0);
}

void MdtBodyResetImpulses(MdtBodyID id)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    MeVector3Set(b->impulse, 0, 0, 0);
    MeVector3Set(b->angularImpulse, 0, 0, 0);
}

void MdtBodyAddForce(MdtBodyID id, MeReal fx, MeReal fy, MeReal fz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(fx, fy, fz, ME_NOTHING);
    b->force[0] += fx;
    b->force[1] += fy;
    b->force[2] += fz;
}

/* Adds v to `linear` and (p − com) × v to `angular`. */
static void addAtPosition(MdtBodyData *b, MeVector3 linear, MeVector3 angular, const MeVector3 v, const MeVector3 p)
{
    MeVector3 r, rxv;
    MeVector3Set(r, p[0] - b->comTM[3][0], p[1] - b->comTM[3][1], p[2] - b->comTM[3][2]);
    MeVector3Cross(rxv, r, v);
    MeVector3Add(linear, linear, v);
    MeVector3Add(angular, angular, rxv);
}

/* Size: Karma 1.2's signature. */
void MdtBodyAddForceAtPosition(MdtBodyID id, MeReal fx, MeReal fy, MeReal fz, MeReal px, MeReal py, MeReal pz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(fx, fy, fz, ME_NOTHING);
    ME_CHECK_FINITE3(px, py, pz, ME_NOTHING);
    MeVector3 f = {fx, fy, fz}, p = {px, py, pz};
    addAtPosition(b, b->force, b->torque, f, p);
}

void MdtBodyAddTorque(MdtBodyID id, MeReal tx, MeReal ty, MeReal tz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(tx, ty, tz, ME_NOTHING);
    b->torque[0] += tx;
    b->torque[1] += ty;
    b->torque[2] += tz;
}

void MdtBodyAddImpulse(MdtBodyID id, MeReal ix, MeReal iy, MeReal iz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(ix, iy, iz, ME_NOTHING);
    b->impulse[0] += ix;
    b->impulse[1] += iy;
    b->impulse[2] += iz;
}

/* Size: Karma 1.2's signature. */
void MdtBodyAddImpulseAtPosition(MdtBodyID id, MeReal ix, MeReal iy, MeReal iz, MeReal px, MeReal py, MeReal pz)
{
    BODY_OR_RETURN(b, id, ME_NOTHING);
    ME_CHECK_FINITE3(ix, iy, iz, ME_NOTHING);
    ME_CHECK_FINITE3(px, py, pz, ME_NOTHING);
    MeVector3 j = {ix, iy, iz}, p = {px, py, pz};
    addAtPosition(b, b->impulse, b->angularImpulse, j, p);
}

/* ---- utilities ---------------------------------------------------------------------------- */
void MdtMakeInertiaTensorSphere(MeReal mass, MeReal radius, MeMatrix3 i)
{
    ME_CHECK_NOT_NULL(i, ME_NOTHING);
    MeMatrix3MakeIdentity(i);
    MeMatrix3Scale(i, ME_R(0.4) * mass * radius * radius);
}

void MdtMakeInertiaTensorBox(MeReal mass, MeReal dx, MeReal dy, MeReal dz, MeMatrix3 i)
{
    ME_CHECK_NOT_NULL(i, ME_NOTHING);
    MeReal k = mass / 12;
    memset(i, 0, sizeof(MeMatrix3));
    i[0][0] = k * (dy * dy + dz * dz);
    i[1][1] = k * (dx * dx + dz * dz);
    i[2][2] = k * (dx * dx + dy * dy);
}

void MdtConvertVector(MdtBodyID from, const MeVector3 v, MdtBodyID to, MeVector3 out)
{
    MeVector3 world;
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    ME_CHECK_NOT_NULL(out, ME_NOTHING);
    MeVector3Copy(world, v);
    if (from) {
        BODY_OR_RETURN(f, from, ME_NOTHING);
        MeMatrix4TMRotate(world, f->bodyTM, v);
    }
    if (to) {
        BODY_OR_RETURN(t, to, ME_NOTHING);
        MeMatrix4TMInverseRotate(out, t->bodyTM, world);
    } else {
        MeVector3Copy(out, world);
    }
}

void MdtConvertPositionVector(MdtBodyID from, const MeVector3 v, MdtBodyID to, MeVector3 out)
{
    MeVector3 world;
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    ME_CHECK_NOT_NULL(out, ME_NOTHING);
    MeVector3Copy(world, v);
    if (from) {
        BODY_OR_RETURN(f, from, ME_NOTHING);
        MeMatrix4TMTransform(world, f->bodyTM, v);
    }
    if (to) {
        BODY_OR_RETURN(t, to, ME_NOTHING);
        MeMatrix4TMInverseTransform(out, t->bodyTM, world);
    } else {
        MeVector3Copy(out, world);
    }
}
