"""The raw C ABI of libcarom through ctypes: finding the library, the
structs that cross it, and an explicit prototype for every function.

Only the layer in carom/__init__.py should use this module directly.
"""

import ctypes
import ctypes.util
import glob
import os
import sys

#: The major version this binding is written for. The shared library's
#: soname carries the same number (libcarom.so.0); a library of another major
#: version is refused.
EXPECTED_MAJOR = 0

#: Environment variable naming the shared library to load (a full path).
LIBRARY_ENV = "CAROM_LIBRARY"


# ------------------------------------------------------------------ types

c_status = ctypes.c_int  # carom_status: an int-sized C enum
c_body_id = ctypes.c_uint64  # carom_body_id
c_world_p = ctypes.c_void_p  # carom_world * (opaque)
c_double_p = ctypes.POINTER(ctypes.c_double)
c_int32_p = ctypes.POINTER(ctypes.c_int32)
c_body_id_p = ctypes.POINTER(c_body_id)
c_joint_id = ctypes.c_uint64  # carom_joint_id (version 0.2)
c_joint_id_p = ctypes.POINTER(c_joint_id)

ALLOC_FN = ctypes.CFUNCTYPE(ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p)
FREE_FN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p)


class Allocator(ctypes.Structure):
    """carom_allocator: {alloc, free, user}; all NULL means malloc/free."""

    _fields_ = [
        ("alloc", ALLOC_FN),
        ("free", FREE_FN),
        ("user", ctypes.c_void_p),
    ]


class WorldDef(ctypes.Structure):
    """carom_world_def, version 0.2 layout (fields only ever appended)."""

    _fields_ = [
        ("size", ctypes.c_uint32),
        ("gravity_x", ctypes.c_double),
        ("gravity_y", ctypes.c_double),
        ("restitution", ctypes.c_double),
        ("friction", ctypes.c_double),
        ("substeps", ctypes.c_int32),
        ("iterations", ctypes.c_int32),
        ("position_correction", ctypes.c_double),
        ("slop", ctypes.c_double),
        ("narrow_phase", ctypes.c_int),
        ("allocator", Allocator),
        ("manifold_tolerance", ctypes.c_double),  # version 0.2
    ]


class BodyDef(ctypes.Structure):
    """carom_body_def, version 0.2 layout (fields only ever appended)."""

    _fields_ = [
        ("size", ctypes.c_uint32),
        ("type", ctypes.c_int),
        ("x", ctypes.c_double),
        ("y", ctypes.c_double),
        ("angle", ctypes.c_double),
        ("vx", ctypes.c_double),
        ("vy", ctypes.c_double),
        ("spin", ctypes.c_double),
        ("density", ctypes.c_double),
        ("restitution", ctypes.c_double),
        ("friction", ctypes.c_double),
        ("user_data", ctypes.c_void_p),  # version 0.2
        ("category", ctypes.c_uint32),
        ("mask", ctypes.c_uint32),
        ("group", ctypes.c_int32),
        ("sensor", ctypes.c_int32),
    ]


class ShapeDef(ctypes.Structure):
    """carom_shape_def (version 0.2): one shape of a compound body."""

    _fields_ = [
        ("size", ctypes.c_uint32),
        ("kind", ctypes.c_int),
        ("x", ctypes.c_double),
        ("y", ctypes.c_double),
        ("angle", ctypes.c_double),
        ("radius", ctypes.c_double),
        ("xy", ctypes.POINTER(ctypes.c_double)),
        ("count", ctypes.c_int32),
        ("density", ctypes.c_double),
        ("restitution", ctypes.c_double),
        ("friction", ctypes.c_double),
    ]


class RayHit(ctypes.Structure):
    """carom_ray_hit (version 0.2)."""

    _fields_ = [
        ("body", ctypes.c_uint64),
        ("x", ctypes.c_double),
        ("y", ctypes.c_double),
        ("nx", ctypes.c_double),
        ("ny", ctypes.c_double),
        ("fraction", ctypes.c_double),
    ]


class ContactEvent(ctypes.Structure):
    """carom_contact_event (version 0.2)."""

    _fields_ = [
        ("type", ctypes.c_int),
        ("a", ctypes.c_uint64),
        ("b", ctypes.c_uint64),
        ("x", ctypes.c_double),
        ("y", ctypes.c_double),
        ("nx", ctypes.c_double),
        ("ny", ctypes.c_double),
        ("approach_speed", ctypes.c_double),
        ("normal_impulse", ctypes.c_double),
    ]


