/* bench_karma.h -- what every Karma bench driver sets up the same way (bench/karma's scenes and
 * bench/convex's): the scenes' contact, a body with the scene's mass properties and pose, and the
 * read-back the runners compare. The scenes' own pools, floors and joints stay in each driver. */
#ifndef BENCH_KARMA_H
#define BENCH_KARMA_H

#include <karma/karma.h>

/** The universe's default contact as every engine runs it: 2D friction with the normal-force model,
 *  coefficient mu, restitution 0. */
void bench_karma_contact_defaults(MstUniverseID u, double mu);
/** A body of geometry g whose mass properties are the scene's (mass in kg, principal moments in
 *  kg m² about its origin, not Karma's own from the geometry) at pos, turned by quat (w, x, y, z).
 *  Returns its model, NULL when the universe refused it (a full pool). */
McdModelID bench_karma_body(MstUniverseID u, McdGeometryID g, double mass, const double inertia[3],
                            const double pos[3], const double quat[4]);
/** Contacts the bridge made in the last step. */
int bench_karma_contact_count(MstUniverseID u);
/** Positions and quaternions (w, x, y, z) of count bodies; a NULL body (a fixed one) is skipped. */
void bench_karma_read(MdtBodyID *bodies, int count, double (*pos)[3], double (*quat)[4]);

#endif /* BENCH_KARMA_H */
