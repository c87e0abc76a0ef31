/* instance.c -- geometry instances: the tree a model keeps of its geometry (a root, and one child per
 * slot of each aggregate in it), refreshed at the model's update, and the McdGeometryInstance API. */
#include <string.h>

#include <karma/McdGeometry.h>
#include <karma/McdModel.h>

#include "../../me/check.h"
#include "../../me/handle.h"
#include "aggregate.h"

static McdInstanceData *instanceFromID(McdGeometryInstanceID id, const char *function)
{
    return MeHandleResolve((uintptr_t)id, ME_HANDLE_GEOMETRY_INSTANCE, function, "ins", NULL);
}

static McdGeometryInstanceID toID(const McdInstanceData *ins) { return (McdGeometryInstanceID)ins->id; }

#define INSTANCE_OR_RETURN(ins, id, ret)                                                             \
    McdInstanceData *ins = instanceFromID((id), __func__);                                           \
    if (!ins)                                                                                        \
    return ret

static McdInstanceData *newInstance(McdFrameworkData *fw)
{
    McdInstanceData *ins = MePoolGetStruct(&fw->instancePool);
    if (!ins)
        return NULL;
    memset(ins, 0, sizeof *ins);
    ins->id = MeHandleOfSlot(fw->ownerSlot, ME_HANDLE_GEOMETRY_INSTANCE, MePoolIndexOf(&fw->instancePool, ins));
    ins->framework = fw;
    MeMatrix4TMMakeIdentity(ins->ownTM);
    return ins;
}

/* Release the children of ins (and theirs). */
static void dropChildren(McdInstanceData *ins)
{
    McdInstanceData *c = ins->child;
    while (c) {
        McdInstanceData *next = c->next;
        dropChildren(c);
        ins->framework->instanceChildCount--;
        MePoolPutStruct(&ins->framework->instancePool, c);
        c = next;
    }
    ins->child = NULL;
    ins->childCount = 0;
}

MeMatrix4Ptr McdInstanceTransform(McdInstanceData *ins)
{
    if (ins->model)
        return ins->model->worldTransform;
    return ins->tmPtr ? ins->tmPtr : ins->ownTM;
}

/* The geometry behind an instance's ID, NULL for an empty slot or one destroyed since. */
static McdGeometryData *geometryOf(const McdInstanceData *ins)
{
    if (!ins->geometry || !MeHandleIsValid((uintptr_t)ins->geometry, ME_HANDLE_GEOMETRY))
        return NULL;
    return McdGeometryFromID(ins->geometry, "McdGeometryInstance");
}

/* Make ins's children follow its geometry's slots; report a pool too small once per instance. */
static void sync(McdInstanceData *ins, const McdGeometryData *g, const char *function)
{
    if (!g || g->type != kMcdGeometryTypeAggregate) {
        dropChildren(ins);
        return;
    }
    const McdAggregateShape *a = g->u.aggregate;
    McdFrameworkData *fw = ins->framework;
    if (ins->childCount != a->countMax) {
        dropChildren(ins);
        if (fw->instanceChildCount + a->countMax > fw->instanceMaxCount) {
            if (!ins->poolFullReported)
                ME_REPORT_IN(function, ME_ERR_POOL_FULL,
                             "an aggregate of %d slots needs as many geometry instances; %d of the framework's %d "
                             "are in use (raise %s); its contacts carry no element tags",
                             a->countMax, fw->instanceChildCount, fw->instanceMaxCount, fw->instancePool.sizeName);
            ins->poolFullReported = METRUE;
            return;
        }
        McdInstanceData **link = &ins->child;
        for (int i = 0; i < a->countMax; i++) {
            McdInstanceData *c = newInstance(fw); /* cannot fail: the count was checked */
            c->parent = ins;
            *link = c;
            link = &c->next;
            fw->instanceChildCount++;
        }
        ins->childCount = a->countMax;
        ins->poolFullReported = MEFALSE;
    }
    McdInstanceData *c = ins->child;
    for (int i = 0; i < a->countMax; i++, c = c->next) {
        const McdGeometryData *e = a->elements[i].geometry;
        McdGeometryID id = e ? McdGeometryToID(e) : NULL;
        if (c->geometry != id) {
            dropChildren(c);
            c->geometry = id;
        }
        sync(c, e, function);
    }
}

