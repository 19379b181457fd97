"""Tests of the Python binding on the real shared library (CAROM_LIBRARY).

Run from the repository: make check-python (or CAROM_LIBRARY=build/libcarom.so.0
python3 -m pytest bindings/python/tests).
"""

import ctypes
import math
import os
import re

import pytest

import carom
from carom import _native

HEADER = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                      os.pardir, os.pardir, os.pardir, "include", "carom.h")

SCENE = """\
gravity 0 -10
box 1 1 at 0 2
bounds -5 0 5 10
"""


# ------------------------------------------------------------- the binding

@pytest.mark.skipif(not os.environ.get("CAROM_TEST_INSTALLED"), reason="not the installed wheel")
def test_the_installed_package_loads_its_own_library():
    # pip built the C library into the package: nothing else is needed
    here = os.path.dirname(os.path.abspath(carom.__file__))
    assert os.path.dirname(os.path.abspath(carom.library_path)) == here
    assert os.path.basename(carom.library_path).startswith("_libcarom")
    assert not os.path.abspath(carom.__file__).startswith(os.path.abspath(
        os.path.join(os.path.dirname(__file__), os.pardir)) + os.sep)
    assert carom.__version__ == "%d.%d.%d" % carom.library_version


def test_library_major_version_matches():
    assert carom.library_version[0] == _native.EXPECTED_MAJOR
    assert _native.lib.carom_version() == (
        carom.library_version[0] * 10000 + carom.library_version[1] * 100
        + carom.library_version[2])


@pytest.mark.parametrize("init, cls", [
    (_native.lib.carom_world_def_init, _native.WorldDef),
    (_native.lib.carom_body_def_init, _native.BodyDef),
    (_native.lib.carom_shape_def_init, _native.ShapeDef),
    (_native.lib.carom_joint_def_init, _native.JointDef),
    (_native.lib.carom_debug_draw_init, _native.DebugDraw),
])
def test_struct_layouts_match_the_library(init, cls):
    # The library accepts exactly the sizes it knows: our layout's size must
    # be one of them, and one byte more (a newer caller) is refused without
    # writing past what we said.
    buf = ctypes.create_string_buffer(ctypes.sizeof(cls) + 16)
    assert init(buf, ctypes.sizeof(cls)) == 0
    assert ctypes.c_uint32.from_buffer(buf).value == ctypes.sizeof(cls)
    assert buf.raw[ctypes.sizeof(cls):] == b"\0" * 16
    assert init(buf, ctypes.sizeof(cls) + 8) == 14  # CAROM_ERR_BAD_STRUCT_SIZE


def test_struct_defaults_come_from_the_library():
    d = _native.new_def(_native.WorldDef)
    assert (d.substeps, d.iterations, d.position_correction, d.slop) == (4, 1, 0.2, 0.01)
    assert d.manifold_tolerance == 0.01
    b = _native.new_def(_native.BodyDef)
    assert (b.type, b.density, b.restitution, b.friction) == (0, 1.0, -1.0, -1.0)


@pytest.mark.skipif(not os.path.exists(HEADER), reason="no include/carom.h beside the binding")
def test_every_header_function_has_a_prototype():
    with open(HEADER) as f:
        declared = set(re.findall(r"^CAROM_API[^(]*?\b(carom_\w+)\s*\(", f.read(), re.M))
    assert declared, "no CAROM_API declarations found"
    assert declared == set(_native.PROTOTYPES)


def test_status_strings_come_from_the_library():
    assert carom.status_string(carom.Status.OK) == "ok"
    for status in carom.Status:
        assert carom.status_string(status)
    err = carom.CaromError(carom.Status.BAD_TIME_STEP)
    assert err.message == carom.status_string(carom.Status.BAD_TIME_STEP)
    assert "BAD_TIME_STEP" in str(err)
    assert carom.CaromError(99).status == 99  # a code from a newer library


