/* poolx.c -- MePoolx: records in caller memory with an intrusive free list (see MePoolx.h).
 *
 * Records are handed out lazily: `ifree` starts at record 0, which is marked -1 ("the rest is
 * untouched"). Taking a record marked -1 moves the mark to the next record; a record put back
 * stores the index of the previous first free record in its first int. */
#include <string.h>

#include <karma/MePoolx.h>

#include "check.h"

#define UNTOUCHED (-1)

void MePoolxInit(MePoolx *p, void *memory, int recsize, int numrec)
{
    if (!p || !memory || numrec <= 0 || recsize < (int)(2 * sizeof(int)) || recsize % (int)sizeof(int) != 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "MePoolxInit needs memory, numrec > 0 and recsize a multiple of "
                  "sizeof(int), at least two ints (got recsize %d, numrec %d)", recsize, numrec);
        if (p)
            memset(p, 0, sizeof *p);
        return;
    }
    p->mem = memory;
    p->isize = recsize / (int)sizeof(int);
    p->numrec = numrec;
    p->numfree = numrec;
    p->ifree = 0;
    p->mem[0] = UNTOUCHED;
}

void *MePoolxGet(MePoolx *p)
{
    int *record;
    if (!p || p->numfree == 0)
        return NULL;
    record = p->mem + p->ifree;
    p->numfree--;
    if (p->numfree > 0) {
        if (record[0] == UNTOUCHED) {
            p->ifree += p->isize;
            p->mem[p->ifree] = UNTOUCHED;
        } else {
            p->ifree = record[0];
        }
    }
    return record;
}

void *MePoolxGetZeroed(MePoolx *p)
{
    void *record = MePoolxGet(p);
    if (record)
        memset(record, 0, (size_t)p->isize * sizeof(int));
    return record;
}

void MePoolxPut(MePoolx *p, void *rec)
{
    int index;
    if (!p || !rec)
        return;
    index = (int)((int *)rec - p->mem);
    if (index < 0 || index >= p->numrec * p->isize || index % p->isize != 0 || p->numfree == p->numrec) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'rec' is not a record handed out by this pool; ignored");
        return;
    }
    /* With no record free, ifree is stale; the count keeps Get from ever following that link. */
    ((int *)rec)[0] = p->ifree;
    p->ifree = index;
    p->numfree++;
}
