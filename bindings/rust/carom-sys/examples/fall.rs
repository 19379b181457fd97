//! A box dropped from 10 m, printed every 0.1 s until it reaches the floor.
//!     CAROM_LIB_DIR=$PWD/build LD_LIBRARY_PATH=$PWD/build \
//!         cargo run --example fall --manifest-path bindings/rust/carom-sys/Cargo.toml
use carom_sys::safe::{self, World};

fn main() -> Result<(), safe::Error> {
    let (major, minor, patch) = safe::version();
    println!("carom {}.{}.{}", major, minor, patch);

    let mut def = safe::world_def();
    def.gravity_y = -9.81;
    let mut world = World::with_def(&def)?;

    let mut floor = safe::body_def();
    floor.type_ = carom_sys::CAROM_STATIC;
    floor.y = -0.5;
    world.add_box(&floor, 20.0, 1.0)?;

    let mut crate_def = safe::body_def();
    crate_def.y = 10.0;
    crate_def.spin = 0.5;
    let body = world.add_box(&crate_def, 1.0, 1.0)?;

    let dt = 1.0 / 60.0;
    for frame in 0..=120 {
        if frame % 6 == 0 {
            let (x, y) = world.position(body)?;
            println!(
                "t={:4.2} x={:6.3} y={:6.3} angle={:6.3}",
                frame as f64 * dt,
                x,
                y,
                world.angle(body)?
            );
        }
        world.step(dt)?;
    }
    println!("contacts at rest: {}", world.contacts().len());
    Ok(())
}
