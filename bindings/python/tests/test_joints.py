"""Joints (version 0.2) through the Python binding, on the real library.

Run from the repository: make check-python (or CAROM_LIBRARY=build/libcarom.so.0
python3 -m pytest bindings/python/tests).
"""

import ctypes
import math

import pytest

import carom
from carom import _native

G = 9.81


def test_joint_def_comes_from_the_library_zeroed():
    d = _native.new_def(_native.JointDef)
    assert d.size == ctypes.sizeof(_native.JointDef)
    assert all(getattr(d, name) == 0 for name, _ in _native.JointDef._fields_ if name != "size")
    draw = _native.new_def(_native.DebugDraw)
    assert (draw.draw_bodies, draw.draw_contacts, draw.draw_joints) == (1, 1, 1)
    assert [t.value for t in carom.JointType] == list(range(7))
    assert carom.Status.STALE_JOINT == 19
    assert "joint" in carom.status_string(carom.Status.STALE_JOINT)


# --------------------------------------------------------------- physics

def test_pendulum_keeps_its_length():
    # a small disc on a revolute joint to the world, 1 m from the pivot,
    # released horizontally: it swings, and its distance to the pivot stays
    with carom.World(gravity=(0.0, -G)) as world:
        bob = world.add_circle(0.05, x=1.0, y=0.0)
        pivot = world.add_joint(carom.JointType.REVOLUTE, a=None, b=bob, x=0.0, y=0.0)
        assert pivot.anchors == ((0.0, 0.0), (0.0, 0.0))
        worst, lowest = 0.0, 0.0
        for _ in range(120):  # 2 s
            world.step(1 / 60)
            x, y = bob.position
            worst = max(worst, abs(math.hypot(x, y) - 1.0))
            lowest = min(lowest, y)
            (ax, ay), (bx, by) = pivot.anchors
            assert (ax, ay) == (0.0, 0.0)
            assert math.hypot(bx, by) < 1e-4  # the anchor on the disc stays on the pivot
        assert worst <= 1e-6
        assert lowest < -0.99  # it did swing through the bottom
        # energy: the speed at the bottom of a swing from the horizontal
        # is at most sqrt(2 g L) (some goes into the disc's own turning)
        speed = math.hypot(*bob.velocity)
        assert speed <= math.sqrt(2 * G * 1.0) * (1 + 1e-6)


def test_small_swings_have_the_physical_pendulums_period():
    # a disc of radius r on a pivot L from its centre: T = 2 pi sqrt((L^2 + r^2 / 2) / (g L))
    L, r, th0, dt = 1.0, 0.05, 0.05, 1 / 240
    with carom.World(gravity=(0.0, -G)) as world:
        bob = world.add_circle(r, x=L * math.sin(th0), y=-L * math.cos(th0))
        world.add_joint("revolute", b=bob)  # a=None, at (0, 0)
        t, prev, crossings = 0.0, bob.position[0], []
        for _ in range(6 * 240):
            world.step(dt)
            t += dt
            x = bob.position[0]
            if (prev > 0.0 >= x) or (prev < 0.0 <= x):
                crossings.append(t - dt * x / (x - prev))
            prev = x
    period = 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    expected = 2 * math.pi * math.sqrt((L * L + r * r / 2) / (G * L))
    assert period == pytest.approx(expected, rel=1e-3)


def test_hanging_body_reaction_is_its_weight():
    with carom.World(gravity=(0.0, -G)) as world:
        box = world.add_box(0.2, 0.2, x=0.0, y=-1.0)
        rope = world.add_joint("revolute", a=None, b=box, x=0.0, y=0.0)
        assert rope.reaction == (0.0, 0.0, 0.0)  # zero before the first step
        for _ in range(60):
            world.step(1 / 60)
        fx, fy, torque = rope.reaction
        assert isinstance(rope.reaction, carom.Reaction)
        assert fy == pytest.approx(box.mass * G, rel=0.01)
        assert abs(fx) <= 1e-9 and abs(torque) <= 1e-9
        # a second body hanging from the first: the lower joint carries its weight
        low = world.add_circle(0.1, x=0.0, y=-2.0)
        link = world.add_joint("revolute", a=box, b=low, x=0.0, y=-1.5)
        for _ in range(60):
            world.step(1 / 60)
        assert link.reaction.fy == pytest.approx(low.mass * G, rel=0.01)
        assert rope.reaction.fy == pytest.approx((box.mass + low.mass) * G, rel=0.01)


