"""carom: 2D rigid-body physics, through the library's stable C ABI.

    import carom

    with carom.World(gravity=(0, -9.81)) as world:
        ball = world.add_circle(0.5, y=10)
        for _ in range(60):
            world.step(1 / 60)
        print(ball.position, ball.velocity)

    with carom.World(gravity=(0, -9.81)) as world:
        bob = world.add_circle(0.1, x=1.0)
        rod = world.add_joint("revolute", a=None, b=bob, x=0.0, y=0.0)  # pinned to the world
        world.step(1 / 60)
        print(rod.reaction, rod.anchors)

Every failure of the C library raises CaromError, whose `status` is a
Status and whose message comes from carom_status_string. The shared
library is found through CAROM_LIBRARY (a full path), else the system's
library search (docs/bindings.md).
"""

import collections
import ctypes
import enum
import os
import weakref

from . import _native
from ._native import lib as _lib

__all__ = [
    "Body",
    "Box",
    "Circle",
    "Polygon",
    "ShapeInfo",
    "CaromError",
    "ClosedWorldError",
    "Contact",
    "Event",
    "EventType",
    "Joint",
    "JointType",
    "Reaction",
    "RayHit",
    "draw",
    "NarrowPhase",
    "Status",
    "World",
    "library_path",
    "library_version",
    "status_string",
]

__version__ = "0.2.0"

#: (major, minor, patch) of the shared library loaded at run time.
library_version = _native.version_tuple
#: The file or name the shared library was loaded from.
library_path = _native.path

#: Largest vertex count of one polygon (CAROM_MAX_POLYGON_VERTICES).
MAX_POLYGON_VERTICES = _native.MAX_POLYGON_VERTICES
#: Most shapes in one compound body (CAROM_MAX_COMPOUND_SHAPES).
MAX_COMPOUND_SHAPES = _native.MAX_COMPOUND_SHAPES


class Status(enum.IntEnum):
    """carom_status: the result of every fallible call (values are fixed)."""

    OK = 0
    NULL_ARGUMENT = 1
    NOT_FINITE = 2
    BAD_SIZE = 3
    BAD_DENSITY = 4
    TOO_FEW_VERTICES = 5
    TOO_MANY_VERTICES = 6
    REPEATED_VERTEX = 7
    SELF_INTERSECTING = 8
    ZERO_AREA = 9
    BAD_TIME_STEP = 10
    STALE_BODY = 11
    OUT_OF_MEMORY = 12
    BAD_ARGUMENT = 13
    BAD_STRUCT_SIZE = 14
    TOO_MANY_BODIES = 15
    STATIC_BODY = 16
    SCENE_SYNTAX = 17
    IO = 18
    STALE_JOINT = 19  # version 0.2


class EventType(enum.IntEnum):
    """carom_event_type: what happened between two bodies in the last step."""

    CONTACT_BEGIN = 0
    CONTACT_END = 1
    SENSOR_BEGIN = 2
    SENSOR_END = 3


class JointType(enum.IntEnum):
    """carom_joint_type: what a joint holds (version 0.2)."""

    REVOLUTE = 0   #: a shared point: b turns about the anchor
    PRISMATIC = 1  #: b slides along an axis fixed in a, without turning
    DISTANCE = 2   #: the two anchors keep their distance
    WELD = 3       #: b is fixed to a
    WHEEL = 4      #: b's anchor stays on an axis through a's (b turns freely)
    MOTOR = 5      #: b is driven towards a pose relative to a
    MOUSE = 6      #: a point of b is pulled towards a moving target


#: A joint's constraint force (fx, fy) on body b, at b's anchor, and torque,
#: averaged over the last step (Joint.reaction).
Reaction = collections.namedtuple("Reaction", "fx fy torque")


#: The first body a ray meets: the Body, the point and outward normal on
#: its outline, and the fraction of the segment.
RayHit = collections.namedtuple("RayHit", "body point normal fraction")

#: One event of the last step (carom_contact_event): for sensor events, a
#: is the sensor.
Event = collections.namedtuple("Event", "type a b point normal approach_speed normal_impulse")

#: Every category bit (a mask that takes every body).
ALL = 0xFFFFFFFF


class NarrowPhase(enum.IntEnum):
    """carom_narrow_phase: the method for pairs of convex polygons."""

    SAT = 0
    VERTEX_EDGE = 1


def _status(value):
    """A Status for a known code, the plain int for one a newer library added."""
    try:
        return Status(value)
    except ValueError:
        return int(value)


def status_string(status):
    """carom_status_string: a short English sentence for a status."""
    return _lib.carom_status_string(int(status)).decode("utf-8", "replace")


class CaromError(Exception):
    """A call into carom failed.

    status  -- the Status (an int if this binding does not know the code)
    message -- what went wrong, from carom_status_string or the scene loader
    line    -- for scenes: the 1-based line of the error, else None
    """

    def __init__(self, status, message=None, line=None):
        self.status = _status(status)
        self.message = message if message is not None else status_string(status)
        self.line = line
        super().__init__(self.status, self.message)

    def __str__(self):
        name = self.status.name if isinstance(self.status, Status) else str(self.status)
        return "%s [%s]" % (self.message, name)


class ClosedWorldError(CaromError):
    """The world was closed: neither it nor its bodies can be used any more."""


def _check(status, what):
    if status != 0:
        raise CaromError(status, "%s: %s" % (what, status_string(status)))


def _bits(value, what):
    if not isinstance(value, int) or isinstance(value, bool):
        raise TypeError("%s must be an int, got %r" % (what, value))
    if not 0 <= value <= 0xFFFFFFFF:
        raise ValueError("%s must fit in 32 bits, got %r" % (what, value))
    return value


def _int32(value, what):
    if not isinstance(value, int) or isinstance(value, bool):
        raise TypeError("%s must be an int, got %r" % (what, value))
    if not -2**31 <= value < 2**31:
        raise ValueError("%s must fit in an int32, got %r" % (what, value))
    return value


def _finite(value, what):
    # Plain numbers go to C as doubles; anything else is a caller's error
    # better reported here than as a ctypes ArgumentError.
    try:
        return float(value)
    except (TypeError, ValueError):
        raise TypeError("%s must be a number, got %r" % (what, value)) from None


