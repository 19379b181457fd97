/* The joints' direct solve. A chain of light links holding a heavy weight,
 * solved one joint at a time, stretches: each pass moves the error a link
 * along, and the weight's pull is a hundred times what a link can pass on
 * in one pass. Solved all at once, the rigid rows of the joints (points,
 * angles, lines, lengths) are exact in every pass, whatever the masses.
 *
 * The joints whose dynamic bodies form a forest (no loop among the bodies,
 * and each tree at most one joint to the ground, static or kinematic
 * bodies, or the world) make a sparse symmetric system
 *
 *   [ M  J^T ] [ y ]   [  0 ]
 *   [ J   0  ] [ x ] = [ -r ]      so  J M^-1 J^T x = r,
 *
 * whose graph, with a node per body and per joint, is that forest. Each
 * tree is eliminated from its leaves to its root and solved back from the
 * root, block by block, without fill-in: linear time, exact to rounding
 * (Baraff, "Linear-time dynamics using Lagrange multipliers", 1996). A
 * joint that would close a loop is solved one at a time, as the other
 * constraints are. The tree is chosen once per update, in slot order, so
 * the result is deterministic. */
#include "joint.h"

#include <string.h>

#include "solver.h"
#include "world.h"

int joint_tree_reserve (carom_world *world)
{
  joint_tree *t = &world->joint_tree;
  int32_t s = world->slot_count, j = world->joints.count;
  if (world->joints.live == 0)
    return 1;
  return mem_reserve (&world->allocator, (void **) &t->nodes, &t->node_cap, s + j, sizeof (tree_node))
         && mem_reserve (&world->allocator, (void **) &t->scratch, &t->scratch_cap, 5 * s + 3 * j + 1,
                         sizeof (int32_t))
         && mem_reserve (&world->allocator, (void **) &t->group_time, &t->group_cap, s, sizeof (double));
}

void joint_tree_destroy (carom_world *world)
{
  joint_tree *t = &world->joint_tree;
  mem_free (&world->allocator, t->nodes, (size_t) t->node_cap * sizeof (tree_node));
  mem_free (&world->allocator, t->scratch, (size_t) t->scratch_cap * sizeof (int32_t));
  mem_free (&world->allocator, t->group_time, (size_t) t->group_cap * sizeof (double));
  memset (t, 0, sizeof *t);
}

/* ------------------------------------------------------------ set-up */

/* A body the direct solve moves: dynamic, awake, with mass and inertia. */
static int tree_body (const carom_world *world, int32_t slot)
{
  const solver_body *b = &world->solver_bodies[slot];
  return slot >= 0 && b->moves == MOVES_DYNAMIC && b->im > 0.0 && b->ii > 0.0;
}

/* The ground: the world, or a body nothing moves (static, kinematic,
 * asleep). */
static int ground (const carom_world *world, int32_t slot)
{
  return slot < 0 || world->solver_bodies[slot].moves != MOVES_DYNAMIC;
}

static int32_t find (int32_t *uf, int32_t i)
{
  while (uf[i] != i)
    {
      uf[i] = uf[uf[i]];
      i = uf[i];
    }
  return i;
}

static int32_t add_node (joint_tree *t, int32_t body, int32_t joint, int32_t parent)
{
  tree_node *n = &t->nodes[t->node_count];
  n->body = body, n->joint = joint, n->parent = parent;
  return t->node_count++;
}

