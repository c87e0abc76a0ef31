/*
  rolling.c -- balls sliding on a plane with friction begin to roll (after Karma 1.2's tutorials
  on the bridge and materials).

  Balls of several sizes are thrown along a ground plane (y up) without spin, through an
  MstUniverse. Friction slows their sliding and spins them up until they roll without slipping;
  for a solid ball the rolling speed is then 5/7 of the throw, whatever the friction. Checked:
  each ball ends rolling (speed = spin x radius) at 5/7 of its throw, on the ground, not through it.
*/
#include <math.h>
#include <Mst.h>
#include "compat_check.h"

#define NBALLS 3
#define THROW 4

int MEAPI_CDECL main(int argc, const char **argv)
{
    MstUniverse *u;
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    McdGeometryID planeGeom, ballGeom[NBALLS];
    McdModelID plane, ball[NBALLS];
    MdtContactParamsID params;
    MeMatrix4 groundTM = { {1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1} };
    MeReal radius[NBALLS] = { (MeReal)0.25, (MeReal)0.5, 1 };
    MeReal step = (MeReal)0.005, lowest = 1;
    int i, n;

    (void)argc;
    (void)argv;

    sizes.dynamicBodiesMaxCount = NBALLS;
    u = MstUniverseCreate(&sizes);
    MdtWorldSetGravity(u->world, 0, -(MeReal)9.8, 0);
    MdtWorldSetAutoDisable(u->world, 0);

    params = MstBridgeGetContactParams(u->bridge, MstBridgeGetDefaultMaterial(), MstBridgeGetDefaultMaterial());
    MdtContactParamsSetType(params, MdtContactTypeFriction2D);
    MdtContactParamsSetFriction(params, 2);
    MdtContactParamsSetRestitution(params, 0);

    planeGeom = McdPlaneCreate(u->frame);
    plane = MstFixedModelCreate(u, planeGeom, groundTM);
    for (i = 0; i < NBALLS; i++)
    {
        ballGeom[i] = McdSphereCreate(u->frame, radius[i]);
        ball[i] = MstModelAndBodyCreate(u, ballGeom[i], 1);
        McdModelDynamicsSetPosition(ball[i], 0, radius[i], (MeReal)(4 * i));
        McdModelDynamicsSetLinearVelocity(ball[i], THROW, 0, 0);
        McdModelDynamicsSetAngularVelocity(ball[i], 0, 0, 0);
    }

    for (n = 0; n < (int)(4 / step); n++)
    {
        MstUniverseStep(u, step);
        for (i = 0; i < NBALLS; i++)
        {
            MeVector3 p;
            McdModelDynamicsGetPosition(ball[i], p);
            if (p[1] - radius[i] < lowest)
                lowest = p[1] - radius[i];
        }
    }

    for (i = 0; i < NBALLS; i++)
    {
        char what[80];
        MeVector3 v, w, p;

        MdtBodyGetLinearVelocity(McdModelGetBody(ball[i]), v);
        MdtBodyGetAngularVelocity(McdModelGetBody(ball[i]), w);
        McdModelDynamicsGetPosition(ball[i], p);
        sprintf(what, "rolling speed of the %.2f m ball (m/s)", (double)radius[i]);
        compatNear(what, v[0], 5.0 * THROW / 7.0, 0.05);
        sprintf(what, "spin x radius of the %.2f m ball (m/s, rolling without slipping)", (double)radius[i]);
        compatNear(what, -w[2] * radius[i], v[0], 0.03);
        sprintf(what, "height of the %.2f m ball's centre (m)", (double)radius[i]);
        compatNear(what, p[1], radius[i], 0.02);
    }
    compatCheck(lowest > -(MeReal)0.02, "no ball sinks through the ground");

    McdFrameworkDestroyAllModelsAndGeometries(u->frame);
    MstUniverseDestroy(u);
    (void)plane;
    return compatExit("rolling");
}
