/* Scene files: a line-oriented text format (docs/scenes.md) loaded into a new
 * world. The text is read twice. The first pass checks every line and
 * collects the world settings, which carom_world_init needs before any body
 * exists, the bodies' names and the joints; the second creates the world
 * and adds the bodies, then the joints, which may name bodies of later
 * lines. The first pass already catches every error a well-formed world can
 * report, so the first error by line order is the one reported (a joint's
 * names are resolved once the whole file is read: what depends on them is
 * reported after every other line), and a failure in the second pass (out
 * of memory, too many bodies) destroys the half-built world: a caller never
 * sees part of a scene. */
#include "alloc.h"
#include "carom.h"
#include "def.h"
#include "shape.h"

#include <errno.h>
#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Body options, as bits so a statement can list the ones it accepts. */
enum {
  OPT_AT = 1u << 0,
  OPT_ANGLE = 1u << 1,
  OPT_VELOCITY = 1u << 2,
  OPT_SPIN = 1u << 3,
  OPT_DENSITY = 1u << 4,
  OPT_RESTITUTION = 1u << 5,
  OPT_FRICTION = 1u << 6,
  OPT_STATIC = 1u << 7,
  OPT_FIXED = 1u << 8,
  OPT_BULLET = 1u << 9,
  OPT_KINEMATIC = 1u << 10,
  OPT_SENSOR = 1u << 11,
  OPT_CATEGORY = 1u << 12,
  OPT_MASK = 1u << 13,
  OPT_GROUP = 1u << 14,
  OPT_NAME = 1u << 15
};
#define OPT_MATERIAL (OPT_RESTITUTION | OPT_FRICTION)
/* a shape inside a compound: where it sits in the body, its density and
 * material */
#define OPT_PART (OPT_AT | OPT_ANGLE | OPT_DENSITY | OPT_MATERIAL)
#define OPT_BODY                                                                                                       \
  (OPT_AT | OPT_ANGLE | OPT_VELOCITY | OPT_SPIN | OPT_DENSITY | OPT_MATERIAL | OPT_STATIC | OPT_FIXED | OPT_BULLET     \
   | OPT_KINEMATIC | OPT_SENSOR | OPT_CATEGORY | OPT_MASK | OPT_GROUP | OPT_NAME)

typedef struct scene_option {
  const char *word;
  int count; /* numbers that follow the word; -1: one word (a name) */
  unsigned bit;
} scene_option;

static const scene_option scene_options[] = {
  { "at", 2, OPT_AT },
  { "angle", 1, OPT_ANGLE },
  { "velocity", 2, OPT_VELOCITY },
  { "spin", 1, OPT_SPIN },
  { "density", 1, OPT_DENSITY },
  { "restitution", 1, OPT_RESTITUTION },
  { "friction", 1, OPT_FRICTION },
  { "static", 0, OPT_STATIC },
  { "fixed", 0, OPT_FIXED },
  { "bullet", 0, OPT_BULLET },
  { "kinematic", 0, OPT_KINEMATIC },
  { "sensor", 0, OPT_SENSOR },
  { "category", 1, OPT_CATEGORY },
  { "mask", 1, OPT_MASK },
  { "group", 1, OPT_GROUP },
  { "name", -1, OPT_NAME },
};

/* Joint options, as bits too, and the kinds of joint with the options each
 * takes and needs. */
enum {
  JOPT_AT = 1u << 0,
  JOPT_TO = 1u << 1,
  JOPT_AXIS = 1u << 2,
  JOPT_LIMIT = 1u << 3,
  JOPT_MOTOR = 1u << 4,
  JOPT_SPRING = 1u << 5,
  JOPT_LENGTH = 1u << 6,
  JOPT_FORCE = 1u << 7,
  JOPT_TORQUE = 1u << 8,
  JOPT_COLLIDE = 1u << 9
};

static const scene_option scene_joint_options[] = {
  { "at", 2, JOPT_AT },
  { "to", 2, JOPT_TO },
  { "axis", 2, JOPT_AXIS },
  { "limit", 2, JOPT_LIMIT },
  { "motor", 2, JOPT_MOTOR },
  { "spring", 2, JOPT_SPRING },
  { "length", 1, JOPT_LENGTH },
  { "force", 1, JOPT_FORCE },
  { "torque", 1, JOPT_TORQUE },
  { "collide", 0, JOPT_COLLIDE },
};

typedef struct scene_joint_kind {
  const char *word;
  carom_joint_type type;
  int32_t bodies;       /* names after the word: A and B, or B alone */
  unsigned needs, options;
  const char *usage;
} scene_joint_kind;

static const scene_joint_kind scene_joint_kinds[] = {
  { "revolute", CAROM_JOINT_REVOLUTE, 2, JOPT_AT, JOPT_AT | JOPT_LIMIT | JOPT_MOTOR | JOPT_SPRING | JOPT_COLLIDE,
    "joint revolute A B at X Y [limit LOWER UPPER] [motor SPEED MAX_TORQUE] [spring HZ DAMPING] [collide]" },
  { "prismatic", CAROM_JOINT_PRISMATIC, 2, JOPT_AT | JOPT_AXIS,
    JOPT_AT | JOPT_AXIS | JOPT_LIMIT | JOPT_MOTOR | JOPT_SPRING | JOPT_COLLIDE,
    "joint prismatic A B at X Y axis AX AY [limit L U] [motor SPEED MAX_FORCE] [spring HZ DAMPING] [collide]" },
  { "wheel", CAROM_JOINT_WHEEL, 2, JOPT_AT | JOPT_AXIS,
    JOPT_AT | JOPT_AXIS | JOPT_LIMIT | JOPT_MOTOR | JOPT_SPRING | JOPT_COLLIDE,
    "joint wheel A B at X Y axis AX AY [limit L U] [motor SPEED MAX_TORQUE] [spring HZ DAMPING] [collide]" },
  { "distance", CAROM_JOINT_DISTANCE, 2, JOPT_AT | JOPT_TO,
    JOPT_AT | JOPT_TO | JOPT_LENGTH | JOPT_LIMIT | JOPT_SPRING | JOPT_MOTOR | JOPT_COLLIDE,
    "joint distance A B at X Y to X2 Y2 [length L] [limit MIN MAX] [spring HZ DAMPING] [motor SPEED MAX_FORCE] "
    "[collide]" },
  { "weld", CAROM_JOINT_WELD, 2, JOPT_AT, JOPT_AT | JOPT_SPRING | JOPT_COLLIDE,
    "joint weld A B at X Y [spring HZ DAMPING] [collide]" },
  { "motor", CAROM_JOINT_MOTOR, 2, 0, JOPT_FORCE | JOPT_TORQUE | JOPT_COLLIDE,
    "joint motor A B [force MAX_FORCE] [torque MAX_TORQUE] [collide]" },
  { "mouse", CAROM_JOINT_MOUSE, 1, JOPT_AT, JOPT_AT | JOPT_FORCE | JOPT_SPRING,
    "joint mouse B at X Y [force MAX_FORCE] [spring HZ DAMPING]" },
};

/* The word that names the world (a fixed point) where a joint names a
 * body; no body may be called so. */
#define SCENE_WORLD "world"

/* A body's name: where its text is, the line that gave it, the body's type
 * and, once made, its id; `stub` is a body of the same type in the trial
 * world, for checking the joints that name it. */
typedef struct scene_name {
  int32_t text;
  int32_t line;
  carom_body_type type;
  carom_body_id id, stub;
} scene_name;

/* A joint line, kept from the first pass: its def without the bodies, the
 * names it gives for a and b (text offsets, -1 for the world) and, once
 * resolved, their entries in the name table (-1 for the world). */
typedef struct scene_joint {
  int32_t line;
  const scene_joint_kind *kind;
  carom_joint_def def;
  int32_t ref[2];
  int32_t entry[2];
} scene_joint;

