/* karma_mcd_reference.c -- see karma_mcd_reference.h. Everything in double, from the definitions. */
#include "karma_mcd_reference.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mcd/geometry/convex_hull.h"

#define REF_PI 3.14159265358979323846

static void zeroGeometry(McdGeometryData *g, int type)
{
    memset(g, 0, sizeof *g);
    g->type = type;
}

void ref_make_sphere(McdGeometryData *g, double r)
{
    zeroGeometry(g, kMcdGeometryTypeSphere);
    g->u.sphere.radius = (MeReal)r;
}

void ref_make_box(McdGeometryData *g, double dx, double dy, double dz)
{
    zeroGeometry(g, kMcdGeometryTypeBox);
    g->u.box.radii[0] = (MeReal)(0.5 * dx);
    g->u.box.radii[1] = (MeReal)(0.5 * dy);
    g->u.box.radii[2] = (MeReal)(0.5 * dz);
}

void ref_make_cylinder(McdGeometryData *g, double r, double height)
{
    zeroGeometry(g, kMcdGeometryTypeCylinder);
    g->u.cylinder.radius = (MeReal)r;
    g->u.cylinder.halfHeight = (MeReal)(0.5 * height);
}

void ref_make_sphyl(McdGeometryData *g, double r, double height)
{
    zeroGeometry(g, kMcdGeometryTypeSphyl);
    g->u.sphyl.radius = (MeReal)r;
    g->u.sphyl.halfHeight = (MeReal)(0.5 * height);
}

void ref_make_cone(McdGeometryData *g, double a, double b, double h)
{
    /* centroid of a frustum with radii a (z = 0) and b (z = h): h (a^2 + 2ab + 3b^2) / (4 (a^2 + ab + b^2)) */
    double zc = h * (a * a + 2 * a * b + 3 * b * b) / (4 * (a * a + a * b + b * b));
    zeroGeometry(g, kMcdGeometryTypeCone);
    g->u.cone.lowerRadius = (MeReal)a;
    g->u.cone.upperRadius = (MeReal)b;
    g->u.cone.zLower = (MeReal)(-zc);
    g->u.cone.zUpper = (MeReal)(h - zc);
}

void ref_make_plane(McdGeometryData *g) { zeroGeometry(g, kMcdGeometryTypePlane); }

void ref_make_convex(McdGeometryData *g, MeVector3 *points, int n, double fatness)
{
    zeroGeometry(g, kMcdGeometryTypeConvexMesh);
    g->u.convex.hull = malloc(sizeof(McdHull));
    if (McdHullBuild((const MeVector3 *)points, n, g->u.convex.hull) != MCD_HULL_OK)
        abort();
    g->u.convex.fatness = (MeReal)fatness;
}

void ref_free_convex(McdGeometryData *g)
{
    if (g->type == kMcdGeometryTypeConvexMesh && g->u.convex.hull) {
        McdHullFree(g->u.convex.hull);
        free(g->u.convex.hull);
        g->u.convex.hull = NULL;
    }
}

double ref_uniform(RefRng *r, double lo, double hi)
{
    uint64_t x = r->s ? r->s : 0x9E3779B97F4A7C15ull;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    r->s = x;
    return lo + (hi - lo) * (double)(x >> 11) / 9007199254740992.0;
}

static void tmFromQuat(MeMatrix4 tm, double w, double x, double y, double z, double px, double py, double pz)
{
    double n = sqrt(w * w + x * x + y * y + z * z);
    double R[3][3];
    int i, j;
    w /= n;
    x /= n;
    y /= n;
    z /= n;
    /* row i = the rotated unit axis e_i */
    R[0][0] = 1 - 2 * (y * y + z * z);
    R[0][1] = 2 * (x * y + w * z);
    R[0][2] = 2 * (x * z - w * y);
    R[1][0] = 2 * (x * y - w * z);
    R[1][1] = 1 - 2 * (x * x + z * z);
    R[1][2] = 2 * (y * z + w * x);
    R[2][0] = 2 * (x * z + w * y);
    R[2][1] = 2 * (y * z - w * x);
    R[2][2] = 1 - 2 * (x * x + y * y);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++)
            tm[i][j] = (MeReal)R[i][j];
        tm[i][3] = 0;
    }
    tm[3][0] = (MeReal)px;
    tm[3][1] = (MeReal)py;
    tm[3][2] = (MeReal)pz;
    tm[3][3] = 1;
}

