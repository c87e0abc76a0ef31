/* ball_hits_wall.c -- a heavy ball shot at a wall of bricks on the ground. */
#include <stdlib.h>

#include "demo.h"

#define ROWS 5
#define COLUMNS 6
#define BRICK_X ME_R(0.6) /* length */
#define BRICK_Y ME_R(0.3) /* height (y is up) */
#define BRICK_Z ME_R(0.3) /* depth */

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 50; /* typical body mass, kg: the world's softness scales with it */
    sizes.dynamicConstraintsMaxCount = 1000;
    sizes.collisionPairsMaxCount = 1000;
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    McdGeometryID brick = McdBoxCreate(fw, BRICK_X, BRICK_Y, BRICK_Z);
    for (int r = 0; r < ROWS; r++)
        for (int c = 0; c < COLUMNS; c++) {
            MeReal x = ((MeReal)c - (COLUMNS - 1) / ME_R(2.0) + (r % 2 ? ME_R(0.25) : 0)) * BRICK_X;
            if (!DemoAddModel(demo, brick, 600, x, BRICK_Y / 2 + (MeReal)r * BRICK_Y, 0))
                return MEFALSE;
        }
    McdModelID ball = DemoAddModel(demo, McdSphereCreate(fw, ME_R(0.3)), 3000, 0, ME_R(0.6), 6);
    if (!ball)
        return MEFALSE;
    demo->named[0] = McdModelGetBody(ball);
    demo->names[0] = "ball";
    demo->namedCount = 1;
    MdtBodySetLinearVelocity(demo->named[0], 0, ME_R(1.5), -15); /* at the wall (-z), a little upwards */
    return METRUE;
}

static void report(const DemoInstance *demo, FILE *out)
{
    MeVector3 p;
    MdtBodyGetPosition(demo->named[0], p);
    fprintf(out, "  ball ended at x %.2f, height y %.2f, z %.2f; %d of %d bodies still awake\n", (double)p[0], (double)p[1],
            (double)p[2], MdtWorldGetEnabledBodies(demo->world), MdtWorldGetTotalBodies(demo->world));
}

const DemoScene DemoSceneBallHitsWall = {"ballhitswall", "a heavy ball shot at a wall of bricks", 300,
                                         ME_R(1.0) / 60, create, NULL, NULL, report};
