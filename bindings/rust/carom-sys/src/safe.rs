//! A small safe layer: [`World`] owns a `carom_world` and destroys it when
//! dropped; bodies are plain [`carom_body_id`]s and joints plain
//! [`carom_joint_id`]s, which the library checks on every call (a removed
//! body's id gives `CAROM_ERR_STALE_BODY`, a removed joint's
//! `CAROM_ERR_STALE_JOINT`, never a dangling pointer).

use super::*;
use std::ffi::{CStr, CString};
use std::fmt;
use std::mem::{size_of, MaybeUninit};
use std::path::Path;
use std::ptr::{self, NonNull};

/// A failed call: the status, its sentence from `carom_status_string` (or the
/// scene loader's message), and for scenes the 1-based line.
#[derive(Debug, Clone, PartialEq)]
pub struct Error {
    pub status: carom_status,
    pub message: String,
    pub line: Option<i32>,
}

impl Error {
    pub fn from_status(status: carom_status) -> Error {
        Error {
            status,
            message: status_string(status).to_owned(),
            line: None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} (carom status {})", self.message, self.status)
    }
}

impl std::error::Error for Error {}

pub type Result<T> = std::result::Result<T, Error>;

fn check(status: carom_status) -> Result<()> {
    if status == CAROM_OK {
        Ok(())
    } else {
        Err(Error::from_status(status))
    }
}

/// `carom_status_string`: a short English sentence, also for unknown codes.
pub fn status_string(status: carom_status) -> &'static str {
    // SAFETY: the library returns a static NUL-terminated string, never NULL.
    unsafe { CStr::from_ptr(carom_status_string(status)) }
        .to_str()
        .unwrap_or("(not UTF-8)")
}

/// The run-time library's version as (major, minor, patch).
pub fn version() -> (u32, u32, u32) {
    // SAFETY: no arguments, no state.
    let v = unsafe { carom_version() };
    (v / 10000, v / 100 % 100, v % 100)
}

/// Fill a size-prefixed struct with the library's defaults, stating the
/// size this crate knows (the ABI rule: the caller gives its own size; the
/// library writes no byte past it). Returns the struct and the status: a
/// library older than this crate refuses a size it does not know.
fn defaults<T: Copy>(init: unsafe extern "C" fn(*mut T, u32) -> carom_status) -> (T, carom_status) {
    let mut p = MaybeUninit::<T>::zeroed();
    // SAFETY: the buffer is zeroed (a valid value for these plain C structs,
    // with None function pointers) and exactly as large as we say.
    unsafe {
        let status = init(p.as_mut_ptr(), size_of::<T>() as u32);
        (p.assume_init(), status)
    }
}

/// World settings with the library's defaults (`carom_world_def_init`).
pub fn world_def() -> carom_world_def {
    defaults(carom_world_def_init).0
}

/// Body settings with the library's defaults (`carom_body_def_init`).
pub fn body_def() -> carom_body_def {
    defaults(carom_body_def_init).0
}

/// Joint settings as `carom_joint_def_init` gives them: all zeros, with
/// this crate's size. [`JointDef`] is the safe way to fill them.
pub fn joint_def() -> carom_joint_def {
    defaults(carom_joint_def_init).0
}

/// The statuses the library gives for this crate's carom_joint_def and
/// carom_debug_draw sizes: CAROM_OK when the declarations match a size
/// the library knows (version 0.2).
pub fn library_accepts_joint_sizes() -> (carom_status, carom_status) {
    (
        defaults(carom_joint_def_init).1,
        defaults(carom_debug_draw_init).1,
    )
}

/// A joint between bodies `a` and `b` ([`World::add_joint`]), version 0.2.
/// `a` may be [`CAROM_NULL_BODY`] for the world itself (a fixed point; a
/// mouse joint's must be); `b` must be a body, and one of the two dynamic.
/// `anchor` is in world coordinates at creation (distance: the anchor on a,
/// `anchor_b` the one on b; mouse: the point of b grabbed and the first
/// target); `axis` is a prismatic or wheel joint's (any non-zero length).
/// `limit` (lower, upper), `motor` (speed, max force: a torque for
/// revolute and wheel joints) and `spring` (hertz, damping ratio) are off
/// when `None`; what each acts on depends on the type (`include/carom.h`).
/// `length` 0 is the anchors' distance at creation; `max_force` and
/// `max_torque` bound a motor joint (and `max_force` a mouse joint, 0
/// unbounded) without turning a motor on.
///
/// ```
/// use carom_sys::safe::{self, JointDef, World};
/// let mut def = safe::world_def();
/// def.gravity_y = -9.81;
/// let mut world = World::with_def(&def)?;
/// let mut bob = safe::body_def();
/// bob.x = 1.0;
/// let bob = world.add_circle(&bob, 0.05)?;
/// let pivot = world.add_joint(&JointDef::revolute(carom_sys::CAROM_NULL_BODY, bob, (0.0, 0.0)))?;
/// for _ in 0..60 {
///     world.step(1.0 / 60.0)?;
/// }
/// let (x, y) = world.position(bob)?;
/// assert!(((x * x + y * y).sqrt() - 1.0).abs() < 1e-6);
/// let (_fx, _fy, _torque) = world.joint_reaction(pivot)?;
/// # Ok::<(), safe::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JointDef {
    pub type_: carom_joint_type,
    pub a: carom_body_id,
    pub b: carom_body_id,
    pub anchor: (f64, f64),
    pub anchor_b: (f64, f64),
    pub axis: (f64, f64),
    pub limit: Option<(f64, f64)>,
    pub motor: Option<(f64, f64)>,
    pub spring: Option<(f64, f64)>,
    pub collide_connected: bool,
    pub length: f64,
    pub max_force: f64,
    pub max_torque: f64,
}

