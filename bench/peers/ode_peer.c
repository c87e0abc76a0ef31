/* ode_peer.c -- the benchmark scenes in ODE 0.16 (Debian's libode, double precision).
 *
 * Two variants on the same scenes:
 *   quickstep20  dWorldQuickStep with 20 iterations (ODE's iterative SOR-LCP, default ω = 1.3)
 *   step         dWorldStep (ODE's "big matrix" stepper: dense J M⁻¹ Jᵀ per island, Dantzig LCP)
 * Everything else is ODE's default: ERP 0.2, CFM 1e-5, no contact surface layer, no limit on the
 * correcting velocity, auto-disable off. Collision is ODE's own: a hash space (dSpaceCollide) and
 * dCollide on each candidate pair, at most 4 contacts per pair (ODE culls box-box manifolds to the
 * best-spread points), pairs of bodies joined by a joint skipped. Each contact joint has
 * surface.mode = dContactApprox1 (the friction pyramid scaled by the normal force, so that mu is a
 * Coulomb coefficient rather than a force in newtons) and mu = 0.6; bounce off, no softness beyond
 * the world's. Mass properties are the scene's (BenchBodyInertia: uniform solids).
 *
 * Motors (b2spinner, b2tumbler): the hinge's dParamVel and dParamFMax; initial velocities (b2smash):
 * dBodySetLinearVel.
 *
 * The timed step is what one simulation step costs an ODE user: dSpaceCollide (with contact joint
 * creation), the stepper, and emptying the contact group.
 *
 * dWorldStep builds a dense matrix per island: memory grows with the square of the island's
 * constraint rows and time up to their cube. The 820-box pyramid is one island of ~19,000 rows (a
 * 2.9 GB matrix); the 210-box pyramid, ~4,700 rows, already takes many times quickstep's time
 * (bench/RESULTS.md). So the step variant checks the largest island before each step and stops the run
 * when it exceeds ODE_STEP_ROW_CAP rows, saying so in the note column; the runner's time budget
 * stops runs that are merely slow. */
#include <ode/ode.h>

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_harness.h"
#include "bench_ode.h"

#define ODE_QUICK_ITERATIONS 20
/* Islands larger than this are not given to dWorldStep (the environment variable ODE_STEP_ROW_CAP
 * overrides it, for measuring). */
#define ODE_STEP_ROW_CAP 6000
static long stepRowCap = ODE_STEP_ROW_CAP;
/* Constraint rows ODE gives each joint (contact with friction: normal + 2 tangents; hinge: 5 plus
 * one when at a limit, counted always). */
#define ODE_ROWS_CONTACT 3
#define ODE_ROWS_BALL 3
#define ODE_ROWS_HINGE 6

typedef struct OdeWorld {
    const BenchScene *scene;
    int quick;
    BenchOde ode;
    dBodyID *bodies; /* NULL for fixed bodies */
    /* dWorldStep only: islands of this step (union-find over body indices) */
    int *parent;
    long *rows;
    char why[128];
    char remark[160];
} OdeWorld;

/* ODE prints its messages (e.g. "LCP internal error, s <= 0" from dWorldStep's Dantzig solver) to
 * stderr; count them instead and report the count and the first one in the note column. The harness
 * runs one world at a time, so a process-wide count reset at creation is the current world's. */
static int odeMessages;
static char odeFirstMessage[96];

static void count_message(int errnum, const char *msg, va_list ap)
{
    if (odeMessages++ == 0) {
        char text[80];
        vsnprintf(text, sizeof text, msg, ap);
        for (char *c = text; *c; c++) /* the note column must hold no commas or line breaks */
            if (*c == ',' || *c == '\n')
                *c = ' ';
        snprintf(odeFirstMessage, sizeof odeFirstMessage, "%s (code %d)", text, errnum);
    }
}

static int find_root(int *parent, int i)
{
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

static void join(OdeWorld *w, dBodyID a, dBodyID b, int rows)
{
    if (!w->parent || (!a && !b))
        return;
    int ia = a ? (int)(intptr_t)dBodyGetData(a) : -1, ib = b ? (int)(intptr_t)dBodyGetData(b) : -1;
    if (ia >= 0 && ib >= 0) {
        int ra = find_root(w->parent, ia), rb = find_root(w->parent, ib);
        if (ra != rb) {
            w->parent[rb] = ra;
            w->rows[ra] += w->rows[rb];
            w->rows[rb] = 0;
        }
        w->rows[ra] += rows;
    } else {
        w->rows[find_root(w->parent, ia >= 0 ? ia : ib)] += rows;
    }
}

static void near_callback(void *data, dGeomID g1, dGeomID g2)
{
    OdeWorld *w = data;
    dBodyID b1 = dGeomGetBody(g1), b2 = dGeomGetBody(g2);
    if (!b1 && !b2)
        return; /* static against static (walls, ground) */
    if (b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact))
        return;
    int n = bench_ode_collide(&w->ode, g1, g2);
    for (int i = 0; i < n; i++)
        join(w, b1, b2, ODE_ROWS_CONTACT);
}