# ------------------------------------------------------------------ worlds

def test_world_is_a_context_manager_and_closes_once():
    with carom.World() as world:
        world.add_circle(1.0)
        assert len(world) == 1
    assert world.closed
    world.close()  # again: harmless
    with pytest.raises(carom.ClosedWorldError):
        world.step(0.1)
    with pytest.raises(carom.ClosedWorldError):
        len(world)


def test_gravity_property():
    with carom.World(gravity=(1.0, -9.81)) as world:
        assert world.gravity == (1.0, -9.81)
        world.gravity = (0.0, -3.0)
        assert world.gravity == (0.0, -3.0)
        with pytest.raises(carom.CaromError) as e:
            world.gravity = (math.inf, 0.0)
        assert e.value.status == carom.Status.NOT_FINITE
        assert world.gravity == (0.0, -3.0)


def test_bad_world_settings():
    with pytest.raises(carom.CaromError) as e:
        carom.World(restitution=2.0)
    assert e.value.status == carom.Status.BAD_ARGUMENT
    with pytest.raises(carom.CaromError) as e:
        carom.World(substeps=0)
    assert e.value.status == carom.Status.BAD_ARGUMENT
    with carom.World(narrow_phase="vertex_edge", substeps=4) as world:
        world.step(0.01)


def test_free_fall_closed_form():
    # Half kick, drift, half kick integrates constant gravity exactly:
    # y(t) = y0 + vy0 t - g t^2 / 2, x(t) = x0 + vx0 t.
    g, dt, n = 9.81, 1.0 / 60.0, 120
    x0, y0, vx0, vy0 = 1.0, 100.0, 2.0, 5.0
    with carom.World(gravity=(0.0, -g)) as world:
        box = world.add_box(1.0, 2.0, x=x0, y=y0, vx=vx0, vy=vy0, spin=0.5)
        ball = world.add_circle(0.5, x=-50.0, y=y0)
        for _ in range(n):
            world.step(dt)
        t = n * dt
        x, y = box.position
        assert x == pytest.approx(x0 + vx0 * t, abs=1e-9)
        assert y == pytest.approx(y0 + vy0 * t - 0.5 * g * t * t, abs=1e-9)
        assert box.velocity == pytest.approx((vx0, vy0 - g * t), abs=1e-9)
        assert box.angle == pytest.approx(0.5 * t, abs=1e-12)
        assert box.spin == 0.5
        assert ball.position[1] == pytest.approx(y0 - 0.5 * g * t * t, abs=1e-9)


def test_elastic_collision_conserves_momentum_and_energy():
    # Two circles head on, e = 1, no gravity, no friction.
    with carom.World(restitution=1.0) as world:
        a = world.add_circle(0.5, x=-2.0, vx=3.0, density=1.0)
        b = world.add_circle(0.8, x=2.0, vx=-1.0, density=2.0)
        bodies = (a, b)

        def momentum():
            return tuple(sum(body.mass * body.velocity[k] for body in bodies) for k in (0, 1))

        def energy():
            return sum(0.5 * body.mass * (body.velocity[0] ** 2 + body.velocity[1] ** 2)
                       + 0.5 * body.inertia * body.spin ** 2 for body in bodies)

        p0, e0 = momentum(), energy()
        touched = False
        for _ in range(300):
            world.step(0.01)
            touched = touched or bool(world.contacts())
        assert touched, "the bodies never met"
        assert a.velocity[0] < 0 < b.velocity[0], "they did not bounce"
        p1, e1 = momentum(), energy()
        assert abs(p1[0] - p0[0]) <= 1e-12 * max(1.0, abs(p0[0]))
        assert abs(p1[1] - p0[1]) <= 1e-12
        assert abs(e1 - e0) <= 1e-9 * e0
        # and the outcome is the closed form of a 1D elastic collision
        m1, m2, u1, u2 = a.mass, b.mass, 3.0, -1.0
        v1 = ((m1 - m2) * u1 + 2 * m2 * u2) / (m1 + m2)
        v2 = ((m2 - m1) * u2 + 2 * m1 * u1) / (m1 + m2)
        assert a.velocity[0] == pytest.approx(v1, abs=1e-9)
        assert b.velocity[0] == pytest.approx(v2, abs=1e-9)


