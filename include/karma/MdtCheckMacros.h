/* MdtCheckMacros.h -- Karma 1.2's argument checks for code written against Mdt (its MdtCHECK...
 * macros), on this library's checked IDs.
 *
 * Each macro takes the value and the name of the calling function (a string) and checks the value
 * as the library's own functions do: an ID must be live and of the right type (a destroyed, stale,
 * foreign or wrong-type ID is reported with ME_ERR_INVALID_HANDLE, ME_ERR_WRONG_HANDLE_KIND...), a
 * pointer non-NULL, an index in range. A failed check is reported through the message hook in the
 * name given, and the program goes on (1.2's checking build stopped with a fatal error; its release
 * build checked nothing). The checks are on in every build, and each is an expression of type void. */
#ifndef MDT_CHECK_MACROS_H
#define MDT_CHECK_MACROS_H

#include "MdtTypes.h"
#include "MeMessage.h"

ME_EXTERN_C_BEGIN

/** What MdtCheckID checks an ID against: a world, a body, any constraint, or (≥ 0) one
 *  MdtBclJointType. */
typedef enum MdtCheckKind {
    MdtCheckKindWorld = -3,
    MdtCheckKindBody = -2,
    MdtCheckKindConstraint = -1
} MdtCheckKind;

/** Whether `id` is a live ID of `kind` (MdtCheckKind, or an MdtBclJointType); reported in
 *  `function`'s name when not. NULL passes when `nullOk`, else it is reported. */
ME_API MeBool MdtCheckID(const void *id, int kind, MeBool nullOk, const char *function);
/** Whether constraint `c` has its body 0 (and, unless `secondNullOk`, its body 1) set; reported
 *  (ME_ERR_BAD_STATE) when not. */
ME_API MeBool MdtCheckConstraintBodies(const void *c, MeBool secondNullOk, const char *function);
/** Whether the pointer is non-NULL; reported (ME_ERR_NULL_ARGUMENT) when not. */
ME_API MeBool MdtCheckPointer(const void *p, const char *function);
/** Whether 0 ≤ index ≤ max; reported when not (ME_ERR_BODY_INDEX when max is 1, else
 *  ME_ERR_ARGUMENT_RANGE). */
ME_API MeBool MdtCheckIndex(long index, long max, const char *function);

#define MdtCHECKWORLD(x, f) ((void)MdtCheckID((x), MdtCheckKindWorld, 0, (f)))
#define MdtCHECKBODY(x, f) ((void)MdtCheckID((x), MdtCheckKindBody, 0, (f)))
#define MdtCHECKBODY_NULL_OK(x, f) ((void)MdtCheckID((x), MdtCheckKindBody, 1, (f)))
#define MdtCHECKCONSTRAINT(x, f) ((void)MdtCheckID((x), MdtCheckKindConstraint, 0, (f)))
#define MdtCHECKCONSTRAINTBODIES_NULL_OK(x, f) ((void)MdtCheckConstraintBodies((x), 1, (f)))
#define MdtCHECKCONSTRAINTBODIES(x, f) ((void)MdtCheckConstraintBodies((x), 0, (f)))
#define MdtCHECKHINGE(x, f) ((void)MdtCheckID((x), MdtBclHINGE, 0, (f)))
#define MdtCHECKBSJOINT(x, f) ((void)MdtCheckID((x), MdtBclBSJOINT, 0, (f)))
#define MdtCHECKCONTACT(x, f) ((void)MdtCheckID((x), MdtBclCONTACT, 0, (f)))
#define MdtCHECKCONTACTGROUP(x, f) ((void)MdtCheckID((x), MdtBclCONTACTGROUP, 0, (f)))
#define MdtCHECKCONTACTPARAMS(x, f) ((void)MdtCheckPointer((x), (f)))
#define MdtCHECKPRISMATIC(x, f) ((void)MdtCheckID((x), MdtBclPRISMATIC, 0, (f)))
#define MdtCHECKCARWHEEL(x, f) ((void)MdtCheckID((x), MdtBclCARWHEEL, 0, (f)))
#define MdtCHECKFIXEDPATH(x, f) ((void)MdtCheckID((x), MdtBclFIXEDPATH, 0, (f)))
#define MdtCHECKRPROJOINT(x, f) ((void)MdtCheckID((x), MdtBclRPROJOINT, 0, (f)))
#define MdtCHECKUNIVERSAL(x, f) ((void)MdtCheckID((x), MdtBclUNIVERSAL, 0, (f)))
#define MdtCHECKSKELETAL(x, f) ((void)MdtCheckID((x), MdtBclSKELETAL, 0, (f)))
#define MdtCHECKLINEAR1(x, f) ((void)MdtCheckID((x), MdtBclLINEAR1, 0, (f)))
#define MdtCHECKLINEAR2(x, f) ((void)MdtCheckID((x), MdtBclLINEAR2, 0, (f)))
#define MdtCHECKANGULAR3(x, f) ((void)MdtCheckID((x), MdtBclANGULAR3, 0, (f)))
#define MdtCHECKSPRING6(x, f) ((void)MdtCheckID((x), MdtBclSPRING6, 0, (f)))
#define MdtCHECKUSERCONSTRAINT(x, f) ((void)MdtCheckID((x), MdtBclUSER, 0, (f)))
#define MdtCHECKSPRING(x, f) ((void)MdtCheckID((x), MdtBclSPRING, 0, (f)))
#define MdtCHECKCONELIMIT(x, f) ((void)MdtCheckID((x), MdtBclCONELIMIT, 0, (f)))
#define MdtCHECKSINGLELIMIT(x, f) ((void)MdtCheckPointer((x), (f)))
#define MdtCHECKLIMIT(x, f) ((void)MdtCheckPointer((x), (f)))
#define MdtCHECKBODYINDEX(x, f) ((void)MdtCheckIndex((long)(x), 1, (f)))
#define MdtCHECKLIMITINDEX3(x, f) ((void)MdtCheckIndex((long)(x), 2, (f)))

ME_EXTERN_C_END

#endif /* MDT_CHECK_MACROS_H */
