//! Firmware examples link with cortex-m-rt's `link.x` (and `memory.x` from the crate root),
//! only for bare-metal ARM targets: host builds of the examples are plain programs.

use std::{env, fs, path::PathBuf};

fn main() {
    let target = env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumb") {
        let out = PathBuf::from(env::var_os("OUT_DIR").unwrap_or_default());
        // The search path goes to this package's examples only: `rustc-link-search` would
        // also reach every firmware that depends on the crate and hand it our QEMU memory
        // layout in place of its own.
        if fs::copy("memory.x", out.join("memory.x")).is_ok() {
            println!("cargo:rustc-link-arg-examples=-L{}", out.display());
        }
        println!("cargo:rustc-link-arg-examples=-Tlink.x");
        if env::var_os("CARGO_FEATURE_DEFMT").is_some() {
            println!("cargo:rustc-link-arg-examples=-Tdefmt.x");
        }
    }
    println!("cargo:rerun-if-changed=memory.x");
    println!("cargo:rerun-if-changed=build.rs");
}
