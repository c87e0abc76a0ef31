/* constraint.c -- the API common to every constraint (MdtConstraint.h) and the bookkeeping behind it:
 * creation in the world's pool, checked IDs, attachment to bodies (each body keeps a singly linked
 * list of its constraints, which the partitioner walks), constraint frames, outputs, iteration. */
#include <string.h>

#include "../me/check.h"
#include "../me/handle.h"
#include "constraint.h"
#include "world.h"

/* ---- lookup ------------------------------------------------------------------------------- */
MdtConstraintData *MdtConstraintFromID(MdtConstraintID id, const char *function)
{
    return MeHandleResolve((uintptr_t)id, ME_HANDLE_CONSTRAINT, function, "c", NULL);
}

MdtConstraintData *MdtConstraintFromIDOfType(const void *id, MdtBclJointType type, const char *function)
{
    MdtConstraintData *c = MeHandleResolve((uintptr_t)id, ME_HANDLE_CONSTRAINT, function, "c", NULL);
    if (c && c->type != type) {
        ME_REPORT_IN(function, ME_ERR_WRONG_HANDLE_KIND, "the constraint is a %s, not the type this function takes",
                     c->cls->name);
        return NULL;
    }
    return c;
}

#define CONSTRAINT_OR_RETURN(c, id, ret)                                                             \
    MdtConstraintData *c = MdtConstraintFromID((id), __func__);                                          \
    if (!c)                                                                                          \
    return ret

static MeBool checkBodyIndex(unsigned int bodyindex, const char *function)
{
    if (bodyindex > 1) {
        ME_REPORT_IN(function, ME_ERR_BODY_INDEX, "argument 'bodyindex' is %u; it must be 0 or 1", bodyindex);
        return MEFALSE;
    }
    return METRUE;
}

/* ---- body lists --------------------------------------------------------------------------- */
static void unlinkFromBody(MdtConstraintData *c, int index)
{
    MdtBodyData *b = c->body[index];
    if (!b)
        return;
    MdtConstraintData **link = (MdtConstraintData **)&b->firstConstraint;
    while (*link) {
        MdtConstraintData *it = *link;
        int which = it->body[0] == b ? 0 : 1;
        if (it == c) {
            *link = it->nextForBody[which];
            break;
        }
        link = &it->nextForBody[which];
    }
    c->nextForBody[index] = NULL;
}

static void linkToBody(MdtConstraintData *c, int index)
{
    MdtBodyData *b = c->body[index];
    if (!b)
        return;
    c->nextForBody[index] = b->firstConstraint;
    b->firstConstraint = c;
}

void MdtConstraintAttach(MdtConstraintData *c, MdtBodyData *b0, MdtBodyData *b1)
{
    if (!c->inGroup) {
        unlinkFromBody(c, 0);
        unlinkFromBody(c, 1);
    }
    c->body[0] = b0;
    c->body[1] = b1;
    if (!c->inGroup) {
        linkToBody(c, 0);
        linkToBody(c, 1);
    }
}

/* ---- creation and destruction ------------------------------------------------------------- */
void MdtConstraintResetFrames(MdtConstraintData *c)
{
    for (int i = 0; i < 2; i++) {
        MeVector3Set(c->position[i], 0, 0, 0);
        MeVector3Set(c->primary[i], 1, 0, 0);
        MeVector3Set(c->orthogonal[i], 0, 1, 0);
    }
}

/* `once`: NULL reports every full pool (a call of the application's); else the flag of a cause that
 * recurs every step (the bridge's contacts), reported once and counted after. */