def test_contacts_and_detect():
    with carom.World() as world:
        floor = world.add_box(10.0, 1.0, y=-0.5, static=True)
        box = world.add_box(1.0, 1.0, y=0.49)
        contacts = world.detect()
        assert contacts
        for c in contacts:
            assert {c.a, c.b} == {floor, box}
            assert math.hypot(*c.normal) == pytest.approx(1.0)
            assert c.depth == pytest.approx(0.01, abs=1e-9)
            assert isinstance(c, carom.Contact)


# ------------------------------------------------------------------ bodies

def test_body_properties():
    with carom.World(restitution=0.25, friction=0.5) as world:
        box = world.add_box(2.0, 3.0, x=1.0, y=2.0, density=2.0, restitution=0.75)
        m = 2.0 * 6.0
        assert box.mass == pytest.approx(m)
        assert box.inertia == pytest.approx(m * (4.0 + 9.0) / 12.0)
        assert box.area == pytest.approx(6.0)
        assert box.shape == "polygon" and box.radius is None
        assert not box.is_static
        assert (box.restitution, box.friction) == (0.75, 0.5)
        assert sorted(box.vertices) == sorted([(0.0, 0.5), (2.0, 0.5), (2.0, 3.5), (0.0, 3.5)])

        box.position = (5.0, 6.0)
        box.angle = math.pi / 2
        box.velocity = (1.0, -1.0)
        box.spin = 2.0
        assert box.position == (5.0, 6.0)
        assert box.angle == math.pi / 2
        assert box.velocity == (1.0, -1.0)
        assert box.spin == 2.0
        xs = sorted(round(v[0], 12) for v in box.vertices)
        assert xs == [3.5, 3.5, 6.5, 6.5]  # rotated a quarter turn

        ball = world.add_circle(0.5, static=True)
        assert ball.is_static and ball.mass == 0.0 and ball.inertia == 0.0
        assert ball.shape == "circle" and ball.radius == 0.5 and ball.vertices == []
        assert ball.area == pytest.approx(math.pi * 0.25)
        with pytest.raises(carom.CaromError) as e:
            ball.velocity = (1.0, 0.0)
        assert e.value.status == carom.Status.STATIC_BODY

        hexagon = world.add_regular(6, 1.0)
        assert len(hexagon.vertices) == 6
        assert hexagon.area == pytest.approx(3 * math.sqrt(3) / 2)
        concave = world.add_polygon([(0, 0), (2, 0), (2, 2), (1, 1), (0, 2)], x=10.0, y=10.0)
        assert concave.area == pytest.approx(3.0)
        assert concave.position == (10.0, 10.0)

        assert world.bodies == [box, ball, hexagon, concave]
        assert len({box, ball, hexagon, concave}) == 4


