/* karma_ground.c -- the bridge tests' scene: a universe with gravity along -z and a ground plane. */
#include "karma_test.h"

#include "karma_ground.h"

void karma_ground_init(KarmaGround *s, MeReal massScale)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = massScale;
    s->u = MstUniverseCreate(&sizes);
    assert_non_null(s->u);
    s->w = MstUniverseGetWorld(s->u);
    s->b = MstUniverseGetBridge(s->u);
    s->fw = MstUniverseGetFramework(s->u);
    MdtWorldSetGravity(s->w, 0, 0, -9.81f);
    MeMatrix4TMMakeIdentity(s->groundTM);
    s->ground = MstFixedModelCreate(s->u, McdPlaneCreate(s->fw), s->groundTM);
    assert_non_null(s->ground);
}
