/* bench_scenes.h -- the benchmark scenes of issue 5, each defined once as engine-neutral data.
 *
 * A BenchScene is a list of bodies (box, sphere or capsule; mass; initial pose; static or dynamic),
 * a list of joints (ball or hinge with axis and limits), an optional ground plane, gravity, the step,
 * the friction coefficient, the number of steps to run and the quality figure the scene reports.
 * Every engine (Karma, ODE, Bullet) builds its own world from the same data, steps it, and hands the
 * body poses back to BenchQualityObserve/Finish, so the quality figures are measured by one piece of
 * code for all engines.
 *
 * Conventions: SI units; y is up (gravity (0, -9.81, 0), docs/decisions.md K30); quaternions
 * (w, x, y, z) rotate local to world; a capsule's axis is its local z (Karma's sphyl, ODE's capsule
 * and Bullet's btCapsuleShapeZ alike), so a standing capsule is turned by -90 degrees about x; box sizes
 * are half-extents along the box's x, y and z here (Karma's McdBoxCreate takes full edge lengths:
 * double them). The ground, when present, is the plane y = 0 with normal +y (Karma's plane, whose normal is
 * its local +z, is turned by -90 degrees about x). See bench/scenes/README.md for the scenes and why
 * each figure is what it is.
 *
 * Plain C11 application code: not part of libkarma, free to use malloc and stdio. Numbers are double
 * throughout; an engine in single precision converts at its boundary. */
#ifndef KARMA_BENCH_SCENES_H
#define KARMA_BENCH_SCENES_H