impl Default for JointDef {
    /// A revolute joint at (0, 0) between no bodies: set `b` at least.
    fn default() -> JointDef {
        JointDef::new(CAROM_JOINT_REVOLUTE, CAROM_NULL_BODY, CAROM_NULL_BODY)
    }
}

impl JointDef {
    /// A joint of any type (an unknown one is refused by the library with
    /// `CAROM_ERR_BAD_ARGUMENT`), every field else zero or off.
    pub fn new(type_: carom_joint_type, a: carom_body_id, b: carom_body_id) -> JointDef {
        JointDef {
            type_,
            a,
            b,
            anchor: (0.0, 0.0),
            anchor_b: (0.0, 0.0),
            axis: (0.0, 0.0),
            limit: None,
            motor: None,
            spring: None,
            collide_connected: false,
            length: 0.0,
            max_force: 0.0,
            max_torque: 0.0,
        }
    }

    /// b turns about `anchor`, shared with a.
    pub fn revolute(a: carom_body_id, b: carom_body_id, anchor: (f64, f64)) -> JointDef {
        JointDef::new(CAROM_JOINT_REVOLUTE, a, b).anchor(anchor)
    }

    /// b slides along `axis` (fixed in a) through `anchor`, without turning.
    pub fn prismatic(a: carom_body_id, b: carom_body_id, anchor: (f64, f64), axis: (f64, f64)) -> JointDef {
        JointDef::new(CAROM_JOINT_PRISMATIC, a, b).anchor(anchor).axis(axis)
    }

    /// `anchor_a` on a and `anchor_b` on b keep their distance.
    pub fn distance(a: carom_body_id, b: carom_body_id, anchor_a: (f64, f64), anchor_b: (f64, f64)) -> JointDef {
        JointDef {
            anchor_b,
            ..JointDef::new(CAROM_JOINT_DISTANCE, a, b).anchor(anchor_a)
        }
    }

    /// b is fixed to a (softly with a spring).
    pub fn weld(a: carom_body_id, b: carom_body_id, anchor: (f64, f64)) -> JointDef {
        JointDef::new(CAROM_JOINT_WELD, a, b).anchor(anchor)
    }

    /// b's `anchor` stays on `axis` through a's; b turns freely.
    pub fn wheel(a: carom_body_id, b: carom_body_id, anchor: (f64, f64), axis: (f64, f64)) -> JointDef {
        JointDef::new(CAROM_JOINT_WHEEL, a, b).anchor(anchor).axis(axis)
    }

    /// The point `grab` of b is pulled towards a target
    /// ([`World::set_joint_target`]), first `grab` itself.
    pub fn mouse(b: carom_body_id, grab: (f64, f64)) -> JointDef {
        JointDef::new(CAROM_JOINT_MOUSE, CAROM_NULL_BODY, b).anchor(grab)
    }

    pub fn anchor(mut self, anchor: (f64, f64)) -> JointDef {
        self.anchor = anchor;
        self
    }

    pub fn axis(mut self, axis: (f64, f64)) -> JointDef {
        self.axis = axis;
        self
    }

    pub fn limit(mut self, lower: f64, upper: f64) -> JointDef {
        self.limit = Some((lower, upper));
        self
    }

    pub fn motor(mut self, speed: f64, max_force: f64) -> JointDef {
        self.motor = Some((speed, max_force));
        self
    }

    pub fn spring(mut self, hertz: f64, damping_ratio: f64) -> JointDef {
        self.spring = Some((hertz, damping_ratio));
        self
    }

    pub fn collide_connected(mut self, collide: bool) -> JointDef {
        self.collide_connected = collide;
        self
    }

    pub fn length(mut self, length: f64) -> JointDef {
        self.length = length;
        self
    }

    pub fn max_force(mut self, max_force: f64) -> JointDef {
        self.max_force = max_force;
        self
    }

    pub fn max_torque(mut self, max_torque: f64) -> JointDef {
        self.max_torque = max_torque;
        self
    }

    /// The C def, with this crate's size (`motor`'s force, when set, is
    /// the def's `max_motor_force`; else `max_force`).
    pub fn to_raw(&self) -> carom_joint_def {
        let mut d = joint_def();
        d.size = size_of::<carom_joint_def>() as u32;
        d.type_ = self.type_;
        d.a = self.a;
        d.b = self.b;
        d.x = self.anchor.0;
        d.y = self.anchor.1;
        d.x2 = self.anchor_b.0;
        d.y2 = self.anchor_b.1;
        d.axis_x = self.axis.0;
        d.axis_y = self.axis.1;
        if let Some((lower, upper)) = self.limit {
            d.enable_limit = 1;
            d.lower = lower;
            d.upper = upper;
        }
        d.max_motor_force = self.max_force;
        if let Some((speed, max_force)) = self.motor {
            d.enable_motor = 1;
            d.motor_speed = speed;
            d.max_motor_force = max_force;
        }
        if let Some((hertz, damping_ratio)) = self.spring {
            d.enable_spring = 1;
            d.hertz = hertz;
            d.damping_ratio = damping_ratio;
        }
        d.collide_connected = self.collide_connected as i32;
        d.length = self.length;
        d.max_motor_torque = self.max_torque;
        d
    }
}

