/* Fuzz target: carom_world_add_polygon on arbitrary vertex lists.
 *
 * Input layout: byte 0 picks how the vertices are encoded, bytes 1-2 the
 * vertex count (below 48, or with bits 14 and 15 set any count up to
 * CAROM_MAX_POLYGON_VERTICES + 8, so both count errors are reached), byte 3
 * the body def (static, density, angle), then the vertices:
 *   mode 0: raw 64-bit doubles (NaN, infinities, subnormals, anything);
 *   mode 1: 16-bit integers on a grid scaled by 10^e, e in [-320, 320) from
 *           two more bytes (the scene files' kind of input, at any scale);
 *   mode 2: a regular polygon with 8-bit radial and angular jitter
 *           (convex and concave stars, near-degenerate shapes);
 *   mode 3: fuzz_number () for each coordinate.
 * Vertices the bytes run out for continue the regular polygon of mode 2.
 *
 * On success: mass > 0 and inertia > 0 for a dynamic body (0 for a static
 * one), area > 0, all finite; the body sits at def (x, y);
 * carom_body_get_vertices reports the count and finite vertices; the world
 * then detects and steps with the polygon against a copy of itself and a
 * circle, and stays finite. On failure: a status add_polygon documents, the
 * id untouched, the body count unchanged. */
#include "fuzz_util.h"

#define MAX_COUNT (CAROM_MAX_POLYGON_VERTICES + 8)

static double grid_scale (fuzz_input *in)
{
  int e = (int) (fuzz_u16 (in) % 640) - 320;
  return pow (10.0, e);
}

static int allowed_failure (carom_status s)
{
  switch (s)
    {
    case CAROM_ERR_NOT_FINITE:
    case CAROM_ERR_BAD_SIZE:
    case CAROM_ERR_TOO_FEW_VERTICES:
    case CAROM_ERR_TOO_MANY_VERTICES:
    case CAROM_ERR_REPEATED_VERTEX:
    case CAROM_ERR_SELF_INTERSECTING:
    case CAROM_ERR_ZERO_AREA:
      return 1;
    default:
      return 0;
    }
}

