//! Joints (version 0.2) through the declarations of this crate, raw and safe.
use carom_sys::safe::{self, JointDef, World};
use carom_sys::*;
use std::mem::size_of;
use std::ptr;

const G: f64 = 9.81;

fn world_with_gravity(gy: f64) -> World {
    let mut def = safe::world_def();
    def.gravity_y = gy;
    World::with_def(&def).unwrap()
}

fn dynamic_at(x: f64, y: f64) -> carom_body_def {
    let mut d = safe::body_def();
    d.x = x;
    d.y = y;
    d
}

fn static_at(x: f64, y: f64) -> carom_body_def {
    let mut d = dynamic_at(x, y);
    d.type_ = CAROM_STATIC;
    d
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn joint_def_and_debug_draw_sizes_match_the_library() {
    assert_eq!(safe::library_accepts_joint_sizes(), (CAROM_OK, CAROM_OK));
    let d = safe::joint_def();
    assert_eq!(d.size as usize, size_of::<carom_joint_def>());
    assert_eq!(carom_joint_def { size: d.size, ..Default::default() }, d); // all zeros
    let mut big = [0u8; 512];
    let st = unsafe {
        carom_joint_def_init(big.as_mut_ptr() as *mut carom_joint_def, size_of::<carom_joint_def>() as u32 + 8)
    };
    assert_eq!(st, CAROM_ERR_BAD_STRUCT_SIZE);
    assert!(big.iter().all(|&b| b == 0)); // nothing written
    assert!(safe::status_string(CAROM_ERR_STALE_JOINT).contains("joint"));
}

#[test]
fn pendulum_keeps_its_length() {
    // a small disc on a revolute joint to the world, 1 m from the pivot,
    // released horizontally
    let mut world = world_with_gravity(-G);
    let bob = world.add_circle(&dynamic_at(1.0, 0.0), 0.05).unwrap();
    let pivot = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, bob, (0.0, 0.0))).unwrap();
    assert_eq!(world.joint_type(pivot).unwrap(), CAROM_JOINT_REVOLUTE);
    assert_eq!(world.joint_bodies(pivot).unwrap(), (CAROM_NULL_BODY, bob));
    let (mut worst, mut lowest) = (0.0f64, 0.0f64);
    for _ in 0..120 {
        world.step(1.0 / 60.0).unwrap();
        let (x, y) = world.position(bob).unwrap();
        worst = worst.max(((x * x + y * y).sqrt() - 1.0).abs());
        lowest = lowest.min(y);
        let ((ax, ay), (bx, by)) = world.joint_anchors(pivot).unwrap();
        assert_eq!((ax, ay), (0.0, 0.0));
        assert!((bx * bx + by * by).sqrt() < 1e-4, "anchor on b at ({}, {})", bx, by);
    }
    assert!(worst <= 1e-6, "the length changed by {}", worst);
    assert!(lowest < -0.99, "it never swung through the bottom ({})", lowest);
}

#[test]
fn hanging_body_reaction_is_its_weight() {
    let mut world = world_with_gravity(-G);
    let boxed = world.add_box(&dynamic_at(0.0, -1.0), 0.2, 0.2).unwrap();
    let rope = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, boxed, (0.0, 0.0))).unwrap();
    assert_eq!(world.joint_reaction(rope).unwrap(), (0.0, 0.0, 0.0)); // before the first step
    for _ in 0..60 {
        world.step(1.0 / 60.0).unwrap();
    }
    let (m, _, _) = world.mass(boxed).unwrap();
    let (fx, fy, torque) = world.joint_reaction(rope).unwrap();
    assert!(close(fy, m * G, 0.01 * m * G), "reaction {} for a weight {}", fy, m * G);
    assert!(fx.abs() < 1e-9 && torque.abs() < 1e-9);
    // a weld 1 m left of a box's centre also holds the moment m g d
    let cube = world.add_box(&dynamic_at(6.0, 0.0), 1.0, 1.0).unwrap();
    let weld = world.add_joint(&JointDef::weld(CAROM_NULL_BODY, cube, (5.0, 0.0))).unwrap();
    for _ in 0..60 {
        world.step(1.0 / 60.0).unwrap();
    }
    let (m, _, _) = world.mass(cube).unwrap();
    let (_, fy, torque) = world.joint_reaction(weld).unwrap();
    assert!(close(fy, m * G, 0.01 * m * G) && close(torque, m * G, 0.01 * m * G), "{} {}", fy, torque);
    let (x, y) = world.position(cube).unwrap();
    assert!(close(x, 6.0, 1e-9) && close(y, 0.0, 1e-9));
}

