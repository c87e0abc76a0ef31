/* model_sweep.c -- continuous collision for fast models: the per-model flag and the sweep of one model
 * through its space (MstUniverseStep moves a flagged body back to its first time of impact).
 *
 * The sweep looks at the other models of the space whose AABB (of the last update) meets the box the
 * model covers along its path, and takes each at rest where it is. A model that already touches
 * another at the start (resting, sliding, rolling on it) hits it only when their signed distance (the
 * depth, when they overlap) falls by the slop (twice the gap) below the start's: a body moving along
 * a floor is not stopped by it, a body being driven through it is. */
#include <karma/McdContinuous.h>
#include <karma/McdInteraction.h>
#include <karma/McdModel.h>
#include <karma/McdSpace.h>

#include "../me/check.h"
#include "framework.h"
#include "safe_time.h"
#include "space.h"

#include <karma/MeMemory.h>

#include <string.h>


void McdModelContinuousForget(McdModelData *m)
{
    if (m->continuous) {
        McdFrameworkData *fw = m->framework;
        McdModelData *last = fw->continuousModels[--fw->continuousCount];
        fw->continuousModels[m->continuousIndex] = last;
        last->continuousIndex = m->continuousIndex;
    }
    m->continuous = MEFALSE;
}

void McdModelEnableContinuous(McdModelID id)
{
    McdModelData *m = McdModelFromID(id, __func__);
    if (!m)
        return;
    if (!m->geometry || !McdSafeTimeIsConvex(m->geometry->type)) {
        ME_REPORT(ME_ERR_MCD_CONTINUOUS_GEOMETRY, "the model's geometry (type %d) cannot be swept: only convex "
                  "primitives and convex meshes can; call ignored", m->geometry ? m->geometry->type : -1);
        return;
    }
    if (m->continuous)
        return;
    McdFrameworkData *fw = m->framework;
    if (!fw->continuousModels) { /* room for every model of the pool, made once */
        fw->continuousModels = MeMemoryCreate(sizeof *fw->continuousModels * (size_t)fw->modelPool.capacity);
        if (!fw->continuousModels) {
            ME_REPORT(ME_ERR_OUT_OF_MEMORY, "no memory for the list of continuous models; call ignored");
            return;
        }
    }
    m->continuousIndex = fw->continuousCount;
    fw->continuousModels[fw->continuousCount++] = m;
    m->continuous = METRUE;
}

void McdModelDisableContinuous(McdModelID id)
{
    McdModelData *m = McdModelFromID(id, __func__);
    if (m)
        McdModelContinuousForget(m);
}

MeBool McdModelIsContinuous(McdModelID id)
{
    McdModelData *m = McdModelFromID(id, __func__);
    return m && m->continuous;
}

int McdFrameworkGetContinuousModelCount(McdFrameworkID id)
{
    McdFrameworkData *fw = McdFrameworkFromID(id, __func__);
    return fw ? fw->continuousCount : 0;
}

int McdFrameworkGetContinuousModels(McdFrameworkID id, McdModelID *models, int maxCount)
{
    McdFrameworkData *fw = McdFrameworkFromID(id, __func__);
    if (!fw)
        return 0;
    if (maxCount > 0)
        ME_CHECK_NOT_NULL(models, 0);
    for (int i = 0; i < fw->continuousCount && i < maxCount; i++)
        models[i] = McdModelToID(fw->continuousModels[i]);
    return fw->continuousCount;
}

/* Whether the sweep's arguments are usable; reports the first that is not. */
static MeBool sweepArgumentsValid(MeMatrix4 start, const MeVector3 v, const MeVector3 w, MeReal duration, MeReal gap)
{
    if (!(isfinite(duration) && duration >= 0) || !(isfinite(gap) && gap >= 0)) {
        ME_REPORT_IN("McdSpaceSweepModel", ME_ERR_MCD_SAFE_TIME_RANGE, "arguments 'duration' (%g) and 'gap' (%g) "
                     "must be finite and >= 0; nothing swept", (double)duration, (double)gap);
        return MEFALSE;
    }
    MeBool finite = MeVector3IsValid(v) && MeVector3IsValid(w);
    for (int k = 0; k < 4 && finite; k++)
        finite = MeVector3IsValid(start[k]);
    if (!finite) {
        ME_REPORT_IN("McdSpaceSweepModel", ME_ERR_MCD_SAFE_TIME_VELOCITY,
                     "the start transform or a velocity is not finite; nothing swept");
        return MEFALSE;
    }
    return METRUE;
}

/* Whether the model in `slot` of m's space may stop m's sweep: live, another body's, its box meeting
 * the swept box [lo, hi], and the pair neither disabled nor culled. */
