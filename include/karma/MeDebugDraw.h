/* MeDebugDraw.h -- the line-drawing hook through which Karma draws debugging information (contacts,
 * forces, bounding boxes). A renderer fills MeDebugDrawAPI.line; by default it draws nothing. */
#ifndef ME_DEBUG_DRAW_H
#define ME_DEBUG_DRAW_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** Draw a line from start to end (world coordinates) in colour (r, g, b), each 0..1. */
typedef void(MEAPI *MeDebugLineFuncPtr)(MeVector3 start, MeVector3 end, MeReal r, MeReal g, MeReal b);

/** The drawing hooks. */
typedef struct MeDebugDrawAPIStruct {
    MeDebugLineFuncPtr line; /**< never NULL in the library's copy: a no-op until replaced */
} MeDebugDrawAPIStruct;

/** The hooks in use; assign MeDebugDrawAPI.line to draw. Process-wide; set it before stepping. */
ME_API extern MeDebugDrawAPIStruct MeDebugDrawAPI;

ME_EXTERN_C_END

#endif /* ME_DEBUG_DRAW_H */
