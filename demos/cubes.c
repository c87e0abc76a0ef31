/* cubes.c -- many boxes: a 4 × 4 grid of columns of three cubes, dropped a little apart so that
 * they land on one another. */
#include <stdlib.h>

#include "demo.h"

#define GRID 4
#define LAYERS 3
#define SIZE ME_R(0.5)

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 125; /* typical body mass, kg: the world's softness scales with it */
    sizes.dynamicConstraintsMaxCount = 1000;
    sizes.collisionPairsMaxCount = 1000;
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    McdGeometryID cube = McdBoxCreate(MstUniverseGetFramework(demo->universe), SIZE, SIZE, SIZE);
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++)
            for (int k = 0; k < LAYERS; k++) {
                MeReal x = (MeReal)(i - 1.5) * ME_R(0.7), z = (MeReal)(j - 1.5) * ME_R(0.7);
                McdModelID m = DemoAddModel(demo, cube, 1000, x, SIZE / 2 + (MeReal)k * (SIZE + ME_R(0.05)), z);
                if (!m)
                    return MEFALSE;
                if (demo->namedCount == 0) {
                    demo->named[0] = McdModelGetBody(m);
                    demo->names[0] = "corner";
                    demo->namedCount = 1;
                }
            }
    return METRUE;
}

static void report(const DemoInstance *demo, FILE *out)
{
    fprintf(out, "  %d cubes, %d still awake\n", MdtWorldGetTotalBodies(demo->world),
            MdtWorldGetEnabledBodies(demo->world));
}

const DemoScene DemoSceneCubes = {"cubes", "48 cubes in 16 columns of three", 600, ME_R(1.0) / 60, create, NULL,
                                  NULL, report};
