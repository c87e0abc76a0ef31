/* karma.h -- the whole Karma SDK in one include.
 *
 * Layers (each usable alone): Me (common: maths, memory, messages, profiling), Mdt (dynamics),
 * Mcd (collision), Mst (the bridge joining them). See docs/ for the user guide. */
#ifndef KARMA_H
#define KARMA_H

#include "MeChunk.h"
#include "MeMath.h"
#include "MeMemory.h"
#include "MeMessage.h"
#include "MePool.h"
#include "MePrecision.h"
#include "MeProfile.h"
#include "MeVersion.h"
#include "Mdt.h"
#include "Mcd.h"
#include "Mst.h"

#endif /* KARMA_H */
