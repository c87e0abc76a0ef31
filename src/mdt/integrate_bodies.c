/* integrate_bodies.c -- MdtKeaIntegrate (MdtIntegrateStage): advance the bodies of the step by one
 * time step.
 *
 * Karma's integrator is first order, velocities first and then positions ("symplectic Euler"):
 *
 *     v⁺ = v* + Δv_c          x⁺ = x + h v⁺          q⁺ = q + (h/2) (0, ω⁺) q, renormalised
 *
 * where v* (see predict_velocities.c) already holds the external forces, impulses and damping, and Δv_c is the
 * velocity change from the constraint impulses the solver found. A fast-spin axis (wheels) splits ω
 * into its component along the axis, which is integrated exactly (a rotation by |ω_a| h), and the
 * rest, integrated to first order: a wheel spinning at 100 rad/s then turns at its true rate, which
 * the first-order update alone would not.
 *
 * Partitions are integrated as one task over their indices (MdtTaskSystem.h): each writes only its
 * own bodies and records, and what it must report is reported afterwards on the stepping thread in
 * partition order, so the result is the serial one for any worker count.
 *
 * After integration each partition's state is checked: a NaN or infinity marks the partition failed
 * (MdtSimErrorState). A partition the solver already marked failed is not integrated at all. Failed
 * partitions are then reported (ME_ERR_NONFINITE_STATE), passed to the world's sim-error callback,
 * and their bodies put back to their pose at the start of the step, stopped and disabled, so that
 * the error cannot spread to other partitions (simerror.c). */
#include "../me/check.h"
#include "world.h"

/* Orientation update: first order, with the fast-spin component (if any) integrated exactly. */
static void integrateOrientation(MdtBodyData *b, MeReal h)
{
    MeVector3 w;
    MeVector3Copy(w, b->velrot);
    if (b->useFastSpin) {
        MeVector3 spin;
        MeVector3MultiplyScalar(spin, b->fastSpinAxis, MeVector3Dot(w, b->fastSpinAxis));
        MeVector3Subtract(w, w, spin);
        MeQuaternionFiniteRotation(b->q, spin, h);
    }
    MeVector4 dq;
    MeQuaternionWtoDQ(dq, b->q, w); /* dq = ½ (0, ω) q */
    for (int k = 0; k < 4; k++)
        b->q[k] += h * dq[k];
    MeQuaternionNormalize(b->q);
}

static MeBool stateIsFinite(const MdtBodyData *b)
{
    MeBool ok = METRUE;
    for (int k = 0; k < 3; k++)
        ok &= ME_IS_FINITE(b->comTM[3][k]) && ME_IS_FINITE(b->vel[k]) && ME_IS_FINITE(b->velrot[k]);
    for (int k = 0; k < 4; k++)
        ok &= ME_IS_FINITE(b->q[k]);
    return ok;
}

/* restBlockSteps is 0 when auto-disable is off: no rest window is kept then. */
static void integrateBody(MdtBodyData *b, const MeReal *dv, const MeReal *dw, MeReal h, int restBlockSteps)
{
    MeVector3 oldVel, oldVelrot, com;
    MeVector3Copy(oldVel, b->vel);
    MeVector3Copy(oldVelrot, b->velrot);
    MeVector3Add(b->vel, b->velStar, dv);
    MeVector3Add(b->velrot, b->velrotStar, dw);
    for (int k = 0; k < 3; k++) {
        b->accel[k] = (b->vel[k] - oldVel[k]) / h;
        b->accelrot[k] = (b->velrot[k] - oldVelrot[k]) / h;
        com[k] = b->comTM[3][k] + h * b->vel[k];
    }
    integrateOrientation(b, h);
    MdtBodyUpdateTransforms(b, com);
    b->enabledTime += h;
    if (restBlockSteps > 0)
        MdtBodyRestWindowRecord(b, restBlockSteps);
}

/* What the integration task shares: read-only but for each partition's own bodies and records. */
typedef struct IntegrateTask {
    MdtWorldData *w;
    const MeReal *deltaVelocities; /* 6 per step body, or NULL when no rows were packed */
    int restBlockSteps;
} IntegrateTask;

/* Integrate partition p's bodies and judge them (state check, runaway check). Writes only its bodies
 * and its own entries of the partition records, so partitions may run on any worker in any order. */
static void integratePartition(const IntegrateTask *t, int p)
{
    MdtWorldData *w = t->w;
    MdtPartitionLists *out = &w->partitions;
    static const MeReal zero[3] = {0, 0, 0};
    out->runawayReports[p] = 0;
    if (out->simError[p])
        return; /* the solver failed it: restored by the stepping thread, never integrated */
    int start = out->partitionStart[p], end = out->partitionStart[p + 1];
    MeBool finite = METRUE;
    /* Kinetic energies for the runaway check, summed only when a cheap bound cannot rule a jump
     * out (a partition moving slower than the world's maximum correcting speed cannot jump). */
    const MeBool sumEnergies = !MdtRunawayEnergyBelowFloor(w, p, t->deltaVelocities);
    MeReal predicted = 0, after = 0;
    for (int i = start; i < end; i++) {
        MdtBodyData *b = out->bodies[i];
        const MeReal *dv = t->deltaVelocities ? t->deltaVelocities + 6 * (size_t)i : zero;
        const MeReal *dw = t->deltaVelocities ? t->deltaVelocities + 6 * (size_t)i + 3 : zero;
        if (sumEnergies)
            predicted += MdtBodyKineticEnergy(b, b->velStar, b->velrotStar);
        integrateBody(b, dv, dw, w->stepSize, t->restBlockSteps);
        if (sumEnergies)
            after += MdtBodyKineticEnergy(b, b->vel, b->velrot);
        finite &= stateIsFinite(b);
    }
    if (!finite) {
        out->simError[p] = MdtSimErrorState;
        return;
    }
    out->runawayReports[p] = MdtRunawayJudgePartition(w, p, predicted, after);
    out->energies[2 * p] = predicted;
    out->energies[2 * p + 1] = after;
}

static void integrateTask(int start, int end, int worker, void *data)
{
    (void)worker;
    for (int p = start; p < end; p++)
        integratePartition(data, p);
}

/* Partitions per range of the integration task: a few bodies' work is less than a hand-out. */
#define INTEGRATE_MIN_RANGE 4

void MdtIntegrateStage(MdtWorldData *w)
{
    MdtPartitionLists *out = &w->partitions;
    IntegrateTask task;
    task.w = w;
    task.deltaVelocities = w->rowsPacked ? (const MeReal *)w->rows.dv : NULL;
    task.restBlockSteps =
        w->autoDisable.enabled ? MdtRestWindowBlockSteps(w->autoDisable.averagingTime, w->stepSize) : 0;
    MdtRunStepTask(w, integrateTask, out->partitionCount, INTEGRATE_MIN_RANGE, &task);
    /* Messages and counters on the stepping thread, in partition order (as a serial step gives them). */
    for (int p = 0; p < out->partitionCount; p++)
        if (out->runawayReports[p])
            MdtRunawayReportPartition(w, p, out->runawayReports[p], out->energies[2 * p], out->energies[2 * p + 1]);
    MdtSimErrorHandlePartitions(w);
}