/* World transforms and AABBs of ins's children, from ins's transform. */
static void place(McdInstanceData *ins, const McdGeometryData *g)
{
    if (!ins->child || !g || g->type != kMcdGeometryTypeAggregate)
        return;
    const McdAggregateShape *a = g->u.aggregate;
    MeMatrix4Ptr tm = McdInstanceTransform(ins);
    McdInstanceData *c = ins->child;
    for (int i = 0; i < a->countMax && c; i++, c = c->next) {
        const McdAggregateElement *e = &a->elements[i];
        if (!e->geometry)
            continue;
        MeMatrix4Ptr ctm = McdInstanceTransform(c);
        MeMatrix4TMCompound(ctm, (MeMatrix4Ptr)e->relTM, tm);
        McdGeometryAABBInternal(e->geometry, ctm, c->aabbMin, c->aabbMax);
        place(c, e->geometry);
    }
}

MeBool McdInstanceTreeCreate(McdModelData *m, const char *function)
{
    McdInstanceData *root = newInstance(m->framework); /* a root per model: the pool holds modelCount more */
    if (!root) {
        ME_REPORT_IN(function, ME_ERR_POOL_FULL, "no geometry instance left for the model (%s)",
                     m->framework->instancePool.sizeName);
        return MEFALSE;
    }
    root->model = m;
    root->geometry = McdGeometryToID(m->geometry); /* McdModelSetGeometry keeps it current */
    m->instance = root;
    return METRUE;
}

void McdInstanceTreeDestroy(McdModelData *m)
{
    if (!m->instance)
        return;
    dropChildren(m->instance);
    MePoolPutStruct(&m->framework->instancePool, m->instance);
    m->instance = NULL;
}

void McdInstanceTreeUpdate(McdModelData *m, const char *function)
{
    McdInstanceData *root = m->instance;
    if (!root)
        return;
    McdGeometryID id = McdGeometryToID(m->geometry);
    if (root->geometry != id) {
        dropChildren(root);
        root->geometry = id;
    }
    if (m->geometry->type != kMcdGeometryTypeAggregate && !root->child)
        return; /* the common case: a primitive model has no children */
    sync(root, m->geometry, function);
    place(root, m->geometry);
}

/* The instance a path code names in the tree under root; NULL when the tree does not have it. */
static McdInstanceData *resolve(McdInstanceData *root, uintptr_t code)
{
    McdInstanceData *ins = root;
    while (code != 0 && ins) {
        if (ins->childCount == 0)
            return NULL;
        const uintptr_t base = (uintptr_t)ins->childCount + 1;
        uintptr_t digit = code % base;
        code /= base;
        if (digit == 0)
            return NULL;
        McdInstanceData *c = ins->child;
        for (uintptr_t k = 1; k < digit && c; k++)
            c = c->next;
        ins = c;
    }
    return code == 0 ? ins : NULL;
}

void McdInstanceResolveTags(const McdModelData *m1, const McdModelData *m2, McdContact *contacts, int n)
{
    const MeBool a1 = m1->geometry->type == kMcdGeometryTypeAggregate;
    const MeBool a2 = m2->geometry->type == kMcdGeometryTypeAggregate;
    for (int k = 0; k < n; k++) {
        if (a1) {
            McdInstanceData *ins = contacts[k].element1 ? resolve(m1->instance, (uintptr_t)contacts[k].element1) : NULL;
            contacts[k].element1 = ins ? (void *)toID(ins) : NULL;
        }
        if (a2) {
            McdInstanceData *ins = contacts[k].element2 ? resolve(m2->instance, (uintptr_t)contacts[k].element2) : NULL;
            contacts[k].element2 = ins ? (void *)toID(ins) : NULL;
        }
    }
}

