/* Seams: where static shapes touch (floor tiles, a terrain of boxes, the
 * convex pieces of a concave static polygon), the edges they share are
 * internal. Nothing can come through an internal edge, so no contact takes
 * one as its face, and a circle meets the vertex next to one as the
 * continuation of the other face (collide.h): a body sliding or rolling
 * over the seam keeps its speed instead of catching on the corner (a ghost
 * collision). */
#ifndef CAROM_SEAMS_H
#define CAROM_SEAMS_H

#include <stdint.h>

struct carom_world;

/* Mark the internal edges of every static piece (convex_piece.internal),
 * after static bodies were added, removed or moved (world->seams_dirty). */
void seams_update (struct carom_world *world);

struct shape;
/* The internal edges of a polygon's whole outline (bit i: edge i, from
 * vertex i to i + 1; the first 64), for the vertex-edge narrow phase: an
 * outline edge is internal when it lies along an internal edge of one of
 * its convex pieces. 0 for a moving body. */
uint64_t seams_outline (const struct shape *s);

#endif