/// The statuses the library gives for this crate's (carom_world_def,
/// carom_body_def) sizes: CAROM_OK when the declarations match a size the
/// library knows.
pub fn library_accepts_def_sizes() -> (carom_status, carom_status) {
    (
        defaults(carom_world_def_init).1,
        defaults(carom_body_def_init).1,
    )
}

/// One shape of a compound body ([`World::add_compound`]), in body
/// coordinates: a circle about `offset`, or a polygon whose points are
/// turned by `angle` and then moved by `offset`. Density, restitution and
/// friction left `None` are the body def's.
#[derive(Debug, Clone, PartialEq)]
pub struct CompoundShape {
    pub kind: carom_shape_kind,
    pub radius: f64,
    pub points: Vec<[f64; 2]>,
    pub offset: [f64; 2],
    pub angle: f64,
    pub density: Option<f64>,
    pub restitution: Option<f64>,
    pub friction: Option<f64>,
}

impl CompoundShape {
    pub fn circle(radius: f64, offset: [f64; 2]) -> CompoundShape {
        CompoundShape {
            kind: CAROM_SHAPE_CIRCLE,
            radius,
            points: Vec::new(),
            offset,
            angle: 0.0,
            density: None,
            restitution: None,
            friction: None,
        }
    }

    pub fn polygon(points: &[[f64; 2]], offset: [f64; 2], angle: f64) -> CompoundShape {
        CompoundShape {
            kind: CAROM_SHAPE_POLYGON,
            points: points.to_vec(),
            angle,
            ..CompoundShape::circle(0.0, offset)
        }
    }

    /// A width x height box centred on `offset`, turned by `angle`.
    pub fn rect(width: f64, height: f64, offset: [f64; 2], angle: f64) -> CompoundShape {
        let (w, h) = (0.5 * width, 0.5 * height);
        CompoundShape::polygon(&[[-w, -h], [w, -h], [w, h], [-w, h]], offset, angle)
    }

    pub fn density(mut self, density: f64) -> CompoundShape {
        self.density = Some(density);
        self
    }

    pub fn restitution(mut self, restitution: f64) -> CompoundShape {
        self.restitution = Some(restitution);
        self
    }

    pub fn friction(mut self, friction: f64) -> CompoundShape {
        self.friction = Some(friction);
        self
    }
}

/// One shape of a body as [`World::shapes`] reports it, in world
/// coordinates: a polygon's `center` is its centroid and its `radius` the
/// farthest vertex from it; `vertices` is empty for a circle.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeInfo {
    pub kind: carom_shape_kind,
    pub center: (f64, f64),
    pub radius: f64,
    pub vertices: Vec<[f64; 2]>,
    pub density: f64,
    pub restitution: f64,
    pub friction: f64,
}

/// One contact point: bodies, point, unit normal from a to b, and the
/// penetration depth (negative when apart within the contact margin), as
/// found at the start of the update, or at the touch for a point an impact
/// moved within it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    pub a: carom_body_id,
    pub b: carom_body_id,
    pub point: (f64, f64),
    pub normal: (f64, f64),
    pub depth: f64,
}

/// An owned world; dropped means destroyed, with all its bodies.
#[derive(Debug)]
pub struct World {
    ptr: NonNull<carom_world>,
}

impl World {
    /// A world with default settings.
    pub fn new() -> Result<World> {
        World::with_def(&world_def())
    }

    /// A world with the given settings (its `size` is set to this crate's).
    pub fn with_def(def: &carom_world_def) -> Result<World> {
        let mut def = *def;
        def.size = size_of::<carom_world_def>() as u32;
        let mut ptr = ptr::null_mut();
        // SAFETY: valid out-pointer and def.
        check(unsafe { carom_world_init(&mut ptr, &def) })?;
        Ok(World {
            ptr: NonNull::new(ptr).expect("carom_world_init returned OK and NULL"),
        })
    }

    fn loaded(
        load: impl FnOnce(*mut *mut carom_world, *mut carom_scene_error) -> carom_status,
    ) -> Result<World> {
        // SAFETY: a zeroed carom_scene_error is valid.
        let mut err: carom_scene_error = unsafe { MaybeUninit::zeroed().assume_init() };
        err.size = size_of::<carom_scene_error>() as u32;
        let mut ptr = ptr::null_mut();
        let status = load(&mut ptr, &mut err);
        if status != CAROM_OK {
            // SAFETY: the library NUL-terminates message; it was zeroed anyway.
            let msg = unsafe { CStr::from_ptr(err.message.as_ptr()) }.to_string_lossy();
            return Err(Error {
                status,
                message: if msg.is_empty() {
                    status_string(status).to_owned()
                } else {
                    msg.into()
                },
                line: if err.line > 0 { Some(err.line) } else { None },
            });
        }
        Ok(World {
            ptr: NonNull::new(ptr).expect("scene loaded OK and NULL"),
        })
    }

