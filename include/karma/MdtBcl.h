/* MdtBcl.h -- Karma 1.2's header of the Basic Constraint Library: the most rows each type of
 * constraint writes into the solver in one step, for budgeting memory (MdtKeaMemoryRequired).
 *
 * 1.2's MdtBclAdd<Type>, MdtBclInitConstraintRowList, MdtBclStartPartition, MdtBclEndPartition and
 * MdtBclEndConstraint wrote Kea's arrays (MdtKeaConstraints), which this library does not have: the
 * world writes every constraint's rows itself in MdtPack, and a user constraint writes its own through
 * its MdtUserConstraintRowsFn (MdtUserConstraint.h), returning the row count that 1.2 passed to
 * MdtBclEndConstraint. Those names are not declared (docs/api_changes.md). */
#ifndef MDT_BCL_H
#define MDT_BCL_H

#include "MdtKea.h"
#include "MePrecision.h"

/* The most rows each constraint type writes per step (its limits and motors included). */
#define MdtBclGETMAXROWSBSJOINT (3)
#define MdtBclGETMAXROWSHINGE (6)
#define MdtBclGETMAXROWSPRISMATIC (6)
#define MdtBclGETMAXROWSCARWHEEL (6)
/** Per contact (a contact group writes this many per contact). */
#define MdtBclGETMAXROWSCONTACT (3)
#define MdtBclGETMAXROWSFIXEDPATH (3)
#define MdtBclGETMAXROWSRPROJOINT (6)
#define MdtBclGETMAXROWSUNIVERSAL (4)
/** 6 here (1.2: 5): 3 for the ball joint, up to 2 for the cone option, 1 for the twist limit. */
#define MdtBclGETMAXROWSSKELETAL (6)
#define MdtBclGETMAXROWSLINEAR1 (1)
#define MdtBclGETMAXROWSLINEAR2 (2)
#define MdtBclGETMAXROWSANGULAR3 (3)
#define MdtBclGETMAXROWSSPRING6 (6)
#define MdtBclGETMAXROWSSPRING (1)
#define MdtBclGETMAXROWSCONELIMIT (1)
/** The most any joint writes, and a user constraint by default (MdtUserConstraintSetMaxRows may
 *  raise a user constraint's to MDT_USER_CONSTRAINT_MAX_ROWS). */
#define MdtBclGETMAXROWS (6)

#endif /* MDT_BCL_H */
