/* viewer_null_context.h -- a context of the null renderer (-null, nothing drawn) made from
 * command-line options as a Karma program makes it, for the viewer's tests of its API. */
#ifndef KARMA_VIEWER_NULL_CONTEXT_H
#define KARMA_VIEWER_NULL_CONTEXT_H

#include <MeViewer.h>

/** A -null context with up to two more options (NULL: none); the options read are eaten. */
static inline RRender *viewerNullContext(const char *extra1, const char *extra2, int *argcLeft)
{
    const char *argv[4] = {"test", "-null", extra1, extra2};
    int argc = 2 + (extra1 != NULL) + (extra2 != NULL);
    MeCommandLineOptions *o = MeCommandLineOptionsCreate(argc, argv);
    RRender *rc = RRenderContextCreate(o, NULL, METRUE);
    *argcLeft = o ? o->m_argc : -1;
    MeCommandLineOptionsDestroy(o);
    return rc;
}

#endif /* KARMA_VIEWER_NULL_CONTEXT_H */
