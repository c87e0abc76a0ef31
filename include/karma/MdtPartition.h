/* MdtPartition.h -- Karma 1.2's header for the partitions of a step (islands of bodies joined by
 * constraints). Here they are read through the world between the stages of MdtMainLoop.h
 * (MdtWorldGetPartitionCount, MdtWorldGetPartitionInfo, MdtWorldGetPartitionBody). */
#ifndef MDT_PARTITION_H
#define MDT_PARTITION_H

#include "MdtMainLoop.h"

#endif /* MDT_PARTITION_H */
