/* Box against box at and near touching, against the geometry: a block of touching cubes 30 m from the
 * origin (Box2D's smash, where float rounds every coordinate by a few micrometres, so that neighbours
 * are apart or overlapping by rounding) gives each face neighbour the shared face's four corners, each
 * edge neighbour the shared edge's two ends and each corner neighbour the shared corner, all at zero
 * separation to rounding; boxes a few millimetres apart face to face, or edge over face, are measured
 * at their exact distance whatever their turn about the normal; crossed edges, which no face axis
 * separates, at theirs too. */
#include "karma_test.h"

#include <math.h>
#include <string.h>

#include <karma/Mcd.h>

#include "karma_mcd_reference.h"
#include "mcd/nearfield/nearfield.h"

#define HALF 0.2
#define FAR_Z 30.0
/* Rounding of a coordinate near 30 m (float: 2 ulp of 32 is 3.8e-6) and of the contact's arithmetic. */
#define ROUNDING ME_TOL(1e-9, 2e-5)

static void cubeData(McdGeometryData *g, MeReal h)
{
    memset(g, 0, sizeof *g);
    g->type = kMcdGeometryTypeBox;
    MeVector3Set(g->u.box.radii, h, h, h);
}

/* The cube of the block at grid cell (i, j, k): 0.4 m apart, the block's front at FAR_Z. */
static void cell(MeMatrix4 tm, int i, int j, int k)
{
    MeMatrix4TMMakeIdentity(tm);
    tm[3][0] = (MeReal)(i * 2 * HALF);
    tm[3][1] = (MeReal)(j * 2 * HALF);
    tm[3][2] = (MeReal)(FAR_Z + k * 2 * HALF);
}

/* Whether every one of the n expected points has a contact within ROUNDING of it, and no contact is
 * anywhere else. */
static void expectPoints(const McdContact *c, int count, const double (*p)[3], int n, const char *what)
{
    if (count != n)
        fail_msg("%s: %d contacts, expected %d", what, count, n);
    for (int e = 0; e < n; e++) {
        int found = 0;
        for (int k = 0; k < count; k++)
            found |= fabs((double)c[k].position[0] - p[e][0]) <= ROUNDING &&
                     fabs((double)c[k].position[1] - p[e][1]) <= ROUNDING &&
                     fabs((double)c[k].position[2] - p[e][2]) <= ROUNDING;
        if (!found)
            for (int k = 0; k < count; k++)
                print_message("  contact %d at (%.7g, %.7g, %.7g) separation %g\n", k, (double)c[k].position[0],
                              (double)c[k].position[1], (double)c[k].position[2], (double)c[k].separation);
        if (!found)
            fail_msg("%s: no contact at (%g, %g, %g)", what, p[e][0], p[e][1], p[e][2]);
    }
    for (int k = 0; k < count; k++)
        if (!(fabs((double)c[k].separation) <= ROUNDING))
            fail_msg("%s: contact %d separation %g, expected 0", what, k, (double)c[k].separation);
}

/* Every neighbour of the middle cube of a 3 x 3 x 3 block, each with the feature it shares. */
static void touching_block_gives_the_shared_features(void **state)
{
    (void)state;
    McdGeometryData a, b;
    cubeData(&a, (MeReal)HALF);
    cubeData(&b, (MeReal)HALF);
    MeMatrix4 t1, t2;
    cell(t1, 1, 1, 1);
    int faces = 0, edges = 0, corners = 0;
    for (int di = -1; di <= 1; di++)
        for (int dj = -1; dj <= 1; dj++)
            for (int dk = -1; dk <= 1; dk++) {
                const int shared = (di != 0) + (dj != 0) + (dk != 0); /* 1 face, 2 edge, 3 corner */
                if (shared == 0)
                    continue;
                cell(t2, 1 + di, 1 + dj, 1 + dk);
                McdContact c[4];
                const int n = McdNfBoxBox(&a, t1, &b, t2, ME_R(0.01), c, 4, NULL);
                /* the shared feature's corners: where each offset axis is +-HALF towards the neighbour,
                 * the others at both ends */
                double p[4][3];
                int m = 0;
                for (int s = 0; s < 4 && m < (shared == 1 ? 4 : shared == 2 ? 2 : 1); s++) {
                    const int d[3] = {di, dj, dk};
                    int free = 0;
                    for (int x = 0; x < 3; x++) {
                        const double centre = x == 2 ? FAR_Z + 2 * HALF : 2 * HALF;
                        if (d[x] != 0)
                            p[m][x] = centre + d[x] * HALF;
                        else
                            p[m][x] = centre + ((s >> free++) & 1 ? HALF : -HALF);
                    }
                    m++;
                }
                char what[64];
                snprintf(what, sizeof what, "neighbour (%d, %d, %d)", di, dj, dk);
                expectPoints(c, n, (const double(*)[3])p, m, what);
                for (int k = 0; k < n; k++) { /* the normal is an axis the boxes are offset along */
                    const double nrm[3] = {c[k].normal[0], c[k].normal[1], c[k].normal[2]};
                    const int d[3] = {di, dj, dk};
                    int along = 0;
                    for (int x = 0; x < 3; x++)
                        along |= d[x] != 0 && fabs(nrm[x] + d[x]) <= ROUNDING;
                    if (!along)
                        fail_msg("%s: normal (%g, %g, %g) is not an axis from the neighbour", what, nrm[0], nrm[1],
                                 nrm[2]);
                }
                faces += shared == 1;
                edges += shared == 2;
                corners += shared == 3;
            }
    assert_int_equal(faces, 6);
    assert_int_equal(edges, 12);
    assert_int_equal(corners, 8);
}

