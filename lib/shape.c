/* Shapes and their exact mass properties (thesis 3.1), polygon validation,
 * and the split of a concave polygon into convex pieces (ear clipping, then
 * Hertel-Mehlhorn merging of triangles across diagonals). */
#include "shape.h"

#include <string.h>

void polygon_mass (const vec2 *v, int32_t n, double *signed_area, vec2 *centroid, double *unit_inertia)
{
  /* Area and centroid from a fan of signed triangles rooted at v[0]: keeping
   * the root on the polygon limits cancellation far from the origin. */
  vec2 o = v[0], c = v2 (0.0, 0.0);
  double area2 = 0.0, inertia = 0.0;
  int32_t i;
  for (i = 1; i + 1 < n; ++i)
    {
      vec2 e1 = v2_sub (v[i], o), e2 = v2_sub (v[i + 1], o);
      double a = v2_cross (e1, e2);
      area2 += a;
      c = v2_mad (c, a, v2_add (e1, e2));
    }
  c = area2 != 0.0 ? v2_add (o, v2_scale (c, 1.0 / (3.0 * area2))) : o;

  /* eq. 3.14: I = sum_i m_Ti / 2 (|P_i P_i+1|^2 / 3 + CP_i . P_i P_i+1
   * + |CP_i|^2), with C the centroid and m_Ti the signed mass of triangle
   * (C, P_i, P_i+1). A triangle on the far side of C for a concave outline
   * gets a negative mass and takes off what its neighbours over-count. */
  for (i = 0; i < n; ++i)
    {
      vec2 a = v[i], b = v[(i + 1) % n];
      vec2 ca = v2_sub (a, c), ab = v2_sub (b, a);
      double m_t = 0.5 * v2_cross (ca, v2_sub (b, c)); /* eq. 3.13's m_Ti */
      inertia += 0.5 * m_t * (v2_dot (ab, ab) / 3.0 + v2_dot (ab, ca) + v2_dot (ca, ca));
    }
  if (area2 < 0.0)
    inertia = -inertia;
  *signed_area = 0.5 * area2;
  *centroid = c;
  *unit_inertia = inertia;
}

/* Orientation of c relative to the directed line a -> b (twice the signed
 * triangle area). */
static double orient (vec2 a, vec2 b, vec2 c)
{
  return v2_cross (v2_sub (b, a), v2_sub (c, a));
}

static int on_segment (vec2 a, vec2 b, vec2 p)
{
  return p.x >= (a.x < b.x ? a.x : b.x) && p.x <= (a.x > b.x ? a.x : b.x)
         && p.y >= (a.y < b.y ? a.y : b.y) && p.y <= (a.y > b.y ? a.y : b.y);
}

static int sign (double x) { return (x > 0.0) - (x < 0.0); }

/* Closed segments p1p2 and q1q2 share at least one point. */
static int segments_touch (vec2 p1, vec2 p2, vec2 q1, vec2 q2)
{
  int d1 = sign (orient (q1, q2, p1)), d2 = sign (orient (q1, q2, p2));
  int d3 = sign (orient (p1, p2, q1)), d4 = sign (orient (p1, p2, q2));
  if (d1 * d2 < 0 && d3 * d4 < 0)
    return 1;
  return (d1 == 0 && on_segment (q1, q2, p1)) || (d2 == 0 && on_segment (q1, q2, p2))
         || (d3 == 0 && on_segment (p1, p2, q1)) || (d4 == 0 && on_segment (p1, p2, q2));
}

static vec2 vertex_at (const double *xy, int32_t i)
{
  return v2 (xy[2 * i], xy[2 * i + 1]);
}

