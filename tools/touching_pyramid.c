/* touching_pyramid -- a 2-D pyramid of unit boxes whose neighbours in a row touch (no gaps), through
 * MstUniverse at world defaults, y up, 1/60 s steps, mu = 0.6, auto-disable off unless asked: prints per step the
 * largest body speed and the solver's residual, sweeps and unconverged partitions (issue 17 point 1;
 * the diagnosis is in docs/kea_log.md, "Touching stacks").
 *
 *   touching_pyramid [rows [steps [gap]]]     defaults 40 rows (820 boxes), 600 steps, gap 0 m
 *
 * Environment: TOUCHING_PYRAMID_QUIET=1 prints only the summary; TOUCHING_PYRAMID_ITERS=n sets the
 * world's sweep cap (MdtWorldSetMaxLCPIterations); TOUCHING_PYRAMID_BODY=i prints body i's state each
 * step and, from step 18 on, its contacts; TOUCHING_PYRAMID_ROWS=1 prints per row, at the end, the
 * largest |x| and |vx| (x is out of the pyramid's plane); TOUCHING_PYRAMID_SLEEP=1 keeps the world's
 * auto-disable (sleeping) on; TOUCHING_PYRAMID_DEFLATION=1 turns the solver's coarse correction on
 * (MdtWorldSetDeflation).
 *
 * TOUCHING_PYRAMID_EPSILON=e sets the world's softness (MdtWorldSetEpsilon); TOUCHING_PYRAMID_ACROSS=m the
 * largest distance a box may end from where it was placed, across (default MOVED_ACROSS_MAX).
 *
 * Exits 1 when a body ever exceeds 0.5 m/s or ends more than MOVED_ACROSS_MAX from where it was
 * placed, across (out of the plane or along its row), so a script or a test can use it as a check. */
#include <karma/karma.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* A pyramid that stands keeps every box within this of where it was placed, across (m); one that
 * creeps out of its plane or falls does not (TOUCHING_PYRAMID_ACROSS=m sets another limit). */
#define MOVED_ACROSS_MAX 0.05

/* The pyramid: row r (from the ground, 0-based) holds rows - r boxes, `pitch` apart along z. */
typedef struct Pyramid {
    int rows, count;
    double gap, pitch; /* m */
    MstUniverseID u;
    MdtBodyID *bodies; /* row by row from the ground, along z within a row */
} Pyramid;

/* Where box i of a row of n boxes was placed along the row (z, m). */
static double placedAlong(const Pyramid *p, int i, int n)
{
    return (i - 0.5 * (n - 1)) * p->pitch;
}

/* The universe at world defaults as the header says, with the settings the environment asks for. */
static MstUniverseID createUniverse(int count)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = count;
    sizes.collisionModelsMaxCount = count + 1;
    sizes.collisionPairsMaxCount = 10 * count + 256;
    sizes.dynamicConstraintsMaxCount = 30 * count + 256;
    MstUniverseID u = MstUniverseCreate(&sizes);
    if (!u)
        return NULL;
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, ME_R(-9.81), 0);
    if (!getenv("TOUCHING_PYRAMID_SLEEP")) /* awake unless asked: the world's default is to sleep */
        MdtWorldSetAutoDisable(w, MEFALSE);
    if (getenv("TOUCHING_PYRAMID_EPSILON"))
        MdtWorldSetEpsilon(w, (MeReal)atof(getenv("TOUCHING_PYRAMID_EPSILON")));
    if (getenv("TOUCHING_PYRAMID_DEFLATION")) /* the coarse correction (MdtWorldSetDeflation) */
        MdtWorldSetDeflation(w, METRUE);
    if (getenv("TOUCHING_PYRAMID_ITERS"))
        MdtWorldSetMaxLCPIterations(w, atoi(getenv("TOUCHING_PYRAMID_ITERS")));
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.6));
    MdtContactParamsSetRestitution(p, 0);
    return u;
}