@pytest.mark.parametrize("make, status", [
    (lambda w: w.add_circle(float("nan")), carom.Status.NOT_FINITE),
    (lambda w: w.add_circle(-1.0), carom.Status.BAD_SIZE),
    (lambda w: w.add_box(1.0, 0.0), carom.Status.BAD_SIZE),
    (lambda w: w.add_box(1.0, 1.0, density=0.0), carom.Status.BAD_DENSITY),
    (lambda w: w.add_box(1.0, 1.0, x=math.inf), carom.Status.NOT_FINITE),
    (lambda w: w.add_polygon([(0, 0), (1, 0)]), carom.Status.TOO_FEW_VERTICES),
    (lambda w: w.add_polygon([]), carom.Status.TOO_FEW_VERTICES),
    (lambda w: w.add_polygon([(0, 0), (1, 1), (1, 0), (0, 1)]), carom.Status.SELF_INTERSECTING),
    (lambda w: w.add_polygon([(0, 0), (1, 0), (2, 0)]), carom.Status.ZERO_AREA),
    (lambda w: w.add_regular(2, 1.0), carom.Status.TOO_FEW_VERTICES),
    (lambda w: w.add_regular(carom.MAX_POLYGON_VERTICES + 1, 1.0), carom.Status.TOO_MANY_VERTICES),
    (lambda w: w.step(0.0), carom.Status.BAD_TIME_STEP),
    (lambda w: w.step(-0.1), carom.Status.BAD_TIME_STEP),
    (lambda w: w.step(float("nan")), carom.Status.BAD_TIME_STEP),
])
def test_bad_input_raises_with_the_right_status(make, status):
    with carom.World() as world:
        with pytest.raises(carom.CaromError) as e:
            make(world)
        assert e.value.status == status
        assert carom.status_string(status) in e.value.message
        assert len(world) == 0  # nothing was created


def test_wrong_python_types_raise_type_error():
    with carom.World() as world:
        with pytest.raises(TypeError):
            world.add_circle("big")
        with pytest.raises(TypeError):
            world.add_polygon([(0, 0), (1,), (1, 1)])
        with pytest.raises(TypeError):
            world.add_regular(3.5, 1.0)


def test_removed_body_handle_raises():
    with carom.World() as world:
        a = world.add_circle(1.0)
        b = world.add_circle(1.0, x=5.0)
        assert a.is_alive
        a.remove()
        assert not a.is_alive
        assert world.bodies == [b]
        for use in (lambda: a.position, lambda: a.mass, lambda: a.vertices, a.remove,
                    lambda: setattr(a, "velocity", (1.0, 0.0))):
            with pytest.raises(carom.CaromError) as e:
                use()
            assert e.value.status == carom.Status.STALE_BODY
        # the slot is reused, the old handle stays stale
        c = world.add_circle(1.0)
        assert c.id != a.id and not a.is_alive and c.is_alive


def test_body_of_a_closed_world_raises_cleanly():
    world = carom.World()
    body = world.add_box(1.0, 1.0)
    world.close()
    assert not body.is_alive
    with pytest.raises(carom.ClosedWorldError) as e:
        body.position
    assert isinstance(e.value, carom.CaromError)
    assert "closed" in str(e.value)
    with pytest.raises(carom.ClosedWorldError):
        body.remove()


def test_bodies_keep_their_world_alive():
    body = carom.World(gravity=(0.0, -1.0)).add_circle(1.0)
    body.world.step(1.0)  # the World object is only reachable through body
    assert body.position == pytest.approx((0.0, -0.5))
    body.world.close()


# ------------------------------------------------------------------ scenes

def test_scene_text_loads():
    with carom.World.from_scene_text(SCENE) as world:
        assert world.gravity == (0.0, -10.0)
        bodies = world.bodies
        assert len(bodies) == 5  # the box and four walls
        box = bodies[0]
        assert box.position == (0.0, 2.0) and not box.is_static
        assert all(wall.is_static for wall in bodies[1:])
        world.step(0.1)
        assert box.position[1] < 2.0


def test_scene_file_loads(tmp_path):
    path = tmp_path / "drop.scene"
    path.write_text("# a comment\n" + SCENE)
    with carom.World.from_scene(path) as world:
        assert len(world) == 5
    with carom.World.from_scene(str(path), friction=0.5) as world:
        assert world.bodies[0].friction == 0.5  # a setting the scene leaves out


