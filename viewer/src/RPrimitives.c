/* RPrimitives.c -- the triangle lists of Karma's primitives, in their local frames (z is the axis
 * of cylinders, cones and sphyls, as in Mcd), with outward normals and counter-clockwise fronts. */
#include <math.h>

#include "RGeometryUtils.h"
#include "RInternal.h"

#define R_PI 3.14159265358979323846

/* Writes vertices one after another into a graphic. */
typedef struct Emit {
    RObjectVertex *v;
    int n;
} Emit;

/* The next vertex: position p, unit normal n, texture coordinates (u, w). */
static void put(Emit *e, const double p[3], const double n[3], double u, double w)
{
    RObjectVertex *v = &e->v[e->n++];
    v->m_X = (AcmeReal)p[0], v->m_Y = (AcmeReal)p[1], v->m_Z = (AcmeReal)p[2];
    v->m_NX = (AcmeReal)n[0], v->m_NY = (AcmeReal)n[1], v->m_NZ = (AcmeReal)n[2];
    v->m_U = (AcmeReal)u, v->m_V = (AcmeReal)w;
}

static int sides(RRender *rc)
{
    return rc && rc->m_sphereRes >= 3 ? rc->m_sphereRes : 24;
}

static MeBool positive(const char *fn, double value)
{
    if (value > 0 && isfinite(value))
        return METRUE;
    R_REPORT(ME_ERR_ARGUMENT_RANGE, fn, "a size must be positive and finite (got %g)", value);
    return MEFALSE;
}

/* A flat quad from corner c with edges a and b (front where a × b points). */
static void quad(Emit *e, const double c[3], const double a[3], const double b[3])
{
    double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    n[0] /= l, n[1] /= l, n[2] /= l;
    double p[4][3];
    for (int k = 0; k < 3; k++) {
        p[0][k] = c[k];
        p[1][k] = c[k] + a[k];
        p[2][k] = c[k] + a[k] + b[k];
        p[3][k] = c[k] + b[k];
    }
    static const int idx[6] = {0, 1, 2, 0, 2, 3};
    static const double uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 6; i++) {
        int j = idx[i];
        put(e, p[j], n, uv[j][0], uv[j][1]);
    }
}

RGraphic *MEAPI RGraphicBoxCreate(RRender *rc, AcmeReal width, AcmeReal height, AcmeReal depth,
                                  const float color[4], MeMatrix4Ptr matrix)
{
    if (!positive("RGraphicBoxCreate", width) || !positive("RGraphicBoxCreate", height) ||
        !positive("RGraphicBoxCreate", depth))
        return NULL;
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 36, color, matrix);
    if (!rg)
        return NULL;
    double h[3] = {width / 2, height / 2, depth / 2};
    Emit e = {rg->m_pVertices, 0};
    for (int axis = 0; axis < 3; axis++) {
        int u = (axis + 1) % 3, w = (axis + 2) % 3;
        for (int s = -1; s <= 1; s += 2) {
            double c[3], a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
            c[axis] = s * h[axis];
            c[u] = -s * h[u];
            c[w] = -h[w];
            a[u] = 2 * s * h[u];
            b[w] = 2 * h[w];
            quad(&e, c, a, b);
        }
    }
    return rg;
}

/* The vertex of a profile point (radius, z, normal r, normal z) turned about z to the angle whose
 * cosine and sine are c and s. */
static void putTurned(Emit *e, const double point[4], double c, double s, double u, double w)
{
    const double p[3] = {point[0] * c, point[0] * s, point[1]}, n[3] = {point[2] * c, point[2] * s, point[3]};
    put(e, p, n, u, w);
}

/* A surface of revolution about z from a profile of (radius, z, normal r, normal z) points; each
 * consecutive pair of points makes a ring of quads. Closed rings when the profile repeats a point. */
static void revolve(Emit *e, const double (*profile)[4], int points, int n)
{
    for (int i = 0; i + 1 < points; i++) {
        const double *p = profile[i], *q = profile[i + 1];
        for (int k = 0; k < n; k++) {
            double a0 = 2 * R_PI * k / n, a1 = 2 * R_PI * (k + 1) / n;
            double c0 = cos(a0), s0 = sin(a0), c1 = cos(a1), s1 = sin(a1);
            double u0 = (double)k / n, u1 = (double)(k + 1) / n;
            double v0 = (double)i / (points - 1), v1 = (double)(i + 1) / (points - 1);
            putTurned(e, p, c0, s0, u0, v0), putTurned(e, p, c1, s1, u1, v0), putTurned(e, q, c1, s1, u1, v1);
            putTurned(e, p, c0, s0, u0, v0), putTurned(e, q, c1, s1, u1, v1), putTurned(e, q, c0, s0, u0, v1);
        }
    }
}

