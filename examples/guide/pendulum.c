/* pendulum.c -- step 3 of the guide's tutorial: a joint. A ball hangs from a hinge on the world and
 * swings; its period is measured and compared with the pendulum's small-angle theory. */
#include <math.h>
#include <stdio.h>
#include <karma/karma.h>

int main(void)
{
    const double length = 1.0, g = 9.81;
    MdtWorldID world = MdtWorldCreate(1, 1, 1, 1);
    MdtWorldSetGravity(world, 0, (MeReal)-g, 0);
    MdtWorldSetAutoDisable(world, MEFALSE); /* keep it swinging: never put it to sleep */

    MdtBodyID ball = MdtBodyCreate(world);
    MdtBodySetMass(ball, 1);
    MdtBodySetSphericalInertiaTensor(ball, 0.0001f); /* a small ball: nearly a point mass */
    const double angle = 0.1;                        /* released 0.1 rad from the vertical */
    MdtBodySetPosition(ball, (MeReal)(length * sin(angle)), (MeReal)(2 - length * cos(angle)), 0);
    MdtBodyEnable(ball);

    /* The hinge: at (0, 2, 0), turning about z, joining the ball to the world (body 1 NULL). */
    MdtHingeID hinge = MdtHingeCreate(world);
    MdtHingeSetBodies(hinge, ball, NULL);
    MdtHingeSetPosition(hinge, 0, 2, 0);
    MdtHingeSetAxis(hinge, 0, 0, 1);
    MdtHingeEnable(hinge);

    /* Time the crossings of the vertical (x changes sign): a period is two of them. */
    const MeReal h = 1.0 / 240;
    int crossings = 0;
    double first = 0, last = 0, previousX = length * sin(angle);
    for (int step = 1; step <= 240 * 10; step++) {
        MdtWorldStep(world, h);
        MeVector3 p;
        MdtBodyGetPosition(ball, p);
        if ((previousX > 0) != (p[0] > 0)) {
            double t = step * (double)h - (double)h * (double)p[0] / ((double)p[0] - previousX);
            if (crossings++ == 0)
                first = t;
            last = t;
        }
        previousX = (double)p[0];
    }
    printf("%d crossings in 10 s: period %.3f s; theory 2 pi sqrt(L/g) = %.3f s\n", crossings,
           2 * (last - first) / (crossings - 1), 2 * 3.14159265358979 * sqrt(length / g));
    MdtWorldDestroy(world);
    return 0;
}
