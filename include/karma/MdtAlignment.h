/* MdtAlignment.h -- Karma 1.2's header for the alignment of Mdt's data. 1.2 aligned its body and
 * constraint structs for the vector units of its consoles; here bodies and constraints are records
 * behind checked IDs that programs never lay out, and the solver's arrays are aligned by the chunks
 * they come from (MeChunk.h). What a program needs for its own data is MePrecision.h's MeALIGNDATA
 * (where the Me layer offers it). */
#ifndef MDT_ALIGNMENT_H
#define MDT_ALIGNMENT_H

#include "MePrecision.h"

#endif /* MDT_ALIGNMENT_H */