    /// Build a world from scene text (docs/scenes.md).
    pub fn from_scene_text(text: &str) -> Result<World> {
        World::loaded(|w, e| unsafe {
            // SAFETY: text and its length; the library does not keep them.
            carom_scene_load_text(
                w,
                text.as_ptr() as *const c_char,
                text.len(),
                ptr::null(),
                e,
            )
        })
    }

    /// Build a world from a scene file.
    pub fn from_scene_file(path: &Path) -> Result<World> {
        #[cfg(unix)]
        let bytes = std::os::unix::ffi::OsStrExt::as_bytes(path.as_os_str()).to_vec();
        #[cfg(not(unix))]
        let bytes = path.to_string_lossy().into_owned().into_bytes();
        let c = CString::new(bytes).map_err(|_| Error {
            status: CAROM_ERR_BAD_ARGUMENT,
            message: "the path contains a NUL byte".to_owned(),
            line: None,
        })?;
        // SAFETY: a NUL-terminated path.
        World::loaded(|w, e| unsafe { carom_scene_load_file(w, c.as_ptr(), ptr::null(), e) })
    }

    /// The raw handle, for calls this wrapper does not cover. It stays owned
    /// by `self`.
    pub fn as_ptr(&self) -> *mut carom_world {
        self.ptr.as_ptr()
    }

    /// Advance by `dt` (> 0, finite).
    pub fn step(&mut self, dt: f64) -> Result<()> {
        check(unsafe { carom_world_update(self.as_ptr(), dt) })
    }

    pub fn set_gravity(&mut self, gx: f64, gy: f64) -> Result<()> {
        check(unsafe { carom_world_set_gravity(self.as_ptr(), gx, gy) })
    }

    pub fn gravity(&self) -> (f64, f64) {
        let (mut x, mut y) = (0.0, 0.0);
        // SAFETY: valid world and out-pointers; cannot fail with them.
        unsafe { carom_world_get_gravity(self.as_ptr(), &mut x, &mut y) };
        (x, y)
    }

    pub fn body_count(&self) -> usize {
        unsafe { carom_world_body_count(self.as_ptr()) }.max(0) as usize
    }

    /// The live bodies' ids in creation order.
    pub fn bodies(&self) -> Vec<carom_body_id> {
        let n = unsafe { carom_world_get_bodies(self.as_ptr(), ptr::null_mut(), 0) }.max(0);
        let mut ids = vec![CAROM_NULL_BODY; n as usize];
        let got = unsafe { carom_world_get_bodies(self.as_ptr(), ids.as_mut_ptr(), n) };
        ids.truncate(got.clamp(0, n) as usize);
        ids
    }

    pub fn add_circle(&mut self, def: &carom_body_def, radius: f64) -> Result<carom_body_id> {
        let def = sized(def);
        let mut id = CAROM_NULL_BODY;
        check(unsafe { carom_world_add_circle(self.as_ptr(), &def, radius, &mut id) })?;
        Ok(id)
    }

    pub fn add_box(
        &mut self,
        def: &carom_body_def,
        width: f64,
        height: f64,
    ) -> Result<carom_body_id> {
        let def = sized(def);
        let mut id = CAROM_NULL_BODY;
        check(unsafe { carom_world_add_box(self.as_ptr(), &def, width, height, &mut id) })?;
        Ok(id)
    }

    pub fn add_regular(
        &mut self,
        def: &carom_body_def,
        n: i32,
        side: f64,
    ) -> Result<carom_body_id> {
        let def = sized(def);
        let mut id = CAROM_NULL_BODY;
        check(unsafe { carom_world_add_regular(self.as_ptr(), &def, n, side, &mut id) })?;
        Ok(id)
    }

    /// A simple polygon from its vertices, in either winding.
    pub fn add_polygon(
        &mut self,
        def: &carom_body_def,
        points: &[[f64; 2]],
    ) -> Result<carom_body_id> {
        let def = sized(def);
        let count = i32::try_from(points.len())
            .map_err(|_| Error::from_status(CAROM_ERR_TOO_MANY_VERTICES))?;
        let mut id = CAROM_NULL_BODY;
        // [[f64; 2]] is laid out as x0, y0, x1, y1, ...
        check(unsafe {
            carom_world_add_polygon(
                self.as_ptr(),
                &def,
                points.as_ptr() as *const f64,
                count,
                &mut id,
            )
        })?;
        Ok(id)
    }

