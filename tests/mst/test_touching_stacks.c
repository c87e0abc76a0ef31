/* Touching stacks stand (issue 17 point 1): stacks whose boxes touch their neighbours, placed exactly
 * touching, run 10 s (600 steps of 1/60 s) through MstUniverse at world defaults (μ = 0.6, auto-disable
 * off so the solver holds them up the whole time). No resting body may ever exceed 0.5 m/s (a kicked
 * box, a stack that sways or falls) and every box must end within 5 cm of where it was placed.
 * Small scenes, so that they run in every configuration; the 820-box pyramid and larger ones run in
 * the Release builds (tests/cmake/touching_stacks.cmake, through tools/touching_pyramid). */
#include "karma_test.h"
#include "karma_stacks.h"

#include <math.h>
#include <stdlib.h>

#include <karma/karma.h>

#define STEPS 600
#define STEP ME_R(1.0 / 60.0)
#define SPEED_MAX 0.5   /* m/s: a resting body is never faster (the first steps' fall is 0.16 m/s a step) */
#define MOVED_MAX 0.05  /* m: a standing box ends within this of where it was placed, across */
#define MAX_BODIES 160

typedef KarmaStack Scene;

static void sceneInit(Scene *s)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = MAX_BODIES;
    sizes.collisionModelsMaxCount = MAX_BODIES + 16;
    sizes.dynamicConstraintsMaxCount = 20 * MAX_BODIES;
    sizes.collisionPairsMaxCount = 10 * MAX_BODIES;
    karma_stack_init(s, &sizes, ME_R(0.6), MAX_BODIES);
    MdtContactParamsSetRestitution(MstBridgeGetContactParams(MstUniverseGetBridge(s->u), 0, 0), 0);
}

/* A box of edges (ex, ey, ez) m and the given density (kg/m³) centred at (x, y, z). */
static void sceneBox(Scene *s, MeReal ex, MeReal ey, MeReal ez, MeReal density, MeReal x, MeReal y, MeReal z)
{
    karma_stack_add(s, McdBoxCreate(MstUniverseGetFramework(s->u), ex, ey, ez), density, x, y, z);
}

/* A fixed model of geometry g whose local z axis lies along world x (lying capsules, cylinders), or
 * upright, at (x, y, z). */
static void sceneFixed(Scene *s, McdGeometryID g, int lying, MeReal x, MeReal y, MeReal z)
{
    MeMatrix4 tm = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    assert_non_null(g);
    if (lying) { /* local x -> world -z, local z -> world x */
        MeMatrix4 turned = {{0, 0, -1, 0}, {0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}};
        MeMatrix4Copy(tm, turned);
    }
    tm[3][0] = x;
    tm[3][1] = y;
    tm[3][2] = z;
    assert_non_null(MstFixedModelCreate(s->u, g, tm));
}

/* Runs the scene for STEPS steps; fails when a body exceeds SPEED_MAX at any step or ends more than
 * MOVED_MAX from where it was placed, across (x, y). */
static void sceneStands(Scene *s, const char *label)
{
    double fastest = 0, moved = 0;
    int fastestStep = 0;
    for (int step = 1; step <= STEPS; step++) {
        MstUniverseStep(s->u, STEP);
        for (int i = 0; i < s->count; i++) {
            MeVector3 v;
            MdtBodyGetLinearVelocity(s->bodies[i], v);
            const double speed = (double)MeVector3Magnitude(v);
            if (!(speed <= fastest)) {
                fastest = speed;
                fastestStep = step;
            }
        }
    }
    for (int i = 0; i < s->count; i++) {
        MeVector3 x;
        MdtBodyGetPosition(s->bodies[i], x);
        const double across = hypot((double)(x[0] - s->start[i][0]), (double)(x[1] - s->start[i][1]));
        moved = across > moved ? across : moved;
    }
    print_message("%s: %d bodies, largest speed %.4f m/s at step %d, moved across %.4f m\n", label, s->count,
                  fastest, fastestStep, moved);
    assert_true(fastest <= SPEED_MAX);
    assert_true(moved <= MOVED_MAX);
    karma_stack_free(s);
}

/* A deterministic jitter in [-1, 1] (a linear congruential generator: the scene is the same everywhere). */
static MeReal jitter(unsigned *seed)
{
    *seed = *seed * 1103515245u + 12345u;
    return (MeReal)((double)((*seed >> 8) & 0xFFFF) / 32767.5 - 1.0);
}

/* A pyramid of `rows` rows of unit 1 kg boxes, one box deep, neighbours in a row touching. */
static void scenePyramid(Scene *s, int rows)
{
    for (int r = 0; r < rows; r++)
        for (int i = 0; i < rows - r; i++)
            sceneBox(s, 1, 1, 1, 1, (MeReal)(i - 0.5 * (rows - r - 1)), 0, ME_R(0.5) + (MeReal)r);
}

/* A pyramid of 15 rows (120 unit 1 kg boxes), one box deep, neighbours in a row touching. */
static void touching_pyramid_of_15_rows_stands(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    scenePyramid(&s, 15);
    sceneStands(&s, "touching pyramid, 15 rows");
}

