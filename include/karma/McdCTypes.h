/* McdCTypes.h -- Karma 1.2's header name: Mcd's C types (IDs, pairs, requests, contacts, callback types). */
#ifndef MCD_CTYPES_H
#define MCD_CTYPES_H

#include "McdTypes.h"
#include "McdContact.h"
#include "McdLineSegment.h"
#include "MePool.h"

#endif /* MCD_CTYPES_H */