static void ode_destroy(void *world)
{
    OdeWorld *w = world;
    if (!w)
        return;
    bench_ode_close(&w->ode);
    free(w->bodies);
    free(w->parent);
    free(w->rows);
    free(w);
}

/* The scene's bodies: a geometry each, fixed ones placed, the others on a body of theirs. */
static void ode_add_bodies(OdeWorld *w)
{
    const BenchScene *scene = w->scene;
    for (int i = 0; i < scene->bodyCount; i++) {
        const BenchBody *b = &scene->bodies[i];
        dGeomID g;
        switch (b->shape) {
        case BENCH_SPHERE:
            g = dCreateSphere(w->ode.space, b->size[0]);
            break;
        case BENCH_CAPSULE: /* ODE's capsule lies along its local z, as the scene's does */
            g = dCreateCapsule(w->ode.space, b->size[0], 2 * b->size[1]);
            break;
        case BENCH_BOX:
        default:
            g = dCreateBox(w->ode.space, 2 * b->size[0], 2 * b->size[1], 2 * b->size[2]);
            break;
        }
        dQuaternion q = {b->quat[0], b->quat[1], b->quat[2], b->quat[3]};
        if (b->fixed) {
            dGeomSetPosition(g, b->pos[0], b->pos[1], b->pos[2]);
            dGeomSetQuaternion(g, q);
            continue;
        }
        double inertia[3];
        dMass m;
        BenchBodyInertia(b, inertia);
        dMassSetParameters(&m, b->mass, 0, 0, 0, inertia[0], inertia[1], inertia[2], 0, 0, 0);
        dBodyID body = dBodyCreate(w->ode.world);
        dBodySetMass(body, &m);
        dBodySetPosition(body, b->pos[0], b->pos[1], b->pos[2]);
        dBodySetQuaternion(body, q);
        dBodySetLinearVel(body, b->vel[0], b->vel[1], b->vel[2]);
        dBodySetData(body, (void *)(intptr_t)i);
        dGeomSetBody(g, body);
        w->bodies[i] = body;
    }
}

/* The scene's joints: ball joints and hinges with their limits and motors. */
static void ode_add_joints(OdeWorld *w)
{
    const BenchScene *scene = w->scene;
    for (int k = 0; k < scene->jointCount; k++) {
        const BenchJoint *bj = &scene->joints[k];
        dBodyID b0 = w->bodies[bj->body[0]], b1 = bj->body[1] >= 0 ? w->bodies[bj->body[1]] : NULL;
        dJointID j;
        if (bj->type == BENCH_BALL) {
            j = dJointCreateBall(w->ode.world, 0);
            dJointAttach(j, b0, b1);
            dJointSetBallAnchor(j, bj->anchor[0], bj->anchor[1], bj->anchor[2]);
        } else {
            j = dJointCreateHinge(w->ode.world, 0);
            dJointAttach(j, b0, b1);
            dJointSetHingeAnchor(j, bj->anchor[0], bj->anchor[1], bj->anchor[2]);
            dJointSetHingeAxis(j, bj->axis[0], bj->axis[1], bj->axis[2]);
            if (bj->limited) {
                /* ODE's hinge angle is that of body1 relative to body2, the opposite of the scene's
                 * (body[1] relative to body[0]), so the limits swap and change sign. Setting lo first
                 * is safe: ODE ignores a lo above hi only while it stays so. */
                dJointSetHingeParam(j, dParamLoStop, -bj->hi);
                dJointSetHingeParam(j, dParamHiStop, -bj->lo);
            }
            if (bj->motor) { /* ODE's rate is body1's relative to body2: the motor's sense */
                dJointSetHingeParam(j, dParamVel, bj->motorSpeed);
                dJointSetHingeParam(j, dParamFMax, bj->motorTorque);
            }
        }
    }
}