def test_bad_scene_raises_with_the_line_number():
    text = "gravity 0 -10\nbox 1 1 at 0 2\ncircle -1 at 0 5\nbounds -5 0 5 10\n"
    with pytest.raises(carom.CaromError) as e:
        carom.World.from_scene_text(text)
    assert e.value.line == 3
    assert e.value.status == carom.Status.BAD_SIZE
    assert e.value.message.startswith("3:")

    with pytest.raises(carom.CaromError) as e:
        carom.World.from_scene_text("gravity 0 -10\n\nfrobnicate 1 2\n")
    assert e.value.line == 3
    assert e.value.status == carom.Status.SCENE_SYNTAX


def test_missing_scene_file_raises_io(tmp_path):
    with pytest.raises(carom.CaromError) as e:
        carom.World.from_scene(tmp_path / "missing.scene")
    assert e.value.status == carom.Status.IO


def test_effects_switch_on_by_use_and_damping_is_exact():
    with carom.World() as w:
        assert w.effects == ["continuous"]  # the one effect on by default
        w.set_continuous(False)
        assert w.effects == []
        w.set_continuous(True)
        assert w.effects == ["continuous"]
        w.set_continuous(False)
        b = w.add_box(1, 1, vx=2.0)
        w.set_damping(0.5)
        w.gravity = (0, -1)
        assert set(w.effects) == {"gravity", "damping"}
        w.gravity = (0, 0)
        for _ in range(60):
            w.step(1 / 60)
        assert b.velocity[0] == pytest.approx(2.0 * math.exp(-0.5), rel=1e-12)
        b.set_fixed_rotation()
        assert "fixed-rotation" in w.effects
        with pytest.raises(carom.CaromError):
            w.set_damping(-1)


# ------------------------------------------------------------ version 0.2

def test_impulses_and_forces_are_exact():
    with carom.World() as world:
        box = world.add_box(2.0, 1.0, x=1.0, y=2.0)
        m, inertia = box.mass, box.inertia
        box.apply_impulse((3.0, -4.0))
        assert box.velocity == pytest.approx((3.0 / m, -4.0 / m), rel=1e-15)
        assert box.spin == 0.0
        box.apply_impulse((0.0, 2.0), point=(1.5, 2.0))  # 0.5 to the right of the centre
        assert box.spin == pytest.approx(0.5 * 2.0 / inertia, rel=1e-14)
        v0 = box.velocity
        box.apply_force((6.0, 0.0))
        box.apply_torque(1.0)
        s0 = box.spin
        world.step(1 / 60)
        assert box.velocity[0] - v0[0] == pytest.approx(6.0 / 60 / m, rel=1e-12)
        assert box.spin - s0 == pytest.approx(1.0 / 60 / inertia, rel=1e-12)
        v1 = box.velocity
        world.step(1 / 60)  # the force acted over one step only
        assert box.velocity == v1


