/* threads.c -- how-to "Threads": two universes stepped at once on two threads (POSIX threads), each
 * used by its own thread only. Both end bit-identical to the same scene run alone afterwards. */
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

/* What a run ends with: a hash of the bytes of the bodies' positions, and how many boxes fell. */
typedef struct Outcome {
    uint64_t hash;
    int knocked; /* boxes that moved more than half their size sideways */
} Outcome;

/* One thread's work: a universe of its own, a stack of five boxes and a ball thrown at it, stepped
 * for 4 s. Writes the outcome to *(Outcome *)arg. */
static void *simulate(void *arg)
{
    Outcome *outcome = arg;
    enum { BOXES = 5 };
    MstUniverseID universe = MstUniverseCreate(&MstUniverseDefaultSizes);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MdtWorldSetGravity(MstUniverseGetWorld(universe), 0, -9.81, 0);
    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);
    MdtBodyID bodies[BOXES + 1];
    for (int i = 0; i < BOXES; i++) {
        bodies[i] = McdModelGetBody(MstModelAndBodyCreate(universe, McdBoxCreate(collision, 0.5, 0.5, 0.5), 8));
        MdtBodySetPosition(bodies[i], 0, (MeReal)(0.25 + 0.501 * i), 0);
    }
    bodies[BOXES] = McdModelGetBody(MstModelAndBodyCreate(universe, McdSphereCreate(collision, 0.2), 50));
    MdtBodySetPosition(bodies[BOXES], -3, 1.6, 0.1);
    MdtBodySetLinearVelocity(bodies[BOXES], 8, 1, 0);

    for (int step = 0; step < 4 * 60; step++)
        MstUniverseStep(universe, 1.0 / 60);

    outcome->hash = 14695981039346656037u; /* FNV-1a over the bytes of the positions */
    outcome->knocked = 0;
    for (int i = 0; i <= BOXES; i++) {
        MeVector3 p;
        MdtBodyGetPosition(bodies[i], p);
        const unsigned char *bytes = (const unsigned char *)p;
        for (size_t k = 0; k < sizeof p; k++)
            outcome->hash = (outcome->hash ^ bytes[k]) * 1099511628211u;
        if (i < BOXES && p[0] * p[0] + p[2] * p[2] > (MeReal)(0.25 * 0.25))
            outcome->knocked++;
    }
    MstUniverseDestroy(universe);
    return NULL;
}

int main(void)
{
    /* Settings shared by all threads (message handlers, the message level) are set before they start. */
    Outcome together[2], alone;
    pthread_t threads[2];
    for (int t = 0; t < 2; t++)
        if (pthread_create(&threads[t], NULL, simulate, &together[t]) != 0) {
            printf("could not start a thread\n");
            return 1;
        }
    for (int t = 0; t < 2; t++)
        pthread_join(threads[t], NULL);
    simulate(&alone);
    const MeBool same = together[0].hash == together[1].hash, sameAlone = together[0].hash == alone.hash;
    printf("the ball toppled the stack: %d of its 5 boxes moved off their spot\n", alone.knocked);
    printf("two universes on two threads: %s\n", same ? "bit-identical" : "DIFFERENT");
    printf("and the same scene alone on one thread: %s\n", sameAlone ? "bit-identical" : "DIFFERENT");
    return same && sameAlone ? 0 : 1;
}
