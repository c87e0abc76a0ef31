/* MdtKea.h -- Karma 1.2's header of the Kea solver: what of it a program can use here.
 *
 * 1.2's Kea was called per step on arrays the main loop built (MdtKeaConstraints, MdtKeaBody,
 * MdtKeaTransformation, MdtKeaParameters). Here the world builds and solves its rows itself: the
 * stages of MdtMainLoop.h (MdtKeaSolve, MdtKeaIntegrate) replace 1.2's MdtKeaAddConstraintForces and
 * MdtKeaIntegrateSystem, which are not declared (decision K16, docs/api_changes.md). What remains is
 * the workspace estimate, the CPU query, the debug request type and the cache calls. */
#ifndef MDT_KEA_H
#define MDT_KEA_H

#include "MePrecision.h"

ME_EXTERN_C_BEGIN

/** The most bodies one constraint acts on. */
#define MdtKeaMAXBODYCONSTRAINT 2

/** What the solver found about the processor (opaque). */
typedef struct MeCPUResourcesData *MeCPUResources;

/** Karma 1.2's request for Kea's input, intermediate and output data to be written to (or its input
 *  read from) files, for one frame and partition. Kept by MdtWorldSetKeaDebugRequest; this solver
 *  writes and reads no such files (a request for them is reported once). */
typedef struct MdtKeaDebugDataRequest {
    MeBool writeKeaInputData;
    char *writeKeaInputDataFilename;
    MeBool readKeaInputData;
    char *readKeaInputDataFilename;
    MeBool writeKeaInterData;
    char *writeKeaInterDataFilename;
    MeBool writeKeaOutputData;
    char *writeKeaOutputDataFilename;
    int frame;        /**< the current frame, set by the application */
    int badFrame;     /**< the frame to investigate */
    int badPartition; /**< the partition to investigate */
} MdtKeaDebugDataRequest;

/** The processor as the solver uses it. There is one portable C path, so this is always the same
 *  non-NULL value. */
ME_API MeCPUResources MdtKeaQueryCPUResources(void);

/** Bytes of workspace the solver needs to solve partitions of num_rows_exc_padding[0 ...
 *  num_partitions−1] rows one after the other, none with more than max_rows rows or max_bodies
 *  bodies, each by the method the default solver settings give it (MdtLCPSolverAuto, 128 direct
 *  rows): what the world's "Kea workspace" chunk (MdtWorldGetKeaPoolChunk) grows to for such a step,
 *  or a little more. A world set to MdtLCPSolverIterative may need up to twice as much.
 *  num_rows_exc_padding may be NULL (every partition then has max_rows rows). −1 (reported) for
 *  negative counts; INT_MAX when the size does not fit an int. */
ME_API int MdtKeaMemoryRequired(const int num_rows_exc_padding[], int num_partitions, int max_rows, int max_bodies);

/* Data-cache maintenance that Karma 1.2 needed on PlayStation 2, where the solver's arrays went to the
 * vector units by DMA and the CPU's data cache had to be written back or invalidated first. Here the
 * solver runs on the CPU, whose caches are coherent with memory: there is nothing to flush or
 * invalidate, and these do nothing. */
/** Write back the data cache (no-op here). */
ME_API void MdtFlushCache(int mode);
/** Write back the cache lines of [start, end) (no-op here). */
ME_API void MdtSyncDCache(void *start, void *end);
/** Invalidate the cache lines of [start, end) (no-op here). */
ME_API void MdtInvalidDCache(void *start, void *end);

ME_EXTERN_C_END

#endif /* MDT_KEA_H */
