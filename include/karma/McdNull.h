/* McdNull.h -- the null geometry: a placeholder with no extent, that touches nothing. */
#ifndef MCD_NULL_H
#define MCD_NULL_H

#include "McdTypes.h"

ME_EXTERN_C_BEGIN

typedef McdGeometryID McdNullID;

/** A geometry that touches nothing (a model kept in the space without collisions); NULL (reported)
 *  when the framework's geometry pool is full. */
ME_API McdNullID McdNullCreate(McdFrameworkID fw);

ME_EXTERN_C_END

#endif /* MCD_NULL_H */