static MdtConstraintData *create(MdtWorldID wid, MdtBclJointType type, const MdtConstraintClass *cls,
                                 const char *function, MeBool *once)
{
    MdtWorldData *w = MdtWorldFromID(wid, function);
    if (!w)
        return NULL;
    if (w->locked) {
        ME_REPORT_IN(function, ME_ERR_WORLD_LOCKED, "constraints cannot be created during the world's step");
        return NULL;
    }
    MdtConstraintData *c = MePoolGetStruct(&w->constraintPool);
    if (!c && once) {
        ME_REPORT_ONCE_IN(once, function, ME_ERR_POOL_FULL,
                          "the world's constraint pool is full (%d joints, contacts and groups): contacts are "
                          "being dropped, so bodies may pass through each other; raise %s (later drops are "
                          "counted, not reported)", w->constraintPool.capacity, w->constraintPool.sizeName);
        return NULL;
    }
    if (!c) {
        ME_REPORT_IN(function, ME_ERR_POOL_FULL,
                     "the world's constraint pool is full (%d joints, contacts and groups); raise %s",
                     w->constraintPool.capacity, w->constraintPool.sizeName);
        return NULL;
    }
    c->world = w;
    c->slot = MePoolIndexOf(&w->constraintPool, c);
    c->id = MeHandleOfSlot(w->ownerSlot, ME_HANDLE_CONSTRAINT, c->slot);
    c->type = type;
    c->cls = cls;
    c->rowStart = -1;
    c->partition = -1;
    MdtConstraintResetFrames(c);
    cls->reset(c);
    return c;
}

MdtConstraintData *MdtConstraintCreateInternal(MdtWorldID wid, MdtBclJointType type, const MdtConstraintClass *cls,
                                           const char *function)
{
    return create(wid, type, cls, function, NULL);
}

MdtConstraintData *MdtConstraintCreateForContacts(MdtWorldID wid, MdtBclJointType type, const MdtConstraintClass *cls,
                                              const char *function)
{
    MdtWorldData *w = MdtWorldFromID(wid, function);
    if (!w)
        return NULL;
    if (!w->callerName)
        return create(wid, type, cls, function, NULL);
    return create(wid, type, cls, w->callerName, &w->contactPoolFullReported);
}

void MdtConstraintRelease(MdtConstraintData *c)
{
    MdtWorldData *w = c->world;
    if (c->enabled) {
        c->enabled = MEFALSE;
        w->enabledConstraintCount--;
    }
    if (c->cls->destroy)
        c->cls->destroy(c);
    MdtConstraintAttach(c, NULL, NULL);
    MePoolPutStruct(&w->constraintPool, c);
}

void MdtConstraintDestroy(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    if (c->world->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "constraints cannot be destroyed during the world's step");
        return;
    }
    if (c->inGroup) {
        ME_REPORT(ME_ERR_BAD_STATE, "this contact belongs to a contact group: use MdtContactGroupDestroyContact");
        return;
    }
    MdtConstraintRelease(c);
}

void MdtConstraintEnable(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    if (c->enabled)
        return;
    if (!c->body[0] && !c->inGroup) {
        ME_REPORT(ME_ERR_BAD_STATE, "a %s cannot be enabled before MdtConstraintSetBodies gives it a body",
                  c->cls->name);
        return;
    }
    c->enabled = METRUE;
    if (!c->inGroup)
        c->world->enabledConstraintCount++;
}

void MdtConstraintDisable(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    if (!c->enabled)
        return;
    c->enabled = MEFALSE;
    if (!c->inGroup)
        c->world->enabledConstraintCount--;
    for (int i = 0; i < 2; i++) {
        MeVector3Set(c->force[i], 0, 0, 0);
        MeVector3Set(c->torque[i], 0, 0, 0);
    }
}

MeBool MdtConstraintIsEnabled(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, MEFALSE);
    return c->enabled;
}

MeBool MdtConstraintIsValid(MdtConstraintID id) { return MeHandleIsValid((uintptr_t)id, ME_HANDLE_CONSTRAINT); }

int MdtConstraintGetType(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, -1);
    return (int)c->type;
}

const char *MdtConstraintGetTypeName(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, "invalid");
    return c->cls->name;
}

/* ---- frames ------------------------------------------------------------------------------- */
void MdtConstraintToBodyPoint(const MdtConstraintData *c, int index, const MeVector3 world, MeVector3 out)
{
    if (c->body[index])
        MeMatrix4TMInverseTransform(out, c->body[index]->bodyTM, world);
    else
        MeVector3Copy(out, world);
}

void MdtConstraintToBodyVector(const MdtConstraintData *c, int index, const MeVector3 world, MeVector3 out)
{
    if (c->body[index])
        MeMatrix4TMInverseRotate(out, c->body[index]->bodyTM, world);
    else
        MeVector3Copy(out, world);
}

