/* angular3.c -- the Angular3 joint: its API and its rows. The rows hold φ = 2·vec(q) = 0, q the
 * rotation of body 0's frame relative to body 1's (≈ the rotation angle about each of body 1's frame
 * axes); with rotation enabled, the row about the primary axis is left out (Angular2: q may only turn
 * about the primary axis). A finite stiffness or a damping makes each row a spring-damper (SPOOK). */
#include <karma/MdtAngular3.h>

#include "joint_parts.h"

typedef struct Angular3Data {
    MeBool rotationEnabled;
    MeReal stiffness, damping;
} Angular3Data;
MDT_CONSTRAINT_DATA_FITS(Angular3Data);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    Angular3Data *d = MDT_CONSTRAINT_DATA(c, Angular3Data);
    d->rotationEnabled = MEFALSE;
    d->stiffness = MEINFINITY;
    d->damping = 0; /* decision D3 */
}

static int rowCount(const MdtConstraintData *c)
{
    return MDT_CONSTRAINT_DATA(c, const Angular3Data)->rotationEnabled ? 2 : 3;
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    const Angular3Data *d = MDT_CONSTRAINT_DATA(c, const Angular3Data);
    MdtBclRotation r;
    MdtBclRelativeRotation(c, NULL, &r);
    for (int k = d->rotationEnabled ? 1 : 0; k < 3; k++) {
        MdtRow row;
        MdtRowInit(&row);
        MdtBclRotationRow(&row, &r, k);
        if (MdtBclRowSpring(&row, c, d->stiffness, d->damping, w->h))
            MdtRowWriterAdd(w, &row);
    }
}

static const MdtConstraintClass angular3Class = {"Angular3", 3, reset, rowCount, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(Angular3, MdtBclANGULAR3, angular3Class)

#define DATA_OR_RETURN(d, j, ret)                                                                    \
    MDT_BCL_JOINT_OR_RETURN(c_, j, MdtBclANGULAR3, ret);                                             \
    Angular3Data *d = MDT_CONSTRAINT_DATA(c_, Angular3Data)

void MdtAngular3EnableRotation(MdtAngular3ID j, MeBool enable)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    d->rotationEnabled = enable ? METRUE : MEFALSE;
}

MeBool MdtAngular3RotationIsEnabled(MdtAngular3ID j)
{
    DATA_OR_RETURN(d, j, MEFALSE);
    return d->rotationEnabled;
}

MDT_BCL_GAIN_PROPERTY(Angular3, MdtBclANGULAR3, Angular3Data, Stiffness, stiffness, stiffness)
MDT_BCL_GAIN_PROPERTY(Angular3, MdtBclANGULAR3, Angular3Data, Damping, damping, damping)
