/* contact.c -- MdtContact: its API and the rows of one contact (used alone and by contact groups).
 *
 * Rows of a contact at point p with unit normal n (from body 1 towards body 0: the direction in
 * which body 0 is pushed, as Karma), lever arms r0 = p − com0 and r1 = p − com1. The constraint
 * velocity of a direction d is the velocity of body 0's material point relative to body 1's along d
 * (Karma's sense):  J v = d·(v0 + ω0 × r0 − v1 − ω1 × r1).
 *   normal:   φ = −penetration (separation), impulse ≥ 0 (≥ −max adhesive force·h when adhesive);
 *             a separated contact (penetration < 0) may close its gap exactly (γ = 1: speculative);
 *             when approaching faster than the restitution threshold and touching within the step,
 *             the target separating speed is restitution × approach speed (no position correction
 *             on top); softness adds to the row's ε.
 *   friction: t1 = the primary direction (given, or chosen perpendicular to n), t2 = t1 × n; target
 *             velocity = slide (body 0 relative to body 1); ε = slip / h instead of the world's ε
 *             (slip is a compliance: sliding speed = slip × friction force, whatever the step, see
 *             decision K28 in docs/decisions.md); bounds ±friction (Box) or
 *             |x| ≤ μ x_normal (NormalForce, a friction link the solver applies with the current
 *             normal impulse).
 * A world that moves under the contact (UseWorldVelocity, body 1 NULL) is body 1 moving at
 * v_world: each row's target shifts by +d·v_world. */
#include <string.h>

#include <karma/MdtContact.h>
#include <karma/MdtContactGroup.h>

#include "../../me/check.h"
#include "../world.h"
#include "contact_internal.h"

/* The friction axis the contact chooses itself follows its normal: last step's axis made normal to
 * the new normal, so that the friction impulses it keeps for the warm start act along the same
 * directions next step. MeVector3PlaneSpace alone would turn the axis by 90 degrees whenever the
 * normal's two smallest components swap sizes, as they do for a nearly vertical normal tilting by a
 * trace: the warm start then pushes sideways with last step's friction. A fresh contact, or one whose
 * normal turned more than 60 degrees towards the old axis, takes the plane's own axis. */
static void followNormal(ContactData *d)
{
    const MeReal along = MeVector3Dot(d->frictionAxis, d->normal);
    MeVector3 t = {d->frictionAxis[0] - along * d->normal[0], d->frictionAxis[1] - along * d->normal[1],
                   d->frictionAxis[2] - along * d->normal[2]};
    if (MeVector3MagnitudeSqr(t) > ME_R(0.25) && MeVector3NormalizeSafe(t)) {
        MeVector3Copy(d->frictionAxis, t);
        return;
    }
    MeVector3 other;
    MeVector3PlaneSpace(d->normal, d->frictionAxis, other);
}

static void resetData(ContactData *d)
{
    memset(d, 0, sizeof *d);
    MeVector3Set(d->normal, 0, 1, 0);
    MeVector3Set(d->direction, 0, 1, 0);
    followNormal(d);
    MdtContactParamsReset(&d->params);
}

static void reset(MdtConstraintData *c)
{
    ContactData *d = MDT_CONSTRAINT_DATA(c, ContactData);
    MdtConstraintData *group = d->group, *next = d->next;
    resetData(d);
    d->group = group; /* membership survives a reset */
    d->next = next;
}

int MdtContactRowCount(const ContactData *d)
{
    switch (d->params.type) {
    case MdtContactTypeFriction1D:
        return 2;
    case MdtContactTypeFriction2D:
        return 3;
    default:
        return 1;
    }
}

int MdtContactStepRows(const MdtConstraintData *c)
{
    const ContactData *d = MDT_CONSTRAINT_DATA(c, const ContactData);
    int full = MdtContactRowCount(d);
    return d->lodStamp == c->world->partitionStamp && d->lodRows < full ? d->lodRows : full;
}

static int rowCount(const MdtConstraintData *c) { return MdtContactStepRows(c); }

MdtConstraintData *MdtContactNextInGroup(const MdtConstraintData *c)
{
    return MDT_CONSTRAINT_DATA(c, const ContactData)->next;
}

