/* Seams: where static shapes touch (floor tiles, a terrain of boxes, the
 * convex pieces of a concave static polygon), the edges they share are
 * internal. Nothing can come through an internal edge, so no contact takes
 * one as its face, and a circle meets the vertex next to one as the
 * continuation of the other face (collide.h): a body sliding or rolling
 * over the seam keeps its speed instead of catching on the corner (a ghost
 * collision). */
#ifndef CAROM_SEAMS_H
#define CAROM_SEAMS_H

struct carom_world;

/* Mark the internal edges of every static piece (convex_piece.internal),
 * after static bodies were added, removed or moved (world->seams_dirty). */
void seams_update (struct carom_world *world);

#endif