void joint_tree_build (carom_world *world)
{
  joint_tree *t = &world->joint_tree;
  joints *js = &world->joints;
  int32_t s = world->slot_count, i, k;
  int32_t *uf = t->scratch, *pendant = uf + s, *start = pendant + s, *adj = start + s + 1, *body_node = adj + 2 * js->count;
  int32_t *queue = body_node + s; /* s + joints */
  t->node_count = 0;
  t->mixed = 0;
  t->factored = t->converged = 0;
  for (i = 0; i < s; ++i)
    uf[i] = i, pendant[i] = 0, start[i] = 0, body_node[i] = -1;
  start[s] = 0;
  /* which joints: in slot order, each that keeps the bodies a forest */
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      int ta, tb;
      j->tree = 0;
      j->node = -1;
      if (!j->alive || joint_row_count (j) == 0)
        continue;
      ta = tree_body (world, j->a);
      tb = tree_body (world, j->b);
      if (!(ta || ground (world, j->a)) || !(tb || ground (world, j->b)) || !(ta || tb))
        continue;
      if (ta && tb)
        {
          int32_t ra = find (uf, j->a), rb = find (uf, j->b);
          if (ra == rb || (pendant[ra] && pendant[rb]))
            continue;
          uf[ra] = rb;
          if (!pendant[rb])
            pendant[rb] = pendant[ra];
        }
      else
        {
          int32_t r = find (uf, ta ? j->a : j->b);
          if (pendant[r])
            continue;
          pendant[r] = i + 1;
        }
      j->tree = 1;
      t->mixed |= j->enable_limit || j->enable_motor || j->enable_spring;
      if (ta)
        start[j->a]++;
      if (tb)
        start[j->b]++;
    }
  /* each body's tree joints, as offsets into adj */
  for (i = 0, k = 0; i <= s; ++i)
    {
      int32_t n = i < s ? start[i] : 0;
      start[i] = k;
      k += n;
    }
  for (i = 0; i < s; ++i)
    body_node[i] = start[i]; /* where the next of its joints goes */
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      if (!j->tree)
        continue;
      if (tree_body (world, j->a))
        adj[body_node[j->a]++] = i;
      if (tree_body (world, j->b))
        adj[body_node[j->b]++] = i;
    }
  for (i = 0; i < s; ++i)
    body_node[i] = -1;
  /* breadth first from each tree's root: its joint to the ground, else
   * the first body met */
  for (i = 0; i < js->count; ++i)
    {
      joint *j = &js->list[i];
      int32_t head, tail = 0, root, r;
      if (!j->tree || j->node >= 0)
        continue;
      r = find (uf, tree_body (world, j->a) ? j->a : j->b);
      head = 0;
      if (pendant[r] > 0)
        {
          joint *p = &js->list[pendant[r] - 1];
          p->node = add_node (t, -1, pendant[r] - 1, -1);
          queue[tail++] = -(pendant[r] - 1) - 1;
        }
      else
        {
          root = tree_body (world, j->a) ? j->a : j->b;
          body_node[root] = add_node (t, root, -1, -1);
          queue[tail++] = root;
        }
      while (head < tail)
        {
          int32_t q = queue[head++];
          if (q >= 0)
            {
              /* a body: its joints other than its parent */
              for (k = start[q]; k < start[q + 1]; ++k)
                {
                  joint *c = &js->list[adj[k]];
                  if (c->node >= 0)
                    continue;
                  c->node = add_node (t, -1, adj[k], body_node[q]);
                  queue[tail++] = -adj[k] - 1;
                }
            }
          else
            {
              /* a joint: its bodies other than its parent */
              joint *c = &js->list[-q - 1];
              int32_t side;
              for (side = 0; side < 2; ++side)
                {
                  int32_t b = side ? c->b : c->a;
                  if (!tree_body (world, b) || body_node[b] >= 0)
                    continue;
                  body_node[b] = add_node (t, b, -1, c->node);
                  queue[tail++] = b;
                }
            }
        }
    }
}

/* -------------------------------------------------------- 3 x 3 blocks */

/* The blocks are 3 x 3, row-major, of which a node's first `rows` rows
 * are used (a body has 3: x, y, angle; a joint its row count), and against
 * its parent the parent's first rows columns. Each kernel comes in one
 * version per pair of sizes, so that every loop has constant bounds. */

/* c = a b, a n x n, b n x m */
#define DEFINE_MUL(n, m)                                                      \
  static void mul_##n##m (const double *a, const double *b, double *c)        \
  {                                                                           \
    int r, k, q;                                                              \
    for (r = 0; r < n; ++r)                                                   \
      for (k = 0; k < m; ++k)                                                 \
        {                                                                     \
          double sum = 0.0;                                                   \
          for (q = 0; q < n; ++q)                                             \
            sum += a[3 * r + q] * b[3 * q + k];                               \
          c[3 * r + k] = sum;                                                 \
        }                                                                     \
  }
/* d -= a^T b, a and b n x m, d m x m */
#define DEFINE_SUB_TMUL(n, m)                                                 \
  static void sub_tmul_##n##m (double *d, const double *a, const double *b)   \
  {                                                                           \
    int r, k, q;                                                              \
    for (r = 0; r < m; ++r)                                                   \
      for (k = 0; k < m; ++k)                                                 \
        {                                                                     \
          double sum = 0.0;                                                   \
          for (q = 0; q < n; ++q)                                             \
            sum += a[3 * q + r] * b[3 * q + k];                               \
          d[3 * r + k] -= sum;                                                \
        }                                                                     \
  }
