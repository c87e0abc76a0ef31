/* karma_rotor.h -- the rotor fixture of the hinge and limit tests (see karma_rotor.c). */
#ifndef KARMA_ROTOR_H
#define KARMA_ROTOR_H

#include <karma/Mdt.h>

/** A rotor: body 0 at the origin with the same inertia about every axis, hinged to the world about
 *  z, in a world of its own (room for 4 bodies and 4 constraints, auto-disable off). */
typedef struct KarmaRotor {
    MdtWorldID w;
    MdtBodyID b;
    MdtHingeID j;
    MdtLimitID l; /**< the hinge's limit */
} KarmaRotor;

/** Make the rotor with inertia I (kg m²); free it with MdtWorldDestroy(r.w). */
KarmaRotor karma_rotor_make(double I);

#endif