def test_weld_cantilever_reaction_has_the_moment():
    # a 1 x 1 box welded to the world 1 m left of its centre: the weld holds
    # its weight and, about b's centre, the torque m g d
    with carom.World(gravity=(0.0, -G)) as world:
        box = world.add_box(1.0, 1.0, x=1.0, y=0.0)
        weld = world.add_joint("weld", b=box, x=0.0, y=0.0)
        for _ in range(60):
            world.step(1 / 60)
        assert box.position == pytest.approx((1.0, 0.0), abs=1e-9)
        assert box.angle == pytest.approx(0.0, abs=1e-9)
        fx, fy, torque = weld.reaction
        assert fy == pytest.approx(box.mass * G, rel=0.01)
        assert torque == pytest.approx(box.mass * G * 1.0, rel=0.01)


def test_prismatic_slides_along_its_axis_to_its_limit():
    with carom.World(gravity=(0.0, -10.0)) as world:
        box = world.add_box(0.5, 0.5, y=3.0)
        rail = world.add_joint("prismatic", b=box, x=0.0, y=3.0, axis=(0.0, 2.0), limit=(-1.0, 0.0))
        for _ in range(120):
            world.step(1 / 60)
        x, y = box.position
        assert abs(x) <= 1e-9 and box.angle == pytest.approx(0.0, abs=1e-9)
        assert y == pytest.approx(2.0, abs=1e-3)  # stopped by the lower limit
        assert rail.reaction.fy == pytest.approx(box.mass * 10.0, rel=0.01)
        with pytest.raises(carom.CaromError) as err:  # the axis is required
            world.add_joint("prismatic", b=box, x=0.0, y=3.0)
        assert err.value.status == carom.Status.BAD_ARGUMENT


def test_distance_spring_oscillates_about_its_stretch():
    # a spring of 2 Hz, undamped, released at its rest length: it swings
    # between rest and twice the static stretch g / omega^2
    omega = 2 * math.pi * 2.0
    with carom.World(gravity=(0.0, -G)) as world:
        bob = world.add_circle(0.1, y=-1.0)
        spring = world.add_joint("distance", b=bob, x=0.0, y=0.0, x2=0.0, y2=-1.0,
                                 spring=(2.0, 0.0))
        assert spring.anchors == ((0.0, 0.0), (0.0, -1.0))
        ys = []
        for _ in range(240):
            world.step(1 / 240)
            ys.append(bob.position[1])
        assert min(ys) == pytest.approx(-1.0 - 2 * G / omega ** 2, abs=0.01)
        assert max(ys) == pytest.approx(-1.0, abs=0.005)
    # rigid, with an explicit length: the anchors are pulled to that length
    with carom.World() as world:
        bob = world.add_circle(0.1, x=2.0)
        rod = world.add_joint("distance", b=bob, x2=2.0, length=1.5)
        for _ in range(120):
            world.step(1 / 60)
        assert math.hypot(*bob.position) == pytest.approx(1.5, abs=1e-3)


def test_revolute_motor_drives_the_spin():
    with carom.World() as world:
        wheel = world.add_circle(0.5, x=1.0, y=2.0)
        axle = world.add_joint("revolute", b=wheel, x=1.0, y=2.0, motor=(2.0, 100.0))
        for _ in range(30):
            world.step(1 / 60)
        assert wheel.spin == pytest.approx(2.0, abs=1e-9)
        assert wheel.position == pytest.approx((1.0, 2.0), abs=1e-9)
        axle.set_motor(-1.0, 100.0)
        for _ in range(30):
            world.step(1 / 60)
        assert wheel.spin == pytest.approx(-1.0, abs=1e-9)
        axle.set_motor(enabled=False)  # free: it keeps turning
        wheel.spin = 3.0
        world.step(1 / 60)
        assert wheel.spin == pytest.approx(3.0, abs=1e-9)
        with pytest.raises(carom.CaromError) as err:
            axle.set_motor(1.0, -1.0)
        assert err.value.status == carom.Status.BAD_ARGUMENT
        with pytest.raises(carom.CaromError) as err:
            axle.set_motor(math.nan, 1.0)
        assert err.value.status == carom.Status.NOT_FINITE
        with pytest.raises(carom.CaromError) as err:
            axle.set_target(0.0, 0.0)  # a revolute joint has no target
        assert err.value.status == carom.Status.BAD_ARGUMENT


