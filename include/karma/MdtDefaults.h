/* MdtDefaults.h -- the default values of Karma Dynamics, under Karma 1.2's macro names. The library
 * itself takes its defaults from here (tests/mdt/test_mdt_karma12.c compares them with new objects).
 * Scaled values: epsilon by 1/massScale, body mass by massScale, inertia by massScale·lengthScale²,
 * the speed and acceleration thresholds of auto-disable by lengthScale² (decision D1). */
#ifndef MDT_DEFAULTS_H
#define MDT_DEFAULTS_H

#include "MePrecision.h"

#define MDTWORLD_DEFAULT_GRAVITY_X 0
#define MDTWORLD_DEFAULT_GRAVITY_Y 0
#define MDTWORLD_DEFAULT_GRAVITY_Z 0
#define MDTWORLD_DEFAULT_EPSILON ME_R(0.01)
#define MDTWORLD_DEFAULT_GAMMA ME_R(0.2)

/* Auto-disable thresholds on squared magnitudes, and the alive window in seconds. */
#define MDTWORLD_DEFAULT_VEL_THRESH ME_R(0.02)
#define MDTWORLD_DEFAULT_VELROT_THRESH ME_R(0.001)
#define MDTWORLD_DEFAULT_ACC_THRESH ME_R(0.05)
#define MDTWORLD_DEFAULT_ACCROT_THRESH ME_R(0.05)
#define MDTWORLD_DEFAULT_ALIVE_TIME_THRESH ME_R(0.2)
/* Seconds auto-disable averages a body's motion over (not in Karma 1.2, whose test is the last step's:
 * MdtWorldSetAutoDisableAveragingTime, src/mdt/rest_window.c). */
#define MDTWORLD_DEFAULT_AVERAGING_TIME ME_R(0.5)

/* Runaway reports and the contacts' correction speed (not in Karma 1.2; docs/step.md): m/s scaled by
 * lengthScale, rad/s unscaled. */
#define MDTWORLD_DEFAULT_SPEED_LIMIT 1000
#define MDTWORLD_DEFAULT_ANGULAR_SPEED_LIMIT 1000
#define MDTWORLD_DEFAULT_MAX_CORRECTING_VEL 10

/* Matrix capping weights (MdtLODParams, decision K15). */
#define MDTWORLD_DEFAULT_FRICTION_RATIO 0
#define MDTWORLD_DEFAULT_ZERO_ROW_BONUS 150
#define MDTWORLD_DEFAULT_TO_WORLD_BONUS 100
#define MDTWORLD_PENETRATION_BIAS 15
#define MDTWORLD_NORM_VEL_BIAS ME_R(6.5)
#define MDTWORLD_ROW_COUNT_BIAS 40
#define MDTWORLD_DEFAULT_NON_AUTO_BONUS 40

/* A new body: a sphere of mass 1 and radius 1 (times the world's scales), no damping, fast-spin
 * axis y. */
#define MDTBODY_DEFAULT_MASS 1
#define MDTBODY_DEFAULT_INERTIA ME_R(0.4)
#define MDTBODY_DEFAULT_LINEAR_DAMPING 0
#define MDTBODY_DEFAULT_ANGULAR_DAMPING 0
#define MDTBODY_DEFAULT_FAST_SPIN_X 0
#define MDTBODY_DEFAULT_FAST_SPIN_Y 1
#define MDTBODY_DEFAULT_FAST_SPIN_Z 0

/* Skeletal joint limit angles (decision D6). */
#define MDTSKELETAL_DEFAULT_TWIST_ANGLE (ME_PI / 4)
#define MDTSKELETAL_DEFAULT_PRI_ANGLE (ME_PI / 4)
#define MDTSKELETAL_DEFAULT_SEC_ANGLE (ME_PI / 4)

#endif /* MDT_DEFAULTS_H */
