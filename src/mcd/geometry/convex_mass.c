/* convex_mass.c -- exact mass properties of a rounded convex polyhedron.
 *
 * The solid P + B(r) (every point within r of the polyhedron P) is the disjoint union of P, a slab of
 * thickness r on each face, a wedge of a cylinder of radius r along each edge (its angle the exterior
 * dihedral angle) and a cone sector of the ball of radius r at each vertex (its directions the
 * vertex's normal cone). Each piece's volume, first and second moments have closed forms; their
 * volumes add up to Steiner's V + S r + M r^2 + 4/3 pi r^3. Everything in double, relative to the
 * vertices' mean. */
#include <math.h>
#include <string.h>

#include <karma/MeMemory.h>

#include "convex_mass.h"

#define PI 3.14159265358979323846

typedef struct Moments {
    double vol, first[3], second[3][3];
} Moments;

/* The polyhedron: each polygon a fan of triangles, each triangle with ref a tetrahedron whose
 * second moment (a vertex at the origin, the others a, b, c) is V/20 (aa' + bb' + cc' + ss'), s = a + b + c. */
static void polyhedronMoments(const McdHull *h, const double ref[3], Moments *m)
{
    int i, j, k, p;
    for (p = 0; p < h->polygonCount; p++) {
        const int *pv = &h->polygonVertices[h->polygonStart[p]];
        int n = h->polygonStart[p + 1] - h->polygonStart[p];
        for (i = 1; i + 1 < n; i++) {
            double x[3][3], s[3], v;
            const int idx[3] = {pv[0], pv[i], pv[i + 1]};
            for (j = 0; j < 3; j++)
                for (k = 0; k < 3; k++)
                    x[j][k] = (double)h->vertices[idx[j]][k] - ref[k];
            v = (x[0][0] * (x[1][1] * x[2][2] - x[1][2] * x[2][1]) - x[0][1] * (x[1][0] * x[2][2] - x[1][2] * x[2][0]) +
                 x[0][2] * (x[1][0] * x[2][1] - x[1][1] * x[2][0])) /
                6;
            for (k = 0; k < 3; k++)
                s[k] = x[0][k] + x[1][k] + x[2][k];
            m->vol += v;
            for (k = 0; k < 3; k++)
                m->first[k] += v * s[k] / 4;
            for (j = 0; j < 3; j++)
                for (k = 0; k < 3; k++)
                    m->second[j][k] += v / 20 * (x[0][j] * x[0][k] + x[1][j] * x[1][k] + x[2][j] * x[2][k] + s[j] * s[k]);
        }
    }
}

