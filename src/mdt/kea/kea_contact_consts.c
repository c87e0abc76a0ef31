/* kea_contact_consts.c -- the contact step's constants (KeaContactConsts, kea_iterative.h): each
 * declared contact's inverse, eps, r and mu copied once a solve into one padded record beside its
 * rows, so that the step (kea_contact_kernel.h), run a dozen times a step per contact, reads them
 * as lanes in one place instead of as scalars from four arrays. The same values: the sweep's bits
 * do not change. */
#include "kea_iterative.h"

_Static_assert(sizeof(KeaContactConsts) <= 36 * sizeof(MeReal), "a contact's constants fit its block's JT room");

void KeaContactConstsFill(const KeaProblem *problem, KeaIterativeWork *w)
{
    int b, r, c;
    for (b = 0; b < w->nBlocks; ++b) {
        const int s = w->blockStart[b];
        const MeReal *inv = w->blockInv + w->blockMatrix[b];
        KeaContactConsts *k;
        if (!w->blockContact[b])
            continue;
        k = (KeaContactConsts *)(void *)(w->JT + 12 * s);
        for (c = 0; c < 3; ++c) {
            for (r = 0; r < 3; ++r)
                k->inv[c][r] = w->blockFactored[b] ? inv[c * 3 + r] : ME_R(0.0);
            k->inv[c][3] = ME_R(0.0);
            k->eps[c] = w->eps[s + c];
            k->rhs[c] = problem->rhs[s + c];
            k->mu[c] = c == 0 ? ME_R(0.0) : problem->mu[s + c];
        }
        k->eps[3] = k->rhs[3] = k->mu[3] = ME_R(0.0);
    }
}
