/* kea_lanes.h -- four-lane arithmetic on the iterative path's padded 3-vectors (KeaVel4 and the
 * halves of a KeaJacobianRow: three components and a pad that is 0).
 *
 * In single precision on x86 (SSE is part of every x86-64 processor) the four lanes are one SSE
 * register; anywhere else, and in double precision, a plain array. Either way each lane does the
 * same IEEE operations in the same order, so the results are the same bits: the choice is speed
 * only. The compiler's own vectoriser finds this in small separate loops but not reliably inside a
 * large block step (the contact step, kea_contact_kernel.h, compiles to scalar code without them;
 * the figures are in bench/RESULTS.md). */
#ifndef KEA_LANES_H
#define KEA_LANES_H

#include <karma/MePrecision.h>

#if !KARMA_DOUBLE && (defined(__SSE__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 1))
#  include <xmmintrin.h>

typedef __m128 KeaLanes;

static inline KeaLanes KeaLanesLoad(const MeReal *p) { return _mm_loadu_ps(p); }
static inline void KeaLanesStore(MeReal *p, KeaLanes a) { _mm_storeu_ps(p, a); }
/** KeaLanesLoad / KeaLanesStore of a 16-byte aligned p (a load the compiler may fold into the
 *  arithmetic that uses it). */
static inline KeaLanes KeaLanesLoadA(const MeReal *p) { return _mm_load_ps(p); }
static inline void KeaLanesStoreA(MeReal *p, KeaLanes a) { _mm_store_ps(p, a); }
static inline KeaLanes KeaLanesAdd(KeaLanes a, KeaLanes b) { return _mm_add_ps(a, b); }
static inline KeaLanes KeaLanesSub(KeaLanes a, KeaLanes b) { return _mm_sub_ps(a, b); }
static inline KeaLanes KeaLanesMul(KeaLanes a, KeaLanes b) { return _mm_mul_ps(a, b); }
/** a > b ? a : b, lane by lane (KeaMax: b where either is a NaN or both are zeros). */
static inline KeaLanes KeaLanesMax(KeaLanes a, KeaLanes b) { return _mm_max_ps(a, b); }
/** a < b ? a : b, lane by lane (b where either is a NaN or both are zeros). */
static inline KeaLanes KeaLanesMin(KeaLanes a, KeaLanes b) { return _mm_min_ps(a, b); }
static inline KeaLanes KeaLanesSplat(MeReal s) { return _mm_set1_ps(s); }
/** The select (as KeaLanesSelectOf's) of the lanes where a != b (true for a NaN). */
static inline KeaLanes KeaLanesSelectNotEqual(KeaLanes a, KeaLanes b) { return _mm_cmpneq_ps(a, b); }
/** a where the select k is set, else b, lane by lane. */
static inline KeaLanes KeaLanesChoose(KeaLanes k, KeaLanes a, KeaLanes b)
{
    return _mm_or_ps(_mm_and_ps(k, a), _mm_andnot_ps(k, b));
}
/** The select of a mask m (SM's masks: 1 or 0) for KeaLanesKeep: all bits set where m is not 0. */
static inline KeaLanes KeaLanesSelectOf(KeaLanes m) { return _mm_cmpneq_ps(m, _mm_setzero_ps()); }
/** a where the select k (KeaLanesSelectOf) is set, else +0: a select, not a product with the mask,
 *  so that a masked lane is +0 even when a is a NaN or an infinity; one AND, as cheap as the product. */
static inline KeaLanes KeaLanesKeep(KeaLanes a, KeaLanes k) { return _mm_and_ps(a, k); }
/** (a0 + a1) + a2: the sum of a padded 3-vector's components, in that order. */
static inline MeReal KeaLanesSum3(KeaLanes a)
{
    const __m128 s01 = _mm_add_ss(a, _mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 1, 1, 1)));
    return _mm_cvtss_f32(_mm_add_ss(s01, _mm_movehl_ps(a, a)));
}

/** Whether lanes 0-2 of all four padded 3-vectors are numbers within +-MEINFINITY (|v| < MEINFINITY,
 *  false for a NaN); the pads are not looked at. */
