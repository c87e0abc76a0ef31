/* karma_pairs.c -- one model pair's contacts for the collision tests (see karma_pairs.h). */
#include "karma_test.h"
#include "karma_pairs.h"

McdFrameworkID karma_pairs_framework(int instances)
{
    McdFrameworkID fw = McdInit(0, 64, instances, 1);
    assert_non_null(fw);
    McdPrimitivesRegisterTypes(fw);
    McdPrimitivesRegisterInteractions(fw);
    return fw;
}

McdModelID karma_model_at(McdGeometryID g, MeMatrix4 tm, MeReal contactTolerance)
{
    McdModelID m = McdModelCreate(g);
    assert_non_null(m);
    McdModelSetContactTolerance(m, contactTolerance);
    MeMatrix4Copy(McdModelGetTransformPtr(m), tm);
    McdModelUpdate(m);
    return m;
}

int karma_intersect(McdModelID m1, McdModelID m2, McdRequest *request, McdContact *c, int max)
{
    McdModelPairID pair = McdModelPairCreate(m1, m2);
    McdIntersectResult r = {0};
    r.contacts = c;
    r.contactMaxCount = max;
    McdHello(pair);
    if (request)
        McdModelPairSetRequestPtr(pair, request);
    McdIntersect(pair, &r);
    McdGoodbye(pair);
    McdModelPairDestroy(pair);
    return r.contactCount;
}
