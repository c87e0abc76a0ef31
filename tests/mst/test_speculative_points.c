/* The bridge's rule for points apart (decision C23): a point whose gap cannot close within the step,
 * at a bound of the bodies' approach speed, is not passed to the solver. Each scene runs twice from
 * the same start: through MstUniverseStep (the rule on: the bridge knows the step) and through
 * McdSpaceUpdateAll, MstBridgeUpdateContacts and MdtWorldStep (the step unknown to the bridge:
 * MstBridgeSetStepSize not called, every point kept, as before the rule). With the rule:
 *  - a box dropped flat on the ground, or on a box resting there, from 24 heights (the gap at the
 *    landing step's start sweeping the contact tolerance), gets all four face points on the step it
 *    lands, never one or two, does not turn, and sinks no deeper than with every point kept; and the
 *    rule did leave points out during the falls (the test measures something);
 *  - a 2 m plank resting on one end and falling flat, its far end dropping faster than g (about 1.5 g
 *    as it turns about the end on the ground), sinks no deeper than with every point kept;
 *  - a box 8 mm above a 2 cm static plate, falling at 3 m/s (5 cm a step), stops on it;
 *  - a row of boxes 3 mm apart at rest in zero gravity, struck end-on (the blow crosses the row within
 *    one step, which no bound of the pairs' own speeds sees), overlaps no deeper than with every point
 *    kept: the points within half the tolerance stay. */
#include "karma_test.h"
#include "karma_stacks.h"

#include <math.h>

#include <karma/karma.h>

#define STEP (ME_R(1.0) / 60)
#define EDGE ME_R(0.5)
#define DENSITY 1000
#define HEIGHTS 24
#define DEPTH_SLACK 1e-4 /* m: deeper than with every point kept by more than this fails */
#define ROW 6             /* boxes in the struck row */

static void universeInit(KarmaStack *s)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 125;
    karma_stack_init(s, &sizes, ME_R(0.6), ROW + 1);
}

/* One step, with the bridge's rule (MstUniverseStep) or without it (the bridge not told the step). */
static void stepWith(KarmaStack *s, MeBool rule)
{
    if (rule) {
        MstUniverseStep(s->u, STEP);
        return;
    }
    McdSpaceID space = MstUniverseGetSpace(s->u);
    MdtWorldID world = MstUniverseGetWorld(s->u);
    McdSpaceUpdateAll(space);
    MstBridgeUpdateContacts(MstUniverseGetBridge(s->u), space, world);
    MdtWorldStep(world, STEP);
}

/* The lowest and highest z of a box body of half sizes hx, hy, hz. */
static void boxZRange(MdtBodyID b, double hx, double hy, double hz, double *lo, double *hi)
{
    MeMatrix4 tm;
    MdtBodyGetTransform(b, tm);
    double reach = hx * fabs((double)tm[0][2]) + hy * fabs((double)tm[1][2]) + hz * fabs((double)tm[2][2]);
    *lo = (double)tm[3][2] - reach;
    *hi = (double)tm[3][2] + reach;
}

typedef struct Landing {
    double depth;      /* deepest penetration over the run (m) */
    double spin;       /* largest |ω| of the falling box (rad/s) */
    MeBool oddCount;   /* some step's contacts were not whole faces */
    int counts[90];    /* contacts each step */
} Landing;

/* A box dropped flat from gap `gap` onto the ground (onBox 0) or onto a box resting on it (onBox 1). */
static void dropBox(double gap, MeBool onBox, MeBool rule, Landing *out)
{
    KarmaStack s;
    universeInit(&s);
    McdGeometryID cube = McdBoxCreate(MstUniverseGetFramework(s.u), EDGE, EDGE, EDGE);
    MdtBodyID lower = onBox ? karma_stack_add(&s, cube, DENSITY, 0, 0, EDGE / 2) : NULL;
    MdtBodyID box = karma_stack_add(&s, cube, DENSITY, 0, 0, (MeReal)(EDGE / 2 + (onBox ? EDGE : 0) + gap));
    out->depth = out->spin = 0;
    out->oddCount = MEFALSE;
    for (int i = 0; i < 90; i++) {
        stepWith(&s, rule);
        double lo, hi, floorTop = 0, unused;
        boxZRange(box, EDGE / 2, EDGE / 2, EDGE / 2, &lo, &hi);
        if (lower)
            boxZRange(lower, EDGE / 2, EDGE / 2, EDGE / 2, &unused, &floorTop);
        out->depth = fmax(out->depth, floorTop - lo);
        MeVector3 w;
        MdtBodyGetAngularVelocity(box, w);
        out->spin = fmax(out->spin, (double)MeVector3Magnitude(w));
        out->counts[i] = MstBridgeGetLastContactCount(MstUniverseGetBridge(s.u));
        /* The ground holds the lower box by four points; the falling box has none or a face's four. */
        int own = out->counts[i] - (onBox ? 4 : 0);
        if (own != 0 && own != 4)
            out->oddCount = METRUE;
    }
    karma_stack_free(&s);
}

