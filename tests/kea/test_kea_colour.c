/* test_kea_colour.c -- the graph colouring of a partition's constraints (src/mdt/kea/kea_colour.c), the split of
 * one large partition for parallel sweeps (issue 17, point 5): every colour is an independent set (no
 * body twice, the world aside), every constraint is in exactly one colour, the colouring is the same
 * whatever the workspace held, and a sweep colour by colour gives the same bits in whatever order
 * (whichever worker) the constraints of a colour are taken. */
#include <stdint.h>
#include <string.h>

#include "karma_test.h"

#include "mdt/kea/kea_colour.h"

#define MAX_BODIES 400
#define MAX_CONSTRAINTS 1600

typedef struct Colouring {
    int colour[MAX_CONSTRAINTS], order[MAX_CONSTRAINTS], start[KEA_COLOUR_COUNT + 2];
    int used;
} Colouring;

static uint64_t workspace[MAX_BODIES * KEA_COLOUR_COUNT];

static void colourAll(const int (*bodies)[2], int count, int bodyCount, Colouring *out)
{
    assert_true(KeaColourMemoryRequired(bodyCount) <= sizeof workspace);
    out->used = KeaColourConstraints(bodies, count, bodyCount, workspace, sizeof workspace, out->colour, out->order,
                                     out->start);
    assert_true(out->used >= 0);
}

/* The properties every colouring must have. */
static void checkColouring(const int (*bodies)[2], int count, int bodyCount, const Colouring *c)
{
    static int seenIn[MAX_BODIES];
    static int placed[MAX_CONSTRAINTS];
    memset(placed, 0, sizeof placed);
    assert_int_equal(c->start[0], 0);
    assert_int_equal(c->start[KEA_COLOUR_COUNT + 1], count);
    for (int k = 0; k <= KEA_COLOUR_COUNT; k++) {
        assert_true(c->start[k] <= c->start[k + 1]);
        for (int b = 0; b < bodyCount; b++)
            seenIn[b] = 0;
        for (int j = c->start[k]; j < c->start[k + 1]; j++) {
            int i = c->order[j];
            assert_true(i >= 0 && i < count);
            assert_int_equal(c->colour[i], k);
            placed[i]++;
            if (j > c->start[k])
                assert_true(c->order[j - 1] < i); /* the constraints' own order within a colour */
            if (k == KEA_COLOUR_OVERFLOW)
                continue; /* swept on one worker: it may share bodies */
            for (int e = 0; e < 2; e++) {
                int b = bodies[i][e];
                if (b == KEA_COLOUR_WORLD)
                    continue;
                assert_int_equal(seenIn[b], 0); /* an independent set */
                seenIn[b] = 1;
            }
        }
        if (k >= c->used && k < KEA_COLOUR_COUNT)
            assert_int_equal(c->start[k + 1] - c->start[k], 0);
    }
    for (int i = 0; i < count; i++)
        assert_int_equal(placed[i], 1);
}

/* Constraints sharing a body with constraint i (the world shared by none). */
static int neighbours(const int (*bodies)[2], int count, int i)
{
    int n = 0;
    for (int j = 0; j < count; j++) {
        if (j == i)
            continue;
        for (int e = 0; e < 2; e++)
            for (int f = 0; f < 2; f++)
                if (bodies[i][e] != KEA_COLOUR_WORLD && bodies[i][e] == bodies[j][f]) {
                    n++;
                    e = f = 2;
                }
    }
    return n;
}

static void a_chain_takes_two_colours(void **state)
{
    (void)state;
    static int bodies[50][2];
    bodies[0][0] = 0;
    bodies[0][1] = KEA_COLOUR_WORLD; /* hung from the world */
    for (int i = 1; i < 50; i++) {
        bodies[i][0] = i - 1;
        bodies[i][1] = i;
    }
    static Colouring c;
    colourAll((const int(*)[2])bodies, 50, 50, &c);
    checkColouring((const int(*)[2])bodies, 50, 50, &c);
    assert_int_equal(c.used, 2);
    assert_int_equal(c.start[1], 25);
    assert_int_equal(c.start[KEA_COLOUR_OVERFLOW + 1] - c.start[KEA_COLOUR_OVERFLOW], 0);
}

