/* space_model.c -- models in a space: create and destroy, insert, remove, update, freeze, pair
 * filtering, iteration (see McdSpace.h). The model API (framework.h) refreshes transforms and AABBs;
 * the engine (space_sort.c, space_pairs.c) sorts the boxes. */
#include "../me/check.h"
#include "framework.h"
#include "space.h"

#define SPACE_OR_RETURN(s, id, ret)                                                                  \
    McdSpaceData *s = McdSpaceFromID((id), __func__);                                                    \
    if (!s)                                                                                          \
    return ret

McdSpaceID McdSpaceAxisSortCreate(McdFrameworkID fw, int axes, int objectCount, int pairCount)
{
    McdFrameworkData *f = McdFrameworkFromID(fw, __func__);
    if (!f)
        return NULL;
    McdSpaceData *s = McdSpaceCreateInternal(f, axes, objectCount, pairCount, __func__);
    return s ? (McdSpaceID)s->id : NULL;
}

void McdSpaceDestroy(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    for (int slot = 0; slot < s->maxObjects; slot++) {
        McdModelData *m = s->obj[slot].model;
        if ((s->obj[slot].flags & MCD_OBJ_LIVE) && m) {
            m->frozen = MEFALSE;
            McdModelSetSpaceInternal(m, NULL, NULL, -1);
        }
    }
    McdSpaceDestroyInternal(s);
}

/* The model and its space, with the change-block rule applied: NULL (reported) when the model is
 * invalid, in no space, or the space is in the wrong state (`changing` < 0: any state). */
static McdSpaceData *modelSpace(McdModelID model, McdModelData **out, int changing, const char *function)
{
    McdModelData *m = McdModelFromID(model, function);
    if (!m)
        return NULL;
    McdSpaceData *s = m->space;
    if (!s) {
        ME_REPORT_IN(function, ME_ERR_BAD_STATE, "the model is in no space (McdSpaceInsertModel); call ignored");
        return NULL;
    }
    if (changing >= 0 && !McdSpaceCheckChanging(s, changing != 0, function))
        return NULL;
    *out = m;
    return s;
}

/* Copies a freshly updated model's box and sort key into its object. */
static void takeModel(McdSpaceData *s, int slot, const McdModelData *m, const char *function)
{
    McdSpaceObject *o = &s->obj[slot];
    if (!McdSpaceObjectSetAABB(s, slot, m->aabbMin, m->aabbMax))
        ME_REPORT_IN(function, ME_ERR_NONFINITE_ARGUMENT,
                     "a model's bounding box is not finite (check its transform); it keeps its last box");
    if (o->key != m->sortKey) {
        o->key = m->sortKey;
        s->keysChanged = METRUE;
    }
}

static MeBool insert(McdSpaceID space, McdModelID model, McdCullingTable *table, int index, int id,
                     const char *function)
{
    McdSpaceData *s = McdSpaceFromID(space, function);
    if (!s)
        return MEFALSE;
    McdModelData *m = McdModelFromID(model, function);
    if (!m || !McdSpaceCheckChanging(s, METRUE, function))
        return MEFALSE;
    if (m->framework != s->framework) {
        ME_REPORT_IN(function, ME_ERR_FOREIGN_HANDLE,
                     "the model belongs to another framework than the space; not inserted");
        return MEFALSE;
    }
    if (m->space) {
        ME_REPORT_IN(function, ME_ERR_BAD_STATE,
                     "the model is already in a space (a model is in at most one); not inserted");
        return MEFALSE;
    }
    if (table && (index < 0 || index >= table->size)) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "index (%d) must be in [0, %d) (the table's size); not inserted",
                     index, table->size);
        return MEFALSE;
    }
    McdModelUpdateInternal(m);
    int slot = McdSpaceObjectAdd(s, m->id, m, m->sortKey, m->aabbMin, m->aabbMax);
    if (slot < 0) {
        ME_REPORT_IN(function, ME_ERR_POOL_FULL,
                     "the space is full (%d models); raise %s; model not inserted", s->maxObjects,
                     s->objectsSizeName);
        return MEFALSE;
    }
    takeModel(s, slot, m, function);
    McdSpaceObjectSetCulling(s, slot, table, index, id);
    m->frozen = MEFALSE;
    McdModelSetSpaceInternal(m, s, (McdSpaceID)s->id, slot);
    return METRUE;
}