#[test]
fn removing_a_body_makes_its_joints_stale() {
    let mut world = world_with_gravity(-G);
    let holder = world.add_circle(&dynamic_at(0.0, -1.0), 0.1).unwrap();
    let hanging = world.add_circle(&dynamic_at(0.0, -2.0), 0.1).unwrap();
    let top = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, holder, (0.0, 0.0))).unwrap();
    let low = world.add_joint(&JointDef::distance(holder, hanging, (0.0, -1.0), (0.0, -2.0))).unwrap();
    assert_eq!(world.joint_count(), 2);
    assert_ne!(unsafe { carom_world_get_effects(world.as_ptr()) } & CAROM_EFFECT_JOINTS as u32, 0);
    world.step(1.0 / 60.0).unwrap();
    world.remove_body(holder).unwrap();
    assert_eq!(world.joint_count(), 0);
    assert_eq!(unsafe { carom_world_get_effects(world.as_ptr()) } & CAROM_EFFECT_JOINTS as u32, 0);
    for id in [top, low] {
        assert!(!world.joint_is_alive(id));
        assert_eq!(world.joint_reaction(id).unwrap_err().status, CAROM_ERR_STALE_JOINT);
        assert_eq!(world.joint_anchors(id).unwrap_err().status, CAROM_ERR_STALE_JOINT);
        assert_eq!(world.joint_bodies(id).unwrap_err().status, CAROM_ERR_STALE_JOINT);
        assert_eq!(world.set_joint_motor(id, true, 1.0, 1.0).unwrap_err().status, CAROM_ERR_STALE_JOINT);
        assert_eq!(world.set_joint_target(id, 0.0, 0.0, 0.0).unwrap_err().status, CAROM_ERR_STALE_JOINT);
        let err = world.remove_joint(id).unwrap_err();
        assert_eq!(err.status, CAROM_ERR_STALE_JOINT);
        assert_eq!(err.message, safe::status_string(CAROM_ERR_STALE_JOINT));
    }
    // the body that hung from it falls freely now
    let (_, y0) = world.position(hanging).unwrap();
    let (_, vy0) = world.velocity(hanging).unwrap();
    world.step(0.1).unwrap();
    let (_, y1) = world.position(hanging).unwrap();
    assert!(close(y1, y0 + vy0 * 0.1 - 0.5 * G * 0.01, 1e-9));
    // a removed joint's slot is reused with a new generation: the old id stays stale
    let cube = world.add_box(&dynamic_at(3.0, 0.0), 1.0, 1.0).unwrap();
    let again = world.add_joint(&JointDef::weld(CAROM_NULL_BODY, cube, (3.0, 0.0))).unwrap();
    assert!(again != top && again != low && world.joint_is_alive(again) && !world.joint_is_alive(low));
    world.remove_joint(again).unwrap();
    assert!(!world.joint_is_alive(again) && world.joint_count() == 0);
}

