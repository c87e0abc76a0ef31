/* profiling.c -- how-to "Profiling": where a step's time goes, and the counts that explain it. Two
 * stacks of three boxes stand on the ground; after half a second the world's counters and solver
 * statistics describe the last step. The times vary run to run: they go to stderr, the counts to stdout. */
#include <stdio.h>
#include <karma/karma.h>

static MeMatrix4 groundTM = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}; /* y up */

int main(void)
{
    MstUniverseID universe = MstUniverseCreate(&MstUniverseDefaultSizes);
    MdtWorldID world = MstUniverseGetWorld(universe);
    McdFrameworkID collision = MstUniverseGetFramework(universe);
    MdtWorldSetGravity(world, 0, -9.81, 0);
    MdtWorldSetAutoDisable(world, MEFALSE); /* keep the stacks awake: we measure their cost */
    MstFixedModelCreate(universe, McdPlaneCreate(collision), groundTM);
    for (int stack = 0; stack < 2; stack++)
        for (int i = 0; i < 3; i++) {
            McdModelID box = MstModelAndBodyCreate(universe, McdBoxCreate(collision, 0.5, 0.5, 0.5), 8);
            MdtBodySetPosition(McdModelGetBody(box), (MeReal)(2 * stack), (MeReal)(0.25 + 0.501 * i), 0);
        }
    const int steps = 30;
    for (int step = 0; step < steps; step++)
        MstUniverseStep(universe, 1.0 / 60);

    /* The world times each stage of its step; the universe times collision. Each section's number of
     * calls is fixed by the program, its time is not. */
    const MeProfile *profiles[2] = {MstUniverseGetProfile(universe), MdtWorldGetProfile(world)};
    const char *titles[2] = {"universe (collision)", "world (dynamics)"};
    for (int p = 0; p < 2; p++) {
        printf("%s sections, calls:", titles[p]);
        for (int s = 0; s < MeProfileGetSectionCount(profiles[p]); s++) {
            const MeProfileSection *section = MeProfileGetSectionByIndex(profiles[p], s);
            printf(" %s %lu", section->name, section->calls);
            fprintf(stderr, "%-12s %8.3f ms a step\n", section->name, 1000 * section->totalTime / steps);
        }
        printf("\n");
    }

    /* What the last step had to do: the counts that make a step slow or fast. */
    MdtWorldCounters counters;
    MdtWorldGetCounters(world, &counters);
    MdtSolverStats solver;
    MdtWorldGetSolverStats(world, &solver);
    printf("%lu steps: %d bodies (%d awake), %d constraints (contacts included)\n", counters.steps,
           counters.bodies, counters.enabledBodies, counters.enabledConstraints);
    printf("last step: %d partitions, %d rows, the largest partition %d rows; %d solved exactly\n",
           solver.partitions, solver.rows, solver.maxPartitionRows, solver.directPartitions);
    MstUniverseDestroy(universe);
    return 0;
}
