/* contact_lod.h -- what Mdt's stages outside BCL (the LOD stage, lod.c) may read and set of a
 * contact, through functions instead of the contact's struct (ContactData, contact_internal.h). */
#ifndef MDT_CONTACT_LOD_H
#define MDT_CONTACT_LOD_H

#include "../constraint.h"

/** A contact's geometry and importance as the bridge or the program set them (read only). */
typedef struct MdtContactLODInputs {
    const MeReal *position; /**< world point, m (3 values) */
    const MeReal *normal;   /**< unit, from body 1 towards body 0 (3 values) */
    MeReal penetration;     /**< m, > 0: overlap */
    MeReal importance;      /**< MdtContactSetImportance's value */
} MdtContactLODInputs;

/* First contact of a group (NULL when empty). */
MdtConstraintData *MdtContactGroupFirst(const MdtConstraintData *group);
/* The contact after `contact` in its group, or NULL (also for a stand-alone contact). */
MdtConstraintData *MdtContactNextInGroup(const MdtConstraintData *contact);
/* Rows of the contact's type (1, 2 or 3), before any capping. */
int MdtContactFullRowCount(const MdtConstraintData *contact);
/* The contact's position, normal, penetration and importance. */
void MdtContactGetLODInputs(const MdtConstraintData *contact, MdtContactLODInputs *out);
/* Let the contact write only `rows` rows (0: dropped, 1: frictionless) in the step whose partition
 * stamp is `stamp` (matrix capping); later steps write all its rows again. */
void MdtContactCapRows(MdtConstraintData *contact, int rows, unsigned long stamp);

#endif
