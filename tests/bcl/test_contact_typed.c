/* Which contacts BCL hands Kea as typed contacts (KeaContact): a non-adhesive contact with two
 * friction directions bounded by the normal force, whatever its other options (softness, slip,
 * restitution, anisotropic coefficients, a surface or world velocity); every other contact
 * (adhesive, box friction, one or no friction direction) as generic rows only. Read from the step's
 * packed rows after MdtWorldStep. */
#include "karma_test.h"
#include "karma_contacts.h"

#include <karma/Mdt.h>

#include "mdt/world.h"

enum { KINDS = 7 };

/* Contact k's parameters: 0 plain, 1 with every option the typed contact takes, then the ones that
 * stay generic rows. */
static void paramsOfKind(int k, MdtContactParams *p)
{
    karma_contact_params_friction(p, ME_R(0.5));
    switch (k) {
    case 1:
        p->options = MdtBclContactOptionSoft | MdtBclContactOptionSlip1 | MdtBclContactOptionSlip2 |
                     MdtBclContactOptionBounce | MdtBclContactOptionSlide1 | MdtBclContactOptionUseWorldVelocity;
        p->softness = ME_R(1e-3);
        p->slip1 = p->slip2 = ME_R(1e-2);
        p->restitution = ME_R(0.5);
        p->slide1 = ME_R(0.2);
        p->frictioncoeff2 = ME_R(0.2); /* anisotropic */
        break;
    case 2:
        p->options = MdtBclContactOptionAdhesive;
        p->max_adhesive_force = ME_R(10.0);
        break;
    case 3:
        p->model2 = MdtFrictionModelBox;
        p->friction2 = ME_R(1.0);
        break;
    case 4:
        p->type = MdtContactTypeFriction1D;
        break;
    case 5:
        p->type = MdtContactTypeFrictionZero;
        break;
    default:
        break;
    }
}

static void only_plain_contacts_are_typed(void **state)
{
    static const int rowsOfKind[KINDS] = {3, 3, 3, 3, 2, 1, 3};
    MdtWorldID world = MdtWorldCreate(4, 16, 1, 1);
    MdtBodyID box = MdtBodyCreate(world);
    MdtContactGroupID group = MdtContactGroupCreate(world);
    const MdtWorldData *w;
    int k, row = 0, declared = 0;
    (void)state;
    MdtWorldSetGravity(world, 0, 0, ME_R(-9.81));
    MdtBodySetPosition(box, 0, 0, ME_R(0.5));
    MdtBodyEnable(box);
    MdtContactGroupSetBodies(group, box, NULL);
    for (k = 0; k < KINDS; ++k) {
        MdtContactID c = MdtContactGroupCreateContact(group);
        MdtContactParams p;
        assert_non_null(c);
        paramsOfKind(k, &p);
        MdtContactSetParams(c, &p);
        MdtContactSetPosition(c, ME_R(0.1) * (MeReal)k - ME_R(0.3), ME_R(0.5) * (MeReal)(k % 2) - ME_R(0.25), 0);
        MdtContactSetNormal(c, 0, 0, 1);
        MdtContactSetPenetration(c, ME_R(1e-3));
    }
    MdtContactGroupEnable(group);
    MdtWorldStep(world, (MeReal)(1.0 / 60));
    w = MdtWorldFromID(world, "test");
    assert_non_null(w);
    assert_int_equal(w->partitions.partitionCount, 1);
    assert_int_equal(w->rows.partitionContactStart[0], 0);
    for (k = 0; k < KINDS; ++k) { /* the group writes its contacts in order */
        const int typed = k == 0 || k == 1 || k == KINDS - 1;
        if (typed) {
            assert_true(declared < w->rows.partitionContactStart[1]);
            assert_int_equal(w->rows.contacts[declared].row, row);
            ++declared;
        }
        row += rowsOfKind[k];
    }
    assert_int_equal(row, w->rows.count);
    assert_int_equal(w->rows.partitionContactStart[1], declared);
    /* and the step solved them: the box rests (its speed is what gravity gives in a step, or less) */
    {
        MeVector3 v;
        MdtBodyGetLinearVelocity(box, v);
        assert_true(fabs((double)v[2]) < 9.81 / 60);
    }
    MdtWorldDestroy(world);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(only_plain_contacts_are_typed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
