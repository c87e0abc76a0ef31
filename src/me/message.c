/* message.c -- the message hook: codes, levels, counters, the default handler and Karma 1.2's
 * per-kind handlers and output functions.
 *
 * Reporting may happen on several threads at once (worlds stepping in parallel): the counters and
 * the last code are atomic, and the default handler formats into a buffer of its own call. The
 * handler, the level and the 1.2 hooks are written only by the application, before threads start;
 * a handler installed for threaded use must itself be thread-safe. */
#include <limits.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <karma/MeMessage.h>

#include "check.h"

typedef struct MeErrorEntry {
    MeErrorCode code;
    const char *name;
    MeMessageLevel level;
    const char *description;
} MeErrorEntry;

static const MeErrorEntry errorTable[] = {
#define ME_ERROR_ENTRY_(name, number, level, text) {name, #name, level, text},
    ME_ERROR_LIST(ME_ERROR_ENTRY_)
#undef ME_ERROR_ENTRY_
};
enum { ERROR_TABLE_SIZE = sizeof errorTable / sizeof errorTable[0] };

static MeMessageHandler currentHandler = MeDefaultMessageHandler;
static void *currentUser = NULL;
/* Information (a chunk grew) is counted but not shown unless asked for: a quiet default run. */
static MeMessageLevel minimumLevel = ME_LEVEL_WARNING;
static atomic_ulong counts[ME_ERR_CODE_LIMIT_];
static atomic_ulong levelCounts[ME_LEVEL_FATAL + 1];
static atomic_int lastCode = ME_ERR_NONE;

static const MeErrorEntry *findEntry(MeErrorCode code)
{
    for (int i = 0; i < ERROR_TABLE_SIZE; i++)
        if (errorTable[i].code == code)
            return &errorTable[i];
    return NULL;
}

MeMessageHandler MeSetMessageHandler(MeMessageHandler handler, void *user, void **previousUser)
{
    MeMessageHandler previous = currentHandler;
    if (previousUser)
        *previousUser = currentUser;
    currentHandler = handler ? handler : MeDefaultMessageHandler;
    currentUser = handler ? user : NULL;
    return previous;
}

void MeSetMessageLevel(MeMessageLevel minimum) { minimumLevel = minimum; }
MeMessageLevel MeGetMessageLevel(void) { return minimumLevel; }

const char *MeErrorCodeName(MeErrorCode code)
{
    const MeErrorEntry *e = findEntry(code);
    return e ? e->name : "unknown";
}

const char *MeErrorCodeDescription(MeErrorCode code)
{
    const MeErrorEntry *e = findEntry(code);
    return e ? e->description : "unknown";
}

MeMessageLevel MeErrorCodeLevel(MeErrorCode code)
{
    const MeErrorEntry *e = findEntry(code);
    return e ? e->level : ME_LEVEL_WARNING;
}

unsigned long MeMessageGetCount(MeErrorCode code)
{
    return ((int)code >= 0 && code < ME_ERR_CODE_LIMIT_) ? atomic_load(&counts[code]) : 0;
}

unsigned long MeMessageGetTotalCount(MeMessageLevel level)
{
    unsigned long total = 0;
    for (int l = (int)level; l <= ME_LEVEL_FATAL; l++)
        total += atomic_load(&levelCounts[l]);
    return total;
}

void MeMessageResetCounts(void)
{
    for (int i = 0; i < ME_ERR_CODE_LIMIT_; i++)
        atomic_store(&counts[i], 0);
    for (int l = 0; l <= ME_LEVEL_FATAL; l++)
        atomic_store(&levelCounts[l], 0);
    atomic_store(&lastCode, ME_ERR_NONE);
}

/* A repeat of a message already reported once (check.h, ME_REPORT_ONCE_IN): counted, not shown. */
void MeMessageCountRepeat(MeErrorCode code)
{
    if ((int)code >= 0 && code < ME_ERR_CODE_LIMIT_) {
        atomic_fetch_add(&counts[code], 1);
        atomic_fetch_add(&levelCounts[MeErrorCodeLevel(code)], 1);
    }
}

MeErrorCode MeMessageGetLastCode(void) { return (MeErrorCode)atomic_load(&lastCode); }

/* ------------------------------------------------------------------ Karma 1.2's output functions */

MeShow MeInfoShow = MeShowStdout;
MeShow MeLogShow = MeShowStdout;
MeShow MeWarningShow = MeShowStderr;
MeShow MeFatalErrorShow = MeShowStderr;
MeShow MeDebugShow = MeShowStdout;

void MEAPI MeShowStdout(const int level, const char *const string)
{
    (void)level;
    fprintf(stdout, "%s\n", string);
    fflush(stdout);
}

void MEAPI MeShowStderr(const int level, const char *const string)
{
    (void)level;
    fprintf(stderr, "%s\n", string);
    fflush(stderr);
}

/* A 1.2 setter: install n (NULL: the default) and return what was there. */
#define ME_SETTER_(type, fnName, variable, fallback)                                                   \
    type MEAPI fnName(type n)                                                                          \
    {                                                                                                  \
        type previous = variable;                                                                      \
        variable = n ? n : fallback;                                                                   \
        return previous;                                                                               \
    }
ME_SETTER_(MeShow, MeSetInfoShow, MeInfoShow, MeShowStdout)
ME_SETTER_(MeShow, MeSetLogShow, MeLogShow, MeShowStdout)
ME_SETTER_(MeShow, MeSetWarningShow, MeWarningShow, MeShowStderr)
ME_SETTER_(MeShow, MeSetFatalErrorShow, MeFatalErrorShow, MeShowStderr)
ME_SETTER_(MeShow, MeSetDebugShow, MeDebugShow, MeShowStdout)

