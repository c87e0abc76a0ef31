/* lod.c -- MdtLODPartitions (MdtLODStage): matrix capping, and the LOD settings (MdtLOD.h).
 *
 * For each partition with more rows than the world's cap, the contacts (of its contact groups and
 * its stand-alone contacts) are listed with an importance (the callback's, or the weighted formula of
 * MdtLOD.h) and sorted, least important first, ties by pool slot. Then:
 *   phase 1  friction rows are dropped, contact by contact, until the partition fits (the most
 *            important frictionRatio share of the friction contacts keeps its friction);
 *   phase 2  whole contacts are dropped, except each group's most important one ("keeper").
 * Joints are never touched. The result is a per-contact row limit stamped with this step's partition
 * stamp (MdtContactCapRows), which the contact's row writer honours in the pack stage; the next step
 * starts from full rows again. Contacts are seen through bcl/contact_lod.h only, not their struct. The list lives in the world's LOD chunk. */

#include <karma/MdtDefaults.h>
#include <karma/MdtContact.h>

#include "../me/check.h"
#include "../me/sort.h"
#include "bcl/contact_lod.h"
#include "constraint.h"
#include "world.h"

typedef struct LODEntry {
    MdtConstraintData *contact;
    const MdtConstraintData *owner; /* the group, or the stand-alone contact itself */
    MeReal importance;
    int full;                   /* rows of its type */
    int rows;                   /* rows it keeps */
    MeBool keeper;              /* the owner's most important contact: never dropped */
} LODEntry;

static int compareEntries(const void *pa, const void *pb)
{
    const LODEntry *a = pa, *b = pb;
    if (a->importance != b->importance)
        return a->importance < b->importance ? -1 : 1;
    return (a->contact->slot > b->contact->slot) - (a->contact->slot < b->contact->slot);
}


/* Speed at which the two bodies approach each other at the contact (0 when separating). */
static MeReal approachSpeed(const MdtConstraintData *owner, const MdtContactLODInputs *d)
{
    MeReal vn = 0;
    for (int i = 0; i < 2; i++) {
        const MdtBodyData *b = owner->body[i];
        if (!b)
            continue;
        MeVector3 r, wxr;
        MeVector3Set(r, d->position[0] - b->comTM[3][0], d->position[1] - b->comTM[3][1],
                     d->position[2] - b->comTM[3][2]);
        MeVector3Cross(wxr, b->velrot, r);
        MeReal v = MeVector3Dot(d->normal, b->vel) + MeVector3Dot(d->normal, wxr);
        vn += i == 0 ? v : -v; /* separating speed: body 0 along n (n points from body 1 to body 0) */
    }
    return vn < 0 ? -vn : 0;
}

static MeReal formulaImportance(const MdtWorldData *w, const MdtConstraintData *owner, const MdtContactLODInputs *d,
                                int ownerRows, int partitionRows)
{
    const MdtLODParams *p = &w->lod;
    MeReal s = p->penetrationBias * d->penetration / w->lengthScale +
               p->normVelBias * approachSpeed(owner, d) / w->lengthScale + d->importance;
    if (!owner->body[1])
        s += p->toWorldBonus;
    MeBool woken = (owner->body[0] && owner->body[0]->enabledByPartitioner) ||
                   (owner->body[1] && owner->body[1]->enabledByPartitioner);
    if (!woken)
        s += p->nonAutoBonus;
    s -= p->rowCountBias * (MeReal)ownerRows / (MeReal)partitionRows;
    return s;
}

/* Append the contacts of one constraint (a group's, or a stand-alone contact) to the list. */
static int listContacts(MdtWorldData *w, MdtConstraintData *c, LODEntry *list, int n, int partitionRows)
{
    MdtConstraintData *first = c->type == MdtBclCONTACTGROUP ? MdtContactGroupFirst(c) : c;
    int ownerRows = MdtConstraintRowBound(c), start = n;
    for (MdtConstraintData *k = first; k; k = k == c ? NULL : MdtContactNextInGroup(k)) {
        LODEntry *e = &list[n++];
        e->contact = k;
        e->owner = c;
        e->full = e->rows = MdtContactFullRowCount(k);
        e->keeper = MEFALSE;
        if (w->importanceCB) {
            e->importance = w->importanceCB((MdtContactID)k->id, w->importanceData);
        } else {
            MdtContactLODInputs d;
            MdtContactGetLODInputs(k, &d);
            e->importance = formulaImportance(w, c, &d, ownerRows, partitionRows);
        }
        if (!ME_IS_FINITE(e->importance))
            e->importance = 0; /* a NaN would make the order depend on the sort */
    }
    /* The owner's most important contact (lowest slot among equals) is kept, with its bonus. */
    int best = -1;
    for (int i = start; i < n; i++)
        if (best < 0 || compareEntries(&list[i], &list[best]) > 0)
            best = i;
    if (best >= 0) {
        list[best].keeper = METRUE;
        if (!w->importanceCB)
            list[best].importance += w->lod.zeroRowBonus;
    }
    return n;
}

static int countContacts(const MdtConstraintData *c)
{
    if (c->type == MdtBclCONTACT)
        return 1;
    int n = 0;
    for (const MdtConstraintData *k = MdtContactGroupFirst(c); k; k = MdtContactNextInGroup(k))
        n++;
    return n;
}