MeBool McdSpaceInsertModel(McdSpaceID space, McdModelID model)
{
    return insert(space, model, NULL, 0, 0, __func__);
}

void McdSpaceSetModelCullingParameters(McdSpaceID space, McdModelID model, McdCullingTable *table, int index, int id)
{
    McdModelData *m;
    McdSpaceData *s = modelSpace(model, &m, 1, __func__);
    if (!s)
        return;
    if (m->space != McdSpaceFromID(space, __func__)) {
        ME_REPORT(ME_ERR_FOREIGN_HANDLE, "the model is in another space; call ignored");
        return;
    }
    if (table && (index < 0 || index >= table->size)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "index (%d) must be in [0, %d) (the table's size); call ignored", index,
                  table->size);
        return;
    }
    McdSpaceObjectSetCulling(s, m->spaceIndex, table, index, id);
}

MeBool McdSpaceInsertModelWithCulling(McdSpaceID space, McdModelID model, McdCullingTableID table, int index, int id)
{
    ME_CHECK_NOT_NULL(table, MEFALSE);
    return insert(space, model, (McdCullingTable *)table, index, id, __func__);
}

void McdSpaceForgetModel(struct McdModelData *m)
{
    McdSpaceObjectRemove(m->space, m->spaceIndex);
    m->frozen = MEFALSE;
    McdModelSetSpaceInternal(m, NULL, NULL, -1);
}

MeBool McdSpaceRemoveModel(McdModelID model)
{
    McdModelData *m;
    McdSpaceData *s = modelSpace(model, &m, 1, __func__);
    if (!s)
        return MEFALSE;
    McdSpaceObjectRemove(s, m->spaceIndex);
    m->frozen = MEFALSE;
    McdModelSetSpaceInternal(m, NULL, NULL, -1);
    return METRUE;
}

void McdSpaceUpdateAll(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, ME_NOTHING);
    if (!McdSpaceCheckChanging(s, METRUE, __func__))
        return;
    for (int slot = 0; slot < s->slotEnd; slot++) {
        McdSpaceObject *o = &s->obj[slot];
        if (!(o->flags & MCD_OBJ_LIVE) || !o->model)
            continue;
        if (!(o->flags & MCD_OBJ_FROZEN)) {
            if (s->updateAABBFn)
                s->updateAABBFn((McdModelID)o->handle, 0);
            else
                McdModelUpdateInternal(o->model);
            takeModel(s, slot, o->model, __func__);
        } else if (o->key != o->model->sortKey) {
            o->key = o->model->sortKey;
            s->keysChanged = METRUE;
        }
    }
    McdSpaceSort(s, METRUE, __func__);
}

void McdSpaceUpdateModel(McdModelID model)
{
    McdModelData *m;
    McdSpaceData *s = modelSpace(model, &m, 1, __func__);
    if (!s)
        return;
    McdModelUpdateInternal(m);
    /* A box that has not moved changes no pair: skip the pass over every axis (O(models)). Auto-
     * disable freezes whole partitions at once, and their boxes are already up to date. */
    const MeReal *box = &s->box[6 * m->spaceIndex];
    MeBool same = s->obj[m->spaceIndex].key == m->sortKey && !s->listsDirty && s->pendingCount == 0;
    for (int k = 0; k < 3 && same; k++)
        same = box[k] == m->aabbMin[k] && box[k + 3] == m->aabbMax[k];
    if (same)
        return;
    takeModel(s, m->spaceIndex, m, __func__);
    McdSpaceSort(s, METRUE, __func__); /* one pass per axis: the other boxes have not moved */
}

