//! How long a bounce lasts and how many impacts it has, when either may be unbounded: what
//! the mechanisms' asymptotes and every tier give.

use crate::Float;

/// A time that may never come.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Time<F> {
    /// At this time after the first impact (s).
    At(F),
    /// Never: the regime is endless (never a huge number).
    Never,
}

impl<F: Float> Time<F> {
    /// The time, if finite.
    #[must_use]
    pub fn seconds(self) -> Option<F> {
        match self {
            Self::At(t) => Some(t),
            Self::Never => None,
        }
    }

    /// The earlier of two times.
    pub(crate) fn min_with(self, other: Self) -> Self {
        match (self, other) {
            (Self::At(a), Self::At(b)) => Self::At(a.min(b)),
            (Self::At(a), Self::Never) | (Self::Never, Self::At(a)) => Self::At(a),
            (Self::Never, Self::Never) => Self::Never,
        }
    }

    /// A rest of this length that starts at `start` (s): where it ends, if it does.
    pub(crate) fn after(self, start: F) -> Self {
        match self {
            Self::At(t) => Self::At(start + t),
            Self::Never => Self::Never,
        }
    }

    /// As [`Time::after`], for a crossing the bounce must reach (the threshold's, which every
    /// impulse falls below): a rest longer than the float can tell is out of range, 2 MAX
    /// (infinite), which the prediction's caller flags.
    pub(crate) fn reached_after(self, start: F) -> Self {
        match self {
            Self::At(t) => Self::At(start + t),
            Self::Never => Self::At(F::MAX * F::TWO),
        }
    }
}

/// A number of impacts that may be infinite.
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Count<F> {
    /// This many (an integer for the discrete tiers, a real number for the averaged tier).
    Finite(F),
    /// Infinitely many (Zeno accumulation or an endless regime).
    Infinite,
}

impl<F: Float> Count<F> {
    /// The count, if finite.
    #[must_use]
    pub fn value(self) -> Option<F> {
        match self {
            Self::Finite(n) => Some(n),
            Self::Infinite => None,
        }
    }

    /// The smaller of two counts.
    pub(crate) fn min_with(self, other: Self) -> Self {
        match (self, other) {
            (Self::Finite(a), Self::Finite(b)) => Self::Finite(a.min(b)),
            (Self::Finite(a), Self::Infinite) | (Self::Infinite, Self::Finite(a)) => {
                Self::Finite(a)
            }
            (Self::Infinite, Self::Infinite) => Self::Infinite,
        }
    }

    /// These impacts after `before` others.
    pub(crate) fn after(self, before: F) -> Self {
        match self {
            Self::Finite(n) => Self::Finite(before + n),
            Self::Infinite => Self::Infinite,
        }
    }

    /// As [`Count::after`], for a crossing the bounce reaches: more impacts than the float
    /// counts are out of range, 2 MAX (infinite), which the prediction's caller flags.
    pub(crate) fn reached_after(self, before: F) -> Self {
        match self {
            Self::Finite(n) => Self::Finite(before + n),
            Self::Infinite => Self::Finite(F::MAX * F::TWO),
        }
    }
}