typedef struct scene_parser {
  carom_allocator allocator; /* the caller's, from def: all scratch memory */
  carom_world_def def;       /* the settings the scene builds up */
  carom_world *world;        /* NULL in the checking pass */
  int32_t line;
  carom_status status;
  char message[sizeof ((carom_scene_error *) 0)->message];

  /* the current line: a NUL-terminated copy, split into tokens in place */
  char *buf;
  int32_t buf_cap;
  char **tok;
  int32_t tok_count, tok_cap;

  /* what the statement's dispatcher parsed for its handler */
  double *num;
  int32_t num_count, num_cap;
  unsigned opts;             /* options given */
  carom_body_def body;       /* options applied to the defaults */
  carom_body_id last;        /* the body the line added */

  /* an open `compound` block: its body def and line, its shapes so far
   * (polygon vertices in part_xy, at part_first[i]), and, in the first
   * pass, a world to try the shapes in */
  int in_compound;
  int32_t compound_line;
  carom_body_def compound;
  unsigned compound_opts;    /* its options (fixed, bullet: applied at end) */
  carom_shape_def *parts;
  int32_t *part_first;
  int32_t part_count, part_cap, first_cap;
  double *part_xy;
  int32_t xy_count, xy_cap;
  carom_world *trial;

  /* effects set by statements, applied once the world exists */
  double central[4];         /* x, y, gm, softening */
  double damping[2];
  int sleeping;
  int continuous;            /* `continuous 1|0`, or -1 when not given */
  uint32_t named_effects;    /* named by `effects`: must end up active */
  int32_t effects_line;

  /* body names: the table, open addressing over their text (slot: entry
   * + 1, 0 empty; slot_cap a power of two), the text of every name and
   * joint reference, NUL-terminated; the line's name (its token and entry)
   * and the open compound's entry */
  scene_name *names;
  int32_t name_count, name_cap;
  int32_t *slots;
  int32_t slot_cap;
  char *text;
  int32_t text_len, text_cap;
  const char *name;
  int32_t name_entry;
  int32_t compound_name;

  /* the joint lines, made after the bodies; two dynamic bodies in the
   * trial world for each line's own check (0 until made) */
  scene_joint *joints;
  int32_t joint_count, joint_cap;
  carom_body_id trial_pair[2];
} scene_parser;

/* When a statement's handler runs: settings fill p->def in the first pass
 * only (the world is created from them), joints are checked and kept in the
 * first pass only (they are made once every body exists); the others run in
 * both passes and add bodies in the second, when p->world is set. */
typedef enum scene_kind { SCENE_SETTING, SCENE_BODY, SCENE_JOINT } scene_kind;

/* One statement: its word, the numbers that follow (max_numbers < 0: any
 * count), the options it accepts after them, and the handler. A statement
 * whose arguments are words (names, not numbers) sets `words`: the
 * dispatcher then leaves the tokens p->tok[1..] to the handler. */
typedef struct scene_statement {
  const char *word;
  scene_kind kind;
  int32_t min_numbers, max_numbers;
  unsigned options;
  int words;
  const char *usage;
  carom_status (*run) (scene_parser *p);
} scene_statement;

/* ---------------------------------------------------------------- errors */

/* Record the error for the current line and return `cause`, so handlers can
 * `return scene_fail (...)`. The message starts with the line number. */
static carom_status scene_fail (scene_parser *p, carom_status cause, const char *fmt, ...)
{
  va_list ap;
  int n = 0;
  p->status = cause;
  if (p->line > 0)
    n = snprintf (p->message, sizeof p->message, "%ld: ", (long) p->line);
  if (n < 0 || (size_t) n >= sizeof p->message)
    n = 0;
  va_start (ap, fmt);
  vsnprintf (p->message + n, sizeof p->message - (size_t) n, fmt, ap);
  va_end (ap);
  return cause;
}

static void scene_report (const scene_parser *p, carom_scene_error *error)
{
  /* every field of the 0.1 layout; fields appended later would be written
   * only when error->size covers them */
  if (!error || error->size < SCENE_ERROR_SIZE_0_1)
    return;
  error->line = p->status == CAROM_OK ? 0 : p->line;
  error->cause = p->status;
  memcpy (error->message, p->message, sizeof error->message);
  error->message[sizeof error->message - 1] = '\0';
}

/* --------------------------------------------------------------- numbers */

static int scene_is_digit (char c)
{
  return c >= '0' && c <= '9';
}

static int scene_lower (char c)
{
  return c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c;
}

static int scene_same_word (const char *a, const char *lower)
{
  while (*a && *lower && scene_lower (*a) == *lower)
    ++a, ++lower;
  return *a == '\0' && *lower == '\0';
}

/* A plain decimal: [+-] (D+ [. D*] | . D+) [(e|E) [+-] D+]. Hex floats and
 * the words strtod knows are left out on purpose: the format is meant to be
 * read by people and by other tools. */
static int scene_is_decimal (const char *s)
{
  int digits = 0;
  if (*s == '+' || *s == '-')
    ++s;
  while (scene_is_digit (*s))
    ++s, ++digits;
  if (*s == '.')
    for (++s; scene_is_digit (*s); ++s)
      ++digits;
  if (!digits)
    return 0;
  if (*s == 'e' || *s == 'E')
    {
      ++s;
      if (*s == '+' || *s == '-')
        ++s;
      if (!scene_is_digit (*s))
        return 0;
      while (scene_is_digit (*s))
        ++s;
    }
  return *s == '\0';
}

static int scene_is_non_finite (const char *s)
{
  if (*s == '+' || *s == '-')
    ++s;
  return scene_same_word (s, "nan") || scene_same_word (s, "inf") || scene_same_word (s, "infinity");
}

/* Tokens that are meant as numbers (even bad ones) rather than words. */
static int scene_looks_numeric (const char *s)
{
  return scene_is_digit (*s) || *s == '+' || *s == '-' || *s == '.' || scene_is_non_finite (s);
}

/* strtod reads the decimal point of the C library's current locale, which a
 * GUI program (gtk_init calls setlocale) may have set to ','. Scene files
 * always use '.', so swap it for the locale's before converting. */
static carom_status scene_strtod (scene_parser *p, char *s, double *out)
{
  const char *point = localeconv ()->decimal_point;
  char *dot = strchr (s, '.');
  size_t plen = strlen (point);
  if (!dot || (plen == 1 && point[0] == '.'))
    *out = strtod (s, NULL);
  else if (plen == 1)
    {
      *dot = point[0];
      *out = strtod (s, NULL);
      *dot = '.';
    }
  else
    {
      /* a multi-byte decimal point: convert a rewritten copy */
      size_t head = (size_t) (dot - s), len = strlen (s);
      char *copy = mem_alloc (&p->allocator, len + plen);
      if (!copy)
        return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
      memcpy (copy, s, head);
      memcpy (copy + head, point, plen);
      memcpy (copy + head + plen, dot + 1, len - head); /* with the NUL */
      *out = strtod (copy, NULL);
      mem_free (&p->allocator, copy, len + plen);
    }
  return CAROM_OK;
}

/* Convert a token that must be a finite number. */
static carom_status scene_number (scene_parser *p, char *tok, double *out)
{
  carom_status s;
  if (scene_is_non_finite (tok))
    return scene_fail (p, CAROM_ERR_NOT_FINITE, "%s: '%s' is not a finite number", p->tok[0], tok);
  if (!scene_is_decimal (tok))
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: '%s' is not a number", p->tok[0], tok);
  s = scene_strtod (p, tok, out);
  if (s != CAROM_OK)
    return s;
  if (!isfinite (*out)) /* overflowed: an underflow to 0 or a denormal is fine */
    return scene_fail (p, CAROM_ERR_NOT_FINITE, "%s: '%s' is too large", p->tok[0], tok);
  return CAROM_OK;
}

/* A count: a whole number in [lo, hi]. */
static carom_status scene_count (scene_parser *p, double v, const char *what, double lo, double hi,
                                 carom_status range_status, int32_t *out)
{
  if (v != floor (v))
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: %s must be a whole number, got %g", p->tok[0], what, v);
  if (v < lo || v > hi)
    return scene_fail (p, range_status, "%s: %s must be between %.0f and %.0f, got %.0f", p->tok[0], what, lo, hi, v);
  *out = (int32_t) v;
  return CAROM_OK;
}

static carom_status scene_positive (scene_parser *p, double v, const char *what, carom_status status)
{
  if (v > 0.0)
    return CAROM_OK;
  return scene_fail (p, status, "%s: %s must be positive, got %g", p->tok[0], what, v);
}

static carom_status scene_restitution (scene_parser *p, double e)
{
  if (e >= 0.0 && e <= 1.0)
    return CAROM_OK;
  return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "%s: restitution must be between 0 and 1, got %g", p->tok[0], e);
}

static carom_status scene_friction (scene_parser *p, double mu)
{
  if (mu >= 0.0)
    return CAROM_OK;
  return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "%s: friction must be 0 or more, got %g", p->tok[0], mu);
}

/* The option `word` of a table, or NULL. */
static const scene_option *scene_lookup_option (const scene_option *table, size_t count, const char *word)
{
  size_t i;
  for (i = 0; i < count; ++i)
    if (strcmp (word, table[i].word) == 0)
      return &table[i];
  return NULL;
}

