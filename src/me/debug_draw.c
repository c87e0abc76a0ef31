/* debug_draw.c -- the default (silent) debug-drawing hooks (see MeDebugDraw.h). */
#include <karma/MeDebugDraw.h>

static void MEAPI drawNothing(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b)
{
    (void)start;
    (void)end;
    (void)r;
    (void)g;
    (void)b;
}

MeDebugDrawAPIStruct MeDebugDrawAPI = {drawNothing};
