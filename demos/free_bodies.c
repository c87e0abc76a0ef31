/* free_bodies.c -- the first scene: four bodies in free flight under gravity (y is up).
 *
 * No constraints and no collision yet, so each body shows one part of the integrator, and the
 * report compares it with the answer from mechanics:
 *  - projectile: launched at 45°; apex height and range against v²/2g and 2·vx·vy/g (symplectic
 *    Euler is first order, so the simulated figures differ by O(h));
 *  - tumbler: a box with three different principal moments, its principal frame tilted in the body
 *    frame (a full inertia tensor), spun about its intermediate axis with the gyroscopic term on:
 *    it flips over and over (the tennis-racket effect) while kinetic energy and |L| stay constant;
 *  - wheel: a disc spinning at 100 rad/s about its axis with a fast-spin axis, which turns it by
 *    exactly ω·h per step where the first-order update alone would turn it by 2·atan(ω·h/2);
 *  - damped: a body with linear and angular drag and an offset centre of mass, thrown sideways;
 *    it approaches the terminal speed m·g/c.
 * Later issues add a ground, joints and contacts in scenes of their own. */
#include <math.h>
#include <stdlib.h>

#include "demo.h"

#define GRAVITY ME_R(9.81)

/* projectile */
#define PROJECTILE_SPEED ME_R(10.0) /* m/s along each of x and y */
/* tumbler: box of full edge lengths 0.5 × 2 × 1 m, 4 kg, principal frame tilted by 30° about x */
#define TUMBLER_SPIN ME_R(4.0)       /* rad/s about the intermediate axis */
#define TUMBLER_NUDGE ME_R(0.01)     /* rad/s about the major axis, to start the flip */
/* wheel: disc of radius 0.3 m and thickness 0.1 m, 5 kg, spinning about its y axis */
#define WHEEL_SPIN ME_R(100.0)
/* damped body */
#define DAMPED_MASS ME_R(2.0)
#define DAMPED_LINEAR_DRAG ME_R(0.5)  /* N·s/m */
#define DAMPED_ANGULAR_DRAG ME_R(0.1) /* N·m·s */

typedef struct FreeBodies {
    MdtBodyID projectile, tumbler, wheel, damped;
    /* projectile */
    MeReal apex;           /* highest y reached (m) */
    MeReal landingX;       /* x where y came back to 0 (interpolated), once landed */
    MeBool landed;
    /* tumbler */
    MeVector3 intermediateAxis; /* in the body frame */
    MeReal energy0, momentum0;  /* rotational kinetic energy and |L| at the start */
    MeReal energyDrift, momentumDrift; /* largest relative change seen */
    int flips;
    int lastSign;
    /* wheel */
    MeVector4 wheelQBefore;
    MeReal wheelStepAngle; /* rotation of the last step (rad) */
} FreeBodies;

static MeReal magnitude(const MeVector3 v) { return MeSqrt(MeVector3Dot(v, v)); }

/* For the report's continuous answers only (MeMath has no exponential). */
static double expOf(MeReal x) { return exp((double)x); }

/* Tumbler's body-frame inertia: principal moments D about axes given by the rows of Q. */
static void tiltedInertia(MeMatrix3 I, const MeVector3 D, MeMatrix3 Q)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            I[i][j] = 0;
            for (int k = 0; k < 3; k++)
                I[i][j] += Q[k][i] * D[k] * Q[k][j];
        }
}

/* Rotational kinetic energy ½ ω·L (the tumbler also falls, so MdtBodyGetKineticEnergy would not do). */
static MeReal rotationalEnergy(MdtBodyID b)
{
    MeVector3 w, L;
    MdtBodyGetAngularVelocity(b, w);
    DemoBodyAngularMomentum(b, L);
    return ME_R(0.5) * MeVector3Dot(w, L);
}

/* Sign (+1/−1) of the tumbler's intermediate axis along its angular momentum. */
static int intermediateSign(const FreeBodies *s)
{
    MeMatrix3 R;
    MeVector3 axis, L;
    MdtBodyGetOrientation(s->tumbler, R);
    MeMatrix3MultiplyVector(axis, R, s->intermediateAxis);
    DemoBodyAngularMomentum(s->tumbler, L);
    return MeVector3Dot(axis, L) >= 0 ? 1 : -1;
}