/* ---- API ------------------------------------------------------------------------------------- */

void McdGeometryInstanceReset(McdGeometryInstanceID id)
{
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    if (ins->model) {
        ins->model->material = 0;
        return;
    }
    ins->material = 0;
    if (ins->tmPtr) { /* the transform goes back into the instance */
        MeMatrix4Copy(ins->ownTM, ins->tmPtr);
        ins->tmPtr = NULL;
    }
}

McdGeometryID McdGeometryInstanceGetGeometry(McdGeometryInstanceID id)
{
    INSTANCE_OR_RETURN(ins, id, NULL);
    return geometryOf(ins) ? ins->geometry : NULL;
}

void McdGeometryInstanceSetGeometry(McdGeometryInstanceID id, McdGeometryID g)
{
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    if (!ins->model) {
        ME_REPORT(ME_ERR_BAD_STATE, "the instance is an aggregate's child: it follows the aggregate's slot "
                                    "(McdAggregateAddElement / McdAggregateRemoveElement); call ignored");
        return;
    }
    McdModelSetGeometry(McdModelToID(ins->model), g);
}

void McdGeometryInstanceSetTransformPtr(const McdGeometryInstanceID id, const MeMatrix4Ptr geometryTM)
{
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    if (ins->model) {
        ME_REPORT(ME_ERR_BAD_STATE, "the instance is a model's root: its transform is the model's "
                                    "(McdModelSetTransformPtr); call ignored");
        return;
    }
    MeMatrix4Ptr current = McdInstanceTransform(ins);
    if (geometryTM) {
        if (geometryTM != current)
            MeMatrix4Copy(geometryTM, current);
        ins->tmPtr = geometryTM == ins->ownTM ? NULL : geometryTM;
    } else if (ins->tmPtr) {
        MeMatrix4Copy(ins->ownTM, ins->tmPtr);
        ins->tmPtr = NULL;
    }
}

MeMatrix4Ptr McdGeometryInstanceGetTransformPtr(McdGeometryInstanceID id)
{
    INSTANCE_OR_RETURN(ins, id, NULL);
    return McdInstanceTransform(ins);
}

void McdGeometryInstanceGetBSphere(McdGeometryInstanceID id, MeVector3 center, MeReal *radius)
{
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(center, ME_NOTHING);
    ME_CHECK_NOT_NULL(radius, ME_NOTHING);
    const McdGeometryData *g = geometryOf(ins);
    if (!g) {
        MeVector3Copy(center, McdInstanceTransform(ins)[3]);
        *radius = 0;
        return;
    }
    MeVector3 local;
    McdGeometryTypeOf(g)->getBSphere(McdGeometryToID(g), McdGeometryShapeData(g), local, radius);
    MeMatrix4TMTransform(center, McdInstanceTransform(ins), local);
}

void McdGeometryInstanceUpdateAABB(McdGeometryInstanceID id, const MeMatrix4Ptr finalTM, MeBool tight)
{
    (void)tight;
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    const McdGeometryData *g = geometryOf(ins);
    if (!g)
        return;
    if (finalTM && !MeMatrix4IsTM(finalTM, MCD_ROTATION_TOLERANCE)) {
        ME_REPORT(ME_ERR_NOT_ROTATION, "argument 'finalTM' is not a rigid transform; call ignored");
        return;
    }
    McdGeometryAABBInternal(g, McdInstanceTransform(ins), ins->aabbMin, ins->aabbMax);
    if (finalTM) {
        MeVector3 lo, hi;
        McdGeometryAABBInternal(g, finalTM, lo, hi);
        for (int j = 0; j < 3; j++) {
            ins->aabbMin[j] = lo[j] < ins->aabbMin[j] ? lo[j] : ins->aabbMin[j];
            ins->aabbMax[j] = hi[j] > ins->aabbMax[j] ? hi[j] : ins->aabbMax[j];
        }
    }
    if (ins->model) {
        MeVector3Copy(ins->model->aabbMin, ins->aabbMin);
        MeVector3Copy(ins->model->aabbMax, ins->aabbMax);
    }
}

