/* Contacts: narrow-phase dispatch for each broad-phase pair, matching with
 * last step's contacts for warm starting, and the public contact queries. */
#include "contact.h"

#include <string.h>

#include "seams.h"
#include "solver.h"
#include "step.h"
#include "toi.h"
#include "world.h"

void contacts_init (carom_world *world)
{
  memset (&world->contacts, 0, sizeof world->contacts);
}

void contacts_destroy (carom_world *world)
{
  contacts *c = &world->contacts;
  mem_free (&world->allocator, c->list, (size_t) c->cap * sizeof (contact));
  mem_free (&world->allocator, c->old, (size_t) c->old_cap * sizeof (contact));
  mem_free (&world->allocator, c->pool, (size_t) c->pool_cap * sizeof (contact_point));
  mem_free (&world->allocator, c->old_pool, (size_t) c->old_pool_cap * sizeof (contact_point));
  mem_free (&world->allocator, c->table, (size_t) c->table_cap * sizeof (int32_t));
  mem_free (&world->allocator, c->sensors, (size_t) c->sensor_cap * sizeof (int32_t));
  mem_free (&world->allocator, c->pushed, (size_t) c->pushed_cap);
  mem_free (&world->allocator, c->deferred, (size_t) c->deferred_cap * sizeof (int32_t));
  memset (c, 0, sizeof *c);
}

/* The table's slot of a pair of pieces, before the mask: the parts, each
 * times its own odd constant, exclusive-or'd, without a mixing round after
 * each (the table is built anew in most detections, a hash for every
 * contact). Which slot a key takes changes where it is found, not what:
 * two contacts of one key lie on one chain, the first kept found first. */
static inline uint32_t pair_hash (int32_t a, int32_t b, int32_t pa, int32_t pb)
{
  return ((uint32_t) a * 0x9E3779B1u) ^ ((uint32_t) b * 0x85EBCA77u) ^ ((uint32_t) pa * 0xC2B2AE3Du)
         ^ ((uint32_t) pb * 0x27D4EB2Fu);
}

static int build_table (carom_world *world)
{
  contacts *c = &world->contacts;
  int32_t need = 16, k;
  uint32_t mask;
  while (need < 2 * c->old_count)
    need *= 2;
  if (need > c->table_cap)
    {
      int32_t *t = mem_alloc (&world->allocator, (size_t) need * sizeof (int32_t));
      if (!t)
        return 0;
      mem_free (&world->allocator, c->table, (size_t) c->table_cap * sizeof (int32_t));
      c->table = t;
      c->table_cap = need;
    }
  memset (c->table, 0xff, (size_t) c->table_cap * sizeof (int32_t)); /* all -1 */
  mask = (uint32_t) c->table_cap - 1;
  for (k = 0; k < c->old_count; ++k)
    {
      const contact *o = &c->old[k];
      uint32_t i = pair_hash (o->a, o->b, o->piece_a, o->piece_b) & mask;
      while (c->table[i] >= 0)
        i = (i + 1) & mask;
      c->table[i] = k;
    }
  c->table_built = 1;
  return 1;
}

/* Index of last step's contact between the same two pieces, or -1. The
 * broad phase reports the pairs of a steady scene in the order it did last
 * step, which is the order of last step's contacts: the one after the last
 * match is tried first, and the hash over them is built only when that
 * fails. */
static int32_t find_old (carom_world *world, int32_t a, int32_t b, int32_t pa, int32_t pb)
{
  contacts *c = &world->contacts;
  uint32_t mask, i;
  const contact *o;
  if (c->old_count == 0)
    return -1;
  if (c->cursor < c->old_count)
    {
      o = &c->old[c->cursor];
      if (o->a == a && o->b == b && o->piece_a == pa && o->piece_b == pb)
        return c->cursor++;
    }
  if (!c->table_built && !build_table (world))
    {
      c->out_of_memory = 1;
      return -1;
    }
  mask = (uint32_t) c->table_cap - 1;
  for (i = pair_hash (a, b, pa, pb) & mask;; i = (i + 1) & mask)
    {
      int32_t k = c->table[i];
      if (k < 0)
        return -1;
      o = &c->old[k];
      if (o->a == a && o->b == b && o->piece_a == pa && o->piece_b == pb)
        {
          c->cursor = k + 1;
          return k;
        }
    }
}

typedef struct pair_context {
  int32_t a, b;          /* the bodies' slots, in the narrow phase's order */
  xform xa, xb;          /* their poses */
  double restitution, friction, slop, margin;
  double margin_kept;    /* the margin of pieces that had a contact the step
                            before and do not bounce: as far as the bodies
                            can move in the step, turning included, capped
                            or not (pair_pieces) */
  double reuse_lin, reuse_ang; /* manifold reuse tolerance (0: never) */
  const convex_piece *pieces_a, *pieces_b; /* a pair with a compound: the
                                              pieces collide_pieces takes */
  int bouncy_swept;      /* a bouncy pair, its bodies in free flight
                            (step_context.free_flight), looking as far as
                            that closes it (detect_pair): clear_of_step */
  const step_context *ctx;
  double reach;          /* detect_pair's reach */
  int margins_set;       /* margin and margin_kept are computed
                            (pair_margins) */
} pair_context;

/* Where each point of a freshly computed manifold lies: a's copy of it
 * (half the depth along the normal from the point, which the narrow phase
 * puts halfway) and the normal in a's frame, b's copy in b's frame (from
 * a's, by the relative pose computed_at), which reuse_contact then needs
 * to take out of b's frame only. */
static void remember_points (contact *k, xform xa, xform xb)
{
  int32_t i;
  k->computed_at = xform_relative (xa, xb);
  k->reused = 0;
  for (i = 0; i < k->count; ++i)
    {
      contact_point *p = &k->points[i];
      vec2 half = v2_scale (p->normal, 0.5 * p->depth);
      p->local_a = xform_apply_inv (xa, v2_add (p->point, half));
      p->local_b = xform_apply_inv (k->computed_at, xform_apply_inv (xa, v2_sub (p->point, half)));
      p->local_normal = rot2_apply_inv (xa.q, p->normal);
    }
}

/* A new contact of pieces pa, pb of the pair with room for n points in
 * the pool, its fields but the points' set; NULL when memory ran out.
 * old: last step's contact of the same pieces, or -1. */
static inline contact *new_contact (carom_world *world, int32_t pa, int32_t pb, const pair_context *pc, int32_t old,
                                    int32_t n, double gap, int clear)
{
  contacts *c = &world->contacts;
  contact *k;
  if ((c->count == c->cap
       && !mem_reserve (&world->allocator, (void **) &c->list, &c->cap, c->count + 1, sizeof (contact)))
      || (c->point_count + n > c->pool_cap
          && !mem_reserve (&world->allocator, (void **) &c->pool, &c->pool_cap, c->point_count + n,
                           sizeof (contact_point))))
    {
      c->out_of_memory = 1;
      return NULL;
    }
  k = &c->list[c->count++];
  c->bouncy_found += pc->restitution > 0.0;
  /* valid until the pool grows again: contacts_update points every
   * contact at its points again if it did */
  k->points = c->pool + c->point_count;
  k->a = pc->a, k->b = pc->b, k->piece_a = pa, k->piece_b = pb;
  k->restitution = pc->restitution;
  k->friction = pc->friction;
  k->slop = pc->slop;
  k->count = n;
  k->fresh = old < 0;
  k->gap = gap;
  k->clear = clear;
  c->clear_count += clear;
  k->first_point = c->point_count;
  c->point_count += n;
  return k;
}

/* Last step's points op[0 .. count) moved with the bodies into np (see
 * reuse_contact): b's relative pose is now `now`, turned by `turn` from
 * where they were computed, a's pose xa. Returns the least separation of
 * the points. The two pools never overlap, which restrict tells the
 * compiler: it would otherwise test their overlap on every call. */