static void a_body_with_more_constraints_than_colours_overflows(void **state)
{
    (void)state;
    /* 30 bodies each in contact with body 0 and with the world (a plate carrying 30 boxes). */
    static int bodies[60][2];
    for (int i = 0; i < 30; i++) {
        bodies[2 * i][0] = i + 1;
        bodies[2 * i][1] = 0;
        bodies[2 * i + 1][0] = i + 1;
        bodies[2 * i + 1][1] = KEA_COLOUR_WORLD;
    }
    static Colouring c;
    colourAll((const int(*)[2])bodies, 60, 31, &c);
    checkColouring((const int(*)[2])bodies, 60, 31, &c);
    assert_int_equal(c.used, KEA_COLOUR_COUNT);
    /* body 0's first 24 constraints take the 24 colours, the other six overflow */
    assert_int_equal(c.start[KEA_COLOUR_OVERFLOW + 1] - c.start[KEA_COLOUR_OVERFLOW], 30 - KEA_COLOUR_COUNT);
    for (int i = 0; i < 30; i++)
        assert_int_equal(c.colour[2 * i], i < KEA_COLOUR_COUNT ? i : KEA_COLOUR_OVERFLOW);
}

/* A wall of boxes in rows, each box touching its right neighbour and the two above it, the bottom row
 * the ground: a pyramid's contact graph. */
static int wall(int (*bodies)[2], int columns, int rows)
{
    int n = 0;
    for (int r = 0; r < rows; r++)
        for (int x = 0; x < columns; x++) {
            int b = r * columns + x;
            if (r == 0) {
                bodies[n][0] = b;
                bodies[n++][1] = KEA_COLOUR_WORLD;
            }
            if (x + 1 < columns) {
                bodies[n][0] = b;
                bodies[n++][1] = b + 1;
            }
            if (r + 1 < rows) {
                bodies[n][0] = b;
                bodies[n++][1] = b + columns;
                if (x + 1 < columns) {
                    bodies[n][0] = b;
                    bodies[n++][1] = b + columns + 1;
                }
            }
        }
    return n;
}

static void a_wall_of_boxes_takes_few_colours(void **state)
{
    (void)state;
    static int bodies[MAX_CONSTRAINTS][2];
    int n = wall(bodies, 20, 20);
    static Colouring c;
    colourAll((const int(*)[2])bodies, n, 400, &c);
    checkColouring((const int(*)[2])bodies, n, 400, &c);
    /* first fit is bounded by the largest neighbourhood plus one: at most 6 + 6 here */
    int most = 0;
    for (int i = 0; i < n; i++) {
        int d = neighbours((const int(*)[2])bodies, n, i);
        most = d > most ? d : most;
    }
    int largest = 0;
    for (int k = 0; k < c.used; k++)
        largest = c.start[k + 1] - c.start[k] > largest ? c.start[k + 1] - c.start[k] : largest;
    print_message("wall of 400 boxes: %d contacts in %d colours, the largest %d; most neighbours %d\n", n, c.used,
                  largest, most);
    assert_true(c.used <= most + 1);
    assert_true(c.used <= 12);
    assert_int_equal(c.start[KEA_COLOUR_OVERFLOW + 1] - c.start[KEA_COLOUR_OVERFLOW], 0);
    /* every colour has work for several workers: the largest colour holds at most a third */
    for (int k = 0; k < c.used; k++)
        assert_true(c.start[k + 1] - c.start[k] <= n / 3);
}