void ref_random_tm(RefRng *r, MeMatrix4 tm, double x, double y, double z)
{
    double q[4], n;
    do {
        int k;
        n = 0;
        for (k = 0; k < 4; k++) {
            q[k] = ref_uniform(r, -1, 1);
            n += q[k] * q[k];
        }
    } while (n > 1 || n < 1e-4);
    tmFromQuat(tm, q[0], q[1], q[2], q[3], x, y, z);
}

void ref_tm_axis_angle(MeMatrix4 tm, double ax, double ay, double az, double angle, double x, double y, double z)
{
    double s = sin(0.5 * angle);
    tmFromQuat(tm, cos(0.5 * angle), ax * s, ay * s, az * s, x, y, z);
}

/* world -> local (double) */
static void toLocal(MeMatrix4 tm, const double p[3], double l[3])
{
    double d[3];
    int i;
    for (i = 0; i < 3; i++)
        d[i] = p[i] - tm[3][i];
    for (i = 0; i < 3; i++)
        l[i] = d[0] * tm[i][0] + d[1] * tm[i][1] + d[2] * tm[i][2];
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* distance from (x, y) to the 2D segment (a, b) */
static double segDist2(double x, double y, double ax, double ay, double bx, double by)
{
    double ex = bx - ax, ey = by - ay, l = ex * ex + ey * ey, t = 0;
    if (l > 0)
        t = ((x - ax) * ex + (y - ay) * ey) / l;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    return hypot(x - ax - t * ex, y - ay - t * ey);
}

/* signed distance to the solid of revolution of the trapezoid (0,zl)-(rl,zl)-(ru,zu)-(0,zu) */
static double revolvedSdf(double rho, double z, double rl, double ru, double zl, double zu)
{
    double d = segDist2(rho, z, 0, zl, rl, zl);
    double ds = segDist2(rho, z, rl, zl, ru, zu), dt = segDist2(rho, z, ru, zu, 0, zu);
    int inside;
    d = d < ds ? d : ds;
    d = d < dt ? d : dt;
    inside = z >= zl && z <= zu && rho <= rl + (ru - rl) * (z - zl) / (zu - zl);
    return inside ? -d : d;
}

/* Distance from the local point l to the convex polygon p of the hull (in 3D). */
static double polygonDistance(const McdHull *h, int p, const double l[3])
{
    const int *v = &h->polygonVertices[h->polygonStart[p]];
    int n = h->polygonStart[p + 1] - h->polygonStart[p], k, j;
    double nrm[3] = {h->normals[p][0], h->normals[p][1], h->normals[p][2]}, best = 1e300;
    int inside = 1;
    for (k = 0; k < n; k++) {
        double a[3], b[3], e[3], ap[3], c[3], t, q[3], d2 = 0;
        for (j = 0; j < 3; j++) {
            a[j] = h->vertices[v[k]][j];
            b[j] = h->vertices[v[(k + 1) % n]][j];
            e[j] = b[j] - a[j];
            ap[j] = l[j] - a[j];
        }
        c[0] = e[1] * ap[2] - e[2] * ap[1];
        c[1] = e[2] * ap[0] - e[0] * ap[2];
        c[2] = e[0] * ap[1] - e[1] * ap[0];
        if (dot3(c, nrm) < 0) /* l lies outside this edge (counter-clockwise about the normal) */
            inside = 0;
        t = dot3(ap, e) / dot3(e, e);
        t = t < 0 ? 0 : (t > 1 ? 1 : t);
        for (j = 0; j < 3; j++) {
            q[j] = l[j] - a[j] - t * e[j];
            d2 += q[j] * q[j];
        }
        best = sqrt(d2) < best ? sqrt(d2) : best;
    }
    if (inside) {
        double a[3] = {h->vertices[v[0]][0], h->vertices[v[0]][1], h->vertices[v[0]][2]}, ap[3];
        for (j = 0; j < 3; j++)
            ap[j] = l[j] - a[j];
        return fabs(dot3(ap, nrm));
    }
    return best;
}

/* Signed distance to the polyhedron: inside, minus the distance to the nearest plane; outside, the
 * distance to the nearest polygon. */
static double convexSdf(const McdHull *h, const double l[3])
{
    double worst = -1e300, best = 1e300;
    int p;
    for (p = 0; p < h->polygonCount; p++) {
        double n[3] = {h->normals[p][0], h->normals[p][1], h->normals[p][2]};
        double d = dot3(n, l) - h->offsets[p];
        worst = d > worst ? d : worst;
    }
    if (worst <= 0)
        return worst;
    for (p = 0; p < h->polygonCount; p++) {
        double d = polygonDistance(h, p, l);
        best = d < best ? d : best;
    }
    return best;
}

double ref_sdf(const McdGeometryData *g, MeMatrix4 tm, const double p[3])
{
    double l[3];
    toLocal(tm, p, l);
    switch (g->type) {
    case kMcdGeometryTypeSphere:
        return sqrt(dot3(l, l)) - g->u.sphere.radius;
    case kMcdGeometryTypeSphyl: {
        double hh = g->u.sphyl.halfHeight, z = l[2] < -hh ? -hh : (l[2] > hh ? hh : l[2]);
        return sqrt(l[0] * l[0] + l[1] * l[1] + (l[2] - z) * (l[2] - z)) - g->u.sphyl.radius;
    }
    case kMcdGeometryTypeBox: {
        double q[3], out = 0, in = -1e300;
        int i;
        for (i = 0; i < 3; i++) {
            q[i] = fabs(l[i]) - g->u.box.radii[i];
            if (q[i] > 0)
                out += q[i] * q[i];
            if (q[i] > in)
                in = q[i];
        }
        return out > 0 ? sqrt(out) : in;
    }
    case kMcdGeometryTypeCylinder: {
        double r = g->u.cylinder.radius, hh = g->u.cylinder.halfHeight;
        return revolvedSdf(hypot(l[0], l[1]), l[2], r, r, -hh, hh);
    }
    case kMcdGeometryTypeCone:
        return revolvedSdf(hypot(l[0], l[1]), l[2], g->u.cone.lowerRadius, g->u.cone.upperRadius,
                           g->u.cone.zLower, g->u.cone.zUpper);
    case kMcdGeometryTypePlane:
        return l[2];
    case kMcdGeometryTypeConvexMesh:
        return convexSdf(g->u.convex.hull, l) - g->u.convex.fatness;
    default:
        return 1e300;
    }
}

double ref_support(const McdGeometryData *g, MeMatrix4 tm, const double d[3])
{
    double c = tm[3][0] * d[0] + tm[3][1] * d[1] + tm[3][2] * d[2];
    double a[3];
    int i;
    for (i = 0; i < 3; i++) /* d in local axes */
        a[i] = tm[i][0] * d[0] + tm[i][1] * d[1] + tm[i][2] * d[2];
    switch (g->type) {
    case kMcdGeometryTypeSphere:
        return c + g->u.sphere.radius;
    case kMcdGeometryTypeBox:
        return c + g->u.box.radii[0] * fabs(a[0]) + g->u.box.radii[1] * fabs(a[1]) + g->u.box.radii[2] * fabs(a[2]);
    case kMcdGeometryTypeSphyl:
        return c + g->u.sphyl.halfHeight * fabs(a[2]) + g->u.sphyl.radius;
    case kMcdGeometryTypeCylinder:
        return c + g->u.cylinder.halfHeight * fabs(a[2]) + g->u.cylinder.radius * hypot(a[0], a[1]);
    case kMcdGeometryTypeCone: {
        double rho = hypot(a[0], a[1]);
        double lo = g->u.cone.zLower * a[2] + g->u.cone.lowerRadius * rho;
        double hi = g->u.cone.zUpper * a[2] + g->u.cone.upperRadius * rho;
        return c + (lo > hi ? lo : hi);
    }
    case kMcdGeometryTypeConvexMesh: {
        const McdHull *h = g->u.convex.hull;
        double best = -1e300;
        for (i = 0; i < h->vertexCount; i++) {
            double v[3] = {h->vertices[i][0], h->vertices[i][1], h->vertices[i][2]}, x = dot3(v, a);
            best = x > best ? x : best;
        }
        return c + best + g->u.convex.fatness;
    }
    default:
        return 1e300;
    }
}

double ref_overlap(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, const double n[3])
{
    double m[3] = {-n[0], -n[1], -n[2]};
    return ref_support(g1, tm1, n) + ref_support(g2, tm2, m);
}

static double planeSigned(const McdGeometryData *g, MeMatrix4 tm, MeMatrix4 plane, double nOut[3])
{
    double N[3] = {plane[2][0], plane[2][1], plane[2][2]}, m[3] = {-N[0], -N[1], -N[2]};
    double lowest = -ref_support(g, tm, m); /* min over the shape of x . N */
    double off = plane[3][0] * N[0] + plane[3][1] * N[1] + plane[3][2] * N[2];
    if (nOut) {
        nOut[0] = m[0];
        nOut[1] = m[1];
        nOut[2] = m[2];
    }
    return lowest - off;
}

/* Overlap along the unit direction n(u, v) = normalize(n0 + u e1 + v e2). */
typedef struct Local {
    const McdGeometryData *g1, *g2;
    MeReal (*tm1)[4];
    MeReal (*tm2)[4];
    double n0[3], e1[3], e2[3];
} Local;

static double localOverlap(const Local *L, const double x[2], double n[3])
{
    double l;
    int i;
    for (i = 0; i < 3; i++)
        n[i] = L->n0[i] + x[0] * L->e1[i] + x[1] * L->e2[i];
    l = sqrt(dot3(n, n));
    for (i = 0; i < 3; i++)
        n[i] /= l;
    return ref_overlap(L->g1, L->tm1, L->g2, L->tm2, n);
}

/* Nelder-Mead in the tangent plane of n (restarted: the overlap has ridges where features change). */
static double refine(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, double n[3])
{
    double f = ref_overlap(g1, tm1, g2, tm2, n);
    int restart;
    for (restart = 0; restart < 4; restart++) {
        Local L = {g1, g2, tm1, tm2, {n[0], n[1], n[2]}, {0, 0, 0}, {0, 0, 0}};
        double a[3] = {1, 0, 0}, x[3][2] = {{0, 0}, {0.02, 0}, {0, 0.02}}, fx[3], tmp[3], l;
        int it, i;
        if (fabs(n[0]) > 0.6) {
            a[0] = 0;
            a[1] = 1;
        }
        L.e1[0] = n[1] * a[2] - n[2] * a[1];
        L.e1[1] = n[2] * a[0] - n[0] * a[2];
        L.e1[2] = n[0] * a[1] - n[1] * a[0];
        l = sqrt(dot3(L.e1, L.e1));
        for (i = 0; i < 3; i++)
            L.e1[i] /= l;
        L.e2[0] = n[1] * L.e1[2] - n[2] * L.e1[1];
        L.e2[1] = n[2] * L.e1[0] - n[0] * L.e1[2];
        L.e2[2] = n[0] * L.e1[1] - n[1] * L.e1[0];
        for (i = 0; i < 3; i++)
            fx[i] = localOverlap(&L, x[i], tmp);
        for (it = 0; it < 400; it++) {
            int hi = 0, lo = 0, mid;
            double c[2], xr[2], fr;
            for (i = 1; i < 3; i++) {
                if (fx[i] > fx[hi])
                    hi = i;
                if (fx[i] < fx[lo])
                    lo = i;
            }
            mid = 3 - hi - lo;
            if (hi == lo)
                mid = (hi + 1) % 3, lo = (hi + 2) % 3;
            if (fabs(x[hi][0] - x[lo][0]) + fabs(x[hi][1] - x[lo][1]) < 1e-13)
                break;
            c[0] = 0.5 * (x[lo][0] + x[mid][0]);
            c[1] = 0.5 * (x[lo][1] + x[mid][1]);
            xr[0] = 2 * c[0] - x[hi][0];
            xr[1] = 2 * c[1] - x[hi][1];
            fr = localOverlap(&L, xr, tmp);
            if (fr < fx[lo]) {
                double xe[2] = {3 * c[0] - 2 * x[hi][0], 3 * c[1] - 2 * x[hi][1]};
                double fe = localOverlap(&L, xe, tmp);
                if (fe < fr) {
                    memcpy(x[hi], xe, sizeof xe);
                    fx[hi] = fe;
                } else {
                    memcpy(x[hi], xr, sizeof xr);
                    fx[hi] = fr;
                }
            } else if (fr < fx[mid]) {
                memcpy(x[hi], xr, sizeof xr);
                fx[hi] = fr;
            } else {
                double xc[2] = {0.5 * (c[0] + x[hi][0]), 0.5 * (c[1] + x[hi][1])};
                double fc = localOverlap(&L, xc, tmp);
                if (fc < fx[hi]) {
                    memcpy(x[hi], xc, sizeof xc);
                    fx[hi] = fc;
                } else { /* shrink towards the best */
                    for (i = 0; i < 3; i++)
                        if (i != lo) {
                            x[i][0] = 0.5 * (x[i][0] + x[lo][0]);
                            x[i][1] = 0.5 * (x[i][1] + x[lo][1]);
                            fx[i] = localOverlap(&L, x[i], tmp);
                        }
                }
            }
        }
        {
            int best = 0;
            for (i = 1; i < 3; i++)
                if (fx[i] < fx[best])
                    best = i;
            if (fx[best] < f) {
                f = localOverlap(&L, x[best], n);
            }
        }
    }
    return f;
}

double ref_signed_distance(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                           double nOut[3])
{
    enum { K = 1200, KEEP = 4, SEEDS = KEEP + 30 };
    double seeds[SEEDS][4];
    double golden = REF_PI * (3.0 - sqrt(5.0)), result = 1e300, rn[3] = {0, 0, 1};
    int k, j, ns = KEEP;
    if (g2->type == kMcdGeometryTypePlane)
        return planeSigned(g1, tm1, tm2, nOut);
    if (g1->type == kMcdGeometryTypePlane) {
        double s = planeSigned(g2, tm2, tm1, nOut);
        if (nOut)
            for (k = 0; k < 3; k++)
                nOut[k] = -nOut[k];
        return s;
    }
    for (j = 0; j < KEEP; j++)
        seeds[j][3] = 1e300;
    /* Fibonacci sphere, keep the KEEP smallest overlaps */
    for (k = 0; k < K; k++) {
        double z = 1 - (2.0 * k + 1) / K, r = sqrt(1 - z * z), phi = golden * k;
        double n[3] = {r * cos(phi), r * sin(phi), z}, f = ref_overlap(g1, tm1, g2, tm2, n);
        int w = 0;
        for (j = 1; j < KEEP; j++)
            if (seeds[j][3] > seeds[w][3])
                w = j;
        if (f < seeds[w][3]) {
            seeds[w][0] = n[0];
            seeds[w][1] = n[1];
            seeds[w][2] = n[2];
            seeds[w][3] = f;
        }
    }
    /* structural candidates, where the overlap has kinks: the shapes' axes (box faces, caps) and the
     * cross products of their axes (edge-edge) */
    for (k = 0; k < 3; k++)
        for (j = 0; j < 3; j++) {
            double c[3], l;
            c[0] = tm1[k][1] * tm2[j][2] - tm1[k][2] * tm2[j][1];
            c[1] = tm1[k][2] * tm2[j][0] - tm1[k][0] * tm2[j][2];
            c[2] = tm1[k][0] * tm2[j][1] - tm1[k][1] * tm2[j][0];
            l = sqrt(dot3(c, c));
            if (l < 1e-9)
                continue;
            seeds[ns][0] = c[0] / l;
            seeds[ns][1] = c[1] / l;
            seeds[ns][2] = c[2] / l;
            ns++;
            seeds[ns][0] = -c[0] / l;
            seeds[ns][1] = -c[1] / l;
            seeds[ns][2] = -c[2] / l;
            ns++;
        }
    for (k = 0; k < 3 && ns + 4 <= SEEDS; k++) {
        for (j = 0; j < 3; j++) {
            seeds[ns][j] = tm1[k][j];
            seeds[ns + 1][j] = -tm1[k][j];
            seeds[ns + 2][j] = tm2[k][j];
            seeds[ns + 3][j] = -tm2[k][j];
        }
        ns += 4;
    }
    for (j = 0; j < ns; j++) {
        double n[3] = {seeds[j][0], seeds[j][1], seeds[j][2]}, f, l = sqrt(dot3(n, n));
        n[0] /= l;
        n[1] /= l;
        n[2] /= l;
        f = j < KEEP ? refine(g1, tm1, g2, tm2, n) : ref_overlap(g1, tm1, g2, tm2, n);
        if (j >= KEEP && f < result + 0.05)
            f = refine(g1, tm1, g2, tm2, n);
        if (f < result) {
            result = f;
            memcpy(rn, n, sizeof rn);
        }
    }
    if (nOut)
        memcpy(nOut, rn, sizeof rn);
    return -result;
}

double ref_box_box_sat(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2)
{
    double axes[15][3], T[3], best = 1e300;
    int n = 0, i, j, k;
    for (i = 0; i < 3; i++) {
        T[i] = tm2[3][i] - tm1[3][i];
        for (k = 0; k < 3; k++) {
            axes[n][k] = tm1[i][k];
            axes[n + 1][k] = tm2[i][k];
        }
        n += 2;
    }
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            double *c = axes[n], l;
            c[0] = tm1[i][1] * tm2[j][2] - tm1[i][2] * tm2[j][1];
            c[1] = tm1[i][2] * tm2[j][0] - tm1[i][0] * tm2[j][2];
            c[2] = tm1[i][0] * tm2[j][1] - tm1[i][1] * tm2[j][0];
            l = sqrt(dot3(c, c));
            if (l < 1e-6)
                continue;
            c[0] /= l;
            c[1] /= l;
            c[2] /= l;
            n++;
        }
    for (k = 0; k < n; k++) {
        double ra = 0, rb = 0, o;
        for (i = 0; i < 3; i++) {
            double a1[3] = {tm1[i][0], tm1[i][1], tm1[i][2]}, b1[3] = {tm2[i][0], tm2[i][1], tm2[i][2]};
            ra += g1->u.box.radii[i] * fabs(dot3(a1, axes[k]));
            rb += g2->u.box.radii[i] * fabs(dot3(b1, axes[k]));
        }
        o = ra + rb - fabs(dot3(T, axes[k]));
        if (o < best)
            best = o;
    }
    return best;
}

