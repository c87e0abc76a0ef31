/* MePoolx.h -- a pool of equal-sized records in memory the caller provides (a stack array, a
 * chunk): no allocation at all. Get and put are O(1); a record is any size from 2 ints up, in
 * whole ints. */
#ifndef ME_POOLX_H
#define ME_POOLX_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** The pool's bookkeeping; its memory is the caller's. */
typedef struct _MePoolx {
    int *mem;    /**< all records */
    int isize;   /**< record size in ints */
    int numrec;  /**< number of records */
    int numfree; /**< records not handed out */
    int ifree;   /**< int index of the first free record */
} MePoolx;

/** Manage numrec records of recsize bytes (a multiple of sizeof(int), at least 2 ints) at memory. */
ME_API void MePoolxInit(MePoolx *p, void *memory, int recsize, int numrec);
/** A record, or NULL when all are in use (contents undefined). */
ME_API void *MePoolxGet(MePoolx *p);
/** A zeroed record, or NULL. */
ME_API void *MePoolxGetZeroed(MePoolx *p);
/** Give a record back. */
ME_API void MePoolxPut(MePoolx *p, void *rec);

ME_EXTERN_C_END

#endif /* ME_POOLX_H */
