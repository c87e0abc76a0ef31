/* karma_rotor.c -- a body hinged to the world about z, for the hinge and limit tests. */
#include "karma_rotor.h"

#include <stddef.h>

KarmaRotor karma_rotor_make(double I)
{
    KarmaRotor r;
    r.w = MdtWorldCreate(4, 4, 1, 1);
    MdtWorldSetAutoDisable(r.w, MEFALSE);
    r.b = MdtBodyCreate(r.w);
    MdtBodySetSphericalInertiaTensor(r.b, (MeReal)I);
    MdtBodyEnable(r.b);
    r.j = MdtHingeCreate(r.w);
    MdtHingeSetBodies(r.j, r.b, NULL);
    MdtHingeSetPosition(r.j, 0, 0, 0);
    MdtHingeSetAxis(r.j, 0, 0, 1);
    MdtHingeEnable(r.j);
    r.l = MdtHingeGetLimit(r.j);
    return r;
}