static MeBool setFrozen(McdModelID model, MeBool frozen, const char *function)
{
    McdModelData *m;
    McdSpaceData *s = modelSpace(model, &m, -1, function);
    if (!s)
        return MEFALSE;
    McdSpaceObjectSetFrozen(s, m->spaceIndex, frozen);
    m->frozen = frozen;
    return METRUE;
}

MeBool McdSpaceFreezeModel(McdModelID model) { return setFrozen(model, METRUE, __func__); }
MeBool McdSpaceUnfreezeModel(McdModelID model) { return setFrozen(model, MEFALSE, __func__); }

MeBool McdSpaceModelIsFrozen(McdModelID model)
{
    McdModelData *m = McdModelFromID(model, __func__);
    return m && m->space && (m->space->obj[m->spaceIndex].flags & MCD_OBJ_FROZEN) != 0;
}

/* Both models, in the same space, in the right state. */
static McdSpaceData *pairSpace(McdModelID model1, McdModelID model2, int *a, int *b, int changing, const char *function)
{
    McdModelData *m1, *m2;
    McdSpaceData *s = modelSpace(model1, &m1, changing, function);
    if (!s || !modelSpace(model2, &m2, -1, function))
        return NULL;
    if (m2->space != s) {
        ME_REPORT_IN(function, ME_ERR_FOREIGN_HANDLE, "the two models are in different spaces; call ignored");
        return NULL;
    }
    if (m1 == m2) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "model1 and model2 are the same model; call ignored");
        return NULL;
    }
    *a = m1->spaceIndex;
    *b = m2->spaceIndex;
    return s;
}

MeBool McdSpaceDisablePair(McdModelID model1, McdModelID model2)
{
    int a, b;
    McdSpaceData *s = pairSpace(model1, model2, &a, &b, 1, __func__);
    if (!s)
        return MEFALSE;
    if (!McdSpacePairSetDisabled(s, a, b, METRUE)) {
        ME_REPORT(ME_ERR_POOL_FULL, "the space's pair pool is full (%d pairs): the pair was not disabled; "
                  "raise %s", s->maxPairs, s->pairsSizeName);
        return MEFALSE;
    }
    return METRUE;
}

MeBool McdSpaceEnablePair(McdModelID model1, McdModelID model2)
{
    int a, b;
    McdSpaceData *s = pairSpace(model1, model2, &a, &b, 1, __func__);
    if (!s)
        return MEFALSE;
    McdSpacePairSetDisabled(s, a, b, MEFALSE);
    return METRUE;
}

MeBool McdSpacePairIsEnabled(McdModelID model1, McdModelID model2)
{
    int a, b;
    McdSpaceData *s = pairSpace(model1, model2, &a, &b, -1, __func__);
    if (!s)
        return MEFALSE;
    int p = McdSpacePairFind(s, a, b);
    return p < 0 || !(s->pairs[p].flags & MCD_PAIR_DISABLED);
}

int McdSpaceGetModelCount(McdSpaceID space)
{
    SPACE_OR_RETURN(s, space, 0);
    return s->objectCount;
}

void McdSpaceModelIteratorBegin(McdSpaceID space, McdSpaceModelIterator *iter)
{
    ME_CHECK_NOT_NULL(iter, ME_NOTHING);
    iter->slot = 0;
    (void)McdSpaceFromID(space, __func__);
}

MeBool McdSpaceGetModel(McdSpaceID space, McdSpaceModelIterator *iter, McdModelID *model)
{
    ME_CHECK_NOT_NULL(iter, MEFALSE);
    ME_CHECK_NOT_NULL(model, MEFALSE);
    SPACE_OR_RETURN(s, space, MEFALSE);
    for (int slot = iter->slot < 0 ? 0 : iter->slot; slot < s->maxObjects; slot++)
        if ((s->obj[slot].flags & MCD_OBJ_LIVE) && s->obj[slot].model) {
            *model = (McdModelID)s->obj[slot].handle;
            iter->slot = slot + 1;
            return METRUE;
        }
    iter->slot = s->maxObjects;
    *model = NULL;
    return MEFALSE;
}
