/* Definition structs across versions. A caller built against an older
 * header passes a smaller struct (its `size` says how small); a newer one a
 * larger struct this library cannot honour. Every def is read through here:
 * known prefixes are copied over the defaults, the rest stays default. */
#ifndef CAROM_DEF_H
#define CAROM_DEF_H

#include <stddef.h>

#include "carom.h"

/* The sizes of the structs as version 0.1 shipped them: the smallest any
 * caller can pass. Fields appended later lie beyond these. */
#define WORLD_DEF_SIZE_0_1 (offsetof (carom_world_def, allocator) + sizeof (carom_allocator))
#define BODY_DEF_SIZE_0_1 (offsetof (carom_body_def, friction) + sizeof (double))
#define SCENE_ERROR_SIZE_0_1 (offsetof (carom_scene_error, message) + 256)

/* `in` may be NULL for the defaults. BAD_STRUCT_SIZE for a size outside
 * [0.1 size, this library's size]. */
carom_status world_def_import (const carom_world_def *in, carom_world_def *out);
carom_status body_def_import (const carom_body_def *in, carom_body_def *out);
/* `in` must not be NULL (a compound's shapes); its size must be 0.2's. */
carom_status shape_def_import (const carom_shape_def *in, carom_shape_def *out);

#endif