class JointDef(ctypes.Structure):
    """carom_joint_def (version 0.2): carom_joint_def_init fills it with zeros."""

    _fields_ = [
        ("size", ctypes.c_uint32),
        ("type", ctypes.c_int),
        ("a", ctypes.c_uint64),
        ("b", ctypes.c_uint64),
        ("x", ctypes.c_double),
        ("y", ctypes.c_double),
        ("x2", ctypes.c_double),
        ("y2", ctypes.c_double),
        ("axis_x", ctypes.c_double),
        ("axis_y", ctypes.c_double),
        ("enable_limit", ctypes.c_int32),
        ("lower", ctypes.c_double),
        ("upper", ctypes.c_double),
        ("enable_motor", ctypes.c_int32),
        ("motor_speed", ctypes.c_double),
        ("max_motor_force", ctypes.c_double),
        ("enable_spring", ctypes.c_int32),
        ("hertz", ctypes.c_double),
        ("damping_ratio", ctypes.c_double),
        ("collide_connected", ctypes.c_int32),
        ("length", ctypes.c_double),
        ("max_motor_torque", ctypes.c_double),
    ]


DRAW_POLYGON_FN = ctypes.CFUNCTYPE(None, ctypes.POINTER(ctypes.c_double), ctypes.c_int32,
                                   ctypes.c_uint64, ctypes.c_void_p)
DRAW_CIRCLE_FN = ctypes.CFUNCTYPE(None, ctypes.c_double, ctypes.c_double, ctypes.c_double,
                                  ctypes.c_double, ctypes.c_uint64, ctypes.c_void_p)
DRAW_SEGMENT_FN = ctypes.CFUNCTYPE(None, ctypes.c_double, ctypes.c_double, ctypes.c_double,
                                   ctypes.c_double, ctypes.c_void_p)
DRAW_POINT_FN = ctypes.CFUNCTYPE(None, ctypes.c_double, ctypes.c_double, ctypes.c_void_p)
DRAW_JOINT_FN = ctypes.CFUNCTYPE(None, ctypes.c_int, ctypes.POINTER(ctypes.c_double),
                                 ctypes.c_uint64, ctypes.c_void_p)


class DebugDraw(ctypes.Structure):
    """carom_debug_draw (version 0.2, with the joints' fields)."""

    _fields_ = [
        ("size", ctypes.c_uint32),
        ("polygon", DRAW_POLYGON_FN),
        ("circle", DRAW_CIRCLE_FN),
        ("segment", DRAW_SEGMENT_FN),
        ("point", DRAW_POINT_FN),
        ("user", ctypes.c_void_p),
        ("draw_bodies", ctypes.c_int32),
        ("draw_contacts", ctypes.c_int32),
        ("joint", DRAW_JOINT_FN),  # version 0.2, joints
        ("draw_joints", ctypes.c_int32),
    ]


class SceneError(ctypes.Structure):
    """carom_scene_error: the caller sets `size`, the library fills the rest."""

    _fields_ = [
        ("size", ctypes.c_uint32),
        ("line", ctypes.c_int32),
        ("cause", ctypes.c_int),
        ("message", ctypes.c_char * 256),
    ]


# Constants of include/carom.h (enum values are fixed by the ABI).
DYNAMIC, STATIC, KINEMATIC = 0, 1, 2
EVENT_CONTACT_BEGIN, EVENT_CONTACT_END, EVENT_SENSOR_BEGIN, EVENT_SENSOR_END = 0, 1, 2, 3
SHAPE_CIRCLE, SHAPE_POLYGON, SHAPE_COMPOUND = 0, 1, 2
NARROW_SAT, NARROW_VERTEX_EDGE = 0, 1
(JOINT_REVOLUTE, JOINT_PRISMATIC, JOINT_DISTANCE, JOINT_WELD, JOINT_WHEEL, JOINT_MOTOR,
 JOINT_MOUSE) = range(7)
MAX_POLYGON_VERTICES = 1024
MAX_COMPOUND_SHAPES = 256


# -------------------------------------------------------------- prototypes

_W = c_world_p
_D = ctypes.c_double
_ID = c_body_id
_JID = c_joint_id