def test_mouse_and_motor_joints_follow_their_targets():
    with carom.World(gravity=(0.0, -G)) as world:
        box = world.add_box(0.5, 0.5, x=1.0, y=1.0)
        mouse = world.add_joint("mouse", b=box, x=1.25, y=1.0)  # grabbed at its right edge
        assert mouse.type == carom.JointType.MOUSE and mouse.bodies == (None, box)
        mouse.set_target(3.0, 2.0)
        assert mouse.anchors == ((3.0, 2.0), (1.25, 1.0))  # the target, then b's point
        for _ in range(240):
            world.step(1 / 60)
        target, (px, py) = mouse.anchors
        assert target == (3.0, 2.0)
        assert math.hypot(px - 3.0, py - 2.0) < 0.5  # soft (5 Hz), against gravity
        with pytest.raises(carom.CaromError) as err:
            mouse.set_motor(1.0, 1.0)
        assert err.value.status == carom.Status.BAD_ARGUMENT
    with carom.World() as world:
        box = world.add_box(1.0, 1.0)
        drive = world.add_joint("motor", b=box, max_motor_force=1e4, max_motor_torque=1e4)
        drive.set_target(2.0, 1.0, 0.5)
        for _ in range(120):
            world.step(1 / 60)
        assert box.position == pytest.approx((2.0, 1.0), abs=1e-3)
        assert box.angle == pytest.approx(0.5, abs=1e-3)
        with pytest.raises(carom.CaromError) as err:
            drive.set_target(math.inf, 0.0)
        assert err.value.status == carom.Status.NOT_FINITE


def test_joined_bodies_do_not_collide_unless_collide_connected():
    for collide in (False, True):
        with carom.World() as world:
            a = world.add_box(1.0, 1.0)
            b = world.add_box(1.0, 1.0, x=0.5)  # overlapping
            world.add_joint("weld", a=a, b=b, x=0.25, y=0.0, collide_connected=collide)
            assert bool(world.detect()) == collide


# ------------------------------------------------------------ the handles

def test_joint_handles():
    with carom.World() as world:
        ground = world.add_box(10.0, 1.0, static=True)
        box = world.add_box(1.0, 1.0, y=2.0)
        assert world.joint_count == 0 and "joints" not in world.effects
        hinge = world.add_joint("REVOLUTE", a=ground, b=box, x=0.0, y=1.5)
        rope = world.add_joint(carom.JointType.DISTANCE, b=box, x=0.0, y=5.0, x2=0.0, y2=2.0)
        assert world.joint_count == 2 and "joints" in world.effects
        assert hinge.type == carom.JointType.REVOLUTE and rope.type == carom.JointType.DISTANCE
        assert hinge.bodies == (ground, box) and (hinge.a, hinge.b) == (ground, box)
        assert rope.bodies == (None, box)
        assert hinge.anchors == ((0.0, 1.5), (0.0, 1.5))
        assert rope.anchors == ((0.0, 5.0), (0.0, 2.0))
        assert hinge.is_alive and hinge != rope and len({hinge, rope, hinge}) == 2
        assert hinge == carom.Joint(world, hinge.id) and hinge != box
        assert hinge.index == (1, 1) and rope.index == (2, 1)
        assert repr(hinge) == "<carom.Joint 1.1 revolute: body 1.1 and body 2.1>"
        assert repr(rope) == "<carom.Joint 2.1 distance: the world and body 2.1>"
        rope.remove()
        assert not rope.is_alive and world.joint_count == 1
        assert repr(rope) == "<carom.Joint 2.1 (gone)>"
        with pytest.raises(carom.CaromError) as err:
            rope.remove()
        assert err.value.status == carom.Status.STALE_JOINT
        again = world.add_joint("weld", a=ground, b=box, x=0.0, y=2.0)
        assert again.index == (2, 2)  # the slot is reused, the old handle stays stale
        assert not rope.is_alive and again.is_alive


