//! The C library through the declarations of this crate, raw and safe.
use carom_sys::safe::{self, CompoundShape, World};
use carom_sys::*;
use std::mem::size_of;
use std::ptr;

#[test]
fn version_and_struct_sizes_match_the_library() {
    let (major, _, _) = safe::version();
    assert_eq!(major, CAROM_VERSION_MAJOR);
    // The library accepts our #[repr(C)] sizes, and writes them to `size`.
    assert_eq!(safe::library_accepts_def_sizes(), (CAROM_OK, CAROM_OK));
    assert_eq!(safe::world_def().size as usize, size_of::<carom_world_def>());
    assert_eq!(safe::body_def().size as usize, size_of::<carom_body_def>());
    // One byte more than the library knows is refused.
    let mut big = [0u8; 512];
    let st = unsafe {
        carom_world_def_init(big.as_mut_ptr() as *mut carom_world_def, size_of::<carom_world_def>() as u32 + 8)
    };
    assert_eq!(st, CAROM_ERR_BAD_STRUCT_SIZE);
    assert_eq!(safe::body_def().density, 1.0);
    assert_eq!(safe::world_def().iterations, 1);
    assert_eq!(safe::world_def().substeps, 4);
    assert_eq!(safe::world_def().manifold_tolerance, 0.01);
}

#[test]
fn raw_calls_free_fall_closed_form() {
    unsafe {
        let mut wdef = safe::world_def();
        wdef.gravity_y = -10.0;
        let mut world: *mut carom_world = ptr::null_mut();
        assert_eq!(carom_world_init(&mut world, &wdef), CAROM_OK);
        let mut bdef = safe::body_def();
        bdef.y = 10.0;
        let mut id = CAROM_NULL_BODY;
        assert_eq!(
            carom_world_add_box(world, &bdef, 1.0, 1.0, &mut id),
            CAROM_OK
        );
        for _ in 0..10 {
            assert_eq!(carom_world_update(world, 0.1), CAROM_OK);
        }
        let (mut x, mut y) = (f64::NAN, f64::NAN);
        assert_eq!(carom_body_get_position(world, id, &mut x, &mut y), CAROM_OK);
        assert!(x.abs() < 1e-12 && (y - 5.0).abs() < 1e-9, "({}, {})", x, y);
        carom_world_destroy(world);
    }
}

#[test]
fn safe_world_free_fall_closed_form() {
    let (g, dt, n) = (9.81, 1.0 / 60.0, 120);
    let mut def = safe::world_def();
    def.gravity_y = -g;
    let mut world = World::with_def(&def).unwrap();
    let mut b = safe::body_def();
    b.x = 1.0;
    b.y = 100.0;
    b.vx = 2.0;
    b.vy = 5.0;
    let id = world.add_box(&b, 1.0, 2.0).unwrap();
    for _ in 0..n {
        world.step(dt).unwrap();
    }
    let t = n as f64 * dt;
    let (x, y) = world.position(id).unwrap();
    assert!((x - (1.0 + 2.0 * t)).abs() < 1e-9);
    assert!((y - (100.0 + 5.0 * t - 0.5 * g * t * t)).abs() < 1e-9);
    let (vx, vy) = world.velocity(id).unwrap();
    assert!((vx - 2.0).abs() < 1e-12 && (vy - (5.0 - g * t)).abs() < 1e-9);
    let (m, i, a) = world.mass(id).unwrap();
    assert!(
        (m - 2.0).abs() < 1e-12 && (i - 2.0 * 5.0 / 12.0).abs() < 1e-12 && (a - 2.0).abs() < 1e-12
    );
    assert_eq!(world.vertices(id).unwrap().len(), 4);
    assert_eq!(world.bodies(), vec![id]);
}

