/* runaway.c -- the step's reports of bodies it cannot simulate well, before they reach NaN
 * (docs/step.md, "Runaway reports").
 *
 * Two symptoms, checked after each partition is integrated (reading the state only, so trajectories
 * do not depend on them):
 *  - speed: a body faster than the world's speed limit, or spinning faster than its angular speed
 *    limit, is reported once (ME_ERR_SPEED_LIMIT) and again only after it has been back under both;
 *  - energy: constraints do not create energy. Contacts with restitution ≤ 1 and frictional rows
 *    only remove it; what the solver adds is position correction (bounded for contacts by the
 *    world's maximum correcting speed) and motors, which add it slowly. So when a partition's
 *    kinetic energy after the solve exceeds ENERGY_JUMP_FACTOR times the energy it had with every
 *    applied force, impulse and gravity (the predicted velocities v*, ω*), plus a floor of
 *    ½ M (correcting speed)², the constraints are feeding it: typically joints whose anchors cannot
 *    all meet, each correction overshooting the others'. The partition is reported once
 *    (ME_ERR_ENERGY_JUMP) until a step without a jump.
 * Both are counted in MdtWorldCounters (speedWarnings, energyWarnings). */
#include "../me/check.h"
#include "world.h"

/* A partition's kinetic energy may grow at most this many times in one step from what the applied
 * forces give it (a doubling of every speed is a factor 4). */
#define ENERGY_JUMP_FACTOR ME_R(4.0)

MeReal MdtBodyKineticEnergy(const MdtBodyData *b, const MeVector3 v, const MeVector3 w)
{
    /* With the inertia in use (full or spherical). The world tensor is R^T I R (rows of R: the body's
     * axes), so ω·(R^T I R)ω = (Rω)·I(Rω): rotating ω is cheaper than forming the world tensor. */
    MeReal rotational;
    if (b->nonSpherical) {
        MeVector3 wb, Iwb;
        for (int k = 0; k < 3; k++)
            wb[k] = b->comTM[k][0] * w[0] + b->comTM[k][1] * w[1] + b->comTM[k][2] * w[2];
        for (int k = 0; k < 3; k++)
            Iwb[k] = b->inertia[k][0] * wb[0] + b->inertia[k][1] * wb[1] + b->inertia[k][2] * wb[2];
        rotational = MeVector3Dot(wb, Iwb);
    } else {
        rotational = (b->inertia[0][0] + b->inertia[1][1] + b->inertia[2][2]) / 3 * MeVector3MagnitudeSqr(w);
    }
    return ME_R(0.5) * (b->mass * MeVector3MagnitudeSqr(v) + rotational);
}

MeBool MdtRunawayEnergyBelowFloor(const MdtWorldData *w, int p, const MeReal *deltaVelocities)
{
    const MdtPartitionLists *out = &w->partitions;
    const int start = out->partitionStart[p], end = out->partitionStart[p + 1];
    const MeReal v = w->maxCorrectingVelocity;
    if (!ME_IS_FINITE(v))
        return MEFALSE; /* no floor: the check compares the energies themselves */
    /* m|v|² + λmax|ω|² bounds each body's 2 × energy (inertiaBound ≥ λmax). The margin of
     * ME_SMALL_EPSILON per body (several of MeReal's rounding errors) covers the rounding of these sums
     * and of the check's own: the answer is "below" only when the check would find no jump. An
     * overflow gives infinity or NaN, and the answer "not below". */
    MeReal mass = 0, energy = 0;
    for (int i = start; i < end; i++) {
        const MdtBodyData *b = out->bodies[i];
        MeVector3 vel, velrot;
        if (deltaVelocities) {
            MeVector3Add(vel, b->velStar, deltaVelocities + 6 * (size_t)i);
            MeVector3Add(velrot, b->velrotStar, deltaVelocities + 6 * (size_t)i + 3);
        } else {
            MeVector3Copy(vel, b->velStar);
            MeVector3Copy(velrot, b->velrotStar);
        }
        mass += b->mass;
        energy += b->mass * MeVector3MagnitudeSqr(vel) + b->inertiaBound * MeVector3MagnitudeSqr(velrot);
    }
    const MeReal margin = ME_SMALL_EPSILON * (MeReal)(end - start + 4);
    return energy * (1 + margin) <= mass * v * v * (1 - margin);
}