static inline int KeaLanesFinite3x4(const MeReal *a, const MeReal *b, const MeReal *c, const MeReal *d)
{
    const __m128 sign = _mm_set1_ps(-0.0f), limit = _mm_set1_ps(MEINFINITY); /* |v|: the sign bit cleared */
    const __m128 ab = _mm_and_ps(_mm_cmplt_ps(_mm_andnot_ps(sign, _mm_loadu_ps(a)), limit),
                                 _mm_cmplt_ps(_mm_andnot_ps(sign, _mm_loadu_ps(b)), limit));
    const __m128 cd = _mm_and_ps(_mm_cmplt_ps(_mm_andnot_ps(sign, _mm_loadu_ps(c)), limit),
                                 _mm_cmplt_ps(_mm_andnot_ps(sign, _mm_loadu_ps(d)), limit));
    return (_mm_movemask_ps(_mm_and_ps(ab, cd)) & 7) == 7;
}

/** [p0, p1, p2, 0]: three reals into lanes (p[3] is not read). */
static inline KeaLanes KeaLanesLoad3(const MeReal *p) { return _mm_setr_ps(p[0], p[1], p[2], 0.0f); }
/** Lane k (0 to 3; a constant where it is called, so that this is one shuffle). */
static inline MeReal KeaLanesAt(KeaLanes a, int k)
{
    switch (k) {
    case 0: return _mm_cvtss_f32(a);
    case 1: return _mm_cvtss_f32(_mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 1, 1, 1)));
    case 2: return _mm_cvtss_f32(_mm_movehl_ps(a, a));
    default: return _mm_cvtss_f32(_mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 3, 3, 3)));
    }
}
/** |a|, lane by lane (the sign bit cleared). */
static inline KeaLanes KeaLanesAbs(KeaLanes a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }
/** Bit k set where a_k <= b_k (false for a NaN), lanes 0-2 (the pad not looked at). */
static inline int KeaLanesLe3(KeaLanes a, KeaLanes b) { return _mm_movemask_ps(_mm_cmple_ps(a, b)) & 7; }
/** Bit k set where a_k < b_k (false for a NaN), lanes 0-2. */
static inline int KeaLanesLt3(KeaLanes a, KeaLanes b) { return _mm_movemask_ps(_mm_cmplt_ps(a, b)) & 7; }
/** Bit k set where a_k != 0 (true for a NaN), lanes 0-2. */
static inline int KeaLanesNonZero3(KeaLanes a) { return _mm_movemask_ps(_mm_cmpneq_ps(a, _mm_setzero_ps())) & 7; }
/** Whether some lane of a is not 0 (true for a NaN), all four lanes. */
static inline int KeaLanesAnyNonZero(KeaLanes a) { return _mm_movemask_ps(_mm_cmpneq_ps(a, _mm_setzero_ps())) != 0; }
/** Whether a <= b (a < b) in all four lanes (false where a NaN is). */
static inline int KeaLanesAllLe4(KeaLanes a, KeaLanes b) { return _mm_movemask_ps(_mm_cmple_ps(a, b)) == 15; }
static inline int KeaLanesAllLt4(KeaLanes a, KeaLanes b) { return _mm_movemask_ps(_mm_cmplt_ps(a, b)) == 15; }
/** [KeaLanesSum3(a), KeaLanesSum3(b), KeaLanesSum3(c), 0]: the three sums at once, the same
 *  additions in the same order (a transpose, then two additions of lanes). */
static inline KeaLanes KeaLanesSum3Each(KeaLanes a, KeaLanes b, KeaLanes c)
{
    const __m128 zero = _mm_setzero_ps();
    const __m128 ab01 = _mm_unpacklo_ps(a, b), c01 = _mm_unpacklo_ps(c, zero);
    const __m128 ab23 = _mm_unpackhi_ps(a, b), c23 = _mm_unpackhi_ps(c, zero);
    return _mm_add_ps(_mm_add_ps(_mm_movelh_ps(ab01, c01), _mm_movehl_ps(c01, ab01)), _mm_movelh_ps(ab23, c23));
}

