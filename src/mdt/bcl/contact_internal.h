/* contact_internal.h -- the data of one contact, shared by contact.c and contact_group.c. */
#ifndef MDT_CONTACT_INTERNAL_H
#define MDT_CONTACT_INTERNAL_H

#include <karma/MdtContactParams.h>

#include "../constraint.h"
#include "contact_lod.h"

typedef struct ContactData {
    MeVector3 position;       /* world */
    MeVector3 normal;         /* unit, from body 1 towards body 0 (body 0 is pushed along it) */
    MeVector3 direction;      /* primary friction direction (with UseDirection) */
    MeVector3 frictionAxis;   /* primary friction direction chosen by the contact (without UseDirection),
                                 carried from step to step with the warm start; zero when fresh */
    MeVector3 worldVelocity;  /* surface velocity of the world (with UseWorldVelocity) */
    MeReal penetration;       /* > 0: overlap */
    MeReal importance;
    MdtContactParams params;
    MeReal impulse[3];        /* last step's row impulses: normal, primary, secondary */
    MeReal normalForce;       /* last step, N */
    MeReal pendingBounce;     /* approach speed of a contact that landed last step and bounces now */
    MdtConstraintData *group;     /* owning group, or NULL */
    MdtConstraintData *next;      /* next contact of the group */
    unsigned long lodStamp;   /* matrix capping: lodRows holds for the step with this partition stamp */
    int lodRows;              /* rows capping left this contact (0: dropped, 1: frictionless) */
    MeBool matched;           /* MdtContactGroupSetFromCollisions: a new point took this old contact */
} ContactData;
MDT_CONSTRAINT_DATA_FITS(ContactData);

extern const MdtConstraintClass MdtContactClass;

/* Rows of the contact's type (1, 2 or 3). */
int MdtContactRowCount(const ContactData *d);
/* Rows the contact writes in this step: its type's, or fewer when matrix capping dropped some. */
int MdtContactStepRows(const MdtConstraintData *contact);
/* Write one contact's rows for `owner` (the contact itself, or its group): bodies come from owner. */
void MdtContactAddRows(const MdtConstraintData *owner, MdtConstraintData *contact, MdtRowWriter *w);
/* MdtContactSetFromCollision's fields (params, position, normal made unit, penetration), each checked
 * as its setter would, a bad one skipped and reported in that setter's name. */
void MdtContactSetCollisionFields(ContactData *d, const MdtContactParams *params, const MeVector3 position,
                                  const MeVector3 normal, MeReal penetration);
/* Keep the contact's impulses (warm start) and its normal force. */
void MdtContactUnpack(MdtConstraintData *contact, const MeReal *impulses, int rows, MeReal h);

#endif
