/* MeSortInPlace (src/me/sort.c): the step's allocation-free sort gives exactly qsort's order for a
 * total order, on random, sorted, reversed and constant-key inputs, for pointer-sized and larger
 * elements. */
#include "karma_test.h"

#include <stdlib.h>
#include <string.h>

#include "me/sort.h"

typedef struct Record {
    double key;  /* many equal keys: ties broken by slot, as Karma's comparators do */
    int slot;
    int payload[3];
} Record;

static int compareRecords(const void *pa, const void *pb)
{
    const Record *a = pa, *b = pb;
    if (a->key != b->key)
        return a->key < b->key ? -1 : 1;
    return (a->slot > b->slot) - (a->slot < b->slot);
}

static int compareLongs(const void *pa, const void *pb)
{
    const long a = *(const long *)pa, b = *(const long *)pb;
    return (a > b) - (a < b);
}

static unsigned long lcg(unsigned long *s)
{
    *s = *s * 6364136223846793005ul + 1442695040888963407ul;
    return *s >> 33;
}

/* pattern 0 random, 1 ascending, 2 descending, 3 all keys equal */
static void fillRecords(Record *r, int n, int pattern, unsigned long *seed)
{
    for (int i = 0; i < n; i++) {
        r[i].slot = (int)((unsigned long)i * 7919u % 10007u); /* distinct (10007 is prime, n < 10007) */
        switch (pattern) {
        case 0: r[i].key = (double)(lcg(seed) % 17u); break;
        case 1: r[i].key = (double)i; break;
        case 2: r[i].key = (double)(n - i); break;
        default: r[i].key = 1.0; break;
        }
        r[i].payload[0] = i;
        r[i].payload[1] = -i;
        r[i].payload[2] = 3 * i;
    }
}

static void records_match_qsort(void **state)
{
    (void)state;
    static Record a[2100], b[2100];
    unsigned long seed = 12345;
    const int sizes[] = {0, 1, 2, 3, 7, 64, 129, 1000, 2049};
    int checked = 0;
    for (size_t s = 0; s < sizeof sizes / sizeof sizes[0]; s++)
        for (int pattern = 0; pattern < 4; pattern++) {
            const int n = sizes[s];
            fillRecords(a, n, pattern, &seed);
            memcpy(b, a, sizeof(Record) * (size_t)n);
            MeSortInPlace(a, (size_t)n, sizeof(Record), compareRecords);
            qsort(b, (size_t)n, sizeof(Record), compareRecords);
            assert_memory_equal(a, b, sizeof(Record) * (size_t)n);
            for (int i = 1; i < n; i++)
                assert_true(compareRecords(&a[i - 1], &a[i]) < 0);
            checked++;
        }
    assert_int_equal(checked, 36);
}

static void longs_match_qsort(void **state)
{
    (void)state;
    static long a[5000], b[5000];
    unsigned long seed = 99;
    for (int i = 0; i < 5000; i++)
        a[i] = b[i] = (long)lcg(&seed) - (1l << 30);
    MeSortInPlace(a, 5000, sizeof(long), compareLongs);
    qsort(b, 5000, sizeof(long), compareLongs);
    assert_memory_equal(a, b, sizeof a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(records_match_qsort),
        cmocka_unit_test(longs_match_qsort),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
