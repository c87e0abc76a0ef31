/* sort.h -- an in-place sort for the step: qsort's interface without its allocation.
 *
 * glibc's qsort takes a merge buffer from malloc when the array passes a kilobyte, and the step must
 * not allocate (pools are sized at creation). MeSortInPlace is a heapsort (O(n log n) in the worst
 * case, no memory beyond one element on the stack), with a first pass that returns at once when the
 * array is already in order and an insertion sort for 16 elements or fewer. It is not stable, so `compare` must be a total
 * order (Karma's comparators break ties by pool slot), and then the result is the same as qsort's. */
#ifndef KARMA_ME_SORT_H
#define KARMA_ME_SORT_H

#include <stddef.h>

/** Largest element MeSortInPlace handles (bytes); larger elements are an internal error. */
#define ME_SORT_MAX_ELEMENT 64

void MeSortInPlace(void *base, size_t count, size_t size, int (*compare)(const void *, const void *));

#endif /* KARMA_ME_SORT_H */