static inline double move_points (const contact_point *restrict op, contact_point *restrict np, int32_t count,
                                  xform xa, xform now, rot2 turn)
{
  double gap = INFINITY;
  int32_t i, j;
  for (i = 0; i < count; ++i)
    {
      const contact_point *p = &op[i];
      contact_point *mp = &np[i];
      /* b's copy, out of b's frame as it is now */
      vec2 b_local = xform_apply (now, p->local_b);
      vec2 n = p->feature >> 31 ? rot2_apply (turn, p->local_normal) : p->local_normal;
      mp->depth = v2_dot (v2_sub (p->local_a, b_local), n);
      mp->found = mp->depth;
      mp->point = xform_apply (xa, v2_scale (v2_add (p->local_a, b_local), 0.5));
      mp->normal = rot2_apply (xa.q, n);
      gap = -mp->depth < gap ? -mp->depth : gap;
      mp->feature = p->feature;
      mp->push_impulse = mp->total_impulse = mp->approach = 0.0;
      /* warm start: the same feature pair carries its impulses over, the
       * first of the old points with this one's feature (this one at the
       * latest), and the effective masses they were found with */
      for (j = 0; j < i && op[j].feature != p->feature; ++j)
        ;
      mp->normal_impulse = op[j].normal_impulse;
      mp->tangent_impulse = op[j].tangent_impulse;
      mp->normal_mass = op[j].normal_mass;
      mp->tangent_mass = op[j].tangent_mass;
      mp->local_a = p->local_a;
      mp->local_b = p->local_b;
      mp->local_normal = p->local_normal;
    }
  return gap;
}

/* Last step's contact `old` of pieces pa, pb, its points moved with the
 * bodies, if the pair's relative pose is still within the tolerance of
 * where they were computed: a's copy of each point stays put in a's frame,
 * b's moves with b, the normal turns with the body whose face gave it (bit
 * 31 of the feature: b's), and the depth is measured again between the two
 * copies. Returns 0 (compute afresh) otherwise. */
static int reuse_contact (carom_world *world, int32_t pa, int32_t pb, const pair_context *pc, int32_t old)
{
  const contact *o = &world->contacts.old[old];
  xform xa = pc->xa, now = xform_relative (xa, pc->xb), then = o->computed_at;
  vec2 moved = v2_sub (now.p, then.p);
  rot2 turn;
  contact *k;
  turn.c = then.q.c * now.q.c + then.q.s * now.q.s; /* now / then */
  turn.s = then.q.c * now.q.s - then.q.s * now.q.c;
  if (!(v2_len_at_most (moved, pc->reuse_lin) && fabs (turn.s) <= pc->reuse_ang && turn.c > 0.0))
    return 0;
  k = new_contact (world, pa, pb, pc, old, o->count, INFINITY, 0);
  if (!k)
    return 1;
  /* the pose and the points of the last computation carry on, so the
   * tolerance bounds the drift from it, not from each step */
  k->computed_at = then;
  k->reused = 1;
  k->gap = move_points (o->points, k->points, o->count, xa, now, turn);
  k->separation_known = 0;
  return 1;
}

/* A freshly computed manifold m of pieces pa, pb as a contact. */
static void add_manifold (carom_world *world, int32_t pa, int32_t pb, const manifold *m, const pair_context *pc,
                          int32_t old, int clear)
{
  contacts *c = &world->contacts;
  contact *k;
  int32_t i, j;
  if (m->count == 0)
    return;
  k = new_contact (world, pa, pb, pc, old, m->count, m->gap, clear);
  if (!k)
    return;
  k->separation_known = m->separation_face != MANIFOLD_NO_FACE;
  k->separation = m->separation;
  k->separation_face = m->separation_face;
  for (i = 0; i < m->count; ++i)
    {
      contact_point *p = &k->points[i];
      /* what the solver reads before it sets it (contact_prepare sets the
       * rest) */
      p->point = m->points[i].point;
      p->normal = m->points[i].normal;
      p->depth = p->found = m->points[i].depth;
      k->gap = -p->depth < k->gap ? -p->depth : k->gap;
      p->feature = m->points[i].feature;
      p->normal_impulse = p->tangent_impulse = 0.0;
      p->normal_mass = p->tangent_mass = 0.0;
      p->push_impulse = p->total_impulse = p->approach = 0.0;
      if (old < 0)
        continue;
      /* warm start: the same feature pair carries its impulses over */
      for (j = 0; j < c->old[old].count; ++j)
        if (c->old[old].points[j].feature == p->feature)
          {
            p->normal_impulse = c->old[old].points[j].normal_impulse;
            p->tangent_impulse = c->old[old].points[j].tangent_impulse;
            /* the effective masses they were found with (the solver
             * rescales them if the geometry changed, see prepare) */
            p->normal_mass = c->old[old].points[j].normal_mass;
            p->tangent_mass = c->old[old].points[j].tangent_mass;
            break;
          }
    }
  remember_points (k, pc->xa, pc->xb);
}

/* The convex pieces of a body for the narrow phase: a circle body's one
 * circle is a piece (in `circle`), a polygon's and a compound's are its
 * shape's. */
static int32_t body_pieces (const body *B, const convex_piece **pieces, convex_piece *circle)
{
  if (B->shape.kind == CAROM_SHAPE_CIRCLE)
    {
      memset (circle, 0, sizeof *circle);
      circle->radius = circle->bound_radius = B->shape.radius;
      *pieces = circle;
      return 1;
    }
  *pieces = B->shape.pieces;
  return B->shape.piece_count;
}

/* Any two pieces, circles (count 0) or convex polygons, each placed by its
 * body's pose. A circle against a polygon is tested the polygon first and
 * the result turned round (the normal then turns with b's face: bit 31 of
 * the feature, see reuse_contact). */
static void collide_pieces (const convex_piece *p, xform xa, const convex_piece *q, xform xb, double margin,
                            const vec2 *toward, manifold *m)
{
  int32_t k;
  if (p->count == 0 && q->count == 0)
    collide_circles (xform_apply (xa, p->center), p->radius, xform_apply (xb, q->center), q->radius, margin, m);
  else if (q->count == 0)
    collide_polygon_circle (p, xa, xform_apply (xb, q->center), q->radius, margin, m);
  else if (p->count > 0)
    collide_polygons_sat_toward (p, xa, q, xb, margin, toward, m);
  else
    {
      collide_polygon_circle (q, xb, xform_apply (xa, p->center), p->radius, margin, m);
      for (k = 0; k < m->count; ++k)
        {
          m->points[k].normal = v2_scale (m->points[k].normal, -1.0);
          m->points[k].feature |= 0x80000000u;
        }
    }
}

/* The narrow phase for pieces pa, pb of bodies a, b placed at xa, xb (with a
 * compound, pieces_a and pieces_b are the two bodies' body_pieces); two
 * convex polygons take their reference face by `toward` when it is not NULL
 * (collide_polygons_sat_toward). */
static void narrow_phase (const carom_world *world, int32_t a, int32_t b, int32_t pa, int32_t pb,
                          const convex_piece *pieces_a, const convex_piece *pieces_b, xform xa, xform xb, double margin,
                          const vec2 *toward, manifold *m)
{
  const shape *sa = &world->bodies[a].shape, *sb = &world->bodies[b].shape;
  if (pieces_a)
    collide_pieces (&pieces_a[pa], xa, &pieces_b[pb], xb, margin, toward, m);
  else if (pa < 0 && pb < 0 && sa->kind == CAROM_SHAPE_CIRCLE)
    collide_circles (xa.p, sa->radius, xb.p, sb->radius, margin, m);
  else if (pb < 0 && sb->kind == CAROM_SHAPE_CIRCLE)
    collide_polygon_circle (&sa->pieces[pa], xa, xb.p, sb->radius, margin, m);
  else if (pa < 0)
    collide_outlines_vertex_edge (sa, xa, sb, xb, margin, m);
  else
    collide_polygons_sat_toward (&sa->pieces[pa], xa, &sb->pieces[pb], xb, margin, toward, m);
}

