/* fuzz_pairs -- every pair test of the primitives, convex meshes, terrains (triangle mesh, height
 * field, triangle list) and aggregates, through McdIntersect and straight (McdNfCollide, the terrain
 * table, the aggregate test).
 *
 * Bytes decode to two geometry types, their sizes (in range, or raw and then refused with a code),
 * their placements (proper rotations within the position range, the second often near the first so
 * that they touch; or twelve raw reals, which McdModelUpdate must refuse or find to be a rotation),
 * the contact tolerances and the room for contacts. Claims: every contact that comes out has a finite
 * position and separation and a unit normal, its separation is at most the tolerance and no deeper
 * than the pair's extent allows; the pair test itself (before Mcd's final guard) makes the same
 * promise; nothing reads or writes out of bounds (ASan, UBSan). */
#include "fuzz_common.h"

#include "mcd/framework.h"
#include "mcd/nearfield/nearfield.h"
#include "mcd/terrain/terrain.h"
#include "mcd/aggregate/aggregate.h"

static McdFrameworkID fw;
static const double LENGTH_SCALE = 1;

static const int TYPES[] = {kMcdGeometryTypeSphere, kMcdGeometryTypeBox,    kMcdGeometryTypePlane,
                            kMcdGeometryTypeCylinder, kMcdGeometryTypeSphyl, kMcdGeometryTypeCone};

/* The type a byte selects: a convex mesh for 47, 95, 143, 191, 239 (byte values the corpus and the
 * crashes kept before convex meshes existed never hold, so they decode as they did), else a
 * primitive. */
static int typeOf(unsigned byte)
{
    /* the terrains: bytes 120, 121, 122, which no input of the corpus or the crashes kept before
     * terrains existed holds in its first two bytes */
    switch (byte) {
    case 120: return kMcdGeometryTypeTriangleMesh;
    case 121: return kMcdGeometryTypeRGHeightField;
    case 122: return kMcdGeometryTypeTriangleList;
    case 124: return kMcdGeometryTypeAggregate; /* held by no earlier input's first two bytes either */
    default: return byte % 48 == 47 ? kMcdGeometryTypeConvexMesh : TYPES[byte % 6];
    }
}

/* The triangle list's triangles (one input at a time), handed out whole by its generator. */
#define LIST_MAX 8
static MeVector3 listVertices[3 * LIST_MAX], listNormals[LIST_MAX];
static int listFlags[LIST_MAX], listCount;

static int listGenerator(McdModelPair *pair, McdUserTriangle *t, MeVector3 pos, MeReal radius, int max)
{
    int n = listCount < max ? listCount : max;
    (void)pair, (void)pos, (void)radius;
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++)
            t[i].vertices[k] = &listVertices[3 * i + k];
        t[i].normal = &listNormals[i];
        t[i].triangleData.tag = i;
        t[i].flags = (McdTriangleFlags)listFlags[i];
    }
    return n;
}

/* A terrain of size a (heights c for a height field): a few triangles of a mesh or a list, or a grid
 * of 2 to 6 by 2 to 6 vertices with holes at times; NULL when refused (always with a message). */
