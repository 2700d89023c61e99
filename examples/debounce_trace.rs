//! Runs the debouncer on a recorded press of the signal relay (a bounce trace of the exact
//! reference, `examples/data/relay_press.rs`), with the physics window in both modes and a
//! guessed short hold-off, and prints the edges by sample; then the learning debouncer on the
//! same press, pressed and released 12 times (`common/learn_report.rs`).
//!
//! Runs on the host and under QEMU for thumbv6m, thumbv7m and thumbv7em: CI checks that every
//! run prints the host's lines.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[path = "common/trace_report.rs"]
mod report;

#[path = "common/learn_report.rs"]
mod learn;

#[cfg(target_os = "none")]
mod firmware {
    use cortex_m as _;
    use cortex_m_semihosting::{debug, hio};
    use panic_halt as _;

    #[cortex_m_rt::entry]
    fn main() -> ! {
        let status = match hio::hstdout() {
            Ok(mut out) => super::report::run(&mut out)
                .and_then(|()| {
                    super::learn::run(
                        &mut out,
                        &super::report::data::BITS,
                        super::report::data::SAMPLES,
                    )
                })
                .map_err(|_| ()),
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
    if report::run(&mut out)
        .and_then(|()| learn::run(&mut out, &report::data::BITS, report::data::SAMPLES))
        .is_err()
    {
        std::process::exit(1);
    }
    print!("{out}");
}