static const scene_option *scene_find_option (const char *word)
{
  return scene_lookup_option (scene_options, sizeof scene_options / sizeof scene_options[0], word);
}

/* ----------------------------------------------------------------- names */

/* A body's name: a letter or '_', then letters, digits, '_' or '-'. */
static int scene_is_name_char (char c, int first)
{
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || (!first && (scene_is_digit (c) || c == '-'));
}

static int scene_is_name (const char *s)
{
  if (!scene_is_name_char (*s, 1))
    return 0;
  while (*++s)
    if (!scene_is_name_char (*s, 0))
      return 0;
  return 1;
}

/* A token where a line wants a body's name (`what` is the statement). */
static carom_status scene_check_name (scene_parser *p, const char *what, const char *name)
{
  if (!name)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: option 'name' needs a name", what);
  if (strcmp (name, SCENE_WORLD) == 0)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: '%s' cannot name a body (in a joint it is the world itself)",
                       what, name);
  if (!scene_is_name (name))
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX,
                       "%s: '%s' is not a name (a letter or '_', then letters, digits, '_' or '-')", what, name);
  return CAROM_OK;
}

/* FNV-1a, for the name table */
static uint32_t scene_hash (const char *s)
{
  uint32_t h = 2166136261u;
  for (; *s; ++s)
    h = (h ^ (unsigned char) *s) * 16777619u;
  return h;
}

/* Keep a NUL-terminated copy of `s` in p->text; its offset in *at. */
static carom_status scene_keep_text (scene_parser *p, const char *s, int32_t *at)
{
  size_t len = strlen (s) + 1;
  if (len > (size_t) (INT32_MAX - p->text_len)
      || !mem_reserve (&p->allocator, (void **) &p->text, &p->text_cap, p->text_len + (int32_t) len, 1))
    return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
  memcpy (p->text + p->text_len, s, len);
  *at = p->text_len;
  p->text_len += (int32_t) len;
  return CAROM_OK;
}

/* The entry of the body named `s`, or -1. */
static int32_t scene_name_find (const scene_parser *p, const char *s)
{
  uint32_t mask = (uint32_t) p->slot_cap - 1, i;
  if (p->slot_cap == 0)
    return -1;
  for (i = scene_hash (s) & mask; p->slots[i]; i = (i + 1) & mask)
    if (strcmp (p->text + p->names[p->slots[i] - 1].text, s) == 0)
      return p->slots[i] - 1;
  return -1;
}

/* Room for one more name, the table at most half full; 0 when out of
 * memory. */
static int scene_name_room (scene_parser *p)
{
  int32_t cap, i, *slots;
  if (!mem_reserve (&p->allocator, (void **) &p->names, &p->name_cap, p->name_count + 1, sizeof *p->names))
    return 0;
  if (2 * (p->name_count + 1) <= p->slot_cap)
    return 1;
  if (p->slot_cap > INT32_MAX / 4)
    return 0;
  cap = p->slot_cap ? 2 * p->slot_cap : 64;
  slots = mem_alloc (&p->allocator, (size_t) cap * sizeof *slots);
  if (!slots)
    return 0;
  memset (slots, 0, (size_t) cap * sizeof *slots);
  for (i = 0; i < p->name_count; ++i)
    {
      uint32_t k = scene_hash (p->text + p->names[i].text) & (uint32_t) (cap - 1);
      while (slots[k])
        k = (k + 1) & (uint32_t) (cap - 1);
      slots[k] = i + 1;
    }
  mem_free (&p->allocator, p->slots, (size_t) p->slot_cap * sizeof *p->slots);
  p->slots = slots;
  p->slot_cap = cap;
  return 1;
}

/* The line's `name` (p->name), its options read: in the first pass a new
 * entry (a name given before is an error), in the second the entry that
 * gets the body's id (p->name_entry). */
static carom_status scene_name_line (scene_parser *p, const char *what)
{
  int32_t found = scene_name_find (p, p->name);
  scene_name *e;
  uint32_t k, mask;
  carom_status s;
  if (p->world)
    {
      p->name_entry = found;
      return CAROM_OK;
    }
  if (found >= 0)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: the name '%s' is already the body of line %ld", what, p->name,
                       (long) p->names[found].line);
  if (!scene_name_room (p))
    return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
  e = &p->names[p->name_count];
  s = scene_keep_text (p, p->name, &e->text);
  if (s != CAROM_OK)
    return s;
  e->line = p->line;
  e->type = p->body.type;
  e->id = e->stub = CAROM_NULL_BODY;
  mask = (uint32_t) p->slot_cap - 1;
  for (k = scene_hash (p->name) & mask; p->slots[k]; k = (k + 1) & mask)
    ;
  p->slots[k] = p->name_count + 1;
  p->name_entry = p->name_count++;
  return CAROM_OK;
}

/* ------------------------------------------------------------- handlers */

static carom_status scene_do_gravity (scene_parser *p)
{
  p->def.gravity_x = p->num[0];
  p->def.gravity_y = p->num[1];
  return CAROM_OK;
}

static carom_status scene_do_restitution (scene_parser *p)
{
  carom_status s = scene_restitution (p, p->num[0]);
  if (s == CAROM_OK)
    p->def.restitution = p->num[0];
  return s;
}

static carom_status scene_do_friction (scene_parser *p)
{
  carom_status s = scene_friction (p, p->num[0]);
  if (s == CAROM_OK)
    p->def.friction = p->num[0];
  return s;
}

static carom_status scene_do_substeps (scene_parser *p)
{
  return scene_count (p, p->num[0], "K", 1, INT32_MAX, CAROM_ERR_BAD_ARGUMENT, &p->def.substeps);
}

static carom_status scene_do_iterations (scene_parser *p)
{
  return scene_count (p, p->num[0], "N", 1, INT32_MAX, CAROM_ERR_BAD_ARGUMENT, &p->def.iterations);
}

/* Name the line's body in an error from the world, apply what the body def
 * does not hold and remember a named body's id (second pass only). */
static carom_status scene_added (scene_parser *p, carom_status s)
{
  if (s == CAROM_OK && (p->opts & OPT_FIXED))
    s = carom_body_set_fixed_rotation (p->world, p->last, 1);
  if (s == CAROM_OK && (p->opts & OPT_BULLET))
    s = carom_body_set_bullet (p->world, p->last, 1);
  if (s == CAROM_OK && p->name_entry >= 0)
    p->names[p->name_entry].id = p->last; /* for the joints that name it */
  if (s == CAROM_OK)
    return s;
  return scene_fail (p, s, "%s: %s", p->tok[0], carom_status_string (s));
}

/* Walls of thickness 5% of the smaller side, outside the rectangle; the top
 * and bottom walls run past the corners so the box has no gaps. */
static carom_status scene_do_bounds (scene_parser *p)
{
  double x0 = p->num[0], y0 = p->num[1], x1 = p->num[2], y1 = p->num[3];
  double w = x1 - x0, h = y1 - y0, t, cx, cy;
  carom_body_def d = p->body;
  carom_status s = CAROM_OK;
  if (!isfinite (w) || !isfinite (h))
    return scene_fail (p, CAROM_ERR_NOT_FINITE, "bounds: the rectangle is too large");
  if (w <= 0.0 || h <= 0.0)
    return scene_fail (p, CAROM_ERR_BAD_SIZE, "bounds: need X0 < X1 and Y0 < Y1");
  if (!p->world)
    return CAROM_OK;
  t = 0.05 * (w < h ? w : h);
  cx = 0.5 * (x0 + x1);
  cy = 0.5 * (y0 + y1);
  d.type = CAROM_STATIC;
  d.x = cx, d.y = y0 - 0.5 * t;
  s = carom_world_add_box (p->world, &d, w + 2.0 * t, t, NULL);
  d.x = cx, d.y = y1 + 0.5 * t;
  if (s == CAROM_OK)
    s = carom_world_add_box (p->world, &d, w + 2.0 * t, t, NULL);
  d.x = x0 - 0.5 * t, d.y = cy;
  if (s == CAROM_OK)
    s = carom_world_add_box (p->world, &d, t, h, NULL);
  d.x = x1 + 0.5 * t, d.y = cy;
  if (s == CAROM_OK)
    s = carom_world_add_box (p->world, &d, t, h, NULL);
  return scene_added (p, s);
}

