/* bridge.c -- MstBridge: creating it, and turning the space's pairs into dynamics contacts.
 *
 * A pair's MdtContactGroup hangs on McdModelPair.userData from the first step its models intersect
 * until the pair's Goodbye (as the User Guide describes; decision M3). Its contacts are refreshed in
 * place each step (a new contact reuses the group's nearest old one, see refreshGroup), so the
 * solver's warm start carries over between steps. A step without contacts (the models apart while
 * their boxes still overlap, every contact refused by the per-contact callback, or the per-pair
 * callback returning 0) empties the group and disables it, as Karma's bridge did: an empty group
 * adds no rows, joins no bodies into a partition and wakes nothing; it is enabled again when
 * contacts come back (they start from no warm start).
 *
 * Mst is written as an application's own bridge would be: it uses the public headers only (and Me's
 * message and handle helpers), so whatever it needs of Mcd and Mdt is public API too. */
#include <string.h>

#include <karma/McdInteraction.h>
#include <karma/McdModel.h>
#include <karma/McdModelPair.h>
#include <karma/McdSpace.h>
#include <karma/MeMath.h>
#include <karma/MeMemory.h>
#include <karma/MdtBody.h>
#include <karma/MdtContact.h>
#include <karma/MdtContactGroup.h>
#include <karma/MdtWorld.h>

#include "../me/check.h"
#include "../me/handle.h"
#include "bridge.h"
#include "speculative.h"

/* Whether `id` is a live ID of an object of `kind` (not an owner's); reported in `function`'s name (argument `argument`) if not. */
static MeBool checkID(const void *id, MeHandleKind kind, const char *function, const char *argument)
{
    return MeHandleResolve((uintptr_t)id, kind, function, argument, NULL) != NULL;
}

#define DEFAULT_PAIR_BUFFER 128
#define DEFAULT_CONTACT_BUFFER 32

/* Make room for `count` contacts in the scratch of a group's refresh; 0 (reported by MeMemory) if
 * memory runs out, the old scratch kept. */
static MeBool reserveRefreshScratch(MstBridgeData *b, int count)
{
    MdtCollisionPoint *points = MeMemoryCreate(sizeof *points * (size_t)count);
    MdtContactID *contacts = MeMemoryCreate(sizeof *contacts * (size_t)count);
    if (!points || !contacts) {
        MeMemoryDestroy(points);
        MeMemoryDestroy(contacts);
        return MEFALSE;
    }
    MeMemoryDestroy(b->points);
    MeMemoryDestroy(b->newContacts);
    b->points = points;
    b->newContacts = contacts;
    return METRUE;
}

static void freeRefreshScratch(MstBridgeData *b)
{
    MeMemoryDestroy(b->points);
    MeMemoryDestroy(b->newContacts);
}

MstBridgeData *MstBridgeFromID(MstBridgeID id, const char *function)
{
    return MeHandleResolveOwner((uintptr_t)id, ME_HANDLE_BRIDGE, function, "b");
}

MstBridgeID MstBridgeCreate(McdFrameworkID frame, int maxMaterials)
{
    if (maxMaterials < 1) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'maxMaterials' (%d) must be at least 1", maxMaterials);
        return NULL;
    }
    MstBridgeData *b = MeMemoryCreateZeroed(sizeof *b);
    if (!b)
        return NULL;
    b->framework = frame;
    b->maxMaterials = maxMaterials;
    b->materialsSizeName = "maxMaterials in MstBridgeCreate";
    b->converting = "MstHandleCollisions";
    b->materialCount = 1; /* the default material */
    b->table = MeMemoryCreateZeroed(sizeof *b->table * (size_t)maxMaterials * (size_t)maxMaterials);
    b->pairBufferSize = DEFAULT_PAIR_BUFFER;
    b->pairs = McdModelPairContainerCreate(b->pairBufferSize);
    b->contactBufferSize = DEFAULT_CONTACT_BUFFER;
    b->contacts = MeMemoryCreate(sizeof *b->contacts * (size_t)b->contactBufferSize);
    const MeBool scratch = reserveRefreshScratch(b, b->contactBufferSize);
    b->ownerSlot = (b->table && b->pairs && b->contacts && scratch) ? MeHandleRegisterOwner(b, ME_HANDLE_BRIDGE, __func__)
                                                                    : 0;
    if (!b->ownerSlot) {
        MeMemoryDestroy(b->table);
        if (b->pairs)
            McdModelPairContainerDestroy(b->pairs);
        MeMemoryDestroy(b->contacts);
        freeRefreshScratch(b);
        MeMemoryDestroy(b);
        return NULL;
    }
    b->id = MeHandleOfOwner(b->ownerSlot);
    for (int i = 0; i < maxMaterials * maxMaterials; i++)
        MdtContactParamsReset(&b->table[i].params);
    return (MstBridgeID)b->id;
}