int MdtContactFullRowCount(const MdtConstraintData *c) { return MdtContactRowCount(MDT_CONSTRAINT_DATA(c, const ContactData)); }

void MdtContactGetLODInputs(const MdtConstraintData *c, MdtContactLODInputs *out)
{
    const ContactData *d = MDT_CONSTRAINT_DATA(c, const ContactData);
    out->position = d->position;
    out->normal = d->normal;
    out->penetration = d->penetration;
    out->importance = d->importance;
}

void MdtContactCapRows(MdtConstraintData *c, int rows, unsigned long stamp)
{
    ContactData *d = MDT_CONSTRAINT_DATA(c, ContactData);
    d->lodRows = rows;
    d->lodStamp = stamp;
}

/* Fills lin/ang of both halves for direction dir: J v = dir·(v0p − v1p). */
static void directionRow(MdtRow *row, const MeVector3 dir, const MeVector3 r0, const MeVector3 r1)
{
    MeVector3Copy(row->lin0, dir);
    MeVector3Cross(row->ang0, r0, dir);
    MeVector3MultiplyScalar(row->lin1, dir, -1);
    MeVector3Cross(row->ang1, dir, r1); /* −(r1 × dir) */
}

static MeReal pointVelocityAlong(const MdtBodyData *b, const MeVector3 r, const MeVector3 dir)
{
    if (!b)
        return 0;
    MeVector3 wxr;
    MeVector3Cross(wxr, b->velrot, r);
    return MeVector3Dot(dir, b->vel) + MeVector3Dot(dir, wxr);
}

/* Where a contact sits on its bodies: the bodies, the lever arms from their centres of mass, and
 * whether body 1 is the world moving at the contact's world velocity. */
typedef struct ContactArms {
    const MdtBodyData *b0, *b1;
    MeVector3 r0, r1;
    MeBool movingWorld;
} ContactArms;

/* Separating speed of body 0 from body 1 along the normal at the contact (negative when approaching). */
static MeReal separatingSpeed(const ContactData *d, const ContactArms *a)
{
    MeReal vn = pointVelocityAlong(a->b0, a->r0, d->normal) - pointVelocityAlong(a->b1, a->r1, d->normal);
    if (a->movingWorld)
        vn -= MeVector3Dot(d->normal, d->worldVelocity);
    return vn;
}

/* Restitution. A contact reported with a gap g that the bodies close within this step (at speed
 * v = −vn) bounces now if g is small (the bounce comes at most g early), or else lands exactly
 * this step and bounces at the start of the next with the remembered approach speed (at most
 * one step late); the choice g < e v h / (1 + 2e) balances the two position errors. Returns
 * whether it bounces now, with the approach speed to bounce from in *approachOut (set only then).
 * A contact without the bounce option never bounces and keeps no pending bounce; its speed is not
 * needed. */
static MeBool bouncesNow(ContactData *d, const ContactArms *a, const MdtRowWriter *w, MeReal *approachOut)
{
    const MdtContactParams *p = &d->params;
    const MeReal h = w->h;
    if (!(p->options & MdtBclContactOptionBounce)) {
        d->pendingBounce = 0;
        return MEFALSE;
    }
    const MeReal gap = -d->penetration;
    MeReal approach = -separatingSpeed(d, a);
    if (d->pendingBounce > approach)
        approach = d->pendingBounce;
    d->pendingBounce = 0;
    MeBool bounceNow = MEFALSE;
    if (approach > p->velThreshold && approach * h >= gap) {
        MeReal e = p->restitution;
        if (gap <= 0 || gap * (1 + 2 * e) <= e * approach * h)
            bounceNow = METRUE;
        else if (!w->captured)
            d->pendingBounce = approach; /* land first */
    }
    *approachOut = approach;
    return bounceNow;
}