#[test]
fn bad_joint_input_returns_the_status_and_adds_nothing() {
    let cases: Vec<(&str, Box<dyn Fn(carom_body_id, carom_body_id, carom_body_id) -> JointDef>, carom_status)> = vec![
        ("a == b", Box::new(|_, b, _| JointDef::revolute(b, b, (0.0, 0.0))), CAROM_ERR_BAD_ARGUMENT),
        ("unknown type", Box::new(|_, b, _| JointDef::new(7, CAROM_NULL_BODY, b)), CAROM_ERR_BAD_ARGUMENT),
        ("negative type", Box::new(|_, b, _| JointDef::new(-1, CAROM_NULL_BODY, b)), CAROM_ERR_BAD_ARGUMENT),
        ("negative hertz", Box::new(|g, b, _| JointDef::weld(g, b, (0.0, 0.0)).spring(-1.0, 0.5)), CAROM_ERR_BAD_ARGUMENT),
        ("negative damping", Box::new(|g, b, _| JointDef::weld(g, b, (0.0, 0.0)).spring(1.0, -0.5)), CAROM_ERR_BAD_ARGUMENT),
        ("mouse with a", Box::new(|g, b, _| JointDef { a: g, ..JointDef::mouse(b, (0.0, 2.0)) }), CAROM_ERR_BAD_ARGUMENT),
        ("zero axis", Box::new(|g, b, _| JointDef::prismatic(g, b, (0.0, 0.0), (0.0, 0.0))), CAROM_ERR_BAD_ARGUMENT),
        ("lower > upper", Box::new(|_, b, _| JointDef::revolute(CAROM_NULL_BODY, b, (0.0, 0.0)).limit(1.0, -1.0)), CAROM_ERR_BAD_ARGUMENT),
        ("negative force", Box::new(|_, b, _| JointDef::revolute(CAROM_NULL_BODY, b, (0.0, 0.0)).motor(1.0, -1.0)), CAROM_ERR_BAD_ARGUMENT),
        ("negative torque", Box::new(|_, b, _| JointDef::new(CAROM_JOINT_MOTOR, CAROM_NULL_BODY, b).max_torque(-1.0)), CAROM_ERR_BAD_ARGUMENT),
        ("coinciding anchors", Box::new(|g, b, _| JointDef::distance(g, b, (1.0, 1.0), (1.0, 1.0))), CAROM_ERR_BAD_ARGUMENT),
        ("huge", Box::new(|_, b, _| JointDef::revolute(CAROM_NULL_BODY, b, (1e101, 0.0))), CAROM_ERR_BAD_ARGUMENT),
        ("nan", Box::new(|_, b, _| JointDef::revolute(CAROM_NULL_BODY, b, (0.0, f64::NAN))), CAROM_ERR_NOT_FINITE),
        ("no dynamic body", Box::new(|g, _, _| JointDef::revolute(CAROM_NULL_BODY, g, (0.0, 0.0))), CAROM_ERR_STATIC_BODY),
        ("stale body", Box::new(|_, b, gone| JointDef::revolute(gone, b, (0.0, 0.0))), CAROM_ERR_STALE_BODY),
        ("no b", Box::new(|g, _, _| JointDef::revolute(g, CAROM_NULL_BODY, (0.0, 0.0))), CAROM_ERR_STALE_BODY),
    ];
    for (what, make, status) in cases {
        let mut world = world_with_gravity(-G);
        let ground = world.add_box(&static_at(0.0, -0.5), 10.0, 1.0).unwrap();
        let ball = world.add_circle(&dynamic_at(0.0, 2.0), 0.5).unwrap();
        let gone = world.add_circle(&dynamic_at(3.0, 2.0), 0.5).unwrap();
        world.remove_body(gone).unwrap();
        let err = world.add_joint(&make(ground, ball, gone)).unwrap_err();
        assert_eq!(err.status, status, "{}", what);
        assert_eq!(world.joint_count(), 0, "{}", what);
        assert_eq!(unsafe { carom_world_get_effects(world.as_ptr()) } & CAROM_EFFECT_JOINTS as u32, 0);
        world.step(0.5).unwrap(); // nothing holds the ball: free fall, exactly
        let (_, y) = world.position(ball).unwrap();
        assert!(close(y, 2.0 - 0.5 * G * 0.25, 1e-9), "{}: y = {}", what, y);
    }
    // raw: a NULL def and a wrong size
    let mut world = World::new().unwrap();
    let ball = world.add_circle(&safe::body_def(), 0.5).unwrap();
    let mut id = CAROM_NULL_JOINT;
    assert_eq!(unsafe { carom_world_add_joint(world.as_ptr(), ptr::null(), &mut id) }, CAROM_ERR_NULL_ARGUMENT);
    let mut raw = JointDef::revolute(CAROM_NULL_BODY, ball, (0.0, 0.0)).to_raw();
    raw.size = 8;
    assert_eq!(unsafe { carom_world_add_joint(world.as_ptr(), &raw, &mut id) }, CAROM_ERR_BAD_STRUCT_SIZE);
    assert_eq!((id, world.joint_count()), (CAROM_NULL_JOINT, 0));
    assert_eq!(unsafe { carom_joint_check(world.as_ptr(), 1) }, CAROM_ERR_STALE_JOINT);
    assert_eq!(unsafe { carom_joint_check(ptr::null(), 1) }, CAROM_ERR_NULL_ARGUMENT);
}