static McdGeometryID makeTerrain(FuzzInput *in, int type, MeReal a, MeReal b, MeReal c)
{
    unsigned shape = fuzz_byte(in);
    if (type == kMcdGeometryTypeRGHeightField) {
        MeReal heights[36];
        unsigned char holes[25];
        int nx = 2 + (int)(shape % 5), ny = 2 + (int)((shape / 5) % 5);
        for (int i = 0; i < nx * ny; i++)
            heights[i] = (MeReal)(fuzz_unit(in) * (double)c);
        McdGeometryID g = McdRGHeightFieldCreate(fw, heights, nx, ny, a, b, -a * (MeReal)(nx - 1) / 2,
                                                 -b * (MeReal)(ny - 1) / 2);
        if (g && (shape & 0x80)) {
            for (int i = 0; i < (nx - 1) * (ny - 1); i++)
                holes[i] = (unsigned char)(fuzz_byte(in) & 1);
            McdRGHeightFieldSetHoles(g, holes);
        }
        return g;
    }
    int n = 1 + (int)(shape % LIST_MAX), nv = 3 + (int)(fuzz_byte(in) % 10);
    MeVector3 v[12];
    for (int i = 0; i < nv; i++)
        for (int k = 0; k < 3; k++)
            v[i][k] = (MeReal)(fuzz_unit(in) * (double)a * (k == 2 && (shape & 8) ? 0.1 : 1));
    if (type == kMcdGeometryTypeTriangleMesh) {
        int idx[3 * LIST_MAX];
        for (int i = 0; i < 3 * n; i++)
            idx[i] = (int)(fuzz_byte(in) % (unsigned)nv);
        return McdTriangleMeshCreate(fw, (const MeVector3 *)v, nv, idx, n);
    }
    /* the list: its box the vertices' (a little more), any flags, normals by the right-hand rule */
    MeVector3 lo, hi;
    MeVector3Copy(lo, v[0]);
    MeVector3Copy(hi, v[0]);
    listCount = n;
    for (int i = 0; i < n; i++) {
        MeVector3 e1, e2;
        for (int k = 0; k < 3; k++) {
            MeVector3Copy(listVertices[3 * i + k], v[fuzz_byte(in) % (unsigned)nv]);
            for (int j = 0; j < 3; j++) {
                lo[j] = MeMIN(lo[j], listVertices[3 * i + k][j]);
                hi[j] = MeMAX(hi[j], listVertices[3 * i + k][j]);
            }
        }
        MeVector3Subtract(e1, listVertices[3 * i + 1], listVertices[3 * i]);
        MeVector3Subtract(e2, listVertices[3 * i + 2], listVertices[3 * i]);
        MeVector3Cross(listNormals[i], e1, e2);
        if (MeVector3MagnitudeSqr(listNormals[i]) > ME_R(0.0))
            MeVector3Normalize(listNormals[i]);
        else
            MeVector3Set(listNormals[i], 0, 0, 1); /* a degenerate triangle from the application */
        listFlags[i] = (int)(fuzz_byte(in) & kMcdTriangleStandard);
    }
    for (int j = 0; j < 3; j++) {
        lo[j] -= ME_R(0.01) * a;
        hi[j] += ME_R(0.01) * a;
    }
    return McdTriangleListCreate(fw, lo, hi, 1 + (int)(fuzz_byte(in) % LIST_MAX), listGenerator);
}

static McdGeometryID makeGeometry(FuzzInput *in, int type);

/* Geometries an input made inside aggregates, destroyed after the aggregates (outermost first). */
#define MADE_MAX 32
static McdGeometryID made[MADE_MAX];
static int madeCount;

/* An aggregate of 1 to 3 elements of any convex type, an aggregate among them at times (one level
 * deep, shared at times), placed near its origin by a rotation in range or 12 raw reals; a raw
 * transform must be refused with a message, or be a placed rotation. */
static McdGeometryID makeAggregate(FuzzInput *in, int depth)
{
    unsigned shape = fuzz_byte(in);
    int count = 1 + (int)(shape % 3);
    McdAggregateID a = McdAggregateCreate(fw, count);
    if (!a)
        return NULL;
    McdGeometryID previous = NULL;
    for (int i = 0; i < count; i++) {
        unsigned kind = fuzz_byte(in);
        McdGeometryID e;
        if ((kind & 15) == 15 && previous) {
            e = previous; /* shared */
        } else {
            int type = (kind & 7) == 7 && depth == 0 ? kMcdGeometryTypeAggregate : typeOf((kind >> 3) == 5 ? 47 : kind >> 3);
            if (type == kMcdGeometryTypePlane || type == kMcdGeometryTypeTriangleMesh ||
                type == kMcdGeometryTypeRGHeightField || type == kMcdGeometryTypeTriangleList)
                type = kMcdGeometryTypeBox;
            e = type == kMcdGeometryTypeAggregate ? makeAggregate(in, depth + 1) : makeGeometry(in, type);
            if (!e || madeCount == MADE_MAX) {
                if (e)
                    McdGeometryDestroy(e);
                continue;
            }
            made[madeCount++] = e;
        }
        MeMatrix4 rel;
        unsigned long before = MeMessageGetTotalCount(ME_LEVEL_WARNING);
        if ((kind & 0x30) == 0x30) {
            fuzz_raw_transform(in, rel);
        } else {
            fuzz_rotation(in, rel);
            MeVector3 zero = {0, 0, 0};
            fuzz_position(in, zero, 2 * LENGTH_SCALE, rel[3]);
        }
        int slot = McdAggregateAddElement(a, e, rel);
        if (slot < 0)
            FUZZ_CHECK(MeMessageGetTotalCount(ME_LEVEL_WARNING) > before, "an element was refused silently");
        else
            FUZZ_CHECK(MeMatrix4IsTM(rel, ME_R(2e-3)), "a relative transform that is not rigid was accepted");
        previous = e;
    }
    return a;
}