    /// A body of several shapes (`carom_world_add_compound`): the centre of
    /// mass of their union is placed at (def.x, def.y).
    pub fn add_compound(
        &mut self,
        def: &carom_body_def,
        shapes: &[CompoundShape],
    ) -> Result<carom_body_id> {
        let def = sized(def);
        let count = i32::try_from(shapes.len())
            .map_err(|_| Error::from_status(CAROM_ERR_BAD_ARGUMENT))?;
        let mut defs = Vec::with_capacity(shapes.len());
        for sh in shapes {
            let (mut d, status) = defaults(carom_shape_def_init);
            check(status)?;
            d.kind = sh.kind;
            d.x = sh.offset[0];
            d.y = sh.offset[1];
            d.angle = sh.angle;
            d.radius = sh.radius;
            // [[f64; 2]] is laid out as x0, y0, x1, y1, ...; `shapes` outlives the call
            d.xy = if sh.points.is_empty() { ptr::null() } else { sh.points.as_ptr() as *const f64 };
            d.count = i32::try_from(sh.points.len()).unwrap_or(i32::MAX);
            d.density = sh.density.unwrap_or(-1.0);
            d.restitution = sh.restitution.unwrap_or(-1.0);
            d.friction = sh.friction.unwrap_or(-1.0);
            defs.push(d);
        }
        let mut id = CAROM_NULL_BODY;
        check(unsafe { carom_world_add_compound(self.as_ptr(), &def, defs.as_ptr(), count, &mut id) })?;
        Ok(id)
    }

    /// The shapes a body is made of (one for a circle or polygon body).
    pub fn shapes(&self, id: carom_body_id) -> Result<Vec<ShapeInfo>> {
        let mut n = 0;
        check(unsafe { carom_body_get_shape_count(self.as_ptr(), id, &mut n) })?;
        let mut out = Vec::with_capacity(n.max(0) as usize);
        for k in 0..n {
            let mut info = ShapeInfo {
                kind: 0,
                center: (0.0, 0.0),
                radius: 0.0,
                vertices: Vec::new(),
                density: 0.0,
                restitution: 0.0,
                friction: 0.0,
            };
            let mut count = 0;
            check(unsafe {
                carom_body_get_shape_geometry(
                    self.as_ptr(),
                    id,
                    k,
                    &mut info.kind,
                    &mut info.center.0,
                    &mut info.center.1,
                    &mut info.radius,
                    ptr::null_mut(),
                    0,
                    &mut count,
                )
            })?;
            info.vertices = vec![[0.0f64; 2]; count.max(0) as usize];
            check(unsafe {
                carom_body_get_shape_geometry(
                    self.as_ptr(),
                    id,
                    k,
                    ptr::null_mut(),
                    ptr::null_mut(),
                    ptr::null_mut(),
                    ptr::null_mut(),
                    info.vertices.as_mut_ptr() as *mut f64,
                    count.max(0),
                    ptr::null_mut(),
                )
            })?;
            check(unsafe {
                carom_body_get_shape_material(
                    self.as_ptr(),
                    id,
                    k,
                    &mut info.density,
                    &mut info.restitution,
                    &mut info.friction,
                )
            })?;
            out.push(info);
        }
        Ok(out)
    }

    /// Remove a body; its id becomes stale. What it touched wakes, and its
    /// weight comes off the impulses of the contacts beneath it, which the
    /// next update starts from.
    pub fn remove_body(&mut self, id: carom_body_id) -> Result<()> {
        check(unsafe { carom_world_remove_body(self.as_ptr(), id) })
    }

    pub fn is_alive(&self, id: carom_body_id) -> bool {
        let status = unsafe { carom_body_check(self.as_ptr(), id) };
        status == CAROM_OK
    }

    pub fn position(&self, id: carom_body_id) -> Result<(f64, f64)> {
        let (mut x, mut y) = (0.0, 0.0);
        check(unsafe { carom_body_get_position(self.as_ptr(), id, &mut x, &mut y) })?;
        Ok((x, y))
    }

    pub fn set_position(&mut self, id: carom_body_id, x: f64, y: f64) -> Result<()> {
        check(unsafe { carom_body_set_position(self.as_ptr(), id, x, y) })
    }

    pub fn velocity(&self, id: carom_body_id) -> Result<(f64, f64)> {
        let (mut x, mut y) = (0.0, 0.0);
        check(unsafe { carom_body_get_velocity(self.as_ptr(), id, &mut x, &mut y) })?;
        Ok((x, y))
    }

    pub fn set_velocity(&mut self, id: carom_body_id, vx: f64, vy: f64) -> Result<()> {
        check(unsafe { carom_body_set_velocity(self.as_ptr(), id, vx, vy) })
    }

    pub fn angle(&self, id: carom_body_id) -> Result<f64> {
        let mut a = 0.0;
        check(unsafe { carom_body_get_angle(self.as_ptr(), id, &mut a) })?;
        Ok(a)
    }

    pub fn spin(&self, id: carom_body_id) -> Result<f64> {
        let mut w = 0.0;
        check(unsafe { carom_body_get_spin(self.as_ptr(), id, &mut w) })?;
        Ok(w)
    }

    /// (mass, inertia, area); mass and inertia are 0 for a static body.
    pub fn mass(&self, id: carom_body_id) -> Result<(f64, f64, f64)> {
        let (mut m, mut i, mut a) = (0.0, 0.0, 0.0);
        check(unsafe { carom_body_get_mass(self.as_ptr(), id, &mut m, &mut i, &mut a) })?;
        Ok((m, i, a))
    }