/** Transpose the 4 x 4 matrix whose rows are a, b, c, d: afterwards a holds the first lanes of the
 *  four, b the second ones, and so on (moves only, no arithmetic). */
static inline void KeaLanesTranspose4(KeaLanes *a, KeaLanes *b, KeaLanes *c, KeaLanes *d)
{
    _MM_TRANSPOSE4_PS(*a, *b, *c, *d);
}

#else

typedef struct KeaLanes {
    MeReal v[4];
} KeaLanes;

static inline KeaLanes KeaLanesLoad(const MeReal *p)
{
    KeaLanes a;
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] = p[k];
    return a;
}
static inline void KeaLanesStore(MeReal *p, KeaLanes a)
{
    int k;
    for (k = 0; k < 4; ++k)
        p[k] = a.v[k];
}
static inline KeaLanes KeaLanesLoadA(const MeReal *p) { return KeaLanesLoad(p); }
static inline void KeaLanesStoreA(MeReal *p, KeaLanes a) { KeaLanesStore(p, a); }
static inline KeaLanes KeaLanesAdd(KeaLanes a, KeaLanes b)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] += b.v[k];
    return a;
}
static inline KeaLanes KeaLanesSub(KeaLanes a, KeaLanes b)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] -= b.v[k];
    return a;
}
static inline KeaLanes KeaLanesMul(KeaLanes a, KeaLanes b)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] *= b.v[k];
    return a;
}
static inline KeaLanes KeaLanesMax(KeaLanes a, KeaLanes b)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] = a.v[k] > b.v[k] ? a.v[k] : b.v[k];
    return a;
}
static inline KeaLanes KeaLanesMin(KeaLanes a, KeaLanes b)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] = a.v[k] < b.v[k] ? a.v[k] : b.v[k];
    return a;
}
static inline KeaLanes KeaLanesSelectNotEqual(KeaLanes a, KeaLanes b)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] = a.v[k] != b.v[k] ? ME_R(1.0) : ME_R(0.0);
    return a;
}
static inline KeaLanes KeaLanesChoose(KeaLanes k, KeaLanes a, KeaLanes b)
{
    int l;
    for (l = 0; l < 4; ++l)
        a.v[l] = k.v[l] != ME_R(0.0) ? a.v[l] : b.v[l];
    return a;
}
static inline KeaLanes KeaLanesSplat(MeReal s)
{
    KeaLanes a;
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] = s;
    return a;
}
static inline KeaLanes KeaLanesSelectOf(KeaLanes m) { return m; }
static inline KeaLanes KeaLanesKeep(KeaLanes a, KeaLanes m)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] = m.v[k] != ME_R(0.0) ? a.v[k] : ME_R(0.0);
    return a;
}
static inline MeReal KeaLanesSum3(KeaLanes a) { return (a.v[0] + a.v[1]) + a.v[2]; }
static inline int KeaLanesFinite3x4(const MeReal *a, const MeReal *b, const MeReal *c, const MeReal *d)
{
    int ok = 1, k;
    for (k = 0; k < 3; ++k)
        ok &= (a[k] > -MEINFINITY) & (a[k] < MEINFINITY) & (b[k] > -MEINFINITY) & (b[k] < MEINFINITY) &
              (c[k] > -MEINFINITY) & (c[k] < MEINFINITY) & (d[k] > -MEINFINITY) & (d[k] < MEINFINITY);
    return ok;
}

