/* karma_heap.h -- the heap of test_heap_sleep (see karma_heap.c), also built by tools/heap_sleep from
 * other seeds and sizes. Needs only the library (no cmocka), so a tool can compile it in. */
#ifndef KARMA_HEAP_H
#define KARMA_HEAP_H

#include <karma/karma.h>

/** Creates a universe of `n` boxes of edges 0.9 to 1.1 m (one dynamic body each, 1 kg/m³, massScale
 *  1), drawn from `seed`, placed 16 to a layer on a 4 x 4 grid 1.6 m apart with layers 1.6 m apart
 *  (no two overlap) at random orientations above a ground plane, gravity 9.81 m/s² along -z, friction
 *  μ = 0.6 (2D, normal-force model); the bodies go to body[0..n). Returns NULL when the universe is
 *  refused. The world's auto-disable keeps its defaults. */
MstUniverseID karma_heap_build(int n, unsigned long long seed, MdtBodyID *body);

#endif
