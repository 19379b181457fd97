/* Seams (seams.h). An edge of a static convex piece is internal when an edge
 * of another static piece lies along it, facing it, and covers it whole:
 * on the same line (to SEAM_TOLERANCE of the shorter edge), with opposite
 * normals, its ends beyond both of the first one's. A partly covered edge
 * stays an outer one (a small box on a large floor: the box's bottom is
 * internal, the floor's top is not). Static sensors make no seams. */
#include "seams.h"

#include "world.h"

/* Collinear and covering to this fraction of the shorter edge's length,
 * plus the rounding of the coordinates. */
#define SEAM_TOLERANCE 1e-9
/* Edges beyond this index of a piece are never marked (one bit each). */
#define SEAM_MAX_EDGES 64

static vec2 world_vertex (const body *b, const convex_piece *p, int32_t i)
{
  xform x;
  x.p = b->p, x.q = b->q;
  return xform_apply (x, p->vertices[i % p->count]);
}

/* Whether edge i of piece p (of body a) lies along edge j of piece q (of
 * body b), facing it, covered by it whole. */
static int covered (const body *a, const convex_piece *p, int32_t i, const body *b, const convex_piece *q, int32_t j)
{
  vec2 p1 = world_vertex (a, p, i), p2 = world_vertex (a, p, i + 1);
  vec2 q1 = world_vertex (b, q, j), q2 = world_vertex (b, q, j + 1);
  vec2 d = v2_sub (p2, p1), e = v2_sub (q2, q1);
  double len = v2_len (d), len_q = v2_len (e), scale, tol, u1, u2;
  vec2 t, n;
  if (!(len > 0.0) || !(len_q > 0.0))
    return 0;
  scale = fabs (p1.x) + fabs (p1.y) + fabs (q1.x) + fabs (q1.y);
  tol = SEAM_TOLERANCE * (len < len_q ? len : len_q) + 1e-15 * scale;
  t = v2_scale (d, 1.0 / len);
  n = v2 (t.y, -t.x); /* outward: the pieces are counter-clockwise */
  /* facing: q's edge runs the other way */
  if (!(v2_dot (e, t) < -(1.0 - SEAM_TOLERANCE) * len_q))
    return 0;
  if (fabs (v2_dot (v2_sub (q1, p1), n)) > tol || fabs (v2_dot (v2_sub (q2, p1), n)) > tol)
    return 0;
  /* along t, q's edge spans [u2, u1] (it runs backwards): it must hold [0, len] */
  u1 = v2_dot (v2_sub (q1, p1), t);
  u2 = v2_dot (v2_sub (q2, p1), t);
  return u2 <= tol && u1 >= len - tol;
}

static void mark (body *a, convex_piece *p, const body *b, const convex_piece *q)
{
  int32_t i, j;
  for (i = 0; i < p->count && i < SEAM_MAX_EDGES; ++i)
    for (j = 0; j < q->count; ++j)
      if (covered (a, p, i, b, q, j))
        {
          p->internal |= (uint64_t) 1 << i;
          break;
        }
}

static int boxes_touch (const body *a, const body *b)
{
  double tol = SEAM_TOLERANCE * (a->shape.size < b->shape.size ? a->shape.size : b->shape.size);
  return a->box_lo.x <= b->box_hi.x + tol && b->box_lo.x <= a->box_hi.x + tol && a->box_lo.y <= b->box_hi.y + tol
         && b->box_lo.y <= a->box_hi.y + tol;
}

void seams_update (carom_world *world)
{
  int32_t i, j, u, v;
  world->seams_dirty = 0;
  for (i = 0; i < world->slot_count; ++i)
    {
      body *b = &world->bodies[i];
      if (b->alive && b->type == CAROM_STATIC)
        for (u = 0; u < b->shape.piece_count; ++u)
          b->shape.pieces[u].internal = 0;
    }
  for (i = 0; i < world->slot_count; ++i)
    {
      body *a = &world->bodies[i];
      if (!a->alive || a->type != CAROM_STATIC || a->sensor || a->shape.kind == CAROM_SHAPE_CIRCLE)
        continue;
      for (j = i; j < world->slot_count; ++j)
        {
          body *b = &world->bodies[j];
          if (!b->alive || b->type != CAROM_STATIC || b->sensor || b->shape.kind == CAROM_SHAPE_CIRCLE
              || !boxes_touch (a, b))
            continue;
          for (u = 0; u < a->shape.piece_count; ++u)
            for (v = i == j ? u + 1 : 0; v < b->shape.piece_count; ++v)
              {
                convex_piece *p = &a->shape.pieces[u], *q = &b->shape.pieces[v];
                if (p->count == 0 || q->count == 0)
                  continue;
                mark (a, p, b, q);
                mark (b, q, a, p);
              }
        }
    }
}

/* Whether the outline edge from u1 to u2 lies along edge j of piece p, in
 * the same direction, within it (to SEAM_TOLERANCE of the piece edge): a
 * piece's edge on the outline is one outline edge, or several where the
 * outline has vertices straight through that the piece drops. */
static int along (vec2 u1, vec2 u2, const convex_piece *p, int32_t j)
{
  vec2 p1 = p->vertices[j], e = v2_sub (p->vertices[(j + 1) % p->count], p1);
  double len2 = v2_len2 (e), tol = SEAM_TOLERANCE * len2;
  vec2 d1 = v2_sub (u1, p1), d2 = v2_sub (u2, p1);
  return len2 > 0.0 && fabs (v2_cross (e, d1)) <= tol && fabs (v2_cross (e, d2)) <= tol && v2_dot (e, d1) >= -tol
         && v2_dot (e, d2) <= len2 + tol && v2_dot (e, v2_sub (u2, u1)) > 0.0;
}

uint64_t seams_outline (const shape *s)
{
  uint64_t out = 0;
  int32_t i, j, u, any = 0;
  if (s->kind != CAROM_SHAPE_POLYGON)
    return 0;
  for (u = 0; u < s->piece_count; ++u)
    any |= s->pieces[u].internal != 0;
  if (!any)
    return 0; /* a moving body, or a static one that touches no other */
  if (s->pieces_shared)
    return s->pieces[0].internal; /* the outline is its one piece */
  for (i = 0; i < s->count && i < SEAM_MAX_EDGES; ++i)
    {
      vec2 u1 = s->vertices[i], u2 = s->vertices[(i + 1) % s->count];
      for (u = 0; u < s->piece_count && !((out >> i) & 1u); ++u)
        for (j = 0; j < s->pieces[u].count && j < SEAM_MAX_EDGES; ++j)
          if (piece_edge_internal (&s->pieces[u], j) && along (u1, u2, &s->pieces[u], j))
            {
              out |= (uint64_t) 1 << i;
              break;
            }
    }
  return out;
}