void MstBridgeDestroy(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return;
    MstBridgeFreeParallel(b);
    MeHandleUnregisterOwner(b->ownerSlot);
    McdModelPairContainerDestroy(b->pairs);
    MeMemoryDestroy(b->contacts);
    freeRefreshScratch(b);
    MeMemoryDestroy(b->table);
    MeMemoryDestroy(b);
}

MeBool MstBridgeIsValid(MstBridgeID id) { return MeHandleIsValid((uintptr_t)id, ME_HANDLE_BRIDGE); }

void MstBridgeSetModelPairBufferSize(MstBridgeID id, int size)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return;
    if (size < 1) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'size' (%d) must be at least 1", size);
        return;
    }
    McdModelPairContainer *c = McdModelPairContainerCreate(size);
    if (!c)
        return;
    McdModelPairContainerDestroy(b->pairs);
    b->pairs = c;
    b->pairBufferSize = size;
    if (b->tested)
        MstBridgeReserveParallel(b, NULL); /* the parallel pair tests' records follow, now */
}

int MstBridgeGetModelPairBufferSize(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    return b ? b->pairBufferSize : 0;
}

void MstBridgeSetContactBufferSize(MstBridgeID id, int size)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return;
    if (size < 1) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'size' (%d) must be at least 1", size);
        return;
    }
    McdContact *c = MeMemoryCreate(sizeof *c * (size_t)size);
    if (!c || !reserveRefreshScratch(b, size)) {
        MeMemoryDestroy(c);
        return;
    }
    MeMemoryDestroy(b->contacts);
    b->contacts = c;
    b->contactBufferSize = size;
    if (b->tested)
        MstBridgeReserveParallel(b, NULL); /* the parallel pair tests' records follow, now */
}

int MstBridgeGetContactBufferSize(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    return b ? b->contactBufferSize : 0;
}

void MstBridgeSetStepSize(MstBridgeID id, MeReal stepSize)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return;
    if (!(ME_IS_FINITE(stepSize) && stepSize >= 0)) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'stepSize' (%g) must be finite and not negative", (double)stepSize);
        return;
    }
    b->stepSize = stepSize;
}

MeReal MstBridgeGetStepSize(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    return b ? b->stepSize : 0;
}

int MstBridgeGetLastPairCount(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    return b ? b->lastPairCount : 0;
}

int MstBridgeGetLastContactCount(MstBridgeID id)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    return b ? b->lastContactCount : 0;
}

/* ---- the update --------------------------------------------------------------------------- */

/* Remove every contact of the pair's group and disable it (the group itself lives on). */
static void emptyGroup(MdtContactGroupID g)
{
    MdtContactID c = MdtContactGroupGetFirstContact(g);
    while (c) {
        MdtContactID next = MdtContactGroupGetNextContact(g, c);
        MdtContactGroupDestroyContact(g, c);
        c = next;
    }
    MdtConstraintDisable(MdtContactGroupQuaConstraint(g));
}

static void destroyGroup(McdModelPair *pair)
{
    MdtContactGroupID g = (MdtContactGroupID)pair->userData;
    pair->userData = NULL;
    if (g && MdtConstraintIsValid(MdtContactGroupQuaConstraint(g))) {
        MdtContactGroupSetGenerator(g, NULL); /* the destroy handler must not touch the pair again */
        MdtContactGroupDestroy(g);
    }
}

void MstHandleTransitions(McdModelPairContainer *pairs, McdSpaceID space, MdtWorldID world, MstBridgeID id)
{
    (void)space;
    (void)world;
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return;
    ME_CHECK_NOT_NULL(pairs, ME_NOTHING);
    MstBridgeSayGoodbye(pairs);
    MstBridgeSayHello(pairs);
}

void MstBridgeSayGoodbye(McdModelPairContainer *pairs)
{
    int n;
    McdModelPairID *goodbye = McdModelPairContainerGetGoodbyeArray(pairs, &n);
    for (int i = 0; i < n; i++) {
        /* MstModelAndBodyDestroy removes a model from its space and destroys it at once, so a goodbye
         * may name dead models: McdGoodbye releases such a pair quietly. */
        destroyGroup(goodbye[i]);
        McdGoodbye(goodbye[i]);
    }
}

void MstBridgeSayHello(McdModelPairContainer *pairs)
{
    int n;
    McdModelPairID *hello = McdModelPairContainerGetHelloArray(pairs, &n);
    for (int i = 0; i < n; i++) {
        hello[i]->userData = NULL;
        McdHello(hello[i]);
    }
}

/* The group's contacts refreshed from the pair's n collision contacts (normals negated for a
 * swapped pair, penetration the negated separation); returns how many have a dynamics contact in
 * b->newContacts. The group's old contacts are reused for the new ones, each new one taking the
 * old one nearest to it (MdtContactGroupSetFromCollisions), so that warm-start impulses follow the
 * points. */
