/* request_table.c -- Karma 1.2's process-wide request table (McduRequestTable.h): one McdRequest per
 * unordered pair of request IDs, kept as a packed lower triangle. */
#include <karma/McdModel.h>
#include <karma/McduRequestTable.h>
#include <karma/MeMemory.h>

#include "../me/check.h"

/* Written by Init/Term only (the application's setup, before threads start). */
static McduRequestTable table;
static MeBool haveTable;

/* Entry index of the unordered pair (a, b), or -1 (reported in `function`) when out of range. */
static int entryIndex(int a, int b, const char *function)
{
    if (!haveTable) {
        ME_REPORT_IN(function, ME_ERR_BAD_STATE, "there is no request table (McduRequestTableInit first)");
        return -1;
    }
    if (a < 0 || b < 0 || a >= table.idCount || b >= table.idCount) {
        ME_REPORT_IN(function, ME_ERR_ARGUMENT_RANGE, "request IDs (%d, %d) are outside 0..%d (McduRequestTableInit)",
                     a, b, table.idCount - 1);
        return -1;
    }
    if (a > b) {
        int t = a;
        a = b;
        b = t;
    }
    return b * (b + 1) / 2 + a;
}

McduRequestTable *MEAPI McduRequestTableInit(int idMaxCount, McdRequest *request)
{
    /* a bound that keeps the triangle's size an int */
    if (idMaxCount <= 0 || idMaxCount > 4096) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "idMaxCount is %d; it must be in 1..4096; call ignored", idMaxCount);
        return NULL;
    }
    int size = idMaxCount * (idMaxCount + 1) / 2;
    McdRequest *entries = MeMemoryCreate((size_t)size * sizeof *entries);
    if (!entries) {
        ME_REPORT(ME_ERR_OUT_OF_MEMORY, "no memory for %d requests", size);
        return NULL;
    }
    McdRequest fill = {4, 0};
    if (request)
        fill = *request;
    for (int i = 0; i < size; i++)
        entries[i] = fill;
    McduRequestTableTerm();
    table.idCount = idMaxCount;
    table.size = size;
    table.ididToElement = entries;
    haveTable = METRUE;
    return &table;
}

void MEAPI McduRequestTableTerm(void)
{
    if (haveTable)
        MeMemoryDestroy(table.ididToElement);
    table.idCount = table.size = 0;
    table.ididToElement = NULL;
    haveTable = MEFALSE;
}

void MEAPI McduRequestTableSetRequest(int requestId1, int requestId2, McdRequest *request)
{
    ME_CHECK_NOT_NULL(request, ME_NOTHING);
    int i = entryIndex(requestId1, requestId2, __func__);
    if (i >= 0)
        table.ididToElement[i] = *request;
}

McdRequest *MEAPI McduRequestTableGetRequestPtr(int id1, int id2)
{
    int i = entryIndex(id1, id2, __func__);
    return i >= 0 ? &table.ididToElement[i] : NULL;
}

/* The entry of the pair's models' IDs, or -1 (reported in `function`). */
static int pairEntry(const McdModelPair *pair, const char *function)
{
    if (!McdModelIsValid(pair->model1) || !McdModelIsValid(pair->model2)) {
        ME_REPORT_IN(function, ME_ERR_INVALID_HANDLE, "a model of the pair is not a live McdModelID; call ignored");
        return -1;
    }
    return entryIndex(McdModelGetRequestID(pair->model1), McdModelGetRequestID(pair->model2), function);
}

void MEAPI McduRequestTableGetRequest(McdModelPair *pair, McdRequest *request)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    ME_CHECK_NOT_NULL(request, ME_NOTHING);
    int i = pairEntry(pair, __func__);
    if (i >= 0)
        *request = table.ididToElement[i];
}

void MEAPI McduHelloRequestTableCB(McdModelPair *pair)
{
    ME_CHECK_NOT_NULL(pair, ME_NOTHING);
    int i = pairEntry(pair, __func__);
    if (i >= 0)
        pair->request = &table.ididToElement[i];
}
