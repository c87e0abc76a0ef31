/* karma.h brings in every public header of every layer: a program that includes it alone reaches
 * the newer headers' functions and macros (Me's MeCall, MeAssert, MeSimpleFile, MeDebugDraw, MeMisc;
 * Mdt's and Mst's utilities; Mcd's messages, checks, profile, batch, pair manager and Mcdu tools). */
#include "karma_test.h"

#include <karma/karma.h>

#if !defined(MEAPI) || !defined(MEASSERT) || !defined(MCD_CHECKMODEL) || !defined(McdCoreError) ||              \
    !defined(McdProfileStart) || !defined(MCDU_DEBUG_DRAW_CIRCLE_SEGMENTS) || !defined(MeProfileStartSection)
#  error "karma.h does not bring in every public header"
#endif

typedef void (*AnyFn)(void);

static void umbrella_declares_every_layer(void **state)
{
    (void)state;
    const AnyFn fns[] = {
        (AnyFn)MeOpenWithSearch,           (AnyFn)MeHSVtoRGB,
        (AnyFn)MeBoundingSphereCalc,       (AnyFn)McdError,
        (AnyFn)McdBatchIntersectEach,      (AnyFn)McdModelPairManagerCreate,
        (AnyFn)McduDebugDrawBox,           (AnyFn)McduRequestTableInit,
        (AnyFn)McduHelloRequestTableCB,    (AnyFn)McdContactSimplify,
        (AnyFn)McdFrameworkGetInteractions, (AnyFn)McdIntersectAt,
        (AnyFn)McdModelDynamicsReset,      (AnyFn)MstBridgeUpdateTransitions,
    };
    for (size_t i = 0; i < sizeof fns / sizeof fns[0]; i++)
        assert_non_null(fns[i]);
    assert_non_null(MeDebugDrawAPI.line);
    assert_true(kMcdMAXErrDefined > kMcdErrorNum_GenericFatal);
    assert_true(gMcdCoreErrorList[0].m_errNum == kMcdErrorNum_GenericFatal);
}

int main(void)
{
    const struct CMUnitTest tests[] = {cmocka_unit_test(umbrella_declares_every_layer)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