static carom_status scene_do_circle (scene_parser *p)
{
  carom_status s = scene_positive (p, p->num[0], "radius R", CAROM_ERR_BAD_SIZE);
  if (s != CAROM_OK || !p->world)
    return s;
  return scene_added (p, carom_world_add_circle (p->world, &p->body, p->num[0], &p->last));
}

/* The numbers of a box, a regular polygon and a polygon line, as a body
 * or as a compound's shape: sizes positive, vertex counts in range (the
 * count in *n). */
static carom_status scene_box_sizes (scene_parser *p)
{
  carom_status s = scene_positive (p, p->num[0], "width W", CAROM_ERR_BAD_SIZE);
  if (s == CAROM_OK)
    s = scene_positive (p, p->num[1], "height H", CAROM_ERR_BAD_SIZE);
  return s;
}

static carom_status scene_regular_sizes (scene_parser *p, int32_t *n)
{
  carom_status s = scene_count (p, p->num[0], "N", 3, CAROM_MAX_POLYGON_VERTICES,
                                p->num[0] < 3 ? CAROM_ERR_TOO_FEW_VERTICES : CAROM_ERR_TOO_MANY_VERTICES, n);
  if (s == CAROM_OK)
    s = scene_positive (p, p->num[1], "side length", CAROM_ERR_BAD_SIZE);
  return s;
}

static carom_status scene_polygon_count (scene_parser *p, int32_t *n)
{
  *n = p->num_count / 2;
  if (p->num_count % 2)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "polygon: vertices come in X Y pairs, got %ld numbers",
                       (long) p->num_count);
  if (*n < 3)
    return scene_fail (p, CAROM_ERR_TOO_FEW_VERTICES, "polygon: needs at least 3 vertices, got %ld", (long) *n);
  if (*n > CAROM_MAX_POLYGON_VERTICES)
    return scene_fail (p, CAROM_ERR_TOO_MANY_VERTICES, "polygon: at most %d vertices, got %ld",
                       CAROM_MAX_POLYGON_VERTICES, (long) *n);
  return CAROM_OK;
}

static carom_status scene_do_box (scene_parser *p)
{
  carom_status s = scene_box_sizes (p);
  if (s != CAROM_OK || !p->world)
    return s;
  return scene_added (p, carom_world_add_box (p->world, &p->body, p->num[0], p->num[1], &p->last));
}

static carom_status scene_do_regular (scene_parser *p)
{
  int32_t n = 0;
  carom_status s = scene_regular_sizes (p, &n);
  if (s != CAROM_OK || !p->world)
    return s;
  return scene_added (p, carom_world_add_regular (p->world, &p->body, n, p->num[1], &p->last));
}

static carom_status scene_do_polygon (scene_parser *p)
{
  int32_t n = 0;
  carom_status s = scene_polygon_count (p, &n);
  if (s != CAROM_OK)
    return s;
  if (!p->world)
    {
      /* the world's own check, so the first pass sees geometry errors too */
      s = polygon_validate (p->num, n);
      if (s != CAROM_OK)
        return scene_fail (p, s, "polygon: %s", carom_status_string (s));
      return CAROM_OK;
    }
  return scene_added (p, carom_world_add_polygon (p->world, &p->body, p->num, n, &p->last));
}

/* ------------------------------------------------------------ compounds */

static carom_status scene_do_compound (scene_parser *p)
{
  if (p->in_compound)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "compound: the compound of line %ld has no 'end' yet",
                       (long) p->compound_line);
  p->in_compound = 1;
  p->compound_line = p->line;
  p->compound = p->body;
  p->compound_opts = p->opts;
  p->compound_name = p->name_entry;
  p->part_count = p->xy_count = 0;
  return CAROM_OK;
}

/* The compound's shapes with their vertex pointers set (part_xy may have
 * moved since each was added). */
static void scene_part_pointers (scene_parser *p)
{
  int32_t i;
  for (i = 0; i < p->part_count; ++i)
    p->parts[i].xy = p->parts[i].kind == CAROM_SHAPE_POLYGON ? p->part_xy + p->part_first[i] : NULL;
}

/* Add the compound of shapes [0, count) to `world` (and, for the trial
 * world, remove it again). */
static carom_status scene_add_compound (scene_parser *p, carom_world *world, int32_t first, int32_t count,
                                        carom_body_id *id)
{
  carom_body_id local;
  carom_status s;
  scene_part_pointers (p);
  s = carom_world_add_compound (world, &p->compound, p->parts + first, count, &local);
  if (s == CAROM_OK && world == p->trial)
    carom_world_remove_body (world, local);
  if (id)
    *id = local;
  return s;
}

/* In the first pass, whether the world would take `count` shapes from
 * `first` as a body: an empty world made once for these trials. */
static carom_status scene_try_compound (scene_parser *p, int32_t first, int32_t count)
{
  carom_status s;
  if (!p->trial)
    {
      s = carom_world_init (&p->trial, &p->def);
      if (s != CAROM_OK)
        return s;
    }
  return scene_add_compound (p, p->trial, first, count, NULL);
}

/* A shape line inside a compound block: its def from the line's numbers and
 * options, polygon vertices (a box's and a regular polygon's made here)
 * appended to part_xy. */
static carom_status scene_do_part (scene_parser *p)
{
  carom_shape_def *d;
  int32_t n = 0;
  const char *what = p->tok[0];
  carom_status s = CAROM_OK;
  if (p->part_count >= CAROM_MAX_COMPOUND_SHAPES)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "%s: a compound has at most %d shapes", what,
                       CAROM_MAX_COMPOUND_SHAPES);
  if (!mem_reserve (&p->allocator, (void **) &p->parts, &p->part_cap, p->part_count + 1, sizeof *p->parts)
      || !mem_reserve (&p->allocator, (void **) &p->part_first, &p->first_cap, p->part_count + 1,
                       sizeof *p->part_first))
    return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
  d = &p->parts[p->part_count];
  carom_shape_def_init (d, sizeof *d);
  d->x = p->body.x, d->y = p->body.y, d->angle = p->body.angle;
  if (p->opts & OPT_DENSITY)
    d->density = p->body.density;
  d->restitution = p->body.restitution;
  d->friction = p->body.friction;
  p->part_first[p->part_count] = p->xy_count;
  if (strcmp (what, "circle") == 0)
    {
      s = scene_positive (p, p->num[0], "radius R", CAROM_ERR_BAD_SIZE);
      d->radius = p->num[0];
    }
  else
    {
      int box = strcmp (what, "box") == 0, regular = strcmp (what, "regular") == 0;
      d->kind = CAROM_SHAPE_POLYGON;
      n = 4;
      s = box ? scene_box_sizes (p) : regular ? scene_regular_sizes (p, &n) : scene_polygon_count (p, &n);
      if (s != CAROM_OK)
        return s;
      if (!mem_reserve (&p->allocator, (void **) &p->part_xy, &p->xy_cap, p->xy_count + 2 * n, sizeof *p->part_xy))
        return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
      /* the outlines carom_world_add_box and _add_regular build */
      if (box)
        box_vertices (p->num[0], p->num[1], p->part_xy + p->xy_count);
      else if (regular)
        regular_vertices (n, p->num[1], p->part_xy + p->xy_count);
      else
        memcpy (p->part_xy + p->xy_count, p->num, (size_t) n * 2 * sizeof (double));
      d->count = n;
      p->xy_count += 2 * n;
    }
  if (s != CAROM_OK)
    return s;
  p->part_count++;
  if (!p->world)
    {
      /* the world's verdict on this shape alone, on its own line */
      s = scene_try_compound (p, p->part_count - 1, 1);
      if (s != CAROM_OK)
        return scene_fail (p, s, "%s: %s", what, carom_status_string (s));
    }
  return CAROM_OK;
}

static carom_status scene_do_end (scene_parser *p)
{
  carom_status s;
  if (!p->in_compound)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "end: no compound to end");
  p->in_compound = 0;
  if (p->part_count == 0)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "end: the compound of line %ld has no shapes",
                       (long) p->compound_line);
  p->opts = p->compound_opts;
  p->name_entry = p->compound_name;
  if (!p->world)
    {
      s = scene_try_compound (p, 0, p->part_count);
      if (s != CAROM_OK)
        return scene_fail (p, s, "end: the compound of line %ld: %s", (long) p->compound_line,
                           carom_status_string (s));
      return CAROM_OK;
    }
  s = scene_add_compound (p, p->world, 0, p->part_count, &p->last);
  if (s != CAROM_OK)
    return scene_fail (p, s, "end: the compound of line %ld: %s", (long) p->compound_line, carom_status_string (s));
  return scene_added (p, s);
}