static void dropsLandOnWholeFaces(MeBool onBox)
{
    int withheld = 0;
    for (int k = 0; k < HEIGHTS; k++) {
        double gap = 0.004 + 0.0007 * k; /* 4 mm to 2 cm: the gap the first steps see sweeps the tolerance */
        Landing on, off;
        dropBox(gap, onBox, METRUE, &on);
        dropBox(gap, onBox, MEFALSE, &off);
        printf("%s gap %.4f m: depth %.3f mm (every point: %.3f mm), spin %.2e rad/s\n",
               onBox ? "on a box" : "on the ground", gap, 1e3 * on.depth, 1e3 * off.depth, on.spin);
        assert_false(on.oddCount);
        assert_true(on.spin < 1e-3);
        assert_true(on.depth <= off.depth + DEPTH_SLACK);
        for (int i = 0; i < 90; i++)
            if (on.counts[i] < off.counts[i]) {
                withheld++;
                break;
            }
    }
    printf("drops where the rule left points out: %d of %d\n", withheld, HEIGHTS);
    assert_true(withheld > 0);
}

static void test_box_dropped_flat_on_ground(void **state)
{
    (void)state;
    dropsLandOnWholeFaces(MEFALSE);
}

static void test_box_dropped_flat_on_box(void **state)
{
    (void)state;
    dropsLandOnWholeFaces(METRUE);
}

#define PLANK_LENGTH 2.0
#define PLANK_THICK 0.1

/* A plank resting on the edge of its −x end, its +x end `rise` above the ground, let go; returns the
 * deepest penetration over 90 steps. */
static double plankFalls(double rise, MeBool rule)
{
    KarmaStack s;
    universeInit(&s);
    McdGeometryID g = McdBoxCreate(MstUniverseGetFramework(s.u), (MeReal)PLANK_LENGTH, (MeReal)PLANK_THICK,
                                   (MeReal)PLANK_THICK);
    double theta = asin(rise / PLANK_LENGTH);
    double cz = PLANK_LENGTH / 2 * sin(theta) + PLANK_THICK / 2 * cos(theta);
    MdtBodyID b = karma_stack_add(&s, g, DENSITY, 0, 0, (MeReal)cz);
    /* Turned by −θ about y: the x axis rises towards +x. */
    MdtBodySetQuaternion(b, (MeReal)cos(theta / 2), 0, (MeReal)-sin(theta / 2), 0);
    double depth = 0;
    for (int i = 0; i < 90; i++) {
        stepWith(&s, rule);
        double lo, hi;
        boxZRange(b, PLANK_LENGTH / 2, PLANK_THICK / 2, PLANK_THICK / 2, &lo, &hi);
        depth = fmax(depth, -lo);
    }
    karma_stack_free(&s);
    return depth;
}

static void test_plank_falling_flat(void **state)
{
    (void)state;
    for (int k = 0; k < HEIGHTS; k++) {
        double rise = 0.004 + 0.0005 * k;
        double on = plankFalls(rise, METRUE), off = plankFalls(rise, MEFALSE);
        printf("plank end %.4f m up: depth %.3f mm (every point: %.3f mm)\n", rise, 1e3 * on, 1e3 * off);
        assert_true(on <= off + DEPTH_SLACK);
    }
}

/* A 0.2 m box 8 mm above a static 1 x 1 x 0.02 m plate (top at z = 1.01), falling at 3 m/s: 5 cm a
 * step, more than the plate's thickness; its points are apart by more than half the tolerance. */