/* The normal row's fields but its Jacobian (bounds, softness, target, error, γ), into *row. */
static void normalRowParams(ContactData *d, const ContactArms *a, const MdtRowWriter *w, MdtRow *row)
{
    const MdtContactParams *p = &d->params;
    const MeReal h = w->h;
    MdtRowInit(row);
    row->lo = (p->options & MdtBclContactOptionAdhesive) ? -p->max_adhesive_force : 0;
    row->hi = MEINFINITY;
    row->epsilon = (p->options & MdtBclContactOptionSoft) ? p->softness : 0;
    MeReal approach = 0;
    if (bouncesNow(d, a, w, &approach)) {
        /* Separate at e·|vn|; a deeper penetration's correction wins if it asks for more. */
        MeReal correction = w->gamma * d->penetration / h;
        if (correction > w->maxCorrection)
            correction = w->maxCorrection;
        MeReal bounce = p->restitution * approach;
        row->velocity = bounce > correction ? bounce : correction;
        row->gamma = 0;
        /* The world's softness would absorb part of the bounce (ε x of it); keep only a trace of it
         * to regularise redundant contacts, so that the restitution law holds. */
        row->noWorldEpsilon = METRUE;
        row->epsilon += ME_R(1e-3) * w->epsilon0;
    } else {
        row->error = -d->penetration;
        /* The correction γ·depth/h is bounded by the world's maximum correcting speed: a deep
         * penetration (or a tiny step) would otherwise launch the bodies apart. */
        if (w->gamma * d->penetration > w->maxCorrection * h)
            row->error = -w->maxCorrection * h / w->gamma;
        /* A separated contact (reported within the contact tolerance) may close its gap completely this
         * step, no less: anything slower would stop the bodies before they touch. */
        if (d->penetration < 0)
            row->gamma = 1;
    }
    if (a->movingWorld)
        row->velocity += MeVector3Dot(d->normal, d->worldVelocity);
}

/* The normal row; returns its index among the constraint's rows (negative when not written). */
static int addNormalRow(ContactData *d, const ContactArms *a, MdtRowWriter *w)
{
    MdtRow row;
    normalRowParams(d, a, w, &row);
    directionRow(&row, d->normal, a->r0, a->r1);
    int normalRow = MdtRowWriterAdd(w, &row);
    if (!w->captured && normalRow >= 0)
        w->x0[w->first + normalRow] = d->impulse[0];
    return normalRow;
}

/* The friction directions: t[0] the given direction made normal to n (or one chosen normal to n),
 * t[1] = t[0] × n. */
static void frictionDirections(const ContactData *d, MeVector3 t[2])
{
    MeBool haveDirection = MEFALSE;
    if (d->params.options & MdtBclContactOptionUseDirection) {
        MeReal dn = MeVector3Dot(d->direction, d->normal);
        MeVector3Set(t[0], d->direction[0] - dn * d->normal[0], d->direction[1] - dn * d->normal[1],
                     d->direction[2] - dn * d->normal[2]);
        haveDirection = MeVector3NormalizeSafe(t[0]);
    }
    if (!haveDirection)
        MeVector3Copy(t[0], d->frictionAxis);
    MeVector3Cross(t[1], t[0], d->normal);
}

/* The fields but the Jacobian of friction row k (0 or 1; along t) of the contact whose normal row is
 * `normalRow`. */
static MdtRow frictionRowParams(const ContactData *d, const ContactArms *a, const MdtRowWriter *w, int k,
                                const MeVector3 t, int normalRow)
{
    MdtRow r, *row = &r;
    const MdtContactParams *p = &d->params;
    const MeReal h = w->h;
    const MeU32 slipOption = k == 0 ? MdtBclContactOptionSlip1 : MdtBclContactOptionSlip2;
    const MeU32 slideOption = k == 0 ? MdtBclContactOptionSlide1 : MdtBclContactOptionSlide2;
    /* Slip is a compliance in force units (User Guide: slip speed = slip × friction force, whatever
     * the step); the row's ε is per impulse (force × h), hence slip / h. A slipping row has its own
     * compliance: the world's ε (which would add ε₀ h × force) is left out but for a trace that keeps
     * redundant rows regular, as for bouncing rows. */
    const MeReal slip = (p->options & slipOption) ? (k == 0 ? p->slip1 : p->slip2) / h : 0;
    MdtRowInit(row);
    row->velocity = (p->options & slideOption) ? (k == 0 ? p->slide1 : p->slide2) : 0;
    if (a->movingWorld)
        row->velocity += MeVector3Dot(t, d->worldVelocity);
    if (slip > 0) {
        row->epsilon = slip + ME_R(1e-3) * w->epsilon0;
        row->noWorldEpsilon = METRUE;
    }
    if ((k == 0 ? p->model1 : p->model2) == MdtFrictionModelNormalForce) {
        row->link = normalRow;
        row->mu = k == 0 ? p->frictioncoeff1 : p->frictioncoeff2;
    } else {
        const MeReal bound = k == 0 ? p->friction1 : p->friction2;
        row->lo = -bound;
        row->hi = bound;
    }
    return r;
}

