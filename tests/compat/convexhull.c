/*
  convexhull.c -- a convex mesh made from a McdConvexHull, as Karma 1.2 programs made them: the
  hull of a box's corners and some points inside is computed with McdComputeHull, walked with 1.2's
  loops over the face and vertex arrays, turned into a geometry by McdConvexMeshCreate and dropped on
  the ground through MstUniverse.

  Checked: the hull is the box (8 vertices, 6 faces, 24 directed edges, each face 4 edges closing a
  ring with the face on their left), the mesh gives the box's volume and the same 6 polygons, and
  the body comes to rest on its largest face at half the box's height, as a primitive box does.
*/
#include <math.h>
#include "Mst.h"
#include "McdQHullTypes.h"
#include "compat_check.h"

#define HX 1.0
#define HY 0.25
#define HZ 0.5

MstUniverseID universe;

/* The ground plane's transform: its normal (the plane's z) along world y. */
MeALIGNDATA(MeMatrix4, groundTM, 16) =
{
    {1, 0,  0, 0},
    {0, 0, -1, 0},
    {0, 1,  0, 0},
    {0, 0,  0, 1}
};

int MEAPI_CDECL main(int argc, const char *(argv[]))
{
    MstUniverseSizes sizes;
    McdFrameworkID framework;
    McdConvexHull hull;
    McdGeometryID planeGeom, convexGeom;
    McdModelID plane, model;
    const McdConvexHull *kept;
    MeVector3 points[12], pos;
    MeMatrix4 relTM;
    MeMatrix3 inertia;
    MeReal volume, step = (MeReal)0.01;
    int i, f, ringsClosed = 1, leftIsFace = 1, ok;

    (void)argc;
    (void)argv;

    for (i = 0; i < 8; i++)
    {
        points[i][0] = (MeReal)((i & 1) ? HX : -HX);
        points[i][1] = (MeReal)((i & 2) ? HY : -HY);
        points[i][2] = (MeReal)((i & 4) ? HZ : -HZ);
    }
    for (i = 8; i < 12; i++) /* inside: dropped */
    {
        points[i][0] = (MeReal)(0.1 * (i - 9));
        points[i][1] = (MeReal)0.05;
        points[i][2] = -(MeReal)0.1;
    }

    ok = McdComputeHull(&hull, 12, (const MeVector3 *)points);
    compatCheck(ok == 1, "McdComputeHull succeeds");
    compatCheck(hull.numVertex == 8 && hull.numFace == 6 && hull.numEdge == 24,
                "the hull is the box: 8 vertices, 6 faces, 24 directed edges");
    for (f = 0; f < hull.numFace; f++)
    {
        for (i = hull.face[f].firstEdge; i < hull.face[f + 1].firstEdge; ++i)
        {
            int next = i + 1 < hull.face[f + 1].firstEdge ? i + 1 : hull.face[f].firstEdge;
            if (hull.edge[i].toVert != hull.edge[next].fromVert)
                ringsClosed = 0;
            if (hull.edge[i].leftFace != f)
                leftIsFace = 0;
        }
        if (McdCnvFaceGetCount(&hull, f) != 4)
            ringsClosed = 0;
    }
    compatCheck(ringsClosed, "each face is a closed ring of 4 edges");
    compatCheck(leftIsFace, "each face's edges have it on their left");

    sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = 1;
    sizes.collisionModelsMaxCount = 2;
    universe = MstUniverseCreate(&sizes);
    framework = universe->frame;
    MdtWorldSetGravity(universe->world, 0, -(MeReal)9.8, 0);

    convexGeom = McdConvexMeshCreate(framework, &hull, 0);
    compatCheck(convexGeom != 0, "McdConvexMeshCreate takes the hull");
    kept = McdConvexMeshGetPolyhedron(convexGeom);
    compatCheck(kept != 0 && kept->edge == hull.edge, "the mesh keeps the hull's arrays (a shallow copy)");
    compatCheck(McdConvexMeshGetPolygonCount(convexGeom) == 6, "the mesh has the box's 6 polygons");
    McdGeometryGetMassProperties(convexGeom, relTM, inertia, &volume);
    compatNear("volume (m^3)", volume, 8 * HX * HY * HZ, 1e-5);

    planeGeom = McdPlaneCreate(framework);
    plane = MstFixedModelCreate(universe, planeGeom, groundTM);
    model = MstModelAndBodyCreate(universe, convexGeom, 1);
    McdModelDynamicsSetPosition(model, 0, 1, 0);
    for (i = 0; i < (int)(3 / step); i++)
        MstUniverseStep(universe, step);
    McdModelDynamicsGetPosition(model, pos);
    printf("ConvexHull: the body rests at (%g, %g, %g)\n", (double)pos[0], (double)pos[1], (double)pos[2]);
    compatNear("resting height of the box's centre (m)", pos[1], HY, 0.01);

    McdFrameworkDestroyAllModelsAndGeometries(framework);
    MstUniverseDestroy(universe);
    (void)plane;
    return compatExit("convexhull");
}
