/* McdMessage.h -- Karma 1.2's collision error reports: McdError and the McdCoreError macro.
 *
 * An error list is an array of McdErrorDescription ended by the entry numbered kMcdMAXErrDefined
 * (gMcdCoreErrorList is the library's, McdCoreErrorList.h). McdError looks the number up and reports
 * "<description><message>" through the message hook, naming `fn` as the function: an error of the
 * core list with a code of ours (McdCoreErrorList.h) is reported with that code; any other goes
 * through MeWarning (1.2's fatal and warning types) or MeInfo (info type), code ME_ERR_USER_MESSAGE.
 * Unlike 1.2, a fatal error does not abort: the library never exits on an application's error. An
 * entry whose m_errorCount is 0 or less is not reported (set it to silence one error). */
#ifndef MCD_MESSAGE_H
#define MCD_MESSAGE_H

#include "McdCoreErrorList.h"
#include "MeMessage.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** 1.2's error types (McdErrorDescription.m_errorLevel). */
enum {
    kMcdErrorTypeFatal,
    kMcdErrorTypeWarning,
    kMcdErrorTypeInfo
};

/** One entry of an error list. */
typedef struct McdErrorDescription {
    MeI16 m_errNum;              /**< the error number (e.g. kMcdErrorNum_InvalidPtr) */
    MeI16 m_errorLevel;          /**< kMcdErrorTypeFatal, ...Warning or ...Info */
    MeI16 m_errorCount;          /**< reported while > 0 (5 in the core list) */
    const char *m_description;   /**< the sentence the message starts with */
} McdErrorDescription;

/** The library's list, one entry per number of McdCoreErrorList.h, in that order. */
ME_API extern McdErrorDescription gMcdCoreErrorList[];

/** Report error `errorCode` of `ErrorList` with `message` appended, in the name of function `fn`
 *  at file:line (the caller's place). */
ME_API void MEAPI McdError(McdErrorDescription *ErrorList, int errorCode, const char *message, const char *fn,
                           const char *file, int line);

/** Report an error of the core list (1.2's macro). */
#define McdCoreError(errorCode, message, fn, file, line)                                             \
    McdError(gMcdCoreErrorList, (errorCode), (message), (fn), (file), (line))

ME_EXTERN_C_END

#endif /* MCD_MESSAGE_H */
