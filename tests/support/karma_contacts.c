/* karma_contacts.c -- hand-made contacts for dynamics tests and benchmarks, as an application with its
 * own collision system would make them: a box resting on a plane or on another box, four corner
 * contacts in a persistent contact group (refreshed in the same order every step, so warm starting
 * works). Plain C on the public API, no test framework: bench/ compiles this file too. */
#include "karma_contacts.h"

#include <stddef.h>

#include <karma/MdtContactGroup.h>
#include <karma/Mdt.h>


void karma_contact_params_friction(MdtContactParams *p, MeReal mu)
{
    MdtContactParamsReset(p);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, mu);
}

/* Make the group hold at least n contacts (reusing the existing ones first); 0 when the pool is full. */
static int ensureContacts(MdtContactGroupID g, int n)
{
    while (MdtContactGroupGetCount(g) < n)
        if (!MdtContactGroupCreateContact(g))
            return 0;
    return 1;
}

/* The axis k of transform tm whose (tm[k]·d) / scale[k] is largest in magnitude (scale NULL: 1);
 * *value gets that signed ratio. Picks reference and incident faces. */
static int mostAlignedAxis(MeMatrix4Ptr tm, const MeVector3 d, const MeReal *scale, MeReal *value)
{
    int axis = 0;
    MeReal best = 0;
    for (int k = 0; k < 3; k++) {
        MeReal v = MeVector3Dot(tm[k], d);
        if (scale)
            v /= scale[k];
        if (MeFabs(v) > MeFabs(best)) {
            best = v;
            axis = k;
        }
    }
    *value = best;
    return axis;
}

int karma_box_on_plane(MdtContactGroupID g, MdtBodyID box, const MeVector3 halfExtents, const MeVector3 up,
                       MeReal planeOffset, const MdtContactParams *params)
{
    if (!ensureContacts(g, 4))
        return 0;
    MeMatrix4Ptr tm = MdtBodyGetTransformPtr(box);
    /* The box's bottom face: the local axis most opposed to `up`. */
    MeReal best;
    int axis = mostAlignedAxis(tm, up, NULL, &best);
    MeReal sign = best > 0 ? -1 : 1; /* towards the plane */
    int a = (axis + 1) % 3, b = (axis + 2) % 3;
    MdtContactID c = MdtContactGroupGetFirstContact(g);
    for (int i = 0; i < 4; i++, c = MdtContactGroupGetNextContact(g, c)) {
        MeVector3 local = {0, 0, 0}, world;
        local[axis] = sign * halfExtents[axis];
        local[a] = (i & 1 ? 1 : -1) * halfExtents[a];
        local[b] = (i & 2 ? 1 : -1) * halfExtents[b];
        MeMatrix4TMTransform(world, tm, local);
        MeReal height = MeVector3Dot(world, up) - planeOffset;
        MdtContactSetParams(c, params);
        MdtContactSetPosition(c, world[0] - height * up[0] / 2, world[1] - height * up[1] / 2,
                              world[2] - height * up[2] / 2);
        MdtContactSetNormal(c, up[0], up[1], up[2]); /* world (body 1) towards the box (body 0) */
        MdtContactSetPenetration(c, -height);
    }
    return 1;
}

int karma_box_on_box(MdtContactGroupID g, MdtBodyID top, MdtBodyID bottom, const MeVector3 halfExtents,
                     const MdtContactParams *params)
{
    if (!ensureContacts(g, 4))
        return 0;
    MeMatrix4Ptr tt = MdtBodyGetTransformPtr(top), tb = MdtBodyGetTransformPtr(bottom);
    /* Reference face: the bottom box's face whose normal is most aligned with the direction to the top box. */
    MeVector3 d = {tt[3][0] - tb[3][0], tt[3][1] - tb[3][1], tt[3][2] - tb[3][2]};
    MeReal best;
    int axis = mostAlignedAxis(tb, d, halfExtents, &best);
    MeVector3 up;
    MeVector3MultiplyScalar(up, tb[axis], best > 0 ? 1 : -1);
    MeReal faceOffset = MeVector3Dot(tb[3], up) + halfExtents[axis];
    /* Incident face: the top box's face most opposed to `up`; its four corners. */
    MeReal ib;
    int ia = mostAlignedAxis(tt, up, NULL, &ib);
    int a = (ia + 1) % 3, b = (ia + 2) % 3;
    MdtContactID c = MdtContactGroupGetFirstContact(g);
    for (int i = 0; i < 4; i++, c = MdtContactGroupGetNextContact(g, c)) {
        MeVector3 local = {0, 0, 0}, world;
        local[ia] = (ib > 0 ? -1 : 1) * halfExtents[ia];
        local[a] = (i & 1 ? 1 : -1) * halfExtents[a];
        local[b] = (i & 2 ? 1 : -1) * halfExtents[b];
        MeMatrix4TMTransform(world, tt, local);
        MeReal height = MeVector3Dot(world, up) - faceOffset;
        MdtContactSetParams(c, params);
        MdtContactSetPosition(c, world[0] - height * up[0] / 2, world[1] - height * up[1] / 2,
                              world[2] - height * up[2] / 2);
        MdtContactSetNormal(c, up[0], up[1], up[2]); /* bottom (body 1) towards top (body 0) */
        MdtContactSetPenetration(c, -height);
    }
    return 1;
}