void MdtConstraintWorldPosition(const MdtConstraintData *c, int index, MeVector3 out)
{
    if (c->body[index])
        MeMatrix4TMTransform(out, c->body[index]->bodyTM, c->position[index]);
    else
        MeVector3Copy(out, c->position[index]);
}

void MdtConstraintWorldPrimary(const MdtConstraintData *c, int index, MeVector3 out)
{
    if (c->body[index])
        MeMatrix4TMRotate(out, c->body[index]->bodyTM, c->primary[index]);
    else
        MeVector3Copy(out, c->primary[index]);
}

void MdtConstraintWorldOrthogonal(const MdtConstraintData *c, int index, MeVector3 out)
{
    if (c->body[index])
        MeMatrix4TMRotate(out, c->body[index]->bodyTM, c->orthogonal[index]);
    else
        MeVector3Copy(out, c->orthogonal[index]);
}

/* The sine of the angle below which a given secondary axis counts as parallel to the primary one
 * (0.06°): closer, the frame it defines is mostly rounding. */
#define PARALLEL_AXES_SINE ME_R(1e-3)

/* Normalise p, and make o a unit vector perpendicular to it. A secondary axis the caller gave
 * (`given`) must have a length and not be parallel to p, else the call is refused; one kept from
 * before (SetAxis) is replaced by any perpendicular when it has become parallel. */
static MeBool makeAxes(MeVector3 p, MeVector3 o, MeBool given, const char *function)
{
    if (given && !(MeVector3MagnitudeSqr(o) > 0)) {
        ME_REPORT_IN(function, ME_ERR_ZERO_AXIS, "the secondary axis has zero length; call ignored");
        return MEFALSE;
    }
    if (!MeVector3NormalizeSafe(p)) {
        ME_REPORT_IN(function, ME_ERR_ZERO_AXIS, "the primary axis has zero length; call ignored");
        return MEFALSE;
    }
    MeReal d = MeVector3Dot(o, p);
    MeVector3 t;
    MeVector3Set(t, o[0] - d * p[0], o[1] - d * p[1], o[2] - d * p[2]);
    if (given && !(MeVector3MagnitudeSqr(t) > PARALLEL_AXES_SINE * PARALLEL_AXES_SINE * MeVector3MagnitudeSqr(o))) {
        ME_REPORT_IN(function, ME_ERR_PARALLEL_AXES,
                     "the secondary axis (%g, %g, %g) is parallel to the primary one: it must be perpendicular "
                     "(or at least %g rad off parallel); call ignored",
                     (double)o[0], (double)o[1], (double)o[2], (double)PARALLEL_AXES_SINE);
        return MEFALSE;
    }
    if (MeVector3MagnitudeSqr(t) < ME_SMALL_EPSILON) {
        MeVector3 a, b;
        MeVector3PlaneSpace(p, a, b);
        MeVector3Copy(o, a);
    } else {
        MeVector3Normalize(t);
        MeVector3Copy(o, t);
    }
    return METRUE;
}

void MdtConstraintSetPosition(MdtConstraintID id, MeReal x, MeReal y, MeReal z)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    MeVector3 p = {x, y, z};
    MdtConstraintToBodyPoint(c, 0, p, c->position[0]);
    MdtConstraintToBodyPoint(c, 1, p, c->position[1]);
}

void MdtConstraintBodySetPosition(MdtConstraintID id, unsigned int bodyindex, MeReal x, MeReal y, MeReal z)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    if (!checkBodyIndex(bodyindex, __func__))
        return;
    MeVector3 p = {x, y, z};
    MdtConstraintToBodyPoint(c, (int)bodyindex, p, c->position[bodyindex]);
}

void MdtConstraintBodySetPositionRel(MdtConstraintID id, unsigned int bodyindex, MeReal x, MeReal y, MeReal z)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    if (!checkBodyIndex(bodyindex, __func__))
        return;
    MeVector3Set(c->position[bodyindex], x, y, z);
}

static void setWorldAxes(MdtConstraintData *c, int first, int last, MeVector3 p, MeVector3 o)
{
    for (int i = first; i <= last; i++) {
        MdtConstraintToBodyVector(c, i, p, c->primary[i]);
        MdtConstraintToBodyVector(c, i, o, c->orthogonal[i]);
    }
}