/* ---------------------------------------------------------------- joints */

/* A body of `type` in the trial world (made once, into *id), for checking
 * the joints that name a body of that type. */
static carom_status scene_trial_body (scene_parser *p, carom_body_type type, carom_body_id *id)
{
  carom_body_def d;
  carom_status s;
  if (*id != CAROM_NULL_BODY)
    return CAROM_OK;
  if (!p->trial)
    {
      s = carom_world_init (&p->trial, &p->def);
      if (s != CAROM_OK)
        return s;
    }
  carom_body_def_init (&d, sizeof d);
  d.type = type;
  return carom_world_add_circle (p->trial, &d, 1.0, id);
}

/* The world's verdict on the joint between trial bodies a (or the world)
 * and b; the joint is removed again. */
static carom_status scene_try_joint (scene_parser *p, const scene_joint *j, carom_body_id a, carom_body_id b)
{
  carom_joint_def d = j->def;
  carom_joint_id id;
  carom_status s;
  d.a = a, d.b = b;
  s = carom_world_add_joint (p->trial, &d, &id);
  if (s == CAROM_OK)
    carom_world_remove_joint (p->trial, id);
  return s;
}

/* A joint's error, from the world's status `s`, in words: what in the line
 * the world refused (the checks of carom_world_add_joint, in its order). */
static carom_status scene_joint_fail (scene_parser *p, const scene_joint *j, carom_status s)
{
  const carom_joint_def *d = &j->def;
  const char *what = j->kind->word;
  const double values[] = { d->x, d->y, d->x2, d->y2, d->axis_x, d->axis_y, d->lower, d->upper, d->motor_speed,
                            d->max_motor_force, d->hertz, d->damping_ratio, d->length, d->max_motor_torque };
  size_t i;
  if (s == CAROM_ERR_STATIC_BODY && j->ref[0] < 0)
    return scene_fail (p, s, "joint %s: '%s' is not a dynamic body", what, p->text + j->ref[1]);
  if (s == CAROM_ERR_STATIC_BODY)
    return scene_fail (p, s, "joint %s: neither '%s' nor '%s' is a dynamic body", what, p->text + j->ref[0],
                       p->text + j->ref[1]);
  if (s != CAROM_ERR_BAD_ARGUMENT)
    return scene_fail (p, s, "joint %s: %s", what, carom_status_string (s));
  for (i = 0; i < sizeof values / sizeof values[0]; ++i)
    if (fabs (values[i]) > CAROM_MAX_MAGNITUDE)
      return scene_fail (p, s, "joint %s: numbers must not exceed %g", what, CAROM_MAX_MAGNITUDE);
  if (d->enable_limit && d->lower > d->upper)
    return scene_fail (p, s, "joint %s: the limit's lower end %g is above its upper end %g", what, d->lower, d->upper);
  if (d->max_motor_force < 0.0 || d->max_motor_torque < 0.0)
    return scene_fail (p, s, "joint %s: a force or torque must be 0 or more", what);
  if (d->hertz < 0.0 || d->damping_ratio < 0.0)
    return scene_fail (p, s, "joint %s: a spring's frequency and damping ratio must be 0 or more", what);
  if ((d->type == CAROM_JOINT_PRISMATIC || d->type == CAROM_JOINT_WHEEL) && d->axis_x == 0.0 && d->axis_y == 0.0)
    return scene_fail (p, s, "joint %s: the axis must not be zero", what);
  if (d->type == CAROM_JOINT_DISTANCE && d->length == 0.0)
    return scene_fail (p, s, "joint %s: the anchors coincide: give a length", what);
  return scene_fail (p, s, "joint %s: %s", what, carom_status_string (s));
}

/* `joint KIND A B [options]` (mouse: `joint mouse B ...`): its def from the
 * line, checked between two dynamic trial bodies, so what the line alone
 * gets wrong is reported on it; kept for the end of the first pass, which
 * resolves the names, and the end of the second, which makes it. */
static carom_status scene_do_joint (scene_parser *p)
{
  const scene_joint_kind *kind = NULL;
  scene_joint j;
  unsigned given = 0;
  int32_t i, n;
  size_t k;
  carom_status s;
  if (p->tok_count < 2)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX,
                       "joint: which joint? (revolute, prismatic, wheel, distance, weld, motor or mouse)");
  for (k = 0; k < sizeof scene_joint_kinds / sizeof scene_joint_kinds[0]; ++k)
    if (strcmp (p->tok[1], scene_joint_kinds[k].word) == 0)
      kind = &scene_joint_kinds[k];
  if (!kind)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX,
                       "joint: unknown joint '%s' (revolute, prismatic, wheel, distance, weld, motor or mouse)",
                       p->tok[1]);
  memset (&j, 0, sizeof j);
  carom_joint_def_init (&j.def, sizeof j.def);
  j.def.type = kind->type;
  j.line = p->line;
  j.kind = kind;
  j.ref[0] = j.ref[1] = -1;

  /* the bodies: A and B, or B alone; `world` only as A */
  for (i = 2, n = 0; n < kind->bodies; ++n, ++i)
    {
      int32_t side = kind->bodies == 2 ? n : 1;
      const char *name = i < p->tok_count ? p->tok[i] : NULL;
      if (!name || scene_looks_numeric (name))
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: expected %s, got %s%s%s (usage: %s)", kind->word,
                           kind->bodies == 2 ? "the names of two bodies" : "the name of a body", name ? "'" : "",
                           name ? name : "nothing", name ? "'" : "", kind->usage);
      if (strcmp (name, SCENE_WORLD) == 0 && side == 1)
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: B must be a body, not '%s'%s (usage: %s)", kind->word,
                           SCENE_WORLD, kind->bodies == 2 ? " (the world can only be A)" : "", kind->usage);
      if (strcmp (name, SCENE_WORLD) == 0)
        continue;
      if (!scene_is_name (name))
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: '%s' is not a body's name", kind->word, name);
      s = scene_keep_text (p, name, &j.ref[side]);
      if (s != CAROM_OK)
        return s;
    }
  if (j.ref[0] >= 0 && strcmp (p->text + j.ref[0], p->text + j.ref[1]) == 0)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "joint %s: '%s' cannot be joined to itself", kind->word,
                       p->text + j.ref[0]);

  /* the options, each at most once, in any order */
  while (i < p->tok_count)
    {
      const char *word = p->tok[i++];
      const scene_option *opt
        = scene_lookup_option (scene_joint_options, sizeof scene_joint_options / sizeof scene_joint_options[0], word);
      double v[2] = { 0.0, 0.0 };
      int c;
      if (scene_looks_numeric (word))
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: unexpected number '%s' (usage: %s)", kind->word, word,
                           kind->usage);
      if (!opt || !(opt->bit & kind->options))
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: unknown option '%s' (usage: %s)", kind->word, word,
                           kind->usage);
      if (given & opt->bit)
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: option '%s' given twice", kind->word, word);
      given |= opt->bit;
      for (c = 0; c < opt->count; ++c)
        {
          if (i >= p->tok_count || !scene_looks_numeric (p->tok[i]))
            return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: option '%s' needs %d number%s", kind->word, word,
                               opt->count, opt->count > 1 ? "s" : "");
          s = scene_number (p, p->tok[i++], &v[c]);
          if (s != CAROM_OK)
            return s;
        }
      switch (opt->bit)
        {
        case JOPT_AT: j.def.x = v[0], j.def.y = v[1]; break;
        case JOPT_TO: j.def.x2 = v[0], j.def.y2 = v[1]; break;
        case JOPT_AXIS: j.def.axis_x = v[0], j.def.axis_y = v[1]; break;
        case JOPT_LIMIT: j.def.enable_limit = 1, j.def.lower = v[0], j.def.upper = v[1]; break;
        case JOPT_MOTOR: j.def.enable_motor = 1, j.def.motor_speed = v[0], j.def.max_motor_force = v[1]; break;
        case JOPT_SPRING: j.def.enable_spring = 1, j.def.hertz = v[0], j.def.damping_ratio = v[1]; break;
        case JOPT_LENGTH:
          if (!(v[0] > 0.0))
            return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "joint %s: length must be positive, got %g", kind->word,
                               v[0]);
          j.def.length = v[0];
          break;
        case JOPT_FORCE: j.def.max_motor_force = v[0]; break;
        case JOPT_TORQUE: j.def.max_motor_torque = v[0]; break;
        case JOPT_COLLIDE: j.def.collide_connected = 1; break;
        }
    }
  for (k = 0; k < sizeof scene_joint_options / sizeof scene_joint_options[0]; ++k)
    if ((kind->needs & scene_joint_options[k].bit) && !(given & scene_joint_options[k].bit))
      return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: needs '%s' (usage: %s)", kind->word,
                         scene_joint_options[k].word, kind->usage);

  /* what the world says to the line's values, between dynamic bodies */
  s = scene_trial_body (p, CAROM_DYNAMIC, &p->trial_pair[0]);
  if (s == CAROM_OK)
    s = scene_trial_body (p, CAROM_DYNAMIC, &p->trial_pair[1]);
  if (s == CAROM_OK)
    s = scene_try_joint (p, &j, j.ref[0] < 0 ? CAROM_NULL_BODY : p->trial_pair[0], p->trial_pair[1]);
  if (s != CAROM_OK)
    return scene_joint_fail (p, &j, s);
  if (!mem_reserve (&p->allocator, (void **) &p->joints, &p->joint_cap, p->joint_count + 1, sizeof *p->joints))
    return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
  p->joints[p->joint_count++] = j;
  return CAROM_OK;
}

