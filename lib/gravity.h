/* Gravity: uniform acceleration, a velocity kick before the solver sees the
 * velocities (the drift makes free flight exact; see world.c). */
#ifndef CAROM_GRAVITY_H
#define CAROM_GRAVITY_H

struct carom_world;

/* v += g * h for every dynamic body, plus the central attraction when it
 * is on; nothing at all when both are off. */
void gravity_update (struct carom_world *world, double h);

#endif
