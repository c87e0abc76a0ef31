/* contact_group.c -- MdtContactGroup: the contacts of one body pair as one constraint.
 *
 * The group is what the partitioner and the packer see; its contacts (pool slots marked inGroup)
 * are a singly linked list in the group's data, each writing its rows in list order with the
 * group's bodies. After the solve each contact keeps its own impulses, so the next step starts
 * from them (warm starting), and the group sums their normal forces. */
#include <karma/MdtContactGroup.h>

#include "../../me/check.h"
#include "../world.h"
#include "contact_internal.h"

typedef struct GroupData {
    MdtConstraintData *first, *last;
    int count;
    MeBool swapped;
    void *generator;
    MeReal normalForce;
} GroupData;
MDT_CONSTRAINT_DATA_FITS(GroupData);

static void destroyContacts(MdtConstraintData *g)
{
    GroupData *d = MDT_CONSTRAINT_DATA(g, GroupData);
    MdtConstraintData *c = d->first;
    while (c) {
        MdtConstraintData *next = MDT_CONSTRAINT_DATA(c, ContactData)->next;
        MdtConstraintRelease(c);
        c = next;
    }
    d->first = d->last = NULL;
    d->count = 0;
}

static void reset(MdtConstraintData *g)
{
    GroupData *d = MDT_CONSTRAINT_DATA(g, GroupData);
    if (d->count)
        destroyContacts(g);
    d->first = d->last = NULL;
    d->count = 0;
    d->swapped = MEFALSE;
    d->generator = NULL;
    d->normalForce = 0;
}

static int rowCount(const MdtConstraintData *g)
{
    int rows = 0;
    for (const MdtConstraintData *c = MDT_CONSTRAINT_DATA(g, const GroupData)->first; c;
         c = MDT_CONSTRAINT_DATA(c, const ContactData)->next)
        rows += MdtContactStepRows(c);
    return rows;
}

static void addRows(MdtConstraintData *g, MdtRowWriter *w)
{
    for (MdtConstraintData *c = MDT_CONSTRAINT_DATA(g, GroupData)->first; c; c = MDT_CONSTRAINT_DATA(c, ContactData)->next) {
        c->body[0] = g->body[0];
        c->body[1] = g->body[1];
        c->rowStart = w->count;
        MdtContactAddRows(g, c, w);
        c->rowCount = w->count - c->rowStart;
    }
}

static void unpack(MdtConstraintData *g, const MeReal *impulses, int rows, MeReal h)
{
    GroupData *d = MDT_CONSTRAINT_DATA(g, GroupData);
    int offset = 0;
    d->normalForce = 0;
    /* Every contact, also those capping dropped (rowCount 0): their warm starts go back to 0. */
    for (MdtConstraintData *c = d->first; c; c = MDT_CONSTRAINT_DATA(c, ContactData)->next) {
        int n = offset + c->rowCount <= rows ? c->rowCount : 0;
        MdtContactUnpack(c, impulses + offset, n, h);
        d->normalForce += MDT_CONSTRAINT_DATA(c, ContactData)->normalForce;
        offset += n;
    }
}

MdtConstraintData *MdtContactGroupFirst(const MdtConstraintData *g) { return MDT_CONSTRAINT_DATA(g, const GroupData)->first; }

static void destroy(MdtConstraintData *g)
{
    MdtWorldData *w = g->world;
    destroyContacts(g);
    if (w->contactGroupDestroyCB)
        w->contactGroupDestroyCB((MdtContactGroupID)g->id, w->contactGroupDestroyData);
}

static const MdtConstraintClass groupClass = {"ContactGroup", 0, reset, rowCount, addRows, unpack, destroy};

/* ---- API ---------------------------------------------------------------------------------- */
#define GROUP_OR_RETURN(g, d, id, ret)                                                               \
    MdtConstraintData *g = MdtConstraintFromIDOfType((id), MdtBclCONTACTGROUP, __func__);                \
    if (!g)                                                                                          \
        return ret;                                                                                  \
    GroupData *d = MDT_CONSTRAINT_DATA(g, GroupData)