def _pair(value, what):
    try:
        x, y = value
    except (TypeError, ValueError):
        raise TypeError("%s must be an (x, y) pair, got %r" % (what, value)) from None
    return _finite(x, what), _finite(y, what)


def _world_def(gravity=(0.0, 0.0), restitution=0.0, friction=0.0, substeps=4,
               iterations=1, position_correction=0.2, slop=0.01,
               narrow_phase=NarrowPhase.SAT, manifold_tolerance=0.01):
    d = _native.new_def(_native.WorldDef)
    d.gravity_x, d.gravity_y = _pair(gravity, "gravity")
    d.restitution = _finite(restitution, "restitution")
    d.friction = _finite(friction, "friction")
    d.substeps = int(substeps)
    d.iterations = int(iterations)
    d.position_correction = _finite(position_correction, "position_correction")
    d.slop = _finite(slop, "slop")
    if isinstance(narrow_phase, str):
        try:
            narrow_phase = NarrowPhase[narrow_phase.upper().replace("-", "_")]
        except KeyError:
            raise ValueError("narrow_phase must be 'sat' or 'vertex_edge', got %r"
                             % narrow_phase) from None
    d.narrow_phase = int(narrow_phase)
    d.manifold_tolerance = _finite(manifold_tolerance, "manifold_tolerance")
    return d


Contact = collections.namedtuple("Contact", "a b point normal depth")
Contact.__doc__ = """A contact point: bodies a and b, the point (x, y), the unit
normal (nx, ny) from a to b, and the penetration depth (negative when the
bodies are apart but within the contact margin), as found at the start of the
update, or at the touch for a point an impact moved within it."""


class Circle:
    """A circle of a compound body (World.add_compound), centred on `offset`
    in body coordinates. density, restitution and friction default to the
    body's (None)."""

    def __init__(self, radius, offset=(0.0, 0.0), density=None, restitution=None, friction=None):
        self.radius = _finite(radius, "radius")
        self.offset = _pair(offset, "offset")
        self.density, self.restitution, self.friction = density, restitution, friction

    def _fill(self, d, keep):
        d.kind = _native.SHAPE_CIRCLE
        d.x, d.y = self.offset
        d.radius = self.radius


class Polygon:
    """A simple polygon (convex or concave, either winding) of a compound
    body: its points in body coordinates, turned by `angle` and then moved by
    `offset`. density, restitution and friction as Circle."""

    def __init__(self, points, offset=(0.0, 0.0), angle=0.0, density=None, restitution=None,
                 friction=None):
        self.points = [_pair(p, "a polygon vertex") for p in points]
        self.offset = _pair(offset, "offset")
        self.angle = _finite(angle, "angle")
        self.density, self.restitution, self.friction = density, restitution, friction

    def _fill(self, d, keep):
        xy = (ctypes.c_double * max(2 * len(self.points), 1))()
        for k, (px, py) in enumerate(self.points):
            xy[2 * k], xy[2 * k + 1] = px, py
        keep.append(xy)  # alive until the C call returns
        d.kind = _native.SHAPE_POLYGON
        d.x, d.y = self.offset
        d.angle = self.angle
        d.xy = ctypes.cast(xy, _native.c_double_p)
        d.count = min(len(self.points), 2**31 - 1)


class Box(Polygon):
    """A width x height box of a compound body, centred on `offset`, turned
    by `angle`."""

    def __init__(self, width, height, offset=(0.0, 0.0), angle=0.0, density=None,
                 restitution=None, friction=None):
        w, h = 0.5 * _finite(width, "width"), 0.5 * _finite(height, "height")
        Polygon.__init__(self, [(-w, -h), (w, -h), (w, h), (-w, h)], offset, angle, density,
                         restitution, friction)


#: One shape of a body as Body.shapes reports it, in world coordinates:
#: kind ('circle' or 'polygon'), center (a polygon's centroid), radius (a
#: polygon's farthest vertex from it), vertices ([] for a circle), and the
#: density, restitution and friction its contacts use.
ShapeInfo = collections.namedtuple(
    "ShapeInfo", "kind center radius vertices density restitution friction")


