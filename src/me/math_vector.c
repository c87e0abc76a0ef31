/* math_vector.c -- the out-of-line MeVector3 functions: building orthonormal bases.
 *
 * Everything else about vectors is small enough to be inline in karma/MeMath.h. */
#include <karma/MeMath.h>

void MeVector3PlaneSpace(const MeVector3 n, MeVector3 a, MeVector3 b)
{
    /* a = (coordinate axis least aligned with n) x n, normalised; the chosen pair of components
     * holds at least half of |n|^2, so the normalisation is well conditioned. b = n x a, which makes
     * a x b = n(a.a) - a(a.n) = n. */
    MeReal len2;
    if (MeFabs(n[0]) > MeFabs(n[1])) {
        len2 = n[0] * n[0] + n[2] * n[2]; /* a = e_y x n */
        if (!(len2 > ME_R(0.0)))
            goto degenerate;
        MeVector3Set(a, n[2], ME_R(0.0), -n[0]);
    } else {
        len2 = n[1] * n[1] + n[2] * n[2]; /* a = e_x x n */
        if (!(len2 > ME_R(0.0)))
            goto degenerate;
        MeVector3Set(a, ME_R(0.0), -n[2], n[1]);
    }
    MeVector3Scale(a, MeRecipSqrt(len2));
    MeVector3Cross(b, n, a);
    return;

degenerate: /* n = 0: any orthonormal pair keeps the outputs finite */
    MeVector3Set(a, ME_R(1.0), ME_R(0.0), ME_R(0.0));
    MeVector3Set(b, ME_R(0.0), ME_R(1.0), ME_R(0.0));
}

void MeVector3MakeOrthogonal(MeVector3 v, const MeVector3 v1)
{
    MeVector3 n, unused;
    MeVector3Copy(n, v1);
    MeVector3Normalize(n);
    MeVector3PlaneSpace(n, v, unused);
}
