/* McdModelPairContainer.h -- Karma 1.2's header name: model pair containers (declared with the space, McdSpace.h). */
#ifndef MCD_MODEL_PAIR_CONTAINER_H
#define MCD_MODEL_PAIR_CONTAINER_H

#include "McdSpace.h"

#endif /* MCD_MODEL_PAIR_CONTAINER_H */
