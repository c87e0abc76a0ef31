/* MeMessage.h -- warnings, errors and information from Karma, through one replaceable handler.
 *
 * Every message carries a stable code (MeErrorCodes.h), a level, the name of the API function the
 * application called and a sentence naming the offending argument. Install a handler with
 * MeSetMessageHandler to route messages into a game's log, to count them in tests, or to stop in a
 * debugger. The library never calls exit() on a recoverable error: a bad argument is reported and
 * the call changes nothing. Only ME_LEVEL_FATAL (an internal inconsistency) aborts by default, and
 * a handler may replace even that (for instance with longjmp).
 *
 * Karma's printf-style entry points (MeFatalError, MeWarning, MeInfo, MeDebug) are kept for
 * applications; their messages arrive with code ME_ERR_USER_MESSAGE. */
#ifndef ME_MESSAGE_H
#define ME_MESSAGE_H

#include <stdarg.h>

#include "MeErrorCodes.h"
#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** Severity of a message. */
typedef enum MeMessageLevel {
    ME_LEVEL_DEBUG = 0,   /**< detail for developers (off by default) */
    ME_LEVEL_INFO = 1,    /**< something worth knowing, nothing wrong */
    ME_LEVEL_WARNING = 2, /**< a call was rejected or a result is degraded; the state is consistent */
    ME_LEVEL_FATAL = 3    /**< Karma found itself inconsistent; the default handler aborts */
} MeMessageLevel;

/** Stable message codes, one per distinct problem. */
typedef enum MeErrorCode {
#define ME_ERROR_ENUM_(name, number, level, text) name = number,
    ME_ERROR_LIST(ME_ERROR_ENUM_)
#undef ME_ERROR_ENUM_
    ME_ERR_CODE_LIMIT_ = 1000
} MeErrorCode;

/** Everything known about one message. Strings are valid only during the handler call. */
typedef struct MeMessageInfo {
    MeErrorCode code;
    MeMessageLevel level;
    const char *function; /**< the API function the application called, e.g. "MdtBodySetMass" */
    const char *file;     /**< source file inside Karma that reported it */
    int line;
    const char *text;     /**< a full sentence naming the argument and the value */
} MeMessageInfo;

/** A message handler. `user` is the pointer given to MeSetMessageHandler. */
typedef void (*MeMessageHandler)(const MeMessageInfo *info, void *user);

/** Install a handler (NULL restores the default, which prints warnings and fatal errors to stderr
 *  and aborts on fatal errors). Returns the previous handler; its user pointer goes to *previousUser
 *  when that is not NULL. Process-wide; set it before creating worlds. */
ME_API MeMessageHandler MeSetMessageHandler(MeMessageHandler handler, void *user, void **previousUser);

/** The default handler, for handlers that want to chain to it. */
ME_API void MeDefaultMessageHandler(const MeMessageInfo *info, void *user);

/** Messages below this level are dropped before reaching the handler, but still counted
 *  (default ME_LEVEL_WARNING: information such as chunk growth is shown only when asked for). */
ME_API void MeSetMessageLevel(MeMessageLevel minimum);
ME_API MeMessageLevel MeGetMessageLevel(void);

/** Name ("ME_ERR_POOL_FULL"), description and default level of a code; "unknown" for a bad code. */
ME_API const char *MeErrorCodeName(MeErrorCode code);
ME_API const char *MeErrorCodeDescription(MeErrorCode code);
ME_API MeMessageLevel MeErrorCodeLevel(MeErrorCode code);

/** How many messages with this code were reported since start or the last MeMessageResetCounts
 *  (counted even when below the message level). */
ME_API unsigned long MeMessageGetCount(MeErrorCode code);
ME_API unsigned long MeMessageGetTotalCount(MeMessageLevel minimumLevel);
ME_API void MeMessageResetCounts(void);

/** The code of the most recent message at warning level or above (ME_ERR_NONE if none). */
ME_API MeErrorCode MeMessageGetLastCode(void);

/* Karma's printf-style functions. `level` is Karma's verbosity number, passed through in the text. */
ME_API void MeFatalError(int level, const char *format, ...);
ME_API void MeWarning(int level, const char *format, ...);
ME_API void MeInfo(int level, const char *format, ...);
ME_API void MeDebug(int level, const char *format, ...);

/** Report a message with a code. Used by the library (through macros that add the function and
 *  place) and available to extensions such as user geometry types. `function` names the API call. */
ME_API void MeReport(MeErrorCode code, const char *function, const char *file, int line,
                     const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;
ME_API void MeReportV(MeErrorCode code, const char *function, const char *file, int line,
                      const char *format, va_list args);

ME_EXTERN_C_END

#endif /* ME_MESSAGE_H */
