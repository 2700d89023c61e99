//! Priors: the window for a switch without a capture, from what is known of its type.
//!
//! A prior is a distribution of the bounce over the switches of a type, with its evidence
//! stated, and its window is a high percentile of that distribution. For hand-operated
//! switches (push buttons, rockers, toggles, slides, tactile buttons) the evidence is one
//! published survey of 18 such switches (J. Ganssle, "A Guide to Debouncing", 2004/2008): a mean
//! bounce of about 1.6 ms, a maximum of 6.2 ms for 17 of them, and one outlier at 157 ms.
//! That survey is modelled as a mixture: 17 of 18 switches log-normal with median 0.94 ms and
//! log-spread 1.0 (which gives the survey's mean, 1.56 ms, and puts its largest typical switch,
//! 6.2 ms, at the 97th percentile), and 1 of 18 at the outlier's 157 ms. Its P99.9 is in the
//! outlier's part: a window that must hold on a switch nobody has measured has to cover the
//! worst switch of its type that was ever measured, because nothing tells the two apart.

use statrs::distribution::{ContinuousCDF, Normal};

/// What is known of the bounce of a type of switch.
#[derive(Debug, Clone, PartialEq)]
pub struct Prior {
    /// The type's name, as `--switch-type` takes it.
    pub name: &'static str,
    /// Median bounce of the typical switches (s).
    pub median: f64,
    /// Spread of ln bounce over the typical switches.
    pub sigma: f64,
    /// Share of outliers.
    pub outlier_share: f64,
    /// Bounce of the outliers (s).
    pub outlier: f64,
    /// Where the figures come from.
    pub evidence: &'static str,
}

const SURVEY: &str = "a published survey of 18 hand-operated switches (J. Ganssle, A Guide to Debouncing): mean 1.6 ms, 17 within 6.2 ms, one at 157 ms";

/// The hand-operated switches' prior (the survey's mixture).
pub const HAND_OPERATED: Prior = Prior {
    name: "hand-operated",
    median: 0.94e-3,
    sigma: 1.0,
    outlier_share: 1.0 / 18.0,
    outlier: 157e-3,
    evidence: SURVEY,
};

/// The types `--switch-type` knows, each with its prior. Every hand-operated type shares the
/// survey's prior: it does not tell them apart.
pub const TYPES: [(&str, &Prior); 6] = [
    ("push-button", &HAND_OPERATED),
    ("rocker", &HAND_OPERATED),
    ("toggle", &HAND_OPERATED),
    ("slide", &HAND_OPERATED),
    ("tactile", &HAND_OPERATED),
    ("hand-operated", &HAND_OPERATED),
];

/// The prior of a type named by `--switch-type` (case-insensitive).
#[must_use]
pub fn by_name(name: &str) -> Option<&'static Prior> {
    TYPES
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|(_, p)| *p)
}

/// The type a capture's switch name gives, if it names one of [`TYPES`] (as
/// `...-rocker` does).
#[must_use]
pub fn from_switch_name(switch: &str) -> Option<&'static Prior> {
    let lower = switch.to_ascii_lowercase();
    TYPES
        .iter()
        .find(|(n, _)| lower.contains(n))
        .map(|(_, p)| *p)
}

impl Prior {
    /// P(bounce <= t) over switches of the type.
    #[must_use]
    pub fn cdf(&self, t: f64) -> f64 {
        if t <= 0.0 {
            return 0.0;
        }
        let typical = Normal::standard().cdf((t / self.median).ln() / self.sigma);
        let outlier = if t >= self.outlier { 1.0 } else { 0.0 };
        (1.0 - self.outlier_share) * typical + self.outlier_share * outlier
    }

    /// The `q` quantile of the bounce (s): the window at that percentile. Bisection in ln t.
    #[must_use]
    pub fn quantile(&self, q: f64) -> f64 {
        crate::support::inverse(|t| self.cdf(t), q.clamp(0.0, 1.0 - 1e-12))
    }

    /// The P99.9 of the type's bounce: for hand-operated switches, the survey's worst switch.
    #[must_use]
    pub fn window(&self) -> f64 {
        self.quantile(PRIOR_PERCENTILE)
    }