/* A geometry of the type chosen by the bytes; NULL when a raw size was (rightly) refused. */
static McdGeometryID makeGeometry(FuzzInput *in, int type)
{
    int raw = 0;
    unsigned long before = MeMessageGetTotalCount(ME_LEVEL_WARNING);
    MeReal a = fuzz_size(in, LENGTH_SCALE, &raw), b = fuzz_size(in, LENGTH_SCALE, &raw),
           c = fuzz_size(in, LENGTH_SCALE, &raw);
    McdGeometryID g = NULL;
    switch (type) {
    case kMcdGeometryTypeSphere: g = McdSphereCreate(fw, a); break;
    case kMcdGeometryTypeBox: g = McdBoxCreate(fw, a, b, c); break;
    case kMcdGeometryTypePlane: g = McdPlaneCreate(fw); break;
    case kMcdGeometryTypeCylinder: g = McdCylinderCreate(fw, a, b); break;
    case kMcdGeometryTypeSphyl: g = McdSphylCreate(fw, a, (fuzz_byte(in) & 3) == 0 ? 0 : b); break;
    case kMcdGeometryTypeConvexMesh: {
        /* 4 to 32 points in a box of size a (flat one time in eight), rounded by 0.1 b one time in four */
        MeVector3 pts[32];
        unsigned shape = fuzz_byte(in);
        int n = 4 + (int)(shape % 29);
        for (int i = 0; i < n; i++)
            for (int k = 0; k < 3; k++)
                pts[i][k] = (MeReal)(fuzz_unit(in) * (double)a);
        if ((shape & 7) == 0)
            for (int i = 0; i < n; i++)
                pts[i][2] = 0;
        g = McdConvexMeshCreateHull(fw, (const MeVector3 *)pts, n, (shape & 3) == 1 ? ME_R(0.1) * b : 0);
        /* refused (a flat or tiny cloud, a raw size) always with a message */
        if (!g)
            FUZZ_CHECK(MeMessageGetTotalCount(ME_LEVEL_WARNING) > before, "convex mesh refused silently");
        return g;
    }
    case kMcdGeometryTypeAggregate:
        if (madeCount < MADE_MAX - 13) /* room for the elements of one more (two levels of three) */
            return makeAggregate(in, 0);
        return NULL;
    case kMcdGeometryTypeTriangleMesh:
    case kMcdGeometryTypeRGHeightField:
    case kMcdGeometryTypeTriangleList:
        g = makeTerrain(in, type, a, b, c);
        if (!g) /* a degenerate or repeated triangle, a raw size: refused with a message */
            FUZZ_CHECK(MeMessageGetTotalCount(ME_LEVEL_WARNING) > before, "terrain type %d refused silently", type);
        return g;
    default: g = McdConeCreate(fw, a, b); break;
    }
    /* refused exactly when a raw size fell outside the range, and then with a message */
    if (!g)
        FUZZ_CHECK(raw && MeMessageGetTotalCount(ME_LEVEL_WARNING) > before, "geometry type %d refused silently",
                   type);
    return g;
}

/* Place m: a proper rotation within range (near `near` when given), or raw reals. */
static void place(FuzzInput *in, McdModelID m, MeReal (*tm)[4], const MeReal *near, double nearRange)
{
    unsigned mode = fuzz_byte(in);
    MeMatrix4 before;
    McdModelGetWorldTransform(m, before);
    if ((mode & 15) == 15) {
        fuzz_raw_transform(in, tm);
        unsigned long warned = MeMessageGetTotalCount(ME_LEVEL_WARNING);
        McdModelUpdate(m);
        MeMatrix4 now;
        McdModelGetWorldTransform(m, now);
        if (MeMessageGetTotalCount(ME_LEVEL_WARNING) > warned) { /* refused: nothing changed */
            FUZZ_CHECK(memcmp(now, before, sizeof now) == 0, "a refused transform changed the model");
        } else { /* accepted: it must have been a placed rotation */
            MeMatrix3 R;
            MeMatrix4TMGetRotation(R, now);
            FUZZ_CHECK(MeMatrix3IsValidOrientationMatrix(R, ME_R(2e-3)), "a non-rotation was accepted");
            FUZZ_CHECK(McdPositionInRange(McdFrameworkFromID(fw, "fuzz"), now[3]), "a far position was accepted");
        }
        return;
    }
    fuzz_rotation(in, tm);
    if (near && (mode & 1))
        fuzz_position(in, near, nearRange, tm[3]);
    else
        fuzz_position(in, NULL, 1e7 * LENGTH_SCALE, tm[3]);
    McdModelUpdate(m);
}