/* After the first pass: each joint's names are bodies' (or the world), and
 * the world takes the joint between bodies of their types; errors at the
 * joint's line, in line order. */
static carom_status scene_check_joints (scene_parser *p)
{
  int32_t i, k;
  for (i = 0; i < p->joint_count; ++i)
    {
      scene_joint *j = &p->joints[i];
      carom_body_id ids[2] = { CAROM_NULL_BODY, CAROM_NULL_BODY };
      carom_status s;
      p->line = j->line;
      for (k = 0; k < 2; ++k)
        {
          scene_name *e;
          j->entry[k] = -1;
          if (j->ref[k] < 0)
            continue;
          j->entry[k] = scene_name_find (p, p->text + j->ref[k]);
          if (j->entry[k] < 0)
            return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "joint %s: no body is named '%s'", j->kind->word,
                               p->text + j->ref[k]);
          e = &p->names[j->entry[k]];
          s = scene_trial_body (p, e->type, &e->stub);
          if (s != CAROM_OK)
            return scene_joint_fail (p, j, s);
          ids[k] = e->stub;
        }
      s = scene_try_joint (p, j, ids[0], ids[1]);
      if (s != CAROM_OK)
        return scene_joint_fail (p, j, s);
    }
  p->line = 0;
  return CAROM_OK;
}

/* After the second pass: the joints, between the bodies they name. */
static carom_status scene_add_joints (scene_parser *p)
{
  int32_t i;
  for (i = 0; i < p->joint_count; ++i)
    {
      const scene_joint *j = &p->joints[i];
      carom_joint_def d = j->def;
      carom_status s;
      d.a = j->entry[0] < 0 ? CAROM_NULL_BODY : p->names[j->entry[0]].id;
      d.b = p->names[j->entry[1]].id;
      s = carom_world_add_joint (p->world, &d, NULL);
      if (s != CAROM_OK)
        {
          p->line = j->line;
          return scene_joint_fail (p, j, s);
        }
    }
  return CAROM_OK;
}

static carom_status scene_do_central (scene_parser *p)
{
  p->central[0] = p->num[0];
  p->central[1] = p->num[1];
  p->central[2] = p->num[2];
  p->central[3] = p->num_count > 3 ? p->num[3] : 0.0;
  if (p->central[2] < 0.0 || p->central[3] < 0.0)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "central: GM and SOFTENING must be 0 or more");
  if (fabs (p->central[0]) > CAROM_MAX_MAGNITUDE || fabs (p->central[1]) > CAROM_MAX_MAGNITUDE
      || p->central[2] > CAROM_MAX_MAGNITUDE || p->central[3] > CAROM_MAX_MAGNITUDE)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "central: values must not exceed %g", CAROM_MAX_MAGNITUDE);
  return CAROM_OK;
}

static carom_status scene_do_continuous (scene_parser *p)
{
  if (p->num[0] != 0.0 && p->num[0] != 1.0)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "continuous: 1 (on, the default) or 0 (off), got %g", p->num[0]);
  p->continuous = p->num[0] != 0.0;
  return CAROM_OK;
}

static carom_status scene_do_damping (scene_parser *p)
{
  p->damping[0] = p->num[0];
  p->damping[1] = p->num_count > 1 ? p->num[1] : 0.0;
  if (p->damping[0] < 0.0 || p->damping[1] < 0.0)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "damping: rates must be 0 or more");
  if (p->damping[0] > CAROM_MAX_MAGNITUDE || p->damping[1] > CAROM_MAX_MAGNITUDE)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "damping: rates must not exceed %g", CAROM_MAX_MAGNITUDE);
  return CAROM_OK;
}

/* `effects NAME...`: sleeping and continuous, which have no parameter, are
 * switched on by naming them (unless `continuous 0` says otherwise); every
 * other named effect must be made active by the scene's other lines, or the
 * scene is rejected at this line. */
static carom_status scene_do_effects (scene_parser *p)
{
  int32_t i;
  if (p->tok_count < 2)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "effects: name at least one effect (usage: effects NAME...)");
  for (i = 1; i < p->tok_count; ++i)
    {
      uint32_t bit;
      for (bit = 1; bit && !(carom_effect_name ((carom_effect) bit)
                             && strcmp (carom_effect_name ((carom_effect) bit), p->tok[i]) == 0);
           bit <<= 1)
        ;
      if (!bit)
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "effects: unknown effect '%s'", p->tok[i]);
      if (bit == CAROM_EFFECT_SLEEPING)
        p->sleeping = 1;
      p->named_effects |= bit;
    }
  p->effects_line = p->line;
  return CAROM_OK;
}

/* Once the world exists: the effects whose settings are not in the def. */
static carom_status scene_apply_effects (scene_parser *p)
{
  carom_status s = CAROM_OK;
  if (p->central[2] > 0.0)
    s = carom_world_set_central_gravity (p->world, p->central[0], p->central[1], p->central[2], p->central[3]);
  if (s == CAROM_OK && (p->damping[0] > 0.0 || p->damping[1] > 0.0))
    s = carom_world_set_damping (p->world, p->damping[0], p->damping[1]);
  if (s == CAROM_OK && p->sleeping)
    s = carom_world_set_sleeping (p->world, 1);
  if (s == CAROM_OK && p->continuous >= 0) /* on by default; naming it keeps it on */
    s = carom_world_set_continuous (p->world, p->continuous);
  if (s != CAROM_OK)
    return scene_fail (p, s, "an effect was rejected: %s", carom_status_string (s));
  return CAROM_OK;
}

/* After the bodies: every effect named by `effects` is in use. */
static carom_status scene_check_named_effects (scene_parser *p)
{
  uint32_t missing = p->named_effects & ~carom_world_get_effects (p->world), bit;
  if (!missing)
    return CAROM_OK;
  for (bit = 1; !(missing & bit); bit <<= 1)
    ;
  p->line = p->effects_line;
  return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "effects: '%s' is named but nothing in the scene uses it",
                     carom_effect_name ((carom_effect) bit));
}

/* The statement table: a new statement is one row here plus its handler. */
static const scene_statement scene_statements[] = {
  { "gravity", SCENE_SETTING, 2, 2, 0, 0, "gravity GX GY", scene_do_gravity },
  { "restitution", SCENE_SETTING, 1, 1, 0, 0, "restitution E", scene_do_restitution },
  { "friction", SCENE_SETTING, 1, 1, 0, 0, "friction MU", scene_do_friction },
  { "substeps", SCENE_SETTING, 1, 1, 0, 0, "substeps K", scene_do_substeps },
  { "iterations", SCENE_SETTING, 1, 1, 0, 0, "iterations N", scene_do_iterations },
  { "central", SCENE_SETTING, 3, 4, 0, 0, "central X Y GM [SOFTENING]", scene_do_central },
  { "damping", SCENE_SETTING, 1, 2, 0, 0, "damping LINEAR [ANGULAR]", scene_do_damping },
  { "continuous", SCENE_SETTING, 1, 1, 0, 0, "continuous 1|0", scene_do_continuous },
  { "effects", SCENE_SETTING, 0, 0, 0, 1, "effects NAME...", scene_do_effects },
  { "bounds", SCENE_BODY, 4, 4, OPT_MATERIAL, 0, "bounds X0 Y0 X1 Y1 [restitution E] [friction MU]", scene_do_bounds },
  { "circle", SCENE_BODY, 1, 1, OPT_BODY, 0, "circle R [options]", scene_do_circle },
  { "box", SCENE_BODY, 2, 2, OPT_BODY, 0, "box W H [options]", scene_do_box },
  { "regular", SCENE_BODY, 2, 2, OPT_BODY, 0, "regular N SIDE [options]", scene_do_regular },
  { "polygon", SCENE_BODY, 6, -1, OPT_BODY, 0, "polygon X1 Y1 X2 Y2 X3 Y3 ... [options]", scene_do_polygon },
  { "compound", SCENE_BODY, 0, 0, OPT_BODY, 0, "compound [options], then its shapes, then end", scene_do_compound },
  { "end", SCENE_BODY, 0, 0, 0, 0, "end", scene_do_end },
  { "joint", SCENE_JOINT, 0, 0, 0, 1, "joint KIND A B [options]", scene_do_joint },
};