def test_compound_mass_shapes_and_errors():
    with carom.World(gravity=(0, -9.81), friction=0.5) as world:
        # a dumbbell: discs of density 2 and 1 (the body's) on a bar of 0.5
        r, L = 0.5, 2.0
        body = world.add_compound([carom.Circle(r, offset=(-L, 0), density=2.0),
                                   carom.Circle(r, offset=(L, 0), friction=0.1),
                                   carom.Box(3.0, 0.4, density=0.5)], x=1.0, y=3.0)
        m1, m2, m3 = 2 * math.pi * r * r, math.pi * r * r, 0.5 * 3.0 * 0.4
        m = m1 + m2 + m3
        c = (m2 * L - m1 * L) / m
        inertia = (m1 * r * r / 2 + m1 * (L + c) ** 2 + m2 * r * r / 2 + m2 * (L - c) ** 2
                   + m3 * (9.0 + 0.16) / 12 + m3 * c * c)
        assert body.mass == pytest.approx(m, rel=1e-15)
        assert body.inertia == pytest.approx(inertia, rel=1e-14)
        assert body.shape == "compound" and body.vertices == []
        shapes = body.shapes
        assert [s.kind for s in shapes] == ["circle", "circle", "polygon"]
        assert shapes[0].center == pytest.approx((1.0 - L - c, 3.0), abs=1e-14)
        assert shapes[0].density == 2.0 and shapes[1].density == 1.0
        assert shapes[1].friction == 0.1 and shapes[0].friction == 0.5
        assert len(shapes[2].vertices) == 4
        # one shape of a circle body
        ball = world.add_circle(0.25, x=5.0, y=1.0)
        assert [s.kind for s in ball.shapes] == ["circle"]
        world.add_box(20.0, 1.0, y=-0.5, static=True)
        for _ in range(240):
            world.step(1 / 60)
        assert body.position[1] == pytest.approx(r, abs=0.01)  # resting on the discs
        drawn = []
        world.debug_draw(polygon=lambda pts, b: drawn.append(("p", b)),
                         circle=lambda c_, r_, a, b: drawn.append(("c", b)))
        assert drawn.count(("c", body)) == 2 and drawn.count(("p", body)) == 1
        with pytest.raises(carom.CaromError) as err:
            world.add_compound([carom.Circle(-1.0)])
        assert err.value.status == carom.Status.BAD_SIZE
        with pytest.raises(carom.CaromError) as err:
            world.add_compound([])
        assert err.value.status == carom.Status.BAD_ARGUMENT
        with pytest.raises(carom.CaromError) as err:
            world.add_compound([carom.Polygon([(0, 0), (1, 1), (1, 0), (0, 1)])])
        assert err.value.status == carom.Status.SELF_INTERSECTING
        with pytest.raises(TypeError):
            world.add_compound([(0, 0)])
        assert len(world) == 3


def test_kinematic_platform_carries_a_box():
    with carom.World(gravity=(0, -10)) as world:
        platform = world.add_box(6.0, 0.5, kinematic=True, vx=1.0, friction=0.6)
        box = world.add_box(1.0, 1.0, y=0.75, friction=0.6)
        assert platform.type == "kinematic" and platform.is_kinematic and platform.mass == 0.0
        for _ in range(120):
            world.step(1 / 60)
        assert platform.position == pytest.approx((2.0, 0.0), abs=1e-9)
        assert box.velocity == pytest.approx((1.0, 0.0), abs=1e-3)
        with pytest.raises(carom.CaromError) as err:
            platform.apply_force((1.0, 0.0))
        assert err.value.status == carom.Status.STATIC_BODY


def test_filtering_and_groups():
    def falls_through(**ball):
        with carom.World(gravity=(0, -10)) as world:
            world.add_box(10, 1, y=-0.5, static=True, category=2, group=-1)
            b = world.add_circle(0.5, y=1.0, **ball)
            for _ in range(60):
                world.step(1 / 60)
            return b.position[1] < 0.0
    assert not falls_through()
    assert falls_through(mask=1)        # not the ground's category
    assert falls_through(group=-1)      # the same negative group
    assert not falls_through(group=-2)
    with carom.World() as world:
        b = world.add_circle(1.0)
        assert b.filter == (1, carom.ALL, 0)
        b.filter = (4, 3, 7)
        assert b.filter == (4, 3, 7)
        with pytest.raises(ValueError):
            b.filter = (1 << 33, 0, 0)


def test_raycast_and_queries():
    with carom.World() as world:
        box = world.add_box(2.0, 2.0, static=True)
        ball = world.add_circle(1.0, x=10.0)
        hit = world.raycast((-5.0, 0.25), (5.0, 0.25))
        assert hit.body == box
        assert hit.point == pytest.approx((-1.0, 0.25), abs=1e-12)
        assert hit.normal == pytest.approx((-1.0, 0.0), abs=1e-12)
        assert hit.fraction == pytest.approx(0.4, abs=1e-12)
        assert world.raycast((-5.0, 3.0), (5.0, 3.0)) is None
        assert world.raycast((-5.0, 0.0), (15.0, 0.0), mask=0) is None
        assert world.query_point((10.5, 0.0)) == [ball]
        assert world.query_point((5.0, 0.0)) == []
        assert world.query_aabb((-1.5, -1.5), (9.5, 0.0)) == [box, ball]
        with pytest.raises(carom.CaromError) as err:
            world.query_aabb((1.0, 0.0), (0.0, 1.0))
        assert err.value.status == carom.Status.BAD_ARGUMENT


