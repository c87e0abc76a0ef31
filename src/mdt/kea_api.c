/* kea_api.c -- what remains of Karma 1.2's Kea API (MdtKea.h): the workspace estimate, the CPU
 * query and the cache calls that were needed on PlayStation 2 only. */
#include <limits.h>

#include <karma/MdtKea.h>

#include "../me/check.h"
#include "kea/kea.h"
#include "kea/kea_tuning.h"

/* The one processor description: the portable C solver. */
struct MeCPUResourcesData {
    const char *solver;
};
static const struct MeCPUResourcesData portableC = {"portable C"};

MeCPUResources MdtKeaQueryCPUResources(void) { return (MeCPUResources)(uintptr_t)&portableC; }

/* The world solves its partitions one after the other in one workspace, sized for the largest
 * (src/mdt/solve_partitions.c), each by the method its size gets under the default solver settings. */
int MdtKeaMemoryRequired(const int num_rows_exc_padding[], int num_partitions, int max_rows, int max_bodies)
{
    if (num_partitions < 0 || max_rows < 0 || max_bodies < 0) {
        ME_REPORT(ME_ERR_ARGUMENT_RANGE, "counts must not be negative (num_partitions %d, max_rows %d, max_bodies %d)",
                  num_partitions, max_rows, max_bodies);
        return -1;
    }
    KeaParameters defaults;
    KeaParametersDefault(&defaults);
    defaults.autoPivotsPerRow = KEA_AUTO_PIVOTS_PER_ROW; /* the world's: its small partitions may go either way */
    size_t need = 0;
    for (int p = 0; p < num_partitions; p++) {
        int rows = num_rows_exc_padding ? num_rows_exc_padding[p] : max_rows;
        if (rows < 0 || rows > max_rows) {
            ME_REPORT(ME_ERR_ARGUMENT_RANGE, "num_rows_exc_padding[%d] (%d) must lie in [0, max_rows = %d]", p, rows,
                      max_rows);
            return -1;
        }
        if (rows == 0)
            continue; /* a partition without rows is not solved */
        size_t bytes = KeaMemoryRequired(rows, max_bodies, KeaSelectPath(rows, &defaults));
        if (bytes > need)
            need = bytes;
    }
    return need > (size_t)INT_MAX ? INT_MAX : (int)need;
}

void MdtFlushCache(int mode) { (void)mode; }

void MdtSyncDCache(void *start, void *end)
{
    (void)start;
    (void)end;
}

void MdtInvalidDCache(void *start, void *end)
{
    (void)start;
    (void)end;
}
