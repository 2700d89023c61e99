// The tactile dome's debounce window at compile time, shared by the `predict` and `uno`
// reports: t_b1 (the `const fn` closed form) widened by its worst atan error (8 % at j0 <= 1;
// x/atan(x) - 1 with x = j0/2 = 0.175: 1 %) and by 50 %, in 10 us ticks.

use contact_bounce::debounce::window::{preload_bounce_time, window_ticks};

/// The window, in 10 us ticks.
pub const DOME_TICKS: u32 = match preload_bounce_time(5e-5, 5000.0, 1.0, 0.5, 0.7) {
    Ok(t) => match window_ticks(t.seconds, 1.5, 10e-6) {
        Ok(ticks) => ticks,
        Err(_) => panic!("window does not fit"),
    },
    Err(_) => panic!("bad switch parameters"),
};
