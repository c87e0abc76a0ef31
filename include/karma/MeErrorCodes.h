/* MeErrorCodes.h -- every message code Karma can report, in one list.
 *
 * Each entry is X(name, number, level, text). Numbers are stable: never renumber or reuse one; add new
 * codes at the end of their layer's block. Ranges: Me 1-99, Mdt 100-299, Kea 300-399, Mcd 400-599,
 * Mst 600-699, tools and viewer 700-799. A message handler receives the code, its level, the name of
 * the API function the caller used, and a sentence that names the offending argument. */
#ifndef ME_ERROR_CODES_H
#define ME_ERROR_CODES_H

/* clang-format off */
#define ME_ERROR_LIST_ME(X) \
    X(ME_ERR_NONE,               0, ME_LEVEL_INFO,    "no error") \
    X(ME_ERR_USER_MESSAGE,       1, ME_LEVEL_INFO,    "message sent by the application through MeWarning/MeInfo/...") \
    X(ME_ERR_OUT_OF_MEMORY,      2, ME_LEVEL_WARNING, "the memory API could not allocate a block") \
    X(ME_ERR_NULL_ARGUMENT,      3, ME_LEVEL_WARNING, "a required pointer or handle argument is NULL") \
    X(ME_ERR_INVALID_HANDLE,     4, ME_LEVEL_WARNING, "a handle refers to an object that was destroyed, or is not a handle at all") \
    X(ME_ERR_FOREIGN_HANDLE,     5, ME_LEVEL_WARNING, "a handle belongs to another world, framework or space than the one it is used with") \
    X(ME_ERR_WRONG_HANDLE_KIND,  6, ME_LEVEL_WARNING, "a handle of one kind was passed where another kind is expected") \
    X(ME_ERR_NONFINITE_ARGUMENT, 7, ME_LEVEL_WARNING, "an argument is NaN or infinite") \
    X(ME_ERR_ARGUMENT_RANGE,     8, ME_LEVEL_WARNING, "an argument is outside its valid range") \
    X(ME_ERR_POOL_FULL,          9, ME_LEVEL_WARNING, "a fixed-size pool is full; raise the size named in the message") \
    X(ME_ERR_CHUNK_GROWTH,      10, ME_LEVEL_INFO,    "a scratch chunk grew; pre-size it to avoid allocation during the step") \
    X(ME_ERR_INTERNAL,          11, ME_LEVEL_FATAL,   "internal inconsistency: a bug in Karma, please report it") \
    X(ME_ERR_TOO_MANY_OWNERS,   12, ME_LEVEL_WARNING, "too many worlds, frameworks or spaces exist at once") \
    X(ME_ERR_BAD_STATE,         13, ME_LEVEL_WARNING, "the call is not allowed in the object's current state") \
    X(ME_ERR_PROFILE_SECTIONS,  14, ME_LEVEL_WARNING, "a profile has no room for another named section") \
    X(ME_ERR_PROFILE_NESTING,   15, ME_LEVEL_WARNING, "profile sections were ended in a different order from the one they were started in")

