/* hello.c -- drop a ball for one second and print where it is. */
#include <stdio.h>
#include <karma/karma.h>

int main(void)
{
    MdtWorldID world = MdtWorldCreate(10, 10, 1, 1); /* room for 10 bodies; typical size 1 m, mass 1 kg */
    MdtWorldSetGravity(world, 0, -9.81, 0);           /* y is up; gravity is zero until set */
    MdtBodyID ball = MdtBodyCreate(world);            /* a 1 kg body at the origin, created disabled */
    MdtBodySetPosition(ball, 0, 10, 0);
    MdtBodyEnable(ball);
    for (int step = 0; step < 60; step++)
        MdtWorldStep(world, 1.0 / 60);                /* 60 steps of 1/60 s */
    MeVector3 p;
    MdtBodyGetPosition(ball, p);
    printf("%s: the ball fell from 10 m to %.3f m in one second\n", MeToolkitVersionString(), (double)p[1]);
    MdtWorldDestroy(world);
    return 0;
}
