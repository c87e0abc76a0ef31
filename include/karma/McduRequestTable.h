/* McduRequestTable.h -- Karma 1.2's request table: the McdRequest for a pair of models chosen by
 * their request IDs (McdModelSetRequestID), e.g. fewer contacts between debris than between wheels
 * and the ground.
 *
 * The table is symmetric ((a, b) and (b, a) are one entry) and process-wide, as in 1.2: fill it
 * before stepping, then install McduHelloRequestTableCB with McdSetHelloCallback so that McdHello
 * points each new pair at its entry. Pairs keep pointers into the table: McduRequestTableTerm only
 * after the last McdGoodbye of such pairs. */
#ifndef MCDU_REQUEST_TABLE_H
#define MCDU_REQUEST_TABLE_H

#include "McdInteractions.h"
#include "McdModelPair.h"

ME_EXTERN_C_BEGIN

/** The table (1.2's fields; read them, change entries through the functions below). */
typedef struct McduRequestTable {
    int idCount;               /**< request IDs 0 .. idCount - 1 */
    int size;                  /**< entries in ididToElement */
    McdRequest *ididToElement; /**< one request per unordered pair of IDs */
} McduRequestTable;

/** Create the table for request IDs 0 .. idMaxCount - 1 (> 0), every entry a copy of `request`
 *  (NULL: contactMaxCount 4, faceNormalsFirst 0). Replaces a table made before. NULL (reported) on
 *  a bad size or no memory. */
ME_API McduRequestTable *MEAPI McduRequestTableInit(int idMaxCount, McdRequest *request);
/** Free the table. */
ME_API void MEAPI McduRequestTableTerm(void);
/** Copy *request into the entry of (requestId1, requestId2). */
ME_API void MEAPI McduRequestTableSetRequest(int requestId1, int requestId2, McdRequest *request);
/** Copy into *request the entry of the pair's two models' request IDs. */
ME_API void MEAPI McduRequestTableGetRequest(McdModelPair *pair, McdRequest *request);
/** The entry of (id1, id2), to read or change in place; NULL (reported) when out of range or no table. */
ME_API McdRequest *MEAPI McduRequestTableGetRequestPtr(int id1, int id2);
/** A hello callback (McdSetHelloCallback): point the pair's request at its models' entry. Leaves the
 *  pair's request alone when there is no table or an ID is out of range (reported). */
ME_API void MEAPI McduHelloRequestTableCB(McdModelPair *pair);

ME_EXTERN_C_END

#endif /* MCDU_REQUEST_TABLE_H */
