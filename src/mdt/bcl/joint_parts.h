/* joint_parts.h -- row pieces for joints with frames, springs and limits (internal; defined at the
 * end of parts.c). Unlike the pieces of constraint.h these fill an MdtRow without adding it, so a
 * joint can soften it (MdtBclRowSpring), bound it or make it a limit before MdtRowWriterAdd.
 *
 * Every piece states its constraint function φ (the row's error) and gives the exact Jacobian
 * J = ∂φ/∂(v0, ω0, v1, ω1), so that J·v = dφ/dt at any pose (tests/bcl checks this by finite
 * differences). */
#ifndef MDT_BCL_JOINT_PARTS_H
#define MDT_BCL_JOINT_PARTS_H

#include "../../me/check.h"
#include "../constraint.h"

/** The axes of body `index`'s constraint frame in the world: primary, orthogonal, primary × orthogonal. */
void MdtBclWorldFrame(const MdtConstraintData *c, int index, MeVector3 f[3]);

/** J·v of a row at the bodies' velocities at the start of the step (for the world as body 1: the
 *  constraint's world velocities). */
MeReal MdtBclRowVelocityNow(const MdtRow *row, const MdtConstraintData *c);

/** Turn a row into a spring of stiffness k and damper d (units of the row: N/m and N·s/m, or N·m/rad
 *  and N·m·s/rad) acting on its error, with the SPOOK discretisation (docs/step.md, "Springs"). A row
 *  with k or d = MEINFINITY stays rigid (world ε and γ). Returns MEFALSE when k = d = 0: the row is
 *  free and must not be added. The damper acts on J·v − (the row's target velocity). */
MeBool MdtBclRowSpring(MdtRow *row, const MdtConstraintData *c, MeReal k, MeReal d, MeReal h);

/** Make `row` (error g, Jacobian dg/dt) a one-sided limit g ≤ 0: impulses only reduce g. Rigid (k or d
 *  infinite): added when at or past the limit, or about to reach it within the step (then with γ = 1,
 *  so it closes the gap exactly, like a speculative contact). Soft: a spring-damper past the limit
 *  only. Returns whether the row should be added. */
MeBool MdtBclLimitRow(MdtRow *row, const MdtConstraintData *c, MeReal g, MeReal k, MeReal d, MeReal h);

/** φ = (p0 − p1)·n for unit n: the attachment points' separation along n. `turnsWithBody1`: n is fixed
 *  in body 1 (a plane or line of body 1), else fixed in the world (as the ball-and-socket rows). */
void MdtBclPointAlongRow(MdtRow *row, const MdtConstraintData *c, const MeVector3 n, MeBool turnsWithBody1);

/** φ = d0·d1 for unit directions d0 fixed in body 0 and d1 fixed in body 1 (0 when perpendicular). */
void MdtBclPerpendicularRowFill(MdtRow *row, const MeVector3 d0, const MeVector3 d1);

/** The relative rotation of frame 0 to the target frame T = F1 ⊗ target (target NULL = identity):
 *  q = conj(T) ⊗ F0 with q_w ≥ 0, and T's axes in the world. */
typedef struct MdtBclRotation {
    MeVector4 q;
    MeVector3 t[3];
} MdtBclRotation;
void MdtBclRelativeRotation(const MdtConstraintData *c, const MeVector4 target, MdtBclRotation *r);

/** Row k of φ = 2·vec(q): for small angles the rotation of frame 0 about T's axis k, in radians
 *  (exactly 2 sin(θ/2) times the axis component). */
void MdtBclRotationRow(MdtRow *row, const MdtBclRotation *r, int k);

/** The twist ψ = 2 atan2(q_x, q_w) ∈ (−π, π] of frame 0 about its primary axis relative to frame 1
 *  (swing-twist decomposition); fills the row with φ = ψ. */
MeReal MdtBclTwistRow(MdtRow *row, const MdtBclRotation *r);

/** Row from a gradient: φ = g(u), u = frame-1 coordinates of body 0's primary axis a0, `gradient` =
 *  ∂g/∂u (frame-1 coordinates), f1 = frame 1's three world axes one after the other: dφ/dt = (ω0 − ω1)·(a0 × G), G the gradient in the world. */
void MdtBclAxisFunctionRow(MdtRow *row, const MeVector3 a0, const MeReal *f1, const MeVector3 gradient, MeReal g);