/* Cap partition p; returns the rows dropped. */
static int capPartition(MdtWorldData *w, int p, int rows)
{
    MdtPartitionLists *out = &w->partitions;
    int cStart = out->constraintStart[p], cEnd = out->constraintStart[p + 1], n = 0;
    for (int i = cStart; i < cEnd; i++)
        if (out->constraints[i]->type == MdtBclCONTACTGROUP || out->constraints[i]->type == MdtBclCONTACT)
            n += countContacts(out->constraints[i]);
    if (n == 0)
        return 0;
    LODEntry *list = MeChunkGetMem(&w->lodChunk, sizeof(LODEntry) * (size_t)n);
    if (!list)
        return 0; /* reported by the chunk: this partition is solved uncapped */
    n = 0;
    for (int i = cStart; i < cEnd; i++) {
        MdtConstraintData *c = out->constraints[i];
        if (c->type == MdtBclCONTACTGROUP || c->type == MdtBclCONTACT)
            n = listContacts(w, c, list, n, rows);
    }
    MeSortInPlace(list, (size_t)n, sizeof *list, compareEntries);

    const int cap = w->maxMatrixSize;
    int excess = rows - cap;
    /* Phase 1: friction, least important first; the top frictionRatio share keeps it. */
    int frictionContacts = 0;
    for (int i = 0; i < n; i++)
        frictionContacts += list[i].full > 1;
    int mayLose = frictionContacts - (int)(w->lod.frictionRatio * (MeReal)frictionContacts);
    for (int i = 0; i < n && excess > 0 && mayLose > 0; i++) {
        if (list[i].rows < 2)
            continue;
        excess -= list[i].rows - 1;
        list[i].rows = 1;
        mayLose--;
    }
    /* Phase 2: whole contacts, never a group's keeper. */
    for (int i = 0; i < n && excess > 0; i++) {
        if (list[i].keeper)
            continue;
        excess -= list[i].rows;
        list[i].rows = 0;
    }
    int dropped = 0;
    for (int i = 0; i < n; i++) {
        if (list[i].rows == list[i].full)
            continue;
        MdtContactCapRows(list[i].contact, list[i].rows, w->partitionStamp);
        dropped += list[i].full - list[i].rows;
    }
    MeChunkPutMem(&w->lodChunk, list);
    return dropped;
}

void MdtLODStage(MdtWorldData *w)
{
    if (w->maxMatrixSize == MDT_MATRIX_SIZE_UNCAPPED)
        return;
    MdtPartitionLists *out = &w->partitions;
    for (int p = 0; p < out->partitionCount; p++) {
        int rows = 0;
        for (int i = out->constraintStart[p]; i < out->constraintStart[p + 1]; i++)
            rows += MdtConstraintRowBound(out->constraints[i]);
        if (rows <= w->maxMatrixSize)
            continue;
        int dropped = capPartition(w, p, rows);
        out->droppedRows[p] = dropped;
        w->droppedRows += dropped;
        w->cappedPartitions += dropped > 0;
    }
}

/* ---- API ---------------------------------------------------------------------------------- */
void MdtLODParamsSetDefaults(MdtLODParams *p)
{
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    p->frictionRatio = MDTWORLD_DEFAULT_FRICTION_RATIO;
    p->zeroRowBonus = MDTWORLD_DEFAULT_ZERO_ROW_BONUS;
    p->toWorldBonus = MDTWORLD_DEFAULT_TO_WORLD_BONUS;
    p->rowCountBias = MDTWORLD_ROW_COUNT_BIAS;
    p->penetrationBias = MDTWORLD_PENETRATION_BIAS;
    p->normVelBias = MDTWORLD_NORM_VEL_BIAS;
    p->nonAutoBonus = MDTWORLD_DEFAULT_NON_AUTO_BONUS;
}

void MdtWorldSetMaxMatrixSize(MdtWorldID id, int size)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    if (size < 1) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'size' (%d) must be at least 1 (MDT_MATRIX_SIZE_UNCAPPED: no cap)",
                  size);
        return;
    }
    w->maxMatrixSize = size;
}

int MdtWorldGetMaxMatrixSize(MdtWorldID id)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    return w ? w->maxMatrixSize : MDT_MATRIX_SIZE_UNCAPPED;
}

void MdtWorldGetLODParams(MdtWorldID id, MdtLODParams *params)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    ME_CHECK_NOT_NULL(params, ME_NOTHING);
    *params = w->lod;
}

void MdtWorldSetLODParams(MdtWorldID id, const MdtLODParams *p)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    ME_CHECK_FINITE(p->frictionRatio, ME_NOTHING);
    ME_CHECK_FINITE3(p->zeroRowBonus, p->toWorldBonus, p->rowCountBias, ME_NOTHING);
    ME_CHECK_FINITE3(p->penetrationBias, p->normVelBias, p->nonAutoBonus, ME_NOTHING);
    if (!(p->frictionRatio >= 0 && p->frictionRatio <= 1)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "frictionRatio (%g) must lie in [0, 1]; call ignored", (double)p->frictionRatio);
        return;
    }
    w->lod = *p;
}

void MdtWorldSetContactImportanceCB(MdtWorldID id, MdtContactImportanceCBPtr cb, void *userData)
{
    MdtWorldData *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    w->importanceCB = cb;
    w->importanceData = userData;
}
