/* world_debug.c -- Karma 1.2's debugging aids of the world: contact drawing through the debug-draw
 * hook, the matrix-size log, the Kea debug request, and the scratch chunks and their high-water marks. */
#include <limits.h>

#include <karma/MdtContact.h>
#include <karma/MdtContactGroup.h>
#include <karma/MdtPartition.h>
#include <karma/MeDebugDraw.h>

#include "../me/check.h"
#include "bcl/contact_lod.h"
#include "constraint.h"
#include "world.h"

#define WORLD_OR_RETURN(w, id, ret)                                                                  \
    MdtWorldData *w = MdtWorldFromID((id), __func__);                                                \
    if (!w)                                                                                          \
    return ret

void MdtWorldDebugDefaults(MdtWorldData *w)
{
    w->debugOptions = 0;
    w->keaDebug = (MdtKeaDebugDataRequest){0};
    w->matrixSizeLog = NULL;
    w->matrixSizeLogSize = 0;
}

void MdtWorldSetDebugDrawing(MdtWorldID id, MdtDebugDrawOptions options)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    const unsigned known = MdtDebugDrawContacts | MdtDebugDrawContactForce;
    if ((unsigned)options & ~known) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'drawOptions' (0x%x) has bits other than MdtDebugDrawContacts "
                  "and MdtDebugDrawContactForce", (unsigned)options);
        return;
    }
    w->debugOptions = options;
}

/* The force a contact applied to its body 0 in this step, from its rows' impulses (a group's contacts
 * keep no force vector of their own). */
static void contactForce(const MdtWorldData *w, const MdtConstraintData *c, MeVector3 f)
{
    MeVector3Set(f, 0, 0, 0);
    if (!w->rowsPacked || c->rowStart < 0)
        return;
    for (int k = 0; k < c->rowCount; k++) {
        const KeaJacobianRow *J = &w->rows.J[c->rowStart + k];
        MeVector3MultiplyAdd(f, w->rows.x[c->rowStart + k] / w->stepSize, J->lin0);
    }
}

/* One contact's lines: red along the normal (longer when deeper), green along its force on body 0. */
static void drawContact(const MdtWorldData *w, const MdtConstraintData *c)
{
    MdtContactID id = (MdtContactID)c->id;
    MeVector3 start, end;
    MdtContactGetPosition(id, start);
    if (w->debugOptions & MdtDebugDrawContacts) {
        MdtContactGetNormal(id, end);
        MeVector3Scale(end, 1 + 50 * MdtContactGetPenetration(id));
        MeVector3Add(end, start, end);
        MeDebugDrawAPI.line(start, end, 1, 0, 0);
    }
    if (w->debugOptions & MdtDebugDrawContactForce) {
        contactForce(w, c, end);
        MeVector3Add(end, start, end);
        MeDebugDrawAPI.line(start, end, 0, 1, 0);
    }
}

void MdtWorldDebugDraw(MdtWorldData *w)
{
    const MdtPartitionLists *out = &w->partitions;
    for (int i = 0; i < out->constraintCount; i++) {
        const MdtConstraintData *c = out->constraints[i];
        if (c->type == MdtBclCONTACT)
            drawContact(w, c);
        else if (c->type == MdtBclCONTACTGROUP)
            for (const MdtConstraintData *k = MdtContactGroupFirst(c); k; k = MdtContactNextInGroup(k))
                drawContact(w, k);
    }
}

void MdtWorldSetKeaDebugRequest(MdtWorldID id, MdtKeaDebugDataRequest request)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    w->keaDebug = request;
    if (request.writeKeaInputData || request.readKeaInputData || request.writeKeaInterData ||
        request.writeKeaOutputData)
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "this solver writes and reads no debug files: the request is kept but "
                  "has no effect (MdtWorldGetSolverStats and MdtWorldSetSimErrorHandler show what a solve did)");
}

void MdtWorldSetMatrixSizeLog(MdtWorldID id, int *sizeLog, int logSize)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    if (logSize < 0 || (logSize > 0 && !sizeLog)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'logSize' (%d) must be 0 (no log), or positive with a "
                  "'sizeLog' array of that many ints", logSize);
        return;
    }
    w->matrixSizeLog = logSize > 0 ? sizeLog : NULL;
    w->matrixSizeLogSize = logSize;
    for (int i = 0; i < logSize; i++)
        sizeLog[i] = 0;
}

void MdtWorldLogMatrixSize(MdtWorldData *w, int rows)
{
    if (!w->matrixSizeLog)
        return;
    /* As Karma 1.2 counted: entry k holds the partitions of 4k−3 ... 4k rows (entry 0 those without
     * rows); the last entry also takes every larger one. */
    int entry = (rows + 3) / 4;
    if (entry > w->matrixSizeLogSize - 1)
        entry = w->matrixSizeLogSize - 1;
    w->matrixSizeLog[entry]++;
}

/* The chunks of 1.2's getters: the rows chunk holds what 1.2 kept in its constraints and transforms
 * chunks. */
#define CHUNK_GETTER(Name, field)                                                                    \
    MeChunk *MdtWorldGet##Name(MdtWorldID id)                                                        \
    {                                                                                                \
        WORLD_OR_RETURN(w, id, NULL);                                                                \
        return &w->field;                                                                            \
    }
CHUNK_GETTER(KeaPoolChunk, keaChunk)
CHUNK_GETTER(PartitionOutputChunk, partitionChunk)
CHUNK_GETTER(KeaConstraintsChunk, rowChunk)
CHUNK_GETTER(KeaTMChunk, rowChunk)

int MdtWorldGetMaxMemoryPoolUsed(MdtWorldID id)
{
    WORLD_OR_RETURN(w, id, 0);
    size_t used = MeChunkGetMaxSize(&w->keaChunk);
    return used > (size_t)INT_MAX ? INT_MAX : (int)used;
}

void MdtWorldGetPartitionParams(MdtWorldID id, MdtPartitionParams *params)
{
    WORLD_OR_RETURN(w, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(params, ME_NOTHING);
    params->autoDisable = w->autoDisable.enabled;
    params->vel_thresh = w->autoDisable.velocity;
    params->velrot_thresh = w->autoDisable.angularVelocity;
    params->acc_thresh = w->autoDisable.acceleration;
    params->accrot_thresh = w->autoDisable.angularAcceleration;
    params->alive_time_thresh = w->autoDisable.aliveTime;
    params->maxMatrixSize = w->maxMatrixSize;
    params->lodParams = w->lod;
    params->debugOptions = w->debugOptions;
}