#define ME_ERROR_LIST_MDT(X) \
    X(ME_ERR_MASS_NOT_POSITIVE,     100, ME_LEVEL_WARNING, "a mass is zero or negative") \
    X(ME_ERR_INERTIA_INVALID,       101, ME_LEVEL_WARNING, "an inertia tensor is not symmetric positive definite") \
    X(ME_ERR_NEGATIVE_DAMPING,      102, ME_LEVEL_WARNING, "a damping coefficient is negative") \
    X(ME_ERR_ZERO_AXIS,             103, ME_LEVEL_WARNING, "an axis or direction has zero length") \
    X(ME_ERR_QUATERNION_NOT_UNIT,   104, ME_LEVEL_WARNING, "a quaternion is not of unit length within tolerance") \
    X(ME_ERR_STEP_SIZE,             105, ME_LEVEL_WARNING, "a time step is not finite or below the minimum MDT_MIN_STEP_SIZE (1e-6 s)") \
    X(ME_ERR_NONFINITE_STATE,       106, ME_LEVEL_WARNING, "the simulation produced a NaN or infinite value; the partition was disabled") \
    X(ME_ERR_SCALE_NOT_POSITIVE,    107, ME_LEVEL_WARNING, "a length or mass scale is zero, negative or not finite") \
    X(ME_ERR_NEGATIVE_VALUE,        108, ME_LEVEL_WARNING, "a value that must be zero or positive is negative") \
    X(ME_ERR_NOT_ROTATION,          109, ME_LEVEL_WARNING, "a matrix is not a rotation (orthonormal, right-handed) within tolerance") \
    X(ME_ERR_WORLD_LOCKED,          110, ME_LEVEL_WARNING, "the world is stepping; this change is not allowed from a callback") \
    X(ME_ERR_MASS_RATIO,            111, ME_LEVEL_INFO,    "an inertia is far (over 100x) from the world's scale (0.4 massScale lengthScale^2); expect poor accuracy (reported once per world)") \
    X(ME_ERR_BODY_INDEX,            112, ME_LEVEL_WARNING, "a body index must be 0 or 1") \
    X(ME_ERR_SPEED_LIMIT,           113, ME_LEVEL_WARNING, "a body moves or spins faster than the world's speed limit (reported once until it is back under it)") \
    X(ME_ERR_ENERGY_JUMP,           114, ME_LEVEL_WARNING, "a partition's kinetic energy jumped in one step beyond what its applied forces can give; the simulation is running away") \
    X(ME_ERR_LIMIT_ORDER,           115, ME_LEVEL_WARNING, "a joint limit's lower stop lies above its upper stop") \
    X(ME_ERR_PARALLEL_AXES,         116, ME_LEVEL_WARNING, "a constraint's primary and secondary axes are parallel") \
    X(ME_ERR_NO_BODY_ENABLED,       130, ME_LEVEL_WARNING, "hint: the world has bodies but none is enabled (bodies are created disabled), so nothing moves; once per world, MdtWorldSetHints silences it") \
    X(ME_ERR_NOTHING_ACTS,          131, ME_LEVEL_WARNING, "hint: gravity is zero and nothing acts on the enabled bodies, so nothing moves (and they fall asleep); once per world, MdtWorldSetHints silences it") \
    X(ME_ERR_MASS_SCALE,            132, ME_LEVEL_WARNING, "a mass is far (over 100x) from the world's massScale: contacts and joints turn soft; set massScale to a typical mass (reported once per world)") \
    X(ME_ERR_TASK_CALLBACK,        140, ME_LEVEL_WARNING, "a task system was given without its enqueue or finish callback; the world keeps its task system") \
    X(ME_ERR_WORKER_COUNT,         141, ME_LEVEL_WARNING, "a worker or thread count is below 1 or above MDT_MAX_WORKERS (64); nothing changed") \
    X(ME_ERR_TASK_WORKER,          142, ME_LEVEL_WARNING, "the task system left work undone or gave a worker index outside 0 to workerCount - 1: that work ran on the stepping thread") \
    X(ME_ERR_THREAD_START,         143, ME_LEVEL_WARNING, "a thread of a thread pool could not be started; no pool was made")

#define ME_ERROR_LIST_KEA(X) \
    X(ME_ERR_KEA_MAX_ITERATIONS,    300, ME_LEVEL_DEBUG,   "the LCP solver stopped at its iteration cap; the result is approximate") \
    X(ME_ERR_KEA_WORKSPACE,         301, ME_LEVEL_WARNING, "the LCP solver's workspace is too small")

