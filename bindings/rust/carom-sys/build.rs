//! Links the carom C library.
//!
//! 1. CAROM_LIB_DIR: the directory holding libcarom.so (a build tree such as
//!    the repository's build/, or an install's lib/);
//! 2. otherwise pkg-config (`carom.pc`, version 0.x; the `pkg-config` feature).
//!
//! CAROM_STATIC=1 links libcarom.a instead of the shared library.

use std::env;
use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-env-changed=CAROM_LIB_DIR");
    println!("cargo:rerun-if-env-changed=CAROM_STATIC");
    let statik = env::var_os("CAROM_STATIC").map_or(false, |v| !v.is_empty() && v != "0");

    if let Some(dir) = env::var_os("CAROM_LIB_DIR") {
        let dir = PathBuf::from(dir);
        let file = if statik { "libcarom.a" } else { "libcarom.so" };
        if !dir.join(file).exists() {
            panic!(
                "carom-sys: CAROM_LIB_DIR={} has no {}; build the C library first \
                 (make, from the repository root) or point CAROM_LIB_DIR at its directory",
                dir.display(),
                file
            );
        }
        println!("cargo:rustc-link-search=native={}", dir.display());
        if statik {
            println!("cargo:rustc-link-lib=static=carom");
            println!("cargo:rustc-link-lib=m");
        } else {
            println!("cargo:rustc-link-lib=dylib=carom");
        }
        println!("cargo:root={}", dir.display());
        return;
    }
    probe(statik);
}

#[cfg(feature = "pkg-config")]
fn probe(statik: bool) {
    if let Err(err) = pkg_config::Config::new()
        .range_version("0.2.0".."1.0.0")
        .statik(statik)
        .probe("carom")
    {
        panic!(
            "carom-sys: cannot find the carom C library.\n  \
             Set CAROM_LIB_DIR to the directory that holds libcarom.so (e.g. the \
             repository's build/),\n  or install carom (make install) so that \
             pkg-config finds carom.pc (PKG_CONFIG_PATH).\n  pkg-config said: {}",
            err
        );
    }
}

#[cfg(not(feature = "pkg-config"))]
fn probe(_statik: bool) {
    panic!(
        "carom-sys: set CAROM_LIB_DIR to the directory that holds libcarom.so \
         (the `pkg-config` feature, which would search for carom.pc, is off)"
    );
}
