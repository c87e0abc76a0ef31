/* convex_mass.h -- exact mass properties of a convex polyhedron rounded by a radius (internal). */
#ifndef MCD_CONVEX_MASS_H
#define MCD_CONVEX_MASS_H

#include "convex_hull.h"

/** Unit-density volume, centre of mass and inertia (about the centre of mass) of the hull h grown by
 *  `fatness` (m, >= 0: the Minkowski sum with a ball), written into h->volume, centreOfMass, inertia.
 *  Exact up to rounding (docs/collision.md, "Convex meshes"). MEFALSE when memory ran out. */
MeBool McdHullComputeMass(McdHull *h, MeReal fatness);

#endif /* MCD_CONVEX_MASS_H */