/* The largest of a cos(d) + b sin(d) over |d| <= turn (turn <= pi/2),
 * bounded from above: a if a >= 0 else a cos(turn), plus |b| sin(turn). */
static double turned_bound (double a, double b, double c, double s)
{
  return (a >= 0.0 ? a : a * c) + fabs (b) * s;
}

/* How far the points of body B's piece (or its whole outline, or its
 * circle) reach from its centre along the unit direction d while the body
 * turns from q by at most `turn` either way: in the body's frame the
 * direction turns by as much, so a vertex v reaches a cos + b sin of that
 * turn, a and b its coordinates along the direction and across it. Past a
 * quarter turn, its bounding radius. */
static double piece_reach_along (const body *B, int32_t piece, rot2 q, vec2 d, double turn)
{
  vec2 u = rot2_apply_inv (q, d), w = v2_perp (u);
  double c = cos (turn), s = sin (turn), best = -INFINITY;
  const vec2 *v;
  int32_t i, n;
  if (B->shape.kind == CAROM_SHAPE_CIRCLE)
    return B->shape.radius;
  if (!(turn <= 0.5 * CAROM_PI))
    return B->shape.bound_radius;
  if (piece < 0)
    v = B->shape.vertices, n = B->shape.count;
  else if (B->shape.pieces[piece].count == 0)
    {
      vec2 o = B->shape.pieces[piece].center;
      return turned_bound (v2_dot (u, o), v2_dot (w, o), c, s) + B->shape.pieces[piece].radius;
    }
  else
    v = B->shape.pieces[piece].vertices, n = B->shape.pieces[piece].count;
  for (i = 0; i < n; ++i)
    {
      double r = turned_bound (v2_dot (u, v[i]), v2_dot (w, v[i]), c, s);
      best = r > best ? r : best;
    }
  return best;
}

/* Whether two polygon pieces whose manifold m was just found, apart by
 * more than the slop, cannot touch within the step in free flight, judged
 * on the reference face m was clipped to as it turns with its body
 * (toi_face_clear). A bouncy pair looks ahead as far as free flight closes
 * it (detect_pair); by the bodies' whole relative speed, in any direction,
 * that takes in neighbours flying alongside or apart, each then a contact
 * whose time of impact is searched every step for nothing. What an impact
 * within the step sends at them is found again after the impacts
 * (contacts_after_impacts). */
static int clear_of_step (const carom_world *world, int32_t a, int32_t b, int32_t pa, int32_t pb,
                          const pair_context *pc, xform xa, xform xb, const manifold *m)
{
  const body *A = &world->bodies[a], *B = &world->bodies[b], *R, *I;
  const convex_piece *P, *Q, *ref;
  double s = INFINITY;
  int32_t edge, j;
  int side;
  if (pa < 0 || pb < 0 || !sat_feature_face (m->points[0].feature, &side, &edge))
    return 0;
  P = pc->pieces_a ? &pc->pieces_a[pa] : A->shape.kind == CAROM_SHAPE_POLYGON ? &A->shape.pieces[pa] : NULL;
  Q = pc->pieces_b ? &pc->pieces_b[pb] : B->shape.kind == CAROM_SHAPE_POLYGON ? &B->shape.pieces[pb] : NULL;
  if (!P || !Q || P->count == 0 || Q->count == 0)
    return 0;
  ref = side ? Q : P;
  if (edge >= ref->count)
    return 0;
  for (j = 0; j < m->count; ++j)
    s = -m->points[j].depth < s ? -m->points[j].depth : s;
  if (!(s > pc->slop))
    return 0;
  R = side ? B : A, I = side ? A : B;
  return toi_face_clear (ref, edge, side ? xb : xa, R->v, R->w, side ? P : Q, side ? xa : xb, I->v, I->w, 0.0,
                         world->contacts.dt)
         >= world->contacts.dt;
}

/* Whether two bodies in free flight, their bounding circles (which hold
 * each body at any angle, about its centre) more than the slop apart, stay
 * so through the step dt: no turn of theirs then brings any piece within
 * the slop of the other, and the pair is clear of the step (as
 * clear_of_step, for a price below one narrow phase). The first time
 * |d + v t| comes down to the radii and the slop, d and v B's position and
 * velocity less A's, is the smaller root of a quadratic, in the form that
 * does not cancel; none that comes later than dt, or none at all, is
 * clear. */
static int circles_clear_of_step (const body *A, const body *B, double slop, double dt)
{
  vec2 d = v2_sub (B->p, A->p), v = v2_sub (B->v, A->v);
  double r = A->shape.bound_radius + B->shape.bound_radius + slop, c = v2_dot (d, d) - r * r, dv = v2_dot (d, v), disc;
  if (!(c > 0.0))
    return 0;
  if (!(dv < 0.0))
    return 1; /* not closing */
  disc = dv * dv - v2_dot (v, v) * c;
  return disc < 0.0 || c > dt * (sqrt (disc) - dv);
}

/* Keep pair a, b (in the narrow phase's order) for redetect_deferred. */
static void defer_pair (carom_world *world, int32_t a, int32_t b)
{
  contacts *c = &world->contacts;
  if (!mem_reserve (&world->allocator, (void **) &c->deferred, &c->deferred_cap, 2 * (c->deferred_count + 1),
                    sizeof (int32_t)))
    {
      c->out_of_memory = 1;
      return;
    }
  c->deferred[2 * c->deferred_count] = a;
  c->deferred[2 * c->deferred_count + 1] = b;
  c->deferred_count++;
}

/* The margins of pair pc (pair_context.margin and margin_kept), computed
 * when first needed: a pair of polygons whose pieces' bounding circles
 * overlap and whose manifolds are all reused needs neither. The speculative
 * margin: pairs that can close their gap within this step are contacts now,
 * so impacts are met before the bodies overlap. */
static void pair_margins (const carom_world *world, pair_context *pc)
{
  const step_context *ctx = pc->ctx;
  const body *A = &world->bodies[pc->a], *B = &world->bodies[pc->b];
  double ra = world->broad.reach[pc->a], rb = world->broad.reach[pc->b];
  if (pc->margins_set)
    return;
  pc->margins_set = 1;
  if (pc->reach >= 0.0)
    pc->margin = pc->slop + pc->reach;
  else if (body_pair_swept (A, ra, B, rb, ctx->dt, ctx->accel, ctx->continuous))
    /* with the world's continuous collision or a bullet, an inelastic pair
     * looks as far as a body goes when what it flies with is stopped (a box
     * of a falling stack landing under the next): nothing else follows it.
     * A bouncy pair's bodies are followed by the impacts, which search
     * again for the pairs they change (contacts_after_impacts); a body
     * swept only for being fast looks no further than free flight closes
     * the pair. */
    pc->margin = pc->slop + body_pair_reach (A, B, ctx->dt, ctx->accel,
                                             pc->restitution == 0.0 && (ctx->continuous || A->bullet || B->bullet));
  else
    pc->margin = pc->slop + body_reach_capped (A, ra, 0) + body_reach_capped (B, rb, 0);
  pc->margin_kept = pc->reach >= 0.0 ? pc->margin : pc->slop + ra + rb;
}

/* Whether the bounding circles of two pieces, d from one centre to the
 * other (their radii's sum rr), come within the pair's margin: at once when
 * they overlap, for which the margin (never negative) is not needed, and
 * without a square root when they clearly do. */