/* Inside a compound block: its shapes, with the options a shape takes. */
static const scene_statement scene_part_statements[] = {
  { "circle", SCENE_BODY, 1, 1, OPT_PART, 0, "circle R [at X Y] [density D] [restitution E] [friction MU]",
    scene_do_part },
  { "box", SCENE_BODY, 2, 2, OPT_PART, 0, "box W H [at X Y] [angle A] [density D] [restitution E] [friction MU]",
    scene_do_part },
  { "regular", SCENE_BODY, 2, 2, OPT_PART, 0, "regular N SIDE [at X Y] [angle A] [density D] ...", scene_do_part },
  { "polygon", SCENE_BODY, 6, -1, OPT_PART, 0, "polygon X1 Y1 X2 Y2 X3 Y3 ... [at X Y] [angle A] [density D] ...",
    scene_do_part },
  { "end", SCENE_BODY, 0, 0, 0, 0, "end", scene_do_end },
};

/* ------------------------------------------------------------ dispatcher */

static carom_status scene_push_number (scene_parser *p, double v)
{
  if (!mem_reserve (&p->allocator, (void **) &p->num, &p->num_cap, p->num_count + 1, sizeof *p->num))
    return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
  p->num[p->num_count++] = v;
  return CAROM_OK;
}

/* Apply option `opt` whose numbers are v[] to the body def. */
static carom_status scene_apply_option (scene_parser *p, const scene_option *opt, const double *v)
{
  carom_body_def *b = &p->body;
  carom_status s = CAROM_OK;
  switch (opt->bit)
    {
    case OPT_AT: b->x = v[0], b->y = v[1]; break;
    case OPT_ANGLE: b->angle = v[0]; break;
    case OPT_VELOCITY: b->vx = v[0], b->vy = v[1]; break;
    case OPT_SPIN: b->spin = v[0]; break;
    case OPT_DENSITY:
      s = scene_positive (p, v[0], "density", CAROM_ERR_BAD_DENSITY);
      b->density = v[0];
      break;
    case OPT_RESTITUTION:
      s = scene_restitution (p, v[0]);
      b->restitution = v[0];
      break;
    case OPT_FRICTION:
      s = scene_friction (p, v[0]);
      b->friction = v[0];
      break;
    case OPT_STATIC: b->type = CAROM_STATIC; break;
    case OPT_KINEMATIC: b->type = CAROM_KINEMATIC; break;
    case OPT_SENSOR: b->sensor = 1; break;
    case OPT_CATEGORY:
    case OPT_MASK:
      {
        /* bit sets: whole numbers from 0 to 2^32 - 1 (0xffffffff) */
        if (v[0] != floor (v[0]) || v[0] < 0.0 || v[0] > 4294967295.0)
          return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "%s: %s must be a whole number from 0 to 4294967295, got %g",
                             p->tok[0], opt->word, v[0]);
        if (opt->bit == OPT_CATEGORY)
          b->category = (uint32_t) v[0];
        else
          b->mask = (uint32_t) v[0];
        break;
      }
    case OPT_GROUP:
      s = scene_count (p, v[0], "group", -2147483648.0, 2147483647.0, CAROM_ERR_BAD_ARGUMENT, &b->group);
      break;
    case OPT_FIXED: break; /* applied once the body exists */
    case OPT_BULLET: break;
    case OPT_NAME: break;  /* a word, read by scene_arguments */
    }
  return s;
}

/* Parse the numbers and options after the statement word into p->num and
 * p->body. */
static carom_status scene_arguments (scene_parser *p, const scene_statement *st)
{
  int32_t i = 1;
  carom_status s;
  while (i < p->tok_count && scene_looks_numeric (p->tok[i]))
    {
      double v;
      if (st->max_numbers >= 0 && p->num_count == st->max_numbers)
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: too many numbers (usage: %s)", st->word, st->usage);
      s = scene_number (p, p->tok[i++], &v);
      if (s == CAROM_OK)
        s = scene_push_number (p, v);
      if (s != CAROM_OK)
        return s;
    }
  if (p->num_count < st->min_numbers)
    {
      if (i < p->tok_count && !scene_find_option (p->tok[i]))
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: expected a number, got '%s' (usage: %s)", st->word,
                           p->tok[i], st->usage);
      return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: missing numbers (usage: %s)", st->word, st->usage);
    }

  while (i < p->tok_count)
    {
      const char *word = p->tok[i++];
      const scene_option *opt = scene_find_option (word);
      double v[2];
      int k;
      if (scene_looks_numeric (word))
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: unexpected number '%s' (usage: %s)", st->word, word,
                           st->usage);
      if (!opt || !(opt->bit & st->options))
        {
          if (!st->options)
            return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: unexpected '%s' (usage: %s)", st->word, word,
                               st->usage);
          return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: unknown option '%s'", st->word, word);
        }
      if (p->opts & opt->bit)
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: option '%s' given twice", st->word, word);
      p->opts |= opt->bit;
      if (opt->count < 0)
        {
          /* `name NAME`: kept for the end of the line */
          s = scene_check_name (p, st->word, i < p->tok_count ? p->tok[i] : NULL);
          if (s != CAROM_OK)
            return s;
          p->name = p->tok[i++];
          continue;
        }
      for (k = 0; k < opt->count; ++k)
        {
          if (i >= p->tok_count || !scene_looks_numeric (p->tok[i]))
            return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: option '%s' needs %d number%s", st->word, word,
                               opt->count, opt->count > 1 ? "s" : "");
          s = scene_number (p, p->tok[i++], &v[k]);
          if (s != CAROM_OK)
            return s;
        }
      s = scene_apply_option (p, opt, v);
      if (s != CAROM_OK)
        return s;
    }
  if ((p->opts & OPT_STATIC) && (p->opts & OPT_KINEMATIC))
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "%s: a body is 'static' or 'kinematic', not both", st->word);
  if (p->body.type == CAROM_STATIC && (p->opts & (OPT_VELOCITY | OPT_SPIN | OPT_FIXED)))
    return scene_fail (p, CAROM_ERR_STATIC_BODY, "%s: a static body cannot have a velocity, spin or 'fixed'",
                       st->word);
  if (p->body.type == CAROM_KINEMATIC && (p->opts & OPT_FIXED))
    return scene_fail (p, CAROM_ERR_STATIC_BODY, "%s: a kinematic body cannot be 'fixed' (it turns as it is told)",
                       st->word);
  if ((p->opts & OPT_FIXED) && p->body.spin != 0.0)
    return scene_fail (p, CAROM_ERR_BAD_ARGUMENT, "%s: a 'fixed' (non-rotating) body cannot spin", st->word);
  if (p->opts & OPT_NAME)
    return scene_name_line (p, st->word);
  return CAROM_OK;
}

/* Would carom_world_init accept these settings? */
static carom_status scene_check_def (const carom_world_def *def)
{
  carom_world *trial = NULL;
  carom_status s = carom_world_init (&trial, def);
  carom_world_destroy (trial);
  return s;
}