static double extent(McdModelID m)
{
    MeVector3 c;
    MeReal r;
    McdModelGetBSphere(m, c, &r);
    return isfinite(r) ? (double)r : 0; /* a plane's depth is bounded by the distance term */
}

static void checkContacts(const McdContact *c, int n, double tolerance, double bound, const char *who)
{
    for (int i = 0; i < n; i++) {
        FUZZ_CHECK(fuzz_vector_finite(c[i].position) && isfinite(c[i].separation), "%s: contact %d not finite",
                   who, i);
        FUZZ_CHECK(fuzz_vector_finite(c[i].normal) && fuzz_is_unit(c[i].normal, 1e-3),
                   "%s: contact %d normal (%g %g %g) not unit", who, i, (double)c[i].normal[0],
                   (double)c[i].normal[1], (double)c[i].normal[2]);
        /* the iterative path is accurate to a few epsilons of the pair's size (MCD_NF_REL_EPS) */
        FUZZ_CHECK((double)c[i].separation <= tolerance * 1.01 + 2 * (double)MCD_NF_REL_EPS * bound,
                   "%s: contact %d separation %g beyond the tolerance %g", who, i, (double)c[i].separation, tolerance);
        FUZZ_CHECK((double)c[i].separation >= -bound, "%s: contact %d separation %g deeper than %g", who, i,
                   (double)c[i].separation, bound);
    }
}

/* FUZZ_VERBOSE=1: print the decoded pair (to reproduce a finding in a test). */
static void describe(McdModelID m1, McdModelID m2)
{
    McdModelID m[2] = {m1, m2};
    for (int i = 0; i < 2; i++) {
        McdModelData *d = McdModelFromID(m[i], "fuzz");
        MeMatrix4 w;
        McdModelGetWorldTransform(m[i], w);
        fprintf(stderr, "model %d: %s tol %.9g data", i + 1, McdGeometryGetTypeName(McdModelGetGeometry(m[i])),
                (double)McdModelGetContactTolerance(m[i]));
        const MeReal *u = (const MeReal *)(const void *)&d->geometry->u;
        for (int k = 0; k < 6; k++)
            fprintf(stderr, " %.9g", (double)u[k]);
        fprintf(stderr, "\n");
        for (int r = 0; r < 4; r++)
            fprintf(stderr, "  %.9g %.9g %.9g\n", (double)w[r][0], (double)w[r][1], (double)w[r][2]);
    }
}

/* The pair test itself: McdNfCollide for the primitives and convex meshes, the terrain table's entry
 * (terrain as geometry 2, the contacts turned round when it is geometry 1) for the terrains. */