/* Profile of a sphere cap-to-cap, or of a sphyl when half > 0: points from the bottom pole up. */
static int roundProfile(double (*out)[4], double radius, double half, int rings)
{
    int n = 0;
    for (int i = 0; i <= rings; i++) {
        double a = -R_PI / 2 + R_PI * i / rings; /* latitude */
        double z = radius * sin(a), r = radius * cos(a);
        double zc = i * 2 < rings ? -half : half;
        if (half > 0 && i * 2 == rings) { /* the cylinder part: the equator twice */
            out[n][0] = r, out[n][1] = z - half, out[n][2] = cos(a), out[n][3] = sin(a), n++;
            zc = half;
        }
        out[n][0] = r, out[n][1] = z + zc, out[n][2] = cos(a), out[n][3] = sin(a), n++;
    }
    return n;
}

#define R_MAX_RINGS 64

static RGraphic *roundCreate(RRender *rc, const char *fn, AcmeReal radius, AcmeReal half, const float color[4],
                             MeMatrix4Ptr matrix)
{
    if (!positive(fn, radius) || !(half >= 0 && isfinite(half)))
        return NULL;
    int n = sides(rc), rings = n / 2 < R_MAX_RINGS ? (n / 2) * 2 : R_MAX_RINGS;
    double profile[R_MAX_RINGS + 2][4];
    int points = roundProfile(profile, radius, half, rings);
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 6 * n * (points - 1), color, matrix);
    if (!rg)
        return NULL;
    Emit e = {rg->m_pVertices, 0};
    revolve(&e, (const double(*)[4])profile, points, n);
    /* Coarser copies for when it is small on the picture (RGL.c picks one by its size there):
     * half and a quarter of the sides, never fewer than 6. */
    rg->m_private->lodExtent = (float)(radius + half);
    for (int k = 0; k < R_LOD_LEVELS; k++) {
        int m = n >> (k + 1), r = m / 2 < R_MAX_RINGS ? (m / 2) * 2 : R_MAX_RINGS;
        if (m < 6 || r < 2)
            break;
        int q = roundProfile(profile, radius, half, r);
        RGraphic *lod = RGraphicCreateEmpty(6 * m * (q - 1));
        if (!lod)
            break;
        Emit el = {lod->m_pVertices, 0};
        revolve(&el, (const double(*)[4])profile, q, m);
        rg->m_private->lod[k] = lod;
    }
    return rg;
}

RGraphic *MEAPI RGraphicSphereCreate(RRender *rc, AcmeReal radius, const float color[4], MeMatrix4Ptr matrix)
{
    return roundCreate(rc, "RGraphicSphereCreate", radius, 0, color, matrix);
}

RGraphic *MEAPI RGraphicSphylCreate(RRender *rc, AcmeReal radius, AcmeReal height, const float color[4],
                                    MeMatrix4Ptr matrix)
{
    return roundCreate(rc, "RGraphicSphylCreate", radius, height / 2, color, matrix);
}

/* Size: Karma 1.2's signature. */
RGraphic *MEAPI RGraphicFrustumCreate(RRender *rc, AcmeReal bottomRadius, AcmeReal topRadius, AcmeReal bottom,
                                      AcmeReal top, int sideCount, const float color[4], MeMatrix4Ptr matrix)
{
    const char *fn = "RGraphicFrustumCreate";
    if (!positive(fn, bottomRadius) || !(topRadius >= 0 && isfinite(topRadius)) || !positive(fn, top - bottom))
        return NULL;
    if (sideCount < 3) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, fn, "at least 3 sides are needed (got %d)", sideCount);
        return NULL;
    }
    /* Side normal: perpendicular to the slant line in the (r, z) plane. */
    double dr = bottomRadius - topRadius, dz = top - bottom, l = sqrt(dr * dr + dz * dz);
    double nr = dz / l, nz = dr / l;
    double profile[6][4] = {
        {0, bottom, 0, -1}, {bottomRadius, bottom, 0, -1},   /* bottom disc */
        {bottomRadius, bottom, nr, nz}, {topRadius, top, nr, nz}, /* side */
        {topRadius, top, 0, 1}, {0, top, 0, 1},              /* top disc */
    };
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 6 * sideCount * 3, color, matrix);
    if (!rg)
        return NULL;
    Emit e = {rg->m_pVertices, 0};
    for (int part = 0; part < 3; part++)
        revolve(&e, (const double(*)[4])profile + 2 * part, 2, sideCount);
    /* Swept outward from the axis, the bottom disc already faces −z; the top, swept inward, faces +z. */
    return rg;
}