static int pieces_near (const carom_world *world, pair_context *pc, vec2 d, double rr)
{
  double r;
  if (v2_len_surely_within (d, rr))
    return 1;
  r = v2_len (d);
  if (!(r > rr))
    return 1;
  pair_margins (world, pc);
  return !(r > rr + pc->margin);
}

/* The narrow phase for one pair of pieces, or last step's points moved
 * (reuse_contact), then the contact. */
static void pair_pieces (carom_world *world, int32_t pa, int32_t pb, pair_context *pc, manifold *m, int can_reuse)
{
  int32_t old = find_old (world, pc->a, pc->b, pa, pb);
  int clear;
  if (!(can_reuse && old >= 0 && reuse_contact (world, pa, pb, pc, old)))
    /* Pieces in contact the step before look as far ahead as their bodies
     * can move: a box tipping over from its corner turns its far corner
     * down faster than the capped reach sees (body_reach_capped), and
     * would land it deep. Few pairs are in contact at a time, and a
     * resting speculative point costs the solver little; a bouncy one
     * would take the time of impact's work for every corner nearby. */
    {
      pair_margins (world, pc);
      narrow_phase (world, pc->a, pc->b, pa, pb, pc->pieces_a, pc->pieces_b, pc->xa, pc->xb,
                    old >= 0 && pc->restitution == 0.0 ? pc->margin_kept : pc->margin, NULL, m);
      clear = pc->bouncy_swept && m->count > 0 && clear_of_step (world, pc->a, pc->b, pa, pb, pc, pc->xa, pc->xb, m);
      add_manifold (world, pa, pb, m, pc, old, clear);
    }
}

void contact_collide_at (const carom_world *world, const contact *k, xform xa, xform xb, double margin,
                         const vec2 *toward, manifold *m)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  convex_piece ca, cb;
  const convex_piece *P = NULL, *Q = NULL;
  if (A->shape.kind == CAROM_SHAPE_COMPOUND || B->shape.kind == CAROM_SHAPE_COMPOUND)
    {
      body_pieces (A, &P, &ca);
      body_pieces (B, &Q, &cb);
    }
  narrow_phase (world, k->a, k->b, k->piece_a, k->piece_b, P, Q, xa, xb, margin, toward, m);
}

/* The points that stand for body X's piece (its vertices, or a circle's
 * centre with *radius), in its body's frame: how many, and the array. */
static int32_t piece_points (const body *X, int32_t piece, const vec2 **v, vec2 *one, double *radius)
{
  *radius = 0.0;
  if (X->shape.kind == CAROM_SHAPE_CIRCLE)
    {
      *one = v2 (0.0, 0.0), *v = one, *radius = X->shape.radius;
      return 1;
    }
  if (piece < 0)
    {
      *v = X->shape.vertices;
      return X->shape.count;
    }
  if (X->shape.pieces[piece].count == 0)
    {
      *one = X->shape.pieces[piece].center, *v = one, *radius = X->shape.pieces[piece].radius;
      return 1;
    }
  *v = X->shape.pieces[piece].vertices;
  return X->shape.pieces[piece].count;
}

void contact_piece_envelope (const carom_world *world, const contact *k, int side, xform x, vec2 vel, double w, vec2 d,
                             double *reach, double *rate)
{
  const body *X = &world->bodies[side ? k->b : k->a];
  const vec2 *v;
  vec2 one;
  double radius;
  int32_t i, n = piece_points (X, side ? k->piece_b : k->piece_a, &v, &one, &radius);
  *reach = *rate = -INFINITY;
  for (i = 0; i < n; ++i)
    {
      vec2 r = rot2_apply (x.q, v[i]);
      double at = v2_dot (d, v2_add (x.p, r)) + radius, moving = v2_dot (d, v2_add (vel, v2_scale (v2_perp (r), w)));
      *reach = at > *reach ? at : *reach;
      *rate = moving > *rate ? moving : *rate;
    }
}

double contact_piece_first_reach (const carom_world *world, const contact *k, int side, xform x, vec2 vel, double w,
                                  vec2 d, double other, double other_rate, double curve)
{
  const body *X = &world->bodies[side ? k->b : k->a];
  const vec2 *v;
  vec2 one;
  double radius, first = INFINITY;
  int32_t i, n = piece_points (X, side ? k->piece_b : k->piece_a, &v, &one, &radius);
  for (i = 0; i < n; ++i)
    {
      vec2 r = rot2_apply (x.q, v[i]);
      /* the gap this point leaves, g0 + g1 tau - curve tau^2 / 2 at least:
       * its first root, in the form that does not cancel */
      double g0 = -(v2_dot (d, v2_add (x.p, r)) + radius) - other;
      double g1 = -v2_dot (d, v2_add (vel, v2_scale (v2_perp (r), w))) - other_rate;
      double tau = contact_gap_root (g0, g1, curve);
      first = tau < first ? tau : first;
    }
  return first;
}

/* A point of a piece along the direction d: its position d . q (its
 * circle's radius added) and its rate d . q'. */
typedef struct piece_track {
  double at, rate;
} piece_track;

static piece_track track_point (vec2 local, double radius, xform x, vec2 vel, double w, vec2 d)
{
  vec2 r = rot2_apply (x.q, local);
  piece_track t;
  t.at = v2_dot (d, v2_add (x.p, r)) + radius;
  t.rate = v2_dot (d, v2_add (vel, v2_scale (v2_perp (r), w)));
  return t;
}

double contact_pieces_first_meeting (const carom_world *world, const contact *k, xform xa, vec2 va, double wa,
                                     xform xb, vec2 vb, double wb, vec2 n, double curve)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  const vec2 *pa, *pb;
  vec2 one_a, one_b;
  double ra, rb, first = INFINITY;
  int32_t na = piece_points (A, k->piece_a, &pa, &one_a, &ra), nb = piece_points (B, k->piece_b, &pb, &one_b, &rb);
  piece_track small[CONTACT_PAIRED_POINTS];
  int32_t i, j, a_small = na <= nb, ns = a_small ? na : nb, nl = a_small ? nb : na;
  if ((int64_t) na * nb > CONTACT_PAIRED_POINTS * CONTACT_PAIRED_POINTS || ns > CONTACT_PAIRED_POINTS)
    return -1.0;
  /* A's points along n (its extent towards B), B's along -n */
  for (i = 0; i < ns; ++i)
    small[i] = a_small ? track_point (pa[i], ra, xa, va, wa, n) : track_point (pb[i], rb, xb, vb, wb, v2_neg (n));
  for (j = 0; j < nl; ++j)
    {
      piece_track l = a_small ? track_point (pb[j], rb, xb, vb, wb, v2_neg (n)) : track_point (pa[j], ra, xa, va, wa, n);
      for (i = 0; i < ns; ++i)
        {
          double tau = contact_gap_root (-(l.at + small[i].at), -(l.rate + small[i].rate), curve);
          first = tau < first ? tau : first;
        }
    }
  return first;
}

double contact_reach_along (const carom_world *world, const contact *k, rot2 qa, rot2 qb, vec2 n, double turn_a,
                            double turn_b)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  return piece_reach_along (A, k->piece_a, qa, n, turn_a) + piece_reach_along (B, k->piece_b, qb, v2_neg (n), turn_b);
}

/* Which piece's edge polygons_separation_face named (edge e of A as e, of
 * B as -1 - e): the reference face, and the other piece, incident. */
static void contact_face_side (contact_face *face, int32_t edge)
{
  face->side = edge < 0;
  face->edge = edge < 0 ? -1 - edge : edge;
  face->ref = edge < 0 ? face->pb : face->pa;
  face->inc = edge < 0 ? face->pa : face->pb;
}