# name: (restype, argtypes). Every function of include/carom.h is here.
PROTOTYPES = {
    "carom_version": (ctypes.c_uint32, []),
    "carom_status_string": (ctypes.c_char_p, [c_status]),
    "carom_world_def_init": (c_status, [ctypes.c_void_p, ctypes.c_uint32]),
    "carom_world_init": (c_status, [ctypes.POINTER(c_world_p), ctypes.POINTER(WorldDef)]),
    "carom_world_destroy": (None, [_W]),
    "carom_world_update": (c_status, [_W, _D]),
    "carom_world_set_gravity": (c_status, [_W, _D, _D]),
    "carom_world_get_gravity": (c_status, [_W, c_double_p, c_double_p]),
    "carom_world_body_count": (ctypes.c_int32, [_W]),
    "carom_world_get_bodies": (ctypes.c_int32, [_W, c_body_id_p, ctypes.c_int32]),
    "carom_world_detect": (c_status, [_W]),
    "carom_world_contact_count": (ctypes.c_int32, [_W]),
    "carom_world_get_contact": (
        c_status,
        [_W, ctypes.c_int32, c_body_id_p, c_body_id_p,
         c_double_p, c_double_p, c_double_p, c_double_p, c_double_p],
    ),
    "carom_body_def_init": (c_status, [ctypes.c_void_p, ctypes.c_uint32]),
    "carom_world_add_circle": (c_status, [_W, ctypes.POINTER(BodyDef), _D, c_body_id_p]),
    "carom_world_add_box": (c_status, [_W, ctypes.POINTER(BodyDef), _D, _D, c_body_id_p]),
    "carom_world_add_regular": (
        c_status, [_W, ctypes.POINTER(BodyDef), ctypes.c_int32, _D, c_body_id_p]),
    "carom_world_add_polygon": (
        c_status, [_W, ctypes.POINTER(BodyDef), c_double_p, ctypes.c_int32, c_body_id_p]),
    "carom_shape_def_init": (c_status, [ctypes.c_void_p, ctypes.c_uint32]),
    "carom_world_add_compound": (
        c_status, [_W, ctypes.POINTER(BodyDef), ctypes.POINTER(ShapeDef), ctypes.c_int32, c_body_id_p]),
    "carom_world_remove_body": (c_status, [_W, _ID]),
    "carom_world_get_effects": (ctypes.c_uint32, [_W]),
    "carom_effect_name": (ctypes.c_char_p, [ctypes.c_int]),
    "carom_world_set_restitution": (c_status, [_W, _D]),
    "carom_world_set_friction": (c_status, [_W, _D]),
    "carom_world_set_central_gravity": (c_status, [_W, _D, _D, _D, _D]),
    "carom_world_set_damping": (c_status, [_W, _D, _D]),
    "carom_world_set_sleeping": (c_status, [_W, ctypes.c_int32]),
    "carom_world_set_continuous": (c_status, [_W, ctypes.c_int32]),
    "carom_body_set_bullet": (c_status, [_W, _ID, ctypes.c_int32]),
    "carom_body_is_awake": (c_status, [_W, _ID, ctypes.POINTER(ctypes.c_int32)]),
    "carom_body_wake": (c_status, [_W, _ID]),
    "carom_body_set_fixed_rotation": (c_status, [_W, _ID, ctypes.c_int32]),
    "carom_body_check": (c_status, [_W, _ID]),
    "carom_body_get_position": (c_status, [_W, _ID, c_double_p, c_double_p]),
    "carom_body_set_position": (c_status, [_W, _ID, _D, _D]),
    "carom_body_get_angle": (c_status, [_W, _ID, c_double_p]),
    "carom_body_set_angle": (c_status, [_W, _ID, _D]),
    "carom_body_get_velocity": (c_status, [_W, _ID, c_double_p, c_double_p]),
    "carom_body_set_velocity": (c_status, [_W, _ID, _D, _D]),
    "carom_body_get_spin": (c_status, [_W, _ID, c_double_p]),
    "carom_body_set_spin": (c_status, [_W, _ID, _D]),
    "carom_body_get_mass": (c_status, [_W, _ID, c_double_p, c_double_p, c_double_p]),
    "carom_body_get_type": (c_status, [_W, _ID, ctypes.POINTER(ctypes.c_int)]),
    "carom_body_get_shape": (c_status, [_W, _ID, ctypes.POINTER(ctypes.c_int), c_double_p]),
    "carom_body_get_material": (c_status, [_W, _ID, c_double_p, c_double_p]),
    "carom_body_get_vertices": (
        c_status, [_W, _ID, c_double_p, ctypes.c_int32, c_int32_p]),
    # version 0.2
    "carom_body_get_shape_count": (c_status, [_W, _ID, c_int32_p]),
    "carom_body_get_shape_geometry": (
        c_status, [_W, _ID, ctypes.c_int32, ctypes.POINTER(ctypes.c_int), c_double_p, c_double_p,
                   c_double_p, c_double_p, ctypes.c_int32, c_int32_p]),
    "carom_body_get_shape_material": (
        c_status, [_W, _ID, ctypes.c_int32, c_double_p, c_double_p, c_double_p]),
    "carom_body_apply_force": (c_status, [_W, _ID, _D, _D, _D, _D]),
    "carom_body_apply_torque": (c_status, [_W, _ID, _D]),
    "carom_world_clear_forces": (c_status, [_W]),
    "carom_body_apply_impulse": (c_status, [_W, _ID, _D, _D, _D, _D]),
    "carom_body_apply_angular_impulse": (c_status, [_W, _ID, _D]),
    "carom_body_get_user_data": (c_status, [_W, _ID, ctypes.POINTER(ctypes.c_void_p)]),
    "carom_body_set_user_data": (c_status, [_W, _ID, ctypes.c_void_p]),
    "carom_body_set_filter": (c_status, [_W, _ID, ctypes.c_uint32, ctypes.c_uint32, ctypes.c_int32]),
    "carom_body_get_filter": (
        c_status, [_W, _ID, ctypes.POINTER(ctypes.c_uint32), ctypes.POINTER(ctypes.c_uint32),
                   ctypes.POINTER(ctypes.c_int32)]),
    "carom_body_is_sensor": (c_status, [_W, _ID, ctypes.POINTER(ctypes.c_int32)]),
    "carom_world_cast_ray": (
        c_status, [_W, _D, _D, _D, _D, ctypes.c_uint32, ctypes.POINTER(RayHit)]),
    "carom_world_query_aabb": (
        ctypes.c_int32, [_W, _D, _D, _D, _D, ctypes.c_uint32, c_body_id_p, ctypes.c_int32]),
    "carom_world_query_point": (
        ctypes.c_int32, [_W, _D, _D, ctypes.c_uint32, c_body_id_p, ctypes.c_int32]),
    "carom_world_get_events": (
        ctypes.c_int32, [_W, ctypes.POINTER(ContactEvent), ctypes.c_int32]),
    "carom_joint_def_init": (c_status, [ctypes.c_void_p, ctypes.c_uint32]),
    "carom_world_add_joint": (c_status, [_W, ctypes.POINTER(JointDef), c_joint_id_p]),
    "carom_world_remove_joint": (c_status, [_W, _JID]),
    "carom_joint_check": (c_status, [_W, _JID]),
    "carom_world_joint_count": (ctypes.c_int32, [_W]),
    "carom_world_get_joints": (ctypes.c_int32, [_W, c_joint_id_p, ctypes.c_int32]),
    "carom_body_get_joints": (ctypes.c_int32, [_W, _ID, c_joint_id_p, ctypes.c_int32]),
    "carom_joint_get_bodies": (
        c_status, [_W, _JID, ctypes.POINTER(ctypes.c_int), c_body_id_p, c_body_id_p]),
    "carom_joint_get_anchors": (
        c_status, [_W, _JID, c_double_p, c_double_p, c_double_p, c_double_p]),
    "carom_joint_get_reaction": (c_status, [_W, _JID, c_double_p, c_double_p, c_double_p]),
    "carom_joint_set_motor": (c_status, [_W, _JID, ctypes.c_int32, _D, _D]),
    "carom_joint_set_limit": (c_status, [_W, _JID, ctypes.c_int32, _D, _D]),
    "carom_joint_set_spring": (c_status, [_W, _JID, ctypes.c_int32, _D, _D]),
    "carom_joint_set_target": (c_status, [_W, _JID, _D, _D, _D]),
    "carom_debug_draw_init": (c_status, [ctypes.c_void_p, ctypes.c_uint32]),
    "carom_world_draw": (c_status, [_W, ctypes.POINTER(DebugDraw)]),
    "carom_scene_load_text": (
        c_status,
        [ctypes.POINTER(c_world_p), ctypes.c_char_p, ctypes.c_size_t,
         ctypes.POINTER(WorldDef), ctypes.POINTER(SceneError)],
    ),
    "carom_scene_load_file": (
        c_status,
        [ctypes.POINTER(c_world_p), ctypes.c_char_p,
         ctypes.POINTER(WorldDef), ctypes.POINTER(SceneError)],
    ),
}


