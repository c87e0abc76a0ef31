/* McdCullingTable.h -- Karma 1.2's header name: culling tables (declared with the space, McdSpace.h). */
#ifndef MCD_CULLING_TABLE_H
#define MCD_CULLING_TABLE_H

#include "McdSpace.h"

#endif /* MCD_CULLING_TABLE_H */
