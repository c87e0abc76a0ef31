/* predict_velocities.c -- velocities of the bodies before constraints act (the first half of the integrator).
 *
 *     v* = (v + h (f/m + g) + j/m) / (1 + h c_lin/m)                          (c: drag coefficient)
 *     ω* = (I_w + h c_ang)⁻¹ I_w (ω_g + I_w⁻¹ (h τ + j_ang))
 *
 * Drag is integrated implicitly, so any damping coefficient is stable and velocity decays as
 * 1/(1 + h c/m) per step (→ exp(−c t/m) as h → 0). ω_g is ω after the gyroscopic term ω × Iω when
 * it is enabled: that term is integrated implicitly in the body frame, and can never add energy
 * (see gyroscopicStep).
 * Constraints are then solved against v*, ω*. */
#include <string.h>

#include "../me/check.h"
#include "predict_velocities.h"

/* Body-frame kinetic energy (times 2) and squared angular momentum of ω under inertia I. */
static void invariants(MeMatrix3 I, MeVector3 w, MeReal *twiceEnergy, MeReal *momentumSqr)
{
    MeVector3 L;
    MeMatrix3MultiplyVector(L, I, w);
    *twiceEnergy = MeVector3Dot(w, L);
    *momentumSqr = MeVector3MagnitudeSqr(L);
}

/* The implicit midpoint rule on Euler's equations in the body frame,
 *     I (ω₂ − ω₁) + h ω_m × I ω_m = 0,   ω_m = (ω₁ + ω₂)/2,
 * by Newton's method from ω₂ = ω₁. It keeps the quadratic invariants of a free body, kinetic energy
 * and |L|, exactly, where explicit Euler gains energy without bound and backward Euler loses it
 * (about 20 % in 10 s for a tumbling box at 60 Hz). Newton converges in two or three iterations
 * while h|ω| is small; returns MEFALSE when it has not converged (fast spin: h|ω| of order one and
 * more), leaving w2 unusable. */
static MeBool midpointStep(MeMatrix3 I, MeReal h, MeVector3 w1, MeVector3 w2)
{
    MeVector3Copy(w2, w1);
    for (int iteration = 0; iteration < 4; iteration++) {
        MeMatrix3 J, S, SI, SIw;
        MeVector3 wm, Iwm, Idw, F, delta, dw;
        for (int k = 0; k < 3; k++) {
            wm[k] = ME_R(0.5) * (w1[k] + w2[k]);
            dw[k] = w2[k] - w1[k];
        }
        MeMatrix3MultiplyVector(Iwm, I, wm);
        MeMatrix3MultiplyVector(Idw, I, dw);
        MeVector3Cross(F, wm, Iwm);
        for (int k = 0; k < 3; k++)
            F[k] = Idw[k] + h * F[k];
        /* dF/dω₂ = I + (h/2)(S(ω_m) I − S(I ω_m)), S(v) u = v × u as column matrices;
         * MeMatrix3MakeCrossProduct stores the transpose of S(v), which is −S(v). */
        MeMatrix3MakeCrossProduct(S, wm);
        MeMatrix3MultiplyMatrix(SI, S, I);
        MeMatrix3MakeCrossProduct(SIw, Iwm);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                J[i][j] = I[i][j] + ME_R(0.5) * h * (SIw[i][j] - SI[i][j]);
        if (!MeMatrix3Invert(J))
            return MEFALSE;
        MeMatrix3TransposeMultiplyVector(delta, J, F);
        MeVector3Subtract(w2, w2, delta);
        if (MeVector3MagnitudeSqr(delta) <= ME_SMALL_EPSILON * ME_SMALL_EPSILON * MeVector3MagnitudeSqr(w2))
            return METRUE;
    }
    return MEFALSE;
}

/* Fast spin: one Newton step of backward Euler, I (ω₂ − ω₁) + h ω₂ × I ω₂ = 0, from ω₁ (the
 * linearisation Catto describes for games, GDC 2015):
 *     ω₂ = ω₁ − (I + h (S(ω₁) I − S(I ω₁)))⁻¹ h ω₁ × I ω₁.
 * Backward Euler damps rather than pumps, but one Newton step is not the exact solution, so the
 * caller still caps the invariants. */
