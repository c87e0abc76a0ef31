/* falling_box.c -- step 1 of the guide's tutorial: one body falling under gravity, no collision. */
#include <stdio.h>
#include <karma/karma.h>

int main(void)
{
    /* Room for 1 body and 1 constraint; typical length 1 m, typical mass 1 kg (the world's scales). */
    MdtWorldID world = MdtWorldCreate(1, 1, 1, 1);
    MdtWorldSetGravity(world, 0, -9.81, 0); /* y is up; gravity is zero until you set it */

    MdtBodyID box = MdtBodyCreate(world);   /* a new body is disabled: it will not move yet */
    MdtBodySetMass(box, 1);
    MdtBodySetPosition(box, 0, 20, 0);
    MdtBodyEnable(box);                     /* now it takes part in the simulation */

    const MeReal h = 1.0 / 60;              /* seconds per step */
    for (int step = 1; step <= 60; step++) {
        MdtWorldStep(world, h);
        if (step % 15 == 0) {
            MeReal t = (MeReal)step * h;
            MeVector3 p, v;
            MdtBodyGetPosition(box, p);
            MdtBodyGetLinearVelocity(box, v);
            printf("t = %.2f s: height %.3f m (free fall: %.3f m), speed %.4f m/s\n", (double)t, (double)p[1],
                   20 - 9.81 / 2 * (double)t * (double)t, (double)-v[1]);
        }
    }
    MdtWorldDestroy(world);
    return 0;
}