static void sub3(double out[3], const double a[3], const double b[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = a[k] - b[k];
}
static void cross3(double out[3], const double a[3], const double b[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}
static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double angleBetween(const double a[3], const double b[3])
{
    double c[3];
    cross3(c, a, b);
    return atan2(sqrt(dot3(c, c)), dot3(a, b));
}
/* out += s (a b' + b a') */
static void addSym(double out[3][3], double s, const double a[3], const double b[3])
{
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            out[j][k] += s * (a[j] * b[k] + b[j] * a[k]);
}
static void addOuter(double out[3][3], double s, const double a[3], const double b[3])
{
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            out[j][k] += s * a[j] * b[k];
}

/* Vertex p of the hull relative to ref, in double. */
static void vertexAt(double out[3], const McdHull *h, int v, const double ref[3])
{
    for (int k = 0; k < 3; k++)
        out[k] = (double)h->vertices[v][k] - ref[k];
}

/* The polygon that holds the directed edge b -> a (the neighbour across a -> b of polygon p), or -1. */
static int polygonAcross(const McdHull *h, int p, int a, int b)
{
    for (int i = h->vertexPolygonStart[a]; i < h->vertexPolygonStart[a + 1]; i++) {
        int q = h->vertexPolygons[i], s = h->polygonStart[q], n = h->polygonStart[q + 1] - s;
        if (q == p)
            continue;
        for (int j = 0; j < n; j++)
            if (h->polygonVertices[s + j] == b && h->polygonVertices[s + (j + 1) % n] == a)
                return q;
    }
    return -1;
}

/* Unit outward normal of polygon p in double (Newell's method on its vertices). */
static void polygonNormal(double n[3], const McdHull *h, int p)
{
    const int s = h->polygonStart[p], c = h->polygonStart[p + 1] - s;
    double len;
    n[0] = n[1] = n[2] = 0;
    for (int i = 0; i < c; i++) {
        const MeReal *u = h->vertices[h->polygonVertices[s + i]], *w = h->vertices[h->polygonVertices[s + (i + 1) % c]];
        n[0] += ((double)u[1] - (double)w[1]) * ((double)u[2] + (double)w[2]);
        n[1] += ((double)u[2] - (double)w[2]) * ((double)u[0] + (double)w[0]);
        n[2] += ((double)u[0] - (double)w[0]) * ((double)u[1] + (double)w[1]);
    }
    len = sqrt(dot3(n, n));
    for (int k = 0; k < 3; k++)
        n[k] /= len;
}

/* A slab {x + t n : x in polygon p, 0 <= t <= r}: the polygon's area A, first moment f and second F
 * (fan of triangles: A s/3 and A/12 (sum x x' + s s')), then
 * vol A r, first r f + A r^2/2 n, second r F + r^2/2 (f n' + n f') + A r^3/3 n n'. */
static void slabMoments(const McdHull *h, int p, const double n[3], double r, const double ref[3], Moments *m)
{
    const int *pv = &h->polygonVertices[h->polygonStart[p]];
    const int c = h->polygonStart[p + 1] - h->polygonStart[p];
    double A = 0, f[3] = {0, 0, 0}, F[3][3] = {{0}};
    for (int i = 1; i + 1 < c; i++) {
        double x[3][3], e1[3], e2[3], cr[3], s[3], a;
        vertexAt(x[0], h, pv[0], ref);
        vertexAt(x[1], h, pv[i], ref);
        vertexAt(x[2], h, pv[i + 1], ref);
        sub3(e1, x[1], x[0]);
        sub3(e2, x[2], x[0]);
        cross3(cr, e1, e2);
        a = dot3(cr, n) / 2;
        for (int k = 0; k < 3; k++)
            s[k] = x[0][k] + x[1][k] + x[2][k];
        A += a;
        for (int k = 0; k < 3; k++)
            f[k] += a * s[k] / 3;
        for (int j = 0; j < 3; j++)
            addOuter(F, a / 12, x[j], x[j]);
        addOuter(F, a / 12, s, s);
    }
    m->vol += A * r;
    for (int k = 0; k < 3; k++)
        m->first[k] += r * f[k] + A * r * r / 2 * n[k];
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            m->second[j][k] += r * F[j][k];
    addSym(m->second, r * r / 2, f, n);
    addOuter(m->second, A * r * r * r / 3, n, n);
}

/* The wedge along the edge a -> b between the faces of normals n1 and n2 (angle phi apart):
 * x = a + s e + rho w(alpha), w = n1 cos alpha + t sin alpha, 0 <= s <= L, 0 <= rho <= r,
 * 0 <= alpha <= phi, dV = rho. W1 = int w = (n1 + n2) tan(phi/2), W2 = int w w'.
 * Size: the edge, its faces' normals, their angle and the radius are the formula's own terms. */
static void wedgeMoments(const double a[3], const double b[3], const double n1[3], const double n2[3], double phi,
                         double r, Moments *m)
{
    double e[3], t[3], W1[3], W2[3][3] = {{0}}, C1[3], L, sp = sin(phi), cp = cos(phi), tanHalf = tan(phi / 2);
    sub3(e, b, a);
    L = sqrt(dot3(e, e));
    for (int k = 0; k < 3; k++) {
        e[k] /= L;
        t[k] = (n2[k] - n1[k] * cp) / sp;
        W1[k] = (n1[k] + n2[k]) * tanHalf;
        C1[k] = a[k] * L + e[k] * L * L / 2; /* int (a + s e) ds */
    }
    addOuter(W2, phi / 2 + sin(2 * phi) / 4, n1, n1);
    addOuter(W2, phi / 2 - sin(2 * phi) / 4, t, t);
    addSym(W2, sp * sp / 2, n1, t);
    const double area = phi * r * r / 2;
    m->vol += area * L;
    for (int k = 0; k < 3; k++)
        m->first[k] += area * C1[k] + L * r * r * r / 3 * W1[k];
    addOuter(m->second, area * L, a, a);
    addSym(m->second, area * L * L / 2, a, e);
    addOuter(m->second, area * L * L * L / 3, e, e);
    addSym(m->second, r * r * r / 3, C1, W1);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            m->second[j][k] += r * r * r * r / 4 * L * W2[j][k];
}

/* Per vertex, over its normal cone N (a spherical polygon whose arcs lie in the planes normal to the
 * vertex's edges): the solid angle (the angle defect: 2 pi - the polygons' angles there), and from
 * Green's identity on the sphere (Laplace-Beltrami: u is an eigenfunction of eigenvalue -2, u u' - I/3
 * of -6) int_N u = -1/2 sum theta m and int_N u u' = Omega/3 I - 1/6 sum (m c' + c m'), m the unit
 * edge direction away from the vertex (the arc's outward conormal), theta the arc's angle, c the
 * integral of u along it, (n1 + n2) tan(theta/2). */
typedef struct VertexCone {
    double omega, u1[3], s2[3][3];
} VertexCone;

static void vertexMoments(const double v[3], const VertexCone *cone, double r, Moments *m)
{
    const double r3 = r * r * r, r4 = r3 * r, r5 = r4 * r, vol = cone->omega * r3 / 3;
    m->vol += vol;
    for (int k = 0; k < 3; k++)
        m->first[k] += v[k] * vol + r4 / 4 * cone->u1[k];
    addOuter(m->second, vol, v, v);
    addSym(m->second, r4 / 4, v, cone->u1);
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            m->second[j][k] += r5 / 5 * ((j == k ? cone->omega / 3 : 0) - cone->s2[j][k] / 6);
}

/* The rounded parts (slabs, wedges, vertex sectors); MEFALSE when memory ran out. */
static MeBool roundedMoments(const McdHull *h, double r, const double ref[3], Moments *m)
{
    VertexCone *cones = MeMemoryCreate((size_t)h->vertexCount * sizeof *cones);
    double (*normals)[3] = MeMemoryCreate((size_t)h->polygonCount * sizeof *normals);
    if (!cones || !normals) {
        MeMemoryDestroy(cones);
        MeMemoryDestroy(normals);
        return MEFALSE;
    }
    memset(cones, 0, (size_t)h->vertexCount * sizeof *cones);
    for (int v = 0; v < h->vertexCount; v++)
        cones[v].omega = 2 * PI;
    for (int p = 0; p < h->polygonCount; p++)
        polygonNormal(normals[p], h, p);
    for (int p = 0; p < h->polygonCount; p++) {
        const int s = h->polygonStart[p], c = h->polygonStart[p + 1] - s;
        slabMoments(h, p, normals[p], r, ref, m);
        for (int i = 0; i < c; i++) {
            const int ia = h->polygonVertices[s + i], ib = h->polygonVertices[s + (i + 1) % c],
                      iz = h->polygonVertices[s + (i + c - 1) % c];
            double a[3], b[3], z[3], ab[3], az[3];
            vertexAt(a, h, ia, ref);
            vertexAt(b, h, ib, ref);
            vertexAt(z, h, iz, ref);
            sub3(ab, b, a);
            sub3(az, z, a);
            cones[ia].omega -= angleBetween(ab, az);
            const int q = polygonAcross(h, p, ia, ib);
            if (q < p) /* each edge once, from the polygon of lower index (q = -1 cannot happen on a closed hull) */
                continue;
            const double phi = angleBetween(normals[p], normals[q]);
            if (!(phi > 1e-12))
                continue;
            double e[3], arc[3], len = sqrt(dot3(ab, ab)), tanHalf = tan(phi / 2);
            for (int k = 0; k < 3; k++) {
                e[k] = ab[k] / len;
                arc[k] = (normals[p][k] + normals[q][k]) * tanHalf;
            }
            wedgeMoments(a, b, normals[p], normals[q], phi, r, m);
            for (int k = 0; k < 3; k++) {
                cones[ia].u1[k] -= phi / 2 * e[k];
                cones[ib].u1[k] += phi / 2 * e[k];
            }
            addSym(cones[ia].s2, 1, e, arc);
            addSym(cones[ib].s2, -1, e, arc);
        }
    }
    for (int v = 0; v < h->vertexCount; v++) {
        double x[3];
        vertexAt(x, h, v, ref);
        vertexMoments(x, &cones[v], r, m);
    }
    MeMemoryDestroy(cones);
    MeMemoryDestroy(normals);
    return METRUE;
}

MeBool McdHullComputeMass(McdHull *h, MeReal fatness)
{
    double ref[3] = {0, 0, 0};
    Moments m;
    int i, j, k;
    memset(&m, 0, sizeof m);
    for (i = 0; i < h->vertexCount; i++)
        for (k = 0; k < 3; k++)
            ref[k] += (double)h->vertices[i][k] / h->vertexCount;
    polyhedronMoments(h, ref, &m);
    if (fatness > 0 && !roundedMoments(h, (double)fatness, ref, &m))
        return MEFALSE;
    {
        double g3[3], c[3][3], tr;
        for (k = 0; k < 3; k++)
            g3[k] = m.first[k] / m.vol;
        for (j = 0; j < 3; j++)
            for (k = 0; k < 3; k++)
                c[j][k] = m.second[j][k] - m.vol * g3[j] * g3[k]; /* about the centre of mass */
        tr = c[0][0] + c[1][1] + c[2][2];
        for (j = 0; j < 3; j++)
            for (k = 0; k < 3; k++)
                h->inertia[j][k] = (MeReal)((j == k ? tr : 0) - c[j][k]);
        MeVector3Set(h->centreOfMass, (MeReal)(ref[0] + g3[0]), (MeReal)(ref[1] + g3[1]), (MeReal)(ref[2] + g3[2]));
        h->volume = (MeReal)m.vol;
    }
    return METRUE;
}