# ------------------------------------------------------------------ loading

def _own_copies():
    """The library built into this package (setup.py), if any."""
    here = os.path.dirname(os.path.abspath(__file__))
    found = []
    for pattern in ("_libcarom*.so", "_libcarom*.dylib", "_libcarom*.pyd"):
        found.extend(sorted(glob.glob(os.path.join(here, pattern))))
    return found


def _candidates():
    """Where to look for the library, in order (see docs/bindings.md)."""
    path = os.environ.get(LIBRARY_ENV)
    if path:
        # An explicit choice: no silent fallback to another copy.
        return [path], True
    # The package's own copy first: the one this binding was built with.
    names = _own_copies()
    if sys.platform == "darwin":
        soname, plain = "libcarom.%d.dylib" % EXPECTED_MAJOR, "libcarom.dylib"
    elif sys.platform.startswith("win"):
        soname, plain = "carom.dll", "carom.dll"
    else:
        soname, plain = "libcarom.so.%d" % EXPECTED_MAJOR, "libcarom.so"
    # The soname first: the dynamic loader's own search (LD_LIBRARY_PATH,
    # the ld.so cache) finds a library of the right major version.
    names.append(soname)
    found = ctypes.util.find_library("carom")
    if found:
        names.append(found)
    for prefix in ("/usr/local/lib", "/usr/lib", "/opt/homebrew/lib",
                   "/usr/lib/x86_64-linux-gnu", "/usr/lib/aarch64-linux-gnu",
                   "/usr/local/lib64", "/usr/lib64"):
        names.append(os.path.join(prefix, soname))
        names.append(os.path.join(prefix, plain))
    return names, False