double ref_size(const McdGeometryData *g)
{
    switch (g->type) {
    case kMcdGeometryTypeSphere:
        return g->u.sphere.radius;
    case kMcdGeometryTypeBox:
        return sqrt((double)g->u.box.radii[0] * g->u.box.radii[0] + (double)g->u.box.radii[1] * g->u.box.radii[1] +
                    (double)g->u.box.radii[2] * g->u.box.radii[2]);
    case kMcdGeometryTypeSphyl:
        return g->u.sphyl.radius + g->u.sphyl.halfHeight;
    case kMcdGeometryTypeCylinder:
        return hypot(g->u.cylinder.radius, g->u.cylinder.halfHeight);
    case kMcdGeometryTypeCone:
        return hypot(g->u.cone.lowerRadius, g->u.cone.zUpper - g->u.cone.zLower);
    case kMcdGeometryTypeConvexMesh:
        return g->u.convex.hull->radius + g->u.convex.fatness;
    default:
        return 1;
    }
}

const char *ref_type_name(int type)
{
    switch (type) {
    case kMcdGeometryTypeSphere: return "sphere";
    case kMcdGeometryTypeBox: return "box";
    case kMcdGeometryTypePlane: return "plane";
    case kMcdGeometryTypeCylinder: return "cylinder";
    case kMcdGeometryTypeSphyl: return "sphyl";
    case kMcdGeometryTypeCone: return "cone";
    case kMcdGeometryTypeConvexMesh: return "convex";
    default: return "?";
    }
}
