/* Time of impact with rotation: when the two pieces of a contact first
 * touch within the step, each body in free flight from where the step
 * begins (its centre on the parabola of uniform gravity, its angle turning
 * at its spin), and where each body is then. */
#ifndef CAROM_TOI_H
#define CAROM_TOI_H

#include "contact.h"
#include "solver.h"
#include "step.h"

struct carom_world;

/* Where body slot `i` (solver body sb) is at time t into the step in free
 * flight: p + v t + g t^2 / 2 (g: gravity, for a dynamic body) and its
 * angle turned by w t; with `shift` (or NULL), the flight after the
 * impacts that shifted it (impact_shift). At t = 0 with no shift, exactly
 * its pose. */
xform toi_pose (const struct carom_world *world, int32_t i, const solver_body *sb, const step_context *ctx, double t,
                const impact_shift *shift);

/* The first time in (t_from, t_max] at which contact k's pieces touch in
 * free flight (their separation, contact_separation_at, falls to 0), the
 * bodies shifted by
 * shifts[slot] when shifts is not NULL; TOI_APART when
 * they stay apart until t_max; TOI_UNKNOWN when they already touch at
 * t_from, or the advancement ran out of trials. Conservative advancement
 * keeps every trial at or before the first touch; once a trial overlaps,
 * the touch is bracketed and found by regula falsi. With a touch, *axis
 * (when not NULL) is the axis that separated the pieces at the last trial
 * before it that found them clearly apart (contact_separation_at): the face
 * they closed on, where at the touch two faces may both be at 0 (corner to
 * corner). The vertex-edge method's whole outlines (piece_a = piece_b =
 * -1): a convex one is its single piece, whose separation the search
 * follows; a concave one is the union of its convex pieces, each pair
 * searched, the earliest touch theirs. The points of the touch still come
 * from the world's narrow phase (contact_collide_at). */
/* How long from now two polygon pieces cannot touch in free flight, judged
 * on edge `edge` of the reference piece `ref` (its body at xr, moving at
 * vr, spinning at wr) turning with its body: the first time a vertex of
 * `inc` (its body at xi, vi, wi) could reach that edge's line, or INFINITY
 * when none can within `span`; 0 when one is not beyond it now. dg bounds
 * the two bodies' relative acceleration (gravity). lib/toi.c, face_time,
 * has the bound. */
double toi_face_clear (const convex_piece *ref, int32_t edge, xform xr, vec2 vr, double wr, const convex_piece *inc,
                       xform xi, vec2 vi, double wi, double dg, double span);

/* Touching: a separation below this fraction of the pair's slop (near the
 * rounding of the coordinates). */
#define TOI_TOUCH 1e-12
#define TOI_APART (-1.0)
#define TOI_UNKNOWN (-2.0)
double toi_first_touch (const struct carom_world *world, const contact *k, const solver_body *a,
                        const solver_body *b, const step_context *ctx, double t_from, double t_max,
                        const impact_shift *shifts, vec2 *axis);

#endif
