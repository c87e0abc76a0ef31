/* contact_simplify.c -- McdContactSimplify: Karma 1.2's reduction of a contact set to a few
 * well-spread points (deepest first, then farthest-point sampling on the contact plane). */
#include <karma/McdContact.h>
#include <karma/MeMath.h>

#include "../me/check.h"

/* Duplicates: contacts closer than this times the length scale to a kept one. */
#define MCD_SIMPLIFY_MERGE_FRACTION ME_R(1e-3)

/* Squared distance of a and b, in the plane perpendicular to the unit n (NULL: in space). */
static MeReal planarDistanceSqr(const MeReal *a, const MeReal *b, const MeReal *n)
{
    MeVector3 d;
    MeVector3Subtract(d, a, b);
    if (n) {
        MeReal along = MeVector3Dot(d, n);
        for (int k = 0; k < 3; k++)
            d[k] -= along * n[k];
    }
    return MeVector3Dot(d, d);
}

/* Size: Karma 1.2's signature. */
int MEAPI McdContactSimplify(const MeReal *avgNormal, McdContact *contacts_src, const int nContacts_src,
                             McdContact *contacts_dst, const int nContacts_dest, const int faceNormalsFirst,
                             const MeReal scale)
{
    if (nContacts_src < 0 || nContacts_dest < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "contact counts (%d, %d) must be >= 0; call ignored", nContacts_src,
                  nContacts_dest);
        return 0;
    }
    if (nContacts_src == 0 || nContacts_dest == 0)
        return 0;
    ME_CHECK_NOT_NULL(contacts_src, 0);
    ME_CHECK_NOT_NULL(contacts_dst, 0);
    ME_CHECK_FINITE(scale, 0);
    MeVector3 n;
    const MeReal *normal = NULL;
    if (avgNormal) {
        MeVector3Copy(n, avgNormal);
        if (MeVector3NormalizeSafe(n))
            normal = n;
    }
    MeReal merge = scale > 0 ? MCD_SIMPLIFY_MERGE_FRACTION * scale : 0;
    MeReal mergeSqr = merge * merge;
    int kept = 0;
    while (kept < nContacts_dest) {
        /* The best candidate: preferred class first, then the deepest (first pick) or the farthest
         * from the kept ones; ties go to the earlier contact, so the result is deterministic. */
        int best = -1, bestClass = -1;
        MeReal bestScore = 0;
        for (int i = 0; i < nContacts_src; i++) {
            const McdContact *c = &contacts_src[i];
            MeReal nearest = MEINFINITY;
            for (int j = 0; j < kept; j++) {
                MeReal d = planarDistanceSqr(c->position, contacts_dst[j].position, normal);
                if (d < nearest)
                    nearest = d;
            }
            if (kept > 0 && nearest <= mergeSqr)
                continue; /* kept already, or a duplicate of a kept one */
            int cls = faceNormalsFirst && c->dims == 2 ? 1 : 0;
            MeReal score = kept == 0 ? -c->separation : nearest;
            if (cls > bestClass || (cls == bestClass && score > bestScore)) {
                best = i;
                bestClass = cls;
                bestScore = score;
            }
        }
        if (best < 0)
            break;
        contacts_dst[kept++] = contacts_src[best];
    }
    return kept;
}
