//! How many Gauss-Legendre points a panel takes: the averaged tier's accuracy knob.

/// Gauss-Legendre points per panel: the averaged tier's accuracy knob.
///
/// With panels 0.5 wide in ln J the averaged integrals converge fast (docs/physics.md sec. 3): 8
/// to 12 nodes reach the rounding level of f64 for smooth scenes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Nodes {
    /// 2 points.
    N2,
    /// 4 points.
    N4,
    /// 6 points.
    N6,
    /// 8 points.
    N8,
    /// 10 points.
    N10,
    /// 12 points.
    N12,
    /// 16 points.
    N16,
    /// 20 points.
    N20,
}

impl Nodes {
    /// Every rule, fewest points first.
    pub const ALL: [Self; 8] = [
        Self::N2,
        Self::N4,
        Self::N6,
        Self::N8,
        Self::N10,
        Self::N12,
        Self::N16,
        Self::N20,
    ];

    /// The number of points.
    #[must_use]
    pub const fn count(self) -> u32 {
        match self {
            Self::N2 => 2,
            Self::N4 => 4,
            Self::N6 => 6,
            Self::N8 => 8,
            Self::N10 => 10,
            Self::N12 => 12,
            Self::N16 => 16,
            Self::N20 => 20,
        }
    }

    /// The rule with exactly `count` points, if there is one.
    #[must_use]
    pub const fn from_count(count: u32) -> Option<Self> {
        match count {
            2 => Some(Self::N2),
            4 => Some(Self::N4),
            6 => Some(Self::N6),
            8 => Some(Self::N8),
            10 => Some(Self::N10),
            12 => Some(Self::N12),
            16 => Some(Self::N16),
            20 => Some(Self::N20),
            _ => None,
        }
    }
}
