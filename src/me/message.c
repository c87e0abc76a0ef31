/* message.c -- the message hook: codes, levels, counters and the default handler.
 *
 * State is process-wide (handler, level, counters): Karma is not thread-safe, and an application
 * that runs worlds on several threads installs a handler that is. */
#include <stdio.h>
#include <stdlib.h>

#include <karma/MeMessage.h>

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
static unsigned long counts[ME_ERR_CODE_LIMIT_];
static unsigned long levelCounts[ME_LEVEL_FATAL + 1];
static MeErrorCode lastCode = ME_ERR_NONE;

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
    return ((int)code >= 0 && code < ME_ERR_CODE_LIMIT_) ? counts[code] : 0;
}

unsigned long MeMessageGetTotalCount(MeMessageLevel level)
{
    unsigned long total = 0;
    for (int l = (int)level; l <= ME_LEVEL_FATAL; l++)
        total += levelCounts[l];
    return total;
}

void MeMessageResetCounts(void)
{
    for (int i = 0; i < ME_ERR_CODE_LIMIT_; i++)
        counts[i] = 0;
    for (int l = 0; l <= ME_LEVEL_FATAL; l++)
        levelCounts[l] = 0;
    lastCode = ME_ERR_NONE;
}

MeErrorCode MeMessageGetLastCode(void) { return lastCode; }

void MeDefaultMessageHandler(const MeMessageInfo *info, void *user)
{
    static const char *const levelNames[] = {"debug", "info", "warning", "FATAL"};
    (void)user;
    FILE *out = info->level >= ME_LEVEL_WARNING ? stderr : stdout;
    fprintf(out, "Karma %s [%s] in %s: %s\n", levelNames[info->level], MeErrorCodeName(info->code),
            info->function ? info->function : "?", info->text);
    fflush(out);
    if (info->level == ME_LEVEL_FATAL)
        abort();
}

static void dispatch(MeErrorCode code, MeMessageLevel level, const char *function, const char *file, int line,
                     const char *format, va_list args)
{
    char text[512];
    if ((int)code >= 0 && code < ME_ERR_CODE_LIMIT_)
        counts[code]++;
    levelCounts[level]++;
    if (level >= ME_LEVEL_WARNING)
        lastCode = code;
    if (level < minimumLevel && level != ME_LEVEL_FATAL)
        return;
    vsnprintf(text, sizeof text, format, args);
    MeMessageInfo info = {code, level, function, file, line, text};
    currentHandler(&info, currentUser);
}

void MeReportV(MeErrorCode code, const char *function, const char *file, int line, const char *format,
               va_list args)
{
    dispatch(code, MeErrorCodeLevel(code), function, file, line, format, args);
}

void MeReport(MeErrorCode code, const char *function, const char *file, int line, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    MeReportV(code, function, file, line, format, args);
    va_end(args);
}

#define ME_USER_MESSAGE_(fnName, lvl)                                                                  \
    void fnName(int level, const char *format, ...)                                                    \
    {                                                                                                  \
        va_list args;                                                                                  \
        (void)level;                                                                                   \
        va_start(args, format);                                                                        \
        dispatch(ME_ERR_USER_MESSAGE, lvl, #fnName, "application", 0, format, args);                  \
        va_end(args);                                                                                  \
    }

ME_USER_MESSAGE_(MeFatalError, ME_LEVEL_FATAL)
ME_USER_MESSAGE_(MeWarning, ME_LEVEL_WARNING)
ME_USER_MESSAGE_(MeInfo, ME_LEVEL_INFO)
ME_USER_MESSAGE_(MeDebug, ME_LEVEL_DEBUG)
