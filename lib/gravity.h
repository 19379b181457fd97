/* Gravity: uniform acceleration applied as two half kicks around the drift
 * (leapfrog), which is exact for constant acceleration. */
#ifndef CAROM_GRAVITY_H
#define CAROM_GRAVITY_H

struct carom_world;

/* v += g * h for every dynamic body; nothing at all when g is zero. */
void gravity_update (struct carom_world *world, double h);

#endif