static MeBool mayBlock(const McdModelData *m, int slot, const MeVector3 lo, const MeVector3 hi)
{
    const McdSpaceData *space = m->space;
    const McdSpaceObject *ob = &space->obj[slot];
    const McdModelData *o = ob->model;
    if (!(ob->flags & MCD_OBJ_LIVE) || !o || o == m || !o->geometry || (m->body && o->body == m->body))
        return MEFALSE;
    const MeReal *olo = MCD_BOX_LO(space, slot), *ohi = MCD_BOX_HI(space, slot);
    for (int k = 0; k < 3; k++)
        if (ohi[k] < lo[k] || olo[k] > hi[k])
            return MEFALSE;
    const int pa = MeMIN(slot, m->spaceIndex), pb = MeMAX(slot, m->spaceIndex);
    const int rec = McdSpacePairFind(space, pa, pb);
    return !((rec >= 0 && (space->pairs[rec].flags & MCD_PAIR_DISABLED)) || McdSpaceObjectsCulled(space, pa, pb));
}

/* Sweeps the motion a of model m against the model o, at rest where it is; an earlier hit than the
 * result's replaces it. Returns whether it did. */
static MeBool sweepAgainst(McdModelData *m, McdMotion *a, McdModelData *o, const McdSafeTimeLimits *limits,
                           McdSweepResult *result)
{
    const McdModelID otherID = McdModelToID(o);
    McdModelPair pair;
    memset(&pair, 0, sizeof pair);
    pair.model1 = McdModelToID(m);
    pair.model2 = otherID;
    McdMotion b = {o->geometry, McdModelTransformInternal(o), McdModelRelativeInternal(o), {0, 0, 0}, {0, 0, 0}, &pair};
    a->pair = &pair;
    MeReal t;
    McdSafeTimeHit hit;
    const McdSafeTimeOutcome out = McdSafeTimeMotions(m->framework, a, &b, limits, &t, &hit);
    if (!(out == MCD_SAFE_HIT && t < result->time))
        return MEFALSE;
    result->time = t;
    result->model = otherID;
    MeVector3Copy(result->normal, hit.normal);
    MeVector3Copy(result->position, hit.point);
    result->touching = hit.touching;
    return METRUE;
}

/* Size: the sweep's public signature, as docs/api_changes.md gives it. */
MeBool McdSpaceSweepModel(McdModelID model, MeMatrix4 start, const MeVector3 v, const MeVector3 w, MeReal duration,
                          MeReal gap, McdSweepResult *result)
{
    ME_CHECK_NOT_NULL(start, MEFALSE);
    ME_CHECK_NOT_NULL(v, MEFALSE);
    ME_CHECK_NOT_NULL(w, MEFALSE);
    ME_CHECK_NOT_NULL(result, MEFALSE);
    McdModelData *m = McdModelFromID(model, __func__);
    if (!m || !sweepArgumentsValid(start, v, w, duration, gap))
        return MEFALSE;
    result->time = duration;
    result->model = NULL;
    result->touching = MEFALSE;
    MeVector3Set(result->normal, 0, 0, 0);
    MeVector3Set(result->position, 0, 0, 0);
    const MeReal slop = MeMAX(ME_R(2.0) * gap, MCD_SAFE_TIME_GAP * m->framework->lengthScale);
    if (!m->space || !m->geometry || !McdSafeTimeIsConvex(m->geometry->type))
        return MEFALSE;
    McdMotion a = {m->geometry, start, McdModelRelativeInternal(m), {v[0], v[1], v[2]}, {w[0], w[1], w[2]}, NULL};
    /* A model whose points all move less than half its inner radius cannot pass through anything the
     * contacts would not catch (Box2D v3's test for fast bodies): resting and slow models cost this. */
    const MeReal reach0 = McdSafeTimeReach(m->geometry, a.relative);
    if ((MeVector3Magnitude(v) + MeVector3Magnitude(w) * reach0) * duration <
        ME_R(0.5) * McdSafeTimeInnerRadius(m->geometry))
        return MEFALSE;
    /* The box the model covers: its reach about both ends of its frame's straight path. */
    const MeReal reach = reach0 + gap;
    MeVector3 lo, hi;
    for (int k = 0; k < 3; k++) {
        const MeReal end = start[3][k] + v[k] * duration;
        lo[k] = MeMIN(start[3][k], end) - reach;
        hi[k] = MeMAX(start[3][k], end) + reach;
    }
    /* The space's own arrays: a plain pass over its slots and boxes (as its segment queries). Touching
     * already: only a further approach by the slop counts (a body resting, sliding or rolling on the
     * other is not stopped; one being driven through it is). */
    MeBool found = MEFALSE;
    for (int slot = 0; slot < m->space->maxObjects; slot++) {
        if (!mayBlock(m, slot, lo, hi))
            continue;
        const McdSafeTimeLimits limits = {result->time, gap, slop};
        if (sweepAgainst(m, &a, m->space->obj[slot].model, &limits, result))
            found = METRUE;
    }
    return found;
}
