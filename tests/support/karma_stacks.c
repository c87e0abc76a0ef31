/* karma_stacks.c -- scenes of bodies resting on a ground plane (see karma_stacks.h). */
#include "karma_test.h"
#include "karma_stacks.h"

#include <stdlib.h>

#include <karma/karma.h>

void karma_stack_init(KarmaStack *s, const MstUniverseSizes *sizes, MeReal mu, int max)
{
    s->u = MstUniverseCreate(sizes);
    assert_non_null(s->u);
    MdtWorldID w = MstUniverseGetWorld(s->u);
    MdtWorldSetGravity(w, 0, 0, ME_R(-9.81));
    MdtWorldSetAutoDisable(w, MEFALSE);
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    assert_non_null(MstFixedModelCreate(s->u, McdPlaneCreate(MstUniverseGetFramework(s->u)), groundTM));
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(s->u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, mu);
    s->count = 0;
    s->max = max;
    s->bodies = calloc((size_t)max, sizeof *s->bodies);
    s->start = calloc((size_t)max, sizeof *s->start);
    assert_non_null(s->bodies);
    assert_non_null(s->start);
}

MdtBodyID karma_stack_add(KarmaStack *s, McdGeometryID g, MeReal density, MeReal x, MeReal y, MeReal z)
{
    assert_true(s->count < s->max);
    assert_non_null(g);
    McdModelID m = MstModelAndBodyCreate(s->u, g, density);
    assert_non_null(m);
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetPosition(b, x, y, z);
    s->bodies[s->count] = b;
    MeVector3Set(s->start[s->count], x, y, z);
    s->count++;
    return b;
}

void karma_stack_free(KarmaStack *s)
{
    MstUniverseDestroy(s->u);
    free(s->bodies);
    free(s->start);
    s->bodies = NULL;
    s->start = NULL;
    s->count = s->max = 0;
}
