/* Resting contact through the whole pipeline: a column of 10 boxes stands for 20 s and a 20-base
 * pyramid of 210 boxes for 10 s on a plane, each as primitive boxes and as convex hulls, with the
 * solver's default settings and friction μ = 0.6 from the material table. Auto-disable is off, so
 * the contacts (box–box and box–plane manifolds, warm-started impulses, the solver) must hold the
 * piles up by themselves for the whole run.
 *
 * massScale: the boxes weigh 125 kg (0.5 m cubes at 1000 kg/m³); the world's ε (constraint
 * softness) scales with 1/massScale, so massScale = 125 makes the contacts as stiff as the defaults
 * intend for 1 kg bodies. */
#include "karma_test.h"
#include "karma_stacks.h"

#include <math.h>
#include <stdlib.h>

#include <karma/karma.h>

#define EDGE ME_R(0.5)
#define DENSITY 1000
#define MASS_SCALE 125

typedef KarmaStack Pile;

static void pileInit(Pile *s, int maxBoxes)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = MASS_SCALE;
    sizes.dynamicBodiesMaxCount = maxBoxes;
    sizes.collisionModelsMaxCount = maxBoxes + 1;
    sizes.dynamicConstraintsMaxCount = 16 * maxBoxes + 16; /* groups and up to 8 contacts per box */
    sizes.collisionPairsMaxCount = 8 * maxBoxes + 16;
    karma_stack_init(s, &sizes, ME_R(0.6), maxBoxes);
}

static void pileAdd(Pile *s, McdGeometryID box, MeReal x, MeReal y, MeReal z)
{
    karma_stack_add(s, box, DENSITY, x, y, z);
}

static MeReal pileDrift(const Pile *s)
{
    MeReal worst = 0;
    for (int i = 0; i < s->count; i++) {
        MeVector3 p;
        MdtBodyGetPosition(s->bodies[i], p);
        assert_true(isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]));
        MeReal d = MeVector3Distance(p, s->start[i]);
        if (d > worst)
            worst = d;
    }
    return worst;
}

static void pileFree(Pile *s)
{
    /* A standing pile is nothing the step cannot do well: no runaway report (docs/step.md). */
    MdtWorldCounters c;
    MdtWorldGetCounters(MstUniverseGetWorld(s->u), &c);
    assert_int_equal(c.speedWarnings, 0);
    assert_int_equal(c.energyWarnings, 0);
    karma_stack_free(s);
}

/* Run `seconds` at 60 Hz; print the drift each second; return the largest drift seen. */
static MeReal pileRun(Pile *s, int seconds, const char *label)
{
    MeReal worst = 0;
    for (int t = 1; t <= seconds; t++) {
        for (int i = 0; i < 60; i++)
            MstUniverseStep(s->u, ME_R(1.0) / 60);
        MeReal d = pileDrift(s);
        if (d > worst)
            worst = d;
        if (t % 5 == 0)
            printf("%s: t = %2d s, max drift %.3e m (%.3f %% of the edge), contacts %d\n", label, t, (double)d,
                   (double)(100 * d / EDGE), MstBridgeGetLastContactCount(MstUniverseGetBridge(s->u)));
    }
    return worst;
}

/* Ten of `g` in a column on the plane, 20 s: none drifts more than 1 % of an edge, the top sinks by the
 * column's compliance, nothing moves sideways. */
