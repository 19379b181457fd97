#include "def.h"

#include <string.h>

/* Fill `def` (of `size` bytes as the caller knows it) with the defaults:
 * writes no byte past `size`. */
static carom_status init_prefix (void *def, uint32_t size, const void *defaults, size_t own_size, size_t min_size)
{
  if (!def)
    return CAROM_ERR_NULL_ARGUMENT;
  if (size != min_size && size != own_size)
    return CAROM_ERR_BAD_STRUCT_SIZE;
  memcpy (def, defaults, size);
  memcpy (def, &size, sizeof size); /* the leading size field */
  return CAROM_OK;
}

static carom_status import (const void *in, uint32_t in_size, void *out, size_t own_size, size_t min_size)
{
  if (in_size != min_size && in_size != own_size)
    return CAROM_ERR_BAD_STRUCT_SIZE;
  memcpy (out, in, in_size);
  return CAROM_OK;
}

static carom_world_def world_defaults (void)
{
  carom_world_def d;
  memset (&d, 0, sizeof d);
  d.size = sizeof d;
  d.substeps = 4;
  d.iterations = 1;
  d.position_correction = 0.2;
  d.slop = 0.01;
  d.narrow_phase = CAROM_NARROW_SAT;
  d.manifold_tolerance = 0.01;
  return d;
}

static carom_body_def body_defaults (void)
{
  carom_body_def d;
  memset (&d, 0, sizeof d);
  d.size = sizeof d;
  d.type = CAROM_DYNAMIC;
  d.density = 1.0;
  d.restitution = -1.0;
  d.friction = -1.0;
  d.category = 1u;
  d.mask = 0xffffffffu;
  return d;
}

static carom_shape_def shape_defaults (void)
{
  carom_shape_def d;
  memset (&d, 0, sizeof d);
  d.size = sizeof d;
  d.kind = CAROM_SHAPE_CIRCLE;
  d.density = -1.0;
  d.restitution = -1.0;
  d.friction = -1.0;
  return d;
}

carom_status carom_world_def_init (carom_world_def *def, uint32_t size)
{
  carom_world_def d = world_defaults ();
  return init_prefix (def, size, &d, sizeof d, WORLD_DEF_SIZE_0_1);
}

carom_status carom_body_def_init (carom_body_def *def, uint32_t size)
{
  carom_body_def d = body_defaults ();
  return init_prefix (def, size, &d, sizeof d, BODY_DEF_SIZE_0_1);
}

carom_status carom_shape_def_init (carom_shape_def *def, uint32_t size)
{
  carom_shape_def d = shape_defaults ();
  return init_prefix (def, size, &d, sizeof d, sizeof d);
}

carom_status world_def_import (const carom_world_def *in, carom_world_def *out)
{
  carom_status st;
  *out = world_defaults ();
  if (!in)
    return CAROM_OK;
  st = import (in, in->size, out, sizeof *out, WORLD_DEF_SIZE_0_1);
  out->size = sizeof *out;
  return st;
}

carom_status body_def_import (const carom_body_def *in, carom_body_def *out)
{
  carom_status st;
  *out = body_defaults ();
  if (!in)
    return CAROM_OK;
  st = import (in, in->size, out, sizeof *out, BODY_DEF_SIZE_0_1);
  out->size = sizeof *out;
  return st;
}

carom_status shape_def_import (const carom_shape_def *in, carom_shape_def *out)
{
  *out = shape_defaults ();
  return import (in, in->size, out, sizeof *out, sizeof *out);
}