carom_status polygon_validate (const double *xy, int32_t n)
{
  int32_t i, j;
  vec2 lo, hi;
  double extent, area;
  if (!xy)
    return CAROM_ERR_NULL_ARGUMENT;
  if (n < 3)
    return CAROM_ERR_TOO_FEW_VERTICES;
  if (n > CAROM_MAX_POLYGON_VERTICES)
    return CAROM_ERR_TOO_MANY_VERTICES;
  for (i = 0; i < 2 * n; ++i)
    if (!is_finite (xy[i]))
      return CAROM_ERR_NOT_FINITE;
  lo = hi = vertex_at (xy, 0);
  for (i = 1; i < n; ++i)
    {
      lo = v2_min (lo, vertex_at (xy, i));
      hi = v2_max (hi, vertex_at (xy, i));
    }
  extent = v2_len (v2_sub (hi, lo));
  if (!is_finite (extent))
    return CAROM_ERR_NOT_FINITE; /* finite coordinates whose spread overflows */
  /* Mass properties take the fourth power of the size and the tolerances
   * below a 1e-12 fraction of it: sizes whose powers leave the range of
   * doubles cannot be simulated. */
  if (!(extent > 1e-60))
    return CAROM_ERR_ZERO_AREA;
  if (!(extent < 1e60))
    return CAROM_ERR_BAD_SIZE;
  /* Consecutive vertices closer than a relative 1e-12 of the polygon's size
   * are one vertex given twice: the edge between them has no direction. */
  for (i = 0; i < n; ++i)
    if (v2_len (v2_sub (vertex_at (xy, (i + 1) % n), vertex_at (xy, i))) <= 1e-12 * extent)
      return CAROM_ERR_REPEATED_VERTEX;
  /* All vertices on one line: no area at all (checked before the edge
   * tests, which would also see overlapping edges here). */
  {
    double spread = 0.0;
    vec2 o = vertex_at (xy, 0);
    for (i = 1; i + 1 < n; ++i)
      spread += fabs (v2_cross (v2_sub (vertex_at (xy, i), o), v2_sub (vertex_at (xy, i + 1), o)));
    if (!(spread > 1e-12 * extent * extent))
      return CAROM_ERR_ZERO_AREA;
  }
  /* Adjacent edges that fold back onto each other overlap. */
  for (i = 0; i < n; ++i)
    {
      vec2 a = vertex_at (xy, (i + n - 1) % n), b = vertex_at (xy, i), d = vertex_at (xy, (i + 1) % n);
      if (orient (a, b, d) == 0.0 && v2_dot (v2_sub (b, a), v2_sub (d, b)) < 0.0)
        return CAROM_ERR_SELF_INTERSECTING;
    }
  /* Non-adjacent edges must not touch at all (a simple polygon). */
  for (i = 0; i < n; ++i)
    for (j = i + 2; j < n; ++j)
      {
        if (i == 0 && j == n - 1)
          continue; /* adjacent through the closing edge */
        if (segments_touch (vertex_at (xy, i), vertex_at (xy, i + 1), vertex_at (xy, j), vertex_at (xy, (j + 1) % n)))
          return CAROM_ERR_SELF_INTERSECTING;
      }
  /* Area, checked on the copy shape_init_polygon will make. */
  {
    double area2 = 0.0;
    vec2 o = vertex_at (xy, 0);
    for (i = 1; i + 1 < n; ++i)
      area2 += v2_cross (v2_sub (vertex_at (xy, i), o), v2_sub (vertex_at (xy, i + 1), o));
    area = 0.5 * area2;
  }
  if (!(fabs (area) > 1e-12 * extent * extent))
    return CAROM_ERR_ZERO_AREA;
  return CAROM_OK;
}

carom_status shape_init_circle (shape *s, double radius)
{
  memset (s, 0, sizeof *s);
  s->kind = CAROM_SHAPE_CIRCLE;
  s->radius = radius;
  s->area = CAROM_PI * radius * radius;
  s->unit_inertia = 0.5 * s->area * radius * radius; /* m r^2 / 2 */
  s->bound_radius = radius;
  s->size = radius; /* 2 pi r^2 / (2 pi r) */
  return CAROM_OK;
}