#[test]
fn bad_input_returns_the_right_status() {
    let mut world = World::new().unwrap();
    let def = safe::body_def();
    assert_eq!(
        world.add_circle(&def, f64::NAN).unwrap_err().status,
        CAROM_ERR_NOT_FINITE
    );
    assert_eq!(
        world.add_circle(&def, -1.0).unwrap_err().status,
        CAROM_ERR_BAD_SIZE
    );
    assert_eq!(
        world
            .add_polygon(&def, &[[0.0, 0.0], [1.0, 0.0]])
            .unwrap_err()
            .status,
        CAROM_ERR_TOO_FEW_VERTICES
    );
    assert_eq!(world.step(0.0).unwrap_err().status, CAROM_ERR_BAD_TIME_STEP);
    let mut dense = def;
    dense.density = 0.0;
    assert_eq!(
        world.add_box(&dense, 1.0, 1.0).unwrap_err().status,
        CAROM_ERR_BAD_DENSITY
    );
    assert_eq!(world.body_count(), 0);

    let err = world.step(f64::INFINITY).unwrap_err();
    assert_eq!(err.message, safe::status_string(CAROM_ERR_BAD_TIME_STEP));

    // a removed body's id is stale, not dangling
    let id = world.add_circle(&def, 1.0).unwrap();
    world.remove_body(id).unwrap();
    assert!(!world.is_alive(id));
    assert_eq!(world.position(id).unwrap_err().status, CAROM_ERR_STALE_BODY);

    // a wrong size field is refused (raw call: the safe layer always fixes it)
    let mut bad = def;
    bad.size = 8;
    let mut out = CAROM_NULL_BODY;
    let s = unsafe { carom_world_add_circle(world.as_ptr(), &bad, 1.0, &mut out) };
    assert_eq!(s, CAROM_ERR_BAD_STRUCT_SIZE);
}

#[test]
fn scenes_load_and_report_the_line() {
    let world =
        World::from_scene_text("gravity 0 -10\nbox 1 1 at 0 2\nbounds -5 0 5 10\n").unwrap();
    assert_eq!(world.gravity(), (0.0, -10.0));
    assert_eq!(world.body_count(), 5);

    let err = World::from_scene_text("gravity 0 -10\nbox 1 1 at 0 2\ncircle -1\n").unwrap_err();
    assert_eq!(err.line, Some(3));
    assert_eq!(err.status, CAROM_ERR_BAD_SIZE);
    assert!(err.message.starts_with("3:"), "{}", err.message);

    let err = World::from_scene_file(std::path::Path::new("/nonexistent/x.scene")).unwrap_err();
    assert_eq!(err.status, CAROM_ERR_IO);
}

#[test]
fn version_0_2_forces_queries_events_and_draw() {
    let mut def = safe::world_def();
    def.gravity_y = -10.0;
    let mut world = World::with_def(&def).unwrap();
    let mut g = safe::body_def();
    g.type_ = CAROM_STATIC;
    g.y = -0.5;
    let ground = world.add_box(&g, 10.0, 1.0).unwrap();
    let mut s = safe::body_def();
    s.type_ = CAROM_STATIC;
    s.sensor = 1;
    s.y = 1.5;
    let zone = world.add_box(&s, 4.0, 1.0).unwrap();
    let mut b = safe::body_def();
    b.y = 3.0;
    let ball = world.add_circle(&b, 0.25).unwrap();
    assert!(world.is_sensor(zone).unwrap() && !world.is_sensor(ball).unwrap());
    // an impulse at the centre: dv = J / m exactly
    let (m, _, _) = world.mass(ball).unwrap();
    world.apply_impulse(ball, (0.5, 0.0), (0.0, 3.0)).unwrap();
    assert!((world.velocity(ball).unwrap().0 - 0.5 / m).abs() < 1e-15);
    world.set_velocity(ball, 0.0, 0.0).unwrap();
    assert_eq!(
        world.apply_force(ground, (1.0, 0.0), (0.0, 0.0)).unwrap_err().status,
        CAROM_ERR_STATIC_BODY
    );
    let mut kinds = Vec::new();
    for _ in 0..120 {
        world.step(1.0 / 60.0).unwrap();
        kinds.extend(world.events().unwrap().iter().map(|e| e.type_));
    }
    assert_eq!(
        kinds,
        vec![CAROM_EVENT_SENSOR_BEGIN, CAROM_EVENT_SENSOR_END, CAROM_EVENT_CONTACT_BEGIN]
    );
    let hit = world.cast_ray((-6.0, -0.25), (5.0, -0.25), !0).unwrap().unwrap();
    assert_eq!(hit.body, ground);
    assert!((hit.point.0 + 5.0).abs() < 1e-12 && (hit.fraction - 1.0 / 11.0).abs() < 1e-12);
    assert!((hit.normal.0 + 1.0).abs() < 1e-12);
    let hit = world.cast_ray((0.0, 5.0), (0.0, -5.0), 1).unwrap().unwrap();
    assert_eq!(hit.body, zone); // sensors are hit too
    assert!((hit.point.1 - 2.0).abs() < 1e-12 && (hit.normal.1 - 1.0).abs() < 1e-12);
    assert_eq!(world.query_point((0.0, 0.25), !0).unwrap(), vec![ball]);
    assert_eq!(world.query_aabb((-1.0, -1.0), (1.0, 0.1), !0).unwrap(), vec![ground, ball]);
    assert_eq!(
        world.query_aabb((1.0, 0.0), (0.0, 1.0), !0).unwrap_err().status,
        CAROM_ERR_BAD_ARGUMENT
    );
    world.set_filter(ball, 2, 1, -3).unwrap();
    assert_eq!(world.filter(ball).unwrap(), (2, 1, -3));
    let (mut polys, mut circles) = (0, 0);
    world
        .draw(|_, pts| {
            assert_eq!(pts.len(), 4);
            polys += 1
        }, |_, _, r, _| {
            assert_eq!(r, 0.25);
            circles += 1
        })
        .unwrap();
    assert_eq!((polys, circles), (2, 1));
}