static int refreshGroup(MstBridgeData *b, MdtContactGroupID g, const MstMaterialPairData *mat,
                        const McdContact *in, int n, MeBool swapped)
{
    MdtCollisionPoint *points = b->points;
    for (int i = 0; i < n; i++) {
        MeVector3Copy(points[i].position, in[i].position);
        if (swapped)
            MeVector3Set(points[i].normal, -in[i].normal[0], -in[i].normal[1], -in[i].normal[2]);
        else
            MeVector3Copy(points[i].normal, in[i].normal);
        points[i].penetration = -in[i].separation;
    }
    return MdtContactGroupSetFromCollisions(g, &mat->params, points, n, b->newContacts);
}

int MstBridgeConvertPair(MstBridgeData *b, McdModelPair *pair, MdtWorldID world, MeBool tested,
                         const McdModelPairModelInfo *models, McdIntersectResult *result)
{
    if (!tested) { /* not tested: */
        if (models->frozen[0] && models->frozen[1])
            return MdtContactGroupGetCount((MdtContactGroupID)pair->userData); /* kept as they were */
        return 0; /* two pieces of the world, or a bad model (reported) */
    }
    MdtBodyID b1 = (MdtBodyID)models->bodyData[0], b2 = (MdtBodyID)models->bodyData[1];
    MstMaterialPairData *mat = MstBridgeMaterialPair(b, models->material[0], models->material[1], b->converting);
    if (!mat)
        return 0;
    if (result->contactCount > 0 && mat->intersectCB)
        mat->intersectCB(result);
    /* Points apart that cannot close their gap this step add no row the solver needs (C23); a material
     * with a callback sees every point, as reported. */
    if (!mat->intersectCB && !mat->perContactCB && !mat->perPairCB)
        result->contactCount =
            MstSpeculativeKeep(world, pair, models, b->stepSize, result->contacts, result->contactCount);
    MdtContactGroupID g = (MdtContactGroupID)pair->userData;
    if (result->contactCount <= 0) {
        if (g)
            emptyGroup(g);
        return 0;
    }
    /* Body 0 is model 1's body and body 1 model 2's, so McdContact's normal (model 2 towards model 1)
     * is the MdtContact normal as it is (body 1 towards body 0). The dynamic body is body 0: a pair
     * whose model 1 is part of the world is turned round and its normals negated. */
    MeBool swapped = !b1;
    if (!g) {
        g = MdtContactGroupCreate(world);
        if (!g)
            return 0; /* pool full: reported by Mdt (once, in the world's caller name) */
        MdtConstraintSetBodies(MdtContactGroupQuaConstraint(g), swapped ? b2 : b1, swapped ? NULL : b2);
        MdtContactGroupSetSwapped(g, swapped);
        MdtContactGroupSetGenerator(g, pair);
        pair->userData = g;
    }
    /* An intersect callback may have set a count beyond the buffer it was given. */
    int n = result->contactCount < b->contactBufferSize ? result->contactCount : b->contactBufferSize;
    n = refreshGroup(b, g, mat, result->contacts, n, swapped);
    /* The per-contact callback sees each contact set, the group's others set too. */
    int kept = n;
    for (int i = 0; i < n && mat->perContactCB; i++)
        if (!mat->perContactCB(result, &result->contacts[i], b->newContacts[i])) {
            MdtContactGroupDestroyContact(g, b->newContacts[i]);
            kept--;
        }
    /* A per-pair callback returning 0 removes the pair's contacts (Karma's MstPerPairCBPtr), not the
     * group, which lives until Goodbye. */
    if (kept == 0 || (mat->perPairCB && !mat->perPairCB(result, g))) {
        emptyGroup(g);
        return 0;
    }
    MdtConstraintEnable(MdtContactGroupQuaConstraint(g));
    return kept;
}

/* Test one pair and convert its contacts; returns the number of dynamics contacts made. */
static int collidePair(MstBridgeData *b, McdModelPair *pair, MdtWorldID world)
{
    McdModelPairModelInfo models;
    McdIntersectResult result;
    memset(&result, 0, sizeof result);
    result.contacts = b->contacts;
    result.contactMaxCount = b->contactBufferSize;
    MeBool tested = McdIntersectForResponse(pair, &models, &result);
    return MstBridgeConvertPair(b, pair, world, tested, &models, &result);
}

