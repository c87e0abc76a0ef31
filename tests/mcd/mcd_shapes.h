/* mcd_shapes.h -- independent descriptions of the primitive geometries for Mcd tests (double).
 *
 * Each shape is described by its dimensions (read back through the public getters) and an exact
 * signed distance function in the geometry's local frame, written here from first principles:
 * negative inside, zero on the surface. For a convex solid, n is an outward normal at a surface point
 * x exactly when sdf(x + d n) = d for d > 0, which the tests use to check normals and support points
 * without trusting the library. */
#ifndef MCD_SHAPES_H
#define MCD_SHAPES_H

#include <math.h>

#include <karma/Mcd.h>
#include <karma/MeMath.h>

#define TEST_PI 3.14159265358979323846

typedef struct TestShape {
    int type;
    double radius, halfHeight;  /* sphere, cylinder, sphyl */
    double radii[3];            /* box */
    double zLo, zHi, rLo, rHi;  /* cone; cylinder as the frustum with rLo = rHi */
} TestShape;

static inline TestShape test_shape_of(McdGeometryID g)
{
    TestShape s = {0};
    s.type = McdGeometryGetTypeId(g);
    switch (s.type) {
    case kMcdGeometryTypeSphere:
        s.radius = McdSphereGetRadius(g);
        break;
    case kMcdGeometryTypeBox: {
        const MeReal *r = McdBoxGetRadii(g);
        s.radii[0] = r[0], s.radii[1] = r[1], s.radii[2] = r[2];
        break;
    }
    case kMcdGeometryTypeCylinder:
        s.radius = McdCylinderGetRadius(g);
        s.halfHeight = McdCylinderGetHeight(g) / 2;
        s.zLo = -s.halfHeight, s.zHi = s.halfHeight, s.rLo = s.rHi = s.radius;
        break;
    case kMcdGeometryTypeSphyl:
        s.radius = McdSphylGetRadius(g);
        s.halfHeight = McdSphylGetHeight(g) / 2;
        break;
    case kMcdGeometryTypeCone:
        s.zLo = McdConeGetLowerZ(g), s.zHi = McdConeGetUpperZ(g);
        s.rLo = McdConeGetLowerRadius(g), s.rHi = McdConeGetUpperRadius(g);
        break;
    default:
        break;
    }
    return s;
}

/* Distance from (x, y) to the 2D segment a-b. */
static inline double test_seg2(double x, double y, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((x - ax) * dx + (y - ay) * dy) / l2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(x - ax - t * dx, y - ay - t * dy);
}

/* Solid of revolution about z whose meridian is the trapezoid (0,zLo) (rLo,zLo) (rHi,zHi) (0,zHi). */
static inline double test_sdf_frustum(const TestShape *s, const double p[3])
{
    double rho = hypot(p[0], p[1]), z = p[2];
    double d = test_seg2(rho, z, 0, s->zLo, s->rLo, s->zLo);
    double d2 = test_seg2(rho, z, s->rLo, s->zLo, s->rHi, s->zHi);
    double d3 = test_seg2(rho, z, s->rHi, s->zHi, 0, s->zHi);
    d = d2 < d ? d2 : d;
    d = d3 < d ? d3 : d;
    double radiusAtZ = s->rLo + (s->rHi - s->rLo) * (z - s->zLo) / (s->zHi - s->zLo);
    int inside = z >= s->zLo && z <= s->zHi && rho <= radiusAtZ;
    return inside ? -d : d;
}

static inline double test_sdf(const TestShape *s, const double p[3])
{
    switch (s->type) {
    case kMcdGeometryTypeSphere:
        return sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - s->radius;
    case kMcdGeometryTypeBox: {
        double q[3], outside = 0, inside = -INFINITY;
        for (int i = 0; i < 3; i++) {
            q[i] = fabs(p[i]) - s->radii[i];
            outside += q[i] > 0 ? q[i] * q[i] : 0;
            inside = q[i] > inside ? q[i] : inside;
        }
        return inside > 0 ? sqrt(outside) : inside;
    }
    case kMcdGeometryTypePlane:
        return p[2];
    case kMcdGeometryTypeSphyl: {
        double z = p[2] < -s->halfHeight ? -s->halfHeight : p[2] > s->halfHeight ? s->halfHeight : p[2];
        return sqrt(p[0] * p[0] + p[1] * p[1] + (p[2] - z) * (p[2] - z)) - s->radius;
    }
    case kMcdGeometryTypeCylinder:
    case kMcdGeometryTypeCone:
        return test_sdf_frustum(s, p);
    default:
        return INFINITY;
    }
}

/* Local point of a world point for a rigid transform (rows = axes, row 3 = position). */
static inline void test_to_local(MeMatrix4 tm, const double w[3], double l[3])
{
    double d[3] = {w[0] - tm[3][0], w[1] - tm[3][1], w[2] - tm[3][2]};
    for (int i = 0; i < 3; i++)
        l[i] = d[0] * tm[i][0] + d[1] * tm[i][1] + d[2] * tm[i][2];
}

static inline double test_sdf_world(const TestShape *s, MeMatrix4 tm, const double w[3])
{
    double l[3];
    test_to_local(tm, w, l);
    return test_sdf(s, l);
}

/* A random rigid transform: rotation from a random unit quaternion, position in [-pos, pos]^3. */
static inline void test_random_tm(MeMatrix4 tm, MeReal pos)
{
    MeVector4 q;
    do {
        for (int i = 0; i < 4; i++)
            q[i] = MeRealRandomInRange(-1, 1);
    } while (MeVector4MagnitudeSqr(q) < ME_R(0.01) || MeVector4MagnitudeSqr(q) > 1);
    MeQuaternionNormalize(q);
    MeMatrix4TMMakeIdentity(tm);
    MeMatrix4TMSetRotationFromQuaternion(tm, q);
    MeMatrix4TMSetPosition(tm, MeRealRandomInRange(-pos, pos), MeRealRandomInRange(-pos, pos),
                           MeRealRandomInRange(-pos, pos));
}

#endif /* MCD_SHAPES_H */