def test_removing_a_body_makes_its_joints_stale():
    with carom.World(gravity=(0.0, -G)) as world:
        holder = world.add_circle(0.1, y=-1.0)
        hanging = world.add_circle(0.1, y=-2.0)
        top = world.add_joint("revolute", b=holder, x=0.0, y=0.0)
        low = world.add_joint("distance", a=holder, b=hanging, x=0.0, y=-1.0, x2=0.0, y2=-2.0)
        world.step(1 / 60)
        holder.remove()
        assert world.joint_count == 0 and "joints" not in world.effects
        for joint in (top, low):
            assert not joint.is_alive
            for use in (lambda: joint.reaction, lambda: joint.anchors, lambda: joint.bodies,
                        lambda: joint.type, joint.remove, lambda: joint.set_motor(1.0, 1.0),
                        lambda: joint.set_target(0.0, 0.0)):
                with pytest.raises(carom.CaromError) as err:
                    use()
                assert err.value.status == carom.Status.STALE_JOINT
                assert carom.status_string(carom.Status.STALE_JOINT) in err.value.message
        # the body that hung from it now falls freely
        y0, vy0 = hanging.position[1], hanging.velocity[1]
        world.step(0.1)
        assert hanging.position[1] == pytest.approx(y0 + vy0 * 0.1 - 0.5 * G * 0.01, abs=1e-9)
        # and a removed joint lets its body go
        box = world.add_box(0.2, 0.2, y=5.0)
        hold = world.add_joint("weld", b=box, x=0.0, y=5.0)
        for _ in range(10):
            world.step(1 / 60)
        assert box.position == pytest.approx((0.0, 5.0), abs=1e-9)
        hold.remove()
        world.step(0.1)
        assert box.position[1] < 5.0 - 0.04


def test_joint_of_a_closed_world_raises_cleanly():
    world = carom.World()
    joint = world.add_joint("revolute", b=world.add_circle(1.0))
    world.close()
    assert not joint.is_alive
    with pytest.raises(carom.ClosedWorldError) as err:
        joint.reaction
    assert err.value.status == carom.Status.STALE_JOINT and "closed" in str(err.value)
    with pytest.raises(carom.ClosedWorldError):
        world.joint_count


@pytest.mark.parametrize("make, status", [
    (lambda w, g, b, c: w.add_joint("revolute", a=b, b=b), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint(7, b=b), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint(-1, b=b), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("weld", a=g, b=b, spring=(-1.0, 0.5)), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("weld", a=g, b=b, spring=(1.0, -0.5)), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("mouse", a=g, b=b), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("wheel", a=g, b=b, axis=(0.0, 0.0)), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("revolute", b=b, limit=(1.0, -1.0)), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("revolute", b=b, motor=(1.0, -1.0)), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("motor", b=b, max_motor_torque=-1.0), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("distance", a=g, b=b, x=1.0, y=1.0, x2=1.0, y2=1.0),
     carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("distance", b=b, x2=1.0, length=-1.0), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("revolute", b=b, x=1e101), carom.Status.BAD_ARGUMENT),
    (lambda w, g, b, c: w.add_joint("revolute", b=b, y=math.nan), carom.Status.NOT_FINITE),
    (lambda w, g, b, c: w.add_joint("revolute", a=g, b=w.add_box(1, 1, x=5, static=True)),
     carom.Status.STATIC_BODY),
    (lambda w, g, b, c: w.add_joint("revolute", b=g), carom.Status.STATIC_BODY),
    (lambda w, g, b, c: (c.remove(), w.add_joint("revolute", a=c, b=b)), carom.Status.STALE_BODY),
])
def test_bad_joint_input_raises_and_adds_nothing(make, status):
    with carom.World(gravity=(0.0, -G)) as world:
        ground = world.add_box(10.0, 1.0, y=-0.5, static=True)
        ball = world.add_circle(0.5, y=2.0)
        other = world.add_circle(0.5, x=3.0, y=2.0)
        with pytest.raises(carom.CaromError) as err:
            make(world, ground, ball, other)
        assert err.value.status == status
        assert carom.status_string(status) in err.value.message
        assert world.joint_count == 0 and "joints" not in world.effects
        world.step(0.5)  # the ball falls freely: nothing holds it
        assert ball.position[1] == pytest.approx(2.0 - 0.5 * G * 0.25, abs=1e-9)