    /// A polygon's vertices in world coordinates, counter-clockwise; empty
    /// for a circle and a compound (see [`World::shapes`]).
    pub fn vertices(&self, id: carom_body_id) -> Result<Vec<[f64; 2]>> {
        let mut n = 0;
        check(unsafe { carom_body_get_vertices(self.as_ptr(), id, ptr::null_mut(), 0, &mut n) })?;
        let mut xy = vec![[0.0f64; 2]; n.max(0) as usize];
        let mut got = 0;
        check(unsafe {
            carom_body_get_vertices(self.as_ptr(), id, xy.as_mut_ptr() as *mut f64, n, &mut got)
        })?;
        xy.truncate(got.clamp(0, n) as usize);
        Ok(xy)
    }

    /// Contacts found by the last step (or [`World::detect`]).
    pub fn contacts(&self) -> Vec<Contact> {
        let n = unsafe { carom_world_contact_count(self.as_ptr()) };
        (0..n)
            .filter_map(|i| {
                let mut c = Contact {
                    a: 0,
                    b: 0,
                    point: (0.0, 0.0),
                    normal: (0.0, 0.0),
                    depth: 0.0,
                };
                let s = unsafe {
                    carom_world_get_contact(
                        self.as_ptr(),
                        i,
                        &mut c.a,
                        &mut c.b,
                        &mut c.point.0,
                        &mut c.point.1,
                        &mut c.normal.0,
                        &mut c.normal.1,
                        &mut c.depth,
                    )
                };
                (s == CAROM_OK).then_some(c)
            })
            .collect()
    }

    /// Collision detection alone on the current positions.
    pub fn detect(&mut self) -> Result<Vec<Contact>> {
        check(unsafe { carom_world_detect(self.as_ptr()) })?;
        Ok(self.contacts())
    }
}

/// The first body a ray meets ([`World::cast_ray`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RayHit {
    pub body: carom_body_id,
    pub point: (f64, f64),
    pub normal: (f64, f64),
    pub fraction: f64,
}

/// What a safe call's count-returning C function said: a count, or minus a status.
fn count(n: i32) -> Result<usize> {
    if n < 0 {
        Err(Error::from_status(-n))
    } else {
        Ok(n as usize)
    }
}

/// Version 0.2: forces, impulses, filters, queries and events.
impl World {
    /// A force at a world point, acting over the next step.
    pub fn apply_force(&mut self, id: carom_body_id, f: (f64, f64), at: (f64, f64)) -> Result<()> {
        check(unsafe { carom_body_apply_force(self.as_ptr(), id, f.0, f.1, at.0, at.1) })
    }

    pub fn apply_torque(&mut self, id: carom_body_id, torque: f64) -> Result<()> {
        check(unsafe { carom_body_apply_torque(self.as_ptr(), id, torque) })
    }

    /// An impulse at a world point: the velocity changes at once.
    pub fn apply_impulse(&mut self, id: carom_body_id, j: (f64, f64), at: (f64, f64)) -> Result<()> {
        check(unsafe { carom_body_apply_impulse(self.as_ptr(), id, j.0, j.1, at.0, at.1) })
    }

    pub fn apply_angular_impulse(&mut self, id: carom_body_id, j: f64) -> Result<()> {
        check(unsafe { carom_body_apply_angular_impulse(self.as_ptr(), id, j) })
    }

    pub fn clear_forces(&mut self) -> Result<()> {
        check(unsafe { carom_world_clear_forces(self.as_ptr()) })
    }

    /// (category, mask, group)
    pub fn filter(&self, id: carom_body_id) -> Result<(u32, u32, i32)> {
        let (mut c, mut m, mut g) = (0, 0, 0);
        check(unsafe { carom_body_get_filter(self.as_ptr(), id, &mut c, &mut m, &mut g) })?;
        Ok((c, m, g))
    }

    pub fn set_filter(&mut self, id: carom_body_id, category: u32, mask: u32, group: i32) -> Result<()> {
        check(unsafe { carom_body_set_filter(self.as_ptr(), id, category, mask, group) })
    }

    pub fn is_sensor(&self, id: carom_body_id) -> Result<bool> {
        let mut s = 0;
        check(unsafe { carom_body_is_sensor(self.as_ptr(), id, &mut s) })?;
        Ok(s != 0)
    }

    /// The first body the segment enters, among those whose category & mask is non-zero.
    pub fn cast_ray(&self, from: (f64, f64), to: (f64, f64), mask: u32) -> Result<Option<RayHit>> {
        let mut hit = carom_ray_hit::default();
        check(unsafe { carom_world_cast_ray(self.as_ptr(), from.0, from.1, to.0, to.1, mask, &mut hit) })?;
        Ok((hit.body != CAROM_NULL_BODY).then_some(RayHit {
            body: hit.body,
            point: (hit.x, hit.y),
            normal: (hit.nx, hit.ny),
            fraction: hit.fraction,
        }))
    }

    /// The ids a call of `carom_world_query_aabb`'s kind gives (a count, or
    /// minus a status); body and joint ids alike, both `u64`.
    fn listed(&self, call: impl Fn(*mut carom_body_id, i32) -> i32) -> Result<Vec<carom_body_id>> {
        let n = count(call(ptr::null_mut(), 0))?;
        let mut ids = vec![0; n];
        let got = count(call(ids.as_mut_ptr(), n as i32))?;
        ids.truncate(got.min(n));
        Ok(ids)
    }

