/* Determinism across processes, compilers and optimisation levels (make
 * check-determinism, mk/determinism.mk): steps a set of scenes and prints one
 * hash per scene over everything the public API reports (every body's pose
 * and velocities, every contact point), bit for bit. The same source built by
 * gcc and clang at -O0 and -O2 must print the same lines.
 *
 * usage: determinism [SCENE_DIR]    (default: scenes) */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carom.h"

static uint64_t mix (uint64_t h, const void *p, size_t n)
{
  const unsigned char *b = p;
  size_t k;
  for (k = 0; k < n; ++k)
    h = (h ^ b[k]) * 1099511628211ull;
  return h;
}

static uint64_t hash_world (const carom_world *w)
{
  uint64_t h = 1469598103934665603ull;
  int32_t n = carom_world_get_bodies (w, NULL, 0), i;
  carom_body_id *ids = malloc ((size_t) (n > 0 ? n : 1) * sizeof *ids);
  if (!ids)
    exit (2);
  carom_world_get_bodies (w, ids, n);
  for (i = 0; i < n; ++i)
    {
      double s[6];
      carom_body_get_position (w, ids[i], &s[0], &s[1]);
      carom_body_get_angle (w, ids[i], &s[2]);
      carom_body_get_velocity (w, ids[i], &s[3], &s[4]);
      carom_body_get_spin (w, ids[i], &s[5]);
      h = mix (h, &ids[i], sizeof ids[i]);
      h = mix (h, s, sizeof s);
    }
  for (i = 0; i < carom_world_contact_count (w); ++i)
    {
      carom_body_id a, b;
      double c[5];
      carom_world_get_contact (w, i, &a, &b, &c[0], &c[1], &c[2], &c[3], &c[4]);
      h = mix (h, &a, sizeof a);
      h = mix (h, &b, sizeof b);
      h = mix (h, c, sizeof c);
    }
  free (ids);
  return h;
}

static int run (const char *name, carom_world *w, int steps)
{
  int i;
  for (i = 0; i < steps; ++i)
    if (carom_world_update (w, 1.0 / 60) != CAROM_OK)
      {
        fprintf (stderr, "determinism: %s: update %d failed\n", name, i);
        return 1;
      }
  printf ("scene=%s steps=%d contacts=%d hash=%016llx\n", name, steps, (int) carom_world_contact_count (w),
          (unsigned long long) hash_world (w));
  carom_world_destroy (w);
  return 0;
}

/* Every effect at once, without joints: gravity, central gravity, damping,
 * friction, restitution, continuous collision, a bullet, a fixed body,
 * concave polygons, and sleeping (set through the API). */
static const char mix_scene[] =
  "gravity 0 -9.81\n"
  "restitution 0.4\n"
  "friction 0.5\n"
  "central 0 30 200 1\n"
  "damping 0.02 0.05\n"
  "continuous 1\n"
  "bounds -10 0 10 20\n"
  "box 2 0.5 at -4 3 angle 0.3 spin 1\n"
  "regular 5 0.6 at -2 6 velocity 3 0\n"
  "circle 0.4 at 0 8 velocity 0 -20 bullet\n"
  "polygon 0 0 3 0 3 3 2 3 2 1 1 1 1 3 0 3 at 3 2\n"
  "box 1 1 at 3 5 fixed\n"
  "circle 0.3 at 5 12 velocity -4 2 restitution 0.9 friction 0.1\n"
  "regular 3 1 at -6 10 spin -3 density 3\n"
  "box 0.8 0.8 at 0 1 \n"
  "box 0.8 0.8 at 0 1.8\n"
  "box 0.8 0.8 at 0 2.6\n";

int main (int argc, char **argv)
{
  static const struct { const char *file; int steps; } files[] = {
    { "pyramid.scene", 300 }, { "rain.scene", 300 }, { "gas.scene", 600 }, { "thesis.scene", 600 },
    { "compound.scene", 600 },
  };
  const char *dir = argc > 1 ? argv[1] : "scenes";
  carom_scene_error err;
  carom_world *w;
  size_t i;
  int rc = 0;
  for (i = 0; i < sizeof files / sizeof files[0]; ++i)
    {
      char path[512];
      snprintf (path, sizeof path, "%s/%s", dir, files[i].file);
      err.size = sizeof err;
      if (carom_scene_load_file (&w, path, NULL, &err) != CAROM_OK)
        {
          fprintf (stderr, "determinism: %s: %s\n", path, err.message);
          return 2;
        }
      rc |= run (files[i].file, w, files[i].steps);
    }
  err.size = sizeof err;
  if (carom_scene_load_text (&w, mix_scene, strlen (mix_scene), NULL, &err) != CAROM_OK
      || carom_world_set_sleeping (w, 1) != CAROM_OK)
    {
      fprintf (stderr, "determinism: the mixed scene: %s\n", err.message);
      return 2;
    }
  rc |= run ("mix", w, 240);
  return rc;
}
