/*
  topple.c -- a stack of boxes knocked over by balls, through MstUniverse and the bridge (after
  Karma 1.2's Topple example).

  A universe is made from Karma's default sizes, changed where the scene needs more; a ground
  plane (y up) is a fixed model, a column of unit boxes stands on it and balls are models with
  bodies. The stack is left to settle, then two balls are thrown at it. Checked: the stack stands
  still on its own, the balls knock it down, and no box or ball sinks through the ground.
*/
#include <math.h>
#include "Mst.h"
#include "compat_check.h"

#define NBoxes 5
#define NBalls 2
#define BallRadius 0.5

MstUniverseID universe;
McdFrameworkID framework;
McdModelID box[NBoxes];
McdModelID ball[NBalls];
MeReal lowest = 10;

/* The ground plane's transform: its normal (the plane's z) along world y. */
MeALIGNDATA(MeMatrix4, groundTM, 16) =
{
    {1, 0,  0, 0},
    {0, 0, -1, 0},
    {0, 1,  0, 0},
    {0, 0,  0, 1}
};

void MEAPI tick(MeReal step)
{
    int i;

    MeProfileStartSection("Universe", 0);
    MstUniverseStep(universe, step);
    MeProfileEndSection("Universe");
    for (i = 0; i < NBoxes; i++)
    {
        MeVector3 p;
        McdModelDynamicsGetPosition(box[i], p);
        if (p[1] - (MeReal)0.5 < lowest)
            lowest = p[1] - (MeReal)0.5;
    }
    for (i = 0; i < NBalls; i++)
    {
        MeVector3 p;
        McdModelDynamicsGetPosition(ball[i], p);
        if (p[1] - (MeReal)BallRadius < lowest)
            lowest = p[1] - (MeReal)BallRadius;
    }
}

void MEAPI shoot(int i)
{
    McdModelDynamicsReset(ball[i]);
    McdModelDynamicsSetPosition(ball[i], -6, (MeReal)(1.5 + i), 0);
    McdModelDynamicsSetLinearVelocity(ball[i], 15, 0, 0);
    McdModelDynamicsEnable(ball[i]);
}

int MEAPI_CDECL main(int argc, const char *(argv[]))
{
    MstUniverseSizes sizes;
    MdtWorldID world;
    MstBridgeID bridge;
    McdGeometryID planeGeom, boxGeom, ballGeom;
    McdModelID plane;
    MdtBclContactParams *p;
    MeReal step = (MeReal)0.01, moved = 0, fallen = 0;
    MeVector3 pos;
    int i;

    (void)argc;
    (void)argv;

    sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = NBoxes + NBalls;
    sizes.dynamicConstraintsMaxCount = 300;
    sizes.materialsMaxCount = 2;
    sizes.collisionModelsMaxCount = NBoxes + NBalls + 1;
    sizes.collisionPairsMaxCount = 100;
    universe = MstUniverseCreate(&sizes);
    world = universe->world;
    framework = universe->frame;
    bridge = universe->bridge;
    compatCheck(universe->space == MstUniverseGetSpace(universe), "the universe's space field is its space");

    MdtWorldSetGravity(world, 0, -(MeReal)9.8, 0);

    planeGeom = McdPlaneCreate(framework);
    plane = MstFixedModelCreate(universe, planeGeom, groundTM);

    boxGeom = McdBoxCreate(framework, 1, 1, 1);
    for (i = 0; i < NBoxes; i++)
    {
        box[i] = MstModelAndBodyCreate(universe, boxGeom, 1);
        McdModelDynamicsSetPosition(box[i], 0, (MeReal)(0.5 + i), 0);
        McdModelDynamicsSetDamping(box[i], (MeReal)0.2, (MeReal)0.1);
    }
    ballGeom = McdSphereCreate(framework, BallRadius);
    for (i = 0; i < NBalls; i++)
    {
        ball[i] = MstModelAndBodyCreate(universe, ballGeom, (MeReal)1.5);
        McdModelDynamicsSetPosition(ball[i], -20, BallRadius, (MeReal)(5 * i));
        McdModelDynamicsDisable(ball[i]);
    }

    p = MstBridgeGetContactParams(bridge, MstBridgeGetDefaultMaterial(), MstBridgeGetDefaultMaterial());
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFriction(p, 5);
    MdtContactParamsSetRestitution(p, (MeReal)0.3);

    for (i = 0; i < (int)(2 / step); i++)
        tick(step);
    for (i = 0; i < NBoxes; i++)
    {
        McdModelDynamicsGetPosition(box[i], pos);
        moved += MeFabs(pos[0]) + MeFabs(pos[1] - (MeReal)(0.5 + i)) + MeFabs(pos[2]);
    }
    compatNear("how far the stack's boxes moved while standing (m, summed)", moved, 0, 0.1);

    shoot(0);
    shoot(1);
    for (i = 0; i < (int)(4 / step); i++)
        tick(step);
    for (i = 0; i < NBoxes; i++)
    {
        McdModelDynamicsGetPosition(box[i], pos);
        if (MeFabs(pos[0]) + MeFabs(pos[2]) > fallen)
            fallen = MeFabs(pos[0]) + MeFabs(pos[2]);
    }
    McdModelDynamicsGetPosition(box[NBoxes - 1], pos);
    printf("Topple: the farthest box is %g m from the column; the top box is at height %g m\n",
           (double)fallen, (double)pos[1]);
    compatCheck(fallen > 1, "the balls knock the stack over (a box ends more than 1 m from the column)");
    compatCheck(pos[1] < NBoxes - (MeReal)1.5, "the top box has come down");
    compatCheck(lowest > -(MeReal)0.1, "no box or ball sinks through the ground");

    McdFrameworkDestroyAllModelsAndGeometries(framework);
    MstUniverseDestroy(universe);
    (void)plane;
    return compatExit("topple");
}
