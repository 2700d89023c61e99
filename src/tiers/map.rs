//! The semi-discrete map: docs/physics.md sec. 6.
//!
//! Per impact: exact restitution (v -> R v), the conservative flight time T(2a) of a flight
//! leaving at a, and the first-order loss of the other mechanisms over that flight
//! (Delta J = E1_damping(J) T(J)); no root finding. Exact for zeta = 0; preload within 0.3 %
//! for zeta <= 0.01 and 2.5 % for zeta <= 0.1; gap end within ~2 % for zeta <= 1e-3, -12 % at
//! zeta = 0.01, unreliable for a gap with zeta >= 0.1 (it cannot decide the last return).
//! Where the first-order loss over a flight exceeds the flight's impulse (heavy viscous
//! damping, large impulses), first order cannot say whether the body returns: the prediction
//! solves that flight exactly (as [`Method::Exact`](crate::Method::Exact) does) and goes on
//! from its return; a scene type without viscous damping links none of this.
//!
//! Iterations are bounded: a preload's Zeno tail is summed on the small-impulse asymptote once
//! J < 5e-3 Omega |Delta| where the scene dissipates between impacts (a few 1e-4 of the tail
//! left out, a tenth of the map's smallest figure), and once J <
//! [`Tuning::TAIL_CUTOFF`](crate::numeric::Tuning::TAIL_CUTOFF) Omega |Delta| (exact to
//! rounding) with restitution alone; past
//! `max_impacts` the averaged model finishes
//! the sum (flagged [`Approximations::MAP_CONTINUED_AVERAGED`]). [`MapImpacts`] yields the
//! impacts themselves.

use crate::numeric::quadrature::{Compensated, Nodes};
use crate::physics::duration::{Count, Time};
use crate::physics::flight::{Landing, Oscillator};
use crate::physics::mechanisms::restitution::rebound;
use crate::physics::mechanisms::{Asymptote, Dissipation};
use crate::physics::regime::Regime;
use crate::scene::{AnySign, OffsetSign};
use crate::tiers::accuracy;
use crate::tiers::approximations::Approximations;
use crate::tiers::averaged::Averaged;
use crate::tiers::prediction::{Course, Prediction, Tier};
use crate::{Float, Scene};

/// The map's default cap on iterated impacts.
pub const DEFAULT_MAX_IMPACTS: u32 = 100_000;

/// One impact of the map: its index (impact 0 at t = 0), time (s) and impulse per unit
/// reduced mass P = (1 + R) v (m/s).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Impact<F> {
    /// 0 for the first impact.
    pub index: u32,
    /// Time after impact 0 (s).
    pub time: F,
    /// P = (1 + R) v (m/s).
    pub impulse: F,
}

/// Why the map's impacts stopped.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum MapEnd<F> {
    /// The flight after the last impact does not return: the bounce ended at it.
    NoReturn,
    /// A preload's flight loses all its impulse to damping (first order): the contact closes
    /// after this flight time (s).
    Closes(F),
    /// A preload's departure fell below where its tail is summed (5e-3 Omega |Delta| where the
    /// scene dissipates, else [`Tuning::TAIL_CUTOFF`](crate::numeric::Tuning::TAIL_CUTOFF)
    /// Omega |Delta|; see the module docs) (and below the
    /// threshold, if any: the impacts above it are all iterated, so they are counted one by
    /// one): the rest is a Zeno tail, from this generating impulse (m/s).
    ZenoTail(F),
    /// The cap on impacts was reached, with this generating impulse left (m/s).
    Capped(F),
}

/// The map's impacts, one by one, allocation-free: impact 0, then each return until the map
/// stops ([`MapImpacts::end`] says why). Also a bounce trace generator for firmware tests.
///
/// The walk is first order only: where a flight's first-order loss exceeds its impulse it
/// ends (`NoReturn` in a gap, `Closes` in a preload), where the map's prediction solves that
/// flight exactly and goes on.
///
/// ```
/// use contact_bounce::{scene::catalogue, tiers::MapImpacts};
/// let dome = catalogue::TACTILE_DOME.scene::<f32>()?;
/// let first: Vec<_> = MapImpacts::new(&dome, 100).take(3).collect();
/// assert_eq!(first[0].time, 0.0);
/// assert!(first[1].time > 0.0 && first[1].impulse < first[0].impulse);
/// # Ok::<(), contact_bounce::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct MapImpacts<'a, F, D, S = AnySign> {
    scene: &'a Scene<F, D, S>,
    speed: F,
    time: Compensated<F>,
    index: u32,
    started: bool,
    max_impacts: u32,
    end: Option<MapEnd<F>>,
    /// The departure speed (m/s) whose first-order loss exceeded its flight's impulse.
    stalled: Option<F>,
}