class World:
    """A simulation world (carom_world).

    World(gravity=(0, 0), restitution=0, friction=0, substeps=4, iterations=1,
          position_correction=0.2, slop=0.01, narrow_phase="sat",
          manifold_tolerance=0.01)

    Use it as a context manager, or call close(); a world that is garbage
    collected is closed too. Bodies keep their world alive.
    """

    def __init__(self, gravity=(0.0, 0.0), **settings):
        d = _world_def(gravity, **settings)
        ptr = ctypes.c_void_p()
        _check(_lib.carom_world_init(ctypes.byref(ptr), ctypes.byref(d)), "World")
        self._adopt(ptr)

    def _adopt(self, ptr):
        self._ptr = ptr
        self._finalizer = weakref.finalize(self, _lib.carom_world_destroy, ptr)
        self._callbacks = {}
        self._user_data = {}

    @classmethod
    def _loaded(cls, loader, source, settings):
        d = _world_def(**settings) if settings else None
        err = _native.SceneError()
        err.size = ctypes.sizeof(err)
        ptr = ctypes.c_void_p()
        status = loader(ctypes.byref(ptr), source, None if d is None else ctypes.byref(d),
                        ctypes.byref(err))
        if status != 0:
            message = err.message.decode("utf-8", "replace") or status_string(status)
            raise CaromError(status, message, err.line or None)
        world = cls.__new__(cls)
        world._adopt(ptr)
        return world

    @classmethod
    def from_scene_text(cls, text, **settings):
        """Build a world from scene text (docs/scenes.md). Settings given here
        apply where the scene does not set them. A bad scene raises CaromError
        with `line` set."""
        data = text.encode("utf-8") if isinstance(text, str) else bytes(text)
        return cls._loaded(lambda w, src, d, e: _lib.carom_scene_load_text(w, src, len(src), d, e),
                           data, settings)

    @classmethod
    def from_scene(cls, path, **settings):
        """Build a world from a scene file; Status.IO if it cannot be read."""
        return cls._loaded(_lib.carom_scene_load_file, os.fsencode(path), settings)

    # ------------------------------------------------------------ lifecycle
    def close(self):
        """Destroy the world and its bodies. Safe to call twice."""
        if self._ptr is not None:
            self._finalizer()
            self._ptr = None

    @property
    def closed(self):
        return self._ptr is None

    def __enter__(self):
        self._handle()
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __repr__(self):
        if self._ptr is None:
            return "<carom.World closed>"
        return "<carom.World with %d bodies>" % len(self)

    def _handle(self, for_body=False, for_joint=False):
        if self._ptr is None:
            if for_body:
                raise ClosedWorldError(Status.STALE_BODY, "the body's world was closed")
            if for_joint:
                raise ClosedWorldError(Status.STALE_JOINT, "the joint's world was closed")
            raise ClosedWorldError(Status.NULL_ARGUMENT, "the world was closed")
        return self._ptr

    # ----------------------------------------------------------- simulation
    def step(self, dt):
        """Advance by dt; then the callbacks of on_contact see the events."""
        self._step(dt)
        if self._callbacks:
            for ev in self.events():
                fn = self._callbacks.get(ev.type)
                if fn is not None:
                    fn(ev)

    def _step(self, dt):
        """Advance the world by dt (> 0, finite)."""
        _check(_lib.carom_world_update(self._handle(), _finite(dt, "dt")), "step")

    @property
    def gravity(self):
        gx, gy = ctypes.c_double(), ctypes.c_double()
        _check(_lib.carom_world_get_gravity(self._handle(), ctypes.byref(gx), ctypes.byref(gy)),
               "gravity")
        return (gx.value, gy.value)

    @gravity.setter
    def gravity(self, value):
        gx, gy = _pair(value, "gravity")
        _check(_lib.carom_world_set_gravity(self._handle(), gx, gy), "gravity")

    @property
    def effects(self):
        """Names of the active effect stages, e.g. ['gravity', 'friction']."""
        mask = _lib.carom_world_get_effects(self._handle())
        return [_lib.carom_effect_name(1 << i).decode() for i in range(31)
                if mask & (1 << i) and _lib.carom_effect_name(1 << i)]

    def set_restitution(self, e):
        """World default restitution e in [0, 1]."""
        _check(_lib.carom_world_set_restitution(self._handle(), _finite(e, "restitution")), "restitution")

    def set_friction(self, mu):
        """World default friction mu >= 0."""
        _check(_lib.carom_world_set_friction(self._handle(), _finite(mu, "friction")), "friction")

    def set_central_gravity(self, x, y, gm, softening=0.0):
        """Attraction to a point mass at (x, y); gm = 0 switches it off."""
        _check(_lib.carom_world_set_central_gravity(self._handle(), x, y, gm, softening),
               "central gravity")

    def set_damping(self, linear, angular=0.0):
        """Velocities decay as exp(-linear t), spins as exp(-angular t)."""
        _check(_lib.carom_world_set_damping(self._handle(), linear, angular), "damping")

    def set_continuous(self, enabled):
        """Continuous collision for every body (on by default; switched off,
        a body that moves more than half its size in a step still has it):
        contacts met before they overlap, impacts at their time within the
        step."""
        _check(_lib.carom_world_set_continuous(self._handle(), 1 if enabled else 0), "continuous")

    def set_sleeping(self, enabled):
        """Put bodies at rest to sleep (True) or wake everything (False)."""
        _check(_lib.carom_world_set_sleeping(self._handle(), 1 if enabled else 0), "sleeping")

    def __len__(self):
        return _lib.carom_world_body_count(self._handle())

    @property
    def bodies(self):
        """The live bodies, in creation order."""
        h = self._handle()
        n = _lib.carom_world_get_bodies(h, None, 0)
        ids = (_native.c_body_id * max(n, 1))()
        n = min(n, _lib.carom_world_get_bodies(h, ids, n))
        return [Body(self, ids[i]) for i in range(n)]

    def detect(self):
        """Run collision detection alone on the current positions and return
        the contacts."""
        _check(_lib.carom_world_detect(self._handle()), "detect")
        return self.contacts()

    def contacts(self):
        """The contact points found by the last step (or detect)."""
        h = self._handle()
        a, b = _native.c_body_id(), _native.c_body_id()
        px, py, nx, ny, depth = (ctypes.c_double() for _ in range(5))
        out = []
        for i in range(_lib.carom_world_contact_count(h)):
            _check(_lib.carom_world_get_contact(
                h, i, ctypes.byref(a), ctypes.byref(b), ctypes.byref(px), ctypes.byref(py),
                ctypes.byref(nx), ctypes.byref(ny), ctypes.byref(depth)), "contacts")
            out.append(Contact(Body(self, a.value), Body(self, b.value), (px.value, py.value),
                               (nx.value, ny.value), depth.value))
        return out

    # -------------------------------------------------------------- queries
    def raycast(self, start, end, mask=ALL):
        """The first body the segment from start to end enters (among those
        whose category & mask is non-zero), as a RayHit, or None."""
        x0, y0 = _pair(start, "start")
        x1, y1 = _pair(end, "end")
        hit = _native.RayHit()
        _check(_lib.carom_world_cast_ray(self._handle(), x0, y0, x1, y1, _bits(mask, "mask"),
                                         ctypes.byref(hit)), "raycast")
        if hit.body == 0:
            return None
        return RayHit(Body(self, hit.body), (hit.x, hit.y), (hit.nx, hit.ny), hit.fraction)

    def _listed(self, call, what, handle=None):
        # ids from a call of carom_world_query_aabb's kind (a count, or
        # minus a status), as Body handles, or Joint ones (handle=Joint:
        # carom_joint_id is the same uint64 as carom_body_id)
        n = call(None, 0)
        if n < 0:
            _check(-n, what)
        ids = (_native.c_body_id * max(n, 1))()
        n = min(n, call(ids, n))
        return [(handle or Body)(self, ids[i]) for i in range(n)]

    def query_point(self, point, mask=ALL):
        """The bodies whose shape contains the point, in creation order."""
        x, y = _pair(point, "point")
        h, m = self._handle(), _bits(mask, "mask")
        return self._listed(lambda ids, cap: _lib.carom_world_query_point(h, x, y, m, ids, cap),
                            "query_point")

    def query_aabb(self, lower, upper, mask=ALL):
        """The bodies whose bounding box overlaps the box from lower to upper."""
        x0, y0 = _pair(lower, "lower")
        x1, y1 = _pair(upper, "upper")
        h, m = self._handle(), _bits(mask, "mask")
        return self._listed(
            lambda ids, cap: _lib.carom_world_query_aabb(h, x0, y0, x1, y1, m, ids, cap), "query_aabb")

    # --------------------------------------------------------------- events
    def events(self):
        """The events of the last step, as Event tuples."""
        h = self._handle()
        n = _lib.carom_world_get_events(h, None, 0)
        if n < 0:
            _check(-n, "events")
        buf = (_native.ContactEvent * max(n, 1))()
        n = min(n, _lib.carom_world_get_events(h, buf, n))
        return [Event(EventType(e.type), Body(self, e.a), Body(self, e.b), (e.x, e.y), (e.nx, e.ny),
                      e.approach_speed, e.normal_impulse) for e in buf[:n]]

    def on_contact(self, begin=None, end=None, sensor_begin=None, sensor_end=None):
        """Call these with each Event of their kind after every step (None:
        not called)."""
        for kind, fn in ((EventType.CONTACT_BEGIN, begin), (EventType.CONTACT_END, end),
                         (EventType.SENSOR_BEGIN, sensor_begin), (EventType.SENSOR_END, sensor_end)):
            if fn is None:
                self._callbacks.pop(kind, None)
            elif not callable(fn):
                raise TypeError("on_contact callbacks must be callable, got %r" % (fn,))
            else:
                self._callbacks[kind] = fn

    def clear_forces(self):
        """Drop the forces and torques applied since the last step."""
        _check(_lib.carom_world_clear_forces(self._handle()), "clear_forces")

    # ----------------------------------------------------------- debug draw
    def debug_draw(self, polygon=None, circle=None, segment=None, point=None, bodies=True,
                   contacts=True, joint=None, joints=True):
        """Call polygon(points, body), circle(center, radius, angle, body),
        joint(type, points, joint), segment(p0, p1) and point(p) for every
        body, joint and contact (carom_world_draw: the bodies, then the
        joints, then the contacts); any may be None. A joint's points are
        four (x, y): the centre of body a, the anchor on a, the anchor on b,
        the centre of body b (for a joint to the world the first two are its
        fixed point; for a mouse joint, its target)."""
        d = _native.DebugDraw()
        _check(_lib.carom_debug_draw_init(ctypes.byref(d), ctypes.sizeof(d)), "debug_draw")
        errors = []

        def guard(fn):
            def call(*args):
                if errors:
                    return
                try:
                    fn(*args)
                except BaseException as exc:  # raised again after the C call
                    errors.append(exc)
            return call
        if polygon is not None:
            d.polygon = _native.DRAW_POLYGON_FN(guard(
                lambda xy, n, b, u: polygon([(xy[2 * k], xy[2 * k + 1]) for k in range(n)],
                                            Body(self, b))))
        if circle is not None:
            d.circle = _native.DRAW_CIRCLE_FN(guard(
                lambda x, y, r, a, b, u: circle((x, y), r, a, Body(self, b))))
        if segment is not None:
            d.segment = _native.DRAW_SEGMENT_FN(guard(
                lambda x0, y0, x1, y1, u: segment((x0, y0), (x1, y1))))
        if point is not None:
            d.point = _native.DRAW_POINT_FN(guard(lambda x, y, u: point((x, y))))
        if joint is not None:
            d.joint = _native.DRAW_JOINT_FN(guard(
                lambda t, xy, j, u: joint(_joint_type(t), [(xy[2 * k], xy[2 * k + 1])
                                                           for k in range(4)], Joint(self, j))))
        d.draw_bodies = 1 if bodies else 0
        d.draw_contacts = 1 if contacts else 0
        d.draw_joints = 1 if joints else 0
        _check(_lib.carom_world_draw(self._handle(), ctypes.byref(d)), "debug_draw")
        if errors:
            raise errors[0]

    # --------------------------------------------------------------- bodies
    def _body_def(self, x=0.0, y=0.0, angle=0.0, vx=0.0, vy=0.0, spin=0.0, density=1.0,
                  restitution=None, friction=None, static=False, kinematic=False, sensor=False,
                  category=1, mask=ALL, group=0):
        d = _native.new_def(_native.BodyDef)
        if static and kinematic:
            raise ValueError("a body is static or kinematic, not both")
        d.type = (_native.STATIC if static else _native.KINEMATIC if kinematic
                  else _native.DYNAMIC)
        d.sensor = 1 if sensor else 0
        d.category, d.mask = _bits(category, "category"), _bits(mask, "mask")
        d.group = _int32(group, "group")
        d.x, d.y = _finite(x, "x"), _finite(y, "y")
        d.angle = _finite(angle, "angle")
        d.vx, d.vy = _finite(vx, "vx"), _finite(vy, "vy")
        d.spin = _finite(spin, "spin")
        d.density = _finite(density, "density")
        # None (and the C convention, a negative value) mean the world's default.
        d.restitution = -1.0 if restitution is None else _finite(restitution, "restitution")
        d.friction = -1.0 if friction is None else _finite(friction, "friction")
        return d

    def _add(self, what, call, options):
        h = self._handle()
        d = self._body_def(**options)
        new = _native.c_body_id()
        _check(call(h, ctypes.byref(d), ctypes.byref(new)), what)
        return Body(self, new.value)

    def add_circle(self, radius, **options):
        """A circle of the given radius centred on (x, y). Options: x, y,
        angle, vx, vy, spin, density, restitution, friction, static,
        kinematic (moves at vx, vy, spin whatever touches it), sensor
        (reports overlaps as events, pushes nothing), category, mask and
        group (collision filtering: docs/api.md)."""
        r = _finite(radius, "radius")
        return self._add("add_circle",
                         lambda h, d, i: _lib.carom_world_add_circle(h, d, r, i), options)

    def add_box(self, width, height, **options):
        """A width x height box centred on (x, y); options as add_circle."""
        w, hh = _finite(width, "width"), _finite(height, "height")
        return self._add("add_box",
                         lambda h, d, i: _lib.carom_world_add_box(h, d, w, hh, i), options)

    def add_regular(self, n, side, **options):
        """A regular polygon of n sides of length `side`, one vertex on the +x
        axis before rotation; options as add_circle."""
        if isinstance(n, float) and n.is_integer():
            n = int(n)
        if not isinstance(n, int):
            raise TypeError("n must be an int, got %r" % (n,))
        count = max(min(n, 2**31 - 1), -2**31)
        s = _finite(side, "side")
        return self._add("add_regular",
                         lambda h, d, i: _lib.carom_world_add_regular(h, d, count, s, i), options)

    def add_compound(self, shapes, **options):
        """A body made of several shapes (Circle, Box, Polygon) given in body
        coordinates, each with its own density and material: the centre of
        mass of their union is placed at (x, y) and the body turned by
        `angle` about it; mass and inertia are the union's (parallel axis
        theorem). Options as add_circle (density: the shapes' default)."""
        shapes = list(shapes)
        for sh in shapes:
            if not isinstance(sh, (Circle, Polygon)):
                raise TypeError("a compound's shapes are Circle, Box or Polygon, got %r" % (sh,))
        defs = (_native.ShapeDef * max(len(shapes), 1))()
        keep = []
        for k, sh in enumerate(shapes):
            d = _native.new_def(_native.ShapeDef)
            sh._fill(d, keep)
            d.density = -1.0 if sh.density is None else _finite(sh.density, "density")
            d.restitution = -1.0 if sh.restitution is None else _finite(sh.restitution, "restitution")
            d.friction = -1.0 if sh.friction is None else _finite(sh.friction, "friction")
            defs[k] = d
        count = min(len(shapes), 2**31 - 1)
        return self._add("add_compound",
                         lambda h, d, i: _lib.carom_world_add_compound(h, d, defs, count, i), options)

    def add_polygon(self, points, **options):
        """A simple polygon (convex or concave, either winding) from (x, y)
        points; its centroid is placed at (x, y). Options as add_circle."""
        pts = [_pair(p, "a polygon vertex") for p in points]
        xy = (ctypes.c_double * max(2 * len(pts), 1))()
        for k, (px, py) in enumerate(pts):
            xy[2 * k], xy[2 * k + 1] = px, py
        count = min(len(pts), 2**31 - 1)
        return self._add("add_polygon",
                         lambda h, d, i: _lib.carom_world_add_polygon(h, d, xy, count, i), options)

    # --------------------------------------------------------------- joints
    def add_joint(self, type, a=None, b=None, x=0.0, y=0.0, x2=0.0, y2=0.0, axis=None,
                  limit=None, motor=None, spring=None, collide_connected=False, length=None,
                  max_motor_force=None, max_motor_torque=None):
        """A joint between bodies a and b (carom_world_add_joint), returned
        as a Joint. `type` is a JointType or its name ('revolute',
        'prismatic', 'distance', 'weld', 'wheel', 'motor', 'mouse'). a may be
        None for the world itself (a fixed point; a mouse joint's a must be
        None); b must be a Body, and one of the two dynamic. (x, y) is the
        anchor in world coordinates at creation (distance: the anchor on a,
        and (x2, y2) the one on b; mouse: the point of b grabbed and the
        first target). axis (ax, ay): prismatic and wheel joints' axis in
        world coordinates, any non-zero length (required for them).
        limit=(lower, upper), motor=(speed, max_force) and
        spring=(hertz, damping_ratio) switch those on (None: off); what
        each means depends on the type (docs/bindings.md, carom.h).
        collide_connected: a and b still collide. length: a distance
        joint's rest length (None: the anchors' distance at creation).
        max_motor_force and max_motor_torque: a motor joint's bounds (a
        mouse joint's force bound, None: unbounded), without turning a
        motor on. Bad input raises CaromError and adds nothing."""
        kind = _joint_type_of(type)
        bodies = []
        for name, body, optional in (("a", a, True), ("b", b, False)):
            if body is None and optional:
                bodies.append(0)
                continue
            if not isinstance(body, Body):
                raise TypeError("%s must be a Body%s, got %r"
                                % (name, " or None (the world)" if optional else "", body))
            if body._world is not self:
                raise ValueError("%s is a body of another world" % name)
            bodies.append(body._id)
        if motor is not None and max_motor_force is not None:
            raise ValueError("give motor=(speed, max_force) or max_motor_force, not both")
        h = self._handle()
        d = _native.new_def(_native.JointDef)
        d.type = kind
        d.a, d.b = bodies
        d.x, d.y = _finite(x, "x"), _finite(y, "y")
        d.x2, d.y2 = _finite(x2, "x2"), _finite(y2, "y2")
        if axis is not None:
            d.axis_x, d.axis_y = _pair(axis, "axis")
        if limit is not None:
            d.enable_limit = 1
            d.lower, d.upper = _pair(limit, "limit")
        if motor is not None:
            d.enable_motor = 1
            d.motor_speed, d.max_motor_force = _pair(motor, "motor")
        elif max_motor_force is not None:
            d.max_motor_force = _finite(max_motor_force, "max_motor_force")
        if spring is not None:
            d.enable_spring = 1
            d.hertz, d.damping_ratio = _pair(spring, "spring")
        d.collide_connected = 1 if collide_connected else 0
        d.length = 0.0 if length is None else _finite(length, "length")
        if max_motor_torque is not None:
            d.max_motor_torque = _finite(max_motor_torque, "max_motor_torque")
        new = _native.c_joint_id()
        _check(_lib.carom_world_add_joint(h, ctypes.byref(d), ctypes.byref(new)), "add_joint")
        return Joint(self, new.value)

    @property
    def joint_count(self):
        """How many live joints the world holds."""
        return _lib.carom_world_joint_count(self._handle())

    @property
    def joints(self):
        """The live joints, as Joint handles in slot order (a removed
        joint's slot is reused by the next joint added)."""
        h = self._handle()
        return self._listed(lambda ids, cap: _lib.carom_world_get_joints(h, ids, cap), "joints",
                            Joint)


