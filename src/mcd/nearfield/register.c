/* register.c -- McdPrimitivesRegisterInteractions' list of pair tests: every entry of the built-in
 * pair table (table.c) and of the terrain's (terrain/collide.c), one way round; the framework swaps
 * the models at hello when needed. */
#include "../framework.h"
#include "nearfield.h"
#include "../terrain/terrain.h"
#include "../aggregate/aggregate.h"

void McdNearfieldRegisterPrimitives(McdFrameworkData *fw)
{
    int count, k;
    const McdNfPairEntry *table = McdNfPairTable(&count);
    for (k = 0; k < count; k++)
        McdFrameworkSetInteractionWithCache(fw, table[k].type1, table[k].type2, table[k].fn,
                                            McdNfCacheReleaseFor(table[k].fn), "McdPrimitivesRegisterInteractions");
    table = McdTerrainPairTable(&count);
    for (k = 0; k < count; k++)
        McdFrameworkSetInteraction(fw, table[k].type1, table[k].type2, table[k].fn, "McdPrimitivesRegisterInteractions");
    McdAggregateRegisterAll(fw, "McdPrimitivesRegisterInteractions"); /* aggregates against every type */
}