static MeBool createFreeBodies(DemoInstance *demo)
{
    FreeBodies *s = calloc(1, sizeof *s);
    if (!s)
        return MEFALSE;
    demo->data = s;
    demo->world = MdtWorldCreate(16, 16, ME_R(1.0), ME_R(1.0));
    if (!demo->world)
        return MEFALSE;
    MdtWorldSetGravity(demo->world, 0, -GRAVITY, 0);

    MeMatrix3 I;

    /* a ball (radius 0.1 m, 1 kg) launched at 45° from the origin */
    s->projectile = DemoAddNamedBody(demo, "projectile");
    MdtBodySetMass(s->projectile, ME_R(1.0));
    MdtMakeInertiaTensorSphere(ME_R(1.0), ME_R(0.1), I);
    MdtBodySetInertiaTensor(s->projectile, I);
    MdtBodySetLinearVelocity(s->projectile, PROJECTILE_SPEED, PROJECTILE_SPEED, 0);

    /* an asymmetric box about its intermediate axis, with a full (tilted) inertia tensor */
    s->tumbler = DemoAddNamedBody(demo, "tumbler");
    MeMatrix3 box, Q;
    MdtMakeInertiaTensorBox(ME_R(4.0), ME_R(0.5), ME_R(2.0), ME_R(1.0), box);
    MeVector3 D = {box[0][0], box[1][1], box[2][2]}; /* major x, minor y, intermediate z */
    MeMatrix3MakeRotationX(Q, ME_PI / 6);
    tiltedInertia(I, D, Q);
    MdtBodySetMass(s->tumbler, ME_R(4.0));
    MdtBodySetInertiaTensor(s->tumbler, I);
    MdtBodyEnableNonSphericalInertia(s->tumbler);
    MdtBodyEnableCoriolisForce(s->tumbler);
    MdtBodySetPosition(s->tumbler, ME_R(-5.0), ME_R(10.0), 0);
    MeVector3Copy(s->intermediateAxis, Q[2]);
    MdtBodySetAngularVelocity(s->tumbler, TUMBLER_SPIN * Q[2][0] + TUMBLER_NUDGE * Q[0][0],
                              TUMBLER_SPIN * Q[2][1] + TUMBLER_NUDGE * Q[0][1],
                              TUMBLER_SPIN * Q[2][2] + TUMBLER_NUDGE * Q[0][2]);

    /* a disc spinning fast about its axis (body y) */
    s->wheel = DemoAddNamedBody(demo, "wheel");
    MeMatrix3MakeIdentity(I);
    I[0][0] = I[2][2] = ME_R(5.0) * (3 * ME_R(0.3) * ME_R(0.3) + ME_R(0.1) * ME_R(0.1)) / 12;
    I[1][1] = ME_R(0.5) * ME_R(5.0) * ME_R(0.3) * ME_R(0.3);
    MdtBodySetMass(s->wheel, ME_R(5.0));
    MdtBodySetInertiaTensor(s->wheel, I);
    MdtBodyEnableNonSphericalInertia(s->wheel);
    MdtBodyEnableCoriolisForce(s->wheel);
    MdtBodySetPosition(s->wheel, ME_R(5.0), ME_R(10.0), 0);
    MdtBodySetAngularVelocity(s->wheel, 0, WHEEL_SPIN, 0);

    /* a body with drag and an offset centre of mass, thrown sideways and spinning */
    s->damped = DemoAddNamedBody(demo, "damped");
    MdtBodySetMass(s->damped, DAMPED_MASS);
    MdtBodySetSphericalInertiaTensor(s->damped, ME_R(0.2));
    MeVector3 com = {ME_R(0.1), 0, 0};
    MdtBodySetCenterOfMassRelativePosition(s->damped, com);
    MdtBodySetLinearVelocityDamping(s->damped, DAMPED_LINEAR_DRAG);
    MdtBodySetAngularVelocityDamping(s->damped, DAMPED_ANGULAR_DRAG);
    MdtBodySetPosition(s->damped, 0, ME_R(20.0), ME_R(5.0));
    MdtBodySetLinearVelocity(s->damped, ME_R(5.0), 0, 0);
    MdtBodySetAngularVelocity(s->damped, 0, 0, ME_R(5.0));

    MdtBodyID all[4] = {s->projectile, s->tumbler, s->wheel, s->damped};
    for (int i = 0; i < 4; i++)
        MdtBodyEnable(all[i]);

    MeVector3 L;
    DemoBodyAngularMomentum(s->tumbler, L);
    s->energy0 = rotationalEnergy(s->tumbler);
    s->momentum0 = magnitude(L);
    s->lastSign = intermediateSign(s);
    return METRUE;
}

static void beforeFreeBodiesStep(DemoInstance *demo, MeReal h)
{
    FreeBodies *s = demo->data;
    (void)h;
    /* Karma's fast-spin axis is re-set every step; the wheel spins about its own y axis. */
    MdtBodySetFastSpinAxis(s->wheel, 0, 1, 0);
    MdtBodyGetQuaternion(s->wheel, s->wheelQBefore);
}

