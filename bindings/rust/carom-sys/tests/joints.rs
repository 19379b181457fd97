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
        assert_eq!(world.set_joint_limit(id, true, -1.0, 1.0).unwrap_err().status, CAROM_ERR_STALE_JOINT);
        assert_eq!(world.set_joint_spring(id, true, 1.0, 0.5).unwrap_err().status, CAROM_ERR_STALE_JOINT);
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

fn sorted(mut ids: Vec<carom_joint_id>) -> Vec<carom_joint_id> {
    ids.sort_unstable();
    ids
}

#[test]
fn world_and_body_list_their_joints() {
    let mut world = World::new().unwrap();
    assert_eq!(world.joints(), Vec::<carom_joint_id>::new());
    let ground = world.add_box(&static_at(0.0, 0.0), 10.0, 1.0).unwrap();
    let a = world.add_circle(&dynamic_at(0.0, 2.0), 0.5).unwrap();
    let b = world.add_circle(&dynamic_at(2.0, 2.0), 0.5).unwrap();
    let c = world.add_circle(&dynamic_at(4.0, 2.0), 0.5).unwrap();
    assert!(world.body_joints(a).unwrap().is_empty() && world.body_joints(ground).unwrap().is_empty());
    let hinge = world.add_joint(&JointDef::revolute(ground, a, (0.0, 2.0))).unwrap();
    let rod = world.add_joint(&JointDef::distance(a, b, (0.0, 2.0), (2.0, 2.0))).unwrap();
    let weld = world.add_joint(&JointDef::weld(b, c, (3.0, 2.0))).unwrap();
    let pin = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, c, (4.0, 3.0))).unwrap();
    assert_eq!(world.joints(), vec![hinge, rod, weld, pin]); // slot order
    // a body's own, each once, in an order of their own
    for (body, mine) in [(ground, vec![hinge]), (a, vec![hinge, rod]), (b, vec![rod, weld]), (c, vec![weld, pin])] {
        let listed = world.body_joints(body).unwrap();
        assert_eq!(sorted(listed.clone()), sorted(mine));
        for j in listed {
            let (ja, jb) = world.joint_bodies(j).unwrap();
            assert!(ja == body || jb == body);
        }
    }
    // a joint removed on its own vanishes from both lists
    world.remove_joint(rod).unwrap();
    assert_eq!(world.joints(), vec![hinge, weld, pin]);
    assert_eq!(world.body_joints(a).unwrap(), vec![hinge]);
    assert_eq!(world.body_joints(b).unwrap(), vec![weld]);
    // its slot is reused by the next joint, listed there; the old id is not
    let rail = world.add_joint(&JointDef::prismatic(ground, b, (2.0, 2.0), (1.0, 0.0))).unwrap();
    assert_eq!(world.joints(), vec![hinge, rail, weld, pin]);
    assert_eq!(sorted(world.body_joints(b).unwrap()), sorted(vec![rail, weld]));
    assert!(!world.joints().contains(&rod));
    // a removed body's joints vanish from every list, and its own is an error
    world.remove_body(b).unwrap();
    assert_eq!(world.joints(), vec![hinge, pin]);
    assert_eq!(world.joint_count(), 2);
    assert_eq!(world.body_joints(ground).unwrap(), vec![hinge]);
    assert_eq!(world.body_joints(a).unwrap(), vec![hinge]);
    assert_eq!(world.body_joints(c).unwrap(), vec![pin]);
    let err = world.body_joints(b).unwrap_err();
    assert_eq!(err.status, CAROM_ERR_STALE_BODY);
    assert_eq!(err.message, safe::status_string(CAROM_ERR_STALE_BODY));
    world.remove_body(a).unwrap();
    world.remove_body(c).unwrap();
    assert!(world.joints().is_empty() && world.body_joints(ground).unwrap().is_empty());
}