/* The friction rows; returns how many were written linked to the normal row (NormalForce model). */
static int addFrictionRows(ContactData *d, const ContactArms *a, MdtRowWriter *w, int normalRow)
{
    const MdtContactParams *p = &d->params;
    MeVector3 t[2];
    frictionDirections(d, t);
    int directions = p->type == MdtContactTypeFriction2D ? 2 : 1, linked = 0;
    for (int k = 0; k < directions; k++) {
        MdtRow row = frictionRowParams(d, a, w, k, t[k], normalRow);
        directionRow(&row, t[k], a->r0, a->r1);
        int local = MdtRowWriterAdd(w, &row);
        if (!w->captured && local >= 0)
            w->x0[w->first + local] = d->impulse[1 + k];
        linked += local >= 0 && row.link >= 0;
    }
    return linked;
}

/* A contact's three rows (two friction directions, nothing capped) written together; returns how many
 * friction rows are linked to the normal row, with the normal row's index in *normalRow. */
static int addThreeRows(ContactData *d, const ContactArms *a, MdtRowWriter *w, int *normalRow)
{
    MdtRow rows[3];
    MeVector3 dir[3], t[2];
    frictionDirections(d, t);
    MeVector3Copy(dir[0], d->normal);
    MeVector3Copy(dir[1], t[0]);
    MeVector3Copy(dir[2], t[1]);
    normalRowParams(d, a, w, &rows[0]);
    const int first = w->count - w->first; /* where the normal row goes */
    rows[1] = frictionRowParams(d, a, w, 0, dir[1], first);
    rows[2] = frictionRowParams(d, a, w, 1, dir[2], first);
    *normalRow = MdtRowWriterAddDirections(w, dir, a->r0, a->r1, rows, d->impulse);
    return *normalRow >= 0 ? (rows[1].link >= 0) + (rows[2].link >= 0) : 0;
}

void MdtContactAddRows(const MdtConstraintData *owner, MdtConstraintData *contact, MdtRowWriter *w)
{
    ContactData *d = MDT_CONSTRAINT_DATA(contact, ContactData);
    const MdtContactParams *p = &d->params;
    ContactArms a = {owner->body[0], owner->body[1], {0, 0, 0}, {0, 0, 0}, MEFALSE};
    MeVector3Set(a.r0, d->position[0] - a.b0->comTM[3][0], d->position[1] - a.b0->comTM[3][1],
                 d->position[2] - a.b0->comTM[3][2]);
    if (a.b1)
        MeVector3Set(a.r1, d->position[0] - a.b1->comTM[3][0], d->position[1] - a.b1->comTM[3][1],
                     d->position[2] - a.b1->comTM[3][2]);
    a.movingWorld = !a.b1 && (p->options & MdtBclContactOptionUseWorldVelocity);
    const int stepRows = MdtContactStepRows(contact); /* matrix capping may drop friction or all */
    if (stepRows == 0)
        return;
    int normalRow, linked;
    if (stepRows == 3 && !w->captured) {
        linked = addThreeRows(d, &a, w, &normalRow);
    } else {
        normalRow = addNormalRow(d, &a, w);
        if (p->type == MdtContactTypeFrictionZero || stepRows < 2)
            return;
        linked = addFrictionRows(d, &a, w, normalRow);
    }
    /* A non-adhesive contact with two friction rows bounded by the normal force is Kea's typed contact
     * (KeaContact); any other (adhesive, box friction, one friction direction) stays generic rows. */
    if (linked == 2 && !(p->options & MdtBclContactOptionAdhesive) && normalRow >= 0 && a.b0 != a.b1)
        MdtRowWriterDeclareContact(w, normalRow);
}

