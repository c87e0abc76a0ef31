/* karma_mcd_reference.h -- independent references for the collision tests (double precision):
 * geometry records built by hand, random poses, exact signed distance to each primitive's surface,
 * support functions of the full shapes, and the signed distance between two convex shapes found by
 * minimising the overlap extent h1(n) + h2(-n) over directions (dense sampling, then local search).
 * Written apart from src/mcd so that a mistake there cannot hide here. */
#ifndef KARMA_MCD_REFERENCE_H
#define KARMA_MCD_REFERENCE_H

#include "mcd/mcd_internal.h"

void ref_make_sphere(McdGeometryData *g, double r);
void ref_make_box(McdGeometryData *g, double dx, double dy, double dz); /* full edge lengths */
void ref_make_cylinder(McdGeometryData *g, double r, double height);
void ref_make_sphyl(McdGeometryData *g, double r, double height);       /* height of the cylinder part */
/* a cone along z, lower radius at the base, upper radius (0: pointed) at height above the base;
 * the origin is its centre of mass */
void ref_make_cone(McdGeometryData *g, double lowerRadius, double upperRadius, double height);
void ref_make_plane(McdGeometryData *g);
/** A convex mesh: the hull of n points (built by the library's McdHullBuild, whose output the hull
 *  tests check against brute force) rounded by fatness; free it with ref_free_convex. */
void ref_make_convex(McdGeometryData *g, MeVector3 *points, int n, double fatness);
void ref_free_convex(McdGeometryData *g);

/** xorshift generator, deterministic on every platform. */
typedef struct RefRng { uint64_t s; } RefRng;
double ref_uniform(RefRng *r, double lo, double hi);
/** A uniformly random rotation and the given position. */
void ref_random_tm(RefRng *r, MeMatrix4 tm, double x, double y, double z);
/** tm = rotation by angle about the unit axis (ax, ay, az), at (x, y, z). */
void ref_tm_axis_angle(MeMatrix4 tm, double ax, double ay, double az, double angle, double x, double y, double z);

/** Signed distance from the world point p to the surface of g at tm (< 0 inside). Plane: height. */
double ref_sdf(const McdGeometryData *g, MeMatrix4 tm, const double p[3]);
/** Support value max over the shape of x . d (world, d unit). */
double ref_support(const McdGeometryData *g, MeMatrix4 tm, const double d[3]);
/** Overlap extent along the unit n (1 -> 2): h1(n) + h2(-n). */
double ref_overlap(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, const double n[3]);
/** Signed distance between two convex shapes (< 0: penetration depth) = -min_n overlap(n), with the
 *  minimising direction in nOut (may be NULL). Plane as geometry 2: exact. */
double ref_signed_distance(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                           double nOut[3]);
/** Box-box penetration by the fifteen separating axes (> 0 overlap, < 0 a separating gap along the
 *  best axis; a lower bound of the distance when apart). */
double ref_box_box_sat(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2);
/** A size of the shape (for relative tolerances). */
double ref_size(const McdGeometryData *g);
const char *ref_type_name(int type);

#endif
