/* McdCheck.h -- Karma 1.2's collision check macros.
 *
 * In 1.2 they checked only in MCDCHECK builds; here they are real checks in every build, as the
 * library's own are. A failed check reports through McdCoreError (McdMessage.h), that is through the
 * message hook with the code the error number maps to, and goes on (it returns nothing). `fn` names
 * the function doing the check. The handle checks go further than 1.2's NULL test: a destroyed or
 * foreign model, space or geometry fails too. Statement macros expand to one statement. */
#ifndef MCD_CHECK_H
#define MCD_CHECK_H

#include "McdFrame.h"
#include "McdGeometry.h"
#include "McdMessage.h"
#include "McdModel.h"
#include "McdSpace.h"

/* One statement: report `errorNum` with `message` when `failed`. */
#define MCD_CHECK_REPORT_(failed, errorNum, message, fn)                                              \
    do {                                                                                             \
        if (failed)                                                                                  \
            McdCoreError((errorNum), (message), (fn), __FILE__, __LINE__);                           \
    } while (0)

/** An expression: report the failed condition's text when EX is false. */
#define MCD_CHECK_ASSERT_(EX, fn)                                                                    \
    ((EX) ? (void)0 : McdCoreError(kMcdErrorNum_AssertionFailed, #EX, (fn), __FILE__, __LINE__))
#define MCD_ASSERT(stuff, fn) MCD_CHECK_ASSERT_(stuff, fn)
/** Report errorNum with errorMsg when inExpression is false. */
#define MCD_CHECK_ASSERT(inExpression, errorNum, errorMsg, fn)                                        \
    MCD_CHECK_REPORT_(!(inExpression), errorNum, errorMsg, fn)
#define MCDCHECK_GENERICFATAL(inExpression, errorMsg, fn)                                            \
    MCD_CHECK_REPORT_(!(inExpression), kMcdErrorNum_GenericFatal, errorMsg, fn)
#define MCDCHECK_GENERICWARNING(inExpression, errorMsg, fn)                                          \
    MCD_CHECK_REPORT_(!(inExpression), kMcdErrorNum_GenericWarning, errorMsg, fn)
/** An allocation returned NULL (typeName names what was allocated). */
#define MCDCHECK_ALLOC(ptr, typeName, fn) MCD_CHECK_REPORT_((ptr) == 0, kMcdErrorNum_AllocFailure, typeName, fn)
#define MCD_CHECK_NULLPTR(ptr, typeName, fn) MCD_CHECK_REPORT_((ptr) == 0, kMcdErrorNum_InvalidPtr, typeName, fn)

/** Handles: NULL, destroyed or foreign. */
#define MCD_CHECKMODEL(x, fn) MCD_CHECK_REPORT_(!McdModelIsValid(x), kMcdErrorNum_InvalidPtr_CM, "", fn)
#define MCD_CHECKGEOMETRYINSTANCE(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidPtr_CM, "", fn)
#define MCD_CHECKSPACE(x, fn) MCD_CHECK_REPORT_(!McdSpaceIsValid(x), kMcdErrorNum_InvalidPtr_Space, "", fn)
#define MCD_CHECKSPACEBUILT(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidFuncOrder_Space, "", fn)
#define MCD_CHECKGEOMETRY(x, fn) MCD_CHECK_REPORT_(!McdGeometryIsValid(x), kMcdErrorNum_InvalidPtr_Geometry, "", fn)
#define MCDGEOMETRY_CHECK_VALID(g, fn)                                                               \
    MCD_CHECK_REPORT_(!McdGeometryIsValid(g), kMcdErrorNum_GenericFatal,                             \
                      "the McdGeometry is not valid (destroyed, or of an unregistered type)", fn)
/** A pair pointer, and both its models. */
#define MCD_CHECKMODELPAIR(x, fn)                                                                    \
    do {                                                                                             \
        if ((x) == 0)                                                                                \
            McdCoreError(kMcdErrorNum_InvalidPtr_SP, "", (fn), __FILE__, __LINE__);                  \
        else if (!McdModelIsValid((x)->model1) || !McdModelIsValid((x)->model2))                     \
            McdCoreError(kMcdErrorNum_InvalidPair, "", (fn), __FILE__, __LINE__);                    \
    } while (0)
/** A result pointer, and its contact array. */
#define MCD_CHECKINTERSECTRESULT(r, fn)                                                              \
    do {                                                                                             \
        if ((r) == 0)                                                                                \
            McdCoreError(kMcdErrorNum_InvalidPtr_IR, "", (fn), __FILE__, __LINE__);                  \
        else if ((r)->contacts == 0)                                                                 \
            McdCoreError(kMcdErrorNum_InvalidIR, "", (fn), __FILE__, __LINE__);                      \
    } while (0)
#define MCD_CHECKMODELPAIRID(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidPtr_SPID, "", fn)
#define MCD_CHECKRWWORLD(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidPtr_RWW, "", fn)
#define MCD_CHECKRWBSP(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidPtr_RWBSP, "", fn)
#define MCD_CHECKTRANSFORM(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidPtr_TM, "", fn)
#define MCD_CHECKBRIDGEBUILT(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidFuncOrder_Bridge, "", fn)
#define MCD_CHECKCDDTBRIDGE(x, fn) MCD_CHECK_REPORT_((x) == 0, kMcdErrorNum_InvalidPtr_CDDT, "", fn)
/** Type numbers of framework f: both (i, j), or one (i), must be numbers f has room for. */
#define MCD_INTERACTIONTABLE_CHECKBOUNDS(f, i, j, fn)                                                \
    MCD_CHECK_REPORT_(!McdFrameworkTypeIsValid((f), (i)) || !McdFrameworkTypeIsValid((f), (j)),      \
                      McdErrorNum_RegisterInteractionWithInvalidGeometryType, "", fn)
#define MCD_INTERACTIONARRAY_CHECKBOUNDS(f, i, fn)                                                   \
    MCD_CHECK_REPORT_(!McdFrameworkTypeIsValid((f), (i)), McdErrorNum_RegisterInteractionWithInvalidGeometryType, \
                      "", fn)

#endif /* MCD_CHECK_H */