void MstHandleCollisions(McdModelPairContainer *pairs, McdSpaceID space, MdtWorldID world, MstBridgeID id)
{
    (void)space;
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return;
    ME_CHECK_NOT_NULL(pairs, ME_NOTHING);
    if (!MeHandleResolveOwner((uintptr_t)world, ME_HANDLE_WORLD, __func__, "w"))
        return;
    /* Contacts are made every step: a full pool is reported once, naming what the application called
     * (this function, unless MstBridgeUpdateContacts or MstUniverseStep named itself first). */
    const char *caller = MdtWorldGetCallerName(world);
    if (!caller)
        MdtWorldSetCallerName(world, __func__);
    b->converting = caller ? caller : __func__;
    int n, ns;
    McdModelPairID *hello = McdModelPairContainerGetHelloArray(pairs, &n);
    McdModelPairID *staying = McdModelPairContainerGetStayingArray(pairs, &ns);
    if (MstBridgeCollideInParallel(b, world, hello, n, staying, ns)) {
        for (int i = 0; i < n + ns; i++) {
            MstTestedPair *t = &b->tested[i];
            b->lastContactCount += MstBridgeConvertPair(b, i < n ? hello[i] : staying[i - n], world, t->tested,
                                                        &t->info, &t->result);
        }
        b->lastPairCount += n + ns;
    } else {
        for (int i = 0; i < n; i++) {
            b->lastContactCount += collidePair(b, hello[i], world);
            b->lastPairCount++;
        }
        for (int i = 0; i < ns; i++) {
            b->lastContactCount += collidePair(b, staying[i], world);
            b->lastPairCount++;
        }
    }
    if (!caller)
        MdtWorldSetCallerName(world, NULL);
}

void MstBridgeUpdateContacts(MstBridgeID id, McdSpaceID space, MdtWorldID world)
{
    MstBridgeData *b = MstBridgeFromID(id, __func__);
    if (!b)
        return;
    if (!MeHandleResolveOwner((uintptr_t)world, ME_HANDLE_WORLD, __func__, "world"))
        return;
    b->lastPairCount = b->lastContactCount = 0;
    /* Messages name what the application called (MstUniverseStep sets its own name first). */
    const char *caller = MdtWorldGetCallerName(world);
    if (!caller)
        MdtWorldSetCallerName(world, __func__);
    MstBridgeReadPairs(b, space, world, METRUE);
    if (!caller)
        MdtWorldSetCallerName(world, NULL);
}

/* ---- linking models and bodies -------------------------------------------------------------- */

/* The model the bridge linked to a body, if it is in a space; NULL (quietly) otherwise: the model may
 * have been destroyed. */
static McdModelID linkedModelInSpace(MdtBodyID body)
{
    McdModelID m = (McdModelID)MdtBodyGetModel(body);
    return m && McdModelIsValid(m) && McdModelGetSpace(m) ? m : NULL;
}

static void onBodyEnabled(MdtBodyID body, void *data)
{
    (void)data;
    McdModelID m = linkedModelInSpace(body);
    if (m && McdSpaceModelIsFrozen(m))
        McdSpaceUnfreezeModel(m);
}

static void onBodyDisabled(MdtBodyID body, void *data)
{
    (void)data;
    McdModelID m = linkedModelInSpace(body);
    if (m && !McdSpaceModelIsFrozen(m)) {
        /* A frozen model's box is not updated again: take the body's pose now, for a body placed and
         * disabled by the application before the space saw it move (auto-disable, inside the step,
         * finds the box already up to date). */
        if (McdSpaceIsChanging(McdModelGetSpace(m)))
            McdSpaceUpdateModel(m);
        McdSpaceFreezeModel(m);
    }
}

static void onGroupDestroyed(MdtContactGroupID g, void *data)
{
    (void)data;
    McdModelPair *pair = MdtContactGroupGetGenerator(g);
    if (pair && pair->userData == (void *)g)
        pair->userData = NULL;
}

void MstSetWorldHandlers(MdtWorldID world)
{
    MdtWorldSetBodyEnableCallback(world, onBodyEnabled, NULL);
    MdtWorldSetBodyDisableCallback(world, onBodyDisabled, NULL);
    MdtWorldSetContactGroupDestroyCallback(world, onGroupDestroyed, NULL);
}

void McdModelSetBody(McdModelID model, MdtBodyID body)
{
    if (!checkID(model, ME_HANDLE_MODEL, __func__, "m") || (body && !checkID(body, ME_HANDLE_BODY, __func__, "b")))
        return;
    MdtBodyID old = (MdtBodyID)McdModelGetBodyData(model);
    if (old && MdtBodyIsValid(old) && MdtBodyGetModel(old) == (void *)model)
        MdtBodySetModel(old, NULL);
    McdModelSetBodyData(model, body);
    if (body) {
        MdtBodySetModel(body, model);
        McdModelSetTransformPtr(model, MdtBodyGetTransformPtr(body));
    }
}

MdtBodyID McdModelGetBody(McdModelID model)
{
    return checkID(model, ME_HANDLE_MODEL, __func__, "m") ? (MdtBodyID)McdModelGetBodyData(model) : NULL;
}
