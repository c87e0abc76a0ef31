/* threads.c -- how-to "Threads": two universes stepped at once on two threads (POSIX threads), each
 * used by its own thread only. Both end bit-identical to the same scene run alone afterwards. */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

/* One thread's work: a universe of its own, a stack of five boxes and a ball thrown at it, stepped
 * for 4 s. Writes the end state's summary (a hash of the bodies' positions' bytes) to *arg. */
static void *simulate(void *arg)
{
    enum { BOXES = 5 };
    MstUniverseID universe = MstUniverseCreate(&MstUniverseDefaultSizes);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MdtWorldSetGravity(MstUniverseGetWorld(universe), 0, -9.81, 0);
    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);
    MdtBodyID bodies[BOXES + 1];
    for (int i = 0; i < BOXES; i++) {
        bodies[i] = McdModelGetBody(MstModelAndBodyCreate(universe, McdBoxCreate(collision, 0.5, 0.5, 0.5), 8));
        MdtBodySetPosition(bodies[i], 0, 0.25f + 0.501f * (MeReal)i, 0);
    }
    bodies[BOXES] = McdModelGetBody(MstModelAndBodyCreate(universe, McdSphereCreate(collision, 0.2), 50));
    MdtBodySetPosition(bodies[BOXES], -3, 1.6, 0.1);
    MdtBodySetLinearVelocity(bodies[BOXES], 8, 1, 0);

    for (int step = 0; step < 4 * 60; step++)
        MstUniverseStep(universe, 1.0 / 60);

    uint64_t hash = 14695981039346656037u; /* FNV-1a over the bytes of the positions */
    for (int i = 0; i <= BOXES; i++) {
        MeVector3 p;
        MdtBodyGetPosition(bodies[i], p);
        const unsigned char *bytes = (const unsigned char *)p;
        for (size_t k = 0; k < sizeof p; k++)
            hash = (hash ^ bytes[k]) * 1099511628211u;
    }
    MstUniverseDestroy(universe);
    *(uint64_t *)arg = hash;
    return NULL;
}

int main(void)
{
    /* Settings shared by all threads (message handlers, the message level) are set before they start. */
    uint64_t together[2], alone;
    pthread_t threads[2];
    for (int t = 0; t < 2; t++)
        if (pthread_create(&threads[t], NULL, simulate, &together[t]) != 0) {
            printf("could not start a thread\n");
            return 1;
        }
    for (int t = 0; t < 2; t++)
        pthread_join(threads[t], NULL);
    simulate(&alone);
    printf("two universes on two threads: %s\n", together[0] == together[1] ? "bit-identical" : "DIFFERENT");
    printf("and the same scene alone on one thread: %s\n", together[0] == alone ? "bit-identical" : "DIFFERENT");
    return together[0] == together[1] && together[0] == alone ? 0 : 1;
}
