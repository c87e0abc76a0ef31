/* sort.c -- heapsort with qsort's interface (see sort.h). */
#include <string.h>

#include "sort.h"

static void swapElements(unsigned char *a, unsigned char *b, size_t size)
{
    unsigned char t[ME_SORT_MAX_ELEMENT];
    memcpy(t, a, size);
    memcpy(a, b, size);
    memcpy(b, t, size);
}

/* Restore the max-heap below `root` in the first `count` elements. */
static void siftDown(unsigned char *base, size_t root, size_t count, size_t size,
                     int (*compare)(const void *, const void *))
{
    for (;;) {
        size_t child = 2 * root + 1;
        if (child >= count)
            return;
        if (child + 1 < count && compare(base + child * size, base + (child + 1) * size) < 0)
            ++child;
        if (compare(base + root * size, base + child * size) >= 0)
            return;
        swapElements(base + root * size, base + child * size, size);
        root = child;
    }
}

void MeSortInPlace(void *base, size_t count, size_t size, int (*compare)(const void *, const void *))
{
    unsigned char *bytes = base;
    size_t i;
    if (count < 2 || size == 0 || size > ME_SORT_MAX_ELEMENT)
        return;
    /* Already in order (bodies gathered in pool order with equal sort keys, say): one pass. */
    for (i = 1; i < count && compare(bytes + (i - 1) * size, bytes + i * size) <= 0; ++i)
        continue;
    if (i == count)
        return;
    if (count <= 16) { /* short lists: insertion sort from the first element out of order */
        for (; i < count; ++i)
            for (size_t j = i; j > 0 && compare(bytes + (j - 1) * size, bytes + j * size) > 0; --j)
                swapElements(bytes + (j - 1) * size, bytes + j * size, size);
        return;
    }
    for (i = count / 2; i-- > 0;)
        siftDown(bytes, i, count, size, compare);
    for (i = count - 1; i > 0; --i) {
        swapElements(bytes, bytes + i * size, size);
        siftDown(bytes, 0, i, size, compare);
    }
}