#define ME_ERROR_LIST_MCD(X) \
    X(ME_ERR_MCD_DEGENERATE_GEOMETRY, 400, ME_LEVEL_WARNING, "a geometry dimension is zero, negative or not finite") \
    X(ME_ERR_MCD_IN_USE,              401, ME_LEVEL_WARNING, "the object is still in use and cannot be destroyed") \
    X(ME_ERR_MCD_NO_INTERACTION,      402, ME_LEVEL_WARNING, "no pair test is registered for two geometry types: their pairs give no contacts (reported once per type pair)") \
    X(ME_ERR_MCD_SIZE_RANGE,          403, ME_LEVEL_WARNING, "a geometry dimension is outside 1e-6 to 1e6 times the framework's lengthScale") \
    X(ME_ERR_MCD_POSITION_RANGE,      404, ME_LEVEL_WARNING, "a model position or segment end point is farther than 1e7 times the framework's lengthScale from the origin") \
    X(ME_ERR_MCD_HULL_FLAT,           405, ME_LEVEL_WARNING, "a convex hull's points span no volume: fewer than four, or all within the hull tolerance of a line or a plane") \
    X(ME_ERR_MCD_BAD_MESH,            420, ME_LEVEL_WARNING, "a triangle mesh or height field is empty, has an index out of range, a count out of range or a height or vertex that is not finite") \
    X(ME_ERR_MCD_DEGENERATE_TRIANGLE, 421, ME_LEVEL_WARNING, "a triangle of a mesh has no area (its vertices coincide or lie on a line)") \
    X(ME_ERR_MCD_BAD_IMAGE,           422, ME_LEVEL_WARNING, "a height image cannot be read or is not an uncompressed 24-bit BMP of at least 2 x 2 pixels") \
    X(ME_ERR_MCD_AGGREGATE_FULL,      430, ME_LEVEL_WARNING, "an aggregate's element slots (maxChildren) are all in use") \
    X(ME_ERR_MCD_AGGREGATE_INDEX,     431, ME_LEVEL_WARNING, "an aggregate element index is out of range or names an empty slot") \
    X(ME_ERR_MCD_AGGREGATE_TRANSFORM, 432, ME_LEVEL_WARNING, "an aggregate element's relative transform is not finite, not rigid or out of range") \
    X(ME_ERR_MCD_AGGREGATE_CYCLE,     433, ME_LEVEL_WARNING, "an aggregate would contain itself, or nest deeper than 16 levels") \
    X(ME_ERR_MCD_AGGREGATE_MASS,      434, ME_LEVEL_WARNING, "an aggregate has an element without finite volume (plane, terrain, empty aggregate): no mass properties") \
    X(ME_ERR_MCD_SAFE_TIME_RANGE,     440, ME_LEVEL_WARNING, "a safe-time or sweep duration is negative or not finite") \
    X(ME_ERR_MCD_SAFE_TIME_VELOCITY,  441, ME_LEVEL_WARNING, "a model velocity or sweep motion for a safe time is not finite") \
    X(ME_ERR_MCD_CONTINUOUS_GEOMETRY, 442, ME_LEVEL_WARNING, "continuous collision asked for a model whose geometry cannot be swept (plane, terrain, aggregate, null or user type)") \
    X(ME_ERR_MCD_HULL_INCONSISTENT,   443, ME_LEVEL_WARNING, "an McdConvexHull's counts, sentinels, indices, face rings, reverse edges or vertex edge order disagree: not a closed polyhedron") \
    X(ME_ERR_MCD_HULL_NOT_CONVEX,     444, ME_LEVEL_WARNING, "an McdConvexHull is not convex: a vertex off its face's plane or in front of another face, a reflex polygon corner, or a face normal not unit or against its winding")

#define ME_ERROR_LIST_MST(X) \
    X(ME_ERR_MST_MATERIAL,            600, ME_LEVEL_WARNING, "a material index is out of range")

/* The viewer's (karma_viewer) own codes. */
#define ME_ERROR_LIST_VIEWER(X) \
    X(ME_ERR_VIEWER_BAD_MEG,          700, ME_LEVEL_WARNING, "a .meg object file cannot be opened, read or written, or is not a vertex count (a positive multiple of 3) followed by exactly that many vertices of 8 finite numbers")

#define ME_ERROR_LIST(X) ME_ERROR_LIST_ME(X) ME_ERROR_LIST_MDT(X) ME_ERROR_LIST_KEA(X) ME_ERROR_LIST_MCD(X) ME_ERROR_LIST_MST(X) ME_ERROR_LIST_VIEWER(X)
/* clang-format on */

#endif /* ME_ERROR_CODES_H */
