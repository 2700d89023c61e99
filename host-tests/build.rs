//! Compiles the C peer of the trade report (`benches/penalty_rk4.c`, a penalty-contact RK4).
fn main() {
    println!("cargo:rerun-if-changed=benches/penalty_rk4.c");
    cc::Build::new()
        .file("benches/penalty_rk4.c")
        .opt_level(3)
        .compile("penalty_rk4");
}
