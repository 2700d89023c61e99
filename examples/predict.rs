//! Predicts debounce windows for four switches of docs/physics.md sec. 7 at run time (f32; map,
//! averaged and Auto tiers) and one at compile time (the `const fn`), and prints them.
//!
//! Runs on the host (`cargo run --example predict`) and under QEMU for thumbv6m, thumbv7m and
//! thumbv7em (`cargo run --profile firmware --example predict --target thumbv7em-none-eabihf`): CI
//! checks that every run prints the host's lines.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[path = "common/predict_report.rs"]
mod report;

#[cfg(target_os = "none")]
mod firmware {
    use cortex_m as _;
    use cortex_m_semihosting::{debug, hio};
    use panic_halt as _;

    #[cortex_m_rt::entry]
    fn main() -> ! {
        let status = match hio::hstdout() {
            Ok(mut out) => super::report::run(&mut out).map_err(|_| ()),
            Err(()) => Err(()),
        };
        debug::exit(status.map_or(debug::EXIT_FAILURE, |()| debug::EXIT_SUCCESS));
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {
    let mut out = String::new();
    if report::run(&mut out).is_err() {
        std::process::exit(1);
    }
    print!("{out}");
}