def _joint_type_of(value):
    """A joint type for the C def: a JointType, its name, or an int (which
    the library checks: an unknown one is Status.BAD_ARGUMENT)."""
    if isinstance(value, str):
        try:
            return int(JointType[value.upper()])
        except KeyError:
            raise ValueError("type must be one of %s, got %r"
                             % (", ".join(repr(t.name.lower()) for t in JointType), value)) from None
    return _int32(int(value) if isinstance(value, enum.IntEnum) else value, "type")


def _joint_type(value):
    """A JointType for a known code, the plain int for one a newer library added."""
    try:
        return JointType(value)
    except ValueError:
        return int(value)


class _Handle:
    """What a Body and a Joint share: an id (a non-zero 64-bit integer, the
    library's carom_body_id or carom_joint_id) in one World; two handles are
    equal when they name the same thing in the same world."""

    __slots__ = ("_world", "_id", "__weakref__")

    def __init__(self, world, handle_id):
        self._world = world
        self._id = int(handle_id)

    @property
    def id(self):
        """The library's id."""
        return self._id

    @property
    def world(self):
        return self._world

    @property
    def index(self):
        """The id's slot (1-based) and generation: what the id is made of."""
        return (self._id & 0xFFFFFFFF, self._id >> 32)

    def __eq__(self, other):
        return type(other) is type(self) and other._world is self._world and other._id == self._id

    def __hash__(self):
        return hash((id(self._world), self._id, type(self).__name__))