#[test]
fn motors_limits_springs_and_targets() {
    // a revolute motor drives the spin
    let mut world = World::new().unwrap();
    let wheel = world.add_circle(&dynamic_at(1.0, 2.0), 0.5).unwrap();
    let axle = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, wheel, (1.0, 2.0)).motor(2.0, 100.0)).unwrap();
    for _ in 0..30 {
        world.step(1.0 / 60.0).unwrap();
    }
    assert!(close(world.spin(wheel).unwrap(), 2.0, 1e-9));
    world.set_joint_motor(axle, true, -1.0, 100.0).unwrap();
    for _ in 0..30 {
        world.step(1.0 / 60.0).unwrap();
    }
    assert!(close(world.spin(wheel).unwrap(), -1.0, 1e-9));
    assert_eq!(world.set_joint_motor(axle, true, 1.0, -1.0).unwrap_err().status, CAROM_ERR_BAD_ARGUMENT);
    assert_eq!(world.set_joint_motor(axle, true, f64::NAN, 1.0).unwrap_err().status, CAROM_ERR_NOT_FINITE);
    assert_eq!(world.set_joint_target(axle, 0.0, 0.0, 0.0).unwrap_err().status, CAROM_ERR_BAD_ARGUMENT);

    // a prismatic joint stops at its limit
    let mut world = world_with_gravity(-10.0);
    let slider = world.add_box(&dynamic_at(0.0, 3.0), 0.5, 0.5).unwrap();
    let rail = world
        .add_joint(&JointDef::prismatic(CAROM_NULL_BODY, slider, (0.0, 3.0), (0.0, 2.0)).limit(-1.0, 0.0))
        .unwrap();
    for _ in 0..120 {
        world.step(1.0 / 60.0).unwrap();
    }
    let (x, y) = world.position(slider).unwrap();
    assert!(x.abs() < 1e-9 && close(y, 2.0, 1e-3) && world.angle(slider).unwrap().abs() < 1e-9);
    let (m, _, _) = world.mass(slider).unwrap();
    assert!(close(world.joint_reaction(rail).unwrap().1, m * 10.0, 0.01 * m * 10.0));

    // an undamped 2 Hz spring swings to twice its static stretch
    let mut world = world_with_gravity(-G);
    let bob = world.add_circle(&dynamic_at(0.0, -1.0), 0.1).unwrap();
    world.add_joint(&JointDef::distance(CAROM_NULL_BODY, bob, (0.0, 0.0), (0.0, -1.0)).spring(2.0, 0.0)).unwrap();
    let mut lowest = 0.0f64;
    for _ in 0..240 {
        world.step(1.0 / 240.0).unwrap();
        lowest = lowest.min(world.position(bob).unwrap().1);
    }
    let omega = 2.0 * std::f64::consts::PI * 2.0;
    assert!(close(lowest, -1.0 - 2.0 * G / (omega * omega), 0.01), "lowest {}", lowest);

    // a mouse joint drags its body; a motor joint drives b to a pose
    let mut world = World::new().unwrap();
    let crate_ = world.add_box(&dynamic_at(1.0, 1.0), 0.5, 0.5).unwrap();
    let mouse = world.add_joint(&JointDef::mouse(crate_, (1.0, 1.0))).unwrap();
    world.set_joint_target(mouse, 3.0, 2.0, 0.0).unwrap();
    assert_eq!(world.joint_anchors(mouse).unwrap(), ((3.0, 2.0), (1.0, 1.0)));
    assert_eq!(world.set_joint_motor(mouse, true, 1.0, 1.0).unwrap_err().status, CAROM_ERR_BAD_ARGUMENT);
    let cube = world.add_box(&dynamic_at(-5.0, 0.0), 1.0, 1.0).unwrap();
    let drive = world
        .add_joint(&JointDef::new(CAROM_JOINT_MOTOR, CAROM_NULL_BODY, cube).max_force(1e4).max_torque(1e4))
        .unwrap();
    world.set_joint_target(drive, -3.0, 1.0, 0.5).unwrap();
    for _ in 0..180 {
        world.step(1.0 / 60.0).unwrap();
    }
    let (x, y) = world.position(crate_).unwrap();
    assert!(close(x, 3.0, 1e-3) && close(y, 2.0, 1e-3), "the mouse left it at ({}, {})", x, y);
    let (x, y) = world.position(cube).unwrap();
    assert!(close(x, -3.0, 1e-3) && close(y, 1.0, 1e-3), "the motor left it at ({}, {})", x, y);
    assert!(close(world.angle(cube).unwrap(), 0.5, 1e-3));
}

