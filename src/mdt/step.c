/* step.c -- MdtWorldStep: one time step of the dynamics pipeline (docs/step.md).
 *
 *   MdtUpdatePartitions   islands of enabled bodies joined by constraints
 *   MdtAutoDisable        islands at rest go to sleep
 *   MdtPack               external forces → predicted velocities; constraints → solver rows
 *   MdtKeaSolve           the LCP for the constraint impulses, per island
 *   MdtKeaIntegrate       velocities, then positions and orientations; state check
 *   MdtUnpackForces       constraint forces back into the constraints for the application
 *
 * Each stage is a section of the world's profile. The world is locked while it steps: creating or
 * destroying bodies from a callback is refused (ME_ERR_WORLD_LOCKED). */
#include "../me/check.h"
#include "kea/kea_integrate.h"
#include "world.h"

void MdtPack(MdtWorld *w)
{
    MdtKeaPredictVelocities(w);
    /* Constraint rows are written here by the constraint library (BCL) once it exists. */
    w->lastRowCount = 0;
}

/* Clears the accumulators of the bodies that were simulated; disabled bodies keep theirs. */
static void clearAccumulators(MdtWorld *w)
{
    for (int i = 0; i < w->bodyPool.capacity; i++) {
        if (!MePoolSlotIsLive(&w->bodyPool, i))
            continue;
        MdtBody *b = MePoolSlot(&w->bodyPool, i);
        if (b->stepIndex < 0)
            continue;
        MeVector3Set(b->force, 0, 0, 0);
        MeVector3Set(b->torque, 0, 0, 0);
        MeVector3Set(b->impulse, 0, 0, 0);
        MeVector3Set(b->angularImpulse, 0, 0, 0);
        b->enabledByPartitioner = MEFALSE;
    }
}

void MdtWorldStep(MdtWorldID id, MeReal stepSize)
{
    MdtWorld *w = MdtWorldFromID(id, __func__);
    if (!w)
        return;
    if (!(ME_IS_FINITE(stepSize) && stepSize > 0)) {
        ME_REPORT(ME_ERR_STEP_SIZE, "argument 'stepSize' (%g) must be positive and finite; step skipped",
                  (double)stepSize);
        return;
    }
    if (w->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "MdtWorldStep was called from inside the same world's step");
        return;
    }
    w->locked = METRUE;
    w->stepSize = stepSize;
    MeProfile *prof = &w->profile;
    MeProfileFrameStart(prof);
    MeProfileStartSection(prof, MDT_SECTION_STEP);

    MeProfileStartSection(prof, MDT_SECTION_PARTITION);
    MdtUpdatePartitions(w);
    MeProfileEndSection(prof, MDT_SECTION_PARTITION);

    MeProfileStartSection(prof, MDT_SECTION_AUTODISABLE);
    MdtAutoDisable(w);
    MeProfileEndSection(prof, MDT_SECTION_AUTODISABLE);

    MeProfileStartSection(prof, MDT_SECTION_PACK);
    MdtPack(w);
    MeProfileEndSection(prof, MDT_SECTION_PACK);

    /* The solver runs on the packed rows; without constraints there is nothing to solve and the
     * constraint velocity changes are zero. */
    MeProfileStartSection(prof, MDT_SECTION_SOLVE);
    MeProfileEndSection(prof, MDT_SECTION_SOLVE);

    MeProfileStartSection(prof, MDT_SECTION_INTEGRATE);
    MdtKeaIntegratePartitions(w, NULL);
    MeProfileEndSection(prof, MDT_SECTION_INTEGRATE);

    MeProfileStartSection(prof, MDT_SECTION_UNPACK);
    clearAccumulators(w);
    MeProfileEndSection(prof, MDT_SECTION_UNPACK);

    MeProfileEndSection(prof, MDT_SECTION_STEP);
    MeProfileFrameEnd(prof);
    w->steps++;
    w->time += stepSize;
    w->locked = MEFALSE;
}
