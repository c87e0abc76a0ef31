/* karma_partitions.h -- a universe whose step has many partitions, for the tests of the threaded step. */
#ifndef KARMA_PARTITIONS_H
#define KARMA_PARTITIONS_H

#include <stdint.h>

#include <karma/karma.h>

/** A universe (gravity -9.81 along y, a ground plane, auto-disable off so every partition stays awake)
 *  with `stacks` stacks of `boxes` leaning 0.5 m boxes, 2 m apart, and `chains` pendulum chains of
 *  `links` bodies on ball joints hung from the world: one partition each. NULL if a pool is full. */
MstUniverseID karma_partitions_scene(int stacks, int boxes, int chains, int links);

/** Steps `u` `steps` times by 1/60 s and returns `hash` chained with karma_hash_world after every step
 *  (the state the threaded tests compare with the serial step's, bit for bit). */
uint64_t karma_partitions_step_hash(MstUniverseID u, int steps, uint64_t hash);

#endif