double contact_separation_face_at (const carom_world *world, const contact *k, xform xa, xform xb, vec2 *axis,
                                   contact_face *face)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  manifold m;
  double deepest = -INFINITY, s;
  int32_t j, edge;
  face->ref = NULL;
  if (A->shape.kind == CAROM_SHAPE_POLYGON && B->shape.kind == CAROM_SHAPE_POLYGON && k->piece_a >= 0
      && k->piece_b >= 0)
    {
      face->pa = &A->shape.pieces[k->piece_a], face->pb = &B->shape.pieces[k->piece_b];
      s = polygons_separation_face (face->pa, xa, face->pb, xb, axis, &edge);
      contact_face_side (face, edge);
      return s;
    }
  if (A->shape.kind == CAROM_SHAPE_COMPOUND || B->shape.kind == CAROM_SHAPE_COMPOUND)
    {
      convex_piece ca, cb;
      const convex_piece *P, *Q;
      body_pieces (A, &P, &ca);
      body_pieces (B, &Q, &cb);
      if (P[k->piece_a].count > 0 && Q[k->piece_b].count > 0)
        {
          face->pa = &P[k->piece_a], face->pb = &Q[k->piece_b];
          s = polygons_separation_face (face->pa, xa, face->pb, xb, axis, &edge);
          contact_face_side (face, edge);
          return s;
        }
    }
  *axis = v2 (1.0, 0.0);
  contact_collide_at (world, k, xa, xb, INFINITY, NULL, &m);
  for (j = 0; j < m.count; ++j)
    if (m.points[j].depth > deepest)
      {
        deepest = m.points[j].depth;
        *axis = m.points[j].normal;
      }
  return -deepest;
}

int contact_separation_face_detected (const carom_world *world, const contact *k, vec2 *axis, contact_face *face,
                                      double *separation)
{
  const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
  xform xa, xb;
  if (!k->separation_known)
    return 0;
  /* a SAT contact's pieces are two polygons: a polygon's or a compound's
   * (body_pieces), as contact_separation_face_at takes them */
  face->pa = &A->shape.pieces[k->piece_a], face->pb = &B->shape.pieces[k->piece_b];
  xa.p = A->p, xa.q = A->q;
  xb.p = B->p, xb.q = B->q;
  *axis = polygons_face_axis (face->pa, xa, face->pb, xb, k->separation_face);
  contact_face_side (face, k->separation_face);
  *separation = k->separation;
  return 1;
}

double contact_separation_at (const carom_world *world, const contact *k, xform xa, xform xb, vec2 *axis)
{
  contact_face face;
  return contact_separation_face_at (world, k, xa, xb, axis, &face);
}

static double material (double own, double fallback)
{
  return own >= 0.0 ? own : fallback;
}

/* The contact's restitution and friction from its two sides' (< 0: the
 * world default): the bouncier side wins (max); friction is the geometric
 * mean. */
static inline void mix_materials (const carom_world *world, double ea, double fa, double eb, double fb,
                                  pair_context *pc)
{
  ea = material (ea, world->def.restitution);
  eb = material (eb, world->def.restitution);
  fa = material (fa, world->def.friction);
  fb = material (fb, world->def.friction);
  pc->restitution = ea > eb ? ea : eb;
  /* two equal frictions (most pairs) mix to that friction: the square root
   * of a square is exact in binary floating point, while the square stays
   * a normal double */
  if (fa == fb && fa >= 0x1p-500 && fa <= 0x1p500)
    {
      pc->friction = fa;
      return;
    }
  pc->friction = sqrt (fa * fb);
  if (!isfinite (pc->friction))
    pc->friction = sqrt (fa) * sqrt (fb); /* mu near the largest double: finite, so mu times 0 is 0 */
}

/* A pair with a compound body: every two pieces whose bounding circles
 * come within the margin, each with its shapes' materials. */
static void on_compound_pair (carom_world *world, pair_context *pc)
{
  int32_t a = pc->a, b = pc->b;
  xform xa = pc->xa, xb = pc->xb;
  const body *A = &world->bodies[a], *B = &world->bodies[b];
  convex_piece ca, cb;
  const convex_piece *P, *Q;
  int32_t na = body_pieces (A, &P, &ca), nb = body_pieces (B, &Q, &cb), i, j;
  int compound_a = A->shape.kind == CAROM_SHAPE_COMPOUND, compound_b = B->shape.kind == CAROM_SHAPE_COMPOUND;
  manifold m;
  pc->pieces_a = P;
  pc->pieces_b = Q;
  for (i = 0; i < na; ++i)
    {
      vec2 pc_center = xform_apply (xa, P[i].center);
      double ea = compound_a ? material (P[i].restitution, A->restitution) : A->restitution;
      double fa = compound_a ? material (P[i].friction, A->friction) : A->friction;
      for (j = 0; j < nb; ++j)
        {
          vec2 qc = xform_apply (xb, Q[j].center);
          if (!pieces_near (world, pc, v2_sub (qc, pc_center), P[i].bound_radius + Q[j].bound_radius))
            continue;
          mix_materials (world, ea, fa, compound_b ? material (Q[j].restitution, B->restitution) : B->restitution,
                         compound_b ? material (Q[j].friction, B->friction) : B->friction, pc);
          pair_pieces (world, i, j, pc, &m, pc->reuse_lin > 0.0 && P[i].count > 0 && Q[j].count > 0);
        }
    }
}

/* contact.h */
int contact_bodies_overlap (const body *A, const body *B)
{
  xform xa, xb;
  manifold m;
  convex_piece ca, cb;
  const convex_piece *pa, *pb;
  int32_t i, j, k, na = body_pieces (A, &pa, &ca), nb = body_pieces (B, &pb, &cb);
  xa.p = A->p, xa.q = A->q;
  xb.p = B->p, xb.q = B->q;
  for (i = 0; i < na; ++i)
    for (j = 0; j < nb; ++j)
      {
        m.count = 0;
        collide_pieces (&pa[i], xa, &pb[j], xb, 0.0, NULL, &m);
        for (k = 0; k < m.count; ++k)
          if (m.points[k].depth >= 0.0)
            return 1;
      }
  return 0;
}

/* A pair with a sensor: no contact, only a pair whose overlap the events
 * test at the end of the update (sensors do not see each other, nor static
 * sensors static bodies). */
static void sensor_pair (carom_world *world, int32_t a, int32_t b)
{
  contacts *c = &world->contacts;
  const body *A = &world->bodies[a], *B = &world->bodies[b];
  if ((A->sensor && B->sensor) || (A->type == CAROM_STATIC && B->type == CAROM_STATIC))
    return;
  if (!mem_reserve (&world->allocator, (void **) &c->sensors, &c->sensor_cap, 2 * (c->sensor_count + 1),
                    sizeof (int32_t)))
    {
      c->out_of_memory = 1;
      return;
    }
  c->sensors[2 * c->sensor_count] = A->sensor ? a : b;
  c->sensors[2 * c->sensor_count + 1] = A->sensor ? b : a;
  c->sensor_count++;
}

/* A body the sub-steps can move, or one that moves on its own. */
static int can_move (const body *b)
{
  return b->inv_mass > 0.0 || body_kinematic_moving (b);
}

const convex_piece *contact_piece (const carom_world *world, const contact *k, int side, convex_piece *circle)
{
  const body *X = &world->bodies[side ? k->b : k->a];
  const convex_piece *pieces;
  int32_t piece = side ? k->piece_b : k->piece_a;
  body_pieces (X, &pieces, circle);
  if (piece >= 0)
    return &pieces[piece];
  return X->shape.kind == CAROM_SHAPE_CIRCLE ? pieces : NULL;
}