void MdtContactUnpack(MdtConstraintData *contact, const MeReal *impulses, int rows, MeReal h)
{
    ContactData *d = MDT_CONSTRAINT_DATA(contact, ContactData);
    for (int k = 0; k < 3; k++)
        d->impulse[k] = k < rows ? impulses[k] : 0;
    d->normalForce = rows > 0 ? impulses[0] / h : 0;
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w) { MdtContactAddRows(c, c, w); }

static void unpack(MdtConstraintData *c, const MeReal *impulses, int rows, MeReal h)
{
    MdtContactUnpack(c, impulses, rows, h);
}

const MdtConstraintClass MdtContactClass = {"Contact", 3, reset, rowCount, addRows, unpack, NULL};

/* ---- API ---------------------------------------------------------------------------------- */
static MdtConstraintData *contactFromID(MdtContactID id, const char *function)
{
    return MdtConstraintFromIDOfType(id, MdtBclCONTACT, function);
}

#define CONTACT_OR_RETURN(c, d, id, ret)                                                             \
    MdtConstraintData *c = contactFromID((id), __func__);                                                \
    if (!c)                                                                                          \
        return ret;                                                                                  \
    ContactData *d = MDT_CONSTRAINT_DATA(c, ContactData)

MdtContactID MdtContactCreate(MdtWorldID w)
{
    MdtConstraintData *c = MdtConstraintCreateInternal(w, MdtBclCONTACT, &MdtContactClass, __func__);
    return c ? (MdtContactID)c->id : NULL;
}

void MdtContactReset(MdtContactID id)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    (void)d;
    reset(c);
}

MdtConstraintID MdtContactQuaConstraint(MdtContactID c) { return (MdtConstraintID)c; }

MdtContactID MdtConstraintDCastContact(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclCONTACT ? (MdtContactID)c : NULL;
}

/* The field setters' checks and effects, reporting in `function` (the public setter's name), shared
 * by the setters and MdtContactSetFromCollision. */
static void setPosition(ContactData *d, MeReal x, MeReal y, MeReal z, const char *function)
{
    ME_CHECK_FINITE3_IN(function, x, y, z, ME_NOTHING);
    MeVector3Set(d->position, x, y, z);
}

void MdtContactSetPosition(MdtContactID id, MeReal x, MeReal y, MeReal z)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    setPosition(d, x, y, z, __func__);
}

void MdtContactGetPosition(MdtContactID id, MeVector3 p)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    MeVector3Copy(p, d->position);
}

static void setNormal(ContactData *d, MeReal x, MeReal y, MeReal z, const char *function)
{
    ME_CHECK_FINITE3_IN(function, x, y, z, ME_NOTHING);
    MeVector3 n = {x, y, z};
    if (!MeVector3NormalizeSafe(n)) {
        ME_REPORT_IN(function, ME_ERR_ZERO_AXIS, "the normal (%g, %g, %g) has zero length; call ignored", (double)x,
                     (double)y, (double)z);
        return;
    }
    MeVector3Copy(d->normal, n);
    followNormal(d);
}

void MdtContactSetNormal(MdtContactID id, MeReal x, MeReal y, MeReal z)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    setNormal(d, x, y, z, __func__);
}

void MdtContactGetNormal(MdtContactID id, MeVector3 n)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(n, ME_NOTHING);
    MeVector3Copy(n, d->normal);
}

static void setPenetration(ContactData *d, MeReal p, const char *function)
{
    ME_CHECK_FINITE_IN(function, p, ME_NOTHING);
    d->penetration = p;
}

void MdtContactSetPenetration(MdtContactID id, MeReal p)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    setPenetration(d, p, __func__);
}

MeReal MdtContactGetPenetration(MdtContactID id)
{
    CONTACT_OR_RETURN(c, d, id, 0);
    return d->penetration;
}

void MdtContactSetDirection(MdtContactID id, MeReal x, MeReal y, MeReal z)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    MeVector3 t = {x, y, z};
    if (!MeVector3NormalizeSafe(t)) {
        ME_REPORT(ME_ERR_ZERO_AXIS, "the direction (%g, %g, %g) has zero length; call ignored", (double)x,
                  (double)y, (double)z);
        return;
    }
    MeVector3Copy(d->direction, t);
    d->params.options |= MdtBclContactOptionUseDirection;
}

void MdtContactGetDirection(MdtContactID id, MeVector3 t)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(t, ME_NOTHING);
    MeVector3Copy(t, d->direction);
}