static inline KeaLanes KeaLanesLoad3(const MeReal *p)
{
    KeaLanes a;
    int k;
    for (k = 0; k < 3; ++k)
        a.v[k] = p[k];
    a.v[3] = ME_R(0.0);
    return a;
}
static inline MeReal KeaLanesAt(KeaLanes a, int k) { return a.v[k]; }
static inline KeaLanes KeaLanesAbs(KeaLanes a)
{
    int k;
    for (k = 0; k < 4; ++k)
        a.v[k] = MeFabs(a.v[k]);
    return a;
}
static inline int KeaLanesLe3(KeaLanes a, KeaLanes b)
{
    return (a.v[0] <= b.v[0]) | (a.v[1] <= b.v[1]) << 1 | (a.v[2] <= b.v[2]) << 2;
}
static inline int KeaLanesLt3(KeaLanes a, KeaLanes b)
{
    return (a.v[0] < b.v[0]) | (a.v[1] < b.v[1]) << 1 | (a.v[2] < b.v[2]) << 2;
}
static inline int KeaLanesNonZero3(KeaLanes a)
{
    return (a.v[0] != ME_R(0.0)) | (a.v[1] != ME_R(0.0)) << 1 | (a.v[2] != ME_R(0.0)) << 2;
}
static inline int KeaLanesAnyNonZero(KeaLanes a)
{
    return a.v[0] != ME_R(0.0) || a.v[1] != ME_R(0.0) || a.v[2] != ME_R(0.0) || a.v[3] != ME_R(0.0);
}
static inline int KeaLanesAllLe4(KeaLanes a, KeaLanes b)
{
    return (a.v[0] <= b.v[0]) & (a.v[1] <= b.v[1]) & (a.v[2] <= b.v[2]) & (a.v[3] <= b.v[3]);
}
static inline int KeaLanesAllLt4(KeaLanes a, KeaLanes b)
{
    return (a.v[0] < b.v[0]) & (a.v[1] < b.v[1]) & (a.v[2] < b.v[2]) & (a.v[3] < b.v[3]);
}
static inline KeaLanes KeaLanesSum3Each(KeaLanes a, KeaLanes b, KeaLanes c)
{
    KeaLanes s;
    s.v[0] = (a.v[0] + a.v[1]) + a.v[2];
    s.v[1] = (b.v[0] + b.v[1]) + b.v[2];
    s.v[2] = (c.v[0] + c.v[1]) + c.v[2];
    s.v[3] = ME_R(0.0);
    return s;
}

static inline void KeaLanesTranspose4(KeaLanes *a, KeaLanes *b, KeaLanes *c, KeaLanes *d)
{
    KeaLanes *rows[4];
    MeReal t;
    int i, j;
    rows[0] = a;
    rows[1] = b;
    rows[2] = c;
    rows[3] = d;
    for (i = 0; i < 4; ++i)
        for (j = i + 1; j < 4; ++j) {
            t = rows[i]->v[j];
            rows[i]->v[j] = rows[j]->v[i];
            rows[j]->v[i] = t;
        }
}

#endif

/** The select (KeaLanesSelectOf) of lanes 0-2, the pad's lane clear: a padded 3-vector's components. */
static inline KeaLanes KeaLanesSelectComponents(void)
{
    static const MeReal components[4] = {ME_R(1.0), ME_R(1.0), ME_R(1.0), ME_R(0.0)};
    return KeaLanesSelectOf(KeaLanesLoad(components));
}

/** a * b + c * d, lane by lane (each product rounded, then the sum). */
static inline KeaLanes KeaLanesDot2(const MeReal *a, const MeReal *b, const MeReal *c, const MeReal *d)
{
    return KeaLanesAdd(KeaLanesMul(KeaLanesLoad(a), KeaLanesLoad(b)), KeaLanesMul(KeaLanesLoad(c), KeaLanesLoad(d)));
}

/** KeaLanesDot2 with b and d already in lanes (the same products and sum). */
static inline KeaLanes KeaLanesDot2L(const MeReal *a, KeaLanes b, const MeReal *c, KeaLanes d)
{
    return KeaLanesAdd(KeaLanesMul(KeaLanesLoad(a), b), KeaLanesMul(KeaLanesLoad(c), d));
}

/** v += u * s on a padded 3-vector (pad stays 0 when u's is). */
static inline void KeaLanesAddScaled(MeReal *v, const MeReal *u, KeaLanes s)
{
    KeaLanesStore(v, KeaLanesAdd(KeaLanesLoad(v), KeaLanesMul(KeaLanesLoad(u), s)));
}

#endif