class Joint(_Handle):
    """A handle to one joint of a World (version 0.2): its id and its
    world. The handle of a removed joint (removing one of its bodies
    removes it too) raises CaromError(Status.STALE_JOINT); one whose world
    was closed raises ClosedWorldError."""

    __slots__ = ()

    def __repr__(self):
        if not self.is_alive:
            return "<carom.Joint %d.%d (gone)>" % self.index
        kind = self.type
        a, b = self.bodies
        return "<carom.Joint %d.%d %s: %s and body %d.%d>" % (
            self.index + (kind.name.lower() if isinstance(kind, JointType) else kind,
                          "the world" if a is None else "body %d.%d" % a.index) + b.index)

    def _h(self):
        return self._world._handle(for_joint=True)

    @property
    def is_alive(self):
        """True while the joint exists (False once removed, with one of its
        bodies or on its own, or its world closed)."""
        h = self._world._ptr
        return h is not None and _lib.carom_joint_check(h, self._id) == 0

    def remove(self):
        """Remove the joint from its world; the handle becomes stale."""
        _check(_lib.carom_world_remove_joint(self._h(), self._id), "remove")

    def _bodies(self):
        kind, a, b = ctypes.c_int(), _native.c_body_id(), _native.c_body_id()
        _check(_lib.carom_joint_get_bodies(self._h(), self._id, ctypes.byref(kind), ctypes.byref(a),
                                           ctypes.byref(b)), "joint bodies")
        return kind.value, a.value, b.value

    @property
    def type(self):
        """The JointType."""
        return _joint_type(self._bodies()[0])

    @property
    def bodies(self):
        """(a, b): the two Bodies, a None for a joint to the world."""
        _, a, b = self._bodies()
        return (None if a == 0 else Body(self._world, a), Body(self._world, b))

    @property
    def a(self):
        return self.bodies[0]

    @property
    def b(self):
        return self.bodies[1]

    @property
    def anchors(self):
        """((ax, ay), (bx, by)): the anchors on a and on b now, in world
        coordinates (mouse joint: the target, then b's grabbed point)."""
        v = [ctypes.c_double() for _ in range(4)]
        _check(_lib.carom_joint_get_anchors(self._h(), self._id, *(ctypes.byref(x) for x in v)),
               "anchors")
        return ((v[0].value, v[1].value), (v[2].value, v[3].value))

    @property
    def reaction(self):
        """Reaction(fx, fy, torque): the constraint force on body b (at its
        anchor) and torque, averaged over the last step; zero before the
        first step."""
        v = [ctypes.c_double() for _ in range(3)]
        _check(_lib.carom_joint_get_reaction(self._h(), self._id, *(ctypes.byref(x) for x in v)),
               "reaction")
        return Reaction(v[0].value, v[1].value, v[2].value)

    def set_motor(self, speed=0.0, max_force=0.0, enabled=True):
        """Turn the motor on (or off: enabled=False) with its speed and its
        most force (a torque for revolute and wheel joints); wakes the
        bodies. Motor, mouse and weld joints have no such motor
        (Status.BAD_ARGUMENT)."""
        _check(_lib.carom_joint_set_motor(self._h(), self._id, 1 if enabled else 0,
                                          _finite(speed, "speed"), _finite(max_force, "max_force")),
               "set_motor")

    def set_limit(self, lower=0.0, upper=0.0, enabled=True):
        """Turn the limit on (or off: enabled=False) with its range, lower
        <= upper: the relative angle from creation (revolute), the
        translation (prismatic, wheel) or the length (distance); wakes the
        bodies. Weld, motor and mouse joints have no limit
        (Status.BAD_ARGUMENT)."""
        _check(_lib.carom_joint_set_limit(self._h(), self._id, 1 if enabled else 0,
                                          _finite(lower, "lower"), _finite(upper, "upper")),
               "set_limit")

    def set_spring(self, hertz=0.0, damping_ratio=0.0, enabled=True):
        """Turn the spring on (or off: enabled=False) with its frequency and
        damping ratio (both >= 0; 1 is critical damping), as add_joint's
        spring=(hertz, damping_ratio); wakes the bodies. A mouse joint's are
        its pull (0: its defaults, 5 Hz and 0.7; `enabled` is ignored); a
        motor joint has none (Status.BAD_ARGUMENT)."""
        _check(_lib.carom_joint_set_spring(self._h(), self._id, 1 if enabled else 0,
                                           _finite(hertz, "hertz"),
                                           _finite(damping_ratio, "damping_ratio")),
               "set_spring")

    def set_target(self, x, y, angle=0.0):
        """Move the target; wakes the bodies. Mouse joint: the world point
        b's grabbed point is pulled to (angle ignored). Motor joint: the
        pose b is driven to, b's centre in a's frame and b's angle less
        a's. Other types: Status.BAD_ARGUMENT."""
        _check(_lib.carom_joint_set_target(self._h(), self._id, _finite(x, "x"), _finite(y, "y"),
                                           _finite(angle, "angle")), "set_target")