void MdtContactSetWorldVelocity(MdtContactID id, MeReal vx, MeReal vy, MeReal vz)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_FINITE3(vx, vy, vz, ME_NOTHING);
    MeVector3Set(d->worldVelocity, vx, vy, vz);
    d->params.options |= MdtBclContactOptionUseWorldVelocity;
}

void MdtContactGetWorldVelocity(MdtContactID id, MeVector3 v)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    MeVector3Copy(v, d->worldVelocity);
}

MdtContactParamsID MdtContactGetParams(MdtContactID id)
{
    CONTACT_OR_RETURN(c, d, id, NULL);
    return &d->params;
}

static void setParams(ContactData *d, const MdtContactParams *p, const char *function)
{
    ME_CHECK_NOT_NULL_IN(function, p, ME_NOTHING);
    /* Keep the option bits this contact set itself (its own direction and world velocity). */
    MeU32 own = d->params.options & (MdtBclContactOptionUseDirection | MdtBclContactOptionUseWorldVelocity);
    d->params = *p;
    d->params.options |= own;
}

void MdtContactSetParams(MdtContactID id, const MdtContactParams *p)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    setParams(d, p, __func__);
}

void MdtContactSetCollisionFields(ContactData *d, const MdtContactParams *params, const MeVector3 position,
                                  const MeVector3 normal, MeReal penetration)
{
    setParams(d, params, "MdtContactSetParams");
    setPosition(d, position[0], position[1], position[2], "MdtContactSetPosition");
    setNormal(d, normal[0], normal[1], normal[2], "MdtContactSetNormal");
    setPenetration(d, penetration, "MdtContactSetPenetration");
}

void MdtContactSetFromCollision(MdtContactID id, const MdtContactParams *params, const MeVector3 position,
                                const MeVector3 normal, MeReal penetration)
{
    /* One handle check; each field then checked and set as its own setter would, a bad one skipped
     * and reported in that setter's name. */
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    (void)c;
    ME_CHECK_NOT_NULL(position, ME_NOTHING);
    ME_CHECK_NOT_NULL(normal, ME_NOTHING);
    MdtContactSetCollisionFields(d, params, position, normal, penetration);
}

void MdtContactGetRelativeVelocity(MdtContactID id, MeVector3 v)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    const MdtConstraintData *owner = d->group ? d->group : c;
    MeVector3 v0 = {0, 0, 0}, v1 = {0, 0, 0};
    for (int i = 0; i < 2; i++) {
        const MdtBodyData *b = owner->body[i];
        MeVector3 *out = i == 0 ? &v0 : &v1;
        if (!b) {
            if (d->params.options & MdtBclContactOptionUseWorldVelocity)
                MeVector3Copy(*out, d->worldVelocity);
            continue;
        }
        MeVector3 r, wxr;
        MeVector3Set(r, d->position[0] - b->comTM[3][0], d->position[1] - b->comTM[3][1],
                     d->position[2] - b->comTM[3][2]);
        MeVector3Cross(wxr, b->velrot, r);
        MeVector3Add(*out, b->vel, wxr);
    }
    MeVector3Subtract(v, v0, v1); /* body 0 relative to body 1, as Karma */
}

MeReal MdtContactGetNormalForce(MdtContactID id)
{
    CONTACT_OR_RETURN(c, d, id, 0);
    return d->normalForce;
}

void MdtContactSetImportance(MdtContactID id, MeReal importance)
{
    CONTACT_OR_RETURN(c, d, id, ME_NOTHING);
    ME_CHECK_FINITE(importance, ME_NOTHING);
    d->importance = importance;
}

MeReal MdtContactGetImportance(MdtContactID id)
{
    CONTACT_OR_RETURN(c, d, id, 0);
    return d->importance;
}

MdtContactID MdtContactGetNext(MdtContactID id)
{
    CONTACT_OR_RETURN(c, d, id, NULL);
    return d->next ? (MdtContactID)d->next->id : NULL;
}

MdtContactGroupID MdtContactGetContactGroup(MdtContactID id)
{
    CONTACT_OR_RETURN(c, d, id, NULL);
    return d->group ? (MdtContactGroupID)d->group->id : NULL;
}
