//! Flash cost of one tier (exact) in a firmware: the tactile dome of docs/physics.md sec. 7
//! (viscous, f32). Built by `scripts/size-report.sh` and `scripts/cost-report.sh` for
//! thumbv6m and thumbv7em; on the host it is an empty program.
#![cfg_attr(target_os = "none", no_std, no_main)]

#[cfg(target_os = "none")]
#[path = "common/size_tier.rs"]
mod body;

#[cfg(target_os = "none")]
mod firmware {
    use contact_bounce::{tiers::EXACT_MAX_IMPACTS, Method};
    use core::hint::black_box;
    use cortex_m as _;
    use panic_halt as _;

    #[cortex_m_rt::entry]
    fn main() -> ! {
        black_box(super::body::run(Method::Exact {
            max_impacts: EXACT_MAX_IMPACTS,
        }));
        loop {
            cortex_m::asm::wfi();
        }
    }
}

#[cfg(not(target_os = "none"))]
fn main() {}
