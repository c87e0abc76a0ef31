/* mdt_scenes.h -- the dynamics benchmark scenes, defined once as engine-neutral data.
 *
 * These scenes measure the dynamics and the LCP solver alone, without collision detection: contacts
 * are made by hand from a list of "supports" (box A rests on box B, or on the ground), as an
 * application with its own collision system would make them. A scene is
 *   - boxes (half extents, mass, initial centre; identity orientation), the ground plane y = 0;
 *   - ball joints (two bodies or a body and the world, anchor in world coordinates at the start);
 *   - supports: for each, the engine refreshes four contacts every step on the overlap of the upper
 *     box's bottom face with the lower box's top face (or the ground), friction `friction`;
 *   - gravity, step, number of steps, and the quality figure the scene reports.
 * An engine (Karma here; ODE and Bullet peers later) builds its world from this data, steps it, and
 * hands the box poses back to BenchMdtQualityObserve/Finish, so every engine's figure is measured by
 * the same code. SI units, y up (docs/decisions.md K30; each scene is its first, z-up version with the
 * axes relabelled (x, y, z) -> (y, z, x), as bench/scenes), quaternions (w, x, y, z). Application
 * code: malloc and stdio allowed. */
#ifndef KARMA_BENCH_MDT_SCENES_H
#define KARMA_BENCH_MDT_SCENES_H

typedef struct BenchMdtBody {
    double half[3]; /**< box half extents (m) */
    double mass;    /**< kg */
    double pos[3];  /**< initial centre (m) */
} BenchMdtBody;

typedef struct BenchMdtJoint {
    int body[2];        /**< body[1] = -1: the world */
    double anchor[3];   /**< world anchor at the start (m) */
    double local[2][3]; /**< anchor in each body's frame (world point for the world), filled by the builder */
} BenchMdtJoint;

typedef struct BenchMdtSupport {
    int upper, lower; /**< lower = -1: the ground */
} BenchMdtSupport;

typedef enum BenchMdtQuality {
    BENCH_MDT_Q_JOINT_GAP,  /**< largest anchor separation of any joint over the run (m) */
    BENCH_MDT_Q_TOP_DRIFT,  /**< displacement of the last (top) box at the end (m) */
    BENCH_MDT_Q_MAX_DRIFT   /**< largest displacement of any box at the end (m) */
} BenchMdtQuality;

typedef struct BenchMdtScene {
    char name[32];
    char description[160];
    int bodyCount;
    BenchMdtBody *bodies;
    int jointCount;
    BenchMdtJoint *joints;
    int supportCount;
    BenchMdtSupport *supports;
    double gravity[3];
    double step;      /**< s */
    double friction;  /**< Coulomb coefficient of every contact */
    int steps;        /**< steps of a full run */
    BenchMdtQuality quality;
    const char *qualityName;
} BenchMdtScene;

/** `links` boxes of 0.1 m x 0.1 m x 1 m (1 kg) on ball joints, laid along +z from a world anchor at
 *  the origin, falling from horizontal; no ground; 600 steps. Figure: the largest joint gap. */
BenchMdtScene *BenchMdtSceneChain(int links);
/** `boxes` unit boxes (1 kg) stacked on the ground; 1200 steps (20 s). Figure: top box drift. */
BenchMdtScene *BenchMdtSceneColumn(int boxes);
/** A running-bond wall along z of `wide` x `high` bricks 0.5 m x 0.5 m x 1 m (1 kg), odd rows shifted by
 *  0.25 m, each brick supported by the one or two below; 600 steps. Figure: the largest brick drift. */
BenchMdtScene *BenchMdtSceneWall(int wide, int high);
/** The standard scenes by name: "chain" (100 links), "column" (20), "wall" (20 x 10 = 200 bricks);
 *  NULL for another name. */
BenchMdtScene *BenchMdtSceneCreate(const char *name);
void BenchMdtSceneDestroy(BenchMdtScene *scene);

/** The standard scenes, in the order of the results table. */
#define BENCH_MDT_SCENES "chain,column,wall"

/** Quality tracking: Observe after every step with the poses of all bodies, Finish at the end. */
typedef struct BenchMdtQualityState {
    double value;  /**< the figure; NaN when a pose became non-finite */
    int nonFinite;
} BenchMdtQualityState;
void BenchMdtQualityInit(const BenchMdtScene *scene, BenchMdtQualityState *q);
void BenchMdtQualityObserve(const BenchMdtScene *scene, BenchMdtQualityState *q, const double (*pos)[3],
                            const double (*quat)[4]);
void BenchMdtQualityFinish(const BenchMdtScene *scene, BenchMdtQualityState *q, const double (*pos)[3],
                           const double (*quat)[4]);

#endif
