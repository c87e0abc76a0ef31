/* bench_scenes_build.h -- the builder helpers bench_scenes.c shares with the scene set of others'
 * making (bench_scenes_others.c). Private to bench/scenes: engines and tests use bench_scenes.h. */
#ifndef KARMA_BENCH_SCENES_BUILD_H
#define KARMA_BENCH_SCENES_BUILD_H

#include "bench_scenes.h"

extern const double kIdentity[4];
extern const double kAxisY[3];
extern const double kAxisZ[3];

/** A new scene called `prefix` when count == standard, else prefix + count; room for maxBodies bodies
 *  and maxJoints joints; ground on, gravity, step and friction the common ones, 600 steps. */
BenchScene *scene_new(const char *prefix, int count, int standard, int maxBodies, int maxJoints);
/** Appends a body (sizes as BenchBody.size); returns its index. */
int add_body(BenchScene *s, BenchShape shape, double a, double b, double c, double mass, const double pos[3],
             const double quat[4], int fixed);
/** Appends a joint; a hinge is limited when lo <= hi. */
void add_joint(BenchScene *s, BenchJointType type, int b0, int b1, const double anchor[3], const double axis[3],
               double lo, double hi);
/** Fills the joints' local anchors and the dynamic body count: call once, after the last body. */
void scene_finish(BenchScene *s);
/** Deterministic jitter in [-1, 1) from a 64-bit LCG state. */
double jitter(unsigned long long *state);
/** Lowest height of a body at the given pose (m). */
double body_lowest_y(const BenchBody *b, const double pos[3], const double quat[4]);
/** Appends one 11-body ragdoll turned by q, over `place` (x, z), lifted so that its lowest point is
 *  `lowest` m above y = 0; returns the index of its first body (the pelvis). */
int add_ragdoll(BenchScene *s, const double q[4], const double place[3], double lowest);
/** The ragdolls scene's orientation of its k-th ragdoll (golden-angle yaw, tilt 0.3 to 1.5 rad). */
void ragdoll_tilt(double q[4], int k);
/** "prefix" or "prefixN" -> N (`fallback` without a number); -1 when the name does not match. */
int parse_count(const char *name, const char *prefix, int fallback);
/** A scene of the set of others' making by name (bench_scenes_others.c); NULL when unknown. */
BenchScene *BenchSceneOthersCreate(const char *name);

#endif
