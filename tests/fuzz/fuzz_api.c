/* fuzz_api.c -- libFuzzer harness for the public API of Mdt and Mst (issue 15, point 3).
 *
 * Each input is a program: a sequence of operations on one MstUniverse (ground plane, collision,
 * bridge) and its world, each operation a byte followed by its arguments read from the input. The
 * arguments are hostile by design: handles are live, destroyed (stale), NULL or arbitrary bits;
 * reals come from a palette of 0, ±1, tiny, huge, ±FLT_MAX, ±infinity and NaN, or from raw bits.
 * After every operation it checks the claims of docs/errors.md:
 *  - a call that reports a warning (the call was refused) changes no body's state (position,
 *    orientation, velocities, mass, forces, enabled flag: hashed before and after);
 *  - no body's state is ever NaN or infinite (the step's containment restores a failed partition);
 *  - nothing crashes, reads out of bounds or overflows (AddressSanitizer, UBSan).
 * The universe steps on a task system of three workers (MdtTaskSystem.h) that runs the ranges on
 * the calling thread, last first, so that every step goes through the threaded step's task.
 * A violated claim aborts, so libFuzzer keeps the input. Build: tests/fuzz/CMakeLists.txt (clang,
 * -fsanitize=fuzzer,address,undefined, `make fuzz`); seed inputs in tests/fuzz/corpus/fuzz_api/, replayed in
 * the suite by tests/cmake/fuzz_replay.cmake. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <karma/karma.h>

#define MAX_HANDLES 24

typedef struct Input {
    const uint8_t *data;
    size_t size, at;
} Input;

static uint8_t byte(Input *in) { return in->at < in->size ? in->data[in->at++] : 0; }

static uint32_t word(Input *in)
{
    uint32_t w = 0;
    for (int i = 0; i < 4; i++)
        w = w << 8 | byte(in);
    return w;
}

/* A real: mostly from a palette of the values that break arithmetic, sometimes raw bits. */
static MeReal real(Input *in)
{
    static const double palette[] = {0,     -0.0,   1,     -1,     0.5,   2,     10,       -10,
                                     1e-20, 1e-7,   1e-6,  1e-3,   1e3,   1e6,   1e19,     -1e19,
                                     1e30,  -1e30,  3.4e38, -3.4e38, 1.2e-38, 1e-40, (double)INFINITY, -(double)INFINITY,
                                     (double)NAN, 0.0167, 100, -0.5, 3.14159, 1e-10, 1e10, 7};
    uint8_t b = byte(in);
    if (b < 224)
        return (MeReal)palette[b % (sizeof palette / sizeof palette[0])];
    if (b < 240)
        return (MeReal)((int)byte(in) - 128) / 16; /* small, ordinary values */
    uint32_t bits = word(in);
    float f;
    memcpy(&f, &bits, sizeof f);
    return (MeReal)f;
}

typedef struct State {
    MstUniverseID u;
    MdtWorldID w;
    McdModelID models[MAX_HANDLES]; /* live or destroyed: both are used */
    int modelCount;
    MdtBodyID bodies[MAX_HANDLES];   /* bodies made with MdtBodyCreate (no model) */
    int bodyCount;
    MdtConstraintID constraints[MAX_HANDLES];
    int constraintCount;
    McdGeometryID shapes[4];
} State;

/* The API function an operation calls, and how many warnings were reported in its name: those mean
 * the call was refused. (A warning from inside a call that went ahead, e.g. a full pair pool while
 * MdtBodyEnable unfreezes a model, names the function that reported it, and is not a refusal.) */
static const char *api;
static unsigned long refusals;
/* Call fn with the arguments, under its name. */
#define CALL(fn, ...) (api = #fn, fn(__VA_ARGS__))
static void countRefusals(const MeMessageInfo *info, void *user)
{
    (void)user;
    /* ME_ERR_MASS_SCALE is advice about a mass that was set, not a refusal. */
    if (info->level >= ME_LEVEL_WARNING && info->code != ME_ERR_MASS_SCALE && api && info->function &&
        !strcmp(info->function, api))
        refusals++;
    if (getenv("FUZZ_API_VERBOSE"))
        fprintf(stderr, "fuzz_api: message %d in %s: %s\n", (int)info->code, info->function, info->text);
}

