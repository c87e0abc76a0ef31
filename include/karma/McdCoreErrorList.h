/* McdCoreErrorList.h -- Karma 1.2's list of collision error numbers, each tied to the coded message
 * (MeErrorCodes.h) that reports it here.
 *
 * Included alone it declares the error numbers (kMcdErrorNum_GenericFatal ... kMcdMAXErrDefined) for
 * McdError / McdCoreError (McdMessage.h). As in 1.2 it is also an X-macro list: with ERR(name, type,
 * text) defined, including it expands to `ERR(...),` once per error (1.2's own way of building
 * tables). Each entry of MCD_CORE_ERROR_LIST(X) is X(name, 1.2's type, our code, text); the code is
 * ME_ERR_NONE where no code of ours corresponds (the message then goes through MeWarning / MeInfo,
 * code ME_ERR_USER_MESSAGE). */
#ifndef MCD_CORE_ERROR_LIST_MACROS_H
#define MCD_CORE_ERROR_LIST_MACROS_H

/* clang-format off */
#define MCD_CORE_ERROR_LIST(X) \
    X(kMcdErrorNum_GenericFatal, kMcdErrorTypeFatal, ME_ERR_NONE, "") \
    X(kMcdErrorNum_GenericWarning, kMcdErrorTypeWarning, ME_ERR_NONE, "") \
    X(kMcdErrorNum_EvalTimedOut, kMcdErrorTypeFatal, ME_ERR_NONE, "evaluation period over (never reported here)") \
    X(kMcdErrorNum_InvalidPtr, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "a pointer argument is NULL: ") \
    X(kMcdErrorNum_BadCast, kMcdErrorTypeFatal, ME_ERR_WRONG_HANDLE_KIND, "the object is not of the expected type: ") \
    X(kMcdErrorNum_AllocFailure, kMcdErrorTypeFatal, ME_ERR_OUT_OF_MEMORY, "could not allocate an object of type ") \
    X(kMcdErrorNum_AssertionFailed, kMcdErrorTypeFatal, ME_ERR_NONE, "check failed: ") \
    X(kMcdErrorNum_BadSetTransInBridge, kMcdErrorTypeWarning, ME_ERR_BAD_STATE, "the model's transform follows a body's; set the body's instead") \
    X(kMcdErrorNum_InvalidPtr_CM, kMcdErrorTypeFatal, ME_ERR_INVALID_HANDLE, "invalid McdModelID") \
    X(kMcdErrorNum_InvalidPtr_Space, kMcdErrorTypeFatal, ME_ERR_INVALID_HANDLE, "invalid McdSpaceID") \
    X(kMcdErrorNum_InvalidPtr_Geometry, kMcdErrorTypeFatal, ME_ERR_INVALID_HANDLE, "invalid McdGeometryID") \
    X(kMcdErrorNum_InvalidPtr_SPID, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "the McdModelPairID is NULL") \
    X(kMcdErrorNum_InvalidPtr_SP, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "the McdModelPair pointer is NULL") \
    X(kMcdErrorNum_InvalidPtr_IR, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "the McdIntersectResult pointer is NULL") \
    X(kMcdErrorNum_InvalidPair, kMcdErrorTypeFatal, ME_ERR_INVALID_HANDLE, "a model of the pair is NULL") \
    X(kMcdErrorNum_InvalidPtr_CDDT, kMcdErrorTypeFatal, ME_ERR_INVALID_HANDLE, "invalid bridge") \
    X(kMcdErrorNum_InvalidPtr_RWW, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "the RenderWare world is NULL") \
    X(kMcdErrorNum_InvalidPtr_RWBSP, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "the RenderWare BSP is NULL") \
    X(kMcdErrorNum_InvalidPtr_TM, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "the transform pointer is NULL") \
    X(kMcdErrorNum_InvalidFuncOrder_Space, kMcdErrorTypeFatal, ME_ERR_BAD_STATE, "the space is not built") \
    X(kMcdErrorNum_InvalidFuncOrder_Bridge, kMcdErrorTypeFatal, ME_ERR_BAD_STATE, "the bridge is not initialised") \
    X(kMcdErrorNum_InvalidGeoType, kMcdErrorTypeFatal, ME_ERR_ARGUMENT_RANGE, "no room for another geometry type (McdInit's geoTypeMaxCount)") \
    X(kMcdErrorNum_InvalidIR, kMcdErrorTypeFatal, ME_ERR_NULL_ARGUMENT, "the result's contact array is NULL") \
    X(kMcdErrorNum_InvalidRequest, kMcdErrorTypeFatal, ME_ERR_ARGUMENT_RANGE, "invalid request: ") \
    X(kMcdErrorNum_Mem_SpaceModelPairPool, kMcdErrorTypeFatal, ME_ERR_POOL_FULL, "the space's pair pool is full (raise pairCount)") \
    X(kMcdErrorNum_Mem_SpaceModelPool, kMcdErrorTypeFatal, ME_ERR_POOL_FULL, "the space's model pool is full (raise objectCount)") \
    X(kMcdErrorNum_Mem_PairData, kMcdErrorTypeWarning, ME_ERR_POOL_FULL, "no room for more pair data") \
    X(kMcdErrorNum_contactBufferOverrun, kMcdErrorTypeWarning, ME_ERR_POOL_FULL, "contact buffer full: ") \
    X(kMcdErrorNum_TriangleArrayOverrun, kMcdErrorTypeWarning, ME_ERR_POOL_FULL, "no room for more triangles") \
    X(kMcdErrorNum_DegenerateTriangle, kMcdErrorTypeInfo, ME_ERR_MCD_DEGENERATE_GEOMETRY, "degenerate triangle ignored") \
    X(kMcdErrorNum_TriangleMeshNoTriangles, kMcdErrorTypeWarning, ME_ERR_MCD_DEGENERATE_GEOMETRY, "the triangle mesh has no triangles") \
    X(kMcdErrorNum_TriangleMeshNotBuilt, kMcdErrorTypeFatal, ME_ERR_BAD_STATE, "the triangle mesh is not built") \
    X(kMcdErrorNum_NoIntersectionFn, kMcdErrorTypeWarning, ME_ERR_MCD_NO_INTERACTION, "no pair test for these geometry types: ") \
    X(McdErrorNum_InvalidRequest, kMcdErrorTypeWarning, ME_ERR_ARGUMENT_RANGE, "invalid request ") \
    X(McdErrorNum_RegisterInteractionUnknownGeom, kMcdErrorTypeWarning, ME_ERR_ARGUMENT_RANGE, "pair test for an unregistered geometry type ignored: ") \
    X(McdErrorNum_FindInteractionUnknownGeom, kMcdErrorTypeWarning, ME_ERR_ARGUMENT_RANGE, "pair test asked for an unregistered geometry type") \
    X(McdErrorNum_SafeTimeUnimplementedCase, kMcdErrorTypeWarning, ME_ERR_MCD_NO_INTERACTION, "no safe-time test for ") \
    X(McdErrorNum_RegisterInteractionWithInvalidGeometryType, kMcdErrorTypeWarning, ME_ERR_ARGUMENT_RANGE, "pair test for an invalid geometry type number") \
    X(kMcdErrorNum_SpaceNotChanging, kMcdErrorTypeWarning, ME_ERR_BAD_STATE, "the space is not changing (McdSpaceBeginChanges first): ") \
    X(kMcdErrorNum_SpaceIsChanging, kMcdErrorTypeWarning, ME_ERR_BAD_STATE, "the space is changing (McdSpaceEndChanges first): ") \
    X(kMcdErrorNum_DestroyModelInSpace, kMcdErrorTypeWarning, ME_ERR_MCD_IN_USE, "the model is still in a space") \
    X(kMcdErrorNum_boxBoxInvalid, kMcdErrorTypeWarning, ME_ERR_NOT_ROTATION, "box-box test given an invalid transform") \
    X(kMcdErrorNum_InertiaTensorInvalid, kMcdErrorTypeWarning, ME_ERR_INERTIA_INVALID, "the inertia tensor is not symmetric") \
    X(kMcdErrorNum_McdFrameworkNULL, kMcdErrorTypeWarning, ME_ERR_INVALID_HANDLE, "the framework is already terminated") \
    X(kMcdMAXErrDefined, kMcdErrorTypeFatal, ME_ERR_NONE, "no error")
/* clang-format on */

/* 1.2's form of an entry: ERR(name, type, text), followed by a comma. */
#define MCD_CORE_ERROR_AS_ERR_(name, type, code, text) ERR(name, type, text),

#endif /* MCD_CORE_ERROR_LIST_MACROS_H */

/* The error numbers, declared once (not while a 1.2-style ERR expansion is under way). */
#if !defined(ERR) && !defined(MCD_CORE_ERROR_LIST_ENUM_H)
#define MCD_CORE_ERROR_LIST_ENUM_H
#define MCD_CORE_ERROR_ENUM_(name, type, code, text) name,
/** 1.2's collision error numbers, from 0 (kMcdErrorNum_GenericFatal); kMcdMAXErrDefined ends the list. */
enum McdCoreErrorNumber { MCD_CORE_ERROR_LIST(MCD_CORE_ERROR_ENUM_) kMcdCoreErrorNumberEnd_ };
#undef MCD_CORE_ERROR_ENUM_
#endif

#ifdef ERR
MCD_CORE_ERROR_LIST(MCD_CORE_ERROR_AS_ERR_)
#endif
