//! Regimes of repeated collisions: docs/physics.md sec. 4 (verified by simulation).

/// How a bounce ends (docs/physics.md sec. 4).
///
/// | regime | when | impacts | end |
/// |---|---|---|---|
/// | [`ZenoAccumulation`](Regime::ZenoAccumulation) | preload, R < 1 | infinite | finite accumulation time |
/// | [`LastImpact`](Regime::LastImpact) | gap with viscous or hereditary damping | finite | time of the last impact |
/// | [`Endless`](Regime::Endless) | preload with R = 1 and damping; gap with R < 1 and no damping; Delta = 0 with zeta < 1 | infinite | never: J decays, only a threshold ends it |
/// | [`Periodic`](Regime::Periodic) | no loss at all (R = 1, no damping) | infinite | never, J constant |
/// | [`SingleImpact`](Regime::SingleImpact) | Delta >= 0, zeta >= 1 | 1 | at the first impact |
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Regime {
    /// Infinitely many impacts in a finite time, then the contact stays closed (quasi-plastic).
    ZenoAccumulation,
    /// Finitely many impacts; the last one ends the bounce.
    LastImpact,
    /// Infinitely many impacts that decay but never end: a bounce time needs a threshold.
    Endless,
    /// No dissipation: the contact bounces with constant impulse forever.
    Periodic,
    /// The contact separates once and never returns (overdamped, Delta >= 0).
    SingleImpact,
}

impl Regime {
    /// Its name in reports and files: `zeno_accumulation`, `last_impact`, `endless`,
    /// `periodic`, `single_impact` (also its `Display`).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::ZenoAccumulation => "zeno_accumulation",
            Self::LastImpact => "last_impact",
            Self::Endless => "endless",
            Self::Periodic => "periodic",
            Self::SingleImpact => "single_impact",
        }
    }

    /// True when the bounce never ends by itself ([`Endless`](Regime::Endless) or
    /// [`Periodic`](Regime::Periodic)).
    #[must_use]
    pub const fn is_endless(self) -> bool {
        matches!(self, Self::Endless | Self::Periodic)
    }

    /// The regime of a contact (docs/physics.md sec. 4).
    ///
    /// `delta_sign`: the sign of Delta (-1, 0, 1); `lossless_impacts`: R = 1;
    /// `zeta`: viscous ratio; `dissipates`: any loss between impacts.
    #[must_use]
    pub fn classify(
        delta_sign: i8,
        lossless_impacts: bool,
        zeta_at_least_one: bool,
        dissipates: bool,
    ) -> Self {
        if delta_sign >= 0 && zeta_at_least_one {
            return Self::SingleImpact;
        }
        match (delta_sign, lossless_impacts, dissipates) {
            (_, true, false) => Self::Periodic,
            (s, false, _) if s < 0 => Self::ZenoAccumulation,
            (s, true, true) if s < 0 => Self::Endless,
            (s, _, true) if s > 0 => Self::LastImpact,
            (s, false, false) if s > 0 => Self::Endless,
            // Delta = 0 with any loss: exact exponential decay.
            _ => Self::Endless,
        }
    }
}

impl core::fmt::Display for Regime {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}
