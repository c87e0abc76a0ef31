/* collide.c -- the aggregate pair test: recursion over the elements of either or both geometries,
 * each pair of leaves (non-aggregate geometries) tested through the framework's pair table (in
 * whichever order it was registered), contacts gathered and reduced to the pair's request.
 *
 * Element tags: a contact's element on an aggregate's side is the path code of the leaf element: the
 * slots from the outer aggregate down, digit (slot + 1) in radix (countMax + 1) per level, so 0 means
 * "no element". McdIntersect turns codes into the child instances of the model's tree
 * (McdInstanceResolveTags). A path too long for a pointer-sized code is tagged NULL. */
#include <stdint.h>

#include "../nearfield/nearfield.h"
#include "aggregate.h"

/* One side of the recursion: a geometry placed at tm, with its element path. */
typedef struct Node {
    const McdGeometryData *g;
    MeReal (*tm)[4];
    MeVector3 lo, hi;  /* world AABB (padded by nothing) */
    uintptr_t code;    /* path code (0 for the outer geometry) */
    uintptr_t radix;   /* weight of the next level's digit; 0 once the code has overflowed */
    MeBool isElement;  /* an element of an aggregate: its contacts get its code */
} Node;

typedef struct Context {
    const McdFrameworkData *fw;
    MeReal tolerance;
    void **cache;      /* the pair's cache slot: handed to terrain tests (their generator needs the pair) */
    McdContact buf[MCD_AGGREGATE_CONTACT_BUFFER];
    int n;
} Context;

static MeBool isTerrain(int type)
{
    return type == kMcdGeometryTypeTriangleList || type == kMcdGeometryTypeTriangleMesh ||
           type == kMcdGeometryTypeRGHeightField;
}

static MeBool overlap(const Node *a, const Node *b, MeReal tolerance)
{
    for (int j = 0; j < 3; j++)
        if (a->lo[j] > b->hi[j] + tolerance || b->lo[j] > a->hi[j] + tolerance)
            return MEFALSE;
    return METRUE;
}

/* The element in slot i of node's aggregate, placed in the world (its transform written to storage). */
static void childNode(Node *child, const Node *parent, int i, MeMatrix4 storage)
{
    const McdAggregateShape *a = parent->g->u.aggregate;
    const McdAggregateElement *e = &a->elements[i];
    MeMatrix4TMCompound(storage, (MeMatrix4Ptr)e->relTM, parent->tm);
    child->g = e->geometry;
    child->tm = storage;
    McdGeometryAABBInternal(child->g, storage, child->lo, child->hi);
    const uintptr_t base = (uintptr_t)a->countMax + 1;
    child->isElement = METRUE;
    if (parent->radix != 0 && parent->radix <= UINTPTR_MAX / base) {
        child->code = parent->code + (uintptr_t)(i + 1) * parent->radix; /* < radix * base: no overflow */
        child->radix = parent->radix * base;
    } else {
        child->code = 0;
        child->radix = 0;
    }
}

/* A pair of leaves through the framework's table; contacts appended to ctx->buf. */
static void leaf(Context *ctx, const Node *a, const Node *b)
{
    int t1 = a->g->type, t2 = b->g->type, swapped = 0;
    McdNearfieldFn fn = McdFrameworkGetInteraction(ctx->fw, t1, t2);
    if (!fn) {
        fn = McdFrameworkGetInteraction(ctx->fw, t2, t1);
        swapped = 1;
    }
    if (!fn)
        return; /* no test for these types: no contacts, as for a pair of models */
    if (ctx->n + MCD_NF_MAX_CONTACTS > MCD_AGGREGATE_CONTACT_BUFFER)
        ctx->n = McdNfReduce(ctx->buf, ctx->n, MCD_NF_MAX_CONTACTS); /* many elements touch: keep the best */
    McdContact *c = ctx->buf + ctx->n;
    void **cache = (isTerrain(t1) || isTerrain(t2)) ? ctx->cache : NULL;
    int n = swapped ? McdNfCallCentred(fn, b->g, b->tm, a->g, a->tm, ctx->tolerance, c, MCD_NF_MAX_CONTACTS, cache)
                    : McdNfCallCentred(fn, a->g, a->tm, b->g, b->tm, ctx->tolerance, c, MCD_NF_MAX_CONTACTS, cache);
    if (n < 0 || n > MCD_NF_MAX_CONTACTS)
        n = 0; /* a broken test: its contacts are not used */
    for (int k = 0; k < n; k++) {
        if (swapped) {
            void *e = c[k].element1;
            MeVector3Scale(c[k].normal, -ME_R(1.0));
            c[k].element1 = c[k].element2;
            c[k].element2 = e;
        }
        if (a->isElement)
            c[k].element1 = (void *)a->code;
        if (b->isElement)
            c[k].element2 = (void *)b->code;
    }
    ctx->n += n;
}

