/* message.c -- Karma 1.2's collision error reports (McdError, gMcdCoreErrorList) routed through the
 * coded message hook (see McdMessage.h). */
#include <karma/McdMessage.h>

/* Karma 1.2 reported each error at most this often; kept as the entries' m_errorCount. */
#define MCD_ERROR_REPEAT_COUNT 5

#define MCD_ERROR_ENTRY_(name, type, code, text) {(MeI16)(name), (MeI16)(type), MCD_ERROR_REPEAT_COUNT, text},
McdErrorDescription gMcdCoreErrorList[] = {MCD_CORE_ERROR_LIST(MCD_ERROR_ENTRY_)};
#undef MCD_ERROR_ENTRY_

/* Our code for each core error number, in the list's order (ME_ERR_NONE: none corresponds). */
#define MCD_ERROR_CODE_(name, type, code, text) code,
static const MeErrorCode coreCodes[] = {MCD_CORE_ERROR_LIST(MCD_ERROR_CODE_)};
#undef MCD_ERROR_CODE_

/* The entry numbered errorCode, or the list's end entry when the number is not in it. */
static McdErrorDescription *findDescription(McdErrorDescription *list, int errorCode)
{
    McdErrorDescription *d = list;
    while (d->m_errNum != kMcdMAXErrDefined && d->m_errNum != errorCode)
        d++;
    return d;
}

void MEAPI McdError(McdErrorDescription *ErrorList, int errorCode, const char *message, const char *fn,
                    const char *file, int line)
{
    if (!ErrorList) {
        MeReport(ME_ERR_NULL_ARGUMENT, "McdError", __FILE__, __LINE__, "argument 'ErrorList' is NULL; call ignored");
        return;
    }
    McdErrorDescription *d = findDescription(ErrorList, errorCode);
    if (d->m_errorCount <= 0)
        return;
    const char *description = d->m_errNum == errorCode ? d->m_description : "undefined collision error ";
    if (!message)
        message = "";
    if (!fn)
        fn = "McdError";
    MeErrorCode code = ME_ERR_NONE;
    if (ErrorList == gMcdCoreErrorList && d->m_errNum == errorCode && errorCode >= 0 && errorCode <= kMcdMAXErrDefined)
        code = coreCodes[errorCode];
    if (code != ME_ERR_NONE)
        MeReport(code, fn, file ? file : "", line, "%s%s", description, message);
    else if (d->m_errorLevel == kMcdErrorTypeInfo)
        MeInfo(0, "Mcd function %s: %s%s", fn, description, message);
    else /* fatal or warning: never an exit here */
        MeWarning(0, "Mcd function %s: %s%s", fn, description, message);
}