int karma_box_on_box_clipped(MdtContactGroupID g, MdtBodyID top, const MeVector3 topHalf, MdtBodyID bottom,
                             const MeVector3 bottomHalf, const MdtContactParams *params)
{
    if (!ensureContacts(g, 4))
        return 0;
    MeMatrix4Ptr tt = MdtBodyGetTransformPtr(top), tb = MdtBodyGetTransformPtr(bottom);
    /* Reference face: the bottom box's face facing the top box (direction scaled by the extents). */
    MeVector3 d = {tt[3][0] - tb[3][0], tt[3][1] - tb[3][1], tt[3][2] - tb[3][2]};
    MeReal best;
    int axis = mostAlignedAxis(tb, d, bottomHalf, &best);
    MeVector3 up, centre;
    MeVector3MultiplyScalar(up, tb[axis], best > 0 ? 1 : -1);
    for (int k = 0; k < 3; k++)
        centre[k] = tb[3][k] + up[k] * bottomHalf[axis];
    int ra = (axis + 1) % 3, rb = (axis + 2) % 3;
    /* Incident face: the top box's face most opposed to `up`, its outward normal m and centre ci. */
    MeReal ib;
    int ia = mostAlignedAxis(tt, up, NULL, &ib);
    MeReal side = ib > 0 ? -1 : 1;
    MeVector3 m, ci;
    MeVector3MultiplyScalar(m, tt[ia], side);
    for (int k = 0; k < 3; k++)
        ci[k] = tt[3][k] + m[k] * topHalf[ia];
    int a = (ia + 1) % 3, b = (ia + 2) % 3;
    MdtContactID c = MdtContactGroupGetFirstContact(g);
    for (int i = 0; i < 4; i++, c = MdtContactGroupGetNextContact(g, c)) {
        MeVector3 local = {0, 0, 0}, world, rel, q;
        local[ia] = side * topHalf[ia];
        local[a] = (i & 1 ? 1 : -1) * topHalf[a];
        local[b] = (i & 2 ? 1 : -1) * topHalf[b];
        MeMatrix4TMTransform(world, tt, local);
        MeVector3Subtract(rel, world, centre);
        /* The corner, projected onto the reference face and clamped into it: for boxes whose faces
         * are parallel, the four clamped corners are the corners of the overlap rectangle. */
        MeReal u = MeVector3Dot(rel, tb[ra]), v = MeVector3Dot(rel, tb[rb]);
        u = u < -bottomHalf[ra] ? -bottomHalf[ra] : (u > bottomHalf[ra] ? bottomHalf[ra] : u);
        v = v < -bottomHalf[rb] ? -bottomHalf[rb] : (v > bottomHalf[rb] ? bottomHalf[rb] : v);
        for (int k = 0; k < 3; k++)
            q[k] = centre[k] + u * tb[ra][k] + v * tb[rb][k];
        /* Height of the incident face above q, along up. */
        MeVector3 cq;
        MeVector3Subtract(cq, ci, q);
        MeReal height = MeVector3Dot(m, cq) / MeVector3Dot(m, up);
        MdtContactSetParams(c, params);
        MdtContactSetPosition(c, q[0] + height * up[0] / 2, q[1] + height * up[1] / 2, q[2] + height * up[2] / 2);
        MdtContactSetNormal(c, up[0], up[1], up[2]); /* bottom (body 1) towards top (body 0) */
        MdtContactSetPenetration(c, -height);
    }
    return 1;
}
