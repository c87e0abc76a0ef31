/* hello_threads.c -- an installed karma::threads from outside: 64 balls fall for one second on a pool of
 * two threads and on the calling thread alone; the program prints both heights, which must agree to
 * the bit (tests/scripts/check_install.cmake). */
#include <stdio.h>
#include <string.h>

#include <karma/karma.h>
#include <MeThreadPool.h>

static double fall(MeThreadPool *pool)
{
    MdtWorldID w = MdtWorldCreate(64, 8, 1, 1);
    MdtWorldSetGravity(w, 0, 0, -9.81f);
    if (pool)
        MeThreadPoolAttachWorld(pool, w);
    MdtBodyID last = NULL;
    for (int i = 0; i < 64; i++) {
        last = MdtBodyCreate(w);
        MdtBodySetPosition(last, (MeReal)i, 0, 10);
        MdtBodyEnable(last);
    }
    for (int step = 0; step < 60; step++)
        MdtWorldStep(w, 1.0f / 60);
    MeVector3 p;
    MdtBodyGetPosition(last, p);
    MdtWorldDestroy(w);
    return (double)p[2];
}

int main(void)
{
    MeThreadPool *pool = MeThreadPoolCreate(2);
    if (!pool)
        return 1;
    double serial = fall(NULL), threaded = fall(pool);
    MeThreadPoolDestroy(pool);
    printf("threads: %.6f m on one thread, %.6f m on %d: %s\n", serial, threaded, 2,
           memcmp(&serial, &threaded, sizeof serial) == 0 ? "bit-identical" : "DIFFERENT");
    return memcmp(&serial, &threaded, sizeof serial) != 0;
}