/* A body handle: a model's body, a plain body (either may be destroyed), NULL, or arbitrary bits. */
static MdtBodyID anyBody(State *s, Input *in)
{
    uint8_t b = byte(in);
    switch (b % 8) {
    case 0:
        return NULL;
    case 1: {
        uintptr_t bits = (uintptr_t)word(in) << 32 | word(in);
        return (MdtBodyID)bits;
    }
    case 2:
    case 3:
        return s->bodyCount ? s->bodies[byte(in) % s->bodyCount] : NULL;
    default:
        if (!s->modelCount)
            return NULL;
        McdModelID m = s->models[byte(in) % s->modelCount];
        return McdModelIsValid(m) ? McdModelGetBody(m) : NULL;
    }
}

static MdtConstraintID anyConstraint(State *s, Input *in)
{
    uint8_t b = byte(in);
    if (b % 6 == 0)
        return NULL;
    if (b % 6 == 1)
        return (MdtConstraintID)((uintptr_t)word(in) << 32 | word(in));
    return s->constraintCount ? s->constraints[byte(in) % s->constraintCount] : NULL;
}

static McdModelID anyModel(State *s, Input *in)
{
    uint8_t b = byte(in);
    if (b % 6 == 0)
        return NULL;
    if (b % 6 == 1)
        return (McdModelID)((uintptr_t)word(in) << 32 | word(in));
    return s->modelCount ? s->models[byte(in) % s->modelCount] : NULL;
}