void MdtConstraintSetAxis(MdtConstraintID id, MeReal px, MeReal py, MeReal pz)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(px, py, pz, ME_NOTHING);
    MeVector3 p = {px, py, pz}, o;
    /* Keep the current orthogonal axis where it is still usable, so SetAxis after SetAxes is harmless. */
    MdtConstraintWorldOrthogonal(c, 0, o);
    if (makeAxes(p, o, MEFALSE, __func__))
        setWorldAxes(c, 0, 1, p, o);
}

/* Size: Karma 1.2's signature. */
void MdtConstraintSetAxes(MdtConstraintID id, MeReal px, MeReal py, MeReal pz, MeReal ox, MeReal oy, MeReal oz)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(px, py, pz, ME_NOTHING);
    ME_CHECK_FINITE3(ox, oy, oz, ME_NOTHING);
    MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
    if (makeAxes(p, o, METRUE, __func__))
        setWorldAxes(c, 0, 1, p, o);
}

/* Size: Karma 1.2's signature. */
void MdtConstraintBodySetAxes(MdtConstraintID id, unsigned int bodyindex, MeReal px, MeReal py, MeReal pz,
                              MeReal ox, MeReal oy, MeReal oz)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(px, py, pz, ME_NOTHING);
    ME_CHECK_FINITE3(ox, oy, oz, ME_NOTHING);
    if (!checkBodyIndex(bodyindex, __func__))
        return;
    MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
    if (makeAxes(p, o, METRUE, __func__))
        setWorldAxes(c, (int)bodyindex, (int)bodyindex, p, o);
}

/* Size: Karma 1.2's signature. */
void MdtConstraintBodySetAxesRel(MdtConstraintID id, unsigned int bodyindex, MeReal px, MeReal py, MeReal pz,
                                 MeReal ox, MeReal oy, MeReal oz)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(px, py, pz, ME_NOTHING);
    ME_CHECK_FINITE3(ox, oy, oz, ME_NOTHING);
    if (!checkBodyIndex(bodyindex, __func__))
        return;
    MeVector3 p = {px, py, pz}, o = {ox, oy, oz};
    if (makeAxes(p, o, METRUE, __func__)) {
        MeVector3Copy(c->primary[bodyindex], p);
        MeVector3Copy(c->orthogonal[bodyindex], o);
    }
}

/* ---- accessors ---------------------------------------------------------------------------- */
MdtBodyID MdtConstraintGetBody(MdtConstraintID id, unsigned int bodyindex)
{
    CONSTRAINT_OR_RETURN(c, id, NULL);
    if (!checkBodyIndex(bodyindex, __func__))
        return NULL;
    return c->body[bodyindex] ? (MdtBodyID)c->body[bodyindex]->id : NULL;
}

void *MdtConstraintGetUserData(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, NULL);
    return c->userData;
}

MdtWorldID MdtConstraintGetWorld(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, NULL);
    return (MdtWorldID)c->world->id;
}

void MdtConstraintGetForce(MdtConstraintID id, unsigned int bodyindex, MeVector3 f)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(f, ME_NOTHING);
    if (checkBodyIndex(bodyindex, __func__))
        MeVector3Copy(f, c->force[bodyindex]);
}

void MdtConstraintGetTorque(MdtConstraintID id, unsigned int bodyindex, MeVector3 t)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(t, ME_NOTHING);
    if (checkBodyIndex(bodyindex, __func__))
        MeVector3Copy(t, c->torque[bodyindex]);
}

void MdtConstraintGetPosition(MdtConstraintID id, MeVector3 p)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    MdtConstraintWorldPosition(c, 0, p);
}

void MdtConstraintBodyGetPosition(MdtConstraintID id, unsigned int bodyindex, MeVector3 p)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (checkBodyIndex(bodyindex, __func__))
        MdtConstraintWorldPosition(c, (int)bodyindex, p);
}

void MdtConstraintBodyGetPositionRel(MdtConstraintID id, unsigned int bodyindex, MeVector3 p)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (checkBodyIndex(bodyindex, __func__))
        MeVector3Copy(p, c->position[bodyindex]);
}

