//! How to predict: the tiers of [`Scene::predict`](crate::Scene::predict) and what they return.
//!
//! | [`Method`] | what it evaluates | cost (host, f64) |
//! |---|---|---|
//! | `Closed` | the closed forms t_b1, t_b1v, t_b2 (and their corrected forms) | tens of ns |
//! | `Averaged(nodes)` | the averaged equation J' = E1(J), integrated by Gauss-Legendre | a few us |
//! | `Map { max_impacts }` | the averaged model impact by impact | under 1 us |
//! | `Exact { max_impacts }` | the exact solution, flight by flight | about 1 us |
//! | `Auto(tolerance)` | the cheapest of them whose expected error meets the tolerance | as the tier chosen |
//!
//! Each gives a [`Prediction`]: the regime, the end of the bounce or the last impact above a
//! threshold, impact counts, the first impacts, the [`Tier`] that answered and its expected
//! error. `docs/physics.md` sec. 6 and `docs/reports/trade-report.md` in the repository give each
//! tier's measured accuracy and cost.

pub(crate) mod accuracy;
pub(crate) mod approximations;
pub(crate) mod averaged;
pub(crate) mod closed;
pub(crate) mod exact;
pub(crate) mod map;
pub(crate) mod method;
pub(crate) mod prediction;
pub(crate) mod settled;
pub(crate) mod walk;

pub use crate::numeric::Nodes;
pub use crate::physics::duration::{Count, Time};
pub use crate::physics::flight::ROOT_STEPS;
pub use approximations::Approximations;
pub use averaged::{preload_restitution_bounce_seconds, Averaged, Bodies, EnvelopePoint, Motion};
pub use closed::{preload_viscous_bounce_seconds, preload_viscous_bounce_time, Estimate};
pub use exact::{EXACT_MAX_IMPACTS, KERNEL_FLIGHT_STEPS};
pub use map::{Impact, MapEnd, MapImpacts, DEFAULT_MAX_IMPACTS};
pub use method::{AutoTiers, Method, Tolerance};
pub use prediction::{ClosedForm, Prediction, Tier};
