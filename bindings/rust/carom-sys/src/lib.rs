//! Declarations of carom's C ABI (`include/carom.h`, version 0.x), checked
//! against the header by `tools/check-ffi`, the C library itself (built in
//! by the default `bundled` feature, or an installed one with `system`),
//! and a small safe wrapper in [`safe`].
//!
//! The raw items keep their C names. C enums are `c_int` type aliases with
//! constants: a library newer than this crate may return a value the crate
//! does not know, which a Rust `enum` could not hold.
//!
//! The structs with a leading `size` field ([`carom_world_def`],
//! [`carom_body_def`], [`carom_shape_def`], [`carom_joint_def`],
//! [`carom_debug_draw`], [`carom_scene_error`]) must be given the size this
//! crate knows: [`safe::world_def`], [`safe::body_def`] and
//! [`safe::joint_def`] return them filled with the library's defaults and
//! the right size.
//!
//! ```
//! use carom_sys::safe::{self, World};
//!
//! let mut def = safe::world_def();
//! def.gravity_y = -10.0;
//! let mut world = World::with_def(&def)?;
//! let mut body = safe::body_def();
//! body.y = 10.0;
//! let ball = world.add_circle(&body, 0.5)?;
//! for _ in 0..10 {
//!     world.step(0.1)?;
//! }
//! let (_, y) = world.position(ball)?;
//! assert!((y - 5.0).abs() < 1e-9); // y0 - g t^2 / 2, exactly
//! # Ok::<(), safe::Error>(())
//! ```
#![allow(non_camel_case_types)]

use std::marker::{PhantomData, PhantomPinned};
use std::os::raw::{c_char, c_int, c_void};

// ------------------------------------------------------------------ version

pub const CAROM_VERSION_MAJOR: u32 = 0;
pub const CAROM_VERSION_MINOR: u32 = 2;
pub const CAROM_VERSION_PATCH: u32 = 0;
/// MAJOR * 10000 + MINOR * 100 + PATCH of the header these declarations follow.
pub const CAROM_VERSION: u32 =
    CAROM_VERSION_MAJOR * 10000 + CAROM_VERSION_MINOR * 100 + CAROM_VERSION_PATCH;

// ------------------------------------------------------------------- status

pub type carom_status = c_int;
pub const CAROM_OK: carom_status = 0;
pub const CAROM_ERR_NULL_ARGUMENT: carom_status = 1;
pub const CAROM_ERR_NOT_FINITE: carom_status = 2;
pub const CAROM_ERR_BAD_SIZE: carom_status = 3;
pub const CAROM_ERR_BAD_DENSITY: carom_status = 4;
pub const CAROM_ERR_TOO_FEW_VERTICES: carom_status = 5;
pub const CAROM_ERR_TOO_MANY_VERTICES: carom_status = 6;
pub const CAROM_ERR_REPEATED_VERTEX: carom_status = 7;
pub const CAROM_ERR_SELF_INTERSECTING: carom_status = 8;
pub const CAROM_ERR_ZERO_AREA: carom_status = 9;
pub const CAROM_ERR_BAD_TIME_STEP: carom_status = 10;
pub const CAROM_ERR_STALE_BODY: carom_status = 11;
pub const CAROM_ERR_OUT_OF_MEMORY: carom_status = 12;
pub const CAROM_ERR_BAD_ARGUMENT: carom_status = 13;
pub const CAROM_ERR_BAD_STRUCT_SIZE: carom_status = 14;
pub const CAROM_ERR_TOO_MANY_BODIES: carom_status = 15;
pub const CAROM_ERR_STATIC_BODY: carom_status = 16;
pub const CAROM_ERR_SCENE_SYNTAX: carom_status = 17;
pub const CAROM_ERR_IO: carom_status = 18;
/// Version 0.2: a joint id is unknown or was removed.
pub const CAROM_ERR_STALE_JOINT: carom_status = 19;

// ------------------------------------------------------------------- limits