/* The same pyramid without the iterative solver's NNCG momentum (MdtWorldSetNonsmoothCG, on by
 * default: decision K47): Karma 1.2's plain sweeps hold it as well. */
static void touching_pyramid_stands_without_nonsmooth_cg(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    MdtWorldID w = MstUniverseGetWorld(s.u);
    assert_true(MdtWorldGetNonsmoothCG(w));
    MdtWorldSetNonsmoothCG(w, MEFALSE);
    assert_false(MdtWorldGetNonsmoothCG(w));
    scenePyramid(&s, 15);
    sceneStands(&s, "touching pyramid, 15 rows, plain sweeps");
}

/* The same pyramid with the coarse correction (MdtWorldSetDeflation, off by default) and its schedule,
 * SM at every second chance: it holds the pyramid as well. */
static void touching_pyramid_stands_with_deflation(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    MdtWorldID w = MstUniverseGetWorld(s.u);
    assert_false(MdtWorldGetDeflation(w));
    MdtWorldSetDeflation(w, METRUE);
    assert_true(MdtWorldGetDeflation(w));
    scenePyramid(&s, 15);
    sceneStands(&s, "touching pyramid, 15 rows, deflation");
}

/* A wall of 1 x 0.5 x 0.5 m bricks in running bond, 12 courses, 8 and 7 bricks a course, touching. */
static void touching_wall_stands(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    for (int c = 0; c < 12; c++) {
        const int n = (c & 1) ? 7 : 8;
        for (int i = 0; i < n; i++)
            sceneBox(&s, 1, ME_R(0.5), ME_R(0.5), 8, (MeReal)(i - 0.5 * (n - 1)), 0, ME_R(0.25) + ME_R(0.5) * (MeReal)c);
    }
    sceneStands(&s, "touching wall, 12 courses");
}

/* A column of 20 boxes about 0.5 m (each edge within 3 %), masses within 20 % of 1 kg, each placed
 * within 5 mm of the axis, each touching the one below. */
static void jittered_column_of_20_stands(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    unsigned seed = 17;
    MeReal z = 0;
    for (int k = 0; k < 20; k++) {
        const MeReal ex = ME_R(0.5) * (1 + ME_R(0.03) * jitter(&seed));
        const MeReal ey = ME_R(0.5) * (1 + ME_R(0.03) * jitter(&seed));
        const MeReal ez = ME_R(0.5) * (1 + ME_R(0.03) * jitter(&seed));
        const MeReal density = (1 + ME_R(0.2) * jitter(&seed)) / (ex * ey * ez);
        const MeReal dx = ME_R(0.005) * jitter(&seed), dy = ME_R(0.005) * jitter(&seed);
        sceneBox(&s, ex, ey, ez, density, dx, dy, z + ez / 2);
        z += ez;
    }
    sceneStands(&s, "jittered column of 20");
}

/* Columns of three touching 0.5 m boxes on fixed shapes 4 m apart: a convex slab, two lying capsules,
 * two lying cylinders, four spheres. */
static void boxes_on_convex_and_primitive_shapes_stand(void **state)
{
    (void)state;
    Scene s;
    sceneInit(&s);
    McdFrameworkID fw = MstUniverseGetFramework(s.u);
    MeVector3 slab[8];
    for (int k = 0; k < 8; k++)
        MeVector3Set(slab[k], (k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? ME_R(0.5) : 0);
    sceneFixed(&s, McdConvexMeshCreateHull(fw, (const MeVector3 *)slab, 8, 0), 0, 0, 0, 0);
    for (int side = -1; side <= 1; side += 2) {
        sceneFixed(&s, McdSphylCreate(fw, ME_R(0.25), 2), 1, 4, ME_R(0.15) * (MeReal)side, ME_R(0.25));
        sceneFixed(&s, McdCylinderCreate(fw, ME_R(0.25), 2), 1, 8, ME_R(0.15) * (MeReal)side, ME_R(0.25));
        for (int other = -1; other <= 1; other += 2)
            sceneFixed(&s, McdSphereCreate(fw, ME_R(0.25)), 0, 12 + ME_R(0.15) * (MeReal)other,
                       ME_R(0.15) * (MeReal)side, ME_R(0.25));
    }
    for (int station = 0; station < 4; station++)
        for (int k = 0; k < 3; k++)
            sceneBox(&s, ME_R(0.5), ME_R(0.5), ME_R(0.5), 8, 4 * (MeReal)station, 0, ME_R(0.75) + ME_R(0.5) * (MeReal)k);
    sceneStands(&s, "boxes on a convex slab, capsules, cylinders, spheres");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(touching_pyramid_of_15_rows_stands),
        cmocka_unit_test(touching_pyramid_stands_without_nonsmooth_cg),
        cmocka_unit_test(touching_pyramid_stands_with_deflation),
        cmocka_unit_test(touching_wall_stands),
        cmocka_unit_test(jittered_column_of_20_stands),
        cmocka_unit_test(boxes_on_convex_and_primitive_shapes_stand),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