int contact_pair_swept (const carom_world *world, int32_t a, int32_t b, const step_context *ctx)
{
  const double *r = world->broad.reach;
  return body_pair_swept (&world->bodies[a], r[a], &world->bodies[b], r[b], ctx->dt, ctx->accel, ctx->continuous);
}

/* The contacts of bodies a and b. The margin looks as far ahead as the
 * pair can close in the step, from the bodies' velocities; `reach`, when
 * not negative, is that distance instead (velocities an impact changed
 * within the step, contacts_after_impacts). */
static void detect_pair (carom_world *world, int32_t a, int32_t b, const step_context *ctx, double reach,
                         int may_defer)
{
  body *A, *B;
  pair_context pc;
  manifold m;
  int32_t i, j;
  /* order: polygon before circle, else lower slot first, so the normal
   * convention of each narrow-phase test holds and the result does not
   * depend on the broad phase's order (with a compound: lower slot first,
   * collide_pieces turns what needs turning) */
  carom_shape_kind ka = world->bodies[a].shape.kind, kb = world->bodies[b].shape.kind;
  int compound = ka == CAROM_SHAPE_COMPOUND || kb == CAROM_SHAPE_COMPOUND;
  {
    /* by selects: which of a pair comes first is not predictable */
    int swap = compound ? a > b : (ka == CAROM_SHAPE_CIRCLE && kb == CAROM_SHAPE_POLYGON) | (ka == kb && a > b);
    int32_t t = select_int (swap, b, a);
    b = select_int (swap, a, b);
    a = t;
  }
  A = &world->bodies[a];
  B = &world->bodies[b];
  /* joints_block_pair only when both have a joint: most pairs have none */
  if (!body_filters_pass (A, B) || (A->joint_head && B->joint_head && joints_block_pair (world, a, b)))
    return;
  if (A->sensor || B->sensor)
    {
      sensor_pair (world, a, b);
      return;
    }
  /* neither can move (a sleeping body against a static or sleeping one,
   * or a kinematic one at rest): nothing to detect or solve */
  if (!can_move (A) && !can_move (B))
    return;
  mix_materials (world, A->restitution, A->friction, B->restitution, B->friction, &pc);
  pc.slop = world->def.slop * (A->shape.size < B->shape.size ? A->shape.size : B->shape.size);
  pc.bouncy_swept = ctx->free_flight && reach < 0.0 && pc.restitution > 0.0
                    && body_pair_swept (A, world->broad.reach[a], B, world->broad.reach[b], ctx->dt, ctx->accel,
                                        ctx->continuous);
  /* clear of the step by the bodies' bounding circles: no narrow phase
   * unless a body of the pair turns out pushed (redetect_deferred) */
  if (pc.bouncy_swept && may_defer && circles_clear_of_step (A, B, pc.slop, ctx->dt))
    {
      defer_pair (world, a, b);
      return;
    }
  pc.ctx = ctx;
  pc.reach = reach;
  pc.margins_set = 0;
  pc.reuse_ang = world->def.manifold_tolerance;
  pc.reuse_lin = world->def.manifold_tolerance * (A->shape.size < B->shape.size ? A->shape.size : B->shape.size);
  pc.pieces_a = pc.pieces_b = NULL;
  pc.a = a, pc.b = b;
  pc.xa.p = A->p, pc.xa.q = A->q;
  pc.xb.p = B->p, pc.xb.q = B->q;

  if (compound)
    {
      on_compound_pair (world, &pc);
      return;
    }
  if (A->shape.kind == CAROM_SHAPE_CIRCLE)
    {
      pair_pieces (world, -1, -1, &pc, &m, 0);
      return;
    }
  if (B->shape.kind == CAROM_SHAPE_CIRCLE)
    {
      for (i = 0; i < A->shape.piece_count; ++i)
        {
          const convex_piece *p = &A->shape.pieces[i];
          vec2 c = xform_apply (pc.xa, p->center);
          if (!pieces_near (world, &pc, v2_sub (B->p, c), p->bound_radius + B->shape.radius))
            continue;
          pair_pieces (world, i, -1, &pc, &m, 0);
        }
      return;
    }
  if (world->def.narrow_phase == CAROM_NARROW_VERTEX_EDGE)
    {
      pair_pieces (world, -1, -1, &pc, &m, 0);
      return;
    }
  for (i = 0; i < A->shape.piece_count; ++i)
    {
      const convex_piece *p = &A->shape.pieces[i];
      vec2 pc_center = xform_apply (pc.xa, p->center);
      for (j = 0; j < B->shape.piece_count; ++j)
        {
          const convex_piece *q = &B->shape.pieces[j];
          vec2 qc = xform_apply (pc.xb, q->center);
          if (!pieces_near (world, &pc, v2_sub (qc, pc_center), p->bound_radius + q->bound_radius))
            continue;
          pair_pieces (world, i, j, &pc, &m, pc.reuse_lin > 0.0);
        }
    }
}

static void on_pair (carom_world *world, int32_t a, int32_t b, void *user)
{
  detect_pair (world, a, b, user, -1.0, 1);
}

/* ------------------------------------------------------- after impacts */

/* What contacts_after_impacts hands each pair it finds. */
typedef struct after_impacts {
  const step_context *ctx;
  const int32_t *start, *other; /* the contacts' adjacency before any was added */
  int full;                     /* that room ran out */
} after_impacts;

/* Whether bodies s and o have a contact (of those before this stage). */
static int have_contact (const after_impacts *ai, int32_t s, int32_t o)
{
  int32_t e;
  for (e = ai->start[s]; e < ai->start[s + 1]; ++e)
    if (ai->other[e] == o)
      return 1;
  return 0;
}

/* How fast two bodies, each at its velocities before or after its
 * impacts (a body not struck: the same), can close on each other: the
 * fastest of the four relative velocities, and the faster spin of each. */
static double closing_speed (const body *S, const solver_body *s, const body *O, const solver_body *o)
{
  double fastest = 0.0;
  int i;
  for (i = 0; i < 4; ++i)
    {
      double u = v2_len (v2_sub (i & 1 ? s->v : S->v, i & 2 ? o->v : O->v));
      fastest = u > fastest ? u : fastest;
    }
  return fastest + fmax (fabs (s->w), fabs (S->w)) * S->shape.bound_radius
         + fmax (fabs (o->w), fabs (O->w)) * O->shape.bound_radius;
}

/* A pair of a struck body s and a body o its flight can reach: its
 * contacts, looking as far ahead as the two can close in the step with
 * their velocities before and after their impacts (the detection looked
 * only as far as those before). */
static void on_struck_pair (carom_world *world, int32_t s, int32_t o, void *user)
{
  after_impacts *ai = user;
  contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  const step_context *ctx = ai->ctx;
  const body *S = &world->bodies[s], *O = &world->bodies[o];
  double fall = S->inv_mass > 0.0 || O->inv_mass > 0.0 ? ctx->accel * ctx->dt : 0.0;
  int32_t pieces = (S->shape.piece_count > 1 ? S->shape.piece_count : 1)
                   * (O->shape.piece_count > 1 ? O->shape.piece_count : 1);
  if (ai->full || O->sensor || S->sensor || have_contact (ai, s, o))
    return;
  /* room kept for it (contacts.room_count): what does not fit is left for
   * the next detection. The list and the pool may hold more, but the
   * solver's arrays per contact were sized for that room alone (and the
   * headroom itself grows with each bouncy contact added here). */
  if (c->count + pieces > c->room_count || c->point_count + MANIFOLD_MAX_POINTS * pieces > c->room_points)
    {
      ai->full = 1;
      return;
    }
  detect_pair (world, s, o, ctx, ctx->dt * (closing_speed (S, &sb[s], O, &sb[o]) + fall), 0);
}