MdtContactGroupID MdtContactGroupCreate(MdtWorldID w)
{
    MdtConstraintData *g = MdtConstraintCreateForContacts(w, MdtBclCONTACTGROUP, &groupClass, __func__);
    return g ? (MdtContactGroupID)g->id : NULL;
}

void MdtContactGroupDestroy(MdtContactGroupID id)
{
    MdtConstraintDestroy((MdtConstraintID)id);
}

void MdtContactGroupReset(MdtContactGroupID id)
{
    GROUP_OR_RETURN(g, d, id, ME_NOTHING);
    (void)d;
    reset(g);
}

MdtConstraintID MdtContactGroupQuaConstraint(MdtContactGroupID g) { return (MdtConstraintID)g; }

MdtContactGroupID MdtConstraintDCastContactGroup(MdtConstraintID c)
{
    return MdtConstraintGetType(c) == MdtBclCONTACTGROUP ? (MdtContactGroupID)c : NULL;
}

MdtContactID MdtContactGroupGetFirstContact(MdtContactGroupID id)
{
    GROUP_OR_RETURN(g, d, id, NULL);
    return d->first ? (MdtContactID)d->first->id : NULL;
}

int MdtContactGroupGetContactsAndPositions(MdtContactGroupID id, MdtContactID *contacts, MeVector3 *positions,
                                           int max)
{
    GROUP_OR_RETURN(g, d, id, 0);
    ME_CHECK_NOT_NULL(contacts, 0);
    if (max < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'max' (%d) must not be negative; call ignored", max);
        return 0;
    }
    int n = 0;
    for (MdtConstraintData *c = d->first; c && n < max; c = MDT_CONSTRAINT_DATA(c, ContactData)->next, ++n) {
        contacts[n] = (MdtContactID)c->id;
        if (positions)
            MeVector3Copy(positions[n], MDT_CONSTRAINT_DATA(c, ContactData)->position);
    }
    return n;
}

MdtContactID MdtContactGroupGetNextContact(MdtContactGroupID id, MdtContactID cid)
{
    GROUP_OR_RETURN(g, d, id, NULL);
    (void)d;
    MdtConstraintData *c = MdtConstraintFromIDOfType(cid, MdtBclCONTACT, __func__);
    if (!c)
        return NULL;
    ContactData *cd = MDT_CONSTRAINT_DATA(c, ContactData);
    if (cd->group != g) {
        ME_REPORT(ME_ERR_BAD_STATE, "the contact is not a member of this group");
        return NULL;
    }
    return cd->next ? (MdtContactID)cd->next->id : NULL;
}

/* Make stand-alone contact c a member of g (not yet linked into its list). */
static void adopt(MdtConstraintData *g, MdtConstraintData *c)
{
    if (c->enabled) {
        c->enabled = MEFALSE;
        c->world->enabledConstraintCount--;
    }
    MdtConstraintAttach(c, NULL, NULL); /* out of the bodies' lists: the group stands for it */
    c->inGroup = METRUE;
    c->body[0] = g->body[0];
    c->body[1] = g->body[1];
    MDT_CONSTRAINT_DATA(c, ContactData)->group = g;
}

static void append(MdtConstraintData *g, GroupData *d, MdtConstraintData *c)
{
    ContactData *cd = MDT_CONSTRAINT_DATA(c, ContactData);
    adopt(g, c);
    cd->next = NULL;
    if (d->last)
        MDT_CONSTRAINT_DATA(d->last, ContactData)->next = c;
    else
        d->first = c;
    d->last = c;
    d->count++;
}

