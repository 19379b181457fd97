/* Gravity: uniform acceleration, a velocity kick before the solver sees the
 * velocities (the drift makes free flight exact; see world.c). */
#ifndef CAROM_GRAVITY_H
#define CAROM_GRAVITY_H

struct carom_world;

/* v += g * h for every dynamic body; nothing at all when g is zero. */
void gravity_update (struct carom_world *world, double h);

#endif