/* xp -= l^T x (l n x m), then, down: x = d x - l xp */
#define DEFINE_UP(n, m)                                                       \
  static void up_##n##m (const double *l, const double *x, double *xp)        \
  {                                                                           \
    int r, q;                                                                 \
    for (r = 0; r < m; ++r)                                                   \
      {                                                                       \
        double sum = 0.0;                                                     \
        for (q = 0; q < n; ++q)                                               \
          sum += l[3 * q + r] * x[q];                                         \
        xp[r] -= sum;                                                         \
      }                                                                       \
  }
#define DEFINE_DOWN(n, m)                                                     \
  static void down_##n##m (const double *d, const double *l, double *x,       \
                           const double *xp)                                  \
  {                                                                           \
    double y[3];                                                              \
    int r, q;                                                                 \
    for (r = 0; r < n; ++r)                                                   \
      {                                                                       \
        double sum = 0.0;                                                     \
        for (q = 0; q < n; ++q)                                               \
          sum += d[3 * r + q] * x[q];                                         \
        for (q = 0; q < m; ++q)                                               \
          sum -= l[3 * r + q] * xp[q];                                        \
        y[r] = sum;                                                           \
      }                                                                       \
    for (r = 0; r < n; ++r)                                                   \
      x[r] = y[r];                                                            \
  }
#define DEFINE_KERNELS(n, m) DEFINE_MUL (n, m) DEFINE_SUB_TMUL (n, m) DEFINE_UP (n, m) DEFINE_DOWN (n, m)
DEFINE_KERNELS (1, 3)
DEFINE_KERNELS (3, 3)
DEFINE_KERNELS (3, 1)
/* (the roots need only the way down) */
DEFINE_DOWN (3, 0)
DEFINE_DOWN (1, 0)
DEFINE_DOWN (2, 0)

/* The pairs of a chain of revolute joints, a body (3) under a joint (2)
 * and a joint under a body, written out: most nodes are one of them. */
static void mul_32 (const double *a, const double *b, double *c)
{
  double b0 = b[0], b1 = b[1], b3 = b[3], b4 = b[4], b6 = b[6], b7 = b[7];
  c[0] = a[0] * b0 + a[1] * b3 + a[2] * b6, c[1] = a[0] * b1 + a[1] * b4 + a[2] * b7;
  c[3] = a[3] * b0 + a[4] * b3 + a[5] * b6, c[4] = a[3] * b1 + a[4] * b4 + a[5] * b7;
  c[6] = a[6] * b0 + a[7] * b3 + a[8] * b6, c[7] = a[6] * b1 + a[7] * b4 + a[8] * b7;
}

static void sub_tmul_32 (double *d, const double *a, const double *b)
{
  d[0] -= a[0] * b[0] + a[3] * b[3] + a[6] * b[6];
  d[1] -= a[0] * b[1] + a[3] * b[4] + a[6] * b[7];
  d[3] -= a[1] * b[0] + a[4] * b[3] + a[7] * b[6];
  d[4] -= a[1] * b[1] + a[4] * b[4] + a[7] * b[7];
}

static void up_32 (const double *l, const double *x, double *xp)
{
  xp[0] -= l[0] * x[0] + l[3] * x[1] + l[6] * x[2];
  xp[1] -= l[1] * x[0] + l[4] * x[1] + l[7] * x[2];
}

static void down_32 (const double *d, const double *l, double *x, const double *xp)
{
  double x0 = x[0], x1 = x[1], x2 = x[2];
  x[0] = d[0] * x0 + d[1] * x1 + d[2] * x2 - (l[0] * xp[0] + l[1] * xp[1]);
  x[1] = d[3] * x0 + d[4] * x1 + d[5] * x2 - (l[3] * xp[0] + l[4] * xp[1]);
  x[2] = d[6] * x0 + d[7] * x1 + d[8] * x2 - (l[6] * xp[0] + l[7] * xp[1]);
}

