/* MeCommandLine.c -- the options object RRenderContextCreate reads. */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "MeCommandLine.h"

MeCommandLineOptions *MEAPI MeCommandLineOptionsCreate(const int argc, const char *argv[])
{
    if (argc < 0 || (argc > 0 && !argv))
        return NULL;
    MeCommandLineOptions *o = malloc(sizeof *o);
    if (!o)
        return NULL;
    o->m_argc = argc;
    o->p_argv = malloc(sizeof *o->p_argv * (size_t)(argc > 0 ? argc : 1));
    if (!o->p_argv) {
        free(o);
        return NULL;
    }
    for (int i = 0; i < argc; i++)
        o->p_argv[i] = argv[i];
    return o;
}

void MEAPI MeCommandLineOptionsDestroy(MeCommandLineOptions *options)
{
    if (!options)
        return;
    free(options->p_argv);
    free(options);
}

void MEAPI MeCommandLineOptionsEat(MeCommandLineOptions *options, const int *eat, const int num_eat)
{
    if (!options || !eat)
        return;
    /* Mark, then compact, so positions refer to the list as it was. */
    for (int k = 0; k < num_eat; k++)
        if (eat[k] >= 0 && eat[k] < options->m_argc)
            options->p_argv[eat[k]] = NULL;
    int n = 0;
    for (int i = 0; i < options->m_argc; i++)
        if (options->p_argv[i])
            options->p_argv[n++] = options->p_argv[i];
    options->m_argc = n;
}

int MEAPI MeCommandLineOptionsGetPos(MeCommandLineOptions *options, const char *arg)
{
    if (!options || !arg)
        return -1;
    for (int i = 0; i < options->m_argc; i++)
        if (strcmp(options->p_argv[i], arg) == 0)
            return i;
    return -1;
}

MeBool MEAPI MeCommandLineOptionsCheckFor(MeCommandLineOptions *options, const char *arg, const MeBool eat)
{
    int pos = MeCommandLineOptionsGetPos(options, arg);
    if (pos < 0)
        return MEFALSE;
    if (eat)
        MeCommandLineOptionsEat(options, &pos, 1);
    return METRUE;
}

MeBool MEAPI MeCommandLineOptionsCheckForList(MeCommandLineOptions *options, const char *arglist[], const MeBool eat)
{
    MeBool found = MEFALSE;
    for (int i = 0; arglist && arglist[i]; i++)
        found = MeCommandLineOptionsCheckFor(options, arglist[i], eat) || found;
    return found;
}

char *MEAPI MeCommandLineOptionsGetString(MeCommandLineOptions *options, const char *arg, const MeBool eat)
{
    int pos = MeCommandLineOptionsGetPos(options, arg);
    if (pos < 0 || pos + 1 >= options->m_argc)
        return NULL;
    const char *value = options->p_argv[pos + 1];
    if (eat) {
        int both[2] = {pos, pos + 1};
        MeCommandLineOptionsEat(options, both, 2);
    }
    return (char *)value; /* Karma's signature; the text is the program's argv */
}

int MEAPI MeCommandLineOptionsGetNumeric(MeCommandLineOptions *options, const char *arg, const MeBool eat)
{
    const char *text = MeCommandLineOptionsGetString(options, arg, MEFALSE);
    char *end;
    long value = text ? strtol(text, &end, 10) : 0;
    if (!text || end == text || *end || value < INT_MIN || value > INT_MAX)
        return -1;
    MeCommandLineOptionsGetString(options, arg, eat);
    return (int)value;
}

double MEAPI MeCommandLineOptionsGetFloat(MeCommandLineOptions *options, const char *arg, const MeBool eat)
{
    const char *text = MeCommandLineOptionsGetString(options, arg, MEFALSE);
    char *end;
    double value = text ? strtod(text, &end) : 0;
    if (!text || end == text || *end)
        return 0;
    MeCommandLineOptionsGetString(options, arg, eat);
    return value;
}