class Body(_Handle):
    """A handle to one body of a World: its id and its world. The handle of
    a removed body raises CaromError(Status.STALE_BODY); one whose world was
    closed raises ClosedWorldError."""

    __slots__ = ()

    def __repr__(self):
        if not self.is_alive:
            return "<carom.Body %d.%d (gone)>" % self.index
        return "<carom.Body %d.%d %s %s at (%g, %g)>" % (self.index + (self.type, self.shape)
                                                         + self.position)

    def _h(self):
        return self._world._handle(for_body=True)

    def _get(self, fn, what, n):
        out = [ctypes.c_double() for _ in range(n)]
        _check(fn(self._h(), self._id, *(ctypes.byref(v) for v in out)), what)
        return tuple(v.value for v in out)

    @property
    def is_alive(self):
        """True while the body exists (False once removed or its world closed)."""
        h = self._world._ptr
        return h is not None and _lib.carom_body_check(h, self._id) == 0

    def remove(self):
        """Remove the body from its world; the handle becomes stale. What it
        touched wakes, and its weight comes off the impulses of the contacts
        beneath it, which the next update starts from."""
        _check(_lib.carom_world_remove_body(self._h(), self._id), "remove")
        self._world._user_data.pop(self._id, None)

    @property
    def joints(self):
        """The live joints the body is one of the two bodies of, as Joint
        handles (in a fixed order, not that of World.joints)."""
        h, body = self._h(), self._id
        return self._world._listed(
            lambda ids, cap: _lib.carom_body_get_joints(h, body, ids, cap), "joints", Joint)

    @property
    def awake(self):
        """False while the body sleeps."""
        v = ctypes.c_int32()
        _check(_lib.carom_body_is_awake(self._h(), self._id, ctypes.byref(v)), "awake")
        return bool(v.value)

    def wake(self):
        _check(_lib.carom_body_wake(self._h(), self._id), "wake")

    def set_bullet(self, bullet=True):
        """Keep continuous collision for this body when the world's is off."""
        _check(_lib.carom_body_set_bullet(self._h(), self._id, 1 if bullet else 0), "bullet")

    def set_fixed_rotation(self, fixed=True):
        """Make the body non-rotating (True) or rotating again (False)."""
        _check(_lib.carom_body_set_fixed_rotation(self._h(), self._id, 1 if fixed else 0),
               "fixed rotation")

    @property
    def position(self):
        """Centre of mass (x, y)."""
        return self._get(_lib.carom_body_get_position, "position", 2)

    @position.setter
    def position(self, value):
        x, y = _pair(value, "position")
        _check(_lib.carom_body_set_position(self._h(), self._id, x, y), "position")

    @property
    def angle(self):
        """Rotation in radians, counter-clockwise."""
        return self._get(_lib.carom_body_get_angle, "angle", 1)[0]

    @angle.setter
    def angle(self, value):
        _check(_lib.carom_body_set_angle(self._h(), self._id, _finite(value, "angle")), "angle")

    @property
    def velocity(self):
        """Linear velocity (vx, vy)."""
        return self._get(_lib.carom_body_get_velocity, "velocity", 2)

    @velocity.setter
    def velocity(self, value):
        vx, vy = _pair(value, "velocity")
        _check(_lib.carom_body_set_velocity(self._h(), self._id, vx, vy), "velocity")

    @property
    def spin(self):
        """Angular velocity, radians per time unit."""
        return self._get(_lib.carom_body_get_spin, "spin", 1)[0]

    @spin.setter
    def spin(self, value):
        _check(_lib.carom_body_set_spin(self._h(), self._id, _finite(value, "spin")), "spin")

    @property
    def mass(self):
        """Mass (0 for a static body)."""
        return self._get(_lib.carom_body_get_mass, "mass", 3)[0]

    @property
    def inertia(self):
        """Moment of inertia about the centre of mass (0 for a static body)."""
        return self._get(_lib.carom_body_get_mass, "inertia", 3)[1]

    @property
    def area(self):
        return self._get(_lib.carom_body_get_mass, "area", 3)[2]

    @property
    def is_static(self):
        kind = ctypes.c_int()
        _check(_lib.carom_body_get_type(self._h(), self._id, ctypes.byref(kind)), "is_static")
        return kind.value == _native.STATIC

    @property
    def shape(self):
        """'circle', 'polygon' (boxes and regular polygons are polygons) or
        'compound' (World.add_compound: see shapes)."""
        kind, radius = ctypes.c_int(), ctypes.c_double()
        _check(_lib.carom_body_get_shape(self._h(), self._id, ctypes.byref(kind),
                                         ctypes.byref(radius)), "shape")
        return {_native.SHAPE_CIRCLE: "circle", _native.SHAPE_POLYGON: "polygon",
                _native.SHAPE_COMPOUND: "compound"}[kind.value]

    @property
    def shapes(self):
        """The shapes the body is made of, as ShapeInfo in world coordinates
        (one for a circle or polygon body)."""
        h = self._h()
        n = ctypes.c_int32()
        _check(_lib.carom_body_get_shape_count(h, self._id, ctypes.byref(n)), "shapes")
        out = []
        for k in range(n.value):
            kind, x, y, r = ctypes.c_int(), ctypes.c_double(), ctypes.c_double(), ctypes.c_double()
            count = ctypes.c_int32()
            _check(_lib.carom_body_get_shape_geometry(
                h, self._id, k, ctypes.byref(kind), ctypes.byref(x), ctypes.byref(y),
                ctypes.byref(r), None, 0, ctypes.byref(count)), "shapes")
            xy = (ctypes.c_double * max(2 * count.value, 1))()
            _check(_lib.carom_body_get_shape_geometry(
                h, self._id, k, None, None, None, None, xy, count.value, None), "shapes")
            rho, e, mu = ctypes.c_double(), ctypes.c_double(), ctypes.c_double()
            _check(_lib.carom_body_get_shape_material(h, self._id, k, ctypes.byref(rho),
                                                      ctypes.byref(e), ctypes.byref(mu)), "shapes")
            out.append(ShapeInfo(
                "circle" if kind.value == _native.SHAPE_CIRCLE else "polygon", (x.value, y.value),
                r.value, [(xy[2 * i], xy[2 * i + 1]) for i in range(count.value)], rho.value,
                e.value, mu.value))
        return out

    @property
    def radius(self):
        """A circle's radius (None for a polygon)."""
        kind, radius = ctypes.c_int(), ctypes.c_double()
        _check(_lib.carom_body_get_shape(self._h(), self._id, ctypes.byref(kind),
                                         ctypes.byref(radius)), "radius")
        return radius.value if kind.value == _native.SHAPE_CIRCLE else None

    @property
    def restitution(self):
        """The restitution in effect (after the world's default)."""
        return self._get(_lib.carom_body_get_material, "restitution", 2)[0]

    @property
    def friction(self):
        """The friction coefficient in effect (after the world's default)."""
        return self._get(_lib.carom_body_get_material, "friction", 2)[1]

    # ------------------------------------------------ forces and impulses
    def _at(self, point):
        return self.position if point is None else _pair(point, "point")

    def apply_force(self, force, point=None):
        """A force (fx, fy) at a world point (default: the centre of mass),
        acting over the next step."""
        fx, fy = _pair(force, "force")
        px, py = self._at(point)
        _check(_lib.carom_body_apply_force(self._h(), self._id, fx, fy, px, py), "apply_force")

    def apply_torque(self, torque):
        """A torque acting over the next step."""
        _check(_lib.carom_body_apply_torque(self._h(), self._id, _finite(torque, "torque")),
               "apply_torque")

    def apply_impulse(self, impulse, point=None):
        """An impulse (jx, jy) at a world point (default: the centre of mass):
        the velocity changes at once by J / m, the spin by r x J / I."""
        jx, jy = _pair(impulse, "impulse")
        px, py = self._at(point)
        _check(_lib.carom_body_apply_impulse(self._h(), self._id, jx, jy, px, py), "apply_impulse")

    def apply_angular_impulse(self, impulse):
        _check(_lib.carom_body_apply_angular_impulse(self._h(), self._id,
                                                     _finite(impulse, "impulse")),
               "apply_angular_impulse")

    # ------------------------------------------------- kind, filter, data
    @property
    def type(self):
        """'dynamic', 'static' or 'kinematic'."""
        kind = ctypes.c_int()
        _check(_lib.carom_body_get_type(self._h(), self._id, ctypes.byref(kind)), "type")
        return {_native.DYNAMIC: "dynamic", _native.STATIC: "static",
                _native.KINEMATIC: "kinematic"}[kind.value]

    @property
    def is_kinematic(self):
        return self.type == "kinematic"

    @property
    def is_sensor(self):
        flag = ctypes.c_int32()
        _check(_lib.carom_body_is_sensor(self._h(), self._id, ctypes.byref(flag)), "is_sensor")
        return flag.value != 0

    @property
    def filter(self):
        """(category, mask, group): collision filtering (docs/api.md)."""
        c, m, g = ctypes.c_uint32(), ctypes.c_uint32(), ctypes.c_int32()
        _check(_lib.carom_body_get_filter(self._h(), self._id, ctypes.byref(c), ctypes.byref(m),
                                          ctypes.byref(g)), "filter")
        return (c.value, m.value, g.value)

    @filter.setter
    def filter(self, value):
        try:
            category, mask, group = value
        except (TypeError, ValueError):
            raise TypeError("filter must be (category, mask, group), got %r" % (value,)) from None
        _check(_lib.carom_body_set_filter(self._h(), self._id, _bits(category, "category"),
                                          _bits(mask, "mask"), _int32(group, "group")), "filter")

    @property
    def user_data(self):
        """Any Python object kept with the body (None by default)."""
        _check(_lib.carom_body_check(self._h(), self._id), "user_data")
        return self._world._user_data.get(self._id)

    @user_data.setter
    def user_data(self, value):
        _check(_lib.carom_body_check(self._h(), self._id), "user_data")
        self._world._user_data[self._id] = value

    @property
    def vertices(self):
        """A polygon's vertices in world coordinates, counter-clockwise, as
        (x, y) tuples; [] for a circle and a compound (see shapes)."""
        h = self._h()
        count = ctypes.c_int32()
        _check(_lib.carom_body_get_vertices(h, self._id, None, 0, ctypes.byref(count)), "vertices")
        n = count.value
        if n == 0:
            return []
        xy = (ctypes.c_double * (2 * n))()
        _check(_lib.carom_body_get_vertices(h, self._id, xy, n, ctypes.byref(count)), "vertices")
        return [(xy[2 * k], xy[2 * k + 1]) for k in range(min(n, count.value))]




