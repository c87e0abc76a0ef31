/* fuzz_common.h -- decoding fuzzer bytes into Mcd inputs, and the checks every harness shares.
 *
 * The harnesses (fuzz_*.c) define LLVMFuzzerTestOneInput. Built with clang and -fsanitize=fuzzer they
 * are libFuzzer targets (make fuzz); linked with replay_main.c (any compiler) they replay the seed
 * corpora and every input that ever crashed (the test fuzz_replay_*). A violated claim aborts.
 *
 * Decoding never fails: bytes past the end read as zero. Values come in two kinds: "in range" (sizes
 * log-uniform over the documented range, unit quaternions, positions up to the documented limit), and
 * "raw" (the bytes of an MeReal as they are: NaN, infinity, FLT_MAX, denormals), which the library
 * must refuse with a coded message. */
#ifndef KARMA_FUZZ_COMMON_H
#define KARMA_FUZZ_COMMON_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <karma/Mcd.h>
#include <karma/MeMath.h>
#include <karma/MeMessage.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FUZZ_CHECK(cond, ...)                                                                          \
    do {                                                                                               \
        if (!(cond)) {                                                                                 \
            fprintf(stderr, "%s:%d: claim violated: %s: ", __FILE__, __LINE__, #cond);                 \
            fprintf(stderr, __VA_ARGS__);                                                              \
            fprintf(stderr, "\n");                                                                     \
            abort();                                                                                   \
        }                                                                                              \
    } while (0)

typedef struct FuzzInput {
    const uint8_t *p;
    size_t n;
} FuzzInput;

static inline unsigned fuzz_byte(FuzzInput *in)
{
    if (!in->n)
        return 0;
    in->n--;
    return *in->p++;
}

static inline unsigned fuzz_u16(FuzzInput *in)
{
    unsigned lo = fuzz_byte(in);
    return lo | (fuzz_byte(in) << 8);
}

/* In [-1, 1]. */
static inline double fuzz_unit(FuzzInput *in) { return (double)fuzz_u16(in) / 32767.5 - 1.0; }

/* Log-uniform in [lo, hi]. */
static inline double fuzz_log(FuzzInput *in, double lo, double hi)
{
    return lo * pow(hi / lo, (double)fuzz_u16(in) / 65535.0);
}

/* The bytes of an MeReal as they are. */
static inline MeReal fuzz_raw(FuzzInput *in)
{
    unsigned char b[sizeof(MeReal)];
    MeReal r;
    for (size_t i = 0; i < sizeof b; i++)
        b[i] = (unsigned char)fuzz_byte(in);
    memcpy(&r, b, sizeof r);
    return r;
}

/* A size: in the documented range (times lengthScale) with probability 7/8, raw otherwise. */
static inline MeReal fuzz_size(FuzzInput *in, double lengthScale, int *raw)
{
    if ((fuzz_byte(in) & 7) == 7) {
        *raw = 1;
        return fuzz_raw(in);
    }
    /* mostly near 1, sometimes anywhere in 1e-6..1e6 */
    if (fuzz_byte(in) & 1)
        return (MeReal)(fuzz_log(in, 1e-6, 1e6) * lengthScale);
    return (MeReal)(fuzz_log(in, 0.05, 20) * lengthScale);
}

/* A proper rotation: from a quaternion (identity when the bytes give none), or one of the 24 axis
 * rotations (exactly parallel features). Rows of tm[0..2] are the rotated axes. */
static inline void fuzz_rotation(FuzzInput *in, MeMatrix4 tm)
{
    double w, x, y, z, l;
    unsigned kind = fuzz_byte(in);
    MeMatrix4TMMakeIdentity(tm);
    if ((kind & 3) == 0) { /* axis rotation: a permutation with signs and determinant +1 */
        static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
        const int *p = perm[(kind >> 2) % 6];
        double s[3] = {(kind & 32) ? -1 : 1, (kind & 64) ? -1 : 1, 1};
        double det = ((kind >> 2) % 6 < 3 ? 1 : -1) * s[0] * s[1];
        s[2] = det; /* makes the determinant +1 */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                tm[i][j] = (MeReal)(j == p[i] ? s[i] : 0);
        return;
    }
    w = fuzz_unit(in), x = fuzz_unit(in), y = fuzz_unit(in), z = fuzz_unit(in);
    l = sqrt(w * w + x * x + y * y + z * z);
    if (l < 1e-3)
        return;
    w /= l, x /= l, y /= l, z /= l;
    tm[0][0] = (MeReal)(1 - 2 * (y * y + z * z)), tm[0][1] = (MeReal)(2 * (x * y + w * z)),
    tm[0][2] = (MeReal)(2 * (x * z - w * y));
    tm[1][0] = (MeReal)(2 * (x * y - w * z)), tm[1][1] = (MeReal)(1 - 2 * (x * x + z * z)),
    tm[1][2] = (MeReal)(2 * (y * z + w * x));
    tm[2][0] = (MeReal)(2 * (x * z + w * y)), tm[2][1] = (MeReal)(2 * (y * z - w * x)),
    tm[2][2] = (MeReal)(1 - 2 * (x * x + y * y));
}

/* A position within `range` of `centre`, log-distributed in magnitude per axis. */
static inline void fuzz_position(FuzzInput *in, const MeReal *centre, double range, MeReal *out)
{
    for (int k = 0; k < 3; k++) {
        double u = fuzz_unit(in);
        double mag = fuzz_log(in, range * 1e-7, range);
        out[k] = (MeReal)((double)(centre ? centre[k] : 0) + (u < 0 ? -mag : mag) * fabs(u));
    }
}

/* Twelve raw reals into the rotation and translation of tm (hostile transforms). */
static inline void fuzz_raw_transform(FuzzInput *in, MeMatrix4 tm)
{
    MeMatrix4TMMakeIdentity(tm);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++)
            tm[i][j] = fuzz_raw(in);
}

static inline int fuzz_vector_finite(const MeReal *v) { return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]); }

/* |v| is 1 to this relative tolerance. */
static inline int fuzz_is_unit(const MeReal *v, double tol)
{
    double l = sqrt((double)v[0] * v[0] + (double)v[1] * v[1] + (double)v[2] * v[2]);
    return fabs(l - 1) <= tol;
}

/* Messages are counted, not printed; a fatal one (Karma found itself inconsistent) is a crash. */
static inline void fuzz_message_handler(const MeMessageInfo *info, void *user)
{
    (void)user;
    if (info->level >= ME_LEVEL_FATAL) {
        fprintf(stderr, "fatal message %d from %s: %s\n", (int)info->code, info->function, info->text);
        abort();
    }
}

static inline void fuzz_quiet_messages(void)
{
    void *previous;
    MeSetMessageHandler(fuzz_message_handler, NULL, &previous);
}

#endif /* KARMA_FUZZ_COMMON_H */
