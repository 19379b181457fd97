//! Builds or finds the carom C library.
//!
//! 1. CAROM_LIB_DIR: link the library in that directory (a build tree such
//!    as the repository's build/, or an install's lib/); CAROM_STATIC=1
//!    links libcarom.a there instead of libcarom.so;
//! 2. the `system` feature: an installed libcarom through pkg-config
//!    (`carom.pc`, the header's version);
//! 3. the `bundled` feature (the default): compile the C sources (csrc/ in a
//!    packaged crate, else the repository's lib/ and include/) with the cc
//!    crate, with the Makefile's flags, and link them statically.

use std::env;
use std::path::{Path, PathBuf};

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
    if cfg!(feature = "system") {
        system(statik);
    } else {
        bundled();
    }
}

/// The C sources: csrc/ beside this file (a packaged crate), else the
/// repository around it.
fn c_root() -> PathBuf {
    let here = PathBuf::from(env::var_os("CARGO_MANIFEST_DIR").expect("CARGO_MANIFEST_DIR"));
    let candidates = [here.join("csrc"), here.join("..").join("..").join("..")];
    for root in candidates.iter() {
        if root.join("include").join("carom.h").is_file() && root.join("lib").is_dir() {
            return root.clone();
        }
    }
    panic!(
        "carom-sys: the C sources (lib/*.c, include/carom.h) are neither in {} nor in \
         the repository around it; use the `system` feature to link an installed libcarom",
        here.join("csrc").display()
    );
}

/// The header's version, "MAJOR.MINOR.PATCH".
fn header_version(root: &Path) -> String {
    let text = std::fs::read_to_string(root.join("include").join("carom.h")).expect("read carom.h");
    let part = |name: &str| -> String {
        let key = format!("#define CAROM_VERSION_{} ", name);
        let line = text.lines().find(|l| l.starts_with(&key)).expect("a CAROM_VERSION_ macro");
        line[key.len()..].trim().to_string()
    };
    format!("{}.{}.{}", part("MAJOR"), part("MINOR"), part("PATCH"))
}

#[cfg(feature = "bundled")]
fn bundled() {
    let root = c_root();
    let version = header_version(&root);
    let crate_version = env::var("CARGO_PKG_VERSION").unwrap();
    if version != crate_version {
        panic!("carom-sys: include/carom.h is version {}, this crate {}", version, crate_version);
    }
    let mut build = cc::Build::new();
    let mut sources: Vec<PathBuf> = std::fs::read_dir(root.join("lib"))
        .expect("read lib/")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().map_or(false, |x| x == "c"))
        .collect();
    sources.sort();
    for s in &sources {
        println!("cargo:rerun-if-changed={}", s.display());
    }
    println!("cargo:rerun-if-changed={}", root.join("lib").display());
    println!("cargo:rerun-if-changed={}", root.join("include").join("carom.h").display());
    build
        .files(&sources)
        .include(root.join("include"))
        .include(root.join("lib"))
        .opt_level(3)
        .warnings(false)
        // the Makefile's: C99, no fused multiply-add (the same bits), only
        // the carom_* API visible
        .flag_if_supported("-std=c99")
        .flag_if_supported("-ffp-contract=off")
        .flag_if_supported("-fvisibility=hidden")
        .compile("carom");
    println!("cargo:rustc-link-lib=m");
    println!("cargo:root={}", env::var("OUT_DIR").unwrap());
}

#[cfg(not(feature = "bundled"))]
fn bundled() {
    panic!(
        "carom-sys: neither the `bundled` feature (the default: the C library built in) nor \
         `system` (an installed one, through pkg-config) is on, and CAROM_LIB_DIR is not set"
    );
}

#[cfg(feature = "system")]
fn system(statik: bool) {
    let version = env::var("CARGO_PKG_VERSION").unwrap();
    if let Err(err) = pkg_config::Config::new()
        .exactly_version(&version)
        .statik(statik)
        .probe("carom")
    {
        panic!(
            "carom-sys (feature `system`): cannot find the carom C library {} through pkg-config.\n  \
             Install carom (make install) so that pkg-config finds carom.pc (PKG_CONFIG_PATH),\n  \
             or build it in: the default `bundled` feature.\n  pkg-config said: {}",
            version, err
        );
    }
}

#[cfg(not(feature = "system"))]
fn system(_statik: bool) {
    unreachable!()
}
