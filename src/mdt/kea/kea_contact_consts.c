/* kea_contact_consts.c -- the contact step's constants (KeaContactConsts, kea_iterative.h): each
 * declared contact's inverse, eps, r and mu copied once a solve into one padded record beside its
 * rows, so that the step (kea_contact_kernel.h), run a dozen times a step per contact, reads them
 * as lanes in one place instead of as scalars from four arrays, with its rows' free flags from the
 * warm start as one mask. The same values: the sweep's bits do not change. */
#include <string.h>

#include "kea_iterative.h"

_Static_assert(sizeof(KeaContactConsts) <= 36 * sizeof(MeReal), "a contact's constants fit its block's JT room");

void KeaContactConstsFill(const KeaProblem *problem, KeaIterativeWork *w)
{
    const int nBlocks = w->nBlocks;
    const int *restrict blockStart = w->blockStart, *restrict blockMatrix = w->blockMatrix;
    const unsigned char *restrict contact = w->blockContact, *restrict factored = w->blockFactored,
                        *restrict wasFree = w->wasFree;
    const MeReal *restrict blockInv = w->blockInv, *restrict eps = w->eps, *restrict rhs = problem->rhs,
                 *restrict mu = problem->mu;
    MeReal *restrict JT = w->JT;
    int b, r, c;
    for (b = 0; b < nBlocks; ++b) {
        const int s = blockStart[b];
        const MeReal *inv = blockInv + blockMatrix[b];
        KeaContactConsts k;
        if (!contact[b])
            continue;
        for (c = 0; c < 3; ++c) {
            for (r = 0; r < 3; ++r)
                k.inv[c][r] = inv[c * 3 + r];
            k.inv[c][3] = ME_R(0.0);
            k.eps[c] = eps[s + c];
            k.rhs[c] = rhs[s + c];
        }
        if (!factored[b]) /* no inverse: the step never reads it */
            memset(k.inv, 0, sizeof k.inv);
        k.mu[0] = ME_R(0.0);
        k.mu[1] = mu[s + 1];
        k.mu[2] = mu[s + 2];
        k.eps[3] = k.rhs[3] = k.mu[3] = ME_R(0.0);
        k.freeRows = wasFree[s] | wasFree[s + 1] << 1 | wasFree[s + 2] << 2;
        memcpy(JT + 12 * s, &k, sizeof k);
    }
}
