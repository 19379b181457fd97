/* Fuzz target: arbitrary bytes as scene text (carom_scene_load_text).
 *
 * Rejected text must give a known status, no world, and an error struct that
 * agrees with the status. Accepted text must give a world whose every body is
 * valid; it is stepped 20 times with dt = 1/60, every step must succeed and
 * leave every state finite (fuzz_check_world), then it is destroyed (leaks are
 * reported by LeakSanitizer).
 *
 * Stepping cost: a scene may legitimately ask for 1000 sub-steps of 1000
 * iterations over 1024-vertex polygons, which takes seconds per step and would
 * only slow the fuzzer down. Such scenes are stepped fewer times (down to
 * none) by a rough work estimate; the parser and the world's checks are still
 * fuzzed on them in full. */
#include "fuzz_util.h"

#define STEPS 20
#define WORK_BUDGET 4e7 /* rough operations per input */

/* The largest number written after the word `word` anywhere in the text
 * (a scene's last setting wins; the largest bounds the cost). */
static double largest_after (const char *text, size_t len, const char *word)
{
  size_t wl = strlen (word), i;
  double best = 1.0;
  for (i = 0; i + wl < len; ++i)
    {
      size_t j = i + wl;
      double v = 0.0;
      if (memcmp (text + i, word, wl) != 0)
        continue;
      while (j < len && (text[j] == ' ' || text[j] == '\t'))
        ++j;
      while (j < len && text[j] >= '0' && text[j] <= '9' && v < 1e9)
        v = 10.0 * v + (text[j++] - '0');
      if (v > best)
        best = v;
    }
  return best;
}

static int steps_within_budget (const carom_world *w, const char *text, size_t len)
{
  carom_body_id stack_ids[256], *ids = stack_ids;
  int32_t n = carom_world_body_count (w), i;
  double vertices = 0.0, substeps, iterations, per_step;
  int steps;
  if (n > 256)
    {
      ids = malloc ((size_t) n * sizeof *ids);
      if (!ids)
        abort ();
    }
  carom_world_get_bodies (w, ids, n);
  for (i = 0; i < n; ++i)
    {
      int32_t shapes = 0, k;
      carom_body_get_shape_count (w, ids[i], &shapes);
      for (k = 0; k < shapes; ++k)
        {
          int32_t count = 0;
          carom_body_get_shape_geometry (w, ids[i], k, NULL, NULL, NULL, NULL, NULL, 0, &count);
          vertices += count > 0 ? count : 1;
        }
    }
  if (ids != stack_ids)
    free (ids);
  substeps = largest_after (text, len, "substeps");
  iterations = largest_after (text, len, "iterations");
  /* narrow phase up to all vertex pairs, solver up to all body pairs */
  per_step = substeps * (vertices * vertices + (double) n * n * (iterations + 4));
  steps = per_step > 0.0 ? (int) (WORK_BUDGET / per_step) : STEPS;
  return steps < STEPS ? steps : STEPS;
}

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  const char *text = (const char *) data;
  carom_world *w = (carom_world *) &w; /* must be overwritten */
  carom_scene_error err;
  carom_status s;
  int step, steps;

  memset (&err, 0x55, sizeof err);
  err.size = sizeof err;
  s = carom_scene_load_text (&w, text, size, NULL, &err);
  if (!fuzz_known_status (s))
    FUZZ_FINDING ("load returned unknown status %d", (int) s);
  if (memchr (err.message, '\0', sizeof err.message) == NULL)
    FUZZ_FINDING ("error message not NUL-terminated");
  if (err.cause != s)
    FUZZ_FINDING ("status %d but err.cause %d", (int) s, (int) err.cause);

  if (s != CAROM_OK)
    {
      char prefix[24];
      if (w != NULL)
        FUZZ_FINDING ("load failed with %d but *world is not NULL", (int) s);
      if (s == CAROM_ERR_OUT_OF_MEMORY || s == CAROM_ERR_NULL_ARGUMENT || s == CAROM_ERR_IO
          || s == CAROM_ERR_BAD_STRUCT_SIZE || s == CAROM_ERR_STALE_BODY || s == CAROM_ERR_BAD_TIME_STEP)
        FUZZ_FINDING ("load of in-memory text failed with %d (%s): %s", (int) s, carom_status_string (s),
                      err.message);
      if (err.line < 1)
        FUZZ_FINDING ("status %d (%s) without a line: '%s'", (int) s, carom_status_string (s), err.message);
      snprintf (prefix, sizeof prefix, "%d: ", (int) err.line);
      if (strncmp (err.message, prefix, strlen (prefix)) != 0)
        FUZZ_FINDING ("message '%s' does not start with its line %d", err.message, (int) err.line);
      return 0;
    }

  if (w == NULL || w == (carom_world *) &w)
    FUZZ_FINDING ("load returned OK without a world");
  if (err.line != 0 || err.message[0] != '\0')
    FUZZ_FINDING ("load OK but the error struct says line %d '%s'", (int) err.line, err.message);
  fuzz_check_world (w, "after load");
  steps = steps_within_budget (w, text, size);
  for (step = 0; step < steps; ++step)
    {
      s = carom_world_update (w, 1.0 / 60.0);
      if (s != CAROM_OK)
        FUZZ_FINDING ("step %d returned %d (%s)", step, (int) s, carom_status_string (s));
      fuzz_check_world (w, "after a step");
    }
  carom_world_destroy (w);
  return 0;
}