static void compute_normals (const vec2 *v, vec2 *normals, int32_t n)
{
  int32_t i;
  for (i = 0; i < n; ++i)
    {
      vec2 e = v2_sub (v[(i + 1) % n], v[i]);
      normals[i] = v2_normalize (v2 (e.y, -e.x)); /* outward for CCW */
    }
}

static void piece_bounds (convex_piece *p)
{
  vec2 c = v2 (0.0, 0.0);
  double r = 0.0;
  int32_t i;
  for (i = 0; i < p->count; ++i)
    c = v2_add (c, p->vertices[i]);
  c = v2_scale (c, 1.0 / p->count);
  for (i = 0; i < p->count; ++i)
    {
      double d = v2_len (v2_sub (p->vertices[i], c));
      if (d > r)
        r = d;
    }
  p->center = c;
  p->bound_radius = r;
}

/* Twice the signed area of the turn a -> b -> c, compared with a tolerance
 * relative to the edge lengths so nearly collinear vertices count as flat. */
static int turn_sign (vec2 a, vec2 b, vec2 c)
{
  vec2 e1 = v2_sub (b, a), e2 = v2_sub (c, b);
  double cr = v2_cross (e1, e2);
  double tol = 1e-12 * v2_len (e1) * v2_len (e2);
  return cr > tol ? 1 : (cr < -tol ? -1 : 0);
}

/* Remove vertices where the outline runs straight on (collinear within the
 * turn_sign tolerance), in place; returns the new count (at least 3). A
 * convex piece must have one edge per direction: SAT's clipping takes a
 * single incident edge, and half of a split face would miss the deepest
 * corner. */
static int32_t drop_flat (vec2 *v, int32_t n)
{
  int32_t i = 0;
  while (n > 3 && i < n)
    {
      if (turn_sign (v[(i + n - 1) % n], v[i], v[(i + 1) % n]) == 0)
        {
          memmove (&v[i], &v[i + 1], (size_t) (n - i - 1) * sizeof *v);
          n--;
          if (i > 0)
            i--;
        }
      else
        i++;
    }
  return n;
}

static int point_in_triangle (vec2 p, vec2 a, vec2 b, vec2 c)
{
  /* closed triangle, counter-clockwise */
  return orient (a, b, p) >= 0.0 && orient (b, c, p) >= 0.0 && orient (c, a, p) >= 0.0;
}

/* One convex piece during merging: a list of outline indices, CCW. */
typedef struct piece_list {
  int32_t *idx;
  int32_t count;
} piece_list;

static int32_t find_in (const piece_list *p, int32_t x)
{
  int32_t i;
  for (i = 0; i < p->count; ++i)
    if (p->idx[i] == x)
      return i;
  return -1;
}