def test_wrong_python_arguments_raise_before_the_library():
    with carom.World() as world:
        ball = world.add_circle(0.5)
        with carom.World() as elsewhere:
            stranger = elsewhere.add_circle(0.5)
            with pytest.raises(ValueError):
                world.add_joint("revolute", b=stranger)
        with pytest.raises(ValueError):
            world.add_joint("hinge", b=ball)
        with pytest.raises(TypeError):
            world.add_joint("revolute")  # b is required
        with pytest.raises(TypeError):
            world.add_joint("revolute", a=ball.id, b=ball)
        with pytest.raises(TypeError):
            world.add_joint("prismatic", b=ball, axis=1.0)
        with pytest.raises(ValueError):
            world.add_joint("mouse", b=ball, motor=(0.0, 1.0), max_motor_force=1.0)
        assert world.joint_count == 0


# ------------------------------------------------------------- debug draw

def test_debug_draw_reports_joints():
    class Axes:
        def __init__(self):
            self.fills, self.plots = 0, 0

        def fill(self, xs, ys, **kw):
            self.fills += 1

        def plot(self, xs, ys, **kw):
            self.plots += 1
    with carom.World() as world:
        ground = world.add_box(4.0, 1.0, static=True)
        arm = world.add_box(2.0, 0.2, x=1.0, y=2.0)
        bob = world.add_circle(0.1, x=3.0, y=0.0)
        hinge = world.add_joint("revolute", a=ground, b=arm, x=0.0, y=2.0)
        pin = world.add_joint("revolute", b=bob, x=3.0, y=1.0)
        seen = []
        world.debug_draw(joint=lambda kind, points, joint: seen.append((kind, points, joint)))
        assert [s[2] for s in seen] == [hinge, pin]
        kind, points, _ = seen[0]
        assert kind == carom.JointType.REVOLUTE
        # centre of a, anchor on a, anchor on b, centre of b
        assert points == [(0.0, 0.0), (0.0, 2.0), (0.0, 2.0), (1.0, 2.0)]
        # a joint to the world: its fixed point twice
        assert seen[1][1] == [(3.0, 1.0), (3.0, 1.0), (3.0, 1.0), (3.0, 0.0)]
        seen.clear()
        world.debug_draw(joint=lambda *args: seen.append(args), joints=False)
        assert seen == []
        ax = Axes()
        carom.draw(world, ax, contacts=False)
        assert ax.fills == 3 and ax.plots == 1 + 2 * 2  # the disc's radius marker, two per joint
        ax = Axes()
        carom.draw(world, ax, contacts=False, joints=False)
        assert ax.plots == 1


def test_draw_joints_on_a_real_matplotlib_axes(tmp_path):
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with carom.World(gravity=(0, -10)) as world:
        bob = world.add_circle(0.1, x=1.0)
        world.add_joint("revolute", b=bob)
        cart = world.add_box(1.0, 0.5, y=-2.0)
        world.add_joint("prismatic", b=cart, x=0.0, y=-2.0, axis=(1.0, 0.0), motor=(1.0, 10.0))
        for _ in range(30):
            world.step(1 / 60)
        fig, ax = plt.subplots()
        carom.draw(world, ax)
        fig.savefig(tmp_path / "joints.png")
        plt.close(fig)
        # the circle's radius marker, then a line and the anchors' markers per joint
        assert len(ax.lines) == 1 + 2 * 2
        assert (tmp_path / "joints.png").stat().st_size > 1000
