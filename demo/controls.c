/* Key and mouse bindings. */
#include "controls.h"

#include <stdio.h>

#include <gdk/gdkkeysyms.h>
#include <glib.h>

/* Number keys 1-9 and 0 pick a scene from the table, n and p the next and
 * the previous one (wrapping round; from a file of the user's, the first
 * and the last). */
static controls_result controls_scene (demo *d, int index)
{
  const scene_entry *e = scenes_get (index);
  char *path;
  int ok;
  if (!e)
    return CONTROLS_HANDLED;
  path = scenes_path (e);
  ok = demo_load (d, e, path);
  g_free (path);
  return ok ? CONTROLS_SCENE : CONTROLS_HANDLED;
}

static controls_result controls_next_scene (demo *d, int step)
{
  int n = scenes_count (), i;
  for (i = 0; i < n && scenes_get (i) != d->entry; ++i)
    ;
  if (i == n)
    i = step > 0 ? -1 : 0; /* not a table scene */
  return controls_scene (d, ((i + step) % n + n) % n);
}

controls_result controls_key (demo *d, unsigned keyval)
{
  switch (keyval)
    {
    case GDK_KEY_1: case GDK_KEY_KP_1: return controls_scene (d, 0);
    case GDK_KEY_2: case GDK_KEY_KP_2: return controls_scene (d, 1);
    case GDK_KEY_3: case GDK_KEY_KP_3: return controls_scene (d, 2);
    case GDK_KEY_4: case GDK_KEY_KP_4: return controls_scene (d, 3);
    case GDK_KEY_5: case GDK_KEY_KP_5: return controls_scene (d, 4);
    case GDK_KEY_6: case GDK_KEY_KP_6: return controls_scene (d, 5);
    case GDK_KEY_7: case GDK_KEY_KP_7: return controls_scene (d, 6);
    case GDK_KEY_8: case GDK_KEY_KP_8: return controls_scene (d, 7);
    case GDK_KEY_9: case GDK_KEY_KP_9: return controls_scene (d, 8);
    case GDK_KEY_0: case GDK_KEY_KP_0: return controls_scene (d, 9);
    case GDK_KEY_n: case GDK_KEY_N: return controls_next_scene (d, 1);
    case GDK_KEY_p: case GDK_KEY_P: return controls_next_scene (d, -1);
    case GDK_KEY_Up:
      demo_change_gravity (d, 0.0, DEMO_GRAVITY_STEP);
      break;
    case GDK_KEY_Down:
      demo_change_gravity (d, 0.0, -DEMO_GRAVITY_STEP);
      break;
    case GDK_KEY_Left:
      demo_change_gravity (d, -DEMO_GRAVITY_STEP, 0.0);
      break;
    case GDK_KEY_Right:
      demo_change_gravity (d, DEMO_GRAVITY_STEP, 0.0);
      break;
    case GDK_KEY_g: case GDK_KEY_G:
      d->show_gravity = !d->show_gravity;
      d->gravity_until = 0.0;
      break;
    case GDK_KEY_plus: case GDK_KEY_equal: case GDK_KEY_KP_Add: case GDK_KEY_Page_Up:
      demo_change_restitution (d, DEMO_RESTITUTION_STEP);
      break;
    case GDK_KEY_minus: case GDK_KEY_underscore: case GDK_KEY_KP_Subtract: case GDK_KEY_Page_Down:
      demo_change_restitution (d, -DEMO_RESTITUTION_STEP);
      break;
    case GDK_KEY_space:
      d->paused = !d->paused;
      break;
    case GDK_KEY_period: case GDK_KEY_KP_Decimal:
      d->paused = 1;
      demo_update (d);
      break;
    case GDK_KEY_v: case GDK_KEY_V:
      d->opt.show_velocities = !d->opt.show_velocities;
      break;
    case GDK_KEY_c: case GDK_KEY_C:
      d->opt.show_contacts = !d->opt.show_contacts;
      break;
    case GDK_KEY_j: case GDK_KEY_J:
      d->opt.show_joints = !d->opt.show_joints;
      break;
    case GDK_KEY_f: case GDK_KEY_F:
      demo_toggle_effect (d, CAROM_EFFECT_FRICTION);
      break;
    case GDK_KEY_d: case GDK_KEY_D:
      demo_toggle_effect (d, CAROM_EFFECT_DAMPING);
      break;
    case GDK_KEY_s: case GDK_KEY_S:
      demo_toggle_effect (d, CAROM_EFFECT_SLEEPING);
      break;
    case GDK_KEY_o: case GDK_KEY_O:
      demo_toggle_effect (d, CAROM_EFFECT_CENTRAL_GRAVITY);
      break;
    case GDK_KEY_t: case GDK_KEY_T:
      demo_toggle_effect (d, CAROM_EFFECT_CONTINUOUS);
      break;
    case GDK_KEY_r: case GDK_KEY_R:
      return demo_restart (d) ? CONTROLS_SCENE : CONTROLS_HANDLED;
    case GDK_KEY_h: case GDK_KEY_H: case GDK_KEY_question: case GDK_KEY_F1:
      d->show_help = !d->show_help;
      break;
    case GDK_KEY_q: case GDK_KEY_Q: case GDK_KEY_Escape:
      return CONTROLS_QUIT;
    default:
      return CONTROLS_IGNORED;
    }
  return CONTROLS_HANDLED;
}

int controls_press (demo *d, double x, double y)
{
  double wx, wy;
  if (!d->entry)
    return 0;
  render_to_world (&d->opt, x, y, &wx, &wy);
  if (!grab_begin (&d->grab, d->stage.world, wx, wy, 2.0 * (d->opt.view_x1 - d->opt.view_x0)))
    return 0;
  if (d->verbose)
    {
      printf ("carom-demo: grab at %.3f %.3f\n", wx, wy);
      fflush (stdout);
    }
  return 1;
}

/* Move the held body's target to the pointer at screen (x, y); 0 when
 * nothing is held. The pointer's world position goes to *wx, *wy. While
 * paused the body stays where it is (nothing steps) and the picture shows
 * the joint's new pull. */
static int controls_drag (demo *d, double x, double y, double *wx, double *wy)
{
  if (!d->entry || d->grab.body == CAROM_NULL_BODY)
    return 0;
  render_to_world (&d->opt, x, y, wx, wy);
  grab_move (&d->grab, d->stage.world, *wx, *wy);
  return 1;
}

int controls_motion (demo *d, double x, double y)
{
  double wx, wy;
  return controls_drag (d, x, y, &wx, &wy);
}

int controls_release (demo *d, double x, double y)
{
  double wx, wy;
  if (!controls_drag (d, x, y, &wx, &wy))
    return 0;
  if (d->verbose)
    {
      double px = wx, py = wy;
      grab_point (&d->grab, d->stage.world, &px, &py);
      printf ("carom-demo: release at %.3f %.3f, the grabbed point at %.3f %.3f\n", wx, wy, px, py);
      fflush (stdout);
    }
  grab_end (&d->grab, d->stage.world);
  return 1;
}
