//! What the exact tier walks: the flights of one model, solved one after another.

use crate::physics::flight::Landing;
use crate::Float;

/// Flights solved one after another from the stop: the free motion of one model (viscous
/// damping; or a relaxation kernel, whose state is carried from flight to flight).
pub(crate) trait Flights<F: Float> {
    /// The flight that leaves the stop at `departure` (m/s, > 0). On a return the model's
    /// state moves to that impact.
    fn land(&mut self, departure: F) -> Landing<F>;
    /// The rest of a Zeno accumulation whose next flight leaves at `departure`, `elapsed`
    /// (s) after the first impact, summed in closed form, with a bound on its error (s):
    /// `None` until that form is exact to the rounding of the whole bounce.
    fn tail(&mut self, departure: F, elapsed: F) -> Option<(F, F)>;
    /// The last return's rounding where its conditioning makes it more than a few epsilons of
    /// the flight: (an error of its time (s), a relative error of its speed, which every later
    /// flight inherits), each an epsilon times the sizes of the terms the return is the
    /// difference of, over the return speed. (0, 0) where the flight's own form keeps its
    /// digits (viscous flights: their terms decay with the motion). Before the first flight,
    /// (0, the relative error of the first flight's fall from the model's starting state).
    fn rounding(&self) -> (F, F) {
        (F::ZERO, F::ZERO)
    }
    /// Whether [`Flights::rounding`] can be other than (0, 0) (a constant: where it is not,
    /// the exact tier links none of its bookkeeping).
    const ROUNDED: bool = false;
}
