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
                        lambda: joint.set_target(0.0, 0.0), lambda: joint.set_limit(-1.0, 1.0),
                        lambda: joint.set_spring(1.0, 0.5)):
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
    disc = world.add_circle(1.0)
    joint = world.add_joint("revolute", b=disc)
    world.close()
    assert not joint.is_alive
    with pytest.raises(carom.ClosedWorldError) as err:
        joint.reaction
    assert err.value.status == carom.Status.STALE_JOINT and "closed" in str(err.value)
    with pytest.raises(carom.ClosedWorldError):
        world.joint_count
    with pytest.raises(carom.ClosedWorldError):
        world.joints
    with pytest.raises(carom.ClosedWorldError) as err:
        disc.joints
    assert err.value.status == carom.Status.STALE_BODY
    with pytest.raises(carom.ClosedWorldError):
        joint.set_limit(-1.0, 1.0)


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


# ------------------------------------- listing, limits and springs set later

def test_world_and_body_list_their_joints():
    with carom.World() as world:
        assert world.joints == []
        ground = world.add_box(10.0, 1.0, static=True)
        a = world.add_circle(0.5, y=2.0)
        b = world.add_circle(0.5, x=2.0, y=2.0)
        c = world.add_circle(0.5, x=4.0, y=2.0)
        assert a.joints == [] and ground.joints == []
        hinge = world.add_joint("revolute", a=ground, b=a, x=0.0, y=2.0)
        rod = world.add_joint("distance", a=a, b=b, x=0.0, y=2.0, x2=2.0, y2=2.0)
        weld = world.add_joint("weld", a=b, b=c, x=3.0, y=2.0)
        pin = world.add_joint("revolute", b=c, x=4.0, y=3.0)  # to the world
        assert world.joints == [hinge, rod, weld, pin]  # slot order
        assert all(isinstance(j, carom.Joint) and j.world is world for j in world.joints)
        # a body's own, each once (in a fixed order of its own)
        for body, mine in ((ground, {hinge}), (a, {hinge, rod}), (b, {rod, weld}),
                           (c, {weld, pin})):
            listed = body.joints
            assert len(listed) == len(mine) and set(listed) == mine
            assert all(body in j.bodies for j in listed)
        # a joint removed on its own vanishes from both lists
        rod.remove()
        assert world.joints == [hinge, weld, pin]
        assert a.joints == [hinge] and b.joints == [weld]
        # its slot is reused: the new joint is listed there, the old handle is not
        rail = world.add_joint("prismatic", a=ground, b=b, x=2.0, y=2.0, axis=(1.0, 0.0))
        assert rail.index == (2, 2) and world.joints == [hinge, rail, weld, pin]
        assert set(b.joints) == {rail, weld} and rod not in world.joints
        # a removed body's joints vanish from every list, and its own raises
        b.remove()
        assert world.joints == [hinge, pin] and world.joint_count == 2
        assert ground.joints == [hinge] and c.joints == [pin] and a.joints == [hinge]
        with pytest.raises(carom.CaromError) as err:
            b.joints
        assert err.value.status == carom.Status.STALE_BODY
        assert carom.status_string(carom.Status.STALE_BODY) in err.value.message
        for body in (a, c):
            body.remove()
        assert world.joints == [] and ground.joints == [] and world.joint_count == 0


def test_joint_lists_through_the_raw_calls():
    # the query_aabb convention: the count whatever the capacity, or minus a status
    lib = _native.lib
    with carom.World() as world:
        bob = world.add_circle(0.5)
        first = world.add_joint("revolute", b=bob)
        second = world.add_joint("revolute", b=bob, x=1.0)
        one = (_native.c_joint_id * 1)()
        assert lib.carom_world_get_joints(world._ptr, one, 1) == 2 and one[0] == first.id
        assert lib.carom_world_get_joints(world._ptr, None, 0) == 2
        assert lib.carom_body_get_joints(world._ptr, bob.id, None, 0) == 2
        assert lib.carom_world_get_joints(None, None, 0) == -carom.Status.NULL_ARGUMENT
        assert lib.carom_world_get_joints(world._ptr, None, 1) == -carom.Status.NULL_ARGUMENT
        assert lib.carom_world_get_joints(world._ptr, one, -1) == -carom.Status.BAD_ARGUMENT
        assert lib.carom_body_get_joints(world._ptr, bob.id, one, -1) == -carom.Status.BAD_ARGUMENT
        assert lib.carom_body_get_joints(world._ptr, 0, None, 0) == -carom.Status.STALE_BODY
        assert {first, second} == set(bob.joints)


def test_set_limit_stops_a_swinging_bar_at_the_new_limit():
    # a 2 m bar pinned at its left end, released horizontally: its limit
    # holds it at -0.3 rad; widened to -1, it swings down and stops there
    one_degree = math.radians(1.0)
    with carom.World(gravity=(0.0, -G)) as world:
        bar = world.add_box(2.0, 0.1, x=1.0)
        hinge = world.add_joint("revolute", b=bar, x=0.0, y=0.0, limit=(-0.3, 0.3))
        for _ in range(120):
            world.step(1 / 60)
        assert bar.angle == pytest.approx(-0.3, abs=one_degree)
        hinge.set_limit(-1.0, 0.3)
        lowest = 0.0
        for _ in range(180):
            world.step(1 / 60)
            lowest = min(lowest, bar.angle)
        assert lowest >= -1.0 - one_degree  # never past the new limit
        assert bar.angle == pytest.approx(-1.0, abs=one_degree)  # and at rest on it
        assert abs(bar.spin) < 0.01
        # a failed call changes nothing: the limit still holds
        with pytest.raises(carom.CaromError) as err:
            hinge.set_limit(0.5, -0.5)
        assert err.value.status == carom.Status.BAD_ARGUMENT
        for _ in range(60):
            world.step(1 / 60)
        assert bar.angle == pytest.approx(-1.0, abs=one_degree)
        # switched off, the bar swings on down past the vertical
        hinge.set_limit(enabled=False)
        for _ in range(60):
            world.step(1 / 60)
            lowest = min(lowest, bar.angle)
        assert lowest < -math.pi / 2