def test_events_and_sensors():
    with carom.World(gravity=(0, -10)) as world:
        ground = world.add_box(10, 1, y=-0.5, static=True)
        zone = world.add_box(4, 1, y=1.5, static=True, sensor=True)
        ball = world.add_circle(0.25, y=3.0)
        assert zone.is_sensor and not ball.is_sensor
        seen = []
        world.on_contact(begin=seen.append, sensor_begin=seen.append, sensor_end=seen.append)
        for _ in range(120):
            world.step(1 / 60)
        kinds = [e.type for e in seen]
        assert kinds == [carom.EventType.SENSOR_BEGIN, carom.EventType.SENSOR_END,
                         carom.EventType.CONTACT_BEGIN]
        assert seen[0].a == zone and seen[0].b == ball
        landing = seen[2]
        assert {landing.a, landing.b} == {ground, ball}
        assert landing.approach_speed == pytest.approx((2 * 10 * 2.75) ** 0.5, rel=0.05)
        assert world.events() == []  # resting: nothing new
        with pytest.raises(TypeError):
            world.on_contact(begin=3)


def test_user_data_and_repr():
    with carom.World() as world:
        b = world.add_circle(1.0)
        assert b.user_data is None
        b.user_data = {"name": "ball"}
        assert world.bodies[0].user_data == {"name": "ball"}
        assert repr(b).startswith("<carom.Body 1.1 dynamic circle")
        b.remove()
        with pytest.raises(carom.CaromError):
            b.user_data


def test_debug_draw_and_matplotlib_style_draw():
    class Axes:
        def __init__(self):
            self.fills, self.plots = 0, 0

        def fill(self, xs, ys, **kw):
            assert len(xs) == len(ys) >= 3
            self.fills += 1

        def plot(self, xs, ys, **kw):
            self.plots += 1
    with carom.World(gravity=(0, -10)) as world:
        world.add_box(10, 1, y=-0.5, static=True)
        world.add_box(1, 1, y=0.5)
        world.add_circle(0.5, x=2.0, y=0.5)
        world.step(1 / 60)
        polys, points = [], []
        world.debug_draw(polygon=lambda pts, body: polys.append((len(pts), body)),
                         point=points.append)
        assert sorted(n for n, _ in polys) == [4, 4]
        assert len(points) == len(world.contacts())
        ax = Axes()
        carom.draw(world, ax)
        assert ax.fills == 3 and ax.plots >= 1 + 2 * len(points)

        def boom(pts, body):
            raise RuntimeError("from the callback")
        with pytest.raises(RuntimeError):
            world.debug_draw(polygon=boom)


def test_draw_on_a_real_matplotlib_axes(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with carom.World(gravity=(0, -10)) as world:
        world.add_box(10, 1, y=-0.5, static=True)
        world.add_polygon([(0, 0), (3, 0), (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)], y=2)
        world.add_circle(0.5, x=3, y=1)
        for _ in range(30):
            world.step(1 / 60)
        fig, ax = plt.subplots()
        carom.draw(world, ax)
        ax.set_aspect("equal")
        fig.savefig(tmp_path / "world.png")
        plt.close(fig)
        # two polygons and a circle filled; the concave U keeps its 8 corners
        assert len(ax.patches) == 3
        assert sorted(len(p.get_xy()) for p in ax.patches)[-1] >= 32  # the circle's 32-gon (closed)
        assert (tmp_path / "world.png").stat().st_size > 1000
