/* math_general.c -- Karma's small dense-matrix helpers, packed-triangle indexing and printing. */
#include <karma/MeMath.h>

void MeMatrixTranspose(MeReal *A, int n, int m, const MeReal *B)
{
    int i, j;
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++)
            A[i + j * n] = B[j + i * m];
}

void MeMatrixMultiply(MeReal *A, int p, int q, int r, const MeReal *B, const MeReal *C)
{
    int i, j, k;
    for (j = 0; j < r; j++)
        for (i = 0; i < p; i++) {
            MeReal sum = ME_R(0.0);
            for (k = 0; k < q; k++)
                sum += B[i + k * p] * C[k + j * q];
            A[i + j * p] = sum;
        }
}

void MeMatrixMultiplyT1(MeReal *A, int p, int q, int r, const MeReal *B, const MeReal *C)
{
    int i, j, k;
    for (j = 0; j < r; j++)
        for (i = 0; i < p; i++) {
            MeReal sum = ME_R(0.0);
            for (k = 0; k < q; k++)
                sum += B[k + i * q] * C[k + j * q];
            A[i + j * p] = sum;
        }
}

void MeMatrixFPrint(FILE *file, const MeReal *A, int n, int m, const char *format)
{
    int i, j;
    if (!file)
        file = stdout;
    if (!format)
        format = "%10.4f ";
    for (i = 0; i < n; i++) {
        for (j = 0; j < m; j++)
            fprintf(file, format, (double)A[i + j * n]);
        fputc('\n', file);
    }
}

void MeMatrixPrint(const MeReal *A, int n, int m, const char *format) { MeMatrixFPrint(stdout, A, n, m, format); }

void MeMatrix3SwapColumns(MeMatrix3 a, unsigned int col1, unsigned int col2)
{
    int i;
    if (col1 > 2 || col2 > 2)
        return;
    for (i = 0; i < 3; i++)
        MeRealSwap(&a[i][col1], &a[i][col2]);
}

MeBool MeRealArrayIsZero(MeReal *v, int elements)
{
    int i;
    for (i = 0; i < elements; i++)
        if (v[i] != ME_R(0.0))
            return MEFALSE;
    return METRUE;
}

/* Row r of the upper triangle (with diagonal) of an n-column matrix starts after
 * n + (n-1) + ... + (n-r+1) = r*n - r*(r-1)/2 elements. */
int MeUpperDiagonalIndex(int inRow, int inCol, int inNCols)
{
    return inRow * inNCols - inRow * (inRow - 1) / 2 + (inCol - inRow);
}

int MeUpperDiagonalSize(int inNCols) { return inNCols * (inNCols + 1) / 2; }

int MeSymUpperDiagonalIndex(int inRow, int inCol, int inNCols)
{
    return inRow <= inCol ? MeUpperDiagonalIndex(inRow, inCol, inNCols) : MeUpperDiagonalIndex(inCol, inRow, inNCols);
}

/* Without the diagonal, row r holds n-1-r elements and starts after r*(n-1) - r*(r-1)/2. */
int MeSuperDiagonalIndex(int inRow, int inCol, int inNCols)
{
    return inRow * (inNCols - 1) - inRow * (inRow - 1) / 2 + (inCol - inRow - 1);
}

int MeSuperDiagonalSize(int inNCols) { return inNCols * (inNCols - 1) / 2; }

int MeSymSuperDiagonalIndex(int inRow, int inCol, int inNCols)
{
    return inRow < inCol ? MeSuperDiagonalIndex(inRow, inCol, inNCols) : MeSuperDiagonalIndex(inCol, inRow, inNCols);
}