#ifdef __cplusplus
extern "C" {
#endif

/** Shapes. Sizes in BenchBody.size: box = half-extents (x, y, z); sphere = radius in size[0];
 *  capsule = radius in size[0] and half-length of the cylinder part (caps excluded) in size[1],
 *  along local z (turned onto world y for a standing capsule). */
typedef enum BenchShape { BENCH_BOX, BENCH_SPHERE, BENCH_CAPSULE } BenchShape;

typedef struct BenchBody {
    BenchShape shape;
    double size[3];  /**< see BenchShape (m) */
    double mass;     /**< kg, uniform density; ignored for fixed bodies */
    double pos[3];   /**< initial position of the centre of mass (m) */
    double quat[4];  /**< initial orientation (w, x, y, z), unit */
    int fixed;       /**< 1: static geometry (walls) that never moves; 0: dynamic */
    double vel[3];   /**< initial linear velocity (m/s); zero in every scene but b2smash */
} BenchBody;

typedef enum BenchJointType { BENCH_BALL, BENCH_HINGE } BenchJointType;

/** A joint between body[0] and body[1]; body[1] = -1 joins body[0] to the world. Anchor and axis are
 *  given in world coordinates at the initial pose (as ODE and Karma set them); local[] holds the
 *  anchor in each body's frame (for body[1] = -1, local[1] is the world point), which is what the
 *  joint error is measured from. Hinge limits bound the angle of body[1] relative to body[0] about
 *  `axis` (right-hand rule, radians), zero at the initial pose; for body[1] = -1 the angle is that
 *  of the world relative to body[0]. */
typedef struct BenchJoint {
    BenchJointType type;
    int body[2];
    double anchor[3];   /**< world anchor at the initial pose (m) */
    double axis[3];     /**< hinge: unit axis in world coordinates at the initial pose */
    int limited;        /**< hinge: 1 when lo/hi apply */
    double lo, hi;      /**< hinge limits (rad), lo <= 0 <= hi */
    double local[2][3]; /**< anchor in body[0]'s and body[1]'s frame (filled by the builders) */
    int motor;          /**< hinge: 1 when a velocity motor drives it */
    double motorSpeed;  /**< rad/s: the angular velocity about `axis` the motor drives body[0] to, relative
                             to body[1] (the world for -1) */
    double motorTorque; /**< N m: the motor's largest torque */
} BenchJoint;

/** What a scene measures, and how (BenchQualityFinish). */
typedef enum BenchQualityKind {
    BENCH_Q_MAX_DRIFT,        /**< largest displacement of any dynamic body at the end (m) */
    BENCH_Q_TOP_DISPLACEMENT, /**< displacement of the last (top) body at the end (m) */
    BENCH_Q_JOINT_ERROR,      /**< largest anchor separation of any joint over the run (m) */
    BENCH_Q_ESCAPED,          /**< dynamic bodies outside the container at the end (count); bodies
                                   jointed to the world (a tumbler's walls, a spinner's bar) do not count */
    BENCH_Q_COM_DRIFT         /**< no gravity, no ground: distance of the centre of mass at the end from the
                                   straight line it must follow (momentum conservation; m) */
} BenchQualityKind;

typedef struct BenchScene {
    char name[32];           /**< e.g. "pyramid20"; what --scene= takes */
    char description[160];   /**< one sentence */
    int bodyCount;           /**< all bodies, fixed ones included */
    int dynamicCount;        /**< dynamic bodies only (the "bodies" column of the results) */
    BenchBody *bodies;
    int jointCount;
    BenchJoint *joints;
    int hasGround;           /**< 1: static plane y = 0, normal +y */
    double gravity[3];       /**< m/s² (0, -9.81, 0) */
    double step;             /**< s (1/60) */
    double friction;         /**< Coulomb μ of every contact (0.6); restitution is 0 */
    int steps;               /**< steps of a full run */
    BenchQualityKind quality;
    const char *qualityName; /**< column label: "max_drift_m", "top_disp_m", "joint_err_m", "escaped" */
    double fallDistance;     /**< m: "fallen" once any dynamic body ends this far from where it started;
                                  < 0 when the scene gives no standing verdict */
    double container[2][3];  /**< BENCH_Q_ESCAPED: inner box (min, max) a body's centre must stay in */
} BenchScene;

/** The six scenes of issue 5, in the order of the results table. */
#define BENCH_STANDARD_SCENES "pyramid20,pyramid40,pile,chain,ragdolls,column"

/** The scene set of others' making (issue 17): 3-D versions of Box2D v3's benchmark scenes and of
 *  Jolt's performance scenes, all touching where bodies rest (bench/scenes/README.md). */
#define BENCH_OTHERS_SCENES \
    "b2pyramid,b2pyramids,b2jointgrid,b2rain,b2smash,b2spinner,b2tumbler,joltpyramid,joltragdolls"

/** Gravity, step and friction shared by every scene (Jolt's scenes: Jolt's default friction 0.2;
 *  b2spinner: Box2D's 0.1). */
#define BENCH_GRAVITY_Y  (-9.81)
#define BENCH_STEP       (1.0 / 60.0)
#define BENCH_FRICTION   0.6
/** A stack has fallen when some box ends half an edge (0.5 m) or more from where it started: it is
 *  then half off its support (sideways) or has dropped off it. A stack that only creeps, sinks or
 *  leans less than that is standing; how much it moved is the scene's figure. */
#define BENCH_FALL_DISTANCE 0.5

/* Builders. Each returns a new scene (free with BenchSceneDestroy), or NULL when out of memory or
 * when a parameter is out of range (counts < 1). */
/** 2-D pyramid one box deep: `base` unit boxes (1 kg) in the bottom row, one fewer in each row above
 *  (base 20: 210 boxes; base 40: 820), 0.05 m gaps between neighbours; 600 steps (10 s). */
BenchScene *BenchScenePyramid(int base);
/** `spheres` balls (radius 0.5 m) and `boxes` unit boxes, 1 kg each, dropped from a jittered grid
 *  into a 16 m × 16 m walled box on the ground; 600 steps. */
BenchScene *BenchScenePile(int spheres, int boxes);
/** `links` capsules (radius 0.1 m, 1 m tip to tip, 1 kg) on ball joints, laid horizontally along +z,
 *  the first joined to the world at the origin; no ground; 600 steps. */
BenchScene *BenchSceneChain(int links);
/** The same chain with its fixed end 60 m above the ground: its free 40 m land and lie on it. */
BenchScene *BenchSceneChainFloor(int links);
/** `count` ragdolls of 11 bodies (58 kg) on 5 ball and 5 limited hinge joints, on a 3 m grid, each
 *  tilted and turned differently, dropped from 0.5 m onto the ground; 600 steps. */
BenchScene *BenchSceneRagdolls(int count);
/** `boxes` unit boxes (1 kg) stacked exactly on top of each other; 1200 steps (20 s). */
BenchScene *BenchSceneColumn(int boxes);
/** `boxes` boxes of random sizes dropped at random onto the open ground: a heap that settles (sleeping). */
BenchScene *BenchSceneHeap(int boxes);

/* The scene set of others' making (issue 17; sources and mappings in bench/scenes/README.md). */
/** Box2D's large pyramid: touching unit boxes (1 kg), `base` at the bottom, one deep (x), rows along z. */
BenchScene *BenchSceneB2Pyramid(int base);
/** Box2D's many pyramids: `count` touching pyramids of base 10 on a grid on the ground. */
BenchScene *BenchSceneB2Pyramids(int count);
/** Box2D's joint grid: `side` × `side` spheres (r 0.4 m) in the y-z plane on hinges about x, 1 m apart,
 *  seven of the top row hinged to the world; no ground. */
BenchScene *BenchSceneB2JointGrid(int side);
/** Box2D's rain: `count` ragdolls in columns of five, dropped from 0.5 m to 40.5 m. */
BenchScene *BenchSceneB2Rain(int count);
/** Box2D's smash: without gravity, an 8 m box at 40 m/s into a touching block of `columns` × 12 × 3
 *  boxes of 0.4 m. */
BenchScene *BenchSceneB2Smash(int columns);
/** Box2D's spinner: about `count` capsules, spheres and boxes in a static ring with a motorised bar. */
BenchScene *BenchSceneB2Spinner(int count);
/** Box2D's tumbler: `side` × `side` × 4 boxes of 0.25 m in a drum of six walls on motorised hinges. */
BenchScene *BenchSceneB2Tumbler(int side);
/** Jolt's pyramid: `height` layers of touching 2 m boxes (8,000 kg), layer i (height - i)², brick bond. */
BenchScene *BenchSceneJoltPyramid(int height);
/** Jolt's ragdolls: `count` ragdolls lying in piles of ten, 0.6 m apart, piles 4 m apart. */
BenchScene *BenchSceneJoltRagdolls(int count);

/** A scene by name: pyramid<N>, pile[<N>] (N spheres and N boxes, default 500), chain[<N>] (default
 *  100), ragdolls[<N>] (default 100), column[<N>] (default 20), and the set of others' making: b2pyramid[<base>] (40),
 *  b2pyramids[<count>] (12), b2jointgrid[<side>] (20), b2rain[<count>] (45), b2smash[<columns>] (12),
 *  b2spinner[<count>] (450), b2tumbler[<side>] (10), joltpyramid[<height>] (10), joltragdolls[<count>]
 *  (40). NULL for an unknown name. */
BenchScene *BenchSceneCreate(const char *name);
void BenchSceneDestroy(BenchScene *scene);

/* Geometry helpers the engines share. */
/** out = q ⊗ p (Hamilton product, w first). */
void BenchQuatMultiply(double out[4], const double q[4], const double p[4]);
/** out = q v q* (local → world for a body with orientation q). */
void BenchQuatRotate(double out[3], const double q[4], const double v[3]);
/** out = q* v q (world → local). */
void BenchQuatRotateInverse(double out[3], const double q[4], const double v[3]);
/** The unit quaternion turning by `angle` radians about the unit `axis`. */
void BenchQuatFromAxisAngle(double out[4], const double axis[3], double angle);

/** Principal moments of inertia (kg m², about the centre of mass, along the body's local axes) of the
 *  body as a uniform solid of its mass: every engine uses these, so all have the same mass properties
 *  (Bullet's own capsule inertia, for one, approximates the capsule by its bounding box). */
void BenchBodyInertia(const BenchBody *body, double inertia[3]);

/** The quality tracker: observe after every step, finish at the end. */
typedef struct BenchQuality {
    double value;     /**< the scene's figure (m or count); NaN when the state became non-finite */
    int standing;     /**< 1 standing, 0 fallen, -1 no verdict (scene has none, or run incomplete) */
    double maxDisplacement; /**< largest displacement of a dynamic body at the end (m) */
    double maxJointError;    /**< largest joint gap seen in any observed step (m) */
    double meanJointError;   /**< mean over the observed steps of that step's largest gap (m) */
    double sumJointError;    /**< running sum for meanJointError */
    double floorPenetration; /**< deepest point of any dynamic body below y = 0 at the end (m, >= 0) */
    int nonFinite;    /**< 1 when some observed pose was NaN or infinite */
    int observed;     /**< steps observed */
} BenchQuality;

void BenchQualityInit(const BenchScene *scene, BenchQuality *quality);
/** Poses of all bodyCount bodies after a step (fixed bodies may hold their initial pose). */
void BenchQualityObserve(const BenchScene *scene, BenchQuality *quality, const double (*pos)[3],
                         const double (*quat)[4]);
/** Final figure from the last poses. `complete` = 0 when the run stopped early: no verdict then. */
void BenchQualityFinish(const BenchScene *scene, BenchQuality *quality, const double (*pos)[3],
                        const double (*quat)[4], int complete);

/** Largest separation over the joints of the scene for the given poses (m). */
double BenchJointError(const BenchScene *scene, const double (*pos)[3], const double (*quat)[4]);

#ifdef __cplusplus
}
#endif

#endif