void McdGeometryInstanceMaximumPoint(McdGeometryInstanceID id, MeReal *const inDir, MeReal *const outPoint)
{
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(inDir, ME_NOTHING);
    ME_CHECK_NOT_NULL(outPoint, ME_NOTHING);
    ME_CHECK_FINITE3(inDir[0], inDir[1], inDir[2], ME_NOTHING);
    const McdGeometryData *g = geometryOf(ins);
    if (!g) {
        MeVector3Copy(outPoint, McdInstanceTransform(ins)[3]);
        return;
    }
    McdGeometrySupportWorld(g, McdInstanceTransform(ins), inDir, outPoint);
}

void McdGeometryInstanceGetAABB(McdGeometryInstanceID id, MeVector3 minCorner, MeVector3 maxCorner)
{
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(minCorner, ME_NOTHING);
    ME_CHECK_NOT_NULL(maxCorner, ME_NOTHING);
    if (ins->model) { /* the model's box without its contact tolerance */
        for (int j = 0; j < 3; j++) {
            minCorner[j] = ins->model->aabbMin[j] + ins->model->contactTolerance;
            maxCorner[j] = ins->model->aabbMax[j] - ins->model->contactTolerance;
        }
        return;
    }
    MeVector3Copy(minCorner, ins->aabbMin);
    MeVector3Copy(maxCorner, ins->aabbMax);
}

void McdGeometryInstanceSetMaterial(McdGeometryInstanceID id, int material)
{
    INSTANCE_OR_RETURN(ins, id, ME_NOTHING);
    if (ins->model)
        McdModelSetMaterial(McdModelToID(ins->model), material);
    else
        ins->material = material;
}

unsigned int McdGeometryInstanceGetMaterial(McdGeometryInstanceID id)
{
    INSTANCE_OR_RETURN(ins, id, 0);
    return (unsigned int)(ins->model ? ins->model->material : ins->material);
}

McdGeometryInstanceID McdGeometryInstanceGetChild(McdGeometryInstanceID id, int i)
{
    INSTANCE_OR_RETURN(ins, id, NULL);
    if (i < 0 || i >= ins->childCount)
        return NULL;
    McdInstanceData *c = ins->child;
    while (i-- > 0)
        c = c->next;
    return toID(c);
}

MeBool McdGeometryInstanceOverlap(McdGeometryInstanceID id1, McdGeometryInstanceID id2)
{
    INSTANCE_OR_RETURN(a, id1, MEFALSE);
    INSTANCE_OR_RETURN(b, id2, MEFALSE);
    MeVector3 alo, ahi, blo, bhi;
    McdGeometryInstanceGetAABB(id1, alo, ahi);
    McdGeometryInstanceGetAABB(id2, blo, bhi);
    (void)a;
    (void)b;
    for (int j = 0; j < 3; j++)
        if (!(alo[j] <= bhi[j] && blo[j] <= ahi[j]))
            return MEFALSE;
    return METRUE;
}

McdGeometryType McdGeometryInstanceGetGeometryType(McdGeometryInstanceID id)
{
    INSTANCE_OR_RETURN(ins, id, kMcdGeometryTypeNull);
    const McdGeometryData *g = geometryOf(ins);
    return g ? (McdGeometryType)g->type : kMcdGeometryTypeNull;
}

McdGeometryInstanceID McdModelGetGeometryInstance(McdModelID id)
{
    McdModelData *m = McdModelFromID(id, __func__);
    return m && m->instance ? toID(m->instance) : NULL;
}
