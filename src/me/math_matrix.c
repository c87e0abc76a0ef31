/* math_matrix.c -- the out-of-line MeMatrix3 functions: comparisons, inversion, LU, rotations and
 * the symmetric eigen-decomposition (for principal moments of inertia).
 *
 * Layout: row-major, row vectors (v' = v * M); a rotation holds the local axes in its rows. */
#include <karma/MeMath.h>

MeBool MeMatrix3IsIdentity(MeMatrix3 a, MeReal tolerance)
{
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            MeReal target = (i == j) ? ME_R(1.0) : ME_R(0.0);
            if (!(MeFabs(a[i][j] - target) <= tolerance))
                return MEFALSE;
        }
    return METRUE;
}

MeBool MeMatrix3IsValidOrientationMatrix(MeMatrix3 rot, MeReal tolerance)
{
    MeMatrix3 t, product;
    MeMatrix3Copy(t, rot);
    MeMatrix3Transpose(t);
    MeMatrix3MultiplyMatrix(product, rot, t);
    if (!MeMatrix3IsIdentity(product, tolerance))
        return MEFALSE;
    return MeMatrix3Determinant(rot) > ME_R(1.0) - tolerance ? METRUE : MEFALSE;
}

/* inverse = adjugate / det; the columns of the adjugate are r1 x r2, r2 x r0, r0 x r1. Refuses a
 * determinant that is tiny compared with the volume bound |r0||r1||r2| (Hadamard), which measures
 * singularity independently of the matrix's scale. */
static MeBool InvertGeneral(MeMatrix3 a)
{
    MeVector3 c[3];
    MeReal det, bound;
    int i, j;
    MeVector3Cross(c[0], a[1], a[2]);
    MeVector3Cross(c[1], a[2], a[0]);
    MeVector3Cross(c[2], a[0], a[1]);
    det = MeVector3Dot(a[0], c[0]);
    bound = MeVector3Magnitude(a[0]) * MeVector3Magnitude(a[1]) * MeVector3Magnitude(a[2]);
    if (!isfinite(det) || !isfinite(bound) || !(MeFabs(det) > ME_SMALL_EPSILON * bound))
        return MEFALSE;
    det = ME_R(1.0) / det;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            a[i][j] = c[j][i] * det;
    return METRUE;
}

MeBool MeMatrix3Invert(MeMatrix3 a)
{
    return InvertGeneral(a);
}

MeBool MeMatrix3SymmetricInvert(MeMatrix3 a)
{
    MeReal largest = ME_R(0.0), tol;
    MeMatrix3 s;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            largest = MeMAX(largest, MeFabs(a[i][j]));
    tol = ME_SMALL_EPSILON * largest;
    if (!(MeFabs(a[0][1] - a[1][0]) <= tol && MeFabs(a[0][2] - a[2][0]) <= tol &&
          MeFabs(a[1][2] - a[2][1]) <= tol))
        return MEFALSE;
    /* Invert the symmetrised copy and symmetrise the result, so it is exactly symmetric. */
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            s[i][j] = ME_R(0.5) * (a[i][j] + a[j][i]);
    if (!InvertGeneral(s))
        return MEFALSE;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            a[i][j] = ME_R(0.5) * (s[i][j] + s[j][i]);
    return METRUE;
}

void MeMatrix3LUDecompose(MeMatrix3 L, MeMatrix3 U, MeMatrix3 a, unsigned int *swappedRow, MeVector3 scale)
{
    /* Doolittle elimination with scaled partial pivoting. b holds U in its upper triangle and the
     * multipliers (L) below it; whole rows are swapped so L follows its row. */
    MeMatrix3 b;
    int perm[3] = {0, 1, 2};
    MeVector3 rowMax;
    int i, j, k;

    MeMatrix3Copy(b, a);
    for (i = 0; i < 3; i++)
        rowMax[i] = MeMAX3(MeFabs(a[i][0]), MeFabs(a[i][1]), MeFabs(a[i][2]));

    for (k = 0; k < 2; k++) {
        int p = k;
        MeReal best = ME_R(-1.0);
        for (i = k; i < 3; i++) {
            MeReal r = rowMax[i] > ME_R(0.0) ? MeFabs(b[i][k]) / rowMax[i] : ME_R(0.0);
            if (r > best) {
                best = r;
                p = i;
            }
        }
        if (p != k) {
            int t = perm[p];
            perm[p] = perm[k];
            perm[k] = t;
            MeVector3Swap(b[p], b[k]);
            MeRealSwap(&rowMax[p], &rowMax[k]);
        }
        for (i = k + 1; i < 3; i++) {
            MeReal l = b[k][k] != ME_R(0.0) ? b[i][k] / b[k][k] : ME_R(0.0);
            for (j = k + 1; j < 3; j++)
                b[i][j] -= l * b[k][j];
            b[i][k] = l;
        }
    }

    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            L[i][j] = (j < i) ? b[i][j] : (i == j ? ME_R(1.0) : ME_R(0.0));
            U[i][j] = (j >= i) ? b[i][j] : ME_R(0.0);
        }
    for (i = 0; i < 3; i++)
        scale[i] = rowMax[i] > ME_R(0.0) ? ME_R(1.0) / rowMax[i] : ME_R(0.0);

    /* Karma's codes for the six row orders. */
    if (perm[0] == 0)
        *swappedRow = perm[1] == 1 ? 0u : 3u;
    else if (perm[0] == 1)
        *swappedRow = perm[1] == 0 ? 1u : 4u;
    else
        *swappedRow = perm[1] == 1 ? 2u : 5u;
}