pub const CAROM_MAX_POLYGON_VERTICES: i32 = 1024;
/// Version 0.2: most shapes in one compound body.
pub const CAROM_MAX_COMPOUND_SHAPES: i32 = 256;
pub const CAROM_MAX_BODIES: i32 = 1 << 24;

// -------------------------------------------------------------------- types

/// A body's id (slot index and generation); 0 is never valid.
pub type carom_body_id = u64;
pub const CAROM_NULL_BODY: carom_body_id = 0;

pub type carom_narrow_phase = c_int;
pub const CAROM_NARROW_SAT: carom_narrow_phase = 0;
pub const CAROM_NARROW_VERTEX_EDGE: carom_narrow_phase = 1;

pub type carom_body_type = c_int;
pub const CAROM_DYNAMIC: carom_body_type = 0;
pub const CAROM_STATIC: carom_body_type = 1;
/// Version 0.2: moves at its set velocity, infinite mass, no gravity.
pub const CAROM_KINEMATIC: carom_body_type = 2;

/// Version 0.2: the kinds of [`carom_contact_event`].
pub type carom_event_type = c_int;
pub const CAROM_EVENT_CONTACT_BEGIN: carom_event_type = 0;
pub const CAROM_EVENT_CONTACT_END: carom_event_type = 1;
pub const CAROM_EVENT_SENSOR_BEGIN: carom_event_type = 2;
pub const CAROM_EVENT_SENSOR_END: carom_event_type = 3;

/// The effects (bits of `carom_world_get_effects`).
pub type carom_effect = c_int;
pub const CAROM_EFFECT_GRAVITY: carom_effect = 1 << 0;
pub const CAROM_EFFECT_CENTRAL_GRAVITY: carom_effect = 1 << 1;
pub const CAROM_EFFECT_RESTITUTION: carom_effect = 1 << 2;
pub const CAROM_EFFECT_FRICTION: carom_effect = 1 << 3;
pub const CAROM_EFFECT_FIXED_ROTATION: carom_effect = 1 << 4;
pub const CAROM_EFFECT_DAMPING: carom_effect = 1 << 5;
pub const CAROM_EFFECT_SLEEPING: carom_effect = 1 << 6;
pub const CAROM_EFFECT_CONTINUOUS: carom_effect = 1 << 7;
/// Version 0.2: the world has a joint.
pub const CAROM_EFFECT_JOINTS: carom_effect = 1 << 8;

pub type carom_shape_kind = c_int;
pub const CAROM_SHAPE_CIRCLE: carom_shape_kind = 0;
pub const CAROM_SHAPE_POLYGON: carom_shape_kind = 1;
/// Version 0.2: a body of several shapes.
pub const CAROM_SHAPE_COMPOUND: carom_shape_kind = 2;

/// Version 0.2: a joint's id (slot index and generation); 0 is never valid.
pub type carom_joint_id = u64;
pub const CAROM_NULL_JOINT: carom_joint_id = 0;

/// Version 0.2: what a joint holds (`include/carom.h` says what each
/// type's limit, motor and spring act on).
pub type carom_joint_type = c_int;
/// A shared point: b turns about the anchor on a.
pub const CAROM_JOINT_REVOLUTE: carom_joint_type = 0;
/// b slides along the axis fixed in a, without turning relative to a.
pub const CAROM_JOINT_PRISMATIC: carom_joint_type = 1;
/// The anchors keep their distance (`length`, or their distance at creation).
pub const CAROM_JOINT_DISTANCE: carom_joint_type = 2;
/// b is fixed to a.
pub const CAROM_JOINT_WELD: carom_joint_type = 3;
/// The anchor on b stays on the axis through the anchor on a; b turns freely.
pub const CAROM_JOINT_WHEEL: carom_joint_type = 4;
/// b is driven towards a pose relative to a, with bounded force and torque.
pub const CAROM_JOINT_MOTOR: carom_joint_type = 5;
/// A point of b is pulled towards a moving target; a must be the world.
pub const CAROM_JOINT_MOUSE: carom_joint_type = 6;

