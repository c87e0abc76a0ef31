/* karma_jacobian.h -- finite-difference checks of constraint Jacobians (see karma_jacobian.c). */
#ifndef KARMA_JACOBIAN_H
#define KARMA_JACOBIAN_H

#include <karma/MdtConstraint.h>

#define KARMA_JACOBIAN_MAX_ROWS 64

/** Largest relative difference, over the constraint's rows, between J·v and the central finite
 *  difference dφ/dt of the row errors, with the bodies' current velocities. Rows that have no
 *  constraint function (motors, friction: error 0 at every pose) pass only if J·v is ~0, so give
 *  such constraints zero velocity along those rows or check them otherwise. */
double karma_jacobian_error(MdtConstraintID c, int *rowsChecked);

/** Random orientation, position within ±spread, and random velocities (MeRealRandomInRange). */
void karma_random_pose(MdtBodyID b, double spread);

#endif
