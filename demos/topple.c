/* topple.c -- Karma's benchmark scene: six stacks of three to six blocks on the ground, and balls
 * shot at them. The report says which stacks stood until the first ball and which fell after. */
#include <stdlib.h>

#include "demo.h"

#define STACKS 6
#define BLOCK_X ME_R(0.4)
#define BLOCK_Y ME_R(0.6) /* height (y is up) */
#define BLOCK_Z ME_R(0.4)
#define SHOT_TIME ME_R(2.0)     /* first ball at 2 s, then one each second */
#define SHOT_SPEED ME_R(12.0)
#define BALLS 4

typedef struct Topple {
    MdtBodyID blocks[STACKS][6];
    int height[STACKS];
    MeVector3 start[STACKS][6];
    MeReal driftBeforeShot;
    McdModelID balls[BALLS];
    int shot;
} Topple;

static MeBool create(DemoInstance *demo)
{
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.massScale = 50; /* typical body mass, kg: the world's softness scales with it */
    sizes.dynamicConstraintsMaxCount = 1000;
    sizes.collisionPairsMaxCount = 1000;
    if (!DemoUniverseCreate(demo, &sizes, ME_R(9.81), ME_R(0.6)))
        return MEFALSE;
    Topple *s = calloc(1, sizeof *s);
    demo->data = s;
    McdFrameworkID fw = MstUniverseGetFramework(demo->universe);
    McdGeometryID block = McdBoxCreate(fw, BLOCK_X, BLOCK_Y, BLOCK_Z);
    for (int k = 0; k < STACKS; k++) {
        s->height[k] = 3 + k % 4;
        MeReal x = (MeReal)(k - (STACKS - 1) / 2.0) * ME_R(1.2);
        for (int i = 0; i < s->height[k]; i++) {
            MeReal y = BLOCK_Y / 2 + (MeReal)i * BLOCK_Y;
            McdModelID m = DemoAddModel(demo, block, 500, x, y, 0);
            if (!m)
                return MEFALSE;
            s->blocks[k][i] = McdModelGetBody(m);
            MeVector3Set(s->start[k][i], x, y, 0);
        }
    }
    McdGeometryID ball = McdSphereCreate(fw, ME_R(0.2));
    for (int i = 0; i < BALLS; i++) {
        s->balls[i] = DemoAddModel(demo, ball, 2000, (MeReal)(i * 2 - 3), ME_R(0.2), 10 + (MeReal)i);
        if (!s->balls[i])
            return MEFALSE;
        MdtBodyDisable(McdModelGetBody(s->balls[i]));
    }
    demo->named[0] = s->blocks[0][0];
    demo->names[0] = "block";
    demo->namedCount = 1;
    return METRUE;
}

static MeReal stackDrift(const Topple *s)
{
    MeReal worst = 0;
    for (int k = 0; k < STACKS; k++)
        for (int i = 0; i < s->height[k]; i++) {
            MeVector3 p;
            MdtBodyGetPosition(s->blocks[k][i], p);
            MeReal d = MeVector3Distance(p, s->start[k][i]);
            if (d > worst)
                worst = d;
        }
    return worst;
}

static void beforeStep(DemoInstance *demo, MeReal h)
{
    (void)h;
    Topple *s = demo->data;
    if (s->shot < BALLS && demo->time >= SHOT_TIME + (MeReal)s->shot) {
        if (s->shot == 0)
            s->driftBeforeShot = stackDrift(s);
        /* Aim along -z at one stack's middle block, from 6 m in front of it. */
        MdtBodyID b = McdModelGetBody(s->balls[s->shot]);
        int target = (s->shot * 2 + 1) % STACKS;
        MeVector3 aim;
        MdtBodyGetPosition(s->blocks[target][1], aim);
        MdtBodySetPosition(b, aim[0], aim[1], aim[2] + 6);
        MdtBodyEnable(b);
        MdtBodySetLinearVelocity(b, 0, ME_R(1.5), -SHOT_SPEED);
        s->shot++;
    }
}

static void report(const DemoInstance *demo, FILE *out)
{
    const Topple *s = demo->data;
    fprintf(out, "  stacks: %d (heights 3-6), largest block drift before the first shot %.4f m\n", STACKS,
            (double)s->driftBeforeShot);
    int fallen = 0;
    for (int k = 0; k < STACKS; k++) {
        MeVector3 p;
        MdtBodyGetPosition(s->blocks[k][s->height[k] - 1], p);
        if (p[1] < s->start[k][s->height[k] - 1][1] - BLOCK_Y / 2)
            fallen++;
    }
    fprintf(out, "  balls shot: %d; stacks whose top block fell: %d of %d\n", s->shot, fallen, STACKS);
}

const DemoScene DemoSceneTopple = {"topple", "six stacks of three to six blocks; balls are shot at them", 600,
                                   ME_R(1.0) / 60, create, beforeStep, NULL, report};