impl<'a, F: Float, D: Dissipation<F>, S: OffsetSign> MapImpacts<'a, F, D, S> {
    /// The impacts of `scene`, at most `max_impacts` + 1 of them.
    #[must_use]
    pub fn new(scene: &'a Scene<F, D, S>, max_impacts: u32) -> Self {
        Self {
            scene,
            speed: scene.closing_speed(),
            time: Compensated::new(),
            index: 0,
            started: false,
            max_impacts,
            end: None,
            stalled: None,
        }
    }

    /// The walk from an impact other than impact 0: `index` at `time` (s), arriving at
    /// `speed` (m/s); the next item is the impact after it.
    fn resume(scene: &'a Scene<F, D, S>, index: u32, time: F, speed: F, max_impacts: u32) -> Self {
        let mut sum = Compensated::new();
        sum.add(time);
        Self {
            scene,
            speed,
            time: sum,
            index,
            started: true,
            max_impacts,
            end: None,
            stalled: None,
        }
    }

    /// Why the impacts stopped, once they have (`None` while they go on).
    #[must_use]
    pub const fn end(&self) -> Option<MapEnd<F>> {
        self.end
    }

    /// Once the impacts stopped in a Zeno tail: the tail's duration (s), summed in closed form
    /// on the small-impulse asymptote, as the map's prediction does. The accumulation time is
    /// the last impact's time plus this. Small: no averaged model is linked.
    #[must_use]
    pub fn zeno_tail_time(&self) -> Option<F> {
        match self.end {
            Some(MapEnd::ZenoTail(j)) => self.scene.asymptote().fall_time(j, F::ZERO).seconds(),
            _ => None,
        }
    }
}

impl<F: Float, D: Dissipation<F>, S: OffsetSign> Iterator for MapImpacts<'_, F, D, S> {
    type Item = Impact<F>;

    fn next(&mut self) -> Option<Impact<F>> {
        let scene = self.scene;
        let restitution = scene.restitution();
        if !self.started {
            self.started = true;
            return Some(Impact {
                index: 0,
                time: F::ZERO,
                impulse: scene.first_impulse(),
            });
        }
        if self.end.is_some() {
            return None;
        }
        let departure = rebound(self.speed, restitution, scene.loss());
        let j = F::TWO * departure;
        let preload = scene.is_preload();
        let stop = if scene.regime() == Regime::SingleImpact {
            Some(MapEnd::NoReturn)
        } else if preload
            && j <= Asymptote::<F>::tail_cutoff(scene.dissipation().dissipates())
                * scene.omega()
                * scene.delta().abs()
            && scene.threshold_generating().is_none_or(|end| j < end)
        {
            Some(MapEnd::ZenoTail(j))
        } else if j < F::MIN_POSITIVE {
            // The impulse has shrunk below the float's normal range (many impacts of a small
            // R, a grazing or gap contact): no flight the float can describe follows.
            Some(MapEnd::NoReturn)
        } else if self.index >= self.max_impacts {
            Some(MapEnd::Capped(j))
        } else {
            None
        };
        if stop.is_some() {
            self.end = stop;
            return None;
        }
        let point = scene.orbit().at(j);
        let period = point.period();
        let returning = j + scene.dissipation().rate(&point) * period;
        // (NaN cannot arise here: j is a normal positive number above.)
        if returning <= F::ZERO {
            // The first-order loss exceeds the flight's impulse (heavy damping): in a gap the
            // last impact was the last; a preload always returns, with a vanishing impulse.
            // (First order cannot decide either: the map's prediction solves this flight.)
            self.stalled = Some(departure);
            self.end = Some(if preload {
                MapEnd::Closes(period)
            } else {
                MapEnd::NoReturn
            });
            return None;
        }
        self.time.add(period);
        self.speed = returning * F::HALF;
        self.index = self.index.saturating_add(1);
        Some(Impact {
            index: self.index,
            time: self.time.value(),
            impulse: (F::ONE + restitution) * self.speed,
        })
    }
}