def _load():
    names, explicit = _candidates()
    errors = []
    for name in names:
        try:
            return ctypes.CDLL(name), name
        except OSError as exc:
            errors.append(str(exc))
    if explicit:
        raise ImportError("carom: cannot load %s=%s (%s)" % (LIBRARY_ENV, names[0], errors[0]))
    raise ImportError(
        "carom: this package has no built-in copy of the carom C library, and none was "
        "found (libcarom.so.%d). Install the package with pip (it builds the library), "
        "install the library (make install), or set %s to its full path, e.g. "
        "%s=/path/to/build/libcarom.so.%d" % (EXPECTED_MAJOR, LIBRARY_ENV, LIBRARY_ENV, EXPECTED_MAJOR))


def _declare(lib):
    missing = []
    for name, (restype, argtypes) in PROTOTYPES.items():
        try:
            fn = getattr(lib, name)
        except AttributeError:
            missing.append(name)
            continue
        fn.restype = restype
        fn.argtypes = argtypes
    if "carom_version" in missing:
        raise ImportError("carom: %s is not the carom library (no carom_version)" % lib._name)
    if missing:
        raise ImportError("carom: %s lacks %s (a library older than this binding?)"
                          % (lib._name, ", ".join(missing)))


lib, path = _load()
_declare(lib)

version = lib.carom_version()
version_tuple = (version // 10000, version // 100 % 100, version % 100)
if version_tuple[0] != EXPECTED_MAJOR:
    raise ImportError(
        "carom: %s is version %d.%d.%d; this binding needs major version %d"
        % ((path,) + version_tuple + (EXPECTED_MAJOR,)))

def new_def(cls):
    """A def filled with the library's defaults for the struct as this binding
    knows it: the binding passes its own size (the ABI rule), and a library
    older than the binding, which cannot fill that much, refuses it."""
    init = {WorldDef: lib.carom_world_def_init, BodyDef: lib.carom_body_def_init,
            ShapeDef: lib.carom_shape_def_init, JointDef: lib.carom_joint_def_init,
            DebugDraw: lib.carom_debug_draw_init}[cls]
    d = cls()
    status = init(ctypes.byref(d), ctypes.sizeof(cls))
    if status != 0:
        raise ImportError("carom: %s refuses a %d-byte %s (%s): the library is "
                          "older than this binding"
                          % (path, ctypes.sizeof(cls), cls.__name__,
                             lib.carom_status_string(status).decode()))
    return d


# Fail at import, not at first use, when the library is older than the binding.
new_def(WorldDef)
new_def(BodyDef)
new_def(ShapeDef)
new_def(JointDef)
new_def(DebugDraw)