static void mul_23 (const double *a, const double *b, double *c)
{
  c[0] = a[0] * b[0] + a[1] * b[3], c[1] = a[0] * b[1] + a[1] * b[4], c[2] = a[0] * b[2] + a[1] * b[5];
  c[3] = a[3] * b[0] + a[4] * b[3], c[4] = a[3] * b[1] + a[4] * b[4], c[5] = a[3] * b[2] + a[4] * b[5];
}

static void sub_tmul_23 (double *d, const double *a, const double *b)
{
  double a0 = a[0], a1 = a[1], a2 = a[2], a3 = a[3], a4 = a[4], a5 = a[5];
  double b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3], b4 = b[4], b5 = b[5];
  d[0] -= a0 * b0 + a3 * b3, d[1] -= a0 * b1 + a3 * b4, d[2] -= a0 * b2 + a3 * b5;
  d[3] -= a1 * b0 + a4 * b3, d[4] -= a1 * b1 + a4 * b4, d[5] -= a1 * b2 + a4 * b5;
  d[6] -= a2 * b0 + a5 * b3, d[7] -= a2 * b1 + a5 * b4, d[8] -= a2 * b2 + a5 * b5;
}

static void up_23 (const double *l, const double *x, double *xp)
{
  xp[0] -= l[0] * x[0] + l[3] * x[1];
  xp[1] -= l[1] * x[0] + l[4] * x[1];
  xp[2] -= l[2] * x[0] + l[5] * x[1];
}

static void down_23 (const double *d, const double *l, double *x, const double *xp)
{
  double x0 = x[0], x1 = x[1];
  x[0] = d[0] * x0 + d[1] * x1 - (l[0] * xp[0] + l[1] * xp[1] + l[2] * xp[2]);
  x[1] = d[3] * x0 + d[4] * x1 - (l[3] * xp[0] + l[4] * xp[1] + l[5] * xp[2]);
}

/* The eliminating of a node into its parent (m 0: a root) */
static void eliminate (tree_node *n, tree_node *p)
{
  switch (4 * n->rows + (p ? p->rows : 0))
    {
    case 4 * 1 + 3: mul_13 (n->d, n->h, n->l), sub_tmul_13 (p->d, n->h, n->l); break;
    case 4 * 2 + 3: mul_23 (n->d, n->h, n->l), sub_tmul_23 (p->d, n->h, n->l); break;
    case 4 * 3 + 3: mul_33 (n->d, n->h, n->l), sub_tmul_33 (p->d, n->h, n->l); break;
    case 4 * 3 + 1: mul_31 (n->d, n->h, n->l), sub_tmul_31 (p->d, n->h, n->l); break;
    case 4 * 3 + 2: mul_32 (n->d, n->h, n->l), sub_tmul_32 (p->d, n->h, n->l); break;
    default: break; /* a root */
    }
}

/* x of the parent -= l^T x (on the way up) */
static void substitute_up (const tree_node *n, tree_node *p)
{
  switch (4 * n->rows + p->rows)
    {
    case 4 * 1 + 3: up_13 (n->l, n->x, p->x); break;
    case 4 * 2 + 3: up_23 (n->l, n->x, p->x); break;
    case 4 * 3 + 3: up_33 (n->l, n->x, p->x); break;
    case 4 * 3 + 1: up_31 (n->l, n->x, p->x); break;
    case 4 * 3 + 2: up_32 (n->l, n->x, p->x); break;
    default: break;
    }
}

/* x = d x - l x of the parent (on the way down; none at a root) */
static void substitute_down (tree_node *n, const tree_node *p)
{
  static const double none[3] = {0.0, 0.0, 0.0};
  switch (4 * n->rows + (p ? p->rows : 0))
    {
    case 4 * 1 + 3: down_13 (n->d, n->l, n->x, p->x); break;
    case 4 * 2 + 3: down_23 (n->d, n->l, n->x, p->x); break;
    case 4 * 3 + 3: down_33 (n->d, n->l, n->x, p->x); break;
    case 4 * 3 + 1: down_31 (n->d, n->l, n->x, p->x); break;
    case 4 * 3 + 2: down_32 (n->d, n->l, n->x, p->x); break;
    case 4 * 3: down_30 (n->d, n->l, n->x, none); break;
    case 4 * 2: down_20 (n->d, n->l, n->x, none); break;
    case 4 * 1: down_10 (n->d, n->l, n->x, none); break;
    default: break;
    }
}

