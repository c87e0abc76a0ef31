/* table.c -- the built-in pair tests, one entry per unordered pair of primitive types (internal).
 * The framework's interaction table is filled from this list; McdNfCollide runs an entry in either
 * order for the tests and the benchmark. */
#include "nearfield.h"

static const McdNfPairEntry pairTable[] = {
    {kMcdGeometryTypeSphere, kMcdGeometryTypeSphere, McdNfSphereSphere, "sphere-sphere"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeBox, McdNfSphereBox, "sphere-box"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeCylinder, McdNfSphereCylinder, "sphere-cylinder"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeSphyl, McdNfSphereSphyl, "sphere-sphyl"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypeCone, McdNfConvexConvex, "sphere-cone"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeBox, McdNfBoxBox, "box-box"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeCylinder, McdNfConvexConvex, "box-cylinder"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeSphyl, McdNfConvexConvex, "box-sphyl"},
    {kMcdGeometryTypeBox, kMcdGeometryTypeCone, McdNfConvexConvex, "box-cone"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeCylinder, McdNfConvexConvex, "cylinder-cylinder"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeSphyl, McdNfConvexConvex, "cylinder-sphyl"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypeCone, McdNfConvexConvex, "cylinder-cone"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeSphyl, McdNfSphylSphyl, "sphyl-sphyl"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypeCone, McdNfConvexConvex, "sphyl-cone"},
    {kMcdGeometryTypeCone, kMcdGeometryTypeCone, McdNfConvexConvex, "cone-cone"},
    {kMcdGeometryTypeSphere, kMcdGeometryTypePlane, McdNfSpherePlane, "sphere-plane"},
    {kMcdGeometryTypeBox, kMcdGeometryTypePlane, McdNfBoxPlane, "box-plane"},
    {kMcdGeometryTypeCylinder, kMcdGeometryTypePlane, McdNfCylinderPlane, "cylinder-plane"},
    {kMcdGeometryTypeSphyl, kMcdGeometryTypePlane, McdNfSphylPlane, "sphyl-plane"},
    {kMcdGeometryTypeCone, kMcdGeometryTypePlane, McdNfConePlane, "cone-plane"},
};

const McdNfPairEntry *McdNfPairTable(int *count)
{
    *count = (int)(sizeof pairTable / sizeof pairTable[0]);
    return pairTable;
}

McdNearfieldFn McdNfFind(int type1, int type2, int *swapped)
{
    size_t k;
    for (k = 0; k < sizeof pairTable / sizeof pairTable[0]; k++) {
        if (pairTable[k].type1 == type1 && pairTable[k].type2 == type2) {
            *swapped = 0;
            return pairTable[k].fn;
        }
        if (pairTable[k].type1 == type2 && pairTable[k].type2 == type1) {
            *swapped = 1;
            return pairTable[k].fn;
        }
    }
    *swapped = 0;
    return NULL;
}

int McdNfCollide(const McdGeometryData *g1, MeMatrix4 tm1, const McdGeometryData *g2, MeMatrix4 tm2, MeReal tolerance,
                 McdContact *contacts, int maxContacts)
{
    int swapped, n, k;
    McdNearfieldFn fn = McdNfFind(g1->type, g2->type, &swapped);
    if (!fn)
        return 0;
    if (!swapped)
        return fn(g1, tm1, g2, tm2, tolerance, contacts, maxContacts, NULL);
    n = fn(g2, tm2, g1, tm1, tolerance, contacts, maxContacts, NULL);
    for (k = 0; k < n; k++) {
        void *e = contacts[k].element1;
        MeVector3Scale(contacts[k].normal, -ME_R(1.0));
        contacts[k].element1 = contacts[k].element2;
        contacts[k].element2 = e;
    }
    return n;
}