static int collideStraight(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                           MeReal tolerance, McdContact *contacts, int max)
{
    int count;
    if (g1->type == kMcdGeometryTypeAggregate)
        return McdNfCallCentred(McdNfAggregateAny, g1, tm1, g2, tm2, tolerance, contacts, max, NULL);
    if (g2->type == kMcdGeometryTypeAggregate) {
        int n = McdNfCallCentred(McdNfAggregateAny, g2, tm2, g1, tm1, tolerance, contacts, max, NULL);
        for (int i = 0; i < n; i++)
            MeVector3Scale(contacts[i].normal, -ME_R(1.0));
        return n;
    }
    const McdNfPairEntry *table = McdTerrainPairTable(&count);
    for (int k = 0; k < count; k++) {
        int swapped = table[k].type1 == g2->type && table[k].type2 == g1->type;
        if (!swapped && !(table[k].type1 == g1->type && table[k].type2 == g2->type))
            continue;
        int n = swapped ? McdNfCallCentred(table[k].fn, g2, tm2, g1, tm1, tolerance, contacts, max, NULL)
                        : McdNfCallCentred(table[k].fn, g1, tm1, g2, tm2, tolerance, contacts, max, NULL);
        for (int i = 0; swapped && i < n; i++)
            MeVector3Scale(contacts[i].normal, -ME_R(1.0));
        return n;
    }
    return McdNfCollide(g1, tm1, g2, tm2, tolerance, contacts, max);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzInput in = {data, size};
    if (!fw) {
        fuzz_quiet_messages();
        fw = McdInit(0, 8, 64, (MeReal)LENGTH_SCALE); /* instances: aggregate children */
        McdPrimitivesRegisterInteractions(fw);
    }
    madeCount = 0;
    int t1 = typeOf(fuzz_byte(&in)), t2 = typeOf(fuzz_byte(&in));
    McdGeometryID g1 = makeGeometry(&in, t1), g2 = makeGeometry(&in, t2);
    McdModelID m1 = g1 ? McdModelCreate(g1) : NULL, m2 = g2 ? McdModelCreate(g2) : NULL;
    if (m1 && m2) {
        MeMatrix4 tm1, tm2;
        MeMatrix4TMMakeIdentity(tm1);
        MeMatrix4TMMakeIdentity(tm2);
        McdModelSetTransformPtr(m1, tm1);
        McdModelSetTransformPtr(m2, tm2);
        McdModelSetContactTolerance(m1, (MeReal)(fuzz_log(&in, 1e-6, 1) * LENGTH_SCALE));
        McdModelSetContactTolerance(m2, (MeReal)(fuzz_log(&in, 1e-6, 1) * LENGTH_SCALE));
        place(&in, m1, tm1, NULL, 0);
        MeMatrix4 w1;
        McdModelGetWorldTransform(m1, w1);
        place(&in, m2, tm2, w1[3], 2 * (extent(m1) + extent(m2)) + 1e-3);

        if (getenv("FUZZ_VERBOSE"))
            describe(m1, m2);
        McdModelPairID pair = McdModelPairCreate(m1, m2);
        McdHello(pair);
        McdContact contacts[16];
        McdIntersectResult r = {.contacts = contacts, .contactMaxCount = 1 + (int)(fuzz_byte(&in) % 16)};
        McdIntersect(pair, &r);
        MeMatrix4 a, b;
        McdModelGetWorldTransform(m1, a);
        McdModelGetWorldTransform(m2, b);
        double tolerance = (double)McdModelGetContactTolerance(m1) + (double)McdModelGetContactTolerance(m2);
        double d = sqrt(pow((double)a[3][0] - b[3][0], 2) + pow((double)a[3][1] - b[3][1], 2) +
                        pow((double)a[3][2] - b[3][2], 2));
        double bound = d + 2 * (extent(m1) + extent(m2)) + tolerance + 1e-3;
        FUZZ_CHECK(r.contactCount >= 0 && r.contactCount <= r.contactMaxCount, "contact count %d", r.contactCount);
        checkContacts(contacts, r.contactCount, tolerance, bound, "McdIntersect");
        if (r.contactCount > 0)
            FUZZ_CHECK(fuzz_vector_finite(r.normal) && fuzz_is_unit(r.normal, 1e-3), "result normal not unit");
        McdGoodbye(pair);
        McdModelPairDestroy(pair);

        /* the pair test itself, without Mcd's last guard: the sources must hold the promise too */
        McdModelData *d1 = McdModelFromID(m1, "fuzz"), *d2 = McdModelFromID(m2, "fuzz");
        int n = collideStraight(d1->geometry, a, d2->geometry, b, (MeReal)tolerance, contacts, 4);
        FUZZ_CHECK(n >= 0 && n <= 4, "pair test count %d", n);
        checkContacts(contacts, n, tolerance, bound, "pair test");
        McdModelSetTransformPtr(m1, NULL);
        McdModelSetTransformPtr(m2, NULL);
    }
    if (m1)
        McdModelDestroy(m1);
    if (m2)
        McdModelDestroy(m2);
    if (g1)
        McdGeometryDestroy(g1);
    if (g2)
        McdGeometryDestroy(g2);
    for (int i = madeCount - 1; i >= 0; i--) /* elements after their aggregates; nested ones made later */
        McdGeometryDestroy(made[i]);
    return 0;
}
