/* karma_ground.h -- the bridge tests' scene (see karma_ground.c): a universe of default sizes, gravity
 * along -z and a ground plane at z = 0. */
#ifndef KARMA_GROUND_H
#define KARMA_GROUND_H

#include <karma/karma.h>

/** The universe, its parts and the ground. */
typedef struct KarmaGround {
    MstUniverseID u;
    MdtWorldID w;
    MstBridgeID b;
    McdFrameworkID fw;
    MeMatrix4 groundTM;
    McdModelID ground;
} KarmaGround;

/** Creates the universe (MstUniverseDefaultSizes but `massScale`, the bodies' typical mass: ε scales
 *  with 1/massScale), sets gravity to 9.81 m/s² along -z and adds the ground plane; fails the test
 *  when either is refused. */
void karma_ground_init(KarmaGround *s, MeReal massScale);

#endif