/* A power of two near the largest of the n x n block's entries when that
 * is far from 1, else 1 (exact to divide by): a joint's rows hold lever
 * arms, and the determinant of the unscaled block is up to their sixth
 * power, which leaves the doubles long before the block itself does. 0
 * for a block of zeros or of a number that is not finite. The pivot
 * blocks are definite (a body's positive: its mass plus what its children
 * hold; a joint's negative: minus its rows' effective inverse mass), so
 * their largest entry is on the diagonal. */
static double scale_of (const double *m, int n)
{
  double big = 0.0;
  int r, exponent;
  for (r = 0; r < n; ++r)
    big = fabs (m[4 * r]) > big ? fabs (m[4 * r]) : big;
  if (!(big > 0.0) || !isfinite (big))
    return 0.0;
  if (big <= 1e100 && big >= 1e-100)
    return 1.0;
  frexp (big, &exponent);
  return ldexp (1.0, exponent);
}

/* The inverse of the n x n block (n = 1, 2, 3; 0 where it is singular),
 * through the block divided by scale_of. */
static void invert (double *m, int n)
{
  double scale = scale_of (m, n), s, det;
  if (scale == 0.0)
    {
      memset (m, 0, 9 * sizeof *m);
      return;
    }
  s = 1.0 / scale;
  if (n == 1)
    m[0] = 1.0 / m[0];
  else if (n == 2)
    {
      double a = m[0] * s, b = m[1] * s, c = m[3] * s, d = m[4] * s;
      det = a * d - b * c;
      if (det != 0.0)
        det = s / det;
      m[0] = d * det, m[1] = -b * det, m[3] = -c * det, m[4] = a * det;
    }
  else
    {
      double a = m[0] * s, b = m[1] * s, c = m[2] * s, d = m[3] * s, e = m[4] * s, f = m[5] * s;
      double g = m[6] * s, h = m[7] * s, i = m[8] * s;
      double A = e * i - f * h, B = -(d * i - f * g), C = d * h - e * g;
      det = a * A + b * B + c * C;
      if (det != 0.0)
        det = s / det;
      m[0] = A * det, m[1] = -(b * i - c * h) * det, m[2] = (b * f - c * e) * det;
      m[3] = B * det, m[4] = (a * i - c * g) * det, m[5] = -(a * f - c * d) * det;
      m[6] = C * det, m[7] = -(a * h - b * g) * det, m[8] = (a * e - b * d) * det;
    }
}

/* ------------------------------------------------------------- a pass */

/* The joint's block against the body in `slot`: its rows for a or b. */
static const double *joint_block (const joint *j, int32_t slot)
{
  return slot == j->b ? j->jb : j->ja;
}

/* Factor the system of the rows in j->ja, j->jb: each node's pivot
 * block inverted (d) and its block against its parent over that (l),
 * leaves up (children come after their parents). */
static void factor (joint_tree *t)
{
  int32_t i;
  for (i = t->node_count - 1; i >= 0; --i)
    {
      tree_node *n = &t->nodes[i];
      invert (n->d, n->rows);
      eliminate (n, n->parent >= 0 ? &t->nodes[n->parent] : NULL);
    }
}

/* Solve the factored system for the right-hand side in each node's x:
 * leaves up, then back down from the roots. */
static void substitute (joint_tree *t)
{
  int32_t i;
  for (i = t->node_count - 1; i >= 0; --i)
    if (t->nodes[i].parent >= 0)
      substitute_up (&t->nodes[i], &t->nodes[t->nodes[i].parent]);
  for (i = 0; i < t->node_count; ++i)
    substitute_down (&t->nodes[i], t->nodes[i].parent >= 0 ? &t->nodes[t->nodes[i].parent] : NULL);
}

/* The projection corrects at most a body's size of a point's error and
 * MAX_PROJECTION_TURN of an angle's per pass (as Box2D v2's position
 * solver bounds its corrections): an error that large comes from a body
 * placed by hand or from forces beyond any joint's hold, and corrected at
 * once it would fling the bodies. */
#define MAX_PROJECTION_TURN 0.5

/* The smaller size of the joint's bodies (the dynamic one's, to the world). */
static double joint_reach (const carom_world *world, const joint *j)
{
  double sb = world->bodies[j->b].shape.size;
  if (j->a < 0)
    return sb;
  return world->bodies[j->a].shape.size < sb ? world->bodies[j->a].shape.size : sb;
}