RGraphic *MEAPI RGraphicCylinderCreate(RRender *rc, AcmeReal radius, AcmeReal height, const float color[4],
                                       MeMatrix4Ptr matrix)
{
    return RGraphicFrustumCreate(rc, radius, radius, -height / 2, height / 2, sides(rc), color, matrix);
}

RGraphic *MEAPI RGraphicConeCreate(RRender *rc, AcmeReal radius, AcmeReal upper_height, AcmeReal lower_height,
                                   const float color[4], MeMatrix4Ptr matrix)
{
    return RGraphicFrustumCreate(rc, radius, 0, -lower_height, upper_height, sides(rc), color, matrix);
}

RGraphic *MEAPI RGraphicTorusCreate(RRender *rc, AcmeReal innerRadius, AcmeReal outerRadius, const float color[4],
                                    MeMatrix4Ptr matrix)
{
    if (!positive("RGraphicTorusCreate", innerRadius) || !positive("RGraphicTorusCreate", outerRadius))
        return NULL;
    int n = sides(rc), m = n / 2 < R_MAX_RINGS ? n / 2 : R_MAX_RINGS;
    double profile[R_MAX_RINGS + 1][4];
    for (int i = 0; i <= m; i++) {
        double a = -R_PI + 2 * R_PI * i / m; /* round the tube from the inside, downwards first */
        profile[i][0] = outerRadius + innerRadius * cos(a);
        profile[i][1] = innerRadius * sin(a);
        profile[i][2] = cos(a);
        profile[i][3] = sin(a);
    }
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 6 * n * m, color, matrix);
    if (!rg)
        return NULL;
    Emit e = {rg->m_pVertices, 0};
    revolve(&e, (const double(*)[4])profile, m + 1, n);
    return rg;
}

RGraphic *MEAPI RGraphicSquareCreate(RRender *rc, AcmeReal side, const float color[4], MeMatrix4Ptr matrix)
{
    if (!positive("RGraphicSquareCreate", side))
        return NULL;
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 6, color, matrix);
    if (!rg)
        return NULL;
    Emit e = {rg->m_pVertices, 0};
    double c[3] = {-side / 2, -side / 2, 0}, a[3] = {side, 0, 0}, b[3] = {0, side, 0};
    quad(&e, c, a, b);
    rg->m_private->checkerCell = (float)(side / 8);
    return rg;
}

RGraphic *MEAPI RGraphicGroundPlaneCreate(RRender *rc, AcmeReal side_length, int triangles_per_side,
                                          const float color[4], AcmeReal y_position)
{
    if (!positive("RGraphicGroundPlaneCreate", side_length))
        return NULL;
    if (triangles_per_side < 1) {
        R_REPORT(ME_ERR_ARGUMENT_RANGE, "RGraphicGroundPlaneCreate", "triangles_per_side must be at least 1 (got %d)",
                 triangles_per_side);
        return NULL;
    }
    RGraphic *rg = RGraphicNew(rc, kRKindTriangles, 6, color, NULL);
    if (!rg)
        return NULL;
    Emit e = {rg->m_pVertices, 0};
    /* Local y = 0 exactly, so the checkerboard's cells have sharp, stable edges; the height is in m_Matrix. */
    double c[3] = {-side_length / 2, 0, -side_length / 2}, a[3] = {0, 0, side_length}, b[3] = {side_length, 0, 0};
    quad(&e, c, a, b);
    rg->m_pObject->m_Matrix[3][1] = y_position;
    rg->m_private->checkerCell = (float)(side_length / triangles_per_side);
    return rg;
}

void MEAPI RSetVertex(RObjectVertex *vertex, const MeVector3 position, const MeVector3 normal, AcmeReal u, AcmeReal v)
{
    if (!vertex || !position || !normal)
        return;
    vertex->m_X = position[0], vertex->m_Y = position[1], vertex->m_Z = position[2];
    vertex->m_NX = normal[0], vertex->m_NY = normal[1], vertex->m_NZ = normal[2];
    vertex->m_U = u, vertex->m_V = v;
}