/* Row-axes rotations: row i is the image of e_i under a right-handed rotation by angle a. */
void MeMatrix3MakeRotationX(MeMatrix3 m, MeReal a)
{
    MeReal s = MeSin(a), c = MeCos(a);
    MeVector3Set(m[0], ME_R(1.0), ME_R(0.0), ME_R(0.0));
    MeVector3Set(m[1], ME_R(0.0), c, s);
    MeVector3Set(m[2], ME_R(0.0), -s, c);
}

void MeMatrix3MakeRotationY(MeMatrix3 m, MeReal a)
{
    MeReal s = MeSin(a), c = MeCos(a);
    MeVector3Set(m[0], c, ME_R(0.0), -s);
    MeVector3Set(m[1], ME_R(0.0), ME_R(1.0), ME_R(0.0));
    MeVector3Set(m[2], s, ME_R(0.0), c);
}

void MeMatrix3MakeRotationZ(MeMatrix3 m, MeReal a)
{
    MeReal s = MeSin(a), c = MeCos(a);
    MeVector3Set(m[0], c, s, ME_R(0.0));
    MeVector3Set(m[1], -s, c, ME_R(0.0));
    MeVector3Set(m[2], ME_R(0.0), ME_R(0.0), ME_R(1.0));
}

void MeMatrix3FromEulerAngles(MeMatrix3 m, MeReal xangle, MeReal yangle, MeReal zangle)
{
    MeMatrix3 rx, ry, rz;
    MeMatrix3MakeRotationX(rx, xangle);
    MeMatrix3MakeRotationY(ry, yangle);
    MeMatrix3MakeRotationZ(rz, zangle);
    MeMatrix3MultiplyMatrix(m, rx, ry);
    MeMatrix3MultiplyMatrix(m, m, rz);
}

/* One Jacobi rotation in the (p, q) plane that zeroes a[p][q]: a <- J^T a J, v <- v J, with
 * J = I except J[p][p] = J[q][q] = c, J[p][q] = s, J[q][p] = -s, and t = s/c the smaller root of
 * t^2 + 2 t theta - 1 = 0, theta = (a_qq - a_pp) / (2 a_pq). (If theta^2 overflows, t = 0: the
 * rotation would be below rounding level anyway.) */
static void JacobiRotate(MeMatrix3 a, MeMatrix3 v, int p, int q)
{
    MeReal theta, t, c, s;
    MeMatrix3 J, Jt;
    if (a[p][q] == ME_R(0.0))
        return;
    theta = (a[q][q] - a[p][p]) / (ME_R(2.0) * a[p][q]);
    t = ME_R(1.0) / (MeFabs(theta) + MeSqrt(theta * theta + ME_R(1.0)));
    if (theta < ME_R(0.0))
        t = -t;
    c = MeRecipSqrt(t * t + ME_R(1.0));
    s = t * c;
    MeMatrix3MakeIdentity(J);
    J[p][p] = c;
    J[q][q] = c;
    J[p][q] = s;
    J[q][p] = -s;
    MeMatrix3Copy(Jt, J);
    MeMatrix3Transpose(Jt);
    MeMatrix3MultiplyMatrix(a, Jt, a);
    MeMatrix3MultiplyMatrix(a, a, J);
    a[p][q] = a[q][p] = ME_R(0.0);
    MeMatrix3MultiplyMatrix(v, v, J);
}

MeBool MeMatrix3SymmetricEigen(MeVector3 values, MeMatrix3 axes, MeMatrix3 m)
{
    static const int planes[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    MeMatrix3 a, v;
    MeReal frob2 = ME_R(0.0), off2 = ME_R(0.0);
    int order[3] = {0, 1, 2};
    MeBool converged = MEFALSE;
    int i, j, sweep;

    for (i = 0; i < 3; i++)
        for (j = i; j < 3; j++) {
            a[i][j] = a[j][i] = m[i][j];
            frob2 += (i == j ? ME_R(1.0) : ME_R(2.0)) * m[i][j] * m[i][j];
        }
    MeMatrix3MakeIdentity(v);
    if (!isfinite(frob2)) {
        MeVector3Set(values, ME_R(0.0), ME_R(0.0), ME_R(0.0));
        MeMatrix3MakeIdentity(axes);
        return MEFALSE;
    }

    for (sweep = 0; sweep < 50; sweep++) {
        off2 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        /* stop once the off-diagonal part is at rounding level relative to the whole matrix */
        if (off2 <= ME_MIN_EPSILON * ME_MIN_EPSILON * frob2) {
            converged = METRUE;
            break;
        }
        for (i = 0; i < 3; i++)
            JacobiRotate(a, v, planes[i][0], planes[i][1]);
    }

    /* ascending eigenvalues (insertion sort: stable, so ties keep their order) */
    for (i = 1; i < 3; i++)
        for (j = i; j > 0 && a[order[j]][order[j]] < a[order[j - 1]][order[j - 1]]; j--) {
            int t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
        }
    for (i = 0; i < 3; i++) {
        values[i] = a[order[i]][order[i]];
        for (j = 0; j < 3; j++)
            axes[i][j] = v[j][order[i]]; /* eigenvectors are the columns of v */
    }
    if (MeMatrix3Determinant(axes) < ME_R(0.0))
        MeVector3Scale(axes[2], ME_R(-1.0));
    return converged;
}