/// The opaque world.
#[repr(C)]
pub struct carom_world {
    _data: [u8; 0],
    _marker: PhantomData<(*mut u8, PhantomPinned)>,
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct carom_allocator {
    pub alloc: Option<unsafe extern "C" fn(size: usize, user: *mut c_void) -> *mut c_void>,
    pub free: Option<unsafe extern "C" fn(ptr: *mut c_void, size: usize, user: *mut c_void)>,
    pub user: *mut c_void,
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct carom_world_def {
    pub size: u32,
    pub gravity_x: f64,
    pub gravity_y: f64,
    pub restitution: f64,
    pub friction: f64,
    pub substeps: i32,
    pub iterations: i32,
    pub position_correction: f64,
    pub slop: f64,
    pub narrow_phase: carom_narrow_phase,
    pub allocator: carom_allocator,
    // version 0.2
    pub manifold_tolerance: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct carom_body_def {
    pub size: u32,
    pub type_: carom_body_type,
    pub x: f64,
    pub y: f64,
    pub angle: f64,
    pub vx: f64,
    pub vy: f64,
    pub spin: f64,
    pub density: f64,
    pub restitution: f64,
    pub friction: f64,
    // version 0.2
    pub user_data: *mut c_void,
    pub category: u32,
    pub mask: u32,
    pub group: i32,
    pub sensor: i32,
}

/// Version 0.2: one shape of a compound body (`carom_world_add_compound`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct carom_shape_def {
    pub size: u32,
    pub kind: carom_shape_kind,
    pub x: f64,
    pub y: f64,
    pub angle: f64,
    pub radius: f64,
    pub xy: *const f64,
    pub count: i32,
    pub density: f64,
    pub restitution: f64,
    pub friction: f64,
}

/// Version 0.2: the first body a ray meets.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct carom_ray_hit {
    pub body: carom_body_id,
    pub x: f64,
    pub y: f64,
    pub nx: f64,
    pub ny: f64,
    pub fraction: f64,
}

/// Version 0.2: one event of the last update.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct carom_contact_event {
    pub type_: carom_event_type,
    pub a: carom_body_id,
    pub b: carom_body_id,
    pub x: f64,
    pub y: f64,
    pub nx: f64,
    pub ny: f64,
    pub approach_speed: f64,
    pub normal_impulse: f64,
}

/// Version 0.2: a joint's settings. `carom_joint_def_init` fills it with
/// zeros ([`safe::joint_def`]); the fields a type does not use are ignored.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct carom_joint_def {
    pub size: u32,
    pub type_: carom_joint_type,
    pub a: carom_body_id,
    pub b: carom_body_id,
    pub x: f64,
    pub y: f64,
    pub x2: f64,
    pub y2: f64,
    pub axis_x: f64,
    pub axis_y: f64,
    pub enable_limit: i32,
    pub lower: f64,
    pub upper: f64,
    pub enable_motor: i32,
    pub motor_speed: f64,
    pub max_motor_force: f64,
    pub enable_spring: i32,
    pub hertz: f64,
    pub damping_ratio: f64,
    pub collide_connected: i32,
    pub length: f64,
    pub max_motor_torque: f64,
}

/// Version 0.2: the debug draw's callbacks.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct carom_debug_draw {
    pub size: u32,
    pub polygon: Option<unsafe extern "C" fn(xy: *const f64, count: i32, body: carom_body_id, user: *mut c_void)>,
    pub circle:
        Option<unsafe extern "C" fn(x: f64, y: f64, radius: f64, angle: f64, body: carom_body_id, user: *mut c_void)>,
    pub segment: Option<unsafe extern "C" fn(x0: f64, y0: f64, x1: f64, y1: f64, user: *mut c_void)>,
    pub point: Option<unsafe extern "C" fn(x: f64, y: f64, user: *mut c_void)>,
    pub user: *mut c_void,
    pub draw_bodies: i32,
    pub draw_contacts: i32,
    // version 0.2, joints
    pub joint: Option<unsafe extern "C" fn(type_: carom_joint_type, xy: *const f64, id: carom_joint_id, user: *mut c_void)>,
    pub draw_joints: i32,
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct carom_scene_error {
    pub size: u32,
    pub line: i32,
    pub cause: carom_status,
    pub message: [c_char; 256],
}