int32_t contacts_after_impacts (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  const solver_body *sb = world->solver_bodies;
  double *reach = world->cold_load; /* free until contact_cold_start */
  sweep_entry *boxes = world->broad.scratch; /* free after the detection */
  int32_t i, k = 0, first = c->count, *adj, *start, *other;
  after_impacts ai;
  if (c->impacts == 0)
    return first;
  for (i = 0; i < world->slot_count; ++i)
    {
      const body *B = &world->bodies[i];
      double r;
      reach[i] = 0.0;
      if (sb[i].moves != MOVES_DYNAMIC || (sb[i].v.x == B->v.x && sb[i].v.y == B->v.y && sb[i].w == B->w))
        continue;
      /* before its impacts it moved at its old velocities, after them at
       * its new ones: from where it began, no further than the faster of
       * the two would take it in the whole step. The detection's pairs
       * looked ahead by the bodies' relative motion at the old ones: any
       * change can bring it to a body it had no contact with. */
      r = fmax (body_reach_at (B, sb[i].v, sb[i].w, ctx->dt, ctx->accel), world->broad.reach[i]);
      /* a reach of 0 (at rest before and after, no gravity) meets nothing
       * new, and would not mark the body as queried (reach[i] != 0), which
       * would pair its box with its own entry */
      if (!(r > 0.0) || !body_swept (B, r, ctx->dt, ctx->accel, ctx->continuous))
        continue;
      reach[i] = r;
      broadphase_box (world, i, r, &boxes[k++]);
    }
  if (k == 0)
    return first;
  solver_contact_adjacency (world, &start, &adj, &other);
  ai.ctx = ctx, ai.start = start, ai.other = other, ai.full = 0;
  broadphase_query (world, boxes, k, reach, on_struck_pair, &ai);
  return first;
}

int32_t contacts_headroom (const carom_world *world)
{
  /* a pair of compounds has a contact for each two pieces: room for one
   * such pair of the largest bodies, up to AFTER_IMPACT_PAIR_ROOT squared */
  int32_t most = world->most_pieces > 1 ? world->most_pieces : 1;
  int32_t pair = most > AFTER_IMPACT_PAIR_ROOT ? AFTER_IMPACT_PAIR_ROOT * AFTER_IMPACT_PAIR_ROOT : most * most;
  return world->contacts.bouncy_found > 0 ? world->contacts.bouncy_found + 8 + pair : 0;
}

/* Put last step's contacts back, as if the last contacts_update had not
 * run (its own failure, or a later stage's, within the same sub-step). */
void contacts_undo (carom_world *world)
{
  contacts *c = &world->contacts;
  contact *t = c->list;
  contact_point *tp = c->pool;
  int32_t tcap = c->cap, tpcap = c->pool_cap, i, points = 0;
  c->list = c->old, c->count = c->old_count, c->cap = c->old_cap;
  c->old = t, c->old_cap = tcap, c->old_count = 0;
  c->pool = c->old_pool, c->pool_cap = c->old_pool_cap;
  c->old_pool = tp, c->old_pool_cap = tpcap;
  for (i = 0; i < c->count; ++i)
    points += c->list[i].count;
  c->point_count = points;
}

/* Point every contact of the list at its points in the pool (which may
 * have moved as it grew during the detection). */
static void point_contacts (contacts *c)
{
  int32_t i;
  for (i = 0; i < c->count; ++i)
    c->list[i].points = c->pool + c->list[i].first_point;
}

void contacts_point_again (carom_world *world)
{
  point_contacts (&world->contacts);
}

/* Mark (c->pushed) the bodies drop_clear keeps every contact of: those
 * with a joint or a contact within the slop. */
static void mark_pushed (carom_world *world)
{
  contacts *c = &world->contacts;
  unsigned char *pushed = c->pushed;
  int32_t i, j;
  for (i = 0; i < world->slot_count; ++i)
    pushed[i] = world->bodies[i].alive && world->bodies[i].joint_count > 0;
  for (i = 0; i < c->count; ++i)
    {
      const contact *k = &c->list[i];
      if (k->clear)
        continue;
      for (j = 0; j < k->count; ++j)
        if (c->pool[k->first_point + j].depth >= -k->slop)
          {
            pushed[k->a] = pushed[k->b] = 1;
            break;
          }
    }
}

/* Drop the contacts found clear of the step (clear_of_step) whose dynamic
 * bodies nothing but an impact can push within it: no other contact of
 * theirs is within the slop, and they have no joint. Free flight, which
 * the verdict assumed, is then theirs until an impact, after which
 * contacts_after_impacts looks again. A body held by a joint, or pressed
 * against another (squeezed between two, or pushed out of an overlap),
 * keeps every contact. The rest keep their order, and their points stay
 * in a row. */
static void drop_clear (carom_world *world)
{
  contacts *c = &world->contacts;
  const unsigned char *pushed = c->pushed;
  int32_t i, j, end, n = 0, points = 0;
  mark_pushed (world);
  /* a pair's contacts (of several pieces) lie in a row; they go together
   * or not at all (contacts_after_impacts takes a pair with any contact
   * as found) */
  for (i = 0; i < c->count; i = end)
    {
      const contact *k = &c->list[i];
      const body *A = &world->bodies[k->a], *B = &world->bodies[k->b];
      int drop = !(A->type == CAROM_DYNAMIC && pushed[k->a]) && !(B->type == CAROM_DYNAMIC && pushed[k->b]);
      for (end = i; end < c->count && c->list[end].a == k->a && c->list[end].b == k->b; ++end)
        drop &= c->list[end].clear;
      for (j = i; j < end; ++j)
        {
          contact *q = &c->list[j];
          if (drop)
            {
              c->bouncy_found -= q->restitution > 0.0;
              continue;
            }
          if (points != q->first_point)
            memmove (&c->pool[points], &c->pool[q->first_point], (size_t) q->count * sizeof (contact_point));
          q->first_point = points;
          points += q->count;
          if (n != j)
            c->list[n] = *q;
          ++n;
        }
    }
  c->count = n;
  c->point_count = points;
}

/* The pairs found clear of the step by their bounding circles alone
 * (detect_pair) whose flight is not free after all, a body of theirs
 * pushed (mark_pushed): their contacts, as drop_clear keeps them. The
 * contacts these add lie beyond the slop, so mark no body pushed. */
static void redetect_deferred (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  const unsigned char *pushed = c->pushed;
  int32_t i;
  mark_pushed (world);
  for (i = 0; i < c->deferred_count; ++i)
    {
      int32_t a = c->deferred[2 * i], b = c->deferred[2 * i + 1];
      if ((world->bodies[a].type == CAROM_DYNAMIC && pushed[a])
          || (world->bodies[b].type == CAROM_DYNAMIC && pushed[b]))
        detect_pair (world, a, b, ctx, -1.0, 0);
    }
}

carom_status contacts_update (carom_world *world, const step_context *ctx)
{
  contacts *c = &world->contacts;
  contact *t = c->old;
  contact_point *tp = c->old_pool;
  int32_t tcap = c->old_cap, tpcap = c->old_pool_cap;
  if (!mem_reserve (&world->allocator, (void **) &c->pushed, &c->pushed_cap, world->slot_count, 1))
    return CAROM_ERR_OUT_OF_MEMORY;
  /* last step's contacts become `old`; this step fills the other buffer */
  c->old = c->list, c->old_count = c->count, c->old_cap = c->cap;
  c->list = t, c->cap = tcap, c->count = 0;
  c->old_pool = c->pool, c->old_pool_cap = c->pool_cap;
  c->pool = tp, c->pool_cap = tpcap;
  c->point_count = 0;
  c->bouncy_found = 0;
  c->room_count = c->room_points = 0;
  c->sensor_count = 0;
  c->clear_count = 0;
  c->deferred_count = 0;
  c->dt = ctx->dt;
  c->out_of_memory = 0;
  c->cursor = 0;
  c->table_built = 0;
  if (world->seams_dirty)
    seams_update (world);
  if (!broadphase_update (world, ctx, on_pair, (void *) ctx) || c->out_of_memory
      || (c->deferred_count > 0 && (redetect_deferred (world, ctx), c->out_of_memory)))
    {
      contacts_undo (world); /* the world is as it was */
      return CAROM_ERR_OUT_OF_MEMORY;
    }
  /* the points of the contacts were placed in the pool as they were
   * added: only a pool that grew since (moved), or drop_clear's moving
   * them down, leaves them pointing elsewhere */
  if (c->clear_count > 0)
    drop_clear (world);
  if (c->clear_count > 0 || c->pool_cap != tpcap)
    point_contacts (c);
  return CAROM_OK;
}

