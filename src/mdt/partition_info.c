/* partition_info.c -- Karma 1.2's partition counts (MdtPartition.h): rows, contacts and joints of a
 * set of constraints, as MdtWorldGetPartitionInfo reports them for a partition. */
#include <string.h>

#include <karma/MdtContactGroup.h>
#include <karma/MdtPartition.h>

#include "../me/check.h"
#include "constraint.h"
#include "world.h"

void MdtPartitionInfoAdd(MdtPartitionInfo *info, const MdtConstraintData *c)
{
    info->rowCount += MdtConstraintRowBound(c);
    if (c->type == MdtBclCONTACTGROUP)
        info->contactCount += MdtContactGroupGetCount((MdtContactGroupID)c->id);
    else if (c->type == MdtBclCONTACT)
        info->contactCount++;
    else
        info->jointCount++;
    info->constraints++;
}

void MdtPartInfoReset(MdtPartitionInfo *info)
{
    ME_CHECK_NOT_NULL(info, ME_NOTHING);
    memset(info, 0, sizeof *info);
}

void MdtPartInfoAddConstraint(MdtPartitionInfo *info, MdtConstraintID id)
{
    ME_CHECK_NOT_NULL(info, ME_NOTHING);
    const MdtConstraintData *c = MdtConstraintFromID(id, __func__);
    if (c)
        MdtPartitionInfoAdd(info, c);
}