// ---------------------------------------------------------------- functions

extern "C" {
    pub fn carom_version() -> u32;
    pub fn carom_status_string(status: carom_status) -> *const c_char;

    pub fn carom_world_def_init(def: *mut carom_world_def, size: u32) -> carom_status;
    pub fn carom_world_init(
        world: *mut *mut carom_world,
        def: *const carom_world_def,
    ) -> carom_status;
    pub fn carom_world_destroy(world: *mut carom_world);
    pub fn carom_world_update(world: *mut carom_world, dt: f64) -> carom_status;
    pub fn carom_world_set_gravity(world: *mut carom_world, gx: f64, gy: f64) -> carom_status;
    pub fn carom_world_get_gravity(
        world: *const carom_world,
        gx: *mut f64,
        gy: *mut f64,
    ) -> carom_status;
    pub fn carom_world_body_count(world: *const carom_world) -> i32;
    pub fn carom_world_get_bodies(
        world: *const carom_world,
        ids: *mut carom_body_id,
        capacity: i32,
    ) -> i32;

    pub fn carom_world_detect(world: *mut carom_world) -> carom_status;
    pub fn carom_world_contact_count(world: *const carom_world) -> i32;
    pub fn carom_world_get_contact(
        world: *const carom_world,
        index: i32,
        a: *mut carom_body_id,
        b: *mut carom_body_id,
        px: *mut f64,
        py: *mut f64,
        nx: *mut f64,
        ny: *mut f64,
        depth: *mut f64,
    ) -> carom_status;

    pub fn carom_body_def_init(def: *mut carom_body_def, size: u32) -> carom_status;
    pub fn carom_world_add_circle(
        world: *mut carom_world,
        def: *const carom_body_def,
        radius: f64,
        id: *mut carom_body_id,
    ) -> carom_status;
    pub fn carom_world_add_box(
        world: *mut carom_world,
        def: *const carom_body_def,
        width: f64,
        height: f64,
        id: *mut carom_body_id,
    ) -> carom_status;
    pub fn carom_world_add_regular(
        world: *mut carom_world,
        def: *const carom_body_def,
        n: i32,
        side: f64,
        id: *mut carom_body_id,
    ) -> carom_status;
    pub fn carom_world_add_polygon(
        world: *mut carom_world,
        def: *const carom_body_def,
        xy: *const f64,
        count: i32,
        id: *mut carom_body_id,
    ) -> carom_status;
    pub fn carom_shape_def_init(def: *mut carom_shape_def, size: u32) -> carom_status;
    pub fn carom_world_add_compound(
        world: *mut carom_world,
        def: *const carom_body_def,
        shapes: *const carom_shape_def,
        count: i32,
        id: *mut carom_body_id,
    ) -> carom_status;
    pub fn carom_world_remove_body(world: *mut carom_world, id: carom_body_id) -> carom_status;
    pub fn carom_world_get_effects(world: *const carom_world) -> u32;
    pub fn carom_effect_name(effect: carom_effect) -> *const c_char;
    pub fn carom_world_set_restitution(world: *mut carom_world, restitution: f64) -> carom_status;
    pub fn carom_world_set_friction(world: *mut carom_world, friction: f64) -> carom_status;
    pub fn carom_world_set_central_gravity(world: *mut carom_world, x: f64, y: f64, gm: f64, softening: f64) -> carom_status;
    pub fn carom_world_set_damping(world: *mut carom_world, linear: f64, angular: f64) -> carom_status;
    pub fn carom_world_set_sleeping(world: *mut carom_world, enabled: i32) -> carom_status;
    pub fn carom_world_set_continuous(world: *mut carom_world, enabled: i32) -> carom_status;
    pub fn carom_body_set_bullet(world: *mut carom_world, id: carom_body_id, bullet: i32) -> carom_status;
    pub fn carom_body_is_awake(world: *const carom_world, id: carom_body_id, awake: *mut i32) -> carom_status;
    pub fn carom_body_wake(world: *mut carom_world, id: carom_body_id) -> carom_status;
    pub fn carom_body_set_fixed_rotation(world: *mut carom_world, id: carom_body_id, fixed: i32) -> carom_status;
    pub fn carom_body_check(world: *const carom_world, id: carom_body_id) -> carom_status;

    pub fn carom_body_get_position(
        world: *const carom_world,
        id: carom_body_id,
        x: *mut f64,
        y: *mut f64,
    ) -> carom_status;
    pub fn carom_body_set_position(
        world: *mut carom_world,
        id: carom_body_id,
        x: f64,
        y: f64,
    ) -> carom_status;
    pub fn carom_body_get_angle(
        world: *const carom_world,
        id: carom_body_id,
        angle: *mut f64,
    ) -> carom_status;
    pub fn carom_body_set_angle(
        world: *mut carom_world,
        id: carom_body_id,
        angle: f64,
    ) -> carom_status;
    pub fn carom_body_get_velocity(
        world: *const carom_world,
        id: carom_body_id,
        vx: *mut f64,
        vy: *mut f64,
    ) -> carom_status;
    pub fn carom_body_set_velocity(
        world: *mut carom_world,
        id: carom_body_id,
        vx: f64,
        vy: f64,
    ) -> carom_status;
    pub fn carom_body_get_spin(
        world: *const carom_world,
        id: carom_body_id,
        spin: *mut f64,
    ) -> carom_status;
    pub fn carom_body_set_spin(
        world: *mut carom_world,
        id: carom_body_id,
        spin: f64,
    ) -> carom_status;
    pub fn carom_body_get_mass(
        world: *const carom_world,
        id: carom_body_id,
        mass: *mut f64,
        inertia: *mut f64,
        area: *mut f64,
    ) -> carom_status;
    pub fn carom_body_get_type(
        world: *const carom_world,
        id: carom_body_id,
        type_: *mut carom_body_type,
    ) -> carom_status;
    pub fn carom_body_get_shape(
        world: *const carom_world,
        id: carom_body_id,
        kind: *mut carom_shape_kind,
        radius: *mut f64,
    ) -> carom_status;
    pub fn carom_body_get_material(
        world: *const carom_world,
        id: carom_body_id,
        restitution: *mut f64,
        friction: *mut f64,
    ) -> carom_status;
    pub fn carom_body_get_vertices(
        world: *const carom_world,
        id: carom_body_id,
        xy: *mut f64,
        capacity: i32,
        count: *mut i32,
    ) -> carom_status;

    // version 0.2
    pub fn carom_body_get_shape_count(world: *const carom_world, id: carom_body_id, count: *mut i32) -> carom_status;
    pub fn carom_body_get_shape_geometry(
        world: *const carom_world,
        id: carom_body_id,
        index: i32,
        kind: *mut carom_shape_kind,
        x: *mut f64,
        y: *mut f64,
        radius: *mut f64,
        xy: *mut f64,
        capacity: i32,
        count: *mut i32,
    ) -> carom_status;
    pub fn carom_body_get_shape_material(
        world: *const carom_world,
        id: carom_body_id,
        index: i32,
        density: *mut f64,
        restitution: *mut f64,
        friction: *mut f64,
    ) -> carom_status;
    pub fn carom_body_apply_force(world: *mut carom_world, id: carom_body_id, fx: f64, fy: f64, px: f64, py: f64) -> carom_status;
    pub fn carom_body_apply_torque(world: *mut carom_world, id: carom_body_id, torque: f64) -> carom_status;
    pub fn carom_world_clear_forces(world: *mut carom_world) -> carom_status;
    pub fn carom_body_apply_impulse(world: *mut carom_world, id: carom_body_id, jx: f64, jy: f64, px: f64, py: f64) -> carom_status;
    pub fn carom_body_apply_angular_impulse(world: *mut carom_world, id: carom_body_id, j: f64) -> carom_status;
    pub fn carom_body_get_user_data(world: *const carom_world, id: carom_body_id, data: *mut *mut c_void) -> carom_status;
    pub fn carom_body_set_user_data(world: *mut carom_world, id: carom_body_id, data: *mut c_void) -> carom_status;
    pub fn carom_body_set_filter(world: *mut carom_world, id: carom_body_id, category: u32, mask: u32, group: i32) -> carom_status;
    pub fn carom_body_get_filter(world: *const carom_world, id: carom_body_id, category: *mut u32, mask: *mut u32, group: *mut i32) -> carom_status;
    pub fn carom_body_is_sensor(world: *const carom_world, id: carom_body_id, sensor: *mut i32) -> carom_status;
    pub fn carom_world_cast_ray(world: *const carom_world, x0: f64, y0: f64, x1: f64, y1: f64, mask: u32, hit: *mut carom_ray_hit) -> carom_status;
    pub fn carom_world_query_aabb(world: *const carom_world, x0: f64, y0: f64, x1: f64, y1: f64, mask: u32, ids: *mut carom_body_id, capacity: i32) -> i32;
    pub fn carom_world_query_point(world: *const carom_world, x: f64, y: f64, mask: u32, ids: *mut carom_body_id, capacity: i32) -> i32;
    pub fn carom_world_get_events(world: *const carom_world, events: *mut carom_contact_event, capacity: i32) -> i32;
    pub fn carom_joint_def_init(def: *mut carom_joint_def, size: u32) -> carom_status;
    pub fn carom_world_add_joint(world: *mut carom_world, def: *const carom_joint_def, id: *mut carom_joint_id) -> carom_status;
    pub fn carom_world_remove_joint(world: *mut carom_world, id: carom_joint_id) -> carom_status;
    pub fn carom_joint_check(world: *const carom_world, id: carom_joint_id) -> carom_status;
    pub fn carom_world_joint_count(world: *const carom_world) -> i32;
    pub fn carom_world_get_joints(world: *const carom_world, ids: *mut carom_joint_id, capacity: i32) -> i32;
    pub fn carom_body_get_joints(world: *const carom_world, id: carom_body_id, ids: *mut carom_joint_id, capacity: i32) -> i32;
    pub fn carom_joint_get_bodies(
        world: *const carom_world,
        id: carom_joint_id,
        type_: *mut carom_joint_type,
        a: *mut carom_body_id,
        b: *mut carom_body_id,
    ) -> carom_status;
    pub fn carom_joint_get_anchors(
        world: *const carom_world,
        id: carom_joint_id,
        ax: *mut f64,
        ay: *mut f64,
        bx: *mut f64,
        by: *mut f64,
    ) -> carom_status;
    pub fn carom_joint_get_reaction(
        world: *const carom_world,
        id: carom_joint_id,
        fx: *mut f64,
        fy: *mut f64,
        torque: *mut f64,
    ) -> carom_status;
    pub fn carom_joint_set_motor(world: *mut carom_world, id: carom_joint_id, enable: i32, speed: f64, max_force: f64) -> carom_status;
    pub fn carom_joint_set_limit(world: *mut carom_world, id: carom_joint_id, enable: i32, lower: f64, upper: f64) -> carom_status;
    pub fn carom_joint_set_spring(world: *mut carom_world, id: carom_joint_id, enable: i32, hertz: f64, damping_ratio: f64) -> carom_status;
    pub fn carom_joint_set_target(world: *mut carom_world, id: carom_joint_id, x: f64, y: f64, angle: f64) -> carom_status;
    pub fn carom_debug_draw_init(draw: *mut carom_debug_draw, size: u32) -> carom_status;
    pub fn carom_world_draw(world: *const carom_world, draw: *const carom_debug_draw) -> carom_status;

    pub fn carom_scene_load_text(
        world: *mut *mut carom_world,
        text: *const c_char,
        length: usize,
        def: *const carom_world_def,
        error: *mut carom_scene_error,
    ) -> carom_status;
    pub fn carom_scene_load_file(
        world: *mut *mut carom_world,
        path: *const c_char,
        def: *const carom_world_def,
        error: *mut carom_scene_error,
    ) -> carom_status;
}

pub mod safe;
