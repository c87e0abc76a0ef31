/* check_macros.c -- the checks behind Karma 1.2's MdtCHECK... macros (MdtCheckMacros.h): the library's
 * own ID resolution, reported in the caller's name. */
#include <karma/MdtCheckMacros.h>

#include "../me/check.h"
#include "constraint.h"
#include "world.h"

MeBool MdtCheckID(const void *id, int kind, MeBool nullOk, const char *function)
{
    if (!id && nullOk)
        return METRUE;
    if (!id) {
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "a required Mdt ID is NULL");
        return MEFALSE;
    }
    switch (kind) {
    case MdtCheckKindWorld:
        return MdtWorldFromID((MdtWorldID)(uintptr_t)id, function) != NULL;
    case MdtCheckKindBody:
        return MdtBodyFromID((MdtBodyID)(uintptr_t)id, function) != NULL;
    case MdtCheckKindConstraint:
        return MdtConstraintFromID((MdtConstraintID)(uintptr_t)id, function) != NULL;
    default:
        if (kind < 0 || kind >= MdtBclJOINT_TYPE_COUNT) {
            ME_REPORT(ME_ERR_ARGUMENT_RANGE, "argument 'kind' (%d) is neither an MdtCheckKind nor an MdtBclJointType",
                      kind);
            return MEFALSE;
        }
        return MdtConstraintFromIDOfType(id, (MdtBclJointType)kind, function) != NULL;
    }
}

MeBool MdtCheckConstraintBodies(const void *id, MeBool secondNullOk, const char *function)
{
    const MdtConstraintData *c = MdtConstraintFromID((MdtConstraintID)(uintptr_t)id, function);
    if (!c)
        return MEFALSE;
    if (!c->body[0] || (!secondNullOk && !c->body[1])) {
        ME_REPORT_IN(function, ME_ERR_BAD_STATE, "the %s's bodies are not set (MdtConstraintSetBodies)%s",
                     c->cls->name, secondNullOk ? "" : ": both are required here");
        return MEFALSE;
    }
    return METRUE;
}

MeBool MdtCheckPointer(const void *p, const char *function)
{
    if (!p)
        ME_REPORT_IN(function, ME_ERR_NULL_ARGUMENT, "a required pointer is NULL");
    return p != NULL;
}

MeBool MdtCheckIndex(long index, long max, const char *function)
{
    if (index >= 0 && index <= max)
        return METRUE;
    ME_REPORT_IN(function, max == 1 ? ME_ERR_BODY_INDEX : ME_ERR_ARGUMENT_RANGE, "index %ld must lie in [0, %ld]",
                 index, max);
    return MEFALSE;
}