/* A cube above another, apart by a gap of 1 to 5 mm, turned about the vertical by any angle and
 * shifted a little: every contact at the exact gap, the normal vertical. */
static void faces_apart_are_at_their_gap(void **state)
{
    (void)state;
    McdGeometryData a, b;
    cubeData(&a, (MeReal)HALF);
    cubeData(&b, (MeReal)HALF);
    unsigned seed = 17;
    for (int trial = 0; trial < 200; trial++) {
        double r[4];
        for (int k = 0; k < 4; k++)
            r[k] = (double)((seed = seed * 1103515245u + 12345u) >> 16 & 0x7fff) / 32768.0;
        const double gap = 0.001 + 0.004 * r[0], turn = 1.5707963 * r[1];
        MeMatrix4 t1, t2;
        cell(t1, 0, 0, 0);
        ref_tm_axis_angle(t2, 0, 0, 1, turn, 0.1 * (r[2] - 0.5), 0.1 * (r[3] - 0.5), FAR_Z + 2 * HALF + gap);
        McdContact c[4];
        const int n = McdNfBoxBox(&a, t1, &b, t2, ME_R(0.01), c, 4, NULL);
        if (n < 3)
            fail_msg("trial %d: %d contacts between faces %g m apart", trial, n, gap);
        for (int k = 0; k < n; k++) {
            if (!(fabs((double)c[k].separation - gap) <= ROUNDING))
                fail_msg("trial %d: separation %.9g, the gap is %.9g", trial, (double)c[k].separation, gap);
            if (!(c[k].normal[2] <= ME_R(-1.0) + ROUNDING))
                fail_msg("trial %d: normal (%g, %g, %g), not down from the upper box", trial, (double)c[k].normal[0],
                         (double)c[k].normal[1], (double)c[k].normal[2]);
        }
    }
}

/* A cube on its edge (turned 45 degrees about x) over a face, and two cubes on crossed edges (one turned
 * about x, the other about y: the nearest points are on edges no face axis separates): the distance is
 * the gap. */
static void edges_apart_are_at_their_gap(void **state)
{
    (void)state;
    McdGeometryData a, b;
    cubeData(&a, (MeReal)HALF);
    cubeData(&b, (MeReal)HALF);
    const double diag = HALF * sqrt(2.0), quarter = 0.78539816339744831;
    for (int crossed = 0; crossed <= 1; crossed++)
        for (double gap = 0.001; gap < 0.006; gap += 0.001) {
            MeMatrix4 t1, t2;
            if (crossed)
                ref_tm_axis_angle(t1, 1, 0, 0, quarter, 0, 0, FAR_Z);
            else
                cell(t1, 0, 0, 0);
            const double below = crossed ? diag : HALF;
            ref_tm_axis_angle(t2, crossed ? 0 : 1, crossed ? 1 : 0, 0, quarter, 0, 0, FAR_Z + below + diag + gap);
            McdContact c[4];
            const int n = McdNfBoxBox(&a, t1, &b, t2, ME_R(0.01), c, 4, NULL);
            if (n < 1 || n > (crossed ? 1 : 2))
                fail_msg("%s, gap %g: %d contacts", crossed ? "crossed edges" : "edge over face", gap, n);
            for (int k = 0; k < n; k++)
                if (!(fabs((double)c[k].separation - gap) <= ROUNDING))
                    fail_msg("%s: separation %.9g, the gap is %.9g", crossed ? "crossed edges" : "edge over face",
                             (double)c[k].separation, gap);
        }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(touching_block_gives_the_shared_features),
        cmocka_unit_test(faces_apart_are_at_their_gap),
        cmocka_unit_test(edges_apart_are_at_their_gap),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