static void afterFreeBodiesStep(DemoInstance *demo, MeReal h)
{
    FreeBodies *s = demo->data;
    MeVector3 p, v, L;
    (void)h;

    /* projectile: apex, and where it comes back down through y = 0 */
    MdtBodyGetPosition(s->projectile, p);
    MdtBodyGetLinearVelocity(s->projectile, v);
    if (p[1] > s->apex)
        s->apex = p[1];
    if (!s->landed && p[1] < 0 && v[1] < 0) {
        MeReal previousY = p[1] - h * v[1], previousX = p[0] - h * v[0];
        MeReal t = previousY / (previousY - p[1]);
        s->landingX = previousX + t * (p[0] - previousX);
        s->landed = METRUE;
    }

    /* tumbler: flips and the drift of its invariants */
    int sign = intermediateSign(s);
    if (sign != s->lastSign)
        s->flips++;
    s->lastSign = sign;
    DemoBodyAngularMomentum(s->tumbler, L);
    MeReal e = MeFabs(rotationalEnergy(s->tumbler) / s->energy0 - 1);
    MeReal m = MeFabs(magnitude(L) / s->momentum0 - 1);
    if (e > s->energyDrift)
        s->energyDrift = e;
    if (m > s->momentumDrift)
        s->momentumDrift = m;

    /* wheel: the angle of this step's rotation, from q_after · conj(q_before) */
    MeVector4 q;
    MdtBodyGetQuaternion(s->wheel, q);
    const MeReal *a = q, *b = s->wheelQBefore;
    MeReal w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    MeVector3 rel = {-a[0] * b[1] + a[1] * b[0] - a[2] * b[3] + a[3] * b[2],
                       -a[0] * b[2] + a[2] * b[0] - a[3] * b[1] + a[1] * b[3],
                       -a[0] * b[3] + a[3] * b[0] - a[1] * b[2] + a[2] * b[1]};
    s->wheelStepAngle = 2 * MeAtan2(magnitude(rel), MeFabs(w));
}

static void reportFreeBodies(const DemoInstance *demo, FILE *out)
{
    const FreeBodies *s = demo->data;
    MeReal h = demo->steps ? demo->time / (MeReal)demo->steps : 0;
    MeVector3 v, w;

    fprintf(out, "    projectile: apex %.3f m (continuous answer v²/2g = %.3f m)", (double)s->apex,
            (double)(PROJECTILE_SPEED * PROJECTILE_SPEED / (2 * GRAVITY)));
    if (s->landed)
        fprintf(out, ", back at launch height after %.3f m (2·vx·vy/g = %.3f m)\n", (double)s->landingX,
                (double)(2 * PROJECTILE_SPEED * PROJECTILE_SPEED / GRAVITY));
    else
        fprintf(out, ", not yet back at launch height\n");

    fprintf(out, "    tumbler: %d flips of the intermediate axis; largest relative drift of rotational energy %.2g, "
            "of |L| %.2g\n", s->flips, (double)s->energyDrift, (double)s->momentumDrift);

    MdtBodyGetAngularVelocity(s->wheel, w);
    fprintf(out, "    wheel: spins at %.3f rad/s, turned %.4f rad in the last step (ω·h = %.4f; without the "
            "fast-spin axis 2·atan(ω·h/2) = %.4f)\n", (double)magnitude(w), (double)s->wheelStepAngle,
            (double)(WHEEL_SPIN * h), (double)(2 * MeAtan2(WHEEL_SPIN * h / 2, 1)));

    MdtBodyGetLinearVelocity(s->damped, v);
    MdtBodyGetAngularVelocity(s->damped, w);
    fprintf(out, "    damped: falls at %.3f m/s (terminal m·g/c = %.3f m/s, continuous answer at t = %.2f s: %.3f "
            "m/s), spin %.4f rad/s (continuous: %.4f)\n", (double)-v[1],
            (double)(DAMPED_MASS * GRAVITY / DAMPED_LINEAR_DRAG), (double)demo->time,
            (double)(DAMPED_MASS * GRAVITY / DAMPED_LINEAR_DRAG) *
                (1 - expOf(-DAMPED_LINEAR_DRAG * demo->time / DAMPED_MASS)),
            (double)w[2], 5.0 * expOf(-DAMPED_ANGULAR_DRAG * demo->time / ME_R(0.2)));
}

const DemoScene DemoSceneFreeBodies = {
    .name = "freebodies",
    .description = "free flight under gravity: a projectile, a tumbling asymmetric box (full inertia, "
                   "gyroscopic term), a fast-spinning wheel and a damped body",
    .defaultSteps = 600,
    .defaultStepSize = ME_R(1.0) / 60,
    .create = createFreeBodies,
    .beforeStep = beforeFreeBodiesStep,
    .afterStep = afterFreeBodiesStep,
    .report = reportFreeBodies,
};
