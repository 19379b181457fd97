/* Built by tests/test_install.sh against an installed carom, with the flags
 * that `pkg-config --cflags --libs carom` gives: a box falls for one second
 * under gravity (0, -10) from (0, 10). The integrator is exact for constant
 * gravity, so it prints "position 0.000000 5.000000". */
#include <carom.h>

#include <stdio.h>

#define CHECK(call)                                                            \
  do                                                                           \
    {                                                                          \
      carom_status check_status_ = (call);                                     \
      if (check_status_ != CAROM_OK)                                           \
        {                                                                      \
          fprintf (stderr, "%s: %s\n", #call,                                  \
                   carom_status_string (check_status_));                       \
          return 1;                                                            \
        }                                                                      \
    }                                                                          \
  while (0)

int main (void)
{
  carom_world_def wdef;
  carom_body_def bdef;
  carom_world *world = NULL;
  carom_body_id box = CAROM_NULL_BODY;
  double x = 0.0, y = 0.0;
  int i;

  printf ("header %d library %u\n", CAROM_VERSION, (unsigned) carom_version ());
  if (carom_version () / 10000 != CAROM_VERSION_MAJOR)
    {
      fprintf (stderr, "library major version differs from the header's\n");
      return 1;
    }

  carom_world_def_init (&wdef, sizeof wdef);
  wdef.gravity_y = -10.0;
  CHECK (carom_world_init (&world, &wdef));

  carom_body_def_init (&bdef, sizeof bdef);
  bdef.y = 10.0;
  CHECK (carom_world_add_box (world, &bdef, 1.0, 1.0, &box));
  for (i = 0; i < 10; ++i)
    CHECK (carom_world_update (world, 0.1));
  CHECK (carom_body_get_position (world, box, &x, &y));
  printf ("position %f %f\n", x, y);

  carom_world_destroy (world);
  return 0;
}
