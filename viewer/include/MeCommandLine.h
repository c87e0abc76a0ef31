/* MeCommandLine.h -- Karma's command-line options object: a program hands its argc/argv to
 * MeCommandLineOptionsCreate and passes the result to RRenderContextCreate, which reads the viewer's
 * options (-gl, -null, -headless, -timeout N, -size WxH, -wireframe, ...). */
#ifndef ME_COMMAND_LINE_H
#define ME_COMMAND_LINE_H

#include <karma/MePrecision.h>
#include <karma/MeCall.h>

ME_EXTERN_C_BEGIN

/** A copy of a program's arguments (argv[0] excluded is not: all argc entries are kept). */
typedef struct MeCommandLineOptions {
    int m_argc;
    const char **p_argv;
} MeCommandLineOptions;

/** Copy argc/argv (the strings are not copied: they must outlive the options). NULL when argc < 0,
 *  argv is NULL with argc > 0, or memory runs out. */
MeCommandLineOptions *MEAPI MeCommandLineOptionsCreate(const int argc, const char *argv[]);
/** Free the options (NULL is accepted). */
void MEAPI MeCommandLineOptionsDestroy(MeCommandLineOptions *options);
/** Remove the arguments at positions eat[0..num_eat-1] (out-of-range positions are ignored). */
void MEAPI MeCommandLineOptionsEat(MeCommandLineOptions *options, const int *eat, const int num_eat);
/** Position of `arg` among the arguments, or −1. */
int MEAPI MeCommandLineOptionsGetPos(MeCommandLineOptions *options, const char *arg);
/** Whether `arg` is present; with `eat` true it is removed. */
MeBool MEAPI MeCommandLineOptionsCheckFor(MeCommandLineOptions *options, const char *arg, const MeBool eat);
/** Whether any of the NULL-terminated `arglist` is present; with `eat` true those present are removed. */
MeBool MEAPI MeCommandLineOptionsCheckForList(MeCommandLineOptions *options, const char *arglist[], const MeBool eat);
/** The argument following `arg` (NULL when absent; points into argv); with `eat` true both are removed. */
char *MEAPI MeCommandLineOptionsGetString(MeCommandLineOptions *options, const char *arg, const MeBool eat);
/** The integer following `arg`, or −1 when absent or not a number (then nothing is eaten). */
int MEAPI MeCommandLineOptionsGetNumeric(MeCommandLineOptions *options, const char *arg, const MeBool eat);
/** The number following `arg`, or 0 when absent or not a number (then nothing is eaten). */
double MEAPI MeCommandLineOptionsGetFloat(MeCommandLineOptions *options, const char *arg, const MeBool eat);

ME_EXTERN_C_END

#endif /* ME_COMMAND_LINE_H */