static void columnStands(McdGeometryID (*make)(McdFrameworkID fw), const char *label)
{
    Pile s;
    pileInit(&s, 10);
    McdGeometryID g = make(MstUniverseGetFramework(s.u));
    assert_non_null(g);
    for (int i = 0; i < 10; i++)
        pileAdd(&s, g, 0, 0, EDGE / 2 + (MeReal)i * EDGE);
    MeReal worst = pileRun(&s, 20, label);
    /* At rest each contact row holds ε λ = γ φ / h: a contact with k boxes above it carries
     * λ = k m g h / 4 on each of its 4 points and sinks by φ_k = ε k m g h² / (4 γ). The top box sinks
     * by the sum over k = 1..10 (55 ε m g h² / (4 γ) = 1.87 mm here): the column's compliance. */
    MdtWorldID w = MstUniverseGetWorld(s.u);
    const double h = 1.0 / 60, m = MdtBodyGetMass(s.bodies[0]);
    const double sag = 55 * (double)MdtWorldGetEpsilon(w) * m * 9.81 * h * h / (4 * (double)MdtWorldGetGamma(w));
    MeVector3 top;
    MdtBodyGetPosition(s.bodies[9], top);
    double sunk = (double)s.start[9][2] - top[2];
    printf("%s, 20 s: max drift %.3e m = %.3f %% of the edge (bound 1 %%); top box sank %.4e m, "
           "compliance predicts %.4e m (%.2f %% off); sideways %.2e m; contacts %d\n",
           label, (double)worst, (double)(100 * worst / EDGE), sunk, sag, 100 * fabs(sunk / sag - 1),
           hypot((double)top[0], (double)top[1]), MstBridgeGetLastContactCount(MstUniverseGetBridge(s.u)));
    assert_int_equal(MstBridgeGetLastContactCount(MstUniverseGetBridge(s.u)), 40); /* four per face */
    assert_true(worst < 0.01 * EDGE);
    assert_rel(sunk, sag, 0.02);
    assert_true(hypot((double)top[0], (double)top[1]) < 1e-4);
    pileFree(&s);
}

static McdGeometryID makeBox(McdFrameworkID fw) { return McdBoxCreate(fw, EDGE, EDGE, EDGE); }

/* The box as a convex mesh: the hull of its eight corners. */
static McdGeometryID makeConvexBox(McdFrameworkID fw)
{
    MeVector3 corners[8];
    for (int k = 0; k < 8; k++)
        MeVector3Set(corners[k], (k & 1) ? EDGE / 2 : -EDGE / 2, (k & 2) ? EDGE / 2 : -EDGE / 2,
                     (k & 4) ? EDGE / 2 : -EDGE / 2);
    return McdConvexMeshCreateHull(fw, (const MeVector3 *)corners, 8, 0);
}

static void column_of_ten_stands(void **state)
{
    (void)state;
    columnStands(makeBox, "column of 10 boxes");
}

/* Convex-plane and convex-convex manifolds (GJK/EPA and face clipping) hold the same column as the
 * box tests do, to the same bounds and compliance. */
static void column_of_ten_convex_boxes_stands(void **state)
{
    (void)state;
    columnStands(makeConvexBox, "column of 10 convex boxes");
}

/* Rows of 20, 19, ..., 1 of `make`'s box in the xz plane, 2 % of an edge apart sideways, each on the
 * two below it, 10 s: every box within 5 % of an edge of where it started. */
static void pyramidStands(McdGeometryID (*make)(McdFrameworkID fw), const char *label)
{
    const int base = 20;
    Pile s;
    pileInit(&s, base * (base + 1) / 2);
    McdGeometryID box = make(MstUniverseGetFramework(s.u));
    assert_non_null(box);
    const MeReal pitch = EDGE * ME_R(1.02);
    for (int row = 0; row < base; row++)
        for (int i = 0; i < base - row; i++)
            pileAdd(&s, box, ((MeReal)i - (MeReal)(base - row - 1) / 2) * pitch, 0, EDGE / 2 + (MeReal)row * EDGE);
    assert_int_equal(s.count, 210);
    MeReal worst = pileRun(&s, 10, label);
    MeVector3 top;
    MdtBodyGetPosition(s.bodies[s.count - 1], top);
    printf("%s, 10 s: max drift %.3e m = %.3f %% of the edge; top box height %.4f m (start %.4f)\n", label,
           (double)worst, (double)(100 * worst / EDGE), (double)top[2], (double)s.start[s.count - 1][2]);
    assert_true(worst < 0.05 * EDGE); /* standing: every box within 5 % of an edge of where it started */
    pileFree(&s);
}

static void pyramid_of_210_stands(void **state)
{
    (void)state;
    pyramidStands(makeBox, "pyramid of 210");
}

/* The same pyramid of convex hulls (convex-convex and convex-plane manifolds) stands to the boxes'
 * bound (issue 18, point 5). */
static void pyramid_of_210_convex_hulls_stands(void **state)
{
    (void)state;
    pyramidStands(makeConvexBox, "pyramid of 210 convex hulls");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(column_of_ten_stands),
        cmocka_unit_test(column_of_ten_convex_boxes_stands),
        cmocka_unit_test(pyramid_of_210_stands),
        cmocka_unit_test(pyramid_of_210_convex_hulls_stands),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
