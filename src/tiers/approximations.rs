//! The approximations a prediction made on its way, as a small bit set.

/// Approximations made on the way to a prediction (a small bit set).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Approximations(u8);

impl Approximations {
    /// None.
    pub const NONE: Self = Self(0);
    /// Two bodies with unequal partial frequencies, reduced at the Rayleigh frequency.
    pub const TWO_BODY_RAYLEIGH: Self = Self(1);
    /// A closed form or tier used outside the validity docs/physics.md sec. 6 states for it:
    /// `expected_error` is then `None`.
    pub const OUTSIDE_VALIDITY: Self = Self(1 << 1);
    /// An iterating tier (the map, the exact tier) reached its cap on impacts and the
    /// averaged model finished the sum.
    pub const MAP_CONTINUED_AVERAGED: Self = Self(1 << 2);
    /// A quadrature reached its panel cap before its range ended.
    pub const PANELS_CAPPED: Self = Self(1 << 3);
    /// A time or count exceeded the float's range: it is reported as `Never` / `Infinite`
    /// (for the bounce, "longer than anything this type can count").
    pub const BEYOND_RANGE: Self = Self(1 << 4);

    /// True when every flag of `other` is set.
    #[must_use]
    pub const fn contains(self, other: Self) -> bool {
        self.0 & other.0 == other.0
    }
    /// The union.
    #[must_use]
    pub const fn with(self, other: Self) -> Self {
        Self(self.0 | other.0)
    }
    /// True when nothing is flagged.
    #[must_use]
    pub const fn is_empty(self) -> bool {
        self.0 == 0
    }
    /// Each flag and its name, in bit order: the one table the names come from.
    const NAMED: [(Self, &'static str); 5] = [
        (Self::TWO_BODY_RAYLEIGH, "two_body_rayleigh"),
        (Self::OUTSIDE_VALIDITY, "outside_validity"),
        (Self::MAP_CONTINUED_AVERAGED, "map_continued_averaged"),
        (Self::PANELS_CAPPED, "panels_capped"),
        (Self::BEYOND_RANGE, "beyond_range"),
    ];
    /// The names of the flags set, in bit order: the constants' names in lower case
    /// (`two_body_rayleigh`, `outside_validity`, ...). Nothing for [`Approximations::NONE`].
    ///
    /// ```
    /// use contact_bounce::tiers::Approximations;
    ///
    /// let a = Approximations::OUTSIDE_VALIDITY.with(Approximations::TWO_BODY_RAYLEIGH);
    /// let mut names = a.names();
    /// assert_eq!(names.next(), Some("two_body_rayleigh"));
    /// assert_eq!(names.next(), Some("outside_validity"));
    /// assert_eq!(names.next(), None);
    /// ```
    pub fn names(self) -> impl Iterator<Item = &'static str> {
        Self::NAMED
            .into_iter()
            .filter(move |(flag, _)| self.contains(*flag))
            .map(|(_, name)| name)
    }
}

/// The flags' names ([`Approximations::names`]) joined by `+`, or `none`.
impl core::fmt::Display for Approximations {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        if self.is_empty() {
            return f.write_str("none");
        }
        for (k, name) in self.names().enumerate() {
            if k > 0 {
                f.write_str("+")?;
            }
            f.write_str(name)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::Approximations;

    #[test]
    fn every_approximation_has_one_name_and_one_bit() {
        let mut seen = 0u8;
        for (flag, name) in Approximations::NAMED {
            assert_eq!(flag.0.count_ones(), 1, "{name} is not one bit");
            assert_eq!(seen & flag.0, 0, "{name}'s bit is named twice");
            seen |= flag.0;
            assert!(flag.names().eq([name]), "{name} does not name itself");
            let others = Approximations(!flag.0 & seen);
            assert!(others.names().all(|n| n != name));
        }
        // The table covers bits 0-4, the five constants above.
        assert_eq!(seen, 0b1_1111);
        assert_eq!(Approximations::NONE.names().count(), 0);
    }

    #[test]
    fn approximations_display_as_their_names() {
        extern crate std;
        use std::string::ToString;
        assert_eq!(Approximations::NONE.to_string(), "none");
        let a = Approximations::BEYOND_RANGE.with(Approximations::TWO_BODY_RAYLEIGH);
        assert_eq!(a.to_string(), "two_body_rayleigh+beyond_range");
    }
}
