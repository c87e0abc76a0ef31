/* speculative.c -- which of a pair's points apart the bridge passes to the solver (decision C23).
 *
 * A point reported apart (positive separation, within the pair's contact tolerance) becomes a row
 * that lets the bodies close the gap in the step and no further (a speculative contact). The row acts
 * only if the point's approach speed at the end of the step reaches gap / h; a point whose gap cannot
 * close even at a conservative bound of that speed would be inactive in the exact solution, and only
 * joins bodies into larger partitions for the solver to factor. Such points are left out; the pair's
 * other points are kept, and a left-out point comes back on the first step its gap can close.
 *
 * The bound on the approach speed at the end of the step, at a point r_k from body k's centre:
 *   max(0, −v_n) + h (MST_SPECULATIVE_GRAVITY |g| + Σ_k (|F_k| / m_k + |ω_k|² |r_k|))
 * with v_n the bodies' present separating speed at the point. Gravity moves both bodies alike, but
 * supports do not: a body held while the other falls approaches at g, and a point of a body turning
 * about a support accelerates faster than g (a plank's free end at 1.5 g), less than 2 g for a point
 * no further from the centre than the support is. F_k is the force applied for the step, and |ω|²|r|
 * the centripetal part of the point's turning. An applied torque leaves the bound unknown: the pair
 * keeps every point. Impulses of the pair's neighbours within the same step are not bounded (a block
 * of boxes at rest in zero gravity, struck: the blow crosses it in one step), so every point within
 * MST_SPECULATIVE_FLOOR of the pair's contact tolerance is kept whatever the bound; continuous
 * collision (C16) puts a fast body within half the tolerance of what it hits, and counts on those
 * points to stop it. */
#include <karma/McdModel.h>
#include <karma/McdModelPair.h>
#include <karma/MdtBody.h>
#include <karma/MdtWorld.h>
#include <karma/MeMath.h>

#include "speculative.h"

/* A body's part of the bound: its velocity, spin and centre, and what an applied force adds. */
typedef struct SpeculativeBody {
    MeVector3 vel, spin, com;
    MeReal forceAccel; /* |F| / m */
    MeReal spin2;      /* |ω|² */
} SpeculativeBody;

/* The body's state for the bound; MEFALSE when an applied torque makes the bound unknown. */
static MeBool bodyBound(MdtBodyID body, SpeculativeBody *s)
{
    MeVector3 force, torque;
    MdtBodyGetTorque(body, torque);
    if (MeVector3MagnitudeSqr(torque) > 0)
        return MEFALSE;
    MdtBodyGetLinearVelocity(body, s->vel);
    MdtBodyGetAngularVelocity(body, s->spin);
    MdtBodyGetCenterOfMassPosition(body, s->com);
    MdtBodyGetForce(body, force);
    s->forceAccel = MeVector3Magnitude(force) / MdtBodyGetMass(body);
    s->spin2 = MeVector3MagnitudeSqr(s->spin);
    return METRUE;
}

/* Body s's velocity at p along n; adds its part of the speed gained in a step of h to *gain. */
static MeReal pointAlong(const SpeculativeBody *s, const MeVector3 p, const MeVector3 n, MeReal h, MeReal *gain)
{
    MeVector3 r, wxr;
    MeVector3Subtract(r, p, s->com);
    MeVector3Cross(wxr, s->spin, r);
    *gain += h * (s->forceAccel + s->spin2 * MeVector3Magnitude(r));
    return MeVector3Dot(n, s->vel) + MeVector3Dot(n, wxr);
}

/* Whether contact c, apart, can close its gap within the step h at the bound (gravity: |g|). */
static MeBool canClose(const McdContact *c, const SpeculativeBody *s1, const SpeculativeBody *s2, MeReal h,
                       MeReal gravity)
{
    MeReal gain = h * MST_SPECULATIVE_GRAVITY * gravity, vn = 0;
    if (s1)
        vn += pointAlong(s1, c->position, c->normal, h, &gain);
    if (s2)
        vn -= pointAlong(s2, c->position, c->normal, h, &gain);
    const MeReal approach = (vn < 0 ? -vn : 0) + gain;
    return c->separation <= approach * h;
}

/* The largest of the points' separations, 0 when none is apart (a NaN is not apart). */
static MeReal largestSeparation(const McdContact *contacts, int n)
{
    MeReal largest = 0;
    for (int i = 0; i < n; i++)
        if (contacts[i].separation > largest)
            largest = contacts[i].separation;
    return largest;
}

int MstSpeculativeKeep(MdtWorldID world, McdModelPairID pair, const McdModelPairModelInfo *models, MeReal h,
                       McdContact *contacts, int n)
{
    const MeReal largest = largestSeparation(contacts, n);
    if (!(h > 0) || !(largest > 0))
        return n;
    MeVector3 g;
    MdtWorldGetGravity(world, g);
    const MeReal gravity = MeVector3Magnitude(g);
    /* Gravity's part of the bound alone closes this much (canClose's least approach · h, rounded the
     * same way): a pair whose points are all nearer keeps them without its bodies being read. */
    if (!(largest > h * MST_SPECULATIVE_GRAVITY * gravity * h))
        return n;
    McdModelID m1, m2;
    McdModelPairGetModels(pair, &m1, &m2);
    const MeReal near = MST_SPECULATIVE_FLOOR * (McdModelGetContactTolerance(m1) + McdModelGetContactTolerance(m2));
    if (!(largest > near))
        return n;
    MdtBodyID body1 = (MdtBodyID)models->bodyData[0], body2 = (MdtBodyID)models->bodyData[1];
    SpeculativeBody s1, s2;
    if ((body1 && !bodyBound(body1, &s1)) || (body2 && !bodyBound(body2, &s2)))
        return n;
    int kept = 0;
    for (int i = 0; i < n; i++) {
        const MeBool apart = contacts[i].separation > near;
        if (apart && !canClose(&contacts[i], body1 ? &s1 : NULL, body2 ? &s2 : NULL, h, gravity))
            continue;
        contacts[kept++] = contacts[i];
    }
    return kept;
}