static carom_status scene_statement_run (scene_parser *p)
{
  const scene_statement *st = NULL;
  carom_status s;
  size_t i;
  if (p->in_compound)
    {
      for (i = 0; i < sizeof scene_part_statements / sizeof scene_part_statements[0]; ++i)
        if (strcmp (p->tok[0], scene_part_statements[i].word) == 0)
          st = &scene_part_statements[i];
      if (!st)
        return scene_fail (p, CAROM_ERR_SCENE_SYNTAX,
                           "'%s' inside the compound of line %ld (only circle, box, regular, polygon and end)",
                           p->tok[0], (long) p->compound_line);
    }
  else
    for (i = 0; i < sizeof scene_statements / sizeof scene_statements[0]; ++i)
      if (strcmp (p->tok[0], scene_statements[i].word) == 0)
        st = &scene_statements[i];
  if (!st)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "unknown statement '%s'", p->tok[0]);
  if (p->world && st->kind != SCENE_BODY)
    return CAROM_OK; /* applied, or kept for after the bodies, in the first pass */
  p->num_count = 0;
  p->opts = 0;
  p->name = NULL;
  p->name_entry = -1;
  carom_body_def_init (&p->body, sizeof p->body);
  if (!st->words)
    {
      s = scene_arguments (p, st);
      if (s != CAROM_OK)
        return s;
    }
  s = st->run (p);
  if (s == CAROM_OK && st->kind == SCENE_SETTING)
    {
      /* The world knows its own limits (substeps <= 1000, ...): ask it now,
       * so an out-of-range setting is reported on its line. */
      s = scene_check_def (&p->def);
      if (s != CAROM_OK)
        return scene_fail (p, s, "%s: the world rejects this setting: %s", st->word, carom_status_string (s));
    }
  return s;
}

/* ----------------------------------------------------------------- lines */

static int scene_is_space (char c)
{
  return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

/* Copy text[0, len) into p->buf, cut the comment and split into tokens. */
static carom_status scene_split (scene_parser *p, const char *text, size_t len)
{
  char *c;
  if (len >= (size_t) INT32_MAX)
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "line longer than %ld bytes", (long) INT32_MAX - 1);
  if (memchr (text, '\0', len))
    return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "line contains a NUL byte");
  if (!mem_reserve (&p->allocator, (void **) &p->buf, &p->buf_cap, (int32_t) len + 1, 1))
    return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
  memcpy (p->buf, text, len);
  p->buf[len] = '\0';
  c = strchr (p->buf, '#');
  if (c)
    *c = '\0';

  p->tok_count = 0;
  for (c = p->buf;;)
    {
      while (scene_is_space (*c))
        ++c;
      if (!*c)
        break;
      if (!mem_reserve (&p->allocator, (void **) &p->tok, &p->tok_cap, p->tok_count + 1, sizeof *p->tok))
        return scene_fail (p, CAROM_ERR_OUT_OF_MEMORY, "out of memory");
      p->tok[p->tok_count++] = c;
      while (*c && !scene_is_space (*c))
        ++c;
      if (*c)
        *c++ = '\0';
    }
  return CAROM_OK;
}

/* One pass over the text; stops at the first error. */
static carom_status scene_pass (scene_parser *p, const char *text, size_t length)
{
  size_t at = 0;
  p->line = 0;
  /* a UTF-8 byte order mark, as some editors write */
  if (length >= 3 && memcmp (text, "\xEF\xBB\xBF", 3) == 0)
    at = 3;
  while (at < length)
    {
      size_t end = at;
      carom_status s;
      while (end < length && text[end] != '\n' && text[end] != '\r')
        ++end;
      ++p->line;
      s = scene_split (p, text + at, end - at);
      if (s == CAROM_OK && p->tok_count > 0)
        s = scene_statement_run (p);
      if (s != CAROM_OK)
        return s;
      /* "\n", "\r\n" and a lone "\r" each end one line */
      if (end < length && text[end] == '\r' && end + 1 < length && text[end + 1] == '\n')
        ++end;
      at = end + 1;
    }
  if (p->in_compound)
    {
      p->in_compound = 0;
      p->line = p->compound_line;
      return scene_fail (p, CAROM_ERR_SCENE_SYNTAX, "compound: no 'end' before the end of the file");
    }
  p->line = 0;
  return CAROM_OK;
}

static void scene_parser_destroy (scene_parser *p)
{
  mem_free (&p->allocator, p->buf, (size_t) p->buf_cap);
  mem_free (&p->allocator, p->tok, (size_t) p->tok_cap * sizeof *p->tok);
  mem_free (&p->allocator, p->num, (size_t) p->num_cap * sizeof *p->num);
  mem_free (&p->allocator, p->parts, (size_t) p->part_cap * sizeof *p->parts);
  mem_free (&p->allocator, p->part_first, (size_t) p->first_cap * sizeof *p->part_first);
  mem_free (&p->allocator, p->part_xy, (size_t) p->xy_cap * sizeof *p->part_xy);
  mem_free (&p->allocator, p->names, (size_t) p->name_cap * sizeof *p->names);
  mem_free (&p->allocator, p->slots, (size_t) p->slot_cap * sizeof *p->slots);
  mem_free (&p->allocator, p->text, (size_t) p->text_cap);
  mem_free (&p->allocator, p->joints, (size_t) p->joint_cap * sizeof *p->joints);
  carom_world_destroy (p->trial);
}

/* Start from the caller's settings, or the defaults. */
static carom_status scene_parser_init (scene_parser *p, const carom_world_def *def)
{
  carom_status s;
  memset (p, 0, sizeof *p);
  p->continuous = -1;
  s = world_def_import (def, &p->def);
  if (s != CAROM_OK)
    return scene_fail (p, s, "the world def's size field is %lu, this library knows %lu to %lu",
                       (unsigned long) def->size, (unsigned long) WORLD_DEF_SIZE_0_1,
                       (unsigned long) sizeof (carom_world_def));
  /* checked before its allocator is used for scratch memory */
  s = scene_check_def (&p->def);
  if (s != CAROM_OK)
    return scene_fail (p, s, "the world def is rejected: %s", carom_status_string (s));
  p->allocator = p->def.allocator;
  return CAROM_OK;
}

carom_status carom_scene_load_text (carom_world **world, const char *text, size_t length, const carom_world_def *def,
                                    carom_scene_error *error)
{
  scene_parser p;
  carom_status s;
  if (world)
    *world = NULL;
  s = scene_parser_init (&p, def);
  if (s == CAROM_OK && (!world || (!text && length > 0)))
    s = scene_fail (&p, CAROM_ERR_NULL_ARGUMENT, "%s is NULL", world ? "text" : "world");
  if (s == CAROM_OK)
    s = scene_pass (&p, text, length);
  if (s == CAROM_OK)
    s = scene_check_joints (&p);
  if (s == CAROM_OK)
    {
      s = carom_world_init (&p.world, &p.def);
      if (s != CAROM_OK)
        scene_fail (&p, s, "the world settings were rejected: %s", carom_status_string (s));
    }
  if (s == CAROM_OK)
    s = scene_apply_effects (&p);
  if (s == CAROM_OK)
    s = scene_pass (&p, text, length);
  if (s == CAROM_OK)
    s = scene_add_joints (&p);
  if (s == CAROM_OK)
    s = scene_check_named_effects (&p);
  if (s == CAROM_OK)
    {
      *world = p.world;
      p.message[0] = '\0';
    }
  else
    carom_world_destroy (p.world);
  scene_report (&p, error);
  scene_parser_destroy (&p);
  return s;
}

carom_status carom_scene_load_file (carom_world **world, const char *path, const carom_world_def *def,
                                    carom_scene_error *error)
{
  scene_parser p;
  carom_status s;
  FILE *f = NULL;
  char *text = NULL;
  size_t len = 0, cap = 0;
  if (world)
    *world = NULL;
  s = scene_parser_init (&p, def);
  if (s == CAROM_OK && (!world || !path))
    s = scene_fail (&p, CAROM_ERR_NULL_ARGUMENT, "%s is NULL", world ? "path" : "world");
  if (s == CAROM_OK && !(f = fopen (path, "rb")))
    s = scene_fail (&p, CAROM_ERR_IO, "cannot open %s: %s", path, strerror (errno));
  while (s == CAROM_OK)
    {
      size_t got;
      if (len == cap)
        {
          size_t new_cap = cap ? 2 * cap : 4096;
          char *t = new_cap > cap ? mem_realloc (&p.allocator, text, cap, new_cap) : NULL;
          if (!t)
            {
              s = scene_fail (&p, CAROM_ERR_OUT_OF_MEMORY, "out of memory reading the file");
              break;
            }
          text = t;
          cap = new_cap;
        }
      got = fread (text + len, 1, cap - len, f);
      len += got;
      if (got == 0)
        {
          if (ferror (f))
            s = scene_fail (&p, CAROM_ERR_IO, "cannot read: %s", strerror (errno));
          break;
        }
    }
  if (f)
    fclose (f);
  if (s == CAROM_OK)
    s = carom_scene_load_text (world, text, len, def, error);
  else
    scene_report (&p, error);
  mem_free (&p.allocator, text, cap);
  scene_parser_destroy (&p);
  return s;
}
