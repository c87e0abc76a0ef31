/* karma_contacts.c -- hand-made contacts for dynamics tests, as an application with its own
 * collision system would make them: a box resting on a plane or on another box, four corner contacts
 * in a persistent contact group (refreshed in the same order every step, so warm starting works). */
#include "karma_contacts.h"

#include <karma/MdtContactGroup.h>
#include <karma/Mdt.h>

#include "karma_test.h"

void karma_contact_params_friction(MdtContactParams *p, MeReal mu)
{
    MdtContactParamsReset(p);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, mu);
}

/* Make the group hold exactly n contacts (reusing the existing ones first). */
static void ensureContacts(MdtContactGroupID g, int n)
{
    while (MdtContactGroupGetCount(g) < n)
        assert_non_null(MdtContactGroupCreateContact(g));
}

void karma_box_on_plane(MdtContactGroupID g, MdtBodyID box, const MeVector3 halfExtents, const MeVector3 up,
                        MeReal planeOffset, const MdtContactParams *params)
{
    ensureContacts(g, 4);
    MeMatrix4Ptr tm = MdtBodyGetTransformPtr(box);
    /* The box's bottom face: the local axis most opposed to `up`. */
    int axis = 0;
    MeReal best = 0;
    for (int k = 0; k < 3; k++) {
        MeReal d = MeVector3Dot(tm[k], up);
        if (MeFabs(d) > MeFabs(best)) {
            best = d;
            axis = k;
        }
    }
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
        MdtContactSetNormal(c, -up[0], -up[1], -up[2]); /* body 0 (box) → body 1 (world) */
        MdtContactSetPenetration(c, -height);
    }
}

void karma_box_on_box(MdtContactGroupID g, MdtBodyID top, MdtBodyID bottom, const MeVector3 halfExtents,
                      const MdtContactParams *params)
{
    ensureContacts(g, 4);
    MeMatrix4Ptr tt = MdtBodyGetTransformPtr(top), tb = MdtBodyGetTransformPtr(bottom);
    /* Reference face: the bottom box's face whose normal is most aligned with the direction to the top box. */
    MeVector3 d = {tt[3][0] - tb[3][0], tt[3][1] - tb[3][1], tt[3][2] - tb[3][2]};
    int axis = 0;
    MeReal best = 0;
    for (int k = 0; k < 3; k++) {
        MeReal v = MeVector3Dot(tb[k], d) / halfExtents[k];
        if (MeFabs(v) > MeFabs(best)) {
            best = v;
            axis = k;
        }
    }
    MeVector3 up;
    MeVector3MultiplyScalar(up, tb[axis], best > 0 ? 1 : -1);
    MeReal faceOffset = MeVector3Dot(tb[3], up) + halfExtents[axis];
    MeVector3 down;
    MeVector3MultiplyScalar(down, up, -1);
    /* Incident face: the top box's face most opposed to `up`; its four corners. */
    int ia = 0;
    MeReal ib = 0;
    for (int k = 0; k < 3; k++) {
        MeReal v = MeVector3Dot(tt[k], up);
        if (MeFabs(v) > MeFabs(ib)) {
            ib = v;
            ia = k;
        }
    }
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
        MdtContactSetNormal(c, down[0], down[1], down[2]); /* body 0 (top) → body 1 (bottom) */
        MdtContactSetPenetration(c, -height);
    }
}
