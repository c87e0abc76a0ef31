/* continuous.c -- the universe's continuous-collision pass (see continuous.h and McdContinuous.h).
 *
 * The step's motion of a body is known exactly once the world has stepped: from the start pose to
 * the end pose at the constant velocities that join them (the straight path of its origin and the
 * one rotation between the orientations). McdSpaceSweepModel finds the first time the model comes
 * within half its contact tolerance of another along that path; the body is put there with its
 * velocity unchanged, so the next step's contacts (reported up to the full tolerance) stop it or
 * bounce it. The time after the impact is lost to that body (Box2D v3's choice: no sub-step). */
#include <karma/McdContinuous.h>
#include <karma/McdModel.h>
#include <karma/McdSpace.h>
#include <karma/MdtBody.h>
#include <karma/MdtContactParams.h>
#include <karma/MeMath.h>
#include <karma/MeMemory.h>
#include <karma/MstBridge.h>

#include "continuous.h"

#include <string.h>

/* Angular speeds below this (rad/s) are no rotation when the pose at the time of impact is made. */
#define MST_SWEEP_SPIN_EPS ME_R(1e-6)

static MeBool reserve(MstContinuous *c, int n)
{
    if (n <= c->capacity)
        return METRUE;
    int capacity = c->capacity ? c->capacity : 8;
    while (capacity < n)
        capacity *= 2;
    MstSweepStart *grown = MeMemoryResize(c->starts, sizeof *grown * (size_t)capacity);
    if (!grown)
        return MEFALSE;
    c->starts = grown;
    c->capacity = capacity;
    return METRUE;
}

static MeBool reserveModels(MstContinuous *c, int n)
{
    if (n <= c->modelCapacity)
        return METRUE;
    McdModelID *grown = MeMemoryResize(c->models, sizeof *grown * (size_t)n);
    if (!grown)
        return MEFALSE;
    c->models = grown;
    c->modelCapacity = n;
    return METRUE;
}

void MstContinuousBeforeStep(MstContinuous *c, McdFrameworkID fw, McdSpaceID space)
{
    c->count = 0;
    const int n = McdFrameworkGetContinuousModelCount(fw);
    if (n == 0)
        return; /* the cost without flagged models: this test */
    if (!reserve(c, n) || !reserveModels(c, n))
        return;
    McdFrameworkGetContinuousModels(fw, c->models, n);
    for (int i = 0; i < n; i++) {
        McdModelID m = c->models[i];
        MdtBodyID b = McdModelGetBody(m);
        if (!b || !MdtBodyIsEnabled(b) || McdModelGetSpace(m) != space)
            continue;
        MstSweepStart *s = &c->starts[c->count++];
        s->model = m;
        s->body = b;
        MeMatrix4Copy(s->start, MdtBodyGetTransformPtr(b));
    }
}

/* The world angular velocity (rad/s) that turns orientation r0 into r1 in h seconds (the shorter
 * way). TM rows are the body axes in world coordinates: the world rotation is M = (r0^T r1)^T. */