#[test]
fn joined_bodies_do_not_collide_unless_collide_connected() {
    for collide in [false, true] {
        let mut world = World::new().unwrap();
        let a = world.add_box(&dynamic_at(0.0, 0.0), 1.0, 1.0).unwrap();
        let b = world.add_box(&dynamic_at(0.5, 0.0), 1.0, 1.0).unwrap(); // overlapping
        world.add_joint(&JointDef::weld(a, b, (0.25, 0.0)).collide_connected(collide)).unwrap();
        assert_eq!(!world.detect().unwrap().is_empty(), collide);
    }
}

#[test]
fn draw_joints_gives_the_four_points() {
    let mut world = World::new().unwrap();
    let ground = world.add_box(&static_at(0.0, 0.0), 4.0, 1.0).unwrap();
    let arm = world.add_box(&dynamic_at(1.0, 2.0), 2.0, 0.2).unwrap();
    let bob = world.add_circle(&dynamic_at(3.0, 0.0), 0.1).unwrap();
    let hinge = world.add_joint(&JointDef::revolute(ground, arm, (0.0, 2.0))).unwrap();
    let pin = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, bob, (3.0, 1.0))).unwrap();
    let mut seen = Vec::new();
    world.draw_joints(|t, id, pts| seen.push((t, id, *pts))).unwrap();
    assert_eq!(
        seen,
        vec![
            (CAROM_JOINT_REVOLUTE, hinge, [[0.0, 0.0], [0.0, 2.0], [0.0, 2.0], [1.0, 2.0]]),
            (CAROM_JOINT_REVOLUTE, pin, [[3.0, 1.0], [3.0, 1.0], [3.0, 1.0], [3.0, 0.0]]),
        ]
    );
    // the bodies' draw is unchanged by the joints' fields
    let (mut polys, mut circles) = (0, 0);
    world.draw(|_, _| polys += 1, |_, _, _, _| circles += 1).unwrap();
    assert_eq!((polys, circles), (2, 1));
}