/* The ground and the boxes of p (rows and gap set); returns MEFALSE when something could not be made. */
static MeBool buildPyramid(Pyramid *p)
{
    p->count = p->rows * (p->rows + 1) / 2;
    p->pitch = 1 + p->gap;
    p->u = createUniverse(p->count);
    if (!p->u)
        return MEFALSE;
    McdFrameworkID fw = MstUniverseGetFramework(p->u);
    /* Karma's plane is z <= 0 of its frame: turned so that its +z is world +y */
    static MeMatrix4 ground = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}};
    if (!MstFixedModelCreate(p->u, McdPlaneCreate(fw), ground))
        return MEFALSE;
    McdGeometryID box = McdBoxCreate(fw, 1, 1, 1);
    p->bodies = calloc((size_t)p->count, sizeof *p->bodies);
    if (!box || !p->bodies)
        return MEFALSE;
    int k = 0;
    for (int r = 0; r < p->rows; r++) {
        int n = p->rows - r;
        for (int i = 0; i < n; i++) {
            McdModelID m = MstModelAndBodyCreate(p->u, box, 1); /* 1 kg/m³: 1 kg unit boxes */
            if (!m)
                return MEFALSE;
            p->bodies[k] = McdModelGetBody(m);
            MdtBodySetPosition(p->bodies[k], 0, ME_R(0.5) + (MeReal)r, (MeReal)placedAlong(p, i, n));
            k++;
        }
    }
    return METRUE;
}

/* The largest body speed (m/s) and, in *fastest, its body's index. */
static double topSpeed(const Pyramid *p, int *fastest)
{
    double top = 0;
    *fastest = -1;
    for (int i = 0; i < p->count; i++) {
        MeVector3 v;
        MdtBodyGetLinearVelocity(p->bodies[i], v);
        double sp = MeVector3Magnitude(v);
        if (!(sp <= top)) {
            top = sp;
            *fastest = i;
        }
    }
    return top;
}

/* TOUCHING_PYRAMID_BODY: body b's state and, with its contacts, their points, normals and forces. */
static void printBody(MdtBodyID body, int b, MeBool withContacts)
{
    MeVector3 v, x, om;
    MdtBodyGetLinearVelocity(body, v);
    MdtBodyGetAngularVelocity(body, om);
    MdtBodyGetPosition(body, x);
    printf("  body %d x %.4f %.4f %.4f v %.4f %.4f %.4f w %.4f %.4f %.4f\n", b, (double)x[0], (double)x[1], (double)x[2], (double)v[0], (double)v[1],
           (double)v[2], (double)om[0], (double)om[1], (double)om[2]);
    if (!withContacts)
        return;
    for (MdtConstraintID c = MdtBodyGetFirstConstraint(body); c; c = MdtBodyGetNextConstraint(body, c)) {
        MdtContactGroupID g = MdtConstraintDCastContactGroup(c);
        if (!g)
            continue;
        for (MdtContactID ct = MdtContactGroupGetFirstContact(g); ct; ct = MdtContactGroupGetNextContact(g, ct)) {
            MeVector3 cp, cn, f;
            MdtContactGetPosition(ct, cp);
            MdtContactGetNormal(ct, cn);
            MdtConstraintGetForce(c, 0, f);
            printf("    contact p %.3f %.3f %.3f n %.3f %.3f %.3f pen %.4f fn %.3f\n", (double)cp[0], (double)cp[1],
                   (double)cp[2], (double)cn[0], (double)cn[1], (double)cn[2],
                   (double)MdtContactGetPenetration(ct), (double)MdtContactGetNormalForce(ct));
        }
    }
}

/* TOUCHING_PYRAMID_ROWS: per row, the largest |x| (out of the pyramid's plane) and |vx|. */
static void printRows(const Pyramid *p)
{
    int first = 0;
    for (int r = 0; r < p->rows; r++) {
        double mx = 0, mv = 0;
        for (int i = first; i < first + p->rows - r; i++) {
            MeVector3 x, v;
            MdtBodyGetPosition(p->bodies[i], x);
            MdtBodyGetLinearVelocity(p->bodies[i], v);
            mx = fabs((double)x[0]) > mx ? fabs((double)x[0]) : mx;
            mv = fabs((double)v[0]) > mv ? fabs((double)v[0]) : mv;
        }
        printf("  row %2d |x| %.4f |vx| %.4f\n", r, mx, mv);
        first += p->rows - r;
    }
}