#[test]
fn joint_lists_through_the_raw_calls() {
    // the carom_world_query_aabb convention: the count whatever the
    // capacity, or minus a status, writing nothing then
    let mut world = World::new().unwrap();
    let bob = world.add_circle(&safe::body_def(), 0.5).unwrap();
    let first = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, bob, (0.0, 0.0))).unwrap();
    let second = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, bob, (1.0, 0.0))).unwrap();
    let w = world.as_ptr();
    let mut one = [CAROM_NULL_JOINT; 1];
    unsafe {
        assert_eq!(carom_world_get_joints(w, one.as_mut_ptr(), 1), 2);
        assert_eq!(one[0], first);
        assert_eq!(carom_world_get_joints(w, ptr::null_mut(), 0), 2);
        assert_eq!(carom_body_get_joints(w, bob, ptr::null_mut(), 0), 2);
        let mut none = [CAROM_NULL_JOINT; 1];
        assert_eq!(carom_world_get_joints(ptr::null(), none.as_mut_ptr(), 1), -CAROM_ERR_NULL_ARGUMENT);
        assert_eq!(carom_world_get_joints(w, ptr::null_mut(), 1), -CAROM_ERR_NULL_ARGUMENT);
        assert_eq!(carom_world_get_joints(w, none.as_mut_ptr(), -1), -CAROM_ERR_BAD_ARGUMENT);
        assert_eq!(carom_body_get_joints(ptr::null(), bob, none.as_mut_ptr(), 1), -CAROM_ERR_NULL_ARGUMENT);
        assert_eq!(carom_body_get_joints(w, bob, ptr::null_mut(), 1), -CAROM_ERR_NULL_ARGUMENT);
        assert_eq!(carom_body_get_joints(w, bob, none.as_mut_ptr(), -1), -CAROM_ERR_BAD_ARGUMENT);
        assert_eq!(carom_body_get_joints(w, CAROM_NULL_BODY, none.as_mut_ptr(), 1), -CAROM_ERR_STALE_BODY);
        assert_eq!(none[0], CAROM_NULL_JOINT); // nothing written
        assert_eq!(carom_joint_set_limit(ptr::null_mut(), first, 1, 0.0, 1.0), CAROM_ERR_NULL_ARGUMENT);
        assert_eq!(carom_joint_set_spring(ptr::null_mut(), first, 1, 1.0, 0.0), CAROM_ERR_NULL_ARGUMENT);
    }
    assert_eq!(sorted(world.body_joints(bob).unwrap()), sorted(vec![first, second]));
}

#[test]
fn set_joint_limit_stops_a_swinging_bar_at_the_new_limit() {
    // a 2 m bar pinned at its left end, released horizontally: its limit
    // holds it at -0.3 rad; widened to -1, it swings down and stops there
    let one_degree = 1.0f64.to_radians();
    let mut world = world_with_gravity(-G);
    let bar = world.add_box(&dynamic_at(1.0, 0.0), 2.0, 0.1).unwrap();
    let hinge = world.add_joint(&JointDef::revolute(CAROM_NULL_BODY, bar, (0.0, 0.0)).limit(-0.3, 0.3)).unwrap();
    for _ in 0..120 {
        world.step(1.0 / 60.0).unwrap();
    }
    assert!(close(world.angle(bar).unwrap(), -0.3, one_degree));
    world.set_joint_limit(hinge, true, -1.0, 0.3).unwrap();
    let mut lowest = 0.0f64;
    for _ in 0..180 {
        world.step(1.0 / 60.0).unwrap();
        lowest = lowest.min(world.angle(bar).unwrap());
    }
    assert!(lowest >= -1.0 - one_degree, "it swung past the limit, to {}", lowest);
    let angle = world.angle(bar).unwrap();
    assert!(close(angle, -1.0, one_degree), "it rests at {}", angle);
    assert!(world.spin(bar).unwrap().abs() < 0.01);
    // a failed call changes nothing: the limit still holds
    assert_eq!(world.set_joint_limit(hinge, true, 0.5, -0.5).unwrap_err().status, CAROM_ERR_BAD_ARGUMENT);
    for _ in 0..60 {
        world.step(1.0 / 60.0).unwrap();
    }
    assert!(close(world.angle(bar).unwrap(), -1.0, one_degree));
    // switched off, the bar swings on down past the vertical
    world.set_joint_limit(hinge, false, 0.0, 0.0).unwrap();
    for _ in 0..60 {
        world.step(1.0 / 60.0).unwrap();
        lowest = lowest.min(world.angle(bar).unwrap());
    }
    assert!(lowest < -std::f64::consts::FRAC_PI_2, "lowest {}", lowest);
}