static void linearisedBackwardEulerStep(MeMatrix3 I, MeReal h, MeVector3 w1, MeVector3 w2)
{
    MeMatrix3 J, S, SI, SIw;
    MeVector3 Iw, F, delta;
    MeMatrix3MultiplyVector(Iw, I, w1);
    MeVector3Cross(F, w1, Iw);
    MeVector3Scale(F, h);
    MeMatrix3MakeCrossProduct(S, w1);
    MeMatrix3MultiplyMatrix(SI, S, I);
    MeMatrix3MakeCrossProduct(SIw, Iw);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            J[i][j] = I[i][j] + h * (SIw[i][j] - SI[i][j]);
    MeVector3Copy(w2, w1);
    if (!MeMatrix3Invert(J))
        return; /* cannot happen for a positive definite I and finite ω; the caps below still hold */
    MeMatrix3TransposeMultiplyVector(delta, J, F);
    MeVector3Subtract(w2, w2, delta);
}

/* The gyroscopic term ω × Iω of a torque-free step, in the body frame. It never adds kinetic energy
 * or angular momentum, at any spin: the midpoint rule keeps both (to rounding) when its Newton
 * iteration converges; otherwise the linearised backward Euler step is taken and ω scaled down,
 * if needed, so that neither the energy nor |L| exceeds its value at the start of the step. Scaling
 * ω by s scales the energy by s² and |L| by s, so one factor caps both. */
static void gyroscopicStep(const MdtBodyData *b, MeReal h, MeVector3 w)
{
    MeMatrix3 R, I;
    MeVector3 w1, w2;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            R[i][j] = b->comTM[i][j];
    memcpy(I, b->inertia, sizeof I);
    MeMatrix3TransposeMultiplyVector(w1, R, w); /* world → body */
    MeReal e1, l1, e2, l2;
    invariants(I, w1, &e1, &l1);
    /* Rounding of the invariants themselves: the midpoint rule's result is kept as it is within it. */
    const MeReal tolerance = 4 * ME_SMALL_EPSILON;
    MeBool kept = midpointStep(I, h, w1, w2);
    if (kept) {
        invariants(I, w2, &e2, &l2);
        kept = e2 <= e1 * (1 + tolerance) && l2 <= l1 * (1 + tolerance);
    }
    if (!kept) {
        linearisedBackwardEulerStep(I, h, w1, w2);
        invariants(I, w2, &e2, &l2);
        MeReal s = 1;
        if (!(e2 <= e1))
            s = e2 > 0 ? MeSqrt(e1 / e2) : 0;
        if (!(l2 * s * s <= l1))
            s = l2 > 0 ? MeSqrt(l1 / l2) : 0;
        MeVector3Scale(w2, s);
    }
    MeMatrix3MultiplyVector(w, R, w2); /* body → world */
}

static void predictBody(MdtBodyData *b, const MdtWorldData *w, MeReal h)
{
    MeMatrix3 invI;
    MeVector3 dw, wg;

    MeVector3Set(b->stepStartCom, b->comTM[3][0], b->comTM[3][1], b->comTM[3][2]);
    MeVector4Copy(b->stepStartQ, b->q);

    /* linear */
    for (int k = 0; k < 3; k++)
        b->velStar[k] = b->vel[k] + h * (b->force[k] * b->invMass + w->gravity[k]) + b->impulse[k] * b->invMass;
    if (b->linearDamping > 0)
        MeVector3Scale(b->velStar, 1 / (1 + h * b->linearDamping * b->invMass));

    /* angular */
    MeVector3Copy(wg, b->velrot);
    if (b->coriolis && b->nonSpherical)
        gyroscopicStep(b, h, wg);
    MdtBodyWorldInverseInertia(b, invI);
    for (int k = 0; k < 3; k++)
        dw[k] = h * b->torque[k] + b->angularImpulse[k];
    MeMatrix3MultiplyVector(dw, invI, dw);
    MeVector3Add(b->velrotStar, wg, dw);
    if (b->angularDamping > 0) {
        MeMatrix3 Iw, A;
        MeVector3 L;
        MdtBodyWorldInertia(b, Iw);
        MeMatrix3MultiplyVector(L, Iw, b->velrotStar);
        memcpy(A, Iw, sizeof A);
        for (int k = 0; k < 3; k++)
            A[k][k] += h * b->angularDamping;
        if (MeMatrix3SymmetricInvert(A))
            MeMatrix3MultiplyVector(b->velrotStar, A, L);
    }
}

void MdtPredictVelocitiesOf(MdtWorldData *w, int start, int end)
{
    const MdtPartitionLists *out = &w->partitions;
    for (int i = start; i < end; i++)
        predictBody(out->bodies[i], w, w->stepSize);
}