void MdtContactGroupAppendContact(MdtContactGroupID id, MdtContactID cid)
{
    GROUP_OR_RETURN(g, d, id, ME_NOTHING);
    MdtConstraintData *c = MdtConstraintFromIDOfType(cid, MdtBclCONTACT, __func__);
    if (!c)
        return;
    if (MDT_CONSTRAINT_DATA(c, ContactData)->group) {
        ME_REPORT(ME_ERR_BAD_STATE, "the contact already belongs to a group; remove it first");
        return;
    }
    if (c->world != g->world) {
        ME_REPORT(ME_ERR_FOREIGN_HANDLE, "the contact belongs to another world than the group");
        return;
    }
    append(g, d, c);
}

/* A contact just unlinked from its group: a stand-alone contact again, on the group's bodies. */
static void release(MdtConstraintData *c)
{
    MdtBodyData *b0 = c->body[0], *b1 = c->body[1];
    c->body[0] = c->body[1] = NULL;
    MdtConstraintAttach(c, b0, b1);
}

/* Unlink c, which follows prev in d's list (NULL: c is the first). */
static void unlinkAfter(GroupData *d, MdtConstraintData *prev, MdtConstraintData *c)
{
    ContactData *cd = MDT_CONSTRAINT_DATA(c, ContactData);
    if (prev)
        MDT_CONSTRAINT_DATA(prev, ContactData)->next = cd->next;
    else
        d->first = cd->next;
    if (d->last == c)
        d->last = prev;
    d->count--;
    cd->group = NULL;
    cd->next = NULL;
    c->inGroup = MEFALSE;
}

/* Unlink c from g's list; returns METRUE if it was there. */
static MeBool unlink(MdtConstraintData *g, GroupData *d, MdtConstraintData *c)
{
    MdtConstraintData *prev = NULL;
    for (MdtConstraintData *it = d->first; it; prev = it, it = MDT_CONSTRAINT_DATA(it, ContactData)->next) {
        if (it != c)
            continue;
        unlinkAfter(d, prev, c);
        (void)g;
        return METRUE;
    }
    return MEFALSE;
}

void MdtContactGroupRemoveContact(MdtContactGroupID id, MdtContactID cid)
{
    GROUP_OR_RETURN(g, d, id, ME_NOTHING);
    MdtConstraintData *c = MdtConstraintFromIDOfType(cid, MdtBclCONTACT, __func__);
    if (!c)
        return;
    if (!unlink(g, d, c)) {
        ME_REPORT(ME_ERR_BAD_STATE, "the contact is not a member of this group");
        return;
    }
    release(c);
}

/* Karma 1.2 set the link field itself (the function was marked deprecated); here the group's list,
 * count and last contact stay consistent: nc is moved (or, stand-alone, adopted) to just after c, and
 * NULL makes c the last contact, the ones after it leaving the group as stand-alone contacts. */
void MdtContactSetNext(MdtContactID cid, MdtContactID nid)
{
    MdtConstraintData *c = MdtConstraintFromIDOfType(cid, MdtBclCONTACT, __func__);
    if (!c)
        return;
    ContactData *cd = MDT_CONSTRAINT_DATA(c, ContactData);
    MdtConstraintData *g = cd->group;
    if (!g) {
        ME_REPORT(ME_ERR_BAD_STATE, "argument 'c' is a stand-alone contact: only a contact group's contacts "
                  "are linked (MdtContactGroupAppendContact)");
        return;
    }
    GroupData *d = MDT_CONSTRAINT_DATA(g, GroupData);
    if (!nid) {
        while (cd->next) {
            MdtConstraintData *k = cd->next;
            unlink(g, d, k);
            release(k);
        }
        return;
    }
    MdtConstraintData *n = MdtConstraintFromIDOfType(nid, MdtBclCONTACT, __func__);
    if (!n)
        return;
    ContactData *nd = MDT_CONSTRAINT_DATA(n, ContactData);
    if (n == c || cd->next == n) {
        if (n == c)
            ME_REPORT(ME_ERR_ARGUMENT_RANGE, "a contact cannot follow itself");
        return;
    }
    if (n->world != c->world) {
        ME_REPORT(ME_ERR_FOREIGN_HANDLE, "argument 'nc' belongs to another world than 'c'");
        return;
    }
    if (nd->group && nd->group != g) {
        ME_REPORT(ME_ERR_BAD_STATE, "argument 'nc' belongs to another contact group; remove it first");
        return;
    }
    if (nd->group)
        unlink(g, d, n);
    adopt(g, n);
    nd->next = cd->next;
    cd->next = n;
    if (d->last == c)
        d->last = n;
    d->count++;
}