void MdtConstraintBodyGetAxis(MdtConstraintID id, unsigned int bodyindex, MeVector3 a)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(a, ME_NOTHING);
    if (checkBodyIndex(bodyindex, __func__))
        MdtConstraintWorldPrimary(c, (int)bodyindex, a);
}

void MdtConstraintGetAxes(MdtConstraintID id, MeVector3 p, MeVector3 o)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_NOT_NULL(o, ME_NOTHING);
    MdtConstraintWorldPrimary(c, 0, p);
    MdtConstraintWorldOrthogonal(c, 0, o);
}

void MdtConstraintBodyGetAxes(MdtConstraintID id, unsigned int bodyindex, MeVector3 p, MeVector3 o)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_NOT_NULL(o, ME_NOTHING);
    if (!checkBodyIndex(bodyindex, __func__))
        return;
    MdtConstraintWorldPrimary(c, (int)bodyindex, p);
    MdtConstraintWorldOrthogonal(c, (int)bodyindex, o);
}

void MdtConstraintBodyGetAxesRel(MdtConstraintID id, unsigned int bodyindex, MeVector3 p, MeVector3 o)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_NOT_NULL(o, ME_NOTHING);
    if (!checkBodyIndex(bodyindex, __func__))
        return;
    MeVector3Copy(p, c->primary[bodyindex]);
    MeVector3Copy(o, c->orthogonal[bodyindex]);
}

MeI32 MdtConstraintGetSortKey(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, 0);
    return c->sortKey;
}

int MdtConstraintRowBound(const MdtConstraintData *c) { return c->cls->rowCount ? c->cls->rowCount(c) : c->cls->maxRows; }

int MdtConstraintGetRowCount(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, 0);
    return c->rowCount;
}

void MdtConstraintGetWorldLinearVelocity(MdtConstraintID id, MeVector3 lv)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(lv, ME_NOTHING);
    MeVector3Copy(lv, c->worldLinearVelocity);
}

void MdtConstraintGetWorldAngularVelocity(MdtConstraintID id, MeVector3 av)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(av, ME_NOTHING);
    MeVector3Copy(av, c->worldAngularVelocity);
}

/* ---- mutators ----------------------------------------------------------------------------- */
void MdtConstraintSetBodies(MdtConstraintID id, MdtBodyID b1, MdtBodyID b2)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    MdtBodyData *body0 = MdtBodyFromID(b1, __func__);
    if (!body0)
        return;
    MdtBodyData *body1 = NULL;
    if (b2) {
        body1 = MdtBodyFromID(b2, __func__);
        if (!body1)
            return;
    }
    if (body0->world != c->world || (body1 && body1->world != c->world)) {
        ME_REPORT(ME_ERR_FOREIGN_HANDLE, "a body belongs to another world than the constraint; call ignored");
        return;
    }
    if (body0 == body1) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "a constraint cannot join a body to itself; call ignored");
        return;
    }
    if (c->enabled && !c->inGroup) {
        ME_REPORT(ME_ERR_BAD_STATE, "disable the %s before changing its bodies; call ignored", c->cls->name);
        return;
    }
    MdtConstraintAttach(c, body0, body1);
}

void MdtConstraintSetUserData(MdtConstraintID id, void *d)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    c->userData = d;
}

void MdtConstraintSetSortKey(MdtConstraintID id, MeI32 key)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    if (key < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'key' (%ld) must lie in 0 ... 2^31-1", (long)key);
        return;
    }
    c->sortKey = key;
}

void MdtConstraintSetWorldLinearVelocity(MdtConstraintID id, MeReal vx, MeReal vy, MeReal vz)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(vx, vy, vz, ME_NOTHING);
    MeVector3Set(c->worldLinearVelocity, vx, vy, vz);
}

void MdtConstraintSetWorldAngularVelocity(MdtConstraintID id, MeReal ax, MeReal ay, MeReal az)
{
    CONSTRAINT_OR_RETURN(c, id, ME_NOTHING);
    ME_CHECK_FINITE3(ax, ay, az, ME_NOTHING);
    MeVector3Set(c->worldAngularVelocity, ax, ay, az);
}