/* What the judging of a partition leaves for the stepping thread to report (MdtRunawayReportPartition). */
enum { REPORT_SPEED = 1, REPORT_ENERGY = 2 };

static MeBool overSpeedLimit(const MdtWorldData *w, const MdtBodyData *b)
{
    MeReal v2 = MeVector3MagnitudeSqr(b->vel), w2 = MeVector3MagnitudeSqr(b->velrot);
    return v2 > w->speedLimit * w->speedLimit || w2 > w->angularSpeedLimit * w->angularSpeedLimit;
}

int MdtRunawayJudgePartition(MdtWorldData *w, int p, MeReal predicted, MeReal after)
{
    const MdtPartitionLists *out = &w->partitions;
    int start = out->partitionStart[p], end = out->partitionStart[p + 1];
    int reports = 0;
    MeReal mass = 0;
    MeBool warned = MEFALSE;
    for (int i = start; i < end; i++) {
        MdtBodyData *b = out->bodies[i];
        MeBool over = overSpeedLimit(w, b);
        if (over && !b->speedWarned)
            reports |= REPORT_SPEED; /* its flag is set when it is reported */
        else
            b->speedWarned = over;
        mass += b->mass;
        warned |= b->energyWarned;
    }
    MeReal v = w->maxCorrectingVelocity;
    MeReal floor = ME_IS_FINITE(v) ? ME_R(0.5) * mass * v * v : MEINFINITY;
    MeBool jump = after > ENERGY_JUMP_FACTOR * predicted + floor;
    if (jump && !warned)
        reports |= REPORT_ENERGY;
    for (int i = start; i < end; i++)
        out->bodies[i]->energyWarned = jump;
    return reports;
}

void MdtRunawayReportPartition(MdtWorldData *w, int p, int reports, MeReal predicted, MeReal after)
{
    const MdtPartitionLists *out = &w->partitions;
    int start = out->partitionStart[p], end = out->partitionStart[p + 1];
    for (int i = start; (reports & REPORT_SPEED) && i < end; i++) {
        MdtBodyData *b = out->bodies[i];
        if (b->speedWarned || !overSpeedLimit(w, b))
            continue;
        MeReal v2 = MeVector3MagnitudeSqr(b->vel), w2 = MeVector3MagnitudeSqr(b->velrot);
        w->speedWarnings++;
        ME_REPORT_IN("MdtWorldStep", ME_ERR_SPEED_LIMIT,
                     "body %p moves at %g m/s and spins at %g rad/s, over the world's limits (%g m/s, %g rad/s: "
                     "MdtWorldSetSpeedLimit, MdtWorldSetAngularSpeedLimit); it will not be reported again until "
                     "it is back under both",
                     (void *)b->id, (double)MeSqrt(v2), (double)MeSqrt(w2), (double)w->speedLimit,
                     (double)w->angularSpeedLimit);
        b->speedWarned = METRUE;
    }
    if (reports & REPORT_ENERGY) {
        w->energyWarnings++;
        ME_REPORT_IN("MdtWorldStep", ME_ERR_ENERGY_JUMP,
                     "partition %d (%d bodies, first %p): kinetic energy %g J after the constraints, from %g J with "
                     "the applied forces; its constraints are adding energy (joints whose anchors cannot all "
                     "meet?); reported once until it calms",
                     p, end - start, (void *)out->bodies[start]->id, (double)after, (double)predicted);
    }
}
