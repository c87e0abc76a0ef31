/* MstUtils.h -- Karma 1.2's header for the bridge's helpers: models made with their bodies, fixed
 * models, mass properties from geometry, the world handlers and the bridge's stages. They are
 * declared in MstUniverse.h and MstBridge.h; this header brings both in. */
#ifndef MST_UTILS_H
#define MST_UTILS_H

#include "MstBridge.h"
#include "MstUniverse.h"

#endif /* MST_UTILS_H */
