/* primitives.c -- Karma 1.2's per-type names of the primitives (McdPrimitives.h), each a check of the
 * geometry's type in front of the generic call. */
#include <karma/McdPrimitives.h>

#include "geometry.h"

/* The generic geometry protocol behind Karma's per-type names, for the primitive of `typeId`. */
#define MCD_DEFINE_PRIMITIVE_TYPE(T, typeId)                                                            \
    MeI16 T##GetTypeId(void) { return (MeI16)(typeId); }                                                \
    void T##RegisterType(McdFramework *frame) { (void)McdPrimitivesRegisterTypes(frame); }               \
    void T##Destroy(McdGeometryID g)                                                                     \
    {                                                                                                    \
        if (McdGeometryOfType(g, typeId, #T "Destroy"))                                                  \
            McdGeometryDestroy(g);                                                                       \
    }                                                                                                    \
    void T##GetBSphere(McdGeometryID g, MeVector3 center, MeReal *radius)                                \
    {                                                                                                    \
        if (McdGeometryOfType(g, typeId, #T "GetBSphere"))                                               \
            McdGeometryGetBSphere(g, center, radius);                                                    \
    }                                                                                                    \
    MeI16 T##GetMassProperties(McdGeometryID g, MeMatrix4 relTM, MeMatrix3 inertia, MeReal *volume)      \
    {                                                                                                    \
        if (!McdGeometryOfType(g, typeId, #T "GetMassProperties"))                                       \
            return 1;                                                                                    \
        return McdGeometryGetMassProperties(g, relTM, inertia, volume);                                  \
    }                                                                                                    \
    char *T##GetTypeName(McdGeometryID g)                                                                \
    {                                                                                                    \
        McdGeometryData *data = McdGeometryOfType(g, typeId, #T "GetTypeName");                          \
        return data ? (char *)McdGeometryTypeOf(data)->typeName : NULL;                                  \
    }                                                                                                    \
    void T##DebugDraw(const McdGeometryID g, MeMatrix4 tm, const MeReal colour[3])                 \
    {                                                                                                    \
        if (!McdGeometryOfType(g, typeId, #T "DebugDraw"))                                               \
            return;                                                                                      \
        const float c[3] = {colour ? (float)colour[0] : 1, colour ? (float)colour[1] : 1,                \
                            colour ? (float)colour[2] : 1};                                              \
        McdGeometryDebugDraw(g, tm, c);                                                              \
    }

MCD_DEFINE_PRIMITIVE_TYPE(McdNull, kMcdGeometryTypeNull)
MCD_DEFINE_PRIMITIVE_TYPE(McdSphere, kMcdGeometryTypeSphere)
MCD_DEFINE_PRIMITIVE_TYPE(McdBox, kMcdGeometryTypeBox)
MCD_DEFINE_PRIMITIVE_TYPE(McdPlane, kMcdGeometryTypePlane)
MCD_DEFINE_PRIMITIVE_TYPE(McdCylinder, kMcdGeometryTypeCylinder)
MCD_DEFINE_PRIMITIVE_TYPE(McdSphyl, kMcdGeometryTypeSphyl)
MCD_DEFINE_PRIMITIVE_TYPE(McdCone, kMcdGeometryTypeCone)
