/* cone.c -- the cone or truncated cone along local z, origin at its centre of mass.
 *
 * Karma gives a cone a length and a lower radius (and optionally an upper one). The solid is the
 * frustum between the disc of lowerRadius at z = zLower and the disc of upperRadius at zUpper =
 * zLower + length; the origin is placed at the centre of mass, so zLower = -c with c the centroid's
 * height above the lower disc. Mass properties come from integrating discs of radius
 * a(s) = R + (r - R) s / L over the height s in [0, L] (R lower, r upper radius):
 *     V = pi int a^2,  c = int s a^2 / int a^2,  Izz = pi/2 int a^4,
 *     Ixx = pi [ int a^4 / 4 + int s^2 a^2 - c^2 int a^2 ]   (about the centre of mass). */
#include <karma/McdCone.h>

#include "../../me/check.h"
#include "geometry.h"

/* The integrals above, in closed form (polynomials in R, r and L). */
typedef struct ConeMoments {
    MeReal a2, a4, sa2, s2a2; /* int a^2, int a^4, int s a^2, int s^2 a^2 over [0, L] */
} ConeMoments;

static ConeMoments coneMoments(MeReal L, MeReal R, MeReal r)
{
    ConeMoments m;
    MeReal k = r - R;
    m.a2 = L * (R * R + R * r + r * r) / 3;
    m.a4 = L * (R * R * R * R + R * R * R * r + R * R * r * r + R * r * r * r + r * r * r * r) / 5;
    m.sa2 = L * L * (R * R / 2 + 2 * R * k / 3 + k * k / 4);
    m.s2a2 = L * L * L * (R * R / 3 + R * k / 2 + k * k / 5);
    return m;
}

static void setParameters(McdConeData *c, MeReal length, MeReal lower, MeReal upper)
{
    ConeMoments m = coneMoments(length, lower, upper);
    MeReal centroid = m.sa2 / m.a2;
    c->lowerRadius = lower;
    c->upperRadius = upper;
    c->zLower = -centroid;
    c->zUpper = length - centroid;
}

static void coneAABB(McdGeometryID g, void *data, MeMatrix4 tm, MeVector3 minCorner, MeVector3 maxCorner)
{
    (void)g;
    const McdConeData *c = data;
    const McdAxialShape shape = {c->zLower, c->lowerRadius, c->zUpper, c->upperRadius, 0};
    McdAABBOfAxialShape(tm, &shape, minCorner, maxCorner);
}

static void coneBSphere(McdGeometryID g, void *data, MeVector3 centre, MeReal *radius)
{
    (void)g;
    const McdConeData *c = data;
    MeReal lo = MeSqrt(c->lowerRadius * c->lowerRadius + c->zLower * c->zLower);
    MeReal hi = MeSqrt(c->upperRadius * c->upperRadius + c->zUpper * c->zUpper);
    MeVector3Set(centre, 0, 0, 0);
    *radius = lo > hi ? lo : hi;
}

static void coneSupport(McdGeometryID g, void *data, const MeVector3 dir, MeVector3 point)
{
    (void)g;
    const McdConeData *c = data;
    /* The frustum is the hull of its two rims: the better of the two discs' support points. */
    MeVector3 lo, hi;
    McdDiscSupport(dir, c->lowerRadius, c->zLower, lo);
    McdDiscSupport(dir, c->upperRadius, c->zUpper, hi);
    MeVector3Copy(point, MeVector3Dot(hi, dir) > MeVector3Dot(lo, dir) ? hi : lo);
}

static void coneMass(McdGeometryID g, void *data, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)
{
    (void)g;
    const McdConeData *c = data;
    MeReal L = c->zUpper - c->zLower;
    ConeMoments m = coneMoments(L, c->lowerRadius, c->upperRadius);
    MeReal centroid = -c->zLower;
    MeReal ixx = ME_PI * (m.a4 / 4 + m.s2a2 - centroid * centroid * m.a2);
    MeMatrix4TMMakeIdentity(relTM);
    McdDiagonalInertia(inertia, ixx, ixx, ME_PI * m.a4 / 2);
    *volume = ME_PI * m.a2;
}

static int coneSegment(McdGeometryID g, void *data, const MeVector3 p0, const MeVector3 p1, MeReal *t,
                       MeVector3 normal)
{
    (void)g;
    const McdConeData *c = data;
    MeVector3 d;
    MeVector3Subtract(d, p1, p0);
    /* radius(z) = alpha + beta z, from lowerRadius at zLower to upperRadius at zUpper. */
    MeReal beta = (c->upperRadius - c->lowerRadius) / (c->zUpper - c->zLower);
    MeReal alpha = c->lowerRadius - beta * c->zLower;
    McdLineInterval iv;
    McdLineIntervalAll(&iv);
    McdLineIntervalSlab(&iv, p0, d, 2, c->zLower, c->zUpper);
    McdLineIntervalCone(&iv, p0, d, alpha, beta);
    return McdLineIntervalToSegmentHit(&iv, d, t, normal);
}

const McdGeometryTypeDesc McdConeTypeDesc = {"Cone", NULL, coneAABB, coneBSphere, coneSupport, coneMass, coneSegment,
                                             NULL};

static MeBool checkParameters(const McdFrameworkData *fw, MeReal length, MeReal lower, MeReal upper, const char *function)
{
    if (!McdCheckDimension(fw, length, "length", MEFALSE, function) ||
        !McdCheckDimension(fw, lower, "lowerRadius", MEFALSE, function) ||
        !McdCheckDimension(fw, upper, "upperRadius", METRUE, function))
        return MEFALSE;
    if (upper > lower) {
        ME_REPORT_IN(function, ME_ERR_MCD_DEGENERATE_GEOMETRY,
                     "upperRadius (%g) must not exceed lowerRadius (%g); call ignored", (double)upper, (double)lower);
        return MEFALSE;
    }
    return METRUE;
}

McdConeID McdConeCreate(McdFrameworkID fwId, MeReal length, MeReal lowerRadius)
{
    McdFrameworkData *fw = McdFrameworkFromID(fwId, __func__);
    if (!fw || !checkParameters(fw, length, lowerRadius, 0, __func__))
        return NULL;
    McdGeometryData *g = McdGeometryNew(fw, kMcdGeometryTypeCone, __func__);
    if (!g)
        return NULL;
    setParameters(&g->u.cone, length, lowerRadius, 0);
    return McdGeometryToID(g);
}

void McdConeSetGeometricalParameters(McdConeID id, MeReal length, MeReal lowerRadius, MeReal upperRadius)
{
    McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCone, __func__);
    if (g && checkParameters(g->framework, length, lowerRadius, upperRadius, __func__))
        setParameters(&g->u.cone, length, lowerRadius, upperRadius);
}

#define CONE_GETTER(name, expr)                                                                      \
    MeReal name(McdConeID id)                                                                        \
    {                                                                                                \
        McdGeometryData *g = McdGeometryOfType(id, kMcdGeometryTypeCone, __func__);                      \
        return g ? (expr) : 0;                                                                       \
    }
CONE_GETTER(McdConeGetLength, g->u.cone.zUpper - g->u.cone.zLower)
CONE_GETTER(McdConeGetLowerRadius, g->u.cone.lowerRadius)
CONE_GETTER(McdConeGetUpperRadius, g->u.cone.upperRadius)
CONE_GETTER(McdConeGetLowerZ, g->u.cone.zLower)
CONE_GETTER(McdConeGetUpperZ, g->u.cone.zUpper)
CONE_GETTER(McdConeGetZOffset, g->u.cone.zLower)