#[test]
fn set_joint_spring_of_one_hertz_gives_a_period_of_one_second() {
    // a rigid distance joint made an undamped 1 Hz spring: the bob bobs
    // about its stretch with a period of 1 s, whatever its mass
    let dt = 1.0 / 240.0;
    let mut world = world_with_gravity(-G);
    let mut def = dynamic_at(0.0, -1.0);
    def.density = 3.0;
    let bob = world.add_circle(&def, 0.1).unwrap();
    let rod = world.add_joint(&JointDef::distance(CAROM_NULL_BODY, bob, (0.0, 0.0), (0.0, -1.0))).unwrap();
    for _ in 0..30 {
        world.step(dt).unwrap();
    }
    let (x, y) = world.position(bob).unwrap();
    assert!(close(x, 0.0, 1e-9) && close(y, -1.0, 1e-9), "not rigid: ({}, {})", x, y);
    world.set_joint_spring(rod, true, 1.0, 0.0).unwrap();
    let (mut t, mut prev, mut ups) = (0.0, world.velocity(bob).unwrap().1, Vec::new());
    for _ in 0..5 * 240 {
        world.step(dt).unwrap();
        t += dt;
        let vy = world.velocity(bob).unwrap().1;
        if prev < 0.0 && vy >= 0.0 {
            ups.push(t - dt * vy / (vy - prev)); // the bottom of a bob
        }
        prev = vy;
    }
    assert!(ups.len() >= 4, "{:?}", ups);
    let period = (ups[ups.len() - 1] - ups[0]) / (ups.len() - 1) as f64;
    assert!(close(period, 1.0, 0.05), "period {}", period);
    // switched off: rigid again at its length
    world.set_joint_spring(rod, false, 1.0, 0.0).unwrap();
    for _ in 0..240 {
        world.step(dt).unwrap();
    }
    let (x, y) = world.position(bob).unwrap();
    assert!(close((x * x + y * y).sqrt(), 1.0, 1e-3));
}

