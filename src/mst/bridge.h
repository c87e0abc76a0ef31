/* bridge.h -- the bridge record (internal): the material table and the buffers of the update. */
#ifndef MST_BRIDGE_INTERNAL_H
#define MST_BRIDGE_INTERNAL_H

#include <stdint.h>

#include <karma/McdModelPair.h>
#include <karma/MstBridge.h>

/** One entry of the symmetric material table. */
typedef struct MstMaterialPairData {
    MdtContactParams params;
    MstIntersectCBPtr intersectCB;
    MstPerContactCBPtr perContactCB;
    MstPerPairCBPtr perPairCB;
} MstMaterialPairData;

/** One pair tested by a worker (parallel_pairs.c): McdIntersectForResponse's answer, the models'
 *  information and the result, whose contacts are the pair's own slice of the bridge's scratch. */
typedef struct MstTestedPair {
    MeBool tested;
    McdModelPairModelInfo info;
    McdIntersectResult result;
} MstTestedPair;

typedef struct MstBridgeData {
    int ownerSlot;
    uintptr_t id;
    McdFrameworkID framework;
    int maxMaterials, materialCount;
    MstMaterialPairData *table;            /* maxMaterials², entry (i, j) with i <= j used */
    McdModelPairContainer *pairs;      /* chunk read from the space */
    int pairBufferSize;
    McdContact *contacts;              /* buffer for one pair test */
    int contactBufferSize;
    /* Scratch of one group's refresh (refreshGroup), room for the contact buffer: the collision
     * points and the group's contacts for them. */
    MdtCollisionPoint *points;
    MdtContactID *newContacts;
    int lastPairCount, lastContactCount;
    /* The pair tests on several workers (parallel_pairs.c): one record per pair of a chunk and
     * contactBufferSize contacts each; made when the universe gets a task system (else at the first
     * threaded update), remade when a buffer size changes. */
    MstTestedPair *tested;             /* two sets of testedPairs records: a chunk's and the next one's */
    McdContact *testedContacts;
    int testedPairs, testedContactsPerPair;
    McdModelPairContainer *nextPairs;  /* the next chunk, read while this one is converted */
    const char *materialsSizeName;     /* what sets maxMaterials, for "pool full" messages */
    int materialCallbackCount;         /* table entries with a callback (the setters keep it) */
    /* Buffer sizes the records could not be made for (reported then; 0: no failure): not tried again
     * until a size changes. */
    int failedPairs, failedContactsPerPair;
    MdtWorldID markedWorld;            /* the world whose task marks were sized for a chunk's tasks */
    const char *converting;            /* the application's call the conversion's messages name */
    MeReal stepSize;                   /* of the step the contacts are for (MstBridgeSetStepSize), else 0 */
} MstBridgeData;

MstBridgeData *MstBridgeFromID(MstBridgeID id, const char *function);
/** The table entry for a material pair, or NULL (reported in `function`'s name) for a bad index. */
MstMaterialPairData *MstBridgeMaterialPair(MstBridgeData *b, MstMaterialID m1, MstMaterialID m2, const char *function);

/** Read the space's pairs chunk by chunk (ending and reopening its change block) and hand each
 *  chunk to MstHandleTransitions and, when `collisions`, to MstHandleCollisions. */
void MstBridgeReadPairs(MstBridgeData *b, McdSpaceID space, MdtWorldID world, MeBool collisions);

/** Test the chunk's pairs (hellos, then stayings) on `world`'s task system, each into its own record
 *  b->tested[i]; MEFALSE (nothing tested) when the world has one worker, the chunk is a single pair or
 *  there is no memory for the records: then the caller tests them itself. */
MeBool MstBridgeCollideInParallel(MstBridgeData *b, MdtWorldID world, McdModelPairID *hello, int helloCount,
                                  McdModelPairID *staying, int stayingCount);
/** Convert one tested pair's contacts (`tested`: what McdIntersectForResponse returned for it) into its
 *  contact group, calling the material's callbacks; returns the number of dynamics contacts made. Its
 *  messages name b->converting, the application's call (set once per update by the caller). */
int MstBridgeConvertPair(MstBridgeData *b, McdModelPair *pair, MdtWorldID world, MeBool tested,
                         const McdModelPairModelInfo *models, McdIntersectResult *result);
/** The Goodbye half of MstHandleTransitions: each leaving pair's contact group destroyed, its cache
 *  released. */
void MstBridgeSayGoodbye(McdModelPairContainer *pairs);
/** The Hello half of MstHandleTransitions: each new pair's user data cleared and McdHello called. */
void MstBridgeSayHello(McdModelPairContainer *pairs);
/** The whole update of the pairs on `world`'s workers, chunk k's conversion running as one item of the
 *  task that tests chunk k + 1 (parallel_pairs.c); MEFALSE, nothing done, when it does not apply (one
 *  worker, no memory for the records, or a material with a callback, which must run on the stepping
 *  thread): then the caller reads the pairs chunk by chunk itself. Called with the space's changes ended. */
MeBool MstBridgeReadPairsPipelined(MstBridgeData *b, McdSpaceID space, MdtWorldID world);
/** Make (or remake, for new buffer sizes) the records of the parallel pair tests: two sets of one per
 *  pair of the pair buffer, with the contact buffer's room each, and the second pair container; and
 *  size `world`'s task marks (NULL: the world they were last sized for, if still valid) for a chunk's
 *  tasks (pairBufferSize + 1 items). MEFALSE, reported by MeMemory, without memory; a failure is
 *  remembered, and not tried again, until a buffer size changes. */
MeBool MstBridgeReserveParallel(MstBridgeData *b, MdtWorldID world);
/** Free the records of the parallel pair tests. */
void MstBridgeFreeParallel(MstBridgeData *b);

#endif /* MST_BRIDGE_INTERNAL_H */
