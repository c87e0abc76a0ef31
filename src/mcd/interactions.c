/* interactions.c -- Karma 1.2's view of the interaction table (McdFrameworkGetInteractions) and the
 * 1.2-form pair test it hands out, which runs the registered test for any pair. */
#include <karma/McdFrame.h>
#include <karma/MeMemory.h>

#include "../me/check.h"
#include "framework.h"

/* McdIntersectFn onto the table: the pair's own choice when McdHello was called on it, otherwise a
 * choice made for this call only (and its cache released after it). */
static int intersectThroughTable(McdModelPair *pair, McdIntersectResult *result)
{
    const char *function = "McdInteractions.intersectFn";
    ME_CHECK_NOT_NULL_IN(function, pair, 0);
    ME_CHECK_NOT_NULL_IN(function, result, 0);
    McdModelData *m1 = McdModelFromID(pair->model1, function), *m2 = McdModelFromID(pair->model2, function);
    if (!m1 || !m2)
        return 0;
    if (pair->testIndex >= 0)
        return McdIntersectModels(pair, m1, m2, result, function);
    McdModelPair once = *pair;
    McdHelloInternal(&once, m1, m2, function);
    int touch = McdIntersectModels(&once, m1, m2, result, function);
    McdGoodbyeInternal(&once, m1);
    result->pair = pair;
    return touch;
}

McdInteractions *McdFrameworkGetInteractions(McdFramework *id, int geoType1, int geoType2)
{
    McdFrameworkData *fw = McdFrameworkFromID(id, __func__);
    if (!fw)
        return NULL;
    if (geoType1 < 0 || geoType2 < 0 || geoType1 >= fw->typeCount || geoType2 >= fw->typeCount) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "geometry types (%d, %d) must be in [0, %d); call ignored", geoType1,
                  geoType2, fw->typeCount);
        return NULL;
    }
    int cap = fw->typeCapacity;
    if (!fw->interactionViews) {
        fw->interactionViews = MeMemoryCreateZeroed(sizeof *fw->interactionViews * (size_t)cap * (size_t)cap);
        if (!fw->interactionViews) {
            ME_REPORT(ME_ERR_OUT_OF_MEMORY, "no memory for the interaction table's view");
            return NULL;
        }
    }
    McdInteractions *view = &fw->interactionViews[geoType1 * cap + geoType2];
    MeBool forward = McdFrameworkGetInteraction(fw, geoType1, geoType2) != NULL;
    MeBool backward = McdFrameworkGetInteraction(fw, geoType2, geoType1) != NULL;
    int lo = geoType1 < geoType2 ? geoType1 : geoType2, hi = geoType1 < geoType2 ? geoType2 : geoType1;
    view->helloFn = NULL;
    view->goodbyeFn = NULL;
    view->intersectFn = forward || backward ? intersectThroughTable : NULL;
    view->safetimeFn = NULL;
    view->swap = !forward && backward;
    view->cull = 0;
    view->warned = fw->warnedPairs[lo * cap + hi] != 0;
    return view;
}
