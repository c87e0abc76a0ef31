/* MeMessage.h -- warnings, errors and information from Karma, through one replaceable handler.
 *
 * Every message carries a stable code (MeErrorCodes.h), a level, the name of the API function the
 * application called and a sentence naming the offending argument. Install a handler with
 * MeSetMessageHandler to route messages into a game's log, to count them in tests, or to stop in a
 * debugger. The library never calls exit() on a recoverable error: a bad argument is reported and
 * the call changes nothing. Only ME_LEVEL_FATAL (an internal inconsistency) aborts by default, and
 * a handler may replace even that (for instance with longjmp).
 *
 * Karma 1.2's printf-style entry points (MeFatalError, MeWarning, MeInfo, MeDebug, MeLog) are kept
 * for applications, with 1.2's per-kind handler and output hooks (MeSetInfoHandler, MeSetInfoShow...)
 * mapped onto the one handler: MeInfo calls MeInfoHandler, whose default (MeHandlerInfo) formats the
 * text and reports it with code ME_ERR_USER_MESSAGE; the default message handler writes every
 * message through the output function of its level (MeInfoShow, MeWarningShow...). Handlers, output
 * functions and levels are process-wide and are set before threads start (as in 1.2); reporting and
 * the counters are thread-safe. */
#ifndef ME_MESSAGE_H
#define ME_MESSAGE_H

#include <stdarg.h>

#include "MeCall.h"
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
/** The level below which messages are dropped before the handler (MeSetMessageLevel). */
ME_API MeMessageLevel MeGetMessageLevel(void);

/** Name ("ME_ERR_POOL_FULL"), description and default level of a code; "unknown" for a bad code. */
ME_API const char *MeErrorCodeName(MeErrorCode code);
/** One-line description of a code (static string, not to be freed); "unknown" for a bad code. */
ME_API const char *MeErrorCodeDescription(MeErrorCode code);
/** The level a code is reported at; ME_LEVEL_WARNING for a bad code. */
ME_API MeMessageLevel MeErrorCodeLevel(MeErrorCode code);

/** How many messages with this code were reported since start or the last MeMessageResetCounts
 *  (counted even when below the message level). */
ME_API unsigned long MeMessageGetCount(MeErrorCode code);
/** How many messages at minimumLevel or above were reported since start or the last reset. */
ME_API unsigned long MeMessageGetTotalCount(MeMessageLevel minimumLevel);
/** Zero every code's count and forget the last code. */
ME_API void MeMessageResetCounts(void);

/** The code of the most recent message at warning level or above (ME_ERR_NONE if none). */
ME_API MeErrorCode MeMessageGetLastCode(void);

/* ------------------------------------------------------------- Karma 1.2's printf-style messages */

/** Longest text of one message, in characters (longer texts are cut). */
#define MeMAXMESSAGE 5000

/** Verbosity cut-offs of the default kind handlers: MeInfo(level, ...) with level > MeInfoLevel is
 *  dropped (fatal errors always pass). Default: INT_MAX (everything passes). */
ME_API extern int MeInfoLevel;
ME_API extern int MeLogLevel;
ME_API extern int MeWarningLevel;
ME_API extern int MeFatalErrorLevel;
ME_API extern int MeDebugLevel;

/** An output function: writes one finished message (no trailing newline in `string`). */
typedef void(MEAPI *MeShow)(const int level, const char *const string);
/** The output function of each kind, used by the default message handler (warnings and fatal errors:
 *  MeShowStderr; the others: MeShowStdout). Assign directly or through MeSet...Show. */
ME_API extern MeShow MeInfoShow;
ME_API extern MeShow MeLogShow;
ME_API extern MeShow MeWarningShow;
ME_API extern MeShow MeFatalErrorShow;
ME_API extern MeShow MeDebugShow;

/** Write string and a newline to stdout / stderr. */
ME_API void MEAPI MeShowStdout(const int level, const char *const string);
/** Write string and a newline to stderr (level unused). */
ME_API void MEAPI MeShowStderr(const int level, const char *const string);

/** A kind handler: receives MeInfo's (or MeWarning's...) level, format and arguments. */
typedef void(MEAPI *MeHandler)(const int level, const char *const format, va_list ap);
/** The handler each kind of message goes to (defaults: MeHandlerInfo...). */
ME_API extern MeHandler MeInfoHandler;
ME_API extern MeHandler MeLogHandler;
ME_API extern MeHandler MeWarningHandler;
ME_API extern MeHandler MeFatalErrorHandler;
ME_API extern MeHandler MeDebugHandler;

/** The default kind handlers: drop the message when level exceeds the kind's cut-off, else format it
 *  and report it with ME_ERR_USER_MESSAGE at the kind's level (log messages at info level). */