static void *ode_create(const BenchScene *scene, int quick)
{
    OdeWorld *w = calloc(1, sizeof *w);
    if (!w)
        return NULL;
    w->scene = scene;
    w->quick = quick;
    w->bodies = calloc((size_t)scene->bodyCount, sizeof *w->bodies);
    if (!quick) {
        w->parent = malloc(sizeof *w->parent * (size_t)scene->bodyCount);
        w->rows = malloc(sizeof *w->rows * (size_t)scene->bodyCount);
    }
    if (!w->bodies || (!quick && (!w->parent || !w->rows))) {
        ode_destroy(w);
        return NULL;
    }
    odeMessages = 0;
    odeFirstMessage[0] = '\0';
    dRandSetSeed(0); /* quickstep reorders its rows with ODE's global generator: same start every run */
    bench_ode_open(&w->ode, scene->gravity[0], scene->gravity[1], scene->gravity[2], ODE_QUICK_ITERATIONS,
                   scene->friction);
    if (scene->hasGround) /* the scenes are y-up: the plane y = 0 */
        dCreatePlane(w->ode.space, 0, 1, 0, 0);
    ode_add_bodies(w);
    ode_add_joints(w);
    return w;
}

static void *ode_create_quick(const BenchScene *scene) { return ode_create(scene, 1); }
static void *ode_create_step(const BenchScene *scene) { return ode_create(scene, 0); }

/* Before dWorldStep: the rows of the largest island, from the joints and this step's contacts. */
static long largest_island_rows(OdeWorld *w)
{
    const BenchScene *s = w->scene;
    for (int k = 0; k < s->jointCount; k++) {
        const BenchJoint *bj = &s->joints[k];
        join(w, w->bodies[bj->body[0]], bj->body[1] >= 0 ? w->bodies[bj->body[1]] : NULL,
             bj->type == BENCH_BALL ? ODE_ROWS_BALL : ODE_ROWS_HINGE);
    }
    long largest = 0;
    for (int i = 0; i < s->bodyCount; i++)
        if (w->parent[i] == i && w->rows[i] > largest)
            largest = w->rows[i];
    return largest;
}

static int ode_step(void *world, const char **why)
{
    OdeWorld *w = world;
    w->ode.contacts = 0;
    if (w->parent)
        for (int i = 0; i < w->scene->bodyCount; i++) {
            w->parent[i] = i;
            w->rows[i] = 0;
        }
    dSpaceCollide(w->ode.space, w, near_callback);
    if (w->quick) {
        dWorldQuickStep(w->ode.world, w->scene->step);
    } else {
        long rows = largest_island_rows(w);
        if (rows > stepRowCap) {
            snprintf(w->why, sizeof w->why, "not run: island of %ld rows > %ld (dense LCP cost ~rows^3)", rows,
                     stepRowCap);
            *why = w->why;
            dJointGroupEmpty(w->ode.contactGroup);
            return 1;
        }
        dWorldStep(w->ode.world, w->scene->step);
    }
    dJointGroupEmpty(w->ode.contactGroup);
    return 0;
}

static const char *ode_remark(void *world)
{
    OdeWorld *w = world;
    if (odeMessages == 0)
        return NULL;
    snprintf(w->remark, sizeof w->remark, "%d ODE messages; first: %s", odeMessages, odeFirstMessage);
    return w->remark;
}

static int ode_contacts(void *world) { return ((OdeWorld *)world)->ode.contacts; }

static void ode_read(void *world, double (*pos)[3], double (*quat)[4])
{
    OdeWorld *w = world;
    for (int i = 0; i < w->scene->bodyCount; i++) {
        if (!w->bodies[i])
            continue;
        const dReal *p = dBodyGetPosition(w->bodies[i]), *q = dBodyGetQuaternion(w->bodies[i]);
        for (int k = 0; k < 3; k++)
            pos[i][k] = p[k];
        for (int k = 0; k < 4; k++)
            quat[i][k] = q[k];
    }
}

int main(int argc, char **argv)
{
    static const BenchEngine engines[] = {
        {"ode", "quickstep20", "dWorldQuickStep, 20 iterations, ERP 0.2, CFM 1e-5, dContactApprox1 mu 0.6",
         ode_create_quick, ode_step, ode_contacts, ode_read, ode_destroy, ode_remark},
        {"ode", "step", "dWorldStep (dense LCP), ERP 0.2, CFM 1e-5, dContactApprox1 mu 0.6", ode_create_step,
         ode_step, ode_contacts, ode_read, ode_destroy, ode_remark},
    };
    const char *cap = getenv("ODE_STEP_ROW_CAP");
    if (cap && atol(cap) > 0)
        stepRowCap = atol(cap);
    dInitODE2(0);
    dSetMessageHandler(count_message);
    int status = BenchMain(argc, argv, engines, (int)(sizeof engines / sizeof engines[0]));
    dCloseODE();
    return status;
}