#[test]
fn bad_limit_and_spring_return_the_status() {
    type Call = Box<dyn Fn(&mut World, &[carom_joint_id; 5]) -> safe::Result<()>>;
    // joints: hinge, rope, weld, motor, mouse
    let cases: Vec<(&str, Call, carom_status)> = vec![
        ("lower > upper", Box::new(|w, j| w.set_joint_limit(j[0], true, 1.0, -1.0)), CAROM_ERR_BAD_ARGUMENT),
        ("huge limit", Box::new(|w, j| w.set_joint_limit(j[0], true, -1.0, 1e101)), CAROM_ERR_BAD_ARGUMENT),
        ("nan limit", Box::new(|w, j| w.set_joint_limit(j[0], true, f64::NAN, 1.0)), CAROM_ERR_NOT_FINITE),
        ("infinite limit", Box::new(|w, j| w.set_joint_limit(j[0], true, -1.0, f64::INFINITY)), CAROM_ERR_NOT_FINITE),
        ("weld limit", Box::new(|w, j| w.set_joint_limit(j[2], true, -1.0, 1.0)), CAROM_ERR_BAD_ARGUMENT),
        ("motor limit", Box::new(|w, j| w.set_joint_limit(j[3], true, -1.0, 1.0)), CAROM_ERR_BAD_ARGUMENT),
        ("mouse limit", Box::new(|w, j| w.set_joint_limit(j[4], true, -1.0, 1.0)), CAROM_ERR_BAD_ARGUMENT),
        ("negative hertz", Box::new(|w, j| w.set_joint_spring(j[1], true, -1.0, 0.5)), CAROM_ERR_BAD_ARGUMENT),
        ("negative damping", Box::new(|w, j| w.set_joint_spring(j[1], true, 1.0, -0.5)), CAROM_ERR_BAD_ARGUMENT),
        ("huge hertz", Box::new(|w, j| w.set_joint_spring(j[1], true, 1e101, 0.5)), CAROM_ERR_BAD_ARGUMENT),
        ("nan hertz", Box::new(|w, j| w.set_joint_spring(j[1], true, f64::NAN, 0.5)), CAROM_ERR_NOT_FINITE),
        ("motor spring", Box::new(|w, j| w.set_joint_spring(j[3], true, 1.0, 0.5)), CAROM_ERR_BAD_ARGUMENT),
        ("mouse negative hertz", Box::new(|w, j| w.set_joint_spring(j[4], true, -1.0, 0.5)), CAROM_ERR_BAD_ARGUMENT),
    ];
    for (what, call, status) in cases {
        let mut world = World::new().unwrap();
        let ground = world.add_box(&static_at(0.0, 0.0), 10.0, 1.0).unwrap();
        let cube = world.add_box(&dynamic_at(0.0, 2.0), 1.0, 1.0).unwrap();
        let joints = [
            world.add_joint(&JointDef::revolute(ground, cube, (0.0, 2.0))).unwrap(),
            world.add_joint(&JointDef::distance(ground, cube, (0.0, 0.0), (0.0, 2.0))).unwrap(),
            world.add_joint(&JointDef::weld(ground, cube, (0.0, 2.0))).unwrap(),
            world.add_joint(&JointDef::new(CAROM_JOINT_MOTOR, ground, cube).max_force(1.0)).unwrap(),
            world.add_joint(&JointDef::mouse(cube, (0.0, 2.0))).unwrap(),
        ];
        let err = call(&mut world, &joints).unwrap_err();
        assert_eq!(err.status, status, "{}", what);
        assert_eq!(err.message, safe::status_string(status), "{}", what);
        assert_eq!(world.joints(), joints.to_vec(), "{}", what);
    }
    // and what is accepted
    let mut world = World::new().unwrap();
    let ground = world.add_box(&static_at(0.0, 0.0), 10.0, 1.0).unwrap();
    let cube = world.add_box(&dynamic_at(0.0, 2.0), 1.0, 1.0).unwrap();
    let hinge = world.add_joint(&JointDef::revolute(ground, cube, (0.0, 2.0))).unwrap();
    world.set_joint_limit(hinge, true, 0.0, 0.0).unwrap(); // lower == upper: locked
    world.set_joint_spring(hinge, true, 2.0, 1.0).unwrap(); // a torsion spring
    let rail = world.add_joint(&JointDef::prismatic(CAROM_NULL_BODY, cube, (0.0, 2.0), (0.0, 1.0))).unwrap();
    world.set_joint_limit(rail, true, -1.0, 1.0).unwrap();
    let wheel = world.add_joint(&JointDef::wheel(CAROM_NULL_BODY, cube, (0.0, 2.0), (0.0, 1.0))).unwrap();
    world.set_joint_spring(wheel, true, 4.0, 0.7).unwrap();
    let weld = world.add_joint(&JointDef::weld(ground, cube, (0.0, 2.0))).unwrap();
    world.set_joint_spring(weld, true, 5.0, 0.5).unwrap();
    let mouse = world.add_joint(&JointDef::mouse(cube, (0.0, 2.0))).unwrap();
    world.set_joint_spring(mouse, true, 0.0, 0.0).unwrap(); // the mouse joint's defaults
    world.set_joint_spring(mouse, false, 10.0, 0.9).unwrap(); // enable is ignored for it
}
