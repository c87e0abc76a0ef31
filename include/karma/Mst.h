/* Mst.h -- Karma's bridge (Mst): collision and dynamics joined; the universe. */
#ifndef MST_H
#define MST_H

#include "MstBridge.h"
#include "MstUniverse.h"

#endif /* MST_H */
