/* bench_ode.c -- an ODE world as every ODE bench driver sets it up (see bench_ode.h). */
#include "bench_ode.h"

#include <string.h>

void bench_ode_open(BenchOde *o, double gx, double gy, double gz, int quickIterations, double friction)
{
    o->world = dWorldCreate();
    dWorldSetGravity(o->world, gx, gy, gz);
    dWorldSetQuickStepNumIterations(o->world, quickIterations);
    o->space = dHashSpaceCreate(0);
    o->contactGroup = dJointGroupCreate(0);
    o->friction = friction;
    o->contacts = 0;
}

int bench_ode_collide(BenchOde *o, dGeomID g1, dGeomID g2)
{
    dBodyID b1 = dGeomGetBody(g1), b2 = dGeomGetBody(g2);
    dContact contact[BENCH_ODE_MAX_CONTACTS];
    int n = dCollide(g1, g2, BENCH_ODE_MAX_CONTACTS, &contact[0].geom, sizeof(dContact));
    for (int i = 0; i < n; i++) {
        memset(&contact[i].surface, 0, sizeof contact[i].surface);
        contact[i].surface.mode = dContactApprox1;
        contact[i].surface.mu = o->friction;
        dJointID j = dJointCreateContact(o->world, o->contactGroup, &contact[i]);
        dJointAttach(j, b1, b2);
    }
    o->contacts += n;
    return n;
}

void bench_ode_close(BenchOde *o)
{
    if (o->contactGroup)
        dJointGroupDestroy(o->contactGroup);
    if (o->space)
        dSpaceDestroy(o->space); /* destroys its geoms too (cleanup mode on by default) */
    if (o->world)
        dWorldDestroy(o->world); /* and its bodies and joints */
    o->contactGroup = NULL;
    o->space = NULL;
    o->world = NULL;
}
