/* Mst.h -- Karma's bridge (Mst): collision and dynamics joined; the universe. As in Karma 1.2 it
 * brings in the whole of Karma Dynamics (Mdt.h) and Karma Collision (Mcd.h). */
#ifndef MST_H
#define MST_H

#include "Mcd.h"
#include "Mdt.h"
#include "MstBridge.h"
#include "MstModelDynamics.h"
#include "MstTypes.h"
#include "MstUniverse.h"
#include "MstUtils.h"

#endif /* MST_H */
