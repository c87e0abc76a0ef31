/* karma_terrain.h -- flat tessellated floors for the terrain tests: the same floor z = 0 of the
 * local frame as a triangle mesh, a height field and a triangle list (whose generator serves the
 * mesh's triangles with Karma's edge flags). */
#ifndef KARMA_TERRAIN_H
#define KARMA_TERRAIN_H

#include <karma/Mcd.h>
#include <karma/MeMath.h>

/** A flat floor z = 0 over [-half, half]^2: cells x cells squares, interior vertices moved by up to
 *  jitter (a fraction of a cell) in x and y, each square split along alternating diagonals. */
McdTriangleMeshID karma_floor_mesh(McdFrameworkID fw, double half, int cells, double jitter, unsigned seed);
/** The same floor (no jitter) as a height field of zeros. */
McdRGHeightFieldID karma_floor_field(McdFrameworkID fw, double half, int cells);
/** The mesh's triangles as a triangle list: its generator hands out the triangles near the sphere
 *  asked for, with the mesh's edges in use as kMcdTriangleUseEdge flags (one list at a time). */
McdTriangleListID karma_floor_list(McdFrameworkID fw, McdTriangleMeshID mesh);
/** Calls of the list's generator so far, and the last pair it was given. */
int karma_floor_list_calls(void);
McdModelPair *karma_floor_list_last_pair(void);

#endif /* KARMA_TERRAIN_H */
