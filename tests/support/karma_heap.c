/* karma_heap.c -- test_heap_sleep's heap of jittered boxes dropped onto the ground. */
#include "karma_heap.h"

#include <math.h>

#define EDGE_JITTER 0.1 /* box edges 0.9 to 1.1 m */

static double uniform(unsigned long long *state) /* [-1, 1) */
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / 4503599627370496.0 - 1.0;
}

/* A rotation drawn uniformly: a point of the unit 4-ball (by rejection), normalised. Only arithmetic and
 * sqrt, which IEEE rounds exactly: libm's sin and cos may differ in the last bit between machines (glibc
 * picks its code by CPU), and a heap is chaotic enough for that bit to decide which box creeps. */
static void randomRotation(unsigned long long *state, double q[4])
{
    double n2;
    do {
        for (int k = 0; k < 4; k++)
            q[k] = uniform(state);
        n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    } while (n2 > 1.0 || n2 < 1e-6);
    const double len = sqrt(n2);
    for (int k = 0; k < 4; k++)
        q[k] /= len;
}

MstUniverseID karma_heap_build(int n, unsigned long long seed, MdtBodyID *body)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 1;
    sizes.dynamicBodiesMaxCount = n;
    sizes.collisionModelsMaxCount = n + 1;
    sizes.collisionPairsMaxCount = 10 * n;
    sizes.dynamicConstraintsMaxCount = 30 * n;
    MstUniverseID u = MstUniverseCreate(&sizes);
    if (!u)
        return NULL;
    MdtWorldSetGravity(MstUniverseGetWorld(u), 0, 0, ME_R(-9.81));
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    McdFrameworkID fw = MstUniverseGetFramework(u);
    MstFixedModelCreate(u, McdPlaneCreate(fw), groundTM);
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionModel(p, MdtFrictionModelNormalForce);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.6));
    unsigned long long rng = seed;
    for (int i = 0; i < n; i++) {
        const int layer = i / 16, j = i % 16;
        const MeReal x = (MeReal)(((j % 4) - 1.5) * 1.6 + 0.1 * uniform(&rng));
        const MeReal y = (MeReal)(((j / 4) - 1.5) * 1.6 + 0.1 * uniform(&rng));
        double q[4];
        randomRotation(&rng, q);
        const MeReal edge[3] = {(MeReal)(1.0 + EDGE_JITTER * uniform(&rng)), (MeReal)(1.0 + EDGE_JITTER * uniform(&rng)),
                                (MeReal)(1.0 + EDGE_JITTER * uniform(&rng))};
        McdModelID m = MstModelAndBodyCreate(u, McdBoxCreate(fw, edge[0], edge[1], edge[2]), 1);
        body[i] = McdModelGetBody(m);
        MdtBodySetPosition(body[i], x, y, (MeReal)(1.0 + 1.6 * layer));
        MdtBodySetQuaternion(body[i], (MeReal)q[0], (MeReal)q[1], (MeReal)q[2], (MeReal)q[3]);
    }
    return u;
}
