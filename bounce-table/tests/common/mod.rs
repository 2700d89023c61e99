//! Helpers shared by the integration tests: compiling generated C and Rust.

use std::path::Path;
use std::process::Command;

/// Compiles `source` (C99) to an object in `dir`, warning-free, or panics with the compiler's
/// message.
pub fn compile_c(source: &Path, dir: &Path) {
    let cc = Command::new("cc")
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Werror",
            "-pedantic",
            "-c",
            "-o",
        ])
        .arg(dir.join("out.o"))
        .arg(source)
        .output()
        .expect("run cc");
    assert!(
        cc.status.success(),
        "{}",
        String::from_utf8_lossy(&cc.stderr)
    );
}

/// Compiles `source` as a Rust library crate with `-D warnings` into `dir`, or panics with the
/// compiler's message.
pub fn compile_rust(source: &Path, dir: &Path) {
    let rustc = Command::new("rustc")
        .args([
            "--edition",
            "2021",
            "--crate-type",
            "lib",
            "-D",
            "warnings",
            "-o",
        ])
        .arg(dir.join("libout.rlib"))
        .arg(source)
        .output()
        .expect("run rustc");
    assert!(
        rustc.status.success(),
        "{}",
        String::from_utf8_lossy(&rustc.stderr)
    );
}