/* ---- iteration ---------------------------------------------------------------------------- */
static MdtConstraintID nextTopLevel(MdtWorldData *w, int from)
{
    for (int i = from; i < w->constraintPool.capacity; i++) {
        if (!MePoolSlotIsLive(&w->constraintPool, i))
            continue;
        const MdtConstraintData *c = MePoolSlot(&w->constraintPool, i);
        if (!c->inGroup)
            return (MdtConstraintID)c->id;
    }
    return NULL;
}

MdtConstraintID MdtConstraintGetFirst(MdtWorldID wid)
{
    MdtWorldData *w = MdtWorldFromID(wid, __func__);
    return w ? nextTopLevel(w, 0) : NULL;
}

MdtConstraintID MdtConstraintGetNext(MdtConstraintID id)
{
    CONSTRAINT_OR_RETURN(c, id, NULL);
    return nextTopLevel(c->world, c->slot + 1);
}

void MdtWorldForAllConstraints(MdtWorldID wid, MdtConstraintIteratorCBPtr cb, void *ccbdata)
{
    MdtWorldData *w = MdtWorldFromID(wid, __func__);
    if (!w)
        return;
    ME_CHECK_NOT_NULL(cb, ME_NOTHING);
    /* By slot index, so the callback may destroy the constraint it is given. */
    for (int i = 0; i < w->constraintPool.capacity; i++) {
        if (!MePoolSlotIsLive(&w->constraintPool, i))
            continue;
        const MdtConstraintData *c = MePoolSlot(&w->constraintPool, i);
        if (!c->inGroup)
            cb((MdtConstraintID)c->id, ccbdata);
    }
}

static MdtConstraintData *nextOnBody(const MdtBodyData *b, const MdtConstraintData *c)
{
    return c->nextForBody[c->body[0] == b ? 0 : 1];
}

MdtConstraintID MdtBodyGetFirstConstraint(MdtBodyID bid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (!b || !b->firstConstraint)
        return NULL;
    return (MdtConstraintID)((MdtConstraintData *)b->firstConstraint)->id;
}

MdtConstraintID MdtBodyGetNextConstraint(MdtBodyID bid, MdtConstraintID cid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (!b)
        return NULL;
    CONSTRAINT_OR_RETURN(c, cid, NULL);
    MdtConstraintData *next = nextOnBody(b, c);
    return next ? (MdtConstraintID)next->id : NULL;
}

/* Calls fn for each constraint of the body (optionally only contact groups); fn may release it. */
static void forBody(MdtBodyData *b, MeBool contactsOnly, void (*fn)(MdtConstraintData *, void *), void *data)
{
    MdtConstraintData *c = b->firstConstraint;
    while (c) {
        MdtConstraintData *next = nextOnBody(b, c);
        if (!contactsOnly || c->type == MdtBclCONTACTGROUP || c->type == MdtBclCONTACT)
            fn(c, data);
        c = next;
    }
}

typedef struct CallbackData {
    MdtConstraintIteratorCBPtr cb;
    void *data;
} CallbackData;

static void callUser(MdtConstraintData *c, void *data)
{
    CallbackData *d = data;
    d->cb((MdtConstraintID)c->id, d->data);
}

static void disableOne(MdtConstraintData *c, void *data)
{
    (void)data;
    MdtConstraintDisable((MdtConstraintID)c->id);
}

static void releaseOne(MdtConstraintData *c, void *data)
{
    (void)data;
    MdtConstraintRelease(c);
}

void MdtBodyForAllConstraints(MdtBodyID bid, MdtConstraintIteratorCBPtr cb, void *ccbdata)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (!b)
        return;
    ME_CHECK_NOT_NULL(cb, ME_NOTHING);
    CallbackData d = {cb, ccbdata};
    forBody(b, MEFALSE, callUser, &d);
}

void MdtBodyDisableConstraints(MdtBodyID bid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (b)
        forBody(b, MEFALSE, disableOne, NULL);
}

void MdtBodyDestroyConstraints(MdtBodyID bid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (b)
        forBody(b, MEFALSE, releaseOne, NULL);
}

void MdtBodyDisableContacts(MdtBodyID bid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (b)
        forBody(b, METRUE, disableOne, NULL);
}

void MdtBodyDestroyContacts(MdtBodyID bid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (b)
        forBody(b, METRUE, releaseOne, NULL);
}