static void collide(Context *ctx, const Node *a, const Node *b, int depth);

/* Each element of the aggregate `agg` against `other`, agg on side 1 or 2 as it was. */
static void expand(Context *ctx, const Node *agg, const Node *other, MeBool aggFirst, int depth)
{
    const McdAggregateShape *s = agg->g->u.aggregate;
    for (int i = 0; i < s->countMax; i++) {
        if (!s->elements[i].geometry)
            continue;
        MeMatrix4 tm;
        Node child;
        childNode(&child, agg, i, tm);
        if (overlap(&child, other, ctx->tolerance)) {
            if (aggFirst)
                collide(ctx, &child, other, depth + 1);
            else
                collide(ctx, other, &child, depth + 1);
        }
    }
}

/* Side 1's elements first, then side 2's, down to pairs of leaves. */
static void collide(Context *ctx, const Node *a, const Node *b, int depth)
{
    if (depth > 2 * (MCD_AGGREGATE_MAX_DEPTH + 1)) /* unreachable through the API: a guard on the stack */
        return;
    if (a->g->type == kMcdGeometryTypeAggregate)
        expand(ctx, a, b, METRUE, depth);
    else if (b->g->type == kMcdGeometryTypeAggregate)
        expand(ctx, b, a, MEFALSE, depth);
    else
        leaf(ctx, a, b);
}

static void rootNode(Node *node, const McdGeometryData *g, MeMatrix4 tm)
{
    node->g = g;
    node->tm = tm;
    if (g->type == kMcdGeometryTypeAggregate) { /* its elements are culled one by one: no box of the whole */
        MeVector3Set(node->lo, -MEINFINITY, -MEINFINITY, -MEINFINITY);
        MeVector3Set(node->hi, MEINFINITY, MEINFINITY, MEINFINITY);
    } else {
        McdGeometryAABBInternal(g, tm, node->lo, node->hi);
    }
    node->code = 0;
    node->radix = 1;
    node->isElement = MEFALSE;
}

/* Size: McdNearfieldFn's signature, the pair-test table's type. */
int McdNfAggregateAny(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2,
                      MeReal tolerance, McdContact *contacts, int maxContacts, void **cache)
{
    Context ctx;
    Node a, b;
    ctx.fw = g1->framework;
    ctx.tolerance = tolerance;
    ctx.cache = cache;
    ctx.n = 0;
    rootNode(&a, g1, tm1);
    rootNode(&b, g2, tm2);
    collide(&ctx, &a, &b, 0);
    int n = ctx.n;
    if (n > maxContacts)
        n = McdNfReduce(ctx.buf, n, maxContacts);
    for (int k = 0; k < n; k++)
        contacts[k] = ctx.buf[k];
    return n;
}

void McdAggregateRegisterAll(McdFrameworkData *fw, const char *function)
{
    for (int t = 0; t < fw->typeCount; t++)
        if (t != kMcdGeometryTypeNull)
            McdFrameworkSetInteraction(fw, kMcdGeometryTypeAggregate, t, McdNfAggregateAny, function);
}