static void forget_in (contact *list, int32_t *count, int32_t slot)
{
  int32_t i, k = 0;
  for (i = 0; i < *count; ++i)
    if (list[i].a != slot && list[i].b != slot)
      list[k++] = list[i];
  *count = k;
}

/* How much of contact k's normal impulse holds body x up against gravity
 * (down: its unit direction): the impulse times the normal's share along
 * gravity, where the other body is below x; else 0. */
static double holds_up (const contact *k, int32_t x, vec2 down)
{
  /* the normal points from a to b: the other body is below x where the
   * normal from x to it points down */
  double along = v2_dot (k->points[0].normal, down) * (k->a == x ? 1.0 : -1.0), total = 0.0;
  int32_t j;
  if (!(along > 0.0))
    return 0.0;
  for (j = 0; j < k->count; ++j)
    total += k->points[j].normal_impulse;
  return total * along;
}

/* Body `slot` is being removed: take its weight off the impulses the
 * contacts beneath it carry into the next step's warm start. What it
 * pressed on each body below (the impulses of its contacts with them,
 * along gravity) comes off that body's own supports, shared as they share
 * its load now, and so on down to the ground. Otherwise the next warm start
 * would apply the removed weight's reaction to what carried it and throw
 * it up (Solver2D's "warm start energy"). Each round takes one level;
 * contacts keep their friction in proportion. Needs no allocation: the
 * scratch is reserved with each slot (body_reserve_slot). */
static void unload_pile (carom_world *world, int32_t slot)
{
  contacts *c = &world->contacts;
  int32_t n = world->slot_count, i, j, side, round;
  double *excess = world->unload, *next = excess + n, *held = next + n, g = v2_len (world->gravity);
  vec2 down;
  int more = 1;
  if (!(g > 0.0) || c->count == 0)
    return;
  down = v2_scale (world->gravity, 1.0 / g);
  /* only bodies of some contact are read or written: each round costs the
   * contacts, not the slots (a world may remove many bodies a step) */
  for (i = 0; i < c->count; ++i)
    excess[c->list[i].a] = excess[c->list[i].b] = 0.0;
  for (i = 0; i < c->count; ++i)
    {
      const contact *k = &c->list[i];
      int32_t other = k->a == slot ? k->b : k->b == slot ? k->a : -1;
      if (other >= 0 && world->bodies[other].type == CAROM_DYNAMIC)
        excess[other] += holds_up (k, slot, down);
    }
  for (round = 0; more && round < n; ++round)
    {
      more = 0;
      for (i = 0; i < c->count; ++i)
        {
          const contact *k = &c->list[i];
          held[k->a] = next[k->a] = held[k->b] = next[k->b] = 0.0;
        }
      for (i = 0; i < c->count; ++i)
        {
          const contact *k = &c->list[i];
          if (k->a == slot || k->b == slot)
            continue;
          if (excess[k->a] > 0.0)
            held[k->a] += holds_up (k, k->a, down);
          if (excess[k->b] > 0.0)
            held[k->b] += holds_up (k, k->b, down);
        }
      for (i = 0; i < c->count; ++i)
        {
          contact *k = &c->list[i];
          if (k->a == slot || k->b == slot)
            continue;
          for (side = 0; side < 2; ++side)
            {
              int32_t x = side ? k->b : k->a, other = side ? k->a : k->b;
              double up, share;
              if (!(excess[x] > 0.0 && held[x] > 0.0))
                continue;
              up = holds_up (k, x, down);
              if (!(up > 0.0))
                continue;
              /* this contact's part of x's load, and what of it goes */
              share = excess[x] < held[x] ? excess[x] / held[x] : 1.0;
              for (j = 0; j < k->count; ++j)
                {
                  k->points[j].normal_impulse *= 1.0 - share;
                  k->points[j].tangent_impulse *= 1.0 - share;
                }
              if (world->bodies[other].type == CAROM_DYNAMIC)
                {
                  next[other] += share * up;
                  more = 1;
                }
            }
        }
      for (i = 0; i < c->count; ++i)
        {
          const contact *k = &c->list[i];
          excess[k->a] = next[k->a], excess[k->b] = next[k->b];
        }
    }
}

void contacts_forget_body (carom_world *world, int32_t slot)
{
  contacts *c = &world->contacts;
  int32_t i, k, points = 0;
  unload_pile (world, slot);
  /* what rested on it must fall: wake what it touched */
  for (i = 0; i < c->count; ++i)
    if (c->list[i].a == slot || c->list[i].b == slot)
      body_wake (&world->bodies[c->list[i].a == slot ? c->list[i].b : c->list[i].a]);
  forget_in (c->list, &c->count, slot);
  forget_in (c->old, &c->old_count, slot);
  for (i = 0, k = 0; i < c->sensor_count; ++i)
    if (c->sensors[2 * i] != slot && c->sensors[2 * i + 1] != slot)
      {
        c->sensors[2 * k] = c->sensors[2 * i];
        c->sensors[2 * k + 1] = c->sensors[2 * i + 1];
        ++k;
      }
  c->sensor_count = k;
  /* the points of those that stay move down with them */
  for (i = 0; i < c->count; ++i)
    {
      contact *k = &c->list[i];
      if (k->first_point != points)
        memmove (c->pool + points, k->points, (size_t) k->count * sizeof (contact_point));
      k->first_point = points;
      k->points = c->pool + points;
      points += k->count;
    }
  c->point_count = points;
}

/* ------------------------------------------------------------ public API */

carom_status carom_world_detect (carom_world *world)
{
  step_context ctx;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  step_context_init (&ctx, world, 0.0); /* no step: no look-ahead */
  return contacts_update (world, &ctx);
}

int32_t carom_world_contact_count (const carom_world *world)
{
  return world ? world->contacts.point_count : 0;
}

carom_status carom_world_get_contact (const carom_world *world, int32_t index, carom_body_id *a, carom_body_id *b,
                                      double *px, double *py, double *nx, double *ny, double *depth)
{
  const contacts *c;
  int32_t lo, hi;
  const contact *k;
  const contact_point *p;
  if (!world)
    return CAROM_ERR_NULL_ARGUMENT;
  c = &world->contacts;
  if (index < 0 || index >= c->point_count)
    return CAROM_ERR_BAD_ARGUMENT;
  /* binary search for the contact holding this point */
  lo = 0, hi = c->count - 1;
  while (lo < hi)
    {
      int32_t mid = (lo + hi + 1) / 2;
      if (c->list[mid].first_point <= index)
        lo = mid;
      else
        hi = mid - 1;
    }
  k = &c->list[lo];
  p = &k->points[index - k->first_point];
  if (a)
    *a = body_id_of (world, k->a);
  if (b)
    *b = body_id_of (world, k->b);
  if (px)
    *px = p->point.x;
  if (py)
    *py = p->point.y;
  if (nx)
    *nx = p->normal.x;
  if (ny)
    *ny = p->normal.y;
  if (depth)
    *depth = p->found;
  return CAROM_OK;
}