static void test_fast_box_stops_on_thin_plate(void **state)
{
    (void)state;
    KarmaStack s;
    universeInit(&s);
    McdFrameworkID fw = MstUniverseGetFramework(s.u);
    static MeMatrix4 plateTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 1, 1}};
    assert_non_null(MstFixedModelCreate(s.u, McdBoxCreate(fw, 1, 1, ME_R(0.02)), plateTM));
    MdtBodyID box = karma_stack_add(&s, McdBoxCreate(fw, ME_R(0.2), ME_R(0.2), ME_R(0.2)), DENSITY, 0, 0,
                                    ME_R(1.01 + 0.1 + 0.008));
    MdtBodySetLinearVelocity(box, 0, 0, -3);
    double lowest = 10;
    for (int i = 0; i < 60; i++) {
        MstUniverseStep(s.u, STEP);
        double lo, hi;
        boxZRange(box, 0.1, 0.1, 0.1, &lo, &hi);
        lowest = fmin(lowest, lo);
    }
    printf("fast box: lowest point %.4f m (the plate's top at 1.01 m)\n", lowest);
    assert_true(lowest > 1.009);
    karma_stack_free(&s);
}

/* The deepest overlap between neighbours of a row of ROW 0.5 m boxes, 3 mm apart at rest in zero
 * gravity, struck end-on by a seventh at 2 m/s, 3 mm away: the blow crosses the row in one step. */
static double rowStruck(MeBool rule)
{
    KarmaStack s;
    universeInit(&s);
    MdtWorldSetGravity(MstUniverseGetWorld(s.u), 0, 0, 0);
    McdGeometryID cube = McdBoxCreate(MstUniverseGetFramework(s.u), EDGE, EDGE, EDGE);
    MdtBodyID body[ROW + 1];
    for (int i = 0; i <= ROW; i++)
        body[i] = karma_stack_add(&s, cube, DENSITY, (MeReal)(i * (EDGE + 0.003)), 0, 2);
    MdtBodySetLinearVelocity(body[0], 2, 0, 0);
    double deepest = 0;
    for (int step = 0; step < 30; step++) {
        stepWith(&s, rule);
        for (int i = 0; i < ROW; i++) {
            MeVector3 a, b;
            MdtBodyGetPosition(body[i], a);
            MdtBodyGetPosition(body[i + 1], b);
            deepest = fmax(deepest, EDGE - (double)(b[0] - a[0]));
        }
    }
    karma_stack_free(&s);
    return deepest;
}

static void test_struck_row_in_zero_gravity(void **state)
{
    (void)state;
    double on = rowStruck(METRUE), off = rowStruck(MEFALSE);
    printf("struck row: deepest %.3f mm (every point: %.3f mm)\n", 1e3 * on, 1e3 * off);
    assert_true(on <= off + DEPTH_SLACK);
}

/* The step the bridge assumes: 0 until set, kept by MstUniverseStep, bad sizes refused. */
static void test_bridge_step_size(void **state)
{
    (void)state;
    karma_capture_messages();
    KarmaStack s;
    universeInit(&s);
    MstBridgeID b = MstUniverseGetBridge(s.u);
    assert_true(MstBridgeGetStepSize(b) == 0);
    MstUniverseStep(s.u, STEP);
    assert_true(MstBridgeGetStepSize(b) == 0);
    MstBridgeSetStepSize(b, ME_R(0.01));
    MstUniverseStep(s.u, STEP);
    assert_true(MstBridgeGetStepSize(b) == ME_R(0.01));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MstBridgeSetStepSize(b, -1));
    assert_reports(ME_ERR_ARGUMENT_RANGE, MstBridgeSetStepSize(b, (MeReal)NAN));
    assert_true(MstBridgeGetStepSize(b) == ME_R(0.01));
    karma_stack_free(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_box_dropped_flat_on_ground),
        cmocka_unit_test(test_box_dropped_flat_on_box),
        cmocka_unit_test(test_plank_falling_flat),
        cmocka_unit_test(test_fast_box_stops_on_thin_plate),
        cmocka_unit_test(test_struck_row_in_zero_gravity),
        cmocka_unit_test(test_bridge_step_size),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
