/* constraint.h -- the constraint record, the per-type class table and the row writer (internal).
 *
 * Every constraint (joint, contact, contact group) lives in a slot of the world's constraint pool:
 * a common header (bodies, frames, flags, outputs, links into the bodies' constraint lists) followed
 * by MDT_CONSTRAINT_DATA_BYTES of type-specific data that only the type's own file interprets. Each
 * type registers an MdtConstraintClass: its name, its maximum row count, how to reset its data, and
 * its row writer, which the packer (BCL) calls once per step for each enabled constraint of a
 * partition.
 *
 * Rows. A row i constrains the relative velocity J_i·v of the two bodies. The writer is given, per
 * row, the Jacobian halves, a desired constraint velocity c, a position error φ (the constraint
 * function's value, in the row's units), a relaxation γ (share of φ removed per step), an extra
 * softness ε and force bounds. It computes the solver's right-hand side
 *
 *     r = c − γ φ / h − J v*       (v*: velocities after external forces; see predict_velocities.c)
 *
 * and Kea finds impulses x with  J v⁺ + ε x = c − γ φ / h  inside the bounds (bounds are given as
 * forces and become impulses f·h). See docs/step.md for the derivation and the meaning of ε and γ. */
#ifndef MDT_CONSTRAINT_INTERNAL_H
#define MDT_CONSTRAINT_INTERNAL_H

#include <karma/MdtConstraint.h>

#include "body.h"
#include "kea/kea.h"

struct MdtWorldData;
struct MdtConstraintData;
struct MdtRowWriter;

/** Largest number of rows any joint writes (contact groups write 3 per contact). */
#define MDT_MAX_JOINT_ROWS 6
/** Bytes of type-specific data in a constraint slot. */
#define MDT_CONSTRAINT_DATA_BYTES 320

/** One type of constraint. */
typedef struct MdtConstraintClass {
    const char *name;
    int maxRows; /* rows written at most (contact groups: per contact) */
    /* Restore the type's defaults in c->data (and frames if the type has its own defaults). */
    void (*reset)(struct MdtConstraintData *c);
    /* Rows this step (an upper bound is fine); NULL means maxRows. */
    int (*rowCount)(const struct MdtConstraintData *c);
    /* Write this step's rows. */
    void (*addRows)(struct MdtConstraintData *c, struct MdtRowWriter *w);
    /* After the solve: per-type outputs from the row impulses (optional). */
    void (*unpack)(struct MdtConstraintData *c, const MeReal *impulses, int rows, MeReal h);
    /* Before the slot is released (optional; contact groups free their contacts). */
    void (*destroy)(struct MdtConstraintData *c);
} MdtConstraintClass;

/** The common header and the type data of a constraint. */
typedef struct MdtConstraintData {
    uintptr_t id;
    struct MdtWorldData *world;
    int slot;
    MdtBclJointType type;
    const MdtConstraintClass *cls;
    MdtBodyData *body[2];             /* body[1] NULL = the world */
    MeBool enabled;
    MeBool inGroup;               /* a contact owned by a contact group (not partitioned itself) */
    void *userData;
    MeI32 sortKey;

    /* Constraint frame per body, in that body's frame (world frame when the body is NULL). */
    MeVector3 position[2];
    MeVector3 primary[2];
    MeVector3 orthogonal[2];
    MeVector3 worldLinearVelocity, worldAngularVelocity;

    /* Outputs of the last step. */
    MeVector3 force[2], torque[2];
    int rowCount;
    MeReal impulse[MDT_MAX_JOINT_ROWS]; /* last step's row impulses: the next step's warm start */

    /* Links: the constraint lists of body 0 and body 1. */
    struct MdtConstraintData *nextForBody[2];
    /* Step bookkeeping. */
    unsigned long visitStamp;     /* partitioner: step in which it was last placed */
    int rowStart;                 /* first row in the step's row arrays, or -1 */
    int rowBound;                 /* this step's MdtConstraintRowBound, kept by MdtPackStage for its pieces */
    int partition;

    /* Type-specific data, interpreted by the type's file only. */
    union {
        MeReal reals[MDT_CONSTRAINT_DATA_BYTES / sizeof(MeReal)];
        void *pointer;
        double alignment;
    } data;
} MdtConstraintData;

