/* fuzz_lineseg -- the segment queries: McdLineSegIntersect on one model, and the space's nearest and
 * sorted hits over two models.
 *
 * Bytes decode to two geometries (in-range sizes), their placements (proper rotations within the
 * position range, or raw reals that McdModelUpdate must refuse), and segments: near the models, across
 * the whole position range, or with raw end points (refused with a code, result 0). Claims: a hit has
 * a finite position on the segment, a finite distance between 0 and the segment's length, and a unit
 * normal; the space's hits are sorted by distance; nothing reads or writes out of bounds. */
#include "fuzz_common.h"

#include "mcd/framework.h"

static McdFrameworkID fw;
static McdSpaceID space;
static const double LENGTH_SCALE = 1;

static const int TYPES[] = {kMcdGeometryTypeSphere, kMcdGeometryTypeBox,    kMcdGeometryTypePlane,
                            kMcdGeometryTypeCylinder, kMcdGeometryTypeSphyl, kMcdGeometryTypeCone};

static McdGeometryID makeGeometry(FuzzInput *in)
{
    int raw = 0, type = TYPES[fuzz_byte(in) % 6];
    MeReal a = fuzz_size(in, LENGTH_SCALE, &raw), b = fuzz_size(in, LENGTH_SCALE, &raw),
           c = fuzz_size(in, LENGTH_SCALE, &raw);
    switch (type) {
    case kMcdGeometryTypeSphere: return McdSphereCreate(fw, a);
    case kMcdGeometryTypeBox: return McdBoxCreate(fw, a, b, c);
    case kMcdGeometryTypePlane: return McdPlaneCreate(fw);
    case kMcdGeometryTypeCylinder: return McdCylinderCreate(fw, a, b);
    case kMcdGeometryTypeSphyl: return McdSphylCreate(fw, a, b);
    default: return McdConeCreate(fw, a, b);
    }
}

static void place(FuzzInput *in, McdModelID m, MeReal (*tm)[4])
{
    if ((fuzz_byte(in) & 15) == 15)
        fuzz_raw_transform(in, tm);
    else {
        fuzz_rotation(in, tm);
        fuzz_position(in, NULL, (fuzz_byte(in) & 1) ? 1e7 * LENGTH_SCALE : 10 * LENGTH_SCALE, tm[3]);
    }
    McdSpaceUpdateModel(m);
}

/* A segment end: near the model, anywhere in range, or raw. *raw is set when it is out of range. */
static void endPoint(FuzzInput *in, const MeReal *near, MeReal *p, int *raw)
{
    unsigned kind = fuzz_byte(in) & 7;
    if (kind == 7) {
        for (int k = 0; k < 3; k++)
            p[k] = fuzz_raw(in); /* refused below unless it happens to be finite and in range */
    } else if (kind == 6)
        fuzz_position(in, NULL, 1e7 * LENGTH_SCALE, p);
    else
        fuzz_position(in, near, 20 * LENGTH_SCALE, p);
    if (!McdPositionInRange(McdFrameworkFromID(fw, "fuzz"), p))
        *raw = 1;
}

static void checkHit(const McdLineSegIntersectResult *r, const MeReal *p0, const MeReal *p1)
{
    double len = sqrt(pow((double)p1[0] - p0[0], 2) + pow((double)p1[1] - p0[1], 2) + pow((double)p1[2] - p0[2], 2));
    double scale = len + fabs((double)p0[0]) + fabs((double)p0[1]) + fabs((double)p0[2]) + 1;
    FUZZ_CHECK(fuzz_vector_finite(r->position) && isfinite(r->distance), "hit not finite");
    FUZZ_CHECK(fuzz_vector_finite(r->normal) && fuzz_is_unit(r->normal, 1e-3), "hit normal (%g %g %g) not unit",
               (double)r->normal[0], (double)r->normal[1], (double)r->normal[2]);
    FUZZ_CHECK(r->distance >= 0 && (double)r->distance <= len * (1 + 1e-5) + 1e-6 * scale,
               "hit distance %g outside [0, %g]", (double)r->distance, len);
    for (int k = 0; k < 3; k++) {
        double lo = fmin((double)p0[k], (double)p1[k]), hi = fmax((double)p0[k], (double)p1[k]);
        FUZZ_CHECK((double)r->position[k] >= lo - 1e-5 * scale && (double)r->position[k] <= hi + 1e-5 * scale,
                   "hit position off the segment on axis %d", k);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    FuzzInput in = {data, size};
    if (!fw) {
        fuzz_quiet_messages();
        fw = McdInit(0, 8, 0, (MeReal)LENGTH_SCALE);
        space = McdSpaceAxisSortCreate(fw, McdAllAxes, 4, 8);
        McdSpaceEndChanges(space);
    }
    McdGeometryID g[2] = {makeGeometry(&in), makeGeometry(&in)};
    McdModelID m[2] = {NULL, NULL};
    MeMatrix4 tm[2];
    McdSpaceBeginChanges(space);
    for (int i = 0; i < 2; i++) {
        if (!g[i])
            continue;
        m[i] = McdModelCreate(g[i]);
        MeMatrix4TMMakeIdentity(tm[i]);
        McdModelSetTransformPtr(m[i], tm[i]);
        McdSpaceInsertModel(space, m[i]);
        place(&in, m[i], tm[i]);
    }
    McdSpaceEndChanges(space);
    for (int q = 0; q < 4 && in.n > 0; q++) {
        MeVector3 p0, p1;
        MeMatrix4 w;
        int raw = 0;
        McdModelID target = m[fuzz_byte(&in) & 1];
        if (!target)
            continue;
        McdModelGetWorldTransform(target, w);
        endPoint(&in, w[3], p0, &raw);
        endPoint(&in, w[3], p1, &raw);
        McdLineSegIntersectResult r;
        memset(&r, 0, sizeof r);
        unsigned long warned = MeMessageGetTotalCount(ME_LEVEL_WARNING);
        int hit = McdLineSegIntersect(target, p0, p1, &r);
        if (raw) {
            FUZZ_CHECK(!hit && MeMessageGetTotalCount(ME_LEVEL_WARNING) > warned, "a segment out of range was taken");
            continue;
        }
        if (hit) {
            FUZZ_CHECK(r.model == target, "hit names another model");
            checkHit(&r, p0, p1);
        }
        McdLineSegIntersectResult hits[2];
        int n = McdSpaceGetLineSegIntersections(space, p0, p1, hits, 2);
        FUZZ_CHECK(n >= 0 && n <= 2, "space hit count %d", n);
        for (int i = 0; i < n; i++)
            checkHit(&hits[i], p0, p1);
        if (n == 2)
            FUZZ_CHECK(hits[0].distance <= hits[1].distance, "space hits out of order");
    }
    McdSpaceBeginChanges(space);
    for (int i = 0; i < 2; i++)
        if (m[i]) {
            McdSpaceRemoveModel(m[i]);
            McdModelSetTransformPtr(m[i], NULL);
        }
    McdSpaceEndChanges(space);
    for (int i = 0; i < 2; i++) {
        if (m[i])
            McdModelDestroy(m[i]);
        if (g[i])
            McdGeometryDestroy(g[i]);
    }
    return 0;
}