/* Whether a row (its entries ja, jb for the two bodies) is an angle's: it
 * moves no point (its linear entries 0 on both bodies). */
static int angle_row (const double *ja, const double *jb)
{
  return ja[0] == 0.0 && ja[1] == 0.0 && jb[0] == 0.0 && jb[1] == 0.0;
}

/* A row's error within those bounds. */
static double clamp_error (double c, const double *ja, const double *jb, double reach)
{
  double max = angle_row (ja, jb) ? MAX_PROJECTION_TURN : reach;
  return c < -max ? -max : c > max ? max : c;
}

/* Each joint's rows where the bodies are now, and the system's blocks
 * from them, factored: K = J M^-1 J^T for the passes that follow. With
 * `errors`, each joint node's right-hand side is its rows' position error
 * there as well, as load (world, 1) would make it from the same rows. */
static void refactor (carom_world *world, int errors)
{
  joint_tree *t = &world->joint_tree;
  joints *js = &world->joints;
  const solver_body *sb = world->solver_bodies;
  int32_t i, r, k;
  for (i = 0; i < t->node_count; ++i)
    {
      tree_node *n = &t->nodes[i];
      memset (n->d, 0, sizeof n->d);
      if (n->joint >= 0)
        {
          joint *j = &js->list[n->joint];
          double c[3];
          /* (rows past its count are never written: 0 since its creation) */
          joint_rows (j, &sb[j->a < 0 ? world->slot_count : j->a], &sb[j->b], j->ja, j->jb, c);
          n->rows = joint_row_count (j);
          if (errors)
            {
              double reach = joint_reach (world, j);
              n->x[0] = n->x[1] = n->x[2] = 0.0;
              for (r = 0; r < n->rows; ++r)
                n->x[r] = clamp_error (c[r], j->ja + 3 * r, j->jb + 3 * r, reach);
            }
          if (n->parent >= 0)
            memcpy (n->h, joint_block (j, t->nodes[n->parent].body), sizeof n->h);
        }
      else
        {
          const solver_body *b = &sb[n->body];
          n->rows = 3;
          n->x[0] = n->x[1] = n->x[2] = 0.0;
          n->d[0] = n->d[4] = 1.0 / b->im;
          n->d[8] = 1.0 / b->ii;
          if (n->parent >= 0)
            {
              /* the transpose of the parent joint's block for this body */
              const double *jb = joint_block (&js->list[t->nodes[n->parent].joint], n->body);
              for (r = 0; r < 3; ++r)
                for (k = 0; k < 3; ++k)
                  n->h[3 * r + k] = jb[3 * k + r];
            }
        }
    }
  factor (t);
  t->factored = 1;
}

/* The right-hand side of each joint node: its rows' velocity error J v
 * (with the factored rows), or their position error C where the bodies
 * are now, within the projection's bounds; 0 at the bodies. The solution
 * at a joint node is then x = -K^-1 J v (or -K^-1 C), and at each body
 * M^-1 J^T x, what x does to it. */
static void load (carom_world *world, int position)
{
  joint_tree *t = &world->joint_tree;
  joints *js = &world->joints;
  const solver_body *sb = world->solver_bodies;
  int32_t i, r;
  for (i = 0; i < t->node_count; ++i)
    {
      tree_node *n = &t->nodes[i];
      n->x[0] = n->x[1] = n->x[2] = 0.0;
      if (n->joint >= 0)
        {
          joint *j = &js->list[n->joint];
          const solver_body *A = &sb[j->a < 0 ? world->slot_count : j->a], *B = &sb[j->b];
          double c[3] = {0.0, 0.0, 0.0}, ja[9], jb[9];
          if (position)
            {
              double reach = joint_reach (world, j);
              joint_rows (j, A, B, ja, jb, c); /* the error now; the factored rows stay */
              for (r = 0; r < n->rows; ++r)
                n->x[r] = clamp_error (c[r], j->ja + 3 * r, j->jb + 3 * r, reach);
            }
          else
            for (r = 0; r < n->rows; ++r)
              {
                const double *a = j->ja + 3 * r, *b = j->jb + 3 * r;
                n->x[r] = a[0] * A->v.x + a[1] * A->v.y + a[2] * A->w + b[0] * B->v.x + b[1] * B->v.y
                          + b[2] * B->w;
              }
        }
    }
}