/** Type data of a constraint, as the type's own struct. */
#define MDT_CONSTRAINT_DATA(c, Type) ((Type *)(void *)(c)->data.reals)
/** Compile-time check that a type's data fits in the slot. */
#define MDT_CONSTRAINT_DATA_FITS(Type)                                                               \
    _Static_assert(sizeof(Type) <= MDT_CONSTRAINT_DATA_BYTES, #Type " does not fit a constraint slot")

/* ---- creation and lookup ------------------------------------------------------------------ */
/** A new disabled constraint of `type` (behaviour in `cls`) in world `wid`, reset to its defaults;
 *  NULL (reported in `function`'s name) when the ID is bad or the pool is full. */
MdtConstraintData *MdtConstraintCreateInternal(MdtWorldID wid, MdtBclJointType type, const MdtConstraintClass *cls,
                                           const char *function);
/** The same for contacts and contact groups: while the world has a caller name (MdtWorldSetCallerName:
 *  a bridge making contacts every step), a full pool is reported once per world in that name and
 *  counted after; otherwise in `function`'s name, every time. */
MdtConstraintData *MdtConstraintCreateForContacts(MdtWorldID wid, MdtBclJointType type, const MdtConstraintClass *cls,
                                              const char *function);
/** Resolve an ID of any constraint type; NULL (reported) if invalid. */
MdtConstraintData *MdtConstraintFromID(MdtConstraintID id, const char *function);
/** Resolve an ID that must be of `type`; NULL (reported) if invalid or of another type. */
MdtConstraintData *MdtConstraintFromIDOfType(const void *id, MdtBclJointType type, const char *function);
/** Rows the constraint may write this step: its class's count (a group's sum) or its maximum. */
int MdtConstraintRowBound(const MdtConstraintData *c);
/** Release the slot (after the class's destroy hook), unlinking from the bodies. */
void MdtConstraintRelease(MdtConstraintData *c);
/** Attach to bodies (NULL body1 = world); relinks the bodies' constraint lists. */
void MdtConstraintAttach(MdtConstraintData *c, MdtBodyData *b0, MdtBodyData *b1);
/** Reset the common frames: positions 0, primary (1,0,0), orthogonal (0,1,0) in each body's frame. */
void MdtConstraintResetFrames(MdtConstraintData *c);

/* ---- frames in world coordinates ----------------------------------------------------------- */
void MdtConstraintWorldPosition(const MdtConstraintData *c, int body, MeVector3 out);
void MdtConstraintWorldPrimary(const MdtConstraintData *c, int body, MeVector3 out);
void MdtConstraintWorldOrthogonal(const MdtConstraintData *c, int body, MeVector3 out);
/** A world point / direction expressed in body `index`'s frame (identity for the world). */
void MdtConstraintToBodyPoint(const MdtConstraintData *c, int index, const MeVector3 world, MeVector3 out);
void MdtConstraintToBodyVector(const MdtConstraintData *c, int index, const MeVector3 world, MeVector3 out);

/* ---- the row writer (BCL) ------------------------------------------------------------------ */
/** One row as a constraint describes it. Zero-initialise, then fill what applies. */
typedef struct MdtRow {
    MeVector3 lin0, ang0;  /* Jacobian on body 0: constraint velocity += lin0·v0 + ang0·ω0 */
    MeVector3 lin1, ang1;  /* on body 1 (ignored when body 1 is the world, except for its velocity) */
    MeReal velocity;       /* desired constraint velocity c */
    MeReal error;          /* position error φ (constraint units); corrected at rate γ/h */
    MeReal gamma;          /* relaxation for this row; < 0 means the world's γ */
    MeReal epsilon;        /* softness added to the world's ε */
    MeBool noWorldEpsilon; /* do not add the world's ε (rows with their own compliance) */
    MeReal lo, hi;         /* force bounds, N (or N·m); ±MEINFINITY for none */
    int link;              /* friction: row index (relative to the constraint's first row) of the
                              normal row whose impulse bounds this one, or -1 */
    MeReal mu;             /* friction coefficient with `link` */
} MdtRow;

typedef struct MdtRowWriter {
    /* Output arrays for the whole step (indexed by global row). */
    KeaJacobianRow *J;
    int (*rowBodies)[2];
    MeReal *epsilon, *rhs, *lo, *hi, *mu, *x0;
    int *link;
    int count;    /* rows written so far */
    int capacity;
    /* The constraint being written. */
    MdtConstraintData *constraint;
    int first;    /* its first row */
    int localBody[2]; /* partition-local indices of its bodies, or KEA_WORLD */
    MeReal h, gamma, epsilon0;
    MeReal maxCorrection; /* bound on a contact's penetration correction speed, m/s (may be MEINFINITY) */
    MdtRow *captured; /* when not NULL, rows are copied here instead (MdtConstraintCaptureRows) */
    KeaContact *contacts; /* the step's declared contacts (global rows), contactCount so far */
    int contactCount;
    int unproven; /* some row written could not be proved valid here (Kea then checks the rows itself) */
} MdtRowWriter;

/** Append a row for the current constraint; returns its index relative to the constraint's first
 *  row, or -1 when the capacity (the class's row count) is exhausted. */
int MdtRowWriterAdd(MdtRowWriter *w, const MdtRow *row);
/** Add a contact's three rows at once: row k's Jacobian is that of direction dir[k] at lever arms r0
 *  and r1 (J v = dir·(v0 + ω0 × r0 − v1 − ω1 × r1), as the contact's rows are written), the rest of
 *  the row from params[k] (whose lin/ang are not read), its warm start x0[k]. The arrays get the bits
 *  three MdtRowWriterAdd calls would give them. Returns the first row's index relative to the
 *  constraint's first row; -1 (an internal error) without room. Not for captured rows. */
int MdtRowWriterAddDirections(MdtRowWriter *w, MeVector3 dir[3], const MeVector3 r0, const MeVector3 r1,
                              const MdtRow params[3], const MeReal x0[3]);
/** Declare the current constraint's three rows from `normalRow` (relative to its first row, as
 *  MdtRowWriterAdd returned it) a contact for Kea (KeaContact: the normal row [0, inf), then two
 *  friction rows linked to it without bounds of their own, on the same bodies, the first a body).
 *  The caller promises that shape; a contact with other options writes generic rows only. Nothing
 *  happens when rows are captured. */
void MdtRowWriterDeclareContact(MdtRowWriter *w, int normalRow);
/** An empty row with the defaults (gamma −1: the world's, link −1, unbounded). Inline: every row of
 *  every step starts here. */
static inline void MdtRowInit(MdtRow *row)
{
    *row = (MdtRow){.gamma = -1, .lo = -MEINFINITY, .hi = MEINFINITY, .link = -1};
}
/** The rows constraint `c` would write now, as MdtRows (at most `max`); for tests and tools (e.g.
 *  Jacobians against finite differences of the errors). `h` is the step the rows are written for. */
int MdtConstraintCaptureRows(MdtConstraintData *c, MdtRow *rows, int max, MeReal h);

/* ---- shared row pieces (bcl/parts.c) -------------------------------------------------------- */
/** Three rows holding a point of body 0 on a point of body 1 (ball and socket). */
void MdtBclAddPointRows(MdtRowWriter *w, const MdtConstraintData *c);
/** Rows keeping the world direction `d1` of body 0 perpendicular to body 1's direction `d2`:
 *  one row, error d1·d2. */
void MdtBclAddPerpendicularRow(MdtRowWriter *w, const MdtConstraintData *c, const MeVector3 d1, const MeVector3 d2);
/** Two rows keeping body 0's primary axis parallel to body 1's (hinge). */
void MdtBclAddParallelAxisRows(MdtRowWriter *w, const MdtConstraintData *c);
/** Lever arm of the attachment point from body `index`'s COM, world frame (zero for the world). */
void MdtBclLeverArm(const MdtConstraintData *c, int index, MeVector3 r);
/** Angular Jacobian of θ = atan2(d·v, d·u), with d fixed in body `dBody` and u, v in the other
 *  (exact at any pose); fills ang0/ang1 of `row` and returns θ in (−π, π]. */
MeReal MdtBclAngleRow(MdtRow *row, const MeVector3 u, const MeVector3 v, const MeVector3 d, int dBody);
/** Jacobian of φ = (p0 − p1)·d (attachment points; d fixed in body `dBody`, world frame now); fills
 *  lin/ang of `row` and returns φ. */
MeReal MdtBclSlideRow(MdtRow *row, const MdtConstraintData *c, const MeVector3 d, int dBody);

#endif /* MDT_CONSTRAINT_INTERNAL_H */
