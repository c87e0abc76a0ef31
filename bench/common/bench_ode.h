/* bench_ode.h -- an ODE world as every ODE bench driver sets it up (bench/peers' and bench/convex's):
 * a world with the scene's gravity and quickstep iterations, a hash space, one contact group emptied
 * after each step, and the contacts of a geom pair as ODE users write them (up to
 * BENCH_ODE_MAX_CONTACTS per pair, the friction pyramid dContactApprox1 with the scene's μ). */
#ifndef BENCH_ODE_H
#define BENCH_ODE_H

#include <ode/ode.h>

#define BENCH_ODE_MAX_CONTACTS 4

typedef struct BenchOde {
    dWorldID world;
    dSpaceID space;
    dJointGroupID contactGroup;
    double friction; /* μ of every contact */
    int contacts;    /* contact joints made since the count was last set to 0 */
} BenchOde;

/** Create the world (gravity in m/s², quickIterations for dWorldQuickStep), its hash space and its
 *  contact group. */
void bench_ode_open(BenchOde *o, double gx, double gy, double gz, int quickIterations, double friction);
/** Contact joints between the bodies of g1 and g2 (either may be static) for their contacts; adds
 *  them to o->contacts and returns how many. */
int bench_ode_collide(BenchOde *o, dGeomID g1, dGeomID g2);
/** Destroy the contact group, the space (and its geoms) and the world (and its bodies and joints);
 *  what was not created is skipped. */
void bench_ode_close(BenchOde *o);

#endif /* BENCH_ODE_H */
