/* userconstraint.c -- the user constraint: its API, and the bridge from the application's rows
 * (MdtUserConstraintRow, public and stable) to the internal MdtRow of the row writer. */
#include <string.h>

#include <karma/MdtUserConstraint.h>

#include "../world.h"
#include "joint_parts.h"

typedef struct UserData {
    MdtUserConstraintRowsFn fn;
    void *constraintStruct;
    int maxRows;
    MeReal force[MDT_USER_CONSTRAINT_MAX_ROWS];
} UserData;
MDT_CONSTRAINT_DATA_FITS(UserData);

static void reset(MdtConstraintData *c)
{
    MdtConstraintResetFrames(c);
    UserData *d = MDT_CONSTRAINT_DATA(c, UserData);
    memset(d, 0, sizeof *d);
    d->maxRows = MDT_MAX_JOINT_ROWS;
}

static int rowCount(const MdtConstraintData *c)
{
    const UserData *d = MDT_CONSTRAINT_DATA(c, const UserData);
    return d->fn ? d->maxRows : 0;
}

static MeBool rowIsValid(const MdtUserConstraintRow *u)
{
    const MeReal *v[4] = {u->linear0, u->angular0, u->linear1, u->angular1};
    for (int i = 0; i < 4; i++)
        if (!MeVector3IsValid(v[i]))
            return MEFALSE;
    return ME_IS_FINITE(u->velocity) && ME_IS_FINITE(u->error) && !isnan(u->lo) && !isnan(u->hi) &&
           !isnan(u->stiffness) && !isnan(u->damping);
}

static void addRows(MdtConstraintData *c, MdtRowWriter *w)
{
    UserData *d = MDT_CONSTRAINT_DATA(c, UserData);
    if (!d->fn)
        return;
    MdtUserConstraintRow rows[MDT_USER_CONSTRAINT_MAX_ROWS];
    memset(rows, 0, sizeof rows);
    for (int i = 0; i < d->maxRows; i++) {
        rows[i].lo = -MEINFINITY;
        rows[i].hi = MEINFINITY;
        rows[i].stiffness = MEINFINITY;
    }
    MdtBclSolverParameters params = {w->h, w->epsilon0, w->gamma};
    int n = d->fn((MdtUserConstraintID)c->id, rows, d->maxRows, &params, d->constraintStruct);
    if (n < 0 || n > d->maxRows) {
        ME_REPORT_IN("MdtWorldStep", ME_ERR_ARGUMENT_RANGE, "the %s's function returned %d rows; it may write 0 ... %d (rows dropped)",
                  c->cls->name, n, d->maxRows);
        n = n < 0 ? 0 : d->maxRows;
    }
    for (int i = 0; i < n; i++) {
        const MdtUserConstraintRow *u = &rows[i];
        if (!rowIsValid(u)) {
            ME_REPORT_IN("MdtWorldStep", ME_ERR_NONFINITE_ARGUMENT, "row %d of the user constraint is not finite; row left out", i);
            continue;
        }
        if (u->lo > u->hi || u->stiffness < 0 || u->damping < 0) {
            ME_REPORT_IN("MdtWorldStep", ME_ERR_ARGUMENT_RANGE,
                      "row %d of the user constraint has lo > hi or a negative stiffness or damping; row left out", i);
            continue;
        }
        MdtRow row;
        MdtRowInit(&row);
        MeVector3Copy(row.lin0, u->linear0);
        MeVector3Copy(row.ang0, u->angular0);
        MeVector3Copy(row.lin1, u->linear1);
        MeVector3Copy(row.ang1, u->angular1);
        row.velocity = u->velocity;
        row.error = u->error;
        row.lo = u->lo;
        row.hi = u->hi;
        if (MdtBclRowSpring(&row, c, u->stiffness, u->damping, w->h))
            MdtRowWriterAdd(w, &row);
    }
}

static void unpack(MdtConstraintData *c, const MeReal *impulses, int rows, MeReal h)
{
    UserData *d = MDT_CONSTRAINT_DATA(c, UserData);
    for (int i = 0; i < MDT_USER_CONSTRAINT_MAX_ROWS; i++)
        d->force[i] = i < rows ? impulses[i] / h : 0;
}

static const MdtConstraintClass userClass = {"UserConstraint", MDT_USER_CONSTRAINT_MAX_ROWS, reset, rowCount, addRows,
                                             unpack, NULL};

MDT_BCL_TYPE_FUNCTIONS(UserConstraint, MdtBclUSER, userClass)

#define DATA_OR_RETURN(d, j, ret)                                                                    \
    MDT_BCL_JOINT_OR_RETURN(c_, j, MdtBclUSER, ret);                                                 \
    UserData *d = MDT_CONSTRAINT_DATA(c_, UserData)

void MdtUserConstraintSetAddConstraintFunction(MdtUserConstraintID j, MdtUserConstraintRowsFn fn)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    if (c_->world->locked) {
        ME_REPORT_IN("MdtWorldStep", ME_ERR_WORLD_LOCKED, "the function of a user constraint cannot change during the step");
        return;
    }
    d->fn = fn;
}

MdtUserConstraintRowsFn MdtUserConstraintGetAddConstraintFunction(MdtUserConstraintID j)
{
    DATA_OR_RETURN(d, j, NULL);
    return d->fn;
}

void MdtUserConstraintSetConstraintStruct(MdtUserConstraintID j, void *constraintStruct)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    d->constraintStruct = constraintStruct;
}

void *MdtUserConstraintGetConstraintStruct(MdtUserConstraintID j)
{
    DATA_OR_RETURN(d, j, NULL);
    return d->constraintStruct;
}

void MdtUserConstraintSetMaxRows(MdtUserConstraintID j, int maxRows)
{
    DATA_OR_RETURN(d, j, ME_NOTHING);
    if (maxRows < 1 || maxRows > MDT_USER_CONSTRAINT_MAX_ROWS) {
        ME_REPORT_IN("MdtWorldStep", ME_ERR_ARGUMENT_RANGE, "argument 'maxRows' (%d) must lie in 1 ... %d", maxRows,
                  MDT_USER_CONSTRAINT_MAX_ROWS);
        return;
    }
    if (c_->world->locked) {
        ME_REPORT_IN("MdtWorldStep", ME_ERR_WORLD_LOCKED, "the row count of a user constraint cannot change during the step");
        return;
    }
    d->maxRows = maxRows;
}

int MdtUserConstraintGetMaxRows(MdtUserConstraintID j)
{
    DATA_OR_RETURN(d, j, 0);
    return d->maxRows;
}

MeReal MdtUserConstraintGetRowForce(MdtUserConstraintID j, int row)
{
    DATA_OR_RETURN(d, j, 0);
    if (row < 0 || row >= MDT_USER_CONSTRAINT_MAX_ROWS) {
        ME_REPORT_IN("MdtWorldStep", ME_ERR_ARGUMENT_RANGE, "argument 'row' (%d) must lie in 0 ... %d", row,
                  MDT_USER_CONSTRAINT_MAX_ROWS - 1);
        return 0;
    }
    return d->force[row];
}
