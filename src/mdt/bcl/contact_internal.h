/* contact_internal.h -- the data of one contact, shared by contact.c and contact_group.c. */
#ifndef MDT_CONTACT_INTERNAL_H
#define MDT_CONTACT_INTERNAL_H

#include <karma/MdtContactParams.h>

#include "../constraint.h"

typedef struct ContactData {
    MeVector3 position;       /* world */
    MeVector3 normal;         /* unit, body 0 → body 1 */
    MeVector3 direction;      /* primary friction direction (with UseDirection) */
    MeVector3 worldVelocity;  /* surface velocity of the world (with UseWorldVelocity) */
    MeReal penetration;       /* > 0: overlap */
    MeReal importance;
    MdtContactParams params;
    MeReal impulse[3];        /* last step's row impulses: normal, primary, secondary */
    MeReal normalForce;       /* last step, N */
    MeReal pendingBounce;     /* approach speed of a contact that landed last step and bounces now */
    MdtConstraint *group;     /* owning group, or NULL */
    MdtConstraint *next;      /* next contact of the group */
} ContactData;
MDT_CONSTRAINT_DATA_FITS(ContactData);

extern const MdtConstraintClass MdtContactClass;

/* Rows of the contact's type (1, 2 or 3). */
int MdtContactRowCount(const ContactData *d);
/* Write one contact's rows for `owner` (the contact itself, or its group): bodies come from owner. */
void MdtContactAddRows(const MdtConstraint *owner, MdtConstraint *contact, MdtRowWriter *w);
/* Keep the contact's impulses (warm start) and its normal force. */
void MdtContactUnpack(MdtConstraint *contact, const MeReal *impulses, int rows, MeReal h);

#endif