MdtContactID MdtContactGroupCreateContact(MdtContactGroupID id)
{
    GROUP_OR_RETURN(g, d, id, NULL);
    MdtConstraintData *c = MdtConstraintCreateForContacts((MdtWorldID)g->world->id, MdtBclCONTACT, &MdtContactClass, __func__);
    if (!c)
        return NULL;
    append(g, d, c);
    return (MdtContactID)c->id;
}

/* A contact unlinked from its group destroyed. */
static void destroyUnlinked(MdtConstraintData *c)
{
    c->body[0] = c->body[1] = NULL;
    MdtConstraintRelease(c);
}

void MdtContactGroupDestroyContact(MdtContactGroupID id, MdtContactID cid)
{
    GROUP_OR_RETURN(g, d, id, ME_NOTHING);
    MdtConstraintData *c = MdtConstraintFromIDOfType(cid, MdtBclCONTACT, __func__);
    if (!c)
        return;
    if (g->world->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "contacts cannot be destroyed during the world's step");
        return;
    }
    if (!unlink(g, d, c)) {
        ME_REPORT(ME_ERR_BAD_STATE, "the contact is not a member of this group");
        return;
    }
    destroyUnlinked(c);
}

/* ---- refreshing the group from a collision's points ------------------------------------------ */

/* The first `old` contacts of d's list not yet matched, the one nearest to p (the first of equals);
 * NULL if none. */
static MdtConstraintData *nearestUnmatched(const GroupData *d, int old, const MeVector3 p)
{
    MdtConstraintData *best = NULL, *c = d->first;
    MeReal bestDistance = MEINFINITY;
    for (int k = 0; k < old; k++, c = MDT_CONSTRAINT_DATA(c, ContactData)->next) {
        const ContactData *cd = MDT_CONSTRAINT_DATA(c, const ContactData);
        if (cd->matched)
            continue;
        const MeReal distance = MeVector3DistanceSqr(cd->position, p);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = c;
        }
    }
    return best;
}

/* Destroy those of the first `old` contacts of d's list that no point matched, in list order. */
static void destroyUnmatched(GroupData *d, int old)
{
    MdtConstraintData *prev = NULL, *c = d->first;
    for (int k = 0; k < old; k++) {
        MdtConstraintData *next = MDT_CONSTRAINT_DATA(c, ContactData)->next;
        if (MDT_CONSTRAINT_DATA(c, ContactData)->matched) {
            prev = c;
        } else {
            unlinkAfter(d, prev, c);
            destroyUnlinked(c);
        }
        c = next;
    }
}