    /// The bodies whose shape contains the point.
    pub fn query_point(&self, p: (f64, f64), mask: u32) -> Result<Vec<carom_body_id>> {
        self.listed(|ids, cap| unsafe { carom_world_query_point(self.as_ptr(), p.0, p.1, mask, ids, cap) })
    }

    /// The bodies whose bounding box overlaps the box from `lo` to `hi`.
    pub fn query_aabb(&self, lo: (f64, f64), hi: (f64, f64), mask: u32) -> Result<Vec<carom_body_id>> {
        self.listed(|ids, cap| unsafe { carom_world_query_aabb(self.as_ptr(), lo.0, lo.1, hi.0, hi.1, mask, ids, cap) })
    }

    /// The events of the last step.
    pub fn events(&self) -> Result<Vec<carom_contact_event>> {
        let n = count(unsafe { carom_world_get_events(self.as_ptr(), ptr::null_mut(), 0) })?;
        let mut ev = vec![carom_contact_event::default(); n];
        let got = count(unsafe { carom_world_get_events(self.as_ptr(), ev.as_mut_ptr(), n as i32) })?;
        ev.truncate(got.min(n));
        Ok(ev)
    }

    /// Every body's outline (polygons as their vertices, circles as
    /// centre, radius and angle), through the debug draw.
    pub fn draw(&self, mut polygon: impl FnMut(carom_body_id, &[[f64; 2]]), mut circle: impl FnMut(carom_body_id, (f64, f64), f64, f64)) -> Result<()> {
        struct Sink<'a> {
            polygon: &'a mut dyn FnMut(carom_body_id, &[[f64; 2]]),
            circle: &'a mut dyn FnMut(carom_body_id, (f64, f64), f64, f64),
        }
        unsafe extern "C" fn on_polygon(xy: *const f64, n: i32, body: carom_body_id, user: *mut c_void) {
            let sink = &mut *(user as *mut Sink);
            let pts = std::slice::from_raw_parts(xy as *const [f64; 2], n.max(0) as usize);
            (sink.polygon)(body, pts);
        }
        unsafe extern "C" fn on_circle(x: f64, y: f64, r: f64, a: f64, body: carom_body_id, user: *mut c_void) {
            let sink = &mut *(user as *mut Sink);
            (sink.circle)(body, (x, y), r, a);
        }
        let mut sink = Sink { polygon: &mut polygon, circle: &mut circle };
        let mut d = std::mem::MaybeUninit::<carom_debug_draw>::zeroed();
        check(unsafe { carom_debug_draw_init(d.as_mut_ptr(), size_of::<carom_debug_draw>() as u32) })?;
        let mut d = unsafe { d.assume_init() };
        d.polygon = Some(on_polygon);
        d.circle = Some(on_circle);
        d.user = &mut sink as *mut Sink as *mut c_void;
        d.draw_contacts = 0;
        check(unsafe { carom_world_draw(self.as_ptr(), &d) })
    }
}

/// Version 0.2: joints.
impl World {
    /// Add a joint (`carom_world_add_joint`); it wakes both bodies, which
    /// stop colliding with each other unless `collide_connected`.
    pub fn add_joint(&mut self, def: &JointDef) -> Result<carom_joint_id> {
        let def = def.to_raw();
        let mut id = CAROM_NULL_JOINT;
        check(unsafe { carom_world_add_joint(self.as_ptr(), &def, &mut id) })?;
        Ok(id)
    }

    /// Remove a joint; its id becomes stale. Removing a body removes its
    /// joints too.
    pub fn remove_joint(&mut self, id: carom_joint_id) -> Result<()> {
        check(unsafe { carom_world_remove_joint(self.as_ptr(), id) })
    }

    pub fn joint_is_alive(&self, id: carom_joint_id) -> bool {
        unsafe { carom_joint_check(self.as_ptr(), id) == CAROM_OK }
    }

    pub fn joint_count(&self) -> usize {
        unsafe { carom_world_joint_count(self.as_ptr()) }.max(0) as usize
    }

    /// The live joints' ids in slot order (a removed joint's slot is
    /// reused by the next joint added).
    pub fn joints(&self) -> Vec<carom_joint_id> {
        let n = unsafe { carom_world_get_joints(self.as_ptr(), ptr::null_mut(), 0) }.max(0);
        let mut ids = vec![CAROM_NULL_JOINT; n as usize];
        let got = unsafe { carom_world_get_joints(self.as_ptr(), ids.as_mut_ptr(), n) };
        ids.truncate(got.clamp(0, n) as usize);
        ids
    }

    /// The live joints of one body (it is their a or b), in a fixed order
    /// of their own; `CAROM_ERR_STALE_BODY` for a removed body.
    pub fn body_joints(&self, id: carom_body_id) -> Result<Vec<carom_joint_id>> {
        self.listed(|ids, cap| unsafe { carom_body_get_joints(self.as_ptr(), id, ids, cap) })
    }

    pub fn joint_type(&self, id: carom_joint_id) -> Result<carom_joint_type> {
        let mut t = 0;
        check(unsafe { carom_joint_get_bodies(self.as_ptr(), id, &mut t, ptr::null_mut(), ptr::null_mut()) })?;
        Ok(t)
    }