/* How far the boxes moved from where they were placed: across (x, out of the pyramid's plane, and
 * z, along its rows) and down (y: the contacts' softness lets a loaded stack sink a little). */
typedef struct Drift {
    double across, down, acrossX, acrossZ; /* m */
    int acrossRow, acrossBox;             /* the box that moved furthest across */
} Drift;

static Drift measureDrift(const Pyramid *p)
{
    Drift d = {0, 0, 0, 0, -1, -1};
    int k = 0;
    for (int r = 0; r < p->rows; r++) {
        int n = p->rows - r;
        for (int i = 0; i < n; i++, k++) {
            MeVector3 x;
            MdtBodyGetPosition(p->bodies[k], x);
            double dz = (double)x[2] - placedAlong(p, i, n);
            double h = sqrt((double)x[0] * (double)x[0] + dz * dz);
            if (h > d.across) {
                d.across = h;
                d.acrossRow = r;
                d.acrossBox = i;
                d.acrossX = (double)x[0];
                d.acrossZ = dz;
            }
            d.down = 0.5 + r - (double)x[1] > d.down ? 0.5 + r - (double)x[1] : d.down;
        }
    }
    return d;
}

int main(int argc, char **argv)
{
    Pyramid p = {.rows = argc > 1 ? atoi(argv[1]) : 40, .gap = argc > 3 ? atof(argv[3]) : 0};
    int steps = argc > 2 ? atoi(argv[2]) : 600;
    const char *quiet = getenv("TOUCHING_PYRAMID_QUIET");
    if (p.rows < 1 || p.rows > 200 || steps < 1) {
        fprintf(stderr, "usage: touching_pyramid [rows (1..200) [steps [gap m]]]\n");
        return 2;
    }
    if (!buildPyramid(&p))
        return 2;
    MdtWorldID w = MstUniverseGetWorld(p.u);
    double worst = 0;
    int worstStep = -1;
    for (int s = 1; s <= steps; s++) {
        MstUniverseStep(p.u, ME_R(1.0) / 60);
        int fastest;
        double top = topSpeed(&p, &fastest);
        if (getenv("TOUCHING_PYRAMID_BODY")) {
            int b = atoi(getenv("TOUCHING_PYRAMID_BODY"));
            printBody(p.bodies[b], b, s >= 18);
        }
        MdtSolverStats st;
        MdtWorldGetSolverStats(w, &st);
        if (!quiet)
            printf("step %4d  t %6.3f s  max speed %9.5f m/s (body %d)  residual %9.3g m/s  sweeps %d  "
                   "partitions %d (iterative %d, unconverged %d)  rows %d\n",
                   s, s / 60.0, top, fastest, (double)st.maxResidual, st.iterations, st.partitions,
                   st.iterativePartitions, st.unconverged, st.rows);
        if (!(top <= worst)) {
            worst = top;
            worstStep = s;
        }
    }
    if (getenv("TOUCHING_PYRAMID_ROWS"))
        printRows(&p);
    const Drift d = measureDrift(&p);
    printf("rows %d boxes %d gap %g m: largest body speed %.5f m/s at step %d; moved across %.4f m (row %d box %d: "
           "x %.4f, along the row %.4f), down %.4f m\n",
           p.rows, p.count, p.gap, worst, worstStep, d.across, d.acrossRow, d.acrossBox, d.acrossX, d.acrossZ, d.down);
    free(p.bodies);
    MstUniverseDestroy(p.u);
    const double acrossMax = getenv("TOUCHING_PYRAMID_ACROSS") ? atof(getenv("TOUCHING_PYRAMID_ACROSS")) : MOVED_ACROSS_MAX;
    return worst > 0.5 || !(d.across <= acrossMax) ? 1 : 0;
}