#[test]
fn compound_bodies_have_the_union_mass_and_their_shapes() {
    let mut def = safe::world_def();
    def.gravity_y = -9.81;
    def.friction = 0.5;
    let mut world = World::with_def(&def).unwrap();
    let (r, l) = (0.5f64, 2.0f64);
    let mut b = safe::body_def();
    b.x = 1.0;
    b.y = 3.0;
    let body = world
        .add_compound(
            &b,
            &[
                CompoundShape::circle(r, [-l, 0.0]).density(2.0),
                CompoundShape::circle(r, [l, 0.0]).friction(0.1),
                CompoundShape::rect(3.0, 0.4, [0.0, 0.0], 0.0).density(0.5),
            ],
        )
        .unwrap();
    let pi = std::f64::consts::PI;
    let (m1, m2, m3) = (2.0 * pi * r * r, pi * r * r, 0.5 * 3.0 * 0.4);
    let m = m1 + m2 + m3;
    let c = (m2 * l - m1 * l) / m;
    let inertia = m1 * r * r / 2.0 + m1 * (l + c) * (l + c) + m2 * r * r / 2.0 + m2 * (l - c) * (l - c)
        + m3 * (9.0 + 0.16) / 12.0 + m3 * c * c;
    let (gm, gi, _) = world.mass(body).unwrap();
    assert!((gm - m).abs() <= 1e-15 * m);
    assert!((gi - inertia).abs() <= 1e-14 * inertia);
    let shapes = world.shapes(body).unwrap();
    assert_eq!(shapes.len(), 3);
    assert_eq!(shapes[0].kind, CAROM_SHAPE_CIRCLE);
    assert!((shapes[0].center.0 - (1.0 - l - c)).abs() < 1e-14);
    assert_eq!((shapes[0].density, shapes[1].density), (2.0, 1.0));
    assert_eq!((shapes[0].friction, shapes[1].friction), (0.5, 0.1));
    assert_eq!(shapes[2].vertices.len(), 4);
    assert!(world.vertices(body).unwrap().is_empty());
    assert_eq!(
        world.add_compound(&b, &[CompoundShape::circle(-1.0, [0.0, 0.0])]).unwrap_err().status,
        CAROM_ERR_BAD_SIZE
    );
    assert_eq!(world.add_compound(&b, &[]).unwrap_err().status, CAROM_ERR_BAD_ARGUMENT);
    assert_eq!(
        world
            .add_compound(&b, &[CompoundShape::polygon(&[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]], [0.0, 0.0], 0.0)])
            .unwrap_err()
            .status,
        CAROM_ERR_SELF_INTERSECTING
    );
    let mut g = safe::body_def();
    g.type_ = CAROM_STATIC;
    g.y = -0.5;
    world.add_box(&g, 20.0, 1.0).unwrap();
    for _ in 0..240 {
        world.step(1.0 / 60.0).unwrap();
    }
    assert!((world.position(body).unwrap().1 - r).abs() < 0.01);
    assert_eq!(world.body_count(), 2);
}
