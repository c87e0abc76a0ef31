/* McdInteractionTable.h -- Karma 1.2's header name: the interaction table (McdFrameworkSetUserInteraction, McdFrame.h; pair calls, McdInteraction.h). */
#ifndef MCD_INTERACTION_TABLE_H
#define MCD_INTERACTION_TABLE_H

#include "McdFrame.h"
#include "McdInteraction.h"

#endif /* MCD_INTERACTION_TABLE_H */