static uint32_t lcg(uint32_t *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

static void random_graphs_are_coloured_into_independent_sets_deterministically(void **state)
{
    (void)state;
    static int bodies[MAX_CONSTRAINTS][2];
    static Colouring first, second;
    uint32_t seed = 12345;
    for (int trial = 0; trial < 20; trial++) {
        int bodyCount = 1 + (int)(lcg(&seed) % MAX_BODIES);
        int count = (int)(lcg(&seed) % MAX_CONSTRAINTS);
        for (int i = 0; i < count; i++) {
            bodies[i][0] = (int)(lcg(&seed) % (uint32_t)bodyCount);
            /* one in five to the world, else another body (a body joined to itself is to the world) */
            bodies[i][1] = lcg(&seed) % 5 == 0 ? KEA_COLOUR_WORLD : (int)(lcg(&seed) % (uint32_t)bodyCount);
            if (bodies[i][1] == bodies[i][0])
                bodies[i][1] = KEA_COLOUR_WORLD;
        }
        memset(workspace, 0, sizeof workspace);
        colourAll((const int(*)[2])bodies, count, bodyCount, &first);
        checkColouring((const int(*)[2])bodies, count, bodyCount, &first);
        /* whatever the workspace held before */
        memset(workspace, 0xa5, sizeof workspace);
        colourAll((const int(*)[2])bodies, count, bodyCount, &second);
        assert_int_equal(first.used, second.used);
        assert_memory_equal(first.colour, second.colour, sizeof(int) * (size_t)count);
        assert_memory_equal(first.order, second.order, sizeof(int) * (size_t)count);
        assert_memory_equal(first.start, second.start, sizeof first.start);
    }
}

/* A Gauss-Seidel-like sweep over body values: each constraint reads both its bodies and writes both,
 * non-linearly in float, so any change of update order between constraints sharing a body changes
 * the bits. Within a colour the constraints are taken in the order `perm` gives (what different
 * workers and schedules would do). */
static void sweep(const int (*bodies)[2], const Colouring *c, float *v, int colourCount, uint32_t shuffleSeed)
{
    static int perm[MAX_CONSTRAINTS];
    for (int k = 0; k <= colourCount; k++) {
        int colourIndex = k < colourCount ? k : KEA_COLOUR_OVERFLOW;
        int a = c->start[colourIndex], n = c->start[colourIndex + 1] - a;
        for (int j = 0; j < n; j++)
            perm[j] = c->order[a + j];
        if (colourIndex != KEA_COLOUR_OVERFLOW) /* the overflow colour is swept on one worker, in order */
            for (int j = n - 1; j > 0 && shuffleSeed; j--) {
                int r = (int)(lcg(&shuffleSeed) % (uint32_t)(j + 1));
                int t = perm[j];
                perm[j] = perm[r];
                perm[r] = t;
            }
        for (int j = 0; j < n; j++) {
            const int *b = bodies[perm[j]];
            float x0 = v[b[0]], x1 = b[1] == KEA_COLOUR_WORLD ? 1.0f : v[b[1]];
            float impulse = 0.3f * (x1 - x0) + 0.01f * x0 * x1;
            v[b[0]] = x0 + impulse;
            if (b[1] != KEA_COLOUR_WORLD)
                v[b[1]] = x1 - 0.7f * impulse;
        }
    }
}

static void a_sweep_in_colour_order_is_the_same_for_any_worker_schedule(void **state)
{
    (void)state;
    static int bodies[MAX_CONSTRAINTS][2];
    static Colouring c;
    static float reference[MAX_BODIES], v[MAX_BODIES];
    int n = wall(bodies, 20, 20);
    colourAll((const int(*)[2])bodies, n, 400, &c);
    for (int b = 0; b < 400; b++)
        reference[b] = v[b] = 0.001f * (float)b;
    for (int s = 0; s < 10; s++)
        sweep((const int(*)[2])bodies, &c, reference, c.used, 0);
    for (uint32_t schedule = 1; schedule <= 8; schedule++) {
        for (int b = 0; b < 400; b++)
            v[b] = 0.001f * (float)b;
        for (int s = 0; s < 10; s++)
            sweep((const int(*)[2])bodies, &c, v, c.used, schedule * 7919u + (uint32_t)s);
        assert_memory_equal(v, reference, sizeof v);
    }
    /* The check can fail: the same shuffles over all the constraints at once (no colours) change the
     * bits, since constraints sharing a body then swap order. */
    static Colouring one;
    one.used = 1;
    one.start[0] = 0;
    for (int k = 1; k <= KEA_COLOUR_COUNT + 1; k++)
        one.start[k] = n;
    for (int i = 0; i < n; i++)
        one.order[i] = c.order[i];
    for (int b = 0; b < 400; b++)
        v[b] = 0.001f * (float)b;
    for (int s = 0; s < 10; s++)
        sweep((const int(*)[2])bodies, &one, v, 1, 7919u + (uint32_t)s);
    assert_true(memcmp(v, reference, sizeof v) != 0);
}

static void bad_input_is_refused_and_nothing_written(void **state)
{
    (void)state;
    int bodies[2][2] = {{0, 1}, {1, 5}}; /* body 5 of a 3-body partition */
    int colour[2] = {-7, -7}, order[2] = {-7, -7}, start[KEA_COLOUR_COUNT + 2];
    memset(start, 0xff, sizeof start);
    assert_int_equal(KeaColourConstraints((const int(*)[2])bodies, 2, 3, workspace, sizeof workspace, colour, order, start), -1);
    bodies[1][1] = -2; /* neither a body nor the world */
    assert_int_equal(KeaColourConstraints((const int(*)[2])bodies, 2, 3, workspace, sizeof workspace, colour, order, start), -1);
    bodies[1][1] = 2;
    assert_int_equal(KeaColourConstraints((const int(*)[2])bodies, 2, 3, workspace, KeaColourMemoryRequired(3) - 1,
                                          colour, order, start),
                     -1);
    assert_int_equal(colour[0], -7);
    assert_int_equal(order[1], -7);
    assert_int_equal(start[0], -1);
    /* and the same input, well formed, is coloured */
    assert_int_equal(KeaColourConstraints((const int(*)[2])bodies, 2, 3, workspace, KeaColourMemoryRequired(3), colour,
                                          order, start),
                     2);
}

/* Items of eight bodies (SM's packs of four contacts, kea_split.c): a colour's items share no body but
 * the world, whatever repeats within an item; an item on the world alone with others takes colour 0;
 * a body in more items than colours overflows; perItem 2 is KeaColourConstraints; perItem 0 is
 * refused with nothing written. */
static void items_of_eight_bodies_are_coloured_into_independent_sets(void **state)
{
    enum { PER = 8, COUNT = 300, BODIES = 200 };
    static int bodies[COUNT * PER], colour[COUNT], order[COUNT];
    static int seen[KEA_COLOUR_COUNT + 1][BODIES];
    int start[KEA_COLOUR_COUNT + 2], i, k, used;
    uint64_t rng = 99;
    (void)state;
    memset(seen, 0, sizeof seen);
    for (i = 0; i < COUNT * PER; ++i) {
        rng = rng * 6364136223846793005ull + 1442695040888963407ull;
        bodies[i] = (int)((rng >> 33) % (BODIES + 20)) - 20; /* about one in ten on the world */
        if (bodies[i] < 0)
            bodies[i] = KEA_COLOUR_WORLD;
    }
    for (i = 0; i < 30; ++i) /* items 0 ... 29 all hold body 7: more of them than colours */
        bodies[PER * i + 3] = 7;
    used = KeaColourItems(bodies, PER, COUNT, BODIES, workspace, sizeof workspace, colour, order, start);
    assert_true(used > 1 && used <= KEA_COLOUR_COUNT);
    assert_int_equal(start[KEA_COLOUR_COUNT + 1], COUNT);
    assert_true(start[KEA_COLOUR_OVERFLOW + 1] - start[KEA_COLOUR_OVERFLOW] >= 30 - KEA_COLOUR_COUNT);
    for (k = 0; k <= KEA_COLOUR_COUNT; ++k)
        for (i = start[k]; i < start[k + 1]; ++i) {
            const int item = order[i];
            int taken[BODIES] = {0};
            assert_int_equal(colour[item], k);
            if (i > start[k])
                assert_true(order[i - 1] < item);
            if (k == KEA_COLOUR_OVERFLOW)
                continue;
            for (int e = 0; e < PER; ++e) {
                const int b = bodies[PER * item + e];
                if (b == KEA_COLOUR_WORLD || taken[b])
                    continue; /* the world, or a body the item holds twice */
                taken[b] = 1;
                assert_int_equal(seen[k][b], 0); /* no other item of the colour holds it */
                seen[k][b] = 1;
            }
        }
    /* first fit: an item on the world and bodies no earlier item holds takes colour 0 */
    {
        int two[2 * PER];
        for (i = 0; i < 2 * PER; ++i)
            two[i] = i % 2 ? KEA_COLOUR_WORLD : i;
        assert_int_equal(KeaColourItems(two, PER, 2, 2 * PER, workspace, sizeof workspace, colour, order, start), 1);
        assert_int_equal(colour[0], 0);
        assert_int_equal(colour[1], 0);
    }
    /* perItem 2 is the constraints' colouring */
    {
        static int pairs[COUNT][2], colour2[COUNT], order2[COUNT];
        int start2[KEA_COLOUR_COUNT + 2];
        for (i = 0; i < COUNT; ++i) {
            pairs[i][0] = bodies[PER * i];
            pairs[i][1] = bodies[PER * i + 1];
        }
        assert_int_equal(KeaColourItems(&pairs[0][0], 2, COUNT, BODIES, workspace, sizeof workspace, colour, order, start),
                         KeaColourConstraints((const int(*)[2])pairs, COUNT, BODIES, workspace, sizeof workspace,
                                              colour2, order2, start2));
        assert_memory_equal(colour, colour2, sizeof colour2);
        assert_memory_equal(order, order2, sizeof order2);
        assert_memory_equal(start, start2, sizeof start2);
    }
    colour[0] = -7;
    assert_int_equal(KeaColourItems(bodies, 0, COUNT, BODIES, workspace, sizeof workspace, colour, order, start), -1);
    assert_int_equal(colour[0], -7);
}

/* The colouring is first fit, exactly: each item takes the lowest colour none of whose earlier items
 * holds one of its bodies (the world aside), or the overflow colour when every colour does. Checked
 * against that rule written out naively (a scan of the earlier items per colour) on random items of
 * two and of eight bodies, with bodies shared by more items than there are colours: the split
 * solve's trajectories rest on these exact colours. */
static void each_item_takes_the_lowest_colour_free_of_its_bodies(void **state)
{
    enum { COUNT = 400, BODIES = 60, MAXPER = 8 };
    static int bodies[COUNT * MAXPER], colour[COUNT], order[COUNT], expect[COUNT];
    int start[KEA_COLOUR_COUNT + 2];
    uint32_t seed = 4242;
    (void)state;
    for (int trial = 0; trial < 40; trial++) {
        const int per = trial % 2 ? 8 : 2, bodyCount = 2 + (int)(lcg(&seed) % BODIES);
        for (int i = 0; i < COUNT * per; i++) {
            bodies[i] = (int)(lcg(&seed) % (uint32_t)(bodyCount + 3)) - 3; /* some on the world */
            if (bodies[i] < 0)
                bodies[i] = KEA_COLOUR_WORLD;
        }
        for (int i = 0; i < COUNT; i++) {
            int c = 0;
            for (; c < KEA_COLOUR_COUNT; c++) {
                int clash = 0;
                for (int j = 0; j < i && !clash; j++) {
                    if (expect[j] != c)
                        continue;
                    for (int a = 0; a < per && !clash; a++)
                        for (int b = 0; b < per && !clash; b++)
                            clash = bodies[per * i + a] != KEA_COLOUR_WORLD && bodies[per * i + a] == bodies[per * j + b];
                }
                if (!clash)
                    break;
            }
            expect[i] = c;
        }
        memset(workspace, 0x5a, sizeof workspace);
        assert_true(KeaColourItems(bodies, per, COUNT, bodyCount, workspace, sizeof workspace, colour, order, start) >= 0);
        assert_memory_equal(colour, expect, sizeof(int) * COUNT);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_chain_takes_two_colours),
        cmocka_unit_test(a_body_with_more_constraints_than_colours_overflows),
        cmocka_unit_test(a_wall_of_boxes_takes_few_colours),
        cmocka_unit_test(random_graphs_are_coloured_into_independent_sets_deterministically),
        cmocka_unit_test(a_sweep_in_colour_order_is_the_same_for_any_worker_schedule),
        cmocka_unit_test(bad_input_is_refused_and_nothing_written),
        cmocka_unit_test(items_of_eight_bodies_are_coloured_into_independent_sets),
        cmocka_unit_test(each_item_takes_the_lowest_colour_free_of_its_bodies),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