def draw(world, ax, contacts=True, joints=True, **style):
    """Draw a world on a matplotlib Axes (or anything with fill and plot):
    polygons and circles filled, a circle's radius marker, the joints (a
    line from body a's centre through the two anchors to body b's, the
    anchors marked), and the contact points and normals. Extra keyword
    arguments go to ax.fill."""
    import math
    style.setdefault("alpha", 0.6)
    style.setdefault("edgecolor", "black")

    def polygon(points, body):
        ax.fill([p[0] for p in points], [p[1] for p in points], **style)

    def circle(center, radius, angle, body):
        n = 32
        ax.fill([center[0] + radius * math.cos(2 * math.pi * k / n) for k in range(n)],
                [center[1] + radius * math.sin(2 * math.pi * k / n) for k in range(n)], **style)
        ax.plot([center[0], center[0] + radius * math.cos(angle)],
                [center[1], center[1] + radius * math.sin(angle)], color="black", linewidth=0.8)

    def segment(p0, p1):
        ax.plot([p0[0], p1[0]], [p0[1], p1[1]], color="red", linewidth=0.8)

    def point(p):
        ax.plot([p[0]], [p[1]], marker="o", markersize=2, color="red")

    def joint(kind, points, joint):
        ax.plot([p[0] for p in points], [p[1] for p in points], color="blue", linewidth=0.8)
        ax.plot([points[1][0], points[2][0]], [points[1][1], points[2][1]], linestyle="none",
                marker="o", markersize=3, color="blue")

    world.debug_draw(polygon, circle, segment, point, contacts=contacts, joint=joint, joints=joints)