/// Where the prediction's iteration stopped and what remains to be summed.
enum Stop<F> {
    /// The bounce ended at this time, after this many impacts.
    Ended(F, F),
    /// Below the threshold in an endless regime: nothing more to sum.
    BelowThreshold,
    /// Hand the rest over, from generating impulse `j` at time `t` after `n` impacts.
    Rest { j: F, t: F, n: F, averaged: bool },
}

/// The impacts counted so far, and those above the threshold.
struct Tally<F> {
    threshold: Option<F>,
    last_above: F,
    above: F,
    still_above: bool,
    below_in_endless: bool,
    latest: Impact<F>,
}

impl<F: Float> Tally<F> {
    /// Counts `impact`; true when counting stops (below the threshold in an endless regime).
    fn record(&mut self, impact: Impact<F>, endless: bool) -> bool {
        self.latest = impact;
        if !self.still_above {
            return false;
        }
        if self.threshold.is_some_and(|p_end| impact.impulse < p_end) {
            self.still_above = false;
            self.below_in_endless = endless;
            endless
        } else {
            self.last_above = impact.time;
            self.above = F::from_u32(impact.index) + F::ONE;
            false
        }
    }
}

/// The map's prediction, iterating at most `max_impacts` impacts. `FULL`: every field (false:
/// the times alone, see [`Scene::bounce_time`]; the counts of an asymptotic tail are then
/// `Infinite` and the expected error `None`, placeholders no caller reads).
#[allow(clippy::too_many_lines)] // one loop and its hand-over; splitting it would hide the state
pub(crate) fn predict<F: Float, D: Dissipation<F>, S: OffsetSign, const FULL: bool>(
    scene: &Scene<F, D, S>,
    max_impacts: u32,
) -> Prediction<F> {
    if let Some(p) = crate::tiers::settled::answer(scene) {
        return p;
    }
    let orbit = scene.orbit();
    let threshold = scene.threshold_impulse();
    let endless = scene.regime() == Regime::Endless;
    let mut tally = Tally {
        threshold,
        last_above: F::ZERO,
        above: F::ONE,
        still_above: true,
        below_in_endless: false,
        latest: Impact {
            index: 0,
            time: F::ZERO,
            impulse: scene.first_impulse(),
        },
    };
    let mut impacts = MapImpacts::new(scene, max_impacts);
    let _ = impacts.next(); // impact 0: `tally.latest`
                            // Where the first-order loss over a flight exceeds its impulse (heavy viscous damping),
                            // first order cannot say whether, or when, the body returns: that flight is solved
                            // exactly, and the map goes on from its return. (Not with a kernel: the exact flight
                            // knows no memory. A scene type without damping links none of this.)
    let dissipation = scene.dissipation();
    let solvable = dissipation.dissipates() && !dissipation.has_kernel();
    let mut capped_stall = None;
    loop {
        for impact in impacts.by_ref() {
            if tally.record(impact, endless) {
                break;
            }
        }
        let Some(departure) = impacts
            .stalled
            .filter(|_| solvable && !tally.below_in_endless)
        else {
            break;
        };
        if tally.latest.index >= max_impacts {
            capped_stall = Some(F::TWO * departure);
            break;
        }
        let flight =
            Oscillator::<F, S>::signed(scene.omega(), dissipation.damping_ratio(), scene.delta());
        let Landing::Returns { time, speed, .. } = flight.land(departure) else {
            break; // the last impact was the last (`impacts.end()` says so)
        };
        let impact = Impact {
            index: tally.latest.index.saturating_add(1),
            time: tally.latest.time + time,
            impulse: (F::ONE + scene.restitution()) * speed,
        };
        if tally.record(impact, endless) {
            break;
        }
        impacts = MapImpacts::resume(scene, impact.index, impact.time, speed, max_impacts);
    }
    let Tally {
        last_above,
        above,
        still_above,
        below_in_endless,
        latest,
        ..
    } = tally;
    let count = F::from_u32(latest.index) + F::ONE;
    let solved_stall = solvable && impacts.stalled.is_some();
    let stop = match (capped_stall, impacts.end()) {
        // An endless regime never ends: where the first-order loss says it does, the next
        // impact is below any threshold.
        _ if below_in_endless => Stop::BelowThreshold,
        (Some(j), _) => Stop::Rest {
            j,
            t: latest.time,
            n: count,
            averaged: true,
        },
        // A kernel's flight whose first-order loss exceeds its impulse: no exact flight solves
        // it (the kernel's memory), and ending there said 0 s for a bounce that goes on (0.18 s
        // at Delta = 0, zeta 0.42, a static share of 0.16): the averaged model finishes from
        // that impulse.
        (_, Some(MapEnd::NoReturn | MapEnd::Closes(_)))
            if dissipation.has_kernel() && impacts.stalled.is_some() =>
        {
            Stop::Rest {
                j: impacts
                    .stalled
                    .map_or(F::ZERO, |departure| F::TWO * departure),
                t: latest.time,
                n: count,
                averaged: true,
            }
        }
        (_, Some(MapEnd::NoReturn | MapEnd::Closes(_))) if endless => Stop::BelowThreshold,
        // The exact flight did not return: the bounce ended at the last impact.
        _ if solved_stall => Stop::Ended(latest.time, count),
        (_, Some(MapEnd::NoReturn) | None) => Stop::Ended(latest.time, count),
        (_, Some(MapEnd::Closes(flight))) => Stop::Ended(latest.time + flight, count),
        (_, Some(MapEnd::ZenoTail(j))) => Stop::Rest {
            j,
            t: latest.time,
            n: count,
            averaged: false,
        },
        (_, Some(MapEnd::Capped(j))) => Stop::Rest {
            j,
            t: latest.time,
            n: count,
            averaged: true,
        },
    };

    let mut approximations = Approximations::NONE;
    let mut rest_above = None;
    let (end_time, impacts_total) = match stop {
        Stop::Ended(t, n) => (Time::At(t), Count::Finite(n)),
        Stop::BelowThreshold => (Time::Never, Count::Infinite),
        Stop::Rest { j, t, n, averaged } => {
            if averaged {
                approximations = approximations.with(Approximations::MAP_CONTINUED_AVERAGED);
            }
            // The rest: by the averaged model past the cap, on the asymptote in a Zeno tail.
            let averaged_model = Averaged::new(scene, Nodes::N8);
            let rest = |low: F| {
                if averaged {
                    let (dt, dn, _) = averaged_model.fall(j, low);
                    (dt, dn)
                } else {
                    let a = scene.asymptote();
                    let time = a.fall_time(j, low);
                    if FULL {
                        (time, a.fall_count::<S>(orbit, j, low))
                    } else {
                        (time, Count::Infinite)
                    }
                }
            };
            // The rest of the threshold count, if the threshold was not crossed yet: every
            // outcome taken (one left out kept the last impact solved as the last above).
            if still_above {
                if let Some(j_end) = scene.threshold_generating() {
                    let (dt, dn) = rest(j_end);
                    rest_above = Some((dt.reached_after(t), dn.reached_after(n)));
                }
            }
            if endless {
                (Time::Never, Count::Infinite)
            } else {
                let (dt, dn) = rest(F::ZERO);
                (dt.after(t), dn.after(n))
            }
        }
    };
    let (last_above_time, impacts_above) = if threshold.is_some() {
        rest_above.unwrap_or((Time::At(last_above), Count::Finite(above)))
    } else {
        (end_time, impacts_total)
    };
    let mut expected = if FULL {
        accuracy::with_reduction(scene, accuracy::map(scene, impacts_total.value()))
    } else {
        None
    };
    if FULL && approximations.contains(Approximations::MAP_CONTINUED_AVERAGED) {
        let averaged = accuracy::averaged(scene, impacts_total.value());
        expected = match (expected, averaged) {
            (Some(a), Some(b)) => Some(a.max(b)),
            _ => None,
        };
    }
    // The walk's rounding, as the exact tier's: each departure rounds from the one before and
    // each flight is added to the clock, so errors compound at worst linearly over the impacts
    // walked. Left out, f32 walks of 10,000 undamped impacts at R within 1e-6 of 1 were
    // 3.2e-4 to 5.0e-4 off where the map stated 1e-4 (the fuzzing harness's promises; the f32
    // exact tier's sums, and f64, agree to 1e-7).
    let expected = expected.map(|e| {
        e + crate::numeric::c::<F>(crate::tiers::exact::ROUNDING_PER_FLIGHT) * F::EPSILON * count
    });
    Prediction::of_tier(
        scene,
        Course {
            end_time,
            last_above_time,
            impacts_above,
            impacts_total,
        },
        Tier::Map,
        approximations,
        expected,
    )
}