/* J^T x of a joint node for its body a (pa) and b (pb) */
static void joint_push (const joint *j, const tree_node *n, double *pa, double *pb)
{
  /* rows past the count are 0 in the joint and in x */
  const double *a = j->ja, *b = j->jb, *x = n->x;
  int k;
  for (k = 0; k < 3; ++k)
    {
      pa[k] = a[k] * x[0] + a[3 + k] * x[1] + a[6 + k] * x[2];
      pb[k] = b[k] * x[0] + b[3 + k] * x[1] + b[6 + k] * x[2];
    }
}

void joint_tree_solve (carom_world *world)
{
  joint_tree *t = &world->joint_tree;
  joints *js = &world->joints;
  solver_body *sb = world->solver_bodies;
  int32_t i;
  if (t->node_count == 0)
    return;
  if (!t->factored)
    refactor (world, 0);
  load (world, 0);
  substitute (t);
  /* x = -K^-1 J v: the impulses that zero every row's velocity error at
   * once */
  for (i = 0; i < t->node_count; ++i)
    {
      tree_node *n = &t->nodes[i];
      joint *j;
      solver_body *A, *B;
      double pa[3], pb[3];
      if (n->joint < 0)
        continue;
      j = &js->list[n->joint];
      A = &sb[j->a < 0 ? world->slot_count : j->a];
      B = &sb[j->b];
      joint_push (j, n, pa, pb);
      {
        vec2 va = v2 (A->v.x + A->im * pa[0], A->v.y + A->im * pa[1]);
        vec2 vb = v2 (B->v.x + B->im * pb[0], B->v.y + B->im * pb[1]);
        double wa = A->w + A->ii * pa[2], wb = B->w + B->ii * pb[2];
        if (!joint_motion_sane (va, wa, A->dp, A->da) || !joint_motion_sane (vb, wb, B->dp, B->da))
          continue; /* beyond the doubles: this joint holds nothing this pass */
        A->v = va, A->w = wa;
        B->v = vb, B->w = wb;
      }
      joint_rows_add (j, n->x);
    }
}

/* What a projection changes of a body: its velocities and its motion
 * since the step began. */
typedef struct moved {
  vec2 v, dp;
  double w, da;
  rot2 dq;
} moved;

/* Body b moved by M^-1 p (p = J^T x), with the velocity of that move over
 * the sub-step; its rotation turned by the small angle first order,
 * renormalised, as the sub-step's move does (solver.c). */
static moved displaced (const solver_body *b, const double *p, double inv_h)
{
  double dx = b->im * p[0], dy = b->im * p[1], a = b->ii * p[2], c, s, n;
  moved m;
  m.v = b->v, m.dp = b->dp, m.w = b->w, m.da = b->da, m.dq = b->dq;
  if (b->im == 0.0 && b->ii == 0.0)
    return m;
  m.dp.x += dx, m.dp.y += dy;
  c = m.dq.c - a * m.dq.s, s = m.dq.s + a * m.dq.c, n = 1.0 / sqrt (c * c + s * s);
  m.dq.c = c * n, m.dq.s = s * n;
  m.da += a;
  m.v.x += dx * inv_h, m.v.y += dy * inv_h;
  m.w += a * inv_h;
  return m;
}

static void take (solver_body *b, const moved *m)
{
  b->v = m->v, b->dp = m->dp, b->w = m->w, b->da = m->da, b->dq = m->dq;
}

static void project (carom_world *world, const step_context *ctx, int loaded)
{
  joint_tree *t = &world->joint_tree;
  joints *js = &world->joints;
  solver_body *sb = world->solver_bodies;
  int32_t i;
  if (!loaded)
    load (world, 1);
  substitute (t);
  for (i = 0; i < t->node_count; ++i)
    {
      tree_node *n = &t->nodes[i];
      joint *j;
      double pa[3], pb[3];
      if (n->joint < 0)
        continue;
      j = &js->list[n->joint];
      joint_push (j, n, pa, pb);
      {
        solver_body *A = &sb[j->a < 0 ? world->slot_count : j->a], *B = &sb[j->b];
        moved a = displaced (A, pa, ctx->inv_h), b = displaced (B, pb, ctx->inv_h);
        if (joint_motion_sane (a.v, a.w, a.dp, a.da) && joint_motion_sane (b.v, b.w, b.dp, b.da))
          take (A, &a), take (B, &b);
      }
    }
}

