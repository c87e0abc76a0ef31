/* soak.c -- a long random run through MstUniverse (issue 15, point 6; tests/README.md).
 *
 *     karma_soak [--seconds S] [--seed N]
 *
 * Spheres and boxes of a few sizes are dropped onto a ground plane; each step, at random (a seeded
 * generator, so a run is repeatable), bodies and their models are created and destroyed, and hinges
 * and ball joints are created between neighbours (or to the world) and destroyed. The run lasts
 * about S seconds of wall time (default: SOAK_SECONDS from the environment, else 10), half of it
 * for a first run and the same number of steps for a second run from the same seed, and checks:
 *  - messages: a handler counts every code; anything at warning level or above fails the soak
 *    (information such as scratch-chunk growth is expected and listed);
 *  - memory: MeMemoryGetStats' live blocks are flat: after a warm-up (a fifth of the steps) they
 *    never exceed the warm-up's high mark, and once every body is destroyed they are back where
 *    they were after the warm-up; the body and constraint pools' high-water marks stay within
 *    their sizes;
 *  - speed: no body is ever over the world's speed or angular speed limit, and no runaway report
 *    (MdtWorldCounters.speedWarnings, energyWarnings) is made;
 *  - determinism: both runs end with the same hash of every body's pose and velocity (and of every
 *    step's).
 * Exit status 0 when all hold; a line per failure otherwise. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <karma/karma.h>

#include "karma_test.h"

#define MAX_BODIES 160
#define MAX_JOINTS 120
#define STEP ME_R(1.0 / 60.0)
#define ARENA ME_R(12.0)   /* bodies are dropped within ±ARENA in x and y */
#define BOUND ME_R(40.0)   /* and destroyed when they leave ±BOUND (or fall through) */

