/* convex_scenes.h -- issue 18 point 6: convex hulls and static terrain, the same scenes for Karma and
 * its peers (Bullet's btConvexHullShape, btBvhTriangleMeshShape, btHeightfieldTerrainShape).
 *
 * Engine-neutral data only: hull point clouds, bodies (shape, size, pose, mass, inertia), the floor
 * (a ground plane z = 0, a 100k-triangle mesh or a 512 x 512 height field of the same wavy heights) and
 * the poses of the pair test. These scenes are z-up (gravity (0, 0, -9.81)): Mcd's height field and
 * Bullet's (up axis 2) are then used as they come. Each driver builds its world from this data, steps
 * it, and hands the poses back to CvxRun, which times the steps (process CPU time) and measures the
 * floor penetration by the same code for every engine. */
#ifndef CONVEX_SCENES_H
#define CONVEX_SCENES_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { CVX_BOX, CVX_SPHERE, CVX_CAPSULE, CVX_HULL } CvxShape;
typedef enum { CVX_GROUND, CVX_MESH, CVX_FIELD } CvxFloor;

typedef struct CvxHull {
    int count;
    double (*p)[3]; /* points around the body's origin (its centre of mass by convention), m */
} CvxHull;

typedef struct CvxBody {
    CvxShape shape;
    double size[3];    /* box: half extents; sphere: radius; capsule: radius, half-length of the core (along z) */
    int hull;          /* CVX_HULL: index into scene->hulls */
    double pos[3];
    double quat[4];    /* w, x, y, z */
    double mass;       /* kg */
    double inertia[3]; /* principal moments about the origin, kg m^2 (the same in every engine) */
} CvxBody;

typedef struct CvxScene {
    const char *name;
    const char *what;
    CvxFloor floor;
    int bodyCount;
    CvxBody *bodies;
    int hullCount;
    CvxHull *hulls;
    /* CVX_MESH and CVX_FIELD: a grid of side x side vertices, spacing 1 m, vertex (i, j) at
     * (i, j, heights[j * side + i]); the mesh's triangles (a, b, c), (a, c, d) per cell split along
     * (i, j)-(i+1, j+1), as Mcd's and Bullet's (flipQuadEdges) height fields split theirs. */
    int side;
    double *heights;
    int triangleCount;
    int *indices;
    double step;     /* s */
    double gravity;  /* m/s^2, along -z */
    double friction;
    int steps;
} CvxScene;

/* Scenes: "pile" (1,000 hulls onto the ground), "mesh", "field" (1,000 mixed bodies onto terrain). */
CvxScene *CvxSceneCreate(const char *name);
void CvxSceneDestroy(CvxScene *s);
/* The floor's height under (x, y) (the piecewise-linear surface the engines collide with). */
double CvxFloorHeight(const CvxScene *s, double x, double y);
/* How deep body i is below the floor (m, >= 0), from sample points of its surface at the pose. */
double CvxBodyDepth(const CvxScene *s, int i, const double pos[3], const double quat[4]);

/* The pair test's poses: `count` pairs of hulls (of `hulls`, 64 clouds) at random relative poses,
 * about half of them touching. */
typedef struct CvxPairSet {
    int hullCount;
    CvxHull *hulls;
    int count;
    int (*hull)[2];
    double (*pos)[2][3];
    double (*quat)[2][4];
} CvxPairSet;
CvxPairSet *CvxPairSetCreate(int count);
void CvxPairSetDestroy(CvxPairSet *p);

/* One engine's world on a scene. */
typedef struct CvxEngine {
    const char *name;
    const char *settings;
    void *(*create)(const CvxScene *s);
    void (*step)(void *w);
    int (*contacts)(void *w);
    void (*read)(void *w, double (*pos)[3], double (*quat)[4]); /* every body's pose */
    void (*destroy)(void *w);
    /* the pair test: build once, run every pair `rounds` times, report contacts and touching pairs */
    void *(*pairsCreate)(const CvxPairSet *p);
    void (*pairsRun)(void *pw, int rounds, long *contacts, long *touching);
    void (*pairsDestroy)(void *pw);
} CvxEngine;

/* Row: engine, scene, bodies, steps, build ms, median and mean CPU ms per step, contacts per step,
 * floor penetration at the end (max, mean over bodies, mm), the largest over the run (sampled every
 * 10 steps, mm), bodies fallen through (centre 1 m below the floor), bodies not finite.
 * Command line: [pairs|pile|mesh|field ...] [--steps=N] [--from=K] [--seconds=S]. Prints one Markdown
 * row per scene. Under valgrind, callgrind's instrumentation is on only for steps K+1 ... N. */
int CvxMain(int argc, char **argv, const CvxEngine *engine);

#ifdef __cplusplus
}
#endif
#endif /* CONVEX_SCENES_H */
