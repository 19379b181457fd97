/* Collision resolution: sequential impulses over all contact points at once,
 * each impulse the one of eq. 3.23 (with the relative velocity of the
 * contact points), accumulated and clamped so contacts only push; then
 * split-impulse position correction. */
#ifndef CAROM_SOLVER_H
#define CAROM_SOLVER_H

struct carom_world;

void solver_update (struct carom_world *world, double h);

#endif