/* ---- a seeded generator (splitmix64): the scene is a function of the seed alone -------------- */
static uint64_t rngState;
static uint64_t rngNext(void)
{
    uint64_t z = (rngState += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static double rngUniform(void) { return (double)(rngNext() >> 11) * (1.0 / 9007199254740992.0); }
static MeReal rngRange(double lo, double hi) { return (MeReal)(lo + (hi - lo) * rngUniform()); }
static int rngInt(int n) { return (int)(rngUniform() * n); }

/* ---- messages -------------------------------------------------------------------------------- */
typedef struct MessageLog {
    unsigned long count[1000];
    unsigned long unexpected;
    char first[512]; /* the first unexpected message */
} MessageLog;

static void countMessage(const MeMessageInfo *info, void *user)
{
    MessageLog *log = user;
    if (info->code >= 0 && info->code < 1000)
        log->count[info->code]++;
    if (info->level >= ME_LEVEL_WARNING) {
        if (log->unexpected++ == 0)
            snprintf(log->first, sizeof log->first, "code %d in %s: %s", (int)info->code, info->function, info->text);
    }
}

/* ---- the scene ------------------------------------------------------------------------------- */
typedef struct Joint {
    MdtConstraintID id;
    McdModelID a, b; /* b NULL: to the world */
} Joint;

typedef struct Scene {
    MstUniverseID u;
    MdtWorldID w;
    McdGeometryID shapes[6];
    McdModelID models[MAX_BODIES];
    int modelCount;
    Joint joints[MAX_JOINTS];
    int jointCount;
    unsigned long created, destroyed, jointsCreated, jointsDestroyed;
} Scene;

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

static void sceneInit(Scene *s)
{
    memset(s, 0, sizeof *s);
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = MAX_BODIES;
    sizes.collisionModelsMaxCount = MAX_BODIES + 1;
    sizes.dynamicConstraintsMaxCount = MAX_JOINTS + 8 * MAX_BODIES;
    sizes.collisionPairsMaxCount = 8 * MAX_BODIES;
    sizes.collisionGeometryInstancesMaxCount = 16;
    sizes.massScale = ME_R(50.0); /* the bodies weigh 2 to 200 kg: a typical mass, so no ME_ERR_MASS_SCALE */
    s->u = MstUniverseCreate(&sizes);
    s->w = MstUniverseGetWorld(s->u);
    MdtWorldSetGravity(s->w, 0, 0, ME_R(-9.81));
    McdFrameworkID fw = MstUniverseGetFramework(s->u);
    MstFixedModelCreate(s->u, McdPlaneCreate(fw), groundTM);
    for (int i = 0; i < 3; i++) {
        MeReal r = ME_R(0.25) + ME_R(0.15) * (MeReal)i;
        s->shapes[i] = McdSphereCreate(fw, r);
        s->shapes[3 + i] = McdBoxCreate(fw, 2 * r, ME_R(1.5) * r, r);
    }
    MdtContactParamsID p = MstBridgeGetContactParams(MstUniverseGetBridge(s->u), 0, 0);
    MdtContactParamsSetType(p, MdtContactTypeFriction2D);
    MdtContactParamsSetFrictionCoeffecient(p, ME_R(0.5));
}

static void centre(McdModelID m, MeVector3 p) { MdtBodyGetPosition(McdModelGetBody(m), p); }

/* A body dropped from 6 to 14 m at a spot at least 2 m from every other body (else none). */
static void createBody(Scene *s)
{
    if (s->modelCount >= MAX_BODIES - 1)
        return;
    MeVector3 at = {rngRange(-ARENA, ARENA), rngRange(-ARENA, ARENA), rngRange(6, 14)};
    int shape = rngInt(6);
    MeVector3 v = {rngRange(-2, 2), rngRange(-2, 2), rngRange(-2, 0)};
    MeReal spin[3] = {rngRange(-3, 3), rngRange(-3, 3), rngRange(-3, 3)};
    for (int i = 0; i < s->modelCount; i++) {
        MeVector3 p;
        centre(s->models[i], p);
        if (MeVector3Distance(p, at) < 2)
            return;
    }
    McdModelID m = MstModelAndBodyCreate(s->u, s->shapes[shape], ME_R(500.0) + ME_R(500.0) * (MeReal)(shape % 3));
    if (!m)
        return;
    MdtBodyID b = McdModelGetBody(m);
    MdtBodySetPosition(b, at[0], at[1], at[2]);
    MdtBodySetLinearVelocity(b, v[0], v[1], v[2]);
    MdtBodySetAngularVelocity(b, spin[0], spin[1], spin[2]);
    s->models[s->modelCount++] = m;
    s->created++;
}

/* Forget the joints of model m: destroying a body destroys its constraints (as in Karma). */
static void forgetJoints(Scene *s, McdModelID m)
{
    for (int j = 0; j < s->jointCount;) {
        if (s->joints[j].a == m || s->joints[j].b == m)
            s->joints[j] = s->joints[--s->jointCount];
        else
            j++;
    }
}

static void destroyModel(Scene *s, int i)
{
    McdModelID m = s->models[i];
    forgetJoints(s, m);
    MstModelAndBodyDestroy(m);
    s->models[i] = s->models[--s->modelCount];
    s->destroyed++;
}

/* A hinge or a ball joint at the midpoint of a body and its nearest neighbour within 2.5 m, or at
 * the body's centre to the world when it has none (anchors consistent: the joint starts satisfied). */
static void createJoint(Scene *s)
{
    if (s->modelCount == 0 || s->jointCount >= MAX_JOINTS)
        return;
    McdModelID a = s->models[rngInt(s->modelCount)], b = NULL;
    MeVector3 pa, pb, at;
    centre(a, pa);
    MeReal best = ME_R(2.5);
    for (int i = 0; i < s->modelCount; i++) {
        if (s->models[i] == a)
            continue;
        MeVector3 p;
        centre(s->models[i], p);
        MeReal d = MeVector3Distance(p, pa);
        if (d < best) {
            best = d;
            b = s->models[i];
        }
    }
    if (b) {
        centre(b, pb);
        MeVector3Set(at, (pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2);
    } else {
        MeVector3Copy(at, pa);
    }
    MdtBodyID ba = McdModelGetBody(a), bb = b ? McdModelGetBody(b) : NULL;
    MdtConstraintID c;
    if (rngUniform() < 0.5) {
        MdtHingeID h = MdtHingeCreate(s->w);
        if (!h)
            return;
        MdtHingeSetBodies(h, ba, bb);
        MdtHingeSetPosition(h, at[0], at[1], at[2]);
        MdtHingeSetAxis(h, rngRange(-1, 1), rngRange(-1, 1), 1);
        c = MdtHingeQuaConstraint(h);
    } else {
        MdtBSJointID j = MdtBSJointCreate(s->w);
        if (!j)
            return;
        MdtBSJointSetBodies(j, ba, bb);
        MdtBSJointSetPosition(j, at[0], at[1], at[2]);
        c = MdtBSJointQuaConstraint(j);
    }
    MdtConstraintEnable(c);
    s->joints[s->jointCount++] = (Joint){c, a, b};
    s->jointsCreated++;
}

static void destroyJoint(Scene *s)
{
    if (s->jointCount == 0)
        return;
    int j = rngInt(s->jointCount);
    MdtConstraintDestroy(s->joints[j].id);
    s->joints[j] = s->joints[--s->jointCount];
    s->jointsDestroyed++;
}

/* One step of churn: create and destroy at random, cull what left the arena, then step. */
static void churn(Scene *s)
{
    double r = rngUniform();
    if (r < 0.30)
        createBody(s);
    else if (r < 0.45 && s->modelCount > 20)
        destroyModel(s, rngInt(s->modelCount));
    else if (r < 0.60)
        createJoint(s);
    else if (r < 0.70)
        destroyJoint(s);
    for (int i = 0; i < s->modelCount;) {
        MeVector3 p;
        centre(s->models[i], p);
        if (fabs((double)p[0]) > BOUND || fabs((double)p[1]) > BOUND || p[2] < -5)
            destroyModel(s, i);
        else
            i++;
    }
    MstUniverseStep(s->u, STEP);
}

/* ---- checks ---------------------------------------------------------------------------------- */
typedef struct RunResult {
    unsigned long steps;
    uint64_t hash;          /* all bodies, every step */
    unsigned long liveAfterWarmup, liveMaxAfterWarmup, liveAtWarmupEmpty, liveAtEndEmpty;
    double fastest, fastestSpin;
    unsigned long overLimit;
    MdtWorldCounters counters;
    unsigned long created, destroyed, jointsCreated, jointsDestroyed;
} RunResult;

static unsigned long liveBlocks(void)
{
    MeMemoryStats m;
    MeMemoryGetStats(&m);
    return m.liveBlocks;
}

/* Destroy every body and joint (the universe and its shapes stay). */
static void emptyScene(Scene *s)
{
    while (s->modelCount > 0)
        destroyModel(s, s->modelCount - 1);
}

/* Run `steps` steps (or, with steps 0, until `seconds` of wall time have passed). */
static RunResult run(uint64_t seed, unsigned long steps, double seconds)
{
    RunResult r;
    memset(&r, 0, sizeof r);
    rngState = seed;
    Scene s;
    sceneInit(&s);
    r.hash = KARMA_HASH_INIT;
    clock_t start = clock();
    unsigned long warmup = steps ? steps / 5 : 0;
    for (unsigned long n = 0; steps ? n < steps : (double)(clock() - start) < seconds * CLOCKS_PER_SEC; n++) {
        churn(&s);
        r.hash = karma_hash_world(r.hash, s.w);
        for (MdtBodyID b = MdtBodyGetFirst(s.w); b; b = MdtBodyGetNext(b)) {
            MeVector3 v, om;
            MdtBodyGetLinearVelocity(b, v);
            MdtBodyGetAngularVelocity(b, om);
            double speed = MeVector3Magnitude(v), spin = MeVector3Magnitude(om);
            r.fastest = fmax(r.fastest, speed);
            r.fastestSpin = fmax(r.fastestSpin, spin);
            if (!(speed <= MdtWorldGetSpeedLimit(s.w)) || !(spin <= MdtWorldGetAngularSpeedLimit(s.w)))
                r.overLimit++;
        }
        if (warmup && n + 1 == warmup)
            r.liveAfterWarmup = r.liveMaxAfterWarmup = liveBlocks();
        else if (warmup && n + 1 > warmup && liveBlocks() > r.liveMaxAfterWarmup)
            r.liveMaxAfterWarmup = liveBlocks();
        r.steps = n + 1;
    }
    MdtWorldGetCounters(s.w, &r.counters);
    r.created = s.created;
    r.destroyed = s.destroyed;
    r.jointsCreated = s.jointsCreated;
    r.jointsDestroyed = s.jointsDestroyed;
    /* Empty the scene, step once (contacts and chunks settle), and count what is still allocated. */
    emptyScene(&s);
    MstUniverseStep(s.u, STEP);
    r.liveAtEndEmpty = liveBlocks();
    MstUniverseDestroy(s.u);
    return r;
}

/* The live-block count of an emptied scene after `steps` steps (the memory reference). */
static unsigned long emptyAfter(uint64_t seed, unsigned long steps)
{
    return run(seed, steps, 0).liveAtEndEmpty;
}

int main(int argc, char **argv)
{
    double seconds = getenv("SOAK_SECONDS") ? atof(getenv("SOAK_SECONDS")) : 10;
    uint64_t seed = 15;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--seconds") && i + 1 < argc)
            seconds = atof(argv[++i]);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 0);
        else {
            fprintf(stderr, "usage: %s [--seconds S] [--seed N]\n", argv[0]);
            return 2;
        }
    }
    if (!(seconds > 0)) {
        fprintf(stderr, "--seconds must be positive\n");
        return 2;
    }
    MessageLog log;
    memset(&log, 0, sizeof log);
    MeSetMessageHandler(countMessage, &log, NULL);

    /* First run: as many steps as half the time allows (measured), then the same steps again. */
    RunResult timed = run(seed, 0, seconds / 2);
    RunResult a = run(seed, timed.steps, 0);
    RunResult b = run(seed, timed.steps, 0);
    /* The memory reference: the same scene stopped after its warm-up and emptied. */
    unsigned long emptyWarm = emptyAfter(seed, timed.steps / 5);

    int failures = 0;
#define CHECK(cond, ...)                                                                             \
    do {                                                                                             \
        if (!(cond)) {                                                                               \
            failures++;                                                                              \
            printf("soak FAILED: " __VA_ARGS__);                                                     \
            printf("\n");                                                                            \
        }                                                                                            \
    } while (0)

    printf("soak: seed %llu, %lu steps of %.4f s (%.1f simulated s) per run, 3 runs\n", (unsigned long long)seed,
           a.steps, (double)STEP, a.steps * (double)STEP);
    printf("soak: %lu bodies and models created, %lu destroyed; %lu joints created, %lu destroyed by hand\n",
           a.created, a.destroyed, a.jointsCreated, a.jointsDestroyed);
    printf("soak: body pool high water %d of %d, constraint pool %d of %d\n", a.counters.bodyPoolHighWater,
           MAX_BODIES, a.counters.constraintPoolHighWater, MAX_JOINTS + 8 * MAX_BODIES);
    printf("soak: fastest body %.2f m/s, fastest spin %.2f rad/s; runaway reports: %lu speed, %lu energy\n",
           a.fastest, a.fastestSpin, a.counters.speedWarnings, a.counters.energyWarnings);
    printf("soak: live memory blocks after warm-up %lu, highest after it %lu; emptied after warm-up %lu, "
           "emptied at the end %lu\n",
           a.liveAfterWarmup, a.liveMaxAfterWarmup, emptyWarm, a.liveAtEndEmpty);
    printf("soak: hash run 1 0x%016llx, run 2 0x%016llx\n", (unsigned long long)a.hash, (unsigned long long)b.hash);
    printf("soak: messages by code:");
    for (int c = 0; c < 1000; c++)
        if (log.count[c])
            printf(" %d (%s) x%lu", c, MeErrorCodeName((MeErrorCode)c), log.count[c]);
    printf("\n");

    CHECK(log.unexpected == 0, "%lu messages at warning level or above; the first: %s", log.unexpected, log.first);
    CHECK(a.hash == b.hash, "two runs from the same seed differ");
    CHECK(a.overLimit == 0 && a.counters.speedWarnings == 0, "bodies over the speed limits (%lu times)",
          a.overLimit);
    CHECK(a.counters.energyWarnings == 0, "%lu energy jumps", a.counters.energyWarnings);
    CHECK(a.liveMaxAfterWarmup <= a.liveAfterWarmup, "live memory blocks grew after the warm-up (%lu to %lu)",
          a.liveAfterWarmup, a.liveMaxAfterWarmup);
    CHECK(a.liveAtEndEmpty == emptyWarm, "an emptied scene holds %lu blocks at the end, %lu after the warm-up",
          a.liveAtEndEmpty, emptyWarm);
    CHECK(a.counters.bodyPoolHighWater <= MAX_BODIES, "body pool high water over its size");
    CHECK(a.created > 10 && a.destroyed > 10 && a.jointsCreated > 10, "the churn did too little");
    printf(failures ? "soak: %d check(s) failed\n" : "soak: passed\n", failures);
    return failures ? 1 : 0;
}