/* The projection's Newton passes go on while some row's error where the
 * bodies are now is more than this fraction of its joint's reach (an
 * angle's: this many radians), at most JOINT_NEWTON_PASSES. A further pass
 * would remove less than any measure of a joint resolves, a few thousand
 * roundings of a coordinate: in the benchmarks' chains the first Newton
 * pass leaves 2e-11 m on average (of 0.25 m links) and a second would leave
 * 1e-14; a chain that snaps taut, its links whipping round within the
 * sub-step, takes more. */
#define JOINT_PROJECT_TOLERANCE 1e-10
#define JOINT_NEWTON_PASSES 8

/* Whether every row of the tree's joints is within JOINT_PROJECT_TOLERANCE
 * where the bodies are now (the factored rows stay). */
static int projected (carom_world *world)
{
  joint_tree *t = &world->joint_tree;
  joints *js = &world->joints;
  const solver_body *sb = world->solver_bodies;
  int32_t i, r;
  for (i = 0; i < t->node_count; ++i)
    {
      const tree_node *n = &t->nodes[i];
      joint *j;
      double c[3] = {0.0, 0.0, 0.0}, ja[9], jb[9], reach;
      if (n->joint < 0)
        continue;
      j = &js->list[n->joint];
      joint_rows (j, &sb[j->a < 0 ? world->slot_count : j->a], &sb[j->b], ja, jb, c);
      reach = joint_reach (world, j);
      for (r = 0; r < n->rows; ++r)
        if (!(fabs (c[r]) <= (angle_row (ja + 3 * r, jb + 3 * r) ? 1.0 : reach) * JOINT_PROJECT_TOLERANCE))
          return 0;
    }
  return 1;
}

/* x = -K^-1 C: the displacements that remove every row's position error
 * at once, to first order. The bodies take the velocity of that move as
 * well, as in position-based dynamics and RATTLE: a taut chain's tension
 * then acts on its sideways waves within the sub-step, which keeps them
 * stable (moved without it, a chain holding a heavy weight zigzags apart);
 * the relax pass that follows removes what of it the joints forbid. The
 * first pass goes along the rows of the sub-step's start (RATTLE's
 * direction, which keeps a swing's energy: the solve pass's factors), the
 * next along the rows where the last left the bodies (Newton's, which
 * removes what the first left, also when the bodies turned fast within the
 * sub-step), until every row is within JOINT_PROJECT_TOLERANCE: one Newton
 * pass in a swinging chain, several where a chain snaps taut. Two, always,
 * let the heavy chain of tests/test_joints.c stretch up to 14% of its
 * length at the snap (2.3% on average over 256 starts a millionth of a
 * radian apart); passes until within the tolerance, 0.33% at most, for 16%
 * fewer instructions in the benchmarks' chains. The relax
 * pass, and once the passes converged the next sub-step's solve pass too,
 * reuse the last factors: Newton's passes converge quadratically, so the
 * last one, which left every row within the tolerance, corrected at most
 * about its square root (1e-5 of a size, 1e-6 m on average in the
 * benchmarks' chains), far less than the sub-step moved the bodies. A
 * solve pass that reused the factors of before the move, as a chain snaps
 * taut, let it stretch; after a projection that did not converge (eight
 * passes) the next sub-step factors afresh. Reused so, the heavy chain's
 * 256 starts stretch 0.18% at most (0.33% factoring every sub-step), and the
 * benchmarks' chains take 9% fewer instructions again. */
void joint_tree_project (carom_world *world, const step_context *ctx)
{
  joint_tree *t = &world->joint_tree;
  int pass;
  if (t->node_count == 0)
    return;
  if (!t->factored)
    refactor (world, 0);
  project (world, ctx, 0);
  t->converged = 0;
  for (pass = 0; pass < JOINT_NEWTON_PASSES && !(t->converged = pass > 0 && projected (world)); ++pass)
    {
      /* the rows where the bodies are now give the errors too */
      refactor (world, 1);
      project (world, ctx, 1);
    }
}

void joint_tree_next_substep (carom_world *world)
{
  joint_tree *t = &world->joint_tree;
  if (!t->converged)
    t->factored = 0;
  t->converged = 0;
}