/** Set body `index`'s primary axis (world direction), keeping its orthogonal axis perpendicular;
 *  reports ME_ERR_ZERO_AXIS / ME_ERR_NONFINITE_ARGUMENT in `function`'s name. */
MeBool MdtBclSetBodyAxis(MdtConstraintData *c, int index, MeReal x, MeReal y, MeReal z, const char *function);

/** Argument checks shared by the joints' setters, reported in `function`'s name. */
/** *v ≥ 0 and not NaN (+∞ is stored as MEINFINITY). */
MeBool MdtBclCheckNonNegative(MeReal *v, const char *name, const char *function);
MeBool MdtBclCheckAngle(MeReal v, MeReal lo, MeReal hi, const char *name, const char *function);
MeBool MdtBclCheckBodyIndex(unsigned int bodyindex, const char *function);

/** Defines Mdt<T>Create, Reset, QuaConstraint and MdtConstraintDCast<T> for a type with class `cls`
 *  and a static `reset(MdtConstraintData *)`. */
#define MDT_BCL_TYPE_FUNCTIONS(T, kind, cls)                                                         \
    Mdt##T##ID Mdt##T##Create(MdtWorldID w)                                                          \
    {                                                                                                \
        MdtConstraintData *c = MdtConstraintCreateInternal(w, kind, &cls, __func__);                    \
        return c ? (Mdt##T##ID)c->id : NULL;                                                         \
    }                                                                                                \
    void Mdt##T##Reset(Mdt##T##ID j)                                                                 \
    {                                                                                                \
        MdtConstraintData *c = MdtConstraintFromIDOfType(j, kind, __func__);                            \
        if (c)                                                                                       \
            reset(c);                                                                                \
    }                                                                                                \
    MdtConstraintID Mdt##T##QuaConstraint(Mdt##T##ID j) { return (MdtConstraintID)j; }               \
    Mdt##T##ID MdtConstraintDCast##T(MdtConstraintID c)                                              \
    {                                                                                                \
        return MdtConstraintGetType(c) == (int)kind ? (Mdt##T##ID)c : NULL;                          \
    }

/** In a function taking `j`: resolve it as a `kind` constraint into `c`, or return `ret`. */
#define MDT_BCL_JOINT_OR_RETURN(c, j, kind, ret)                                                     \
    MdtConstraintData *c = MdtConstraintFromIDOfType((j), (kind), __func__);                            \
    if (!c)                                                                                          \
    return ret

/** Defines Mdt<T>Set<Name>(j, arg) and Mdt<T>Get<Name>(j) for the MeReal `field` of the type's data
 *  struct `Data`; the setter stores `arg` only when `valid` (an expression of `arg`) holds. */
#define MDT_BCL_CHECKED_PROPERTY(T, kind, Data, Name, field, arg, valid)                             \
    void Mdt##T##Set##Name(Mdt##T##ID j, MeReal arg)                                                 \
    {                                                                                                \
        MDT_BCL_JOINT_OR_RETURN(c, j, kind, ME_NOTHING);                                             \
        if (valid)                                                                                   \
            MDT_CONSTRAINT_DATA(c, Data)->field = arg;                                               \
    }                                                                                                \
    MeReal Mdt##T##Get##Name(Mdt##T##ID j)                                                           \
    {                                                                                                \
        MDT_BCL_JOINT_OR_RETURN(c, j, kind, 0);                                                      \
        return MDT_CONSTRAINT_DATA(c, Data)->field;                                                  \
    }
/** A stiffness or damping property (≥ 0, +∞ stored as MEINFINITY). */
#define MDT_BCL_GAIN_PROPERTY(T, kind, Data, Name, field, arg)                                       \
    MDT_BCL_CHECKED_PROPERTY(T, kind, Data, Name, field, arg, MdtBclCheckNonNegative(&arg, #arg, __func__))
/** An angle property in [0, π]. */
#define MDT_BCL_ANGLE_PROPERTY(T, kind, Data, Name, field, arg)                                      \
    MDT_BCL_CHECKED_PROPERTY(T, kind, Data, Name, field, arg, MdtBclCheckAngle(arg, 0, ME_PI, #arg, __func__))

#endif /* MDT_BCL_JOINT_PARTS_H */