/* The function name the log kind reports under; the default handler routes it to MeLogShow. */
static const char logFunctionName[] = "MeLog";

static MeShow showFor(const MeMessageInfo *info)
{
    switch (info->level) {
    case ME_LEVEL_DEBUG: return MeDebugShow;
    case ME_LEVEL_INFO: return info->function == logFunctionName ? MeLogShow : MeInfoShow;
    case ME_LEVEL_WARNING: return MeWarningShow;
    default: return MeFatalErrorShow;
    }
}

void MeDefaultMessageHandler(const MeMessageInfo *info, void *user)
{
    static const char *const levelNames[] = {"debug", "info", "warning", "FATAL"};
    char line[MeMAXMESSAGE + 128];
    (void)user;
    snprintf(line, sizeof line, "Karma %s [%s] in %s: %s", levelNames[info->level], MeErrorCodeName(info->code),
             info->function ? info->function : "?", info->text);
    showFor(info)(0, line);
    if (info->level == ME_LEVEL_FATAL)
        abort();
}

/* Counts the message and hands it to the handler; `info` says all but the text, which is made here
 * from format and args only when the message is shown. */
static void dispatch(MeMessageInfo info, const char *format, va_list args)
{
    char text[MeMAXMESSAGE];
    if ((int)info.code >= 0 && info.code < ME_ERR_CODE_LIMIT_)
        atomic_fetch_add(&counts[info.code], 1);
    atomic_fetch_add(&levelCounts[info.level], 1);
    if (info.level >= ME_LEVEL_WARNING)
        atomic_store(&lastCode, (int)info.code);
    if (info.level < minimumLevel && info.level != ME_LEVEL_FATAL)
        return;
    vsnprintf(text, sizeof text, format, args);
    info.text = text;
    currentHandler(&info, currentUser);
}

void MeReportV(MeErrorCode code, const char *function, const char *file, int line, const char *format,
               va_list args)
{
    dispatch((MeMessageInfo){code, MeErrorCodeLevel(code), function, file, line, NULL}, format, args);
}

void MeReport(MeErrorCode code, const char *function, const char *file, int line, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    MeReportV(code, function, file, line, format, args);
    va_end(args);
}

/* ---------------------------------------------------------------- Karma 1.2's kind handlers */

int MeInfoLevel = INT_MAX;
int MeLogLevel = INT_MAX;
int MeWarningLevel = INT_MAX;
int MeFatalErrorLevel = INT_MAX;
int MeDebugLevel = INT_MAX;

#define ME_KIND_HANDLER_(fnName, cutoff, lvl, name, alwaysShown)                                       \
    void MEAPI fnName(const int level, const char *const format, va_list ap)                          \
    {                                                                                                  \
        if (level > (cutoff) && !(alwaysShown))                                                        \
            return;                                                                                    \
        dispatch((MeMessageInfo){ME_ERR_USER_MESSAGE, lvl, name, "application", 0, NULL}, format, ap); \
    }
ME_KIND_HANDLER_(MeHandlerInfo, MeInfoLevel, ME_LEVEL_INFO, "MeInfo", 0)
ME_KIND_HANDLER_(MeHandlerLog, MeLogLevel, ME_LEVEL_INFO, logFunctionName, 0)
ME_KIND_HANDLER_(MeHandlerWarning, MeWarningLevel, ME_LEVEL_WARNING, "MeWarning", 0)
ME_KIND_HANDLER_(MeHandlerFatalError, MeFatalErrorLevel, ME_LEVEL_FATAL, "MeFatalError", 1)
ME_KIND_HANDLER_(MeHandlerDebug, MeDebugLevel, ME_LEVEL_DEBUG, "MeDebug", 0)

MeHandler MeInfoHandler = MeHandlerInfo;
MeHandler MeLogHandler = MeHandlerLog;
MeHandler MeWarningHandler = MeHandlerWarning;
MeHandler MeFatalErrorHandler = MeHandlerFatalError;
MeHandler MeDebugHandler = MeHandlerDebug;

ME_SETTER_(MeHandler, MeSetInfoHandler, MeInfoHandler, MeHandlerInfo)
ME_SETTER_(MeHandler, MeSetLogHandler, MeLogHandler, MeHandlerLog)
ME_SETTER_(MeHandler, MeSetWarningHandler, MeWarningHandler, MeHandlerWarning)
ME_SETTER_(MeHandler, MeSetFatalErrorHandler, MeFatalErrorHandler, MeHandlerFatalError)
ME_SETTER_(MeHandler, MeSetDebugHandler, MeDebugHandler, MeHandlerDebug)

#define ME_USER_MESSAGE_(fnName, handler)                                                              \
    void MEAPI fnName(const int level, const char *const format, ...)                                 \
    {                                                                                                  \
        va_list args;                                                                                  \
        va_start(args, format);                                                                        \
        (handler)(level, format, args);                                                                \
        va_end(args);                                                                                  \
    }

ME_USER_MESSAGE_(MeInfo, MeInfoHandler)
ME_USER_MESSAGE_(MeLog, MeLogHandler)
ME_USER_MESSAGE_(MeWarning, MeWarningHandler)
ME_USER_MESSAGE_(MeFatalError, MeFatalErrorHandler)
ME_USER_MESSAGE_(MeDebug, MeDebugHandler)

char *MEAPI MeShortenPath(char *path)
{
    char *slash, *backslash;
    if (!path)
        return path;
    slash = strrchr(path, '/');
    backslash = strrchr(path, '\\');
    if (backslash > slash)
        slash = backslash;
    return slash ? slash + 1 : path;
}