int MdtContactGroupSetFromCollisions(MdtContactGroupID id, const MdtContactParams *params,
                                     const MdtCollisionPoint *points, int n, MdtContactID *out)
{
    GROUP_OR_RETURN(g, d, id, 0);
    ME_CHECK_NOT_NULL(params, 0);
    if (n < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'n' (%d) must not be negative; call ignored", n);
        return 0;
    }
    if (n > 0) {
        ME_CHECK_NOT_NULL(points, 0);
        ME_CHECK_NOT_NULL(out, 0);
    }
    if (g->world->locked) {
        ME_REPORT(ME_ERR_WORLD_LOCKED, "contacts cannot be changed during the world's step");
        return 0;
    }
    /* New contacts are appended after the old ones, so the old are the list's first `old`. */
    const int old = d->count;
    MdtConstraintData *c = d->first;
    for (int k = 0; k < old; k++, c = MDT_CONSTRAINT_DATA(c, ContactData)->next)
        MDT_CONSTRAINT_DATA(c, ContactData)->matched = MEFALSE;
    int i = 0;
    for (; i < n; i++) {
        c = nearestUnmatched(d, old, points[i].position);
        if (c) {
            MDT_CONSTRAINT_DATA(c, ContactData)->matched = METRUE;
        } else {
            c = MdtConstraintCreateForContacts((MdtWorldID)g->world->id, MdtBclCONTACT, &MdtContactClass, __func__);
            if (!c)
                break; /* pool full: reported (once, in the world's caller name when it has one) */
            append(g, d, c);
        }
        MdtContactSetCollisionFields(MDT_CONSTRAINT_DATA(c, ContactData), params, points[i].position,
                                     points[i].normal, points[i].penetration);
        out[i] = (MdtContactID)c->id;
    }
    destroyUnmatched(d, old);
    return i;
}

MeBool MdtContactGroupIsSwapped(MdtContactGroupID id)
{
    GROUP_OR_RETURN(g, d, id, MEFALSE);
    return d->swapped;
}

void MdtContactGroupSetSwapped(MdtContactGroupID id, MeBool swapped)
{
    GROUP_OR_RETURN(g, d, id, ME_NOTHING);
    d->swapped = swapped ? METRUE : MEFALSE;
}

int MdtContactGroupGetCount(MdtContactGroupID id)
{
    GROUP_OR_RETURN(g, d, id, 0);
    return d->count;
}

MeReal MdtContactGroupGetNormalForce(MdtContactGroupID id)
{
    GROUP_OR_RETURN(g, d, id, 0);
    return d->normalForce;
}

void MdtContactGroupSetGenerator(MdtContactGroupID id, void *generator)
{
    GROUP_OR_RETURN(g, d, id, ME_NOTHING);
    d->generator = generator;
}

void *MdtContactGroupGetGenerator(MdtContactGroupID id)
{
    GROUP_OR_RETURN(g, d, id, NULL);
    return d->generator;
}

/* ---- a body's contacts (D9) ---------------------------------------------------------------- */
/* The first contact at or after constraint c in body b's list: a group's first contact or a
 * stand-alone contact. */
static MdtConstraintData *firstContactFrom(const MdtBodyData *b, MdtConstraintData *c)
{
    for (; c; c = c->nextForBody[c->body[0] == b ? 0 : 1]) {
        if (c->type == MdtBclCONTACT)
            return c;
        if (c->type == MdtBclCONTACTGROUP && MDT_CONSTRAINT_DATA(c, GroupData)->first)
            return MDT_CONSTRAINT_DATA(c, GroupData)->first;
    }
    return NULL;
}

MdtContactID MdtBodyGetFirstContact(MdtBodyID bid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (!b)
        return NULL;
    MdtConstraintData *c = firstContactFrom(b, b->firstConstraint);
    return c ? (MdtContactID)c->id : NULL;
}

MdtContactID MdtBodyGetNextContact(MdtBodyID bid, MdtContactID cid)
{
    MdtBodyData *b = MdtBodyFromID(bid, __func__);
    if (!b)
        return NULL;
    MdtConstraintData *c = MdtConstraintFromIDOfType(cid, MdtBclCONTACT, __func__);
    if (!c)
        return NULL;
    ContactData *d = MDT_CONSTRAINT_DATA(c, ContactData);
    MdtConstraintData *owner = d->group ? d->group : c;
    if (owner->body[0] != b && owner->body[1] != b) {
        ME_REPORT(ME_ERR_BAD_STATE, "the contact does not touch this body");
        return NULL;
    }
    if (d->group && d->next)
        return (MdtContactID)d->next->id;
    MdtConstraintData *next = firstContactFrom(b, owner->nextForBody[owner->body[0] == b ? 0 : 1]);
    return next ? (MdtContactID)next->id : NULL;
}
