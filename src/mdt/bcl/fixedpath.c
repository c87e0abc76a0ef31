/* fixedpath.c -- the fixed-path joint: its API and its rows (3: a ball and socket whose attachment
 * points move along prescribed paths). With V_i the velocity of attachment i along its path, relative
 * to body i, φ = p0 − p1 changes at J·v + V0 − V1; the rows ask for dφ/dt = 0, i.e. the target
 * velocity c_k = e_k·(V1 − V0), so the joint follows the path in the step instead of a step late. */
#include <karma/MdtFixedPath.h>

#include "../../me/check.h"
#include "joint_parts.h"

typedef struct FixedPathData {
    MeVector3 velocity[2]; /* path velocity of each attachment, in its body's frame */
} FixedPathData;
MDT_CONSTRAINT_DATA_FITS(FixedPathData);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    FixedPathData *d = MDT_CONSTRAINT_DATA(c, FixedPathData);
    MeVector3Set(d->velocity[0], 0, 0, 0);
    MeVector3Set(d->velocity[1], 0, 0, 0);
}

static void worldVelocity(const MdtConstraintData *c, int index, MeVector3 out)
{
    const FixedPathData *d = MDT_CONSTRAINT_DATA(c, const FixedPathData);
    if (c->body[index])
        MeMatrix4TMRotate(out, c->body[index]->bodyTM, d->velocity[index]);
    else
        MeVector3Copy(out, d->velocity[index]);
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    MeVector3 v0, v1;
    worldVelocity(c, 0, v0);
    worldVelocity(c, 1, v1);
    for (int k = 0; k < 3; k++) {
        MdtRow row;
        MeVector3 e = {0, 0, 0};
        e[k] = 1;
        MdtRowInit(&row);
        MdtBclPointAlongRow(&row, c, e, MEFALSE);
        row.velocity = v1[k] - v0[k];
        MdtRowWriterAdd(w, &row);
    }
}

static const MdtConstraintClass fixedPathClass = {"FixedPath", 3, reset, NULL, addRows, NULL, NULL};

MDT_BCL_TYPE_FUNCTIONS(FixedPath, MdtBclFIXEDPATH, fixedPathClass)

void MdtFixedPathSetPosition(MdtFixedPathID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclFIXEDPATH, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    if (!MdtBclCheckBodyIndex(bodyindex, __func__))
        return;
    MeVector3 p = {x, y, z};
    MdtConstraintToBodyPoint(c, (int)bodyindex, p, c->position[bodyindex]);
}

void MdtFixedPathGetPosition(MdtFixedPathID j, unsigned int bodyindex, MeVector3 p)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclFIXEDPATH, ME_NOTHING);
    ME_CHECK_NOT_NULL(p, ME_NOTHING);
    if (MdtBclCheckBodyIndex(bodyindex, __func__))
        MdtConstraintWorldPosition(c, (int)bodyindex, p);
}

void MdtFixedPathSetVelocity(MdtFixedPathID j, unsigned int bodyindex, MeReal x, MeReal y, MeReal z)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclFIXEDPATH, ME_NOTHING);
    ME_CHECK_FINITE3(x, y, z, ME_NOTHING);
    if (!MdtBclCheckBodyIndex(bodyindex, __func__))
        return;
    MeVector3 v = {x, y, z};
    MdtConstraintToBodyVector(c, (int)bodyindex, v, MDT_CONSTRAINT_DATA(c, FixedPathData)->velocity[bodyindex]);
}

void MdtFixedPathGetVelocity(MdtFixedPathID j, unsigned int bodyindex, MeVector3 v)
{
    MDT_BCL_JOINT_OR_RETURN(c, j, MdtBclFIXEDPATH, ME_NOTHING);
    ME_CHECK_NOT_NULL(v, ME_NOTHING);
    if (MdtBclCheckBodyIndex(bodyindex, __func__))
        worldVelocity(c, (int)bodyindex, v);
}