int LLVMFuzzerTestOneInput (const uint8_t *data, size_t size)
{
  static double xy[2 * MAX_COUNT];
  fuzz_input in = { data, size };
  carom_world *w = NULL;
  carom_body_def def;
  carom_body_id id = 4242, other;
  carom_status s;
  int mode = fuzz_u8 (&in) % 4;
  uint16_t count_bits = fuzz_u16 (&in);
  /* mostly small polygons (fast to fuzz); with the top two bits, any count
   * (a 1024-gon costs a tenth of a second under the sanitizers) */
  int32_t count = (int32_t) ((count_bits & 0xc000) == 0xc000 ? (count_bits & 0x3fff) % (MAX_COUNT + 1)
                                                             : count_bits % 48);
  int32_t i, got = -1;
  uint8_t flags = fuzz_u8 (&in);
  double scale = mode == 1 ? grid_scale (&in) : 1.0;
  double m, inertia, area, x, y, *out;
  int any_non_finite = 0;

  for (i = 0; i < count; ++i)
    {
      double t = 2.0 * 3.14159265358979323846 * i / (count > 0 ? count : 1);
      double rx = cos (t), ry = sin (t);
      if (in.n == 0)
        {
          xy[2 * i] = rx, xy[2 * i + 1] = ry;
          continue;
        }
      switch (mode)
        {
        case 0:
          xy[2 * i] = fuzz_raw_double (&in);
          xy[2 * i + 1] = fuzz_raw_double (&in);
          break;
        case 1:
          xy[2 * i] = (int16_t) fuzz_u16 (&in) * scale;
          xy[2 * i + 1] = (int16_t) fuzz_u16 (&in) * scale;
          break;
        case 2:
          {
            double r = 1.0 + (int8_t) fuzz_u8 (&in) / 128.0;
            double dt = (int8_t) fuzz_u8 (&in) / 128.0 * 3.14159265358979323846 / (count > 0 ? count : 1);
            xy[2 * i] = r * cos (t + dt);
            xy[2 * i + 1] = r * sin (t + dt);
          }
          break;
        default:
          xy[2 * i] = fuzz_number (&in, 0);
          xy[2 * i + 1] = fuzz_number (&in, 0);
          break;
        }
    }
  for (i = 0; i < 2 * count; ++i)
    if (!isfinite (xy[i]))
      any_non_finite = 1;

  if (carom_world_init (&w, NULL) != CAROM_OK)
    FUZZ_FINDING ("world init failed");
  if (carom_body_def_init (&def, sizeof def) != CAROM_OK)
    FUZZ_FINDING ("body def init failed");
  if (flags & 1)
    def.type = CAROM_STATIC;
  def.density = (flags & 6) == 2 ? 1e-3 : (flags & 6) == 4 ? 1e3 : 1.0;
  def.x = 0.25, def.y = -0.5;
  def.angle = (flags >> 3) * 0.2;

  s = carom_world_add_polygon (w, &def, xy, count, &id);
  if (s != CAROM_OK)
    {
      if (!allowed_failure (s))
        FUZZ_FINDING ("add_polygon (count %d) returned %d (%s)", (int) count, (int) s, carom_status_string (s));
      if (id != 4242)
        FUZZ_FINDING ("add_polygon failed (%d) but wrote *id", (int) s);
      if (carom_world_body_count (w) != 0)
        FUZZ_FINDING ("add_polygon failed (%d) but the world has %d bodies", (int) s, (int) carom_world_body_count (w));
      if (s == CAROM_ERR_TOO_FEW_VERTICES && count >= 3)
        FUZZ_FINDING ("TOO_FEW_VERTICES for %d vertices", (int) count);
      if (s == CAROM_ERR_TOO_MANY_VERTICES && count <= CAROM_MAX_POLYGON_VERTICES)
        FUZZ_FINDING ("TOO_MANY_VERTICES for %d vertices", (int) count);
      if ((count < 3 && s != CAROM_ERR_TOO_FEW_VERTICES)
          || (count > CAROM_MAX_POLYGON_VERTICES && s != CAROM_ERR_TOO_MANY_VERTICES))
        FUZZ_FINDING ("count %d rejected with %d (%s)", (int) count, (int) s, carom_status_string (s));
      if (any_non_finite && count >= 3 && count <= CAROM_MAX_POLYGON_VERTICES && s != CAROM_ERR_NOT_FINITE)
        FUZZ_FINDING ("a non-finite vertex rejected with %d (%s), not NOT_FINITE", (int) s, carom_status_string (s));
      carom_world_destroy (w);
      return 0;
    }

  if (count < 3 || count > CAROM_MAX_POLYGON_VERTICES || any_non_finite)
    FUZZ_FINDING ("add_polygon accepted count %d (non-finite: %d)", (int) count, any_non_finite);
  if (carom_body_check (w, id) != CAROM_OK || carom_world_body_count (w) != 1)
    FUZZ_FINDING ("accepted polygon is not in the world");
  if (carom_body_get_mass (w, id, &m, &inertia, &area) != CAROM_OK)
    FUZZ_FINDING ("get_mass failed");
  if (!isfinite (m) || !isfinite (inertia) || !isfinite (area) || !(area > 0.0))
    FUZZ_FINDING ("accepted polygon (%d vertices) has mass %g inertia %g area %g", (int) count, m, inertia, area);
  if (def.type == CAROM_DYNAMIC && !(m > 0.0 && inertia > 0.0))
    FUZZ_FINDING ("accepted dynamic polygon (%d vertices) has mass %g inertia %g area %g", (int) count, m, inertia,
                  area);
  if (def.type == CAROM_STATIC && (m != 0.0 || inertia != 0.0))
    FUZZ_FINDING ("static polygon has mass %g inertia %g", m, inertia);
  if (carom_body_get_position (w, id, &x, &y) != CAROM_OK || x != def.x || y != def.y)
    FUZZ_FINDING ("polygon placed at (%g, %g), not at def (%g, %g)", x, y, def.x, def.y);
  if (carom_body_get_vertices (w, id, NULL, 0, &got) != CAROM_OK || got != count)
    FUZZ_FINDING ("get_vertices reports %d vertices, %d given", (int) got, (int) count);
  out = malloc ((size_t) count * 2 * sizeof *out);
  if (!out)
    abort ();
  got = -1;
  if (carom_body_get_vertices (w, id, out, count, &got) != CAROM_OK || got != count)
    FUZZ_FINDING ("get_vertices with a buffer reports %d", (int) got);
  for (i = 0; i < 2 * count; ++i)
    if (!isfinite (out[i]))
      FUZZ_FINDING ("vertex %d of the accepted polygon is not finite: %g", (int) i / 2, out[i]);
  free (out);

  /* the same outline again, overlapping, and a circle: collide them (the
   * copy only for up to 128 vertices: two 1024-gons take half a second) */
  def.x += 0.1, def.angle += 0.3;
  def.type = CAROM_DYNAMIC;
  if (count <= 128)
    {
      s = carom_world_add_polygon (w, &def, xy, count, &other);
      if (s != CAROM_OK)
        FUZZ_FINDING ("the same polygon was accepted once and then refused with %d", (int) s);
    }
  def.x = 0.0, def.y = 0.0;
  if (carom_world_add_circle (w, &def, 0.5, NULL) != CAROM_OK)
    FUZZ_FINDING ("add_circle failed");
  if (carom_world_detect (w) != CAROM_OK)
    FUZZ_FINDING ("detect failed");
  fuzz_check_world (w, "after detect");
  if (carom_world_update (w, 1.0 / 60.0) != CAROM_OK)
    FUZZ_FINDING ("update failed");
  fuzz_check_world (w, "after a step");
  if (carom_world_remove_body (w, id) != CAROM_OK || carom_body_check (w, id) != CAROM_ERR_STALE_BODY)
    FUZZ_FINDING ("remove failed");
  carom_world_destroy (w);
  return 0;
}
