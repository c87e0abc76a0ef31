/* karma_pendulum.h -- the pendulum of the joint tests (see karma_pendulum.c): a bob of 1 kg hung
 * from the world at the origin by a joint, released from rest, its period measured. */
#ifndef KARMA_PENDULUM_H
#define KARMA_PENDULUM_H

/** Which joint holds the bob. */
typedef enum KarmaPendulumJoint {
    KARMA_PENDULUM_BALL,  /**< MdtBSJoint at the origin */
    KARMA_PENDULUM_HINGE  /**< MdtHinge at the origin, axis y (the swing plane is x-z) */
} KarmaPendulumJoint;

/** What one swing measured. */
typedef struct KarmaPendulum {
    double period;      /**< s, from the 2nd to the 8th crossing of the vertical (three periods);
                             NaN if the bob crossed fewer than eight times in 60 s */
    double lengthDrift; /**< m, largest | |bob| - L | */
    double axisDrift;   /**< largest of |y| of the bob and the tilt of its y axis out of the hinge axis */
} KarmaPendulum;

/** Swing a bob (mass 1 kg, inertia 1e-3 kg m² about every axis) at length L (m) from angle theta0
 *  (rad) in x-z, under g = 9.81 m/s² along -z, with steps of h s. */
KarmaPendulum karma_pendulum_swing(KarmaPendulumJoint joint, double h, double L, double theta0);

/** The period the bob must show: 2π √((L² + I)/(g L)) with its inertia I = 1e-3, corrected to second
 *  order in the amplitude (1 + θ0²/16). */
double karma_pendulum_expected_period(double L, double theta0);

#endif
