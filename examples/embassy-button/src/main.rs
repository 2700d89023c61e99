//! A push button on P0.11 (to ground, the pin pulled up), debounced by the learning debouncer
//! in an embassy task: `next_edge().await` sleeps on the pin's GPIOTE interrupt until the
//! button moves, samples it once a millisecond while the change and its bounce last, and
//! returns each press and release. The learner starts from a hand-operated button's prior
//! (31 ms windows at 1 ms samples: the fastest real tap) and tightens to the button's bounce.
#![no_std]
#![no_main]

use contact_bounce::debounce::Polarity;
use contact_bounce::debounce::wait::{AsyncDebouncer, Learning};
use contact_bounce::{Edge, LearnerPrior};
use core::num::NonZeroU32;
use embassy_executor::Spawner;
use embassy_nrf::gpio::{Input, Pull};
use embassy_time::Delay;
use panic_halt as _;

#[embassy_executor::main]
async fn main(_spawner: Spawner) {
    let p = embassy_nrf::init(Default::default());
    let pin = Input::new(p.P0_11, Pull::Up);
    let (Ok(prior), Some(period)) = (
        LearnerPrior::at_period(31, 31, 1_000_000),
        NonZeroU32::new(1_000_000),
    ) else {
        return;
    };
    // Reading an embassy pin cannot fail (its error type is Infallible).
    let Ok(mut button) = AsyncDebouncer::new(
        pin,
        Delay,
        Learning::new(prior),
        Polarity::ActiveLow,
        period,
    );
    let mut presses: u32 = 0;
    loop {
        let Ok(edge) = button.next_edge().await;
        if edge == Edge::Press {
            presses = presses.wrapping_add(1);
            // Show `presses` on a display, send it over BLE...: kept here for a debugger.
            core::hint::black_box(presses);
        }
    }
}
