/* karma_partitions.c -- a universe whose step has many partitions (karma_partitions.h). */
#include "karma_partitions.h"
#include "karma_test.h"

MstUniverseID karma_partitions_scene(int stacks, int boxes, int chains, int links)
{
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* normal +y */
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = (unsigned int)(stacks * boxes + chains * links);
    sizes.collisionModelsMaxCount = (unsigned int)(stacks * boxes + 1);
    sizes.dynamicConstraintsMaxCount = (unsigned int)(20 * stacks * boxes + chains * links + 16);
    sizes.collisionPairsMaxCount = (unsigned int)(10 * stacks * boxes + 16);
    MstUniverseID u = MstUniverseCreate(&sizes);
    if (!u)
        return NULL;
    MdtWorldID w = MstUniverseGetWorld(u);
    MdtWorldSetGravity(w, 0, ME_R(-9.81), 0);
    MdtWorldSetAutoDisable(w, MEFALSE); /* every partition awake, every step */
    McdFrameworkID fw = MstUniverseGetFramework(u);
    if (!MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM))
        return NULL;
    McdGeometryID box = McdBoxCreate(fw, ME_R(0.5), ME_R(0.5), ME_R(0.5));
    for (int s = 0; s < stacks; s++)
        for (int k = 0; k < boxes; k++) {
            McdModelID m = MstModelAndBodyCreate(u, box, ME_R(1.0));
            if (!m)
                return NULL;
            /* a little offset per level, so the stacks lean and slide */
            MdtBodySetPosition(McdModelGetBody(m), ME_R(2.0) * (MeReal)s + ME_R(0.08) * (MeReal)k,
                               ME_R(0.3) + ME_R(0.55) * (MeReal)k, ME_R(0.04) * (MeReal)(s % 3));
        }
    for (int c = 0; c < chains; c++) {
        MdtBodyID previous = NULL;
        for (int k = 0; k < links; k++) {
            MdtBodyID b = MdtBodyCreate(w);
            MdtBSJointID j = MdtBSJointCreate(w);
            if (!b || !j)
                return NULL;
            MeReal z = ME_R(4.0) + ME_R(2.0) * (MeReal)c;
            MdtBodySetPosition(b, ME_R(0.4) * (MeReal)(k + 1), ME_R(5.0), z);
            MdtBodyEnable(b);
            MdtBSJointSetBodies(j, b, previous);
            MdtBSJointSetPosition(j, ME_R(0.4) * (MeReal)k, ME_R(5.0), z);
            MdtConstraintEnable(MdtBSJointQuaConstraint(j));
            previous = b;
        }
    }
    return u;
}

uint64_t karma_partitions_step_hash(MstUniverseID u, int steps, uint64_t hash)
{
    for (int i = 0; i < steps; i++) {
        MstUniverseStep(u, ME_R(1.0) / 60);
        hash = karma_hash_world(hash, MstUniverseGetWorld(u));
    }
    return hash;
}