/* FNV-1a over every body's state that a refused call must leave alone. */
static uint64_t hashBytes(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

static uint64_t worldHash(MdtWorldID w, MeBool *finite)
{
    uint64_t h = 1469598103934665603ull;
    *finite = METRUE;
    for (MdtBodyID b = MdtBodyGetFirst(w); b; b = MdtBodyGetNext(b)) {
        MeVector3 x, v, om, f, t;
        MeVector4 q;
        MdtBodyGetPosition(b, x);
        MdtBodyGetQuaternion(b, q);
        MdtBodyGetLinearVelocity(b, v);
        MdtBodyGetAngularVelocity(b, om);
        MdtBodyGetForce(b, f);
        MdtBodyGetTorque(b, t);
        MeReal m = MdtBodyGetMass(b);
        MeBool on = MdtBodyIsEnabled(b);
        for (int k = 0; k < 3; k++)
            *finite &= isfinite(x[k]) && isfinite(v[k]) && isfinite(om[k]);
        for (int k = 0; k < 4; k++)
            *finite &= isfinite(q[k]);
        *finite &= isfinite(m) && m > 0;
        h = hashBytes(h, x, sizeof x);
        h = hashBytes(h, q, sizeof q);
        h = hashBytes(h, v, sizeof v);
        h = hashBytes(h, om, sizeof om);
        h = hashBytes(h, f, sizeof f);
        h = hashBytes(h, t, sizeof t);
        h = hashBytes(h, &m, sizeof m);
        h = hashBytes(h, &on, sizeof on);
    }
    return h;
}

static void fail(const char *what, int op)
{
    fprintf(stderr, "fuzz_api: %s (operation %d)\n", what, op);
    abort();
}

static void addConstraint(State *s, MdtConstraintID c)
{
    if (!c)
        return;
    if (s->constraintCount < MAX_HANDLES)
        s->constraints[s->constraintCount++] = c;
    else
        s->constraints[s->constraintCount - 1] = c;
}

/* One operation; returns MEFALSE when it is a step (its reports do not mean "refused"). */
static MeBool operate(State *s, Input *in, int op)
{
    MdtWorldID w = s->w;
    switch (op) {
    case 0: { /* a body with a model */
        McdModelID m = CALL(MstModelAndBodyCreate, s->u, s->shapes[byte(in) % 4], real(in));
        if (m && s->modelCount < MAX_HANDLES)
            s->models[s->modelCount++] = m;
        return METRUE;
    }
    case 1:
        CALL(MstModelAndBodyDestroy, anyModel(s, in));
        return METRUE;
    case 2: {
        MdtBodyID b = CALL(MdtBodyCreate, w);
        if (b && s->bodyCount < MAX_HANDLES)
            s->bodies[s->bodyCount++] = b;
        CALL(MdtBodyEnable, b);
        return METRUE;
    }
    case 3:
        CALL(MdtBodyDestroy, anyBody(s, in));
        return METRUE;
    case 4:
        CALL(MdtBodySetPosition, anyBody(s, in), real(in), real(in), real(in));
        return METRUE;
    case 5:
        CALL(MdtBodySetLinearVelocity, anyBody(s, in), real(in), real(in), real(in));
        return METRUE;
    case 6:
        CALL(MdtBodySetAngularVelocity, anyBody(s, in), real(in), real(in), real(in));
        return METRUE;
    case 7:
        CALL(MdtBodySetMass, anyBody(s, in), real(in));
        return METRUE;
    case 8: {
        MeMatrix3 I;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                I[i][j] = real(in);
        CALL(MdtBodySetInertiaTensor, anyBody(s, in), I);
        return METRUE;
    }
    case 9:
        CALL(MdtBodySetQuaternion, anyBody(s, in), real(in), real(in), real(in), real(in));
        return METRUE;
    case 10:
        CALL(MdtBodyAddForce, anyBody(s, in), real(in), real(in), real(in));
        return METRUE;
    case 11:
        CALL(MdtBodyAddTorque, anyBody(s, in), real(in), real(in), real(in));
        return METRUE;
    case 12:
        CALL(MdtBodyAddImpulse, anyBody(s, in), real(in), real(in), real(in));
        return METRUE;
    case 13:
        if (byte(in) & 1)
            CALL(MdtBodySetLinearVelocityDamping, anyBody(s, in), real(in));
        else
            CALL(MdtBodySetAngularVelocityDamping, anyBody(s, in), real(in));
        return METRUE;
    case 14: {
        MdtBodyID b = anyBody(s, in);
        CALL(MdtBodyEnableNonSphericalInertia, b);
        CALL(MdtBodyEnableCoriolisForce, b);
        return METRUE;
    }
    case 15:
        if (byte(in) & 1)
            CALL(MdtBodyEnable, anyBody(s, in));
        else
            CALL(MdtBodyDisable, anyBody(s, in));
        return METRUE;
    case 16: { /* a joint between two bodies (either may be bad) */
        MdtBodyID a = anyBody(s, in), b = anyBody(s, in);
        MdtConstraintID c = NULL;
        switch (byte(in) % 3) {
        case 0: {
            MdtHingeID h = MdtHingeCreate(w);
            c = h ? MdtHingeQuaConstraint(h) : NULL;
            break;
        }
        case 1: {
            MdtBSJointID j = MdtBSJointCreate(w);
            c = j ? MdtBSJointQuaConstraint(j) : NULL;
            break;
        }
        default: {
            MdtPrismaticID p = MdtPrismaticCreate(w);
            c = p ? MdtPrismaticQuaConstraint(p) : NULL;
            break;
        }
        }
        MdtConstraintSetBodies(c, a, b);
        CALL(MdtConstraintSetPosition, c, real(in), real(in), real(in));
        CALL(MdtConstraintEnable, c);
        addConstraint(s, c);
        return MEFALSE; /* several calls: one may be refused while another succeeds */
    }
    case 17:
        CALL(MdtConstraintSetAxes, anyConstraint(s, in), real(in), real(in), real(in), real(in), real(in), real(in));
        return METRUE;
    case 18:
        CALL(MdtConstraintSetAxis, anyConstraint(s, in), real(in), real(in), real(in));
        return METRUE;
    case 19: { /* limits of a hinge or prismatic */
        MdtConstraintID c = anyConstraint(s, in);
        MdtHingeID h = MdtConstraintDCastHinge(c);
        MdtPrismaticID p = h ? NULL : MdtConstraintDCastPrismatic(c);
        MdtLimitID l = h ? MdtHingeGetLimit(h) : p ? MdtPrismaticGetLimit(p) : NULL;
        CALL(MdtSingleLimitSetStop, l ? MdtLimitGetLowerLimit(l) : NULL, real(in));
        CALL(MdtSingleLimitSetStop, l ? MdtLimitGetUpperLimit(l) : NULL, real(in));
        CALL(MdtSingleLimitSetStiffness, l ? MdtLimitGetUpperLimit(l) : NULL, real(in));
        CALL(MdtLimitActivateLimits, l, byte(in) & 1);
        CALL(MdtLimitSetLimitedForceMotor, l, real(in), real(in));
        CALL(MdtLimitActivateMotor, l, byte(in) & 1);
        return METRUE;
    }
    case 20:
        CALL(MdtConstraintDestroy, anyConstraint(s, in));
        return METRUE;
    case 21:
        CALL(MdtConstraintSetBodies, anyConstraint(s, in), anyBody(s, in), anyBody(s, in));
        return METRUE;
    case 22:
        CALL(MdtWorldSetGravity, w, real(in), real(in), real(in));
        return METRUE;
    case 23:
        CALL(MdtWorldSetEpsilon, w, real(in));
        CALL(MdtWorldSetGamma, w, real(in));
        return METRUE;
    case 24:
        CALL(MdtWorldSetSpeedLimit, w, real(in));
        CALL(MdtWorldSetAngularSpeedLimit, w, real(in));
        CALL(MdtWorldSetMaxCorrectingVelocity, w, real(in));
        return METRUE;
    case 25: { /* a step of any size: refused below the minimum or not finite, else it runs */
        MeReal h = real(in);
        if (byte(in) & 1)
            CALL(MstUniverseStep, s->u, h);
        else
            CALL(MdtWorldStep, w, h);
        return !(isfinite(h) && h >= MDT_MIN_STEP_SIZE);
    }
    case 26: { /* an ordinary step */
        CALL(MstUniverseStep, s->u, ME_R(1.0) / 60);
        return MEFALSE;
    }
    case 27:
        CALL(MdtConstraintBodySetPositionRel, anyConstraint(s, in), byte(in) % 3, real(in), real(in), real(in));
        return METRUE;
    default:
        CALL(MdtBodySetFastSpinAxis, anyBody(s, in), real(in), real(in), real(in));
        return METRUE;
    }
}

/* The task system: ranges of minRange items run last first, worker indices in turn. */
static void *reverseEnqueue(MdtTaskFnPtr task, int itemCount, int minRange, void *taskData, void *user)
{
    (void)user;
    int ranges = (itemCount + minRange - 1) / minRange;
    for (int k = ranges - 1; k >= 0; k--) {
        int end = (k + 1) * minRange < itemCount ? (k + 1) * minRange : itemCount;
        task(k * minRange, end, k % 3, taskData);
    }
    return NULL;
}
static void finishNothing(void *userTask, void *user)
{
    (void)userTask;
    (void)user;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static MeBool installed;
    if (!installed) {
        MeSetMessageHandler(countRefusals, NULL, NULL);
        installed = METRUE;
    }
    Input in = {data, size, 0};
    State s;
    memset(&s, 0, sizeof s);
    MstUniverseSizes sizes = MstUniverseDefaultSizes;
    sizes.dynamicBodiesMaxCount = 16; /* small pools: full pools are part of the test */
    sizes.collisionModelsMaxCount = 12;
    sizes.dynamicConstraintsMaxCount = 64;
    sizes.collisionPairsMaxCount = 64;
    s.u = MstUniverseCreate(&sizes);
    if (!s.u)
        fail("MstUniverseCreate failed", -1);
    s.w = MstUniverseGetWorld(s.u);
    MstUniverseSetTaskSystem(s.u, 3, reverseEnqueue, finishNothing, NULL);
    MdtWorldSetGravity(s.w, 0, 0, ME_R(-9.81));
    McdFrameworkID fw = MstUniverseGetFramework(s.u);
    static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    MstFixedModelCreate(s.u, McdPlaneCreate(fw), groundTM);
    s.shapes[0] = McdSphereCreate(fw, ME_R(0.5));
    s.shapes[1] = McdBoxCreate(fw, 1, ME_R(0.5), 2);
    s.shapes[2] = McdSphereCreate(fw, ME_R(0.1));
    s.shapes[3] = McdBoxCreate(fw, ME_R(0.2), ME_R(0.2), ME_R(0.2));

    for (int op = 0; in.at < in.size && op < 256; op++) {
        int code = byte(&in) % 29;
        MeBool finite;
        uint64_t before = worldHash(s.w, &finite);
        unsigned long refused = refusals;
        api = NULL;
        MeBool checkRefusal = operate(&s, &in, code);
        api = NULL;
        uint64_t after = worldHash(s.w, &finite);
        if (checkRefusal && refusals != refused && after != before)
            fail("a call that reported a warning changed a body's state", code);
        if (!finite)
            fail("a body's state is not finite", code);
    }
    MstUniverseDestroy(s.u);
    return 0;
}