    /// (a, b); a is [`CAROM_NULL_BODY`] for a joint to the world.
    pub fn joint_bodies(&self, id: carom_joint_id) -> Result<(carom_body_id, carom_body_id)> {
        let (mut a, mut b) = (CAROM_NULL_BODY, CAROM_NULL_BODY);
        check(unsafe { carom_joint_get_bodies(self.as_ptr(), id, ptr::null_mut(), &mut a, &mut b) })?;
        Ok((a, b))
    }

    /// The anchors on a and on b now, in world coordinates (a mouse
    /// joint's: the target, then b's grabbed point).
    pub fn joint_anchors(&self, id: carom_joint_id) -> Result<((f64, f64), (f64, f64))> {
        let (mut ax, mut ay, mut bx, mut by) = (0.0, 0.0, 0.0, 0.0);
        check(unsafe { carom_joint_get_anchors(self.as_ptr(), id, &mut ax, &mut ay, &mut bx, &mut by) })?;
        Ok(((ax, ay), (bx, by)))
    }

    /// (fx, fy, torque): the constraint force on body b (at its anchor)
    /// and torque, averaged over the last step; zeros before the first.
    pub fn joint_reaction(&self, id: carom_joint_id) -> Result<(f64, f64, f64)> {
        let (mut fx, mut fy, mut t) = (0.0, 0.0, 0.0);
        check(unsafe { carom_joint_get_reaction(self.as_ptr(), id, &mut fx, &mut fy, &mut t) })?;
        Ok((fx, fy, t))
    }

    /// Turn a joint's motor on or off, with its speed and most force (a
    /// torque for revolute and wheel joints); wakes the bodies.
    pub fn set_joint_motor(&mut self, id: carom_joint_id, enable: bool, speed: f64, max_force: f64) -> Result<()> {
        check(unsafe { carom_joint_set_motor(self.as_ptr(), id, enable as i32, speed, max_force) })
    }

    /// Turn a joint's limit on or off, with its range (`lower <= upper`):
    /// the relative angle from creation (revolute), the translation
    /// (prismatic, wheel) or the length (distance); wakes the bodies. Weld,
    /// motor and mouse joints have none (`CAROM_ERR_BAD_ARGUMENT`).
    pub fn set_joint_limit(&mut self, id: carom_joint_id, enable: bool, lower: f64, upper: f64) -> Result<()> {
        check(unsafe { carom_joint_set_limit(self.as_ptr(), id, enable as i32, lower, upper) })
    }

    /// Turn a joint's spring on or off, with its frequency and damping
    /// ratio (both >= 0, as [`JointDef::spring`]); wakes the bodies. A
    /// mouse joint's are its pull (0 for its defaults; `enable` is
    /// ignored); a motor joint has none (`CAROM_ERR_BAD_ARGUMENT`).
    pub fn set_joint_spring(&mut self, id: carom_joint_id, enable: bool, hertz: f64, damping_ratio: f64) -> Result<()> {
        check(unsafe { carom_joint_set_spring(self.as_ptr(), id, enable as i32, hertz, damping_ratio) })
    }

    /// Move a mouse joint's target (the world point (x, y); `angle` is
    /// ignored) or a motor joint's (b's centre in a's frame, and b's angle
    /// less a's); wakes the bodies.
    pub fn set_joint_target(&mut self, id: carom_joint_id, x: f64, y: f64, angle: f64) -> Result<()> {
        check(unsafe { carom_joint_set_target(self.as_ptr(), id, x, y, angle) })
    }

    /// Every joint through the debug draw, in slot order: its type, id and
    /// four points, the centre of body a, the anchor on a, the anchor on b
    /// and the centre of body b (for a joint to the world the first two are
    /// its fixed point; for a mouse joint, its target).
    pub fn draw_joints(&self, mut joint: impl FnMut(carom_joint_type, carom_joint_id, &[[f64; 2]; 4])) -> Result<()> {
        struct Sink<'a> {
            joint: &'a mut dyn FnMut(carom_joint_type, carom_joint_id, &[[f64; 2]; 4]),
        }
        unsafe extern "C" fn on_joint(t: carom_joint_type, xy: *const f64, id: carom_joint_id, user: *mut c_void) {
            let sink = &mut *(user as *mut Sink);
            let pts = &*(xy as *const [[f64; 2]; 4]);
            (sink.joint)(t, id, pts);
        }
        let mut sink = Sink { joint: &mut joint };
        let (mut d, status) = defaults(carom_debug_draw_init);
        check(status)?;
        d.joint = Some(on_joint);
        d.user = &mut sink as *mut Sink as *mut c_void;
        d.draw_bodies = 0;
        d.draw_contacts = 0;
        check(unsafe { carom_world_draw(self.as_ptr(), &d) })
    }
}

impl Drop for World {
    fn drop(&mut self) {
        // SAFETY: owned, destroyed once.
        unsafe { carom_world_destroy(self.ptr.as_ptr()) }
    }
}

fn sized(def: &carom_body_def) -> carom_body_def {
    let mut d = *def;
    d.size = size_of::<carom_body_def>() as u32;
    d
}
