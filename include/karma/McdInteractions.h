/* McdInteractions.h -- Karma 1.2's header name: the pair tests' entry points (McdHello, McdIntersect, McdGoodbye and the ...Each helpers). */
#ifndef MCD_INTERACTIONS_H
#define MCD_INTERACTIONS_H

#include "McdInteraction.h"

#endif /* MCD_INTERACTIONS_H */