static int32_t uf_find (int32_t *parent, int32_t x)
{
  while (parent[x] != x)
    {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
  return x;
}

/* Split the counter-clockwise simple polygon v[0..n) into convex pieces.
 * Triangulates by ear clipping (recording which two triangles share each
 * diagonal), then removes every diagonal whose removal keeps both of its
 * endpoints convex (Hertel-Mehlhorn: at most four times the optimal count). */
static carom_status decompose (shape *s, const carom_allocator *a)
{
  const vec2 *v = s->vertices;
  int32_t n = s->count;
  size_t scratch_ints = (size_t) n * 12;
  int32_t *scratch = mem_alloc (a, scratch_ints * sizeof (int32_t));
  piece_list *lists = NULL;
  int32_t *prev, *next, *tri, *diag_of_edge, *diag_first, *diag_second, *diag_u, *diag_v, *parent;
  int32_t tri_count = 0, diag_count = 0, remaining = n, i, guard, k, pieces = 0;
  carom_status status = CAROM_OK;
  if (!scratch)
    return CAROM_ERR_OUT_OF_MEMORY;
  prev = scratch;
  next = prev + n;
  tri = next + n;             /* 3 per triangle, at most n - 2 triangles */
  diag_of_edge = tri + 3 * n; /* diagonal that is the edge i -> next[i] */
  diag_first = diag_of_edge + n;
  diag_second = diag_first + n;
  diag_u = diag_second + n;
  diag_v = diag_u + n;
  parent = diag_v + n;
  for (i = 0; i < n; ++i)
    {
      prev[i] = (i + n - 1) % n;
      next[i] = (i + 1) % n;
      diag_of_edge[i] = -1;
    }

  i = 0;
  guard = 0;
  while (remaining > 3)
    {
      int32_t p = prev[i], q = next[i], ear = 0, t = turn_sign (v[p], v[i], v[q]);
      if (t == 0)
        ear = 2; /* a flat vertex: drop it, no triangle */
      else if (t > 0)
        {
          int32_t j;
          ear = 1;
          for (j = next[q]; j != p; j = next[j])
            if (turn_sign (v[prev[j]], v[j], v[next[j]]) <= 0 && point_in_triangle (v[j], v[p], v[i], v[q]))
              {
                ear = 0;
                break;
              }
        }
      if (!ear && ++guard > remaining)
        ear = 1; /* rounding left no clean ear: clip this vertex anyway */
      if (ear)
        {
          int32_t d = -1;
          if (ear == 1)
            {
              int32_t t_id = tri_count++;
              tri[3 * t_id] = p;
              tri[3 * t_id + 1] = i;
              tri[3 * t_id + 2] = q;
              /* the edges p->i and i->q may be diagonals made earlier: this
               * triangle is their second side */
              if (diag_of_edge[p] >= 0)
                diag_second[diag_of_edge[p]] = t_id;
              if (diag_of_edge[i] >= 0)
                diag_second[diag_of_edge[i]] = t_id;
              d = diag_count++;
              diag_first[d] = t_id;
              diag_second[d] = -1;
              diag_u[d] = p;
              diag_v[d] = q;
            }
          else if (diag_of_edge[p] >= 0 || diag_of_edge[i] >= 0)
            d = diag_of_edge[p] >= 0 ? diag_of_edge[p] : diag_of_edge[i]; /* keep the link */
          next[p] = q;
          prev[q] = p;
          diag_of_edge[p] = d;
          --remaining;
          guard = 0;
          i = q;
        }
      else
        i = next[i];
    }
  /* the last triangle */
  {
    int32_t p = prev[i], q = next[i], t_id = tri_count;
    if (turn_sign (v[p], v[i], v[q]) != 0 || tri_count == 0)
      {
        tri_count++;
        tri[3 * t_id] = p;
        tri[3 * t_id + 1] = i;
        tri[3 * t_id + 2] = q;
        if (diag_of_edge[p] >= 0)
          diag_second[diag_of_edge[p]] = t_id;
        if (diag_of_edge[i] >= 0)
          diag_second[diag_of_edge[i]] = t_id;
        if (diag_of_edge[q] >= 0)
          diag_second[diag_of_edge[q]] = t_id;
      }
  }

  lists = mem_alloc (a, (size_t) tri_count * sizeof *lists);
  if (!lists)
    {
      mem_free (a, scratch, scratch_ints * sizeof (int32_t));
      return CAROM_ERR_OUT_OF_MEMORY;
    }
  memset (lists, 0, (size_t) tri_count * sizeof *lists);
  for (k = 0; k < tri_count; ++k)
    {
      lists[k].idx = mem_alloc (a, 3 * sizeof (int32_t));
      if (!lists[k].idx)
        {
          status = CAROM_ERR_OUT_OF_MEMORY;
          goto done;
        }
      memcpy (lists[k].idx, tri + 3 * k, 3 * sizeof (int32_t));
      lists[k].count = 3;
      parent[k] = k;
    }

  /* Hertel-Mehlhorn: drop each diagonal that leaves both endpoints convex. */
  for (k = 0; k < diag_count; ++k)
    {
      int32_t u = diag_u[k], w = diag_v[k], rp, rq, pu, pw, qu, qw, m, j;
      piece_list *P, *Q;
      int32_t *merged;
      if (diag_second[k] < 0)
        continue;
      rq = uf_find (parent, diag_first[k]);  /* holds the edge w -> u */
      rp = uf_find (parent, diag_second[k]); /* holds the edge u -> w */
      if (rp == rq)
        continue;
      P = &lists[rp];
      Q = &lists[rq];
      pu = find_in (P, u);
      pw = find_in (P, w);
      qu = find_in (Q, u);
      qw = find_in (Q, w);
      if (pu < 0 || pw < 0 || qu < 0 || qw < 0 || P->idx[(pu + 1) % P->count] != w || Q->idx[(qw + 1) % Q->count] != u)
        continue; /* the diagonal is no longer a shared edge (flat vertices) */
      /* at u: comes from P's predecessor of u, leaves to Q's successor of u */
      if (turn_sign (v[P->idx[(pu + P->count - 1) % P->count]], v[u], v[Q->idx[(qu + 1) % Q->count]]) < 0)
        continue;
      if (turn_sign (v[Q->idx[(qw + Q->count - 1) % Q->count]], v[w], v[P->idx[(pw + 1) % P->count]]) < 0)
        continue;
      merged = mem_alloc (a, (size_t) (P->count + Q->count - 2) * sizeof (int32_t));
      if (!merged)
        {
          status = CAROM_ERR_OUT_OF_MEMORY;
          goto done;
        }
      /* w, P's vertices after w up to u, then Q's vertices after u up to
       * (not including) w */
      m = 0;
      for (j = pw; ; j = (j + 1) % P->count)
        {
          merged[m++] = P->idx[j];
          if (P->idx[j] == u)
            break;
        }
      for (j = (qu + 1) % Q->count; Q->idx[j] != w; j = (j + 1) % Q->count)
        merged[m++] = Q->idx[j];
      mem_free (a, P->idx, (size_t) P->count * sizeof (int32_t));
      mem_free (a, Q->idx, (size_t) Q->count * sizeof (int32_t));
      Q->idx = NULL;
      Q->count = 0;
      P->idx = merged;
      P->count = m;
      parent[rq] = rp;
    }

  for (k = 0; k < tri_count; ++k)
    if (lists[k].count > 0)
      pieces++;
  s->pieces = mem_alloc (a, (size_t) pieces * sizeof (convex_piece));
  if (!s->pieces)
    {
      status = CAROM_ERR_OUT_OF_MEMORY;
      goto done;
    }
  s->piece_alloc = pieces;
  memset (s->pieces, 0, (size_t) pieces * sizeof (convex_piece));
  s->piece_count = 0;
  for (k = 0; k < tri_count; ++k)
    {
      convex_piece *cp;
      int32_t j;
      if (lists[k].count == 0)
        continue;
      cp = &s->pieces[s->piece_count++];
      cp->count = cp->alloc_count = lists[k].count;
      cp->vertices = mem_alloc (a, (size_t) cp->count * 2 * sizeof (vec2));
      if (!cp->vertices)
        {
          s->piece_count--;
          status = CAROM_ERR_OUT_OF_MEMORY;
          goto done;
        }
      cp->normals = cp->vertices + cp->count;
      for (j = 0; j < cp->count; ++j)
        cp->vertices[j] = v[lists[k].idx[j]];
      cp->count = drop_flat (cp->vertices, cp->count);
      cp->normals = cp->vertices + cp->count;
      compute_normals (cp->vertices, cp->normals, cp->count);
      piece_bounds (cp);
    }

done:
  for (k = 0; k < tri_count; ++k)
    mem_free (a, lists[k].idx, (size_t) lists[k].count * sizeof (int32_t));
  mem_free (a, lists, (size_t) tri_count * sizeof *lists);
  mem_free (a, scratch, scratch_ints * sizeof (int32_t));
  return status;
}

carom_status shape_init_polygon (shape *s, const carom_allocator *a, const double *xy, int32_t n, vec2 *centroid)
{
  double area, inertia, perimeter = 0.0;
  vec2 c, c2;
  int32_t i;
  carom_status status;
  memset (s, 0, sizeof *s);
  s->kind = CAROM_SHAPE_POLYGON;
  s->count = n;
  s->vertices = mem_alloc (a, (size_t) n * 2 * sizeof (vec2));
  if (!s->vertices)
    return CAROM_ERR_OUT_OF_MEMORY;
  s->normals = s->vertices + n;
  for (i = 0; i < n; ++i)
    s->vertices[i] = v2 (xy[2 * i], xy[2 * i + 1]);
  polygon_mass (s->vertices, n, &area, &c, &inertia);
  if (area < 0.0)
    for (i = 0; i < n / 2; ++i)
      {
        vec2 t = s->vertices[i];
        s->vertices[i] = s->vertices[n - 1 - i];
        s->vertices[n - 1 - i] = t;
      }
  for (i = 0; i < n; ++i)
    s->vertices[i] = v2_sub (s->vertices[i], c);
  /* mass properties again about the centred copy, where rounding is least */
  polygon_mass (s->vertices, n, &area, &c2, &inertia);
  *centroid = c;
  s->area = area;
  s->unit_inertia = inertia;
  compute_normals (s->vertices, s->normals, n);
  s->convex = 1;
  for (i = 0; i < n; ++i)
    {
      double r = v2_len (s->vertices[i]);
      if (r > s->bound_radius)
        s->bound_radius = r;
      perimeter += v2_len (v2_sub (s->vertices[(i + 1) % n], s->vertices[i]));
      if (turn_sign (s->vertices[(i + n - 1) % n], s->vertices[i], s->vertices[(i + 1) % n]) < 0)
        s->convex = 0;
    }
  s->size = 2.0 * area / perimeter;
  if (s->convex)
    {
      int32_t flat = 0;
      for (i = 0; i < n; ++i)
        flat += turn_sign (s->vertices[(i + n - 1) % n], s->vertices[i], s->vertices[(i + 1) % n]) == 0;
      s->pieces = mem_alloc (a, sizeof (convex_piece));
      if (!s->pieces)
        {
          mem_free (a, s->vertices, (size_t) n * 2 * sizeof (vec2));
          s->vertices = NULL;
          return CAROM_ERR_OUT_OF_MEMORY;
        }
      memset (s->pieces, 0, sizeof (convex_piece));
      s->piece_count = s->piece_alloc = 1;
      if (!flat)
        {
          s->pieces_shared = 1;
          s->pieces[0].count = n;
          s->pieces[0].vertices = s->vertices; /* shared with the outline */
          s->pieces[0].normals = s->normals;
        }
      else
        {
          /* the outline as drawn keeps its straight-through vertices; the
           * piece collisions use does not */
          convex_piece *cp = &s->pieces[0];
          cp->vertices = mem_alloc (a, (size_t) n * 2 * sizeof (vec2));
          if (!cp->vertices)
            {
              s->piece_count = 0;
              shape_destroy (s, a);
              return CAROM_ERR_OUT_OF_MEMORY;
            }
          cp->alloc_count = n;
          memcpy (cp->vertices, s->vertices, (size_t) n * sizeof (vec2));
          cp->count = drop_flat (cp->vertices, n);
          cp->normals = cp->vertices + cp->count;
          compute_normals (cp->vertices, cp->normals, cp->count);
        }
      piece_bounds (&s->pieces[0]);
      return CAROM_OK;
    }
  status = decompose (s, a);
  if (status != CAROM_OK)
    shape_destroy (s, a);
  return status;
}

void shape_destroy (shape *s, const carom_allocator *a)
{
  int32_t i;
  if (!s)
    return;
  if (s->kind == CAROM_SHAPE_COMPOUND)
    {
      /* the pieces list shares the parts' vertices */
      for (i = 0; i < s->part_count; ++i)
        shape_destroy (&s->parts[i].s, a);
      mem_free (a, s->parts, (size_t) s->part_count * sizeof (shape_part));
      mem_free (a, s->pieces, (size_t) s->piece_alloc * sizeof (convex_piece));
      s->parts = NULL;
      s->pieces = NULL;
      s->part_count = s->piece_count = 0;
      return;
    }
  if (s->kind != CAROM_SHAPE_POLYGON)
    return;
  if (s->pieces)
    {
      if (!s->pieces_shared)
        for (i = 0; i < s->piece_count; ++i)
          mem_free (a, s->pieces[i].vertices, (size_t) s->pieces[i].alloc_count * 2 * sizeof (vec2));
      mem_free (a, s->pieces, (size_t) s->piece_alloc * sizeof (convex_piece));
    }
  mem_free (a, s->vertices, (size_t) s->count * 2 * sizeof (vec2));
  s->vertices = NULL;
  s->pieces = NULL;
  s->piece_count = 0;
}

void box_vertices (double width, double height, double *xy)
{
  xy[0] = -0.5 * width, xy[1] = -0.5 * height;
  xy[2] = 0.5 * width, xy[3] = -0.5 * height;
  xy[4] = 0.5 * width, xy[5] = 0.5 * height;
  xy[6] = -0.5 * width, xy[7] = 0.5 * height;
}

void regular_vertices (int32_t n, double side, double *xy)
{
  /* circumradius of a regular n-gon with side l: l / (2 sin(pi / n)) */
  double radius = side / (2.0 * sin (CAROM_PI / n));
  int32_t i;
  for (i = 0; i < n; ++i)
    {
      double t = 2.0 * CAROM_PI * i / n;
      xy[2 * i] = radius * cos (t);
      xy[2 * i + 1] = radius * sin (t);
    }
}

carom_status shape_init_box (shape *s, const carom_allocator *a, double width, double height)
{
  double xy[8];
  vec2 centroid;
  carom_status st;
  box_vertices (width, height, xy);
  st = shape_init_polygon (s, a, xy, 4, &centroid);
  /* eq. 3.4: I = m (w^2 + h^2) / 12, here per unit density (m = w h) */
  if (st == CAROM_OK)
    s->unit_inertia = width * height * (width * width + height * height) / 12.0;
  return st;
}

carom_status shape_init_regular (shape *s, const carom_allocator *a, int32_t n, double side)
{
  double *xy, area, cot;
  vec2 centroid;
  carom_status st;
  xy = mem_alloc (a, (size_t) n * 2 * sizeof (double));
  if (!xy)
    return CAROM_ERR_OUT_OF_MEMORY;
  regular_vertices (n, side, xy);
  st = polygon_validate (xy, n);
  if (st == CAROM_OK)
    st = shape_init_polygon (s, a, xy, n, &centroid);
  mem_free (a, xy, (size_t) n * 2 * sizeof (double));
  if (st != CAROM_OK)
    return st;
  /* eq. 3.6: I = m l^2 / 24 (1 + 3 cot^2(pi / n)), with m = area at unit
   * density; area = n l^2 / 4 cot(pi / n) */
  cot = 1.0 / tan (CAROM_PI / n);
  area = 0.25 * n * side * side * cot;
  s->unit_inertia = area * side * side / 24.0 * (1.0 + 3.0 * cot * cot);
  return CAROM_OK;
}

/* Move a circle or polygon shape's geometry by d (its pieces with it). */
static void shape_translate (shape *s, vec2 d)
{
  int32_t i, j;
  for (i = 0; i < s->count; ++i)
    s->vertices[i] = v2_add (s->vertices[i], d);
  for (i = 0; i < s->piece_count; ++i)
    {
      convex_piece *p = &s->pieces[i];
      if (p->vertices != s->vertices)
        for (j = 0; j < p->count; ++j)
          p->vertices[j] = v2_add (p->vertices[j], d);
      p->center = v2_add (p->center, d);
    }
}

carom_status shape_init_compound (shape *s, const carom_allocator *a, const shape_part *parts, int32_t count,
                                  vec2 *centroid)
{
  double mass = 0.0, inertia = 0.0, area = 0.0, size = INFINITY, bound = 0.0;
  vec2 c = v2 (0.0, 0.0), o = parts[0].center;
  int32_t i, j, pieces = 0;
  memset (s, 0, sizeof *s);
  for (i = 0; i < count; ++i)
    pieces += parts[i].s.kind == CAROM_SHAPE_CIRCLE ? 1 : parts[i].s.piece_count;
  s->parts = mem_alloc (a, (size_t) count * sizeof (shape_part));
  s->pieces = mem_alloc (a, (size_t) pieces * sizeof (convex_piece));
  if (!s->parts || !s->pieces)
    {
      mem_free (a, s->parts, (size_t) count * sizeof (shape_part));
      mem_free (a, s->pieces, (size_t) pieces * sizeof (convex_piece));
      return CAROM_ERR_OUT_OF_MEMORY;
    }
  memcpy (s->parts, parts, (size_t) count * sizeof (shape_part));
  s->kind = CAROM_SHAPE_COMPOUND;
  s->part_count = count;
  s->piece_alloc = s->piece_count = pieces;
  /* the centre of mass, summed about the first part's centroid so that
   * parts far from the caller's origin lose nothing to rounding */
  for (i = 0; i < count; ++i)
    {
      double m = parts[i].density * parts[i].s.area;
      mass += m;
      c = v2_mad (c, m, v2_sub (parts[i].center, o));
    }
  c = v2_add (o, v2_scale (c, 1.0 / mass));
  *centroid = c;
  /* the parallel axis theorem: each part's inertia about its own centroid,
   * plus its mass times the squared distance to the union's */
  for (i = 0, pieces = 0; i < count; ++i)
    {
      shape_part *p = &s->parts[i];
      double m = p->density * p->s.area;
      vec2 d = v2_sub (p->center, c);
      p->center = d;
      inertia += p->density * p->s.unit_inertia + m * v2_dot (d, d);
      area += p->s.area;
      if (p->s.size < size)
        size = p->s.size;
      if (v2_len (d) + p->s.bound_radius > bound)
        bound = v2_len (d) + p->s.bound_radius;
      if (p->s.kind == CAROM_SHAPE_CIRCLE)
        {
          convex_piece *q = &s->pieces[pieces++];
          memset (q, 0, sizeof *q);
          q->center = d;
          q->radius = q->bound_radius = p->s.radius;
        }
      else
        {
          shape_translate (&p->s, d);
          for (j = 0; j < p->s.piece_count; ++j)
            s->pieces[pieces++] = p->s.pieces[j];
        }
      for (j = pieces - (p->s.kind == CAROM_SHAPE_CIRCLE ? 1 : p->s.piece_count); j < pieces; ++j)
        {
          s->pieces[j].restitution = p->restitution;
          s->pieces[j].friction = p->friction;
        }
    }
  s->pieces_shared = 1;
  s->mass = mass;
  s->inertia = inertia;
  s->area = area;
  s->bound_radius = bound;
  s->size = size;
  return CAROM_OK;
}

void shape_mass (const shape *s, double density, double *mass, double *inertia)
{
  if (s->kind == CAROM_SHAPE_COMPOUND)
    {
      *mass = s->mass;
      *inertia = s->inertia;
      return;
    }
  *mass = density * s->area;
  *inertia = density * s->unit_inertia;
}