def test_set_spring_of_one_hertz_gives_a_period_of_one_second():
    # a rigid distance joint turned into an undamped 1 Hz spring: the bob
    # bobs about its stretch with a period of 1 s, whatever its mass
    dt = 1 / 240
    with carom.World(gravity=(0.0, -G)) as world:
        bob = world.add_circle(0.1, y=-1.0, density=3.0)
        rod = world.add_joint("distance", b=bob, x2=0.0, y2=-1.0)
        for _ in range(30):
            world.step(dt)
        assert bob.position == pytest.approx((0.0, -1.0), abs=1e-9)  # rigid so far
        rod.set_spring(1.0, 0.0)
        t, prev, ups = 0.0, bob.velocity[1], []
        for _ in range(5 * 240):
            world.step(dt)
            t += dt
            vy = bob.velocity[1]
            if prev < 0.0 <= vy:  # the bottom of a bob
                ups.append(t - dt * vy / (vy - prev))
            prev = vy
        assert len(ups) >= 4
        period = (ups[-1] - ups[0]) / (len(ups) - 1)
        assert period == pytest.approx(1.0, rel=0.05)
        # switched off (hertz 0 or enabled=False): rigid again at its length
        rod.set_spring(1.0, 0.0, enabled=False)
        for _ in range(240):
            world.step(dt)
        assert math.hypot(*bob.position) == pytest.approx(1.0, abs=1e-3)


@pytest.mark.parametrize("call, status", [
    (lambda j: j["hinge"].set_limit(1.0, -1.0), carom.Status.BAD_ARGUMENT),  # lower > upper
    (lambda j: j["hinge"].set_limit(-1.0, 1e101), carom.Status.BAD_ARGUMENT),
    (lambda j: j["hinge"].set_limit(math.nan, 1.0), carom.Status.NOT_FINITE),
    (lambda j: j["hinge"].set_limit(-1.0, math.inf), carom.Status.NOT_FINITE),
    (lambda j: j["weld"].set_limit(-1.0, 1.0), carom.Status.BAD_ARGUMENT),
    (lambda j: j["motor"].set_limit(-1.0, 1.0), carom.Status.BAD_ARGUMENT),
    (lambda j: j["mouse"].set_limit(-1.0, 1.0), carom.Status.BAD_ARGUMENT),
    (lambda j: j["rope"].set_spring(-1.0, 0.5), carom.Status.BAD_ARGUMENT),  # negative hertz
    (lambda j: j["rope"].set_spring(1.0, -0.5), carom.Status.BAD_ARGUMENT),
    (lambda j: j["rope"].set_spring(1e101, 0.5), carom.Status.BAD_ARGUMENT),
    (lambda j: j["rope"].set_spring(math.nan, 0.5), carom.Status.NOT_FINITE),
    (lambda j: j["motor"].set_spring(1.0, 0.5), carom.Status.BAD_ARGUMENT),  # a motor joint's
    (lambda j: j["mouse"].set_spring(-1.0, 0.5), carom.Status.BAD_ARGUMENT),
])
def test_bad_limit_and_spring_raise_with_the_status(call, status):
    with carom.World() as world:
        ground = world.add_box(10.0, 1.0, static=True)
        box = world.add_box(1.0, 1.0, y=2.0)
        joints = {
            "hinge": world.add_joint("revolute", a=ground, b=box, x=0.0, y=2.0),
            "rope": world.add_joint("distance", a=ground, b=box, x2=0.0, y2=2.0),
            "weld": world.add_joint("weld", a=ground, b=box, x=0.0, y=2.0),
            "motor": world.add_joint("motor", a=ground, b=box, max_motor_force=1.0),
            "mouse": world.add_joint("mouse", b=box, x=0.0, y=2.0),
        }
        with pytest.raises(carom.CaromError) as err:
            call(joints)
        assert err.value.status == status
        assert carom.status_string(status) in err.value.message
        assert world.joints == list(joints.values())  # nothing removed either


def test_limit_and_spring_calls_that_are_accepted():
    with carom.World() as world:
        ground = world.add_box(10.0, 1.0, static=True)
        box = world.add_box(1.0, 1.0, y=2.0)
        hinge = world.add_joint("revolute", a=ground, b=box, x=0.0, y=2.0)
        hinge.set_limit(0.0, 0.0)  # lower == upper: locked
        hinge.set_spring(2.0, 1.0)  # a torsion spring
        hinge.set_spring(0.0, 0.0)
        world.add_joint("prismatic", b=box, x=0.0, y=2.0, axis=(0.0, 1.0)).set_limit(-1.0, 1.0)
        world.add_joint("wheel", b=box, x=0.0, y=2.0, axis=(0.0, 1.0)).set_spring(4.0, 0.7)
        world.add_joint("weld", a=ground, b=box, x=0.0, y=2.0).set_spring(5.0, 0.5)
        mouse = world.add_joint("mouse", b=box, x=0.0, y=2.0)
        mouse.set_spring()  # 0, 0: the mouse joint's defaults
        mouse.set_spring(10.0, 0.9, enabled=False)  # a mouse joint ignores enabled
        with pytest.raises(TypeError):
            hinge.set_limit("low", 1.0)
        with pytest.raises(TypeError):
            hinge.set_spring(None, 1.0)


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
