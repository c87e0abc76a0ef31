/* demo.h -- the scene registry shared by the karma tool, the viewer, tests and benchmarks.
 *
 * A scene is described once, by a DemoScene: its name (what `karma run NAME` takes), a sentence
 * saying what it shows, a default step count and step size, a function that builds it and optional
 * hooks run before every step and after the run. Running a scene yields a DemoInstance: the world
 * (later also the collision space and the universe joining them), a few named bodies for reports,
 * and scene-private data.
 *
 * Everything here is application code built on the public API only: it is not part of libkarma and
 * may use the C library freely (malloc, stdio). */
#ifndef KARMA_DEMO_H
#define KARMA_DEMO_H

#include <stdio.h>

#include <karma/karma.h>

/** How many bodies a scene may name for reports (other bodies are reported by index). */
#define DEMO_MAX_NAMED_BODIES 16

typedef struct DemoScene DemoScene;

/** A running scene. */
typedef struct DemoInstance {
    const DemoScene *scene;
    MdtWorldID world;      /**< the dynamics world the scene built */
    MstUniverseID universe; /**< the universe holding it, for scenes with collision (else NULL) */
    int namedCount;
    MdtBodyID named[DEMO_MAX_NAMED_BODIES];
    const char *names[DEMO_MAX_NAMED_BODIES];
    void *data;            /**< scene-private state, freed by DemoDestroy */
    unsigned long steps;   /**< steps taken by DemoStep */
    MeReal time;           /**< simulated seconds */
} DemoInstance;

struct DemoScene {
    const char *name;        /**< one lowercase word: what `karma run` takes */
    const char *description; /**< one sentence: what the scene shows */
    int defaultSteps;        /**< steps of a default run */
    MeReal defaultStepSize;  /**< seconds per step */
    /** Build the scene into `demo` (world already NULL, data NULL). Returns MEFALSE on failure. */
    MeBool (*create)(DemoInstance *demo);
    /** Called before each step with the step size (forces, fast-spin axes, scripted events); may be NULL. */
    void (*beforeStep)(DemoInstance *demo, MeReal stepSize);
    /** Called after each step (to record what the report needs); may be NULL. */
    void (*afterStep)(DemoInstance *demo, MeReal stepSize);
    /** Print what the scene measured, one indented line per fact; may be NULL. */
    void (*report)(const DemoInstance *demo, FILE *out);
};

/** The scene `make demo` runs. */
#define DEMO_DEFAULT_SCENE "topple"

/** Number of scenes in the registry, and the scene at `index` (NULL when out of range). Order is fixed: new scenes are appended. */
int DemoSceneCount(void);
const DemoScene *DemoSceneAt(int index);
/** The scene called `name`, or NULL. */
const DemoScene *DemoSceneFind(const char *name);

/** Build `scene` into `demo`. Returns MEFALSE (and leaves `demo` empty) when the scene fails. */
MeBool DemoCreate(const DemoScene *scene, DemoInstance *demo);
/** Make the scene's universe (and set demo->world to its world) with `sizes`, gravity (0, −g, 0) (y is up) and,
 *  when groundFriction ≥ 0, a ground plane y = 0 (frictionless at 0; above 0 the default material pair
 *  gets 2D friction with that NormalForce coefficient). Returns MEFALSE when the universe cannot be made. */
MeBool DemoUniverseCreate(DemoInstance *demo, const MstUniverseSizes *sizes, MeReal g, MeReal groundFriction);
/** A model with an enabled body at (x, y, z) in the demo's universe (density in kg/m³); NULL on failure. */
McdModelID DemoAddModel(DemoInstance *demo, McdGeometryID geometry, MeReal density, MeReal x, MeReal y, MeReal z);

/** No contacts between models a and b (jointed neighbours), inside or outside a change block. */
void DemoDisablePair(DemoInstance *demo, McdModelID a, McdModelID b);

/** One step of `stepSize` seconds: beforeStep hook, MstUniverseStep (or MdtWorldStep for scenes
 *  without collision), afterStep hook. */
void DemoStep(DemoInstance *demo, MeReal stepSize);
/** Destroy the world and free the scene data. */
void DemoDestroy(DemoInstance *demo);

/** Create a body (disabled, like every new body) and remember its name for reports (a literal).
 *  Returns NULL when the world's pool is full. */
MdtBodyID DemoAddNamedBody(DemoInstance *demo, const char *name);
/** The name given to `body`, or NULL. */
const char *DemoBodyName(const DemoInstance *demo, MdtBodyID body);
/** The body called `name`, or NULL. */
MdtBodyID DemoFindBody(const DemoInstance *demo, const char *name);

/** Angular momentum of `body` about its centre of mass, world frame (kg·m²/s): I_w ω with the
 *  inertia the integrator uses (the full tensor only when non-spherical inertia is enabled). */
void DemoBodyAngularMomentum(MdtBodyID body, MeVector3 L);

#endif /* KARMA_DEMO_H */