ME_API void MEAPI MeHandlerInfo(const int level, const char *const format, va_list ap);
/** Default MeLog handler: dropped when level > MeLogLevel, else an info message through the message handler. */
ME_API void MEAPI MeHandlerLog(const int level, const char *const format, va_list ap);
/** Default MeWarning handler: dropped when level > MeWarningLevel, else a warning (ME_ERR_USER_MESSAGE). */
ME_API void MEAPI MeHandlerWarning(const int level, const char *const format, va_list ap);
/** Default MeFatalError handler: always a fatal message (the default message handler then aborts). */
ME_API void MEAPI MeHandlerFatalError(const int level, const char *const format, va_list ap);
/** Default MeDebug handler: dropped when level > MeDebugLevel, else a debug message. */
ME_API void MEAPI MeHandlerDebug(const int level, const char *const format, va_list ap);

/** Replace a kind's output function or handler (NULL restores the default); returns the previous. */
ME_API MeShow MEAPI MeSetInfoShow(MeShow n);
/** Replace MeLog's output function (NULL: the default); returns the previous one. */
ME_API MeShow MEAPI MeSetLogShow(MeShow n);
/** Replace MeWarning's output function (NULL: the default, stderr); returns the previous one. */
ME_API MeShow MEAPI MeSetWarningShow(MeShow n);
/** Replace MeFatalError's output function (NULL: the default, stderr); returns the previous one. */
ME_API MeShow MEAPI MeSetFatalErrorShow(MeShow n);
/** Replace MeDebug's output function (NULL: the default); returns the previous one. */
ME_API MeShow MEAPI MeSetDebugShow(MeShow n);
/** Replace MeInfo's kind handler (NULL: MeHandlerInfo); returns the previous one. */
ME_API MeHandler MEAPI MeSetInfoHandler(MeHandler n);
/** Replace MeLog's kind handler (NULL: MeHandlerLog); returns the previous one. */
ME_API MeHandler MEAPI MeSetLogHandler(MeHandler n);
/** Replace MeWarning's kind handler (NULL: MeHandlerWarning); returns the previous one. */
ME_API MeHandler MEAPI MeSetWarningHandler(MeHandler n);
/** Replace MeFatalError's kind handler (NULL: MeHandlerFatalError); returns the previous one. */
ME_API MeHandler MEAPI MeSetFatalErrorHandler(MeHandler n);
/** Replace MeDebug's kind handler (NULL: MeHandlerDebug); returns the previous one. */
ME_API MeHandler MEAPI MeSetDebugHandler(MeHandler n);

/* Karma's printf-style functions: each calls its kind's handler. `level` is the verbosity number. */
/** printf-style information message through MeInfoHandler (shown when level ≤ MeInfoLevel). */
ME_API void MEAPI MeInfo(const int level, const char *const format, ...);
/** printf-style log message through MeLogHandler (shown when level ≤ MeLogLevel). */
ME_API void MEAPI MeLog(const int level, const char *const format, ...);
/** printf-style warning through MeWarningHandler (code ME_ERR_USER_MESSAGE; shown when level ≤ MeWarningLevel). */
ME_API void MEAPI MeWarning(const int level, const char *const format, ...);
/** printf-style fatal error through MeFatalErrorHandler (the default message handler aborts after printing). */
ME_API void MEAPI MeFatalError(const int level, const char *const format, ...);
/** printf-style debug message through MeDebugHandler (shown when level ≤ MeDebugLevel). */
ME_API void MEAPI MeDebug(const int level, const char *const format, ...);

/** The file name part of path (a pointer into it). */
ME_API char *MEAPI MeShortenPath(char *path);

/** ME_REPORT(statement): run a reporting statement, prefixed by an information line giving the
 *  source place, in checking builds (_MECHECK defined); nothing otherwise. */
#ifdef _MECHECK
#  define ME_REPORT(x)                                                                               \
      do {                                                                                           \
          MeInfo(0, "(%s line %d):", __FILE__, __LINE__);                                            \
          x;                                                                                         \
      } while (0)
#else
#  define ME_REPORT(x)                                                                               \
      do {                                                                                           \
      } while (0)
#endif

/** Report a message with a code. Used by the library (through macros that add the function and
 *  place) and available to extensions such as user geometry types. `function` names the API call. */
ME_API void MeReport(MeErrorCode code, const char *function, const char *file, int line,
                     const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;
/** MeReport with a va_list instead of the variable arguments. */
ME_API void MeReportV(MeErrorCode code, const char *function, const char *file, int line,
                      const char *format, va_list args);

ME_EXTERN_C_END

#endif /* ME_MESSAGE_H */