static void spinBetween(MeMatrix4 r0, MeMatrix4 r1, MeReal h, MeVector3 w)
{
    MeReal m[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            m[i][j] = r0[0][j] * r1[0][i] + r0[1][j] * r1[1][i] + r0[2][j] * r1[2][i];
    MeVector3 axis = {m[2][1] - m[1][2], m[0][2] - m[2][0], m[1][0] - m[0][1]}; /* 2 sin(angle) axis */
    const MeReal s2 = MeVector3Magnitude(axis), c = ME_R(0.5) * (m[0][0] + m[1][1] + m[2][2] - ME_R(1.0));
    if (s2 <= ME_R(0.0)) {
        MeVector3Set(w, 0, 0, 0);
        return;
    }
    const MeReal angle = MeAtan2(ME_R(0.5) * s2, c);
    MeVector3MultiplyScalar(w, axis, angle / (s2 * h));
}

/* A body that was touching what it hit and was driven into it all the same (the step's contacts did
 * not hold it: a spin much faster than the step resolves, a push) gets the frictionless impulse at
 * the point of the hit that reverses its approach there times the pair's restitution: the contact
 * law at that point (or at its centre of mass, below), which adds neither energy nor momentum
 * along the normal. */
static void unjam(MdtBodyID body, McdModelID model, const McdSweepResult *hit, MstBridgeID bridge)
{
    MeVector3 v, w, com, r, rxn, vp;
    MdtBodyGetLinearVelocity(body, v);
    MdtBodyGetAngularVelocity(body, w);
    MdtBodyGetCenterOfMassPosition(body, com);
    MeVector3Subtract(r, hit->position, com);
    MeVector3Cross(vp, w, r);
    MeVector3Add(vp, vp, v);
    MeReal approach = MeVector3Dot(vp, hit->normal);
    /* A body turning about the point it touches (a spin of radians per step, which the contacts
     * linearise) drives other points in while that one stands still: the impulse then goes through
     * its centre of mass, against the centre's approach. */
    const MeBool throughCentre = !(approach > ME_R(0.0));
    if (throughCentre) {
        approach = MeVector3Dot(v, hit->normal);
        MeVector3Set(r, 0, 0, 0);
    }
    if (!(approach > ME_R(0.0)))
        return;
    MeReal e = ME_R(0.0);
    MdtContactParamsID p =
        MstBridgeGetContactParams(bridge, McdModelGetMaterial(model), McdModelGetMaterial(hit->model));
    if (p && approach > MdtContactParamsGetRestitutionThreshold(p))
        e = MdtContactParamsGetRestitution(p);
    /* The inverse inertia in world axes applied to r x n: through the body frame (TM rows = axes). */
    MeMatrix3 inv;
    MdtBodyGetInertiaTensor(body, inv);
    if (!MeMatrix3Invert(inv))
        return;
    MeMatrix4Ptr tm = MdtBodyGetCenterOfMassTransformPtr(body);
    MeVector3Cross(rxn, r, hit->normal);
    MeVector3 local, turn, dw = {0, 0, 0};
    for (int i = 0; i < 3; i++)
        local[i] = MeVector3Dot(rxn, tm[i]);
    for (int i = 0; i < 3; i++)
        turn[i] = inv[i][0] * local[0] + inv[i][1] * local[1] + inv[i][2] * local[2];
    for (int i = 0; i < 3; i++)
        MeVector3ScaleAndAdd(dw, dw, turn[i], tm[i]);
    const MeReal k = ME_R(1.0) / MdtBodyGetMass(body) + MeVector3Dot(rxn, dw);
    if (!(k > ME_R(0.0)))
        return;
    const MeReal j = (ME_R(1.0) + e) * approach / k;
    MeVector3ScaleAndAdd(v, v, -j / MdtBodyGetMass(body), hit->normal);
    MeVector3ScaleAndAdd(w, w, -j, dw);
    MdtBodySetLinearVelocity(body, v[0], v[1], v[2]);
    MdtBodySetAngularVelocity(body, w[0], w[1], w[2]);
}

void MstContinuousAfterStep(MstContinuous *c, MstBridgeID bridge, MeReal stepSize)
{
    for (int i = 0; i < c->count; i++) {
        MstSweepStart *s = &c->starts[i];
        if (!MdtBodyIsValid(s->body) || !McdModelIsValid(s->model))
            continue; /* destroyed by a callback during the step */
        MeReal(*end)[4] = MdtBodyGetTransformPtr(s->body);
        MeVector3 v, w;
        for (int k = 0; k < 3; k++)
            v[k] = (end[3][k] - s->start[3][k]) / stepSize;
        spinBetween(s->start, end, stepSize, w);
        McdSweepResult hit;
        const MeReal gap = ME_R(0.5) * McdModelGetContactTolerance(s->model);
        if (!McdSpaceSweepModel(s->model, s->start, v, w, stepSize, gap, &hit) || !(hit.time < stepSize))
            continue;
        MeMatrix4 at;
        MeVector4 q;
        MeMatrix4TMUpdateFromVelocities(at, MST_SWEEP_SPIN_EPS, hit.time, v, w, s->start);
        MeQuaternionFromTM(q, at);
        MdtBodySetQuaternion(s->body, q[0], q[1], q[2], q[3]);
        MdtBodySetPosition(s->body, at[3][0], at[3][1], at[3][2]);
        if (hit.touching)
            unjam(s->body, s->model, &hit, bridge);
    }
}

void MstContinuousFree(MstContinuous *c)
{
    MeMemoryDestroy(c->starts);
    MeMemoryDestroy(c->models);
    memset(c, 0, sizeof *c);
}