    /// The window a user can type with: the P99.9, at most the fastest real tap `fastest_tap`
    /// (s). A longer window swallows real taps (`docs/human-timing.md`); a switch that bounces
    /// longer than a tap shows it as false edges, which the learner reports
    /// (`reverts_like_a_tap`).
    #[must_use]
    pub fn window_in_use(&self, fastest_tap: f64) -> f64 {
        self.window().min(fastest_tap)
    }
}

/// The percentile of a prior's window.
pub const PRIOR_PERCENTILE: f64 = 0.999;

/// How far each parameter of a catalogue switch is taken to range over switches of its type:
/// relative half-widths (uniform), and R's absolute half-width. Assumed, not measured: a
/// catalogue entry is a typical value, and these say how much the switches sold under that
/// name vary. The catalogue's windows are the P99.9 of the predicted bounce over these ranges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ranges {
    /// Moving mass: +-20 %.
    pub mass: f64,
    /// Spring stiffness: +-20 %.
    pub stiffness: f64,
    /// Contact (preload) force: +-30 %.
    pub preload_force: f64,
    /// R: +-0.1, inside (0, 1).
    pub restitution: f64,
    /// Damping ratio: +-50 %.
    pub damping_ratio: f64,
    /// Closing speed: +-50 % (hands and coil drives vary most).
    pub closing_speed: f64,
}

/// The ranges of every catalogue switch.
pub const CATALOGUE_RANGES: Ranges = Ranges {
    mass: 0.2,
    stiffness: 0.2,
    preload_force: 0.3,
    restitution: 0.1,
    damping_ratio: 0.5,
    closing_speed: 0.5,
};

/// Published bounce figures for a catalogue switch's type, beside the model's range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Published {
    /// The catalogue entry.
    pub switch: &'static str,
    /// The longest bounce published for the type (s).
    pub max: f64,
    /// What was published, and by whom.
    pub evidence: &'static str,
}

/// The catalogue entries whose types have published figures. The rest (MEMS switches, power
/// relays, contactors) rest on the model's ranges alone.
pub const PUBLISHED: [Published; 4] = [
    Published {
        switch: "tactile dome",
        max: 5e-3,
        evidence: "tactile switch datasheets promise at most 5 ms; a survey of 18 hand-operated switches found up to 6.2 ms, and one at 157 ms",
    },
    Published {
        switch: "keyboard leaf contact",
        max: 5e-3,
        evidence: "keyboard switch datasheets promise at most 5 ms; a survey of 18 hand-operated switches found up to 6.2 ms, and one at 157 ms",
    },
    Published {
        switch: "miniature reed",
        max: 1e-3,
        evidence: "reed switches are quoted at 0.1-1 ms",
    },
    Published {
        switch: "signal relay",
        max: 5e-3,
        evidence: "signal relays are quoted at about 1 ms typical, 5 ms at most",
    },
];

/// The published figures for a catalogue entry, if any.
#[must_use]
pub fn published(switch: &str) -> Option<&'static Published> {
    PUBLISHED.iter().find(|p| p.switch == switch)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_survey_prior_reproduces_the_survey() {
        let p = HAND_OPERATED;
        // The typical part's mean, e^(mu + sigma^2 / 2), is the survey's 1.56 ms.
        let mean = p.median * (p.sigma * p.sigma / 2.0).exp();
        assert!((mean / 1.557e-3 - 1.0).abs() < 0.01, "{mean}");
        // The largest typical switch, 6.2 ms, sits near the 97th percentile of the typical part.
        let at = Normal::standard().cdf((6.2e-3 / p.median).ln() / p.sigma);
        assert!((0.96..0.98).contains(&at), "{at}");
        // The window, P99.9, is the outlier's 157 ms: the outlier part holds 1/18 > 0.1 %.
        assert!((p.window() / 157e-3 - 1.0).abs() < 1e-6, "{}", p.window());
        // Below the outlier, the typical part's quantile.
        let median = p.quantile(0.5 * (1.0 - p.outlier_share));
        assert!((median / p.median - 1.0).abs() < 1e-6);
    }

    #[test]
    fn types_come_from_the_option_or_the_switch_name() {
        assert_eq!(by_name("Rocker"), Some(&HAND_OPERATED));
        assert_eq!(by_name("contactor"), None);
        assert_eq!(
            from_switch_name("bbb-sample-v0.3.0-banggood-1276758-rocker"),
            Some(&HAND_OPERATED)
        );
        assert_eq!(from_switch_name("bbb-sample-v0.2.3-2024-02-24"), None);
    }
}
