//! Order statistics shared by the reports.

/// The `q`-quantile (`q` in 0..=1) of ascending data by the nearest-rank method: the smallest
/// value with at least a fraction `q` of the data at or below it. `None` when empty.
#[must_use]
pub fn nearest_rank(sorted: &[f64], q: f64) -> Option<f64> {
    sorted.get(rank(sorted.len(), q)?).copied()
}

/// As [`nearest_rank`], of data in any order, in linear time: `data` is reordered (partly
/// sorted around the rank), not sorted.
pub fn nearest_rank_unsorted(data: &mut [f64], q: f64) -> Option<f64> {
    let k = rank(data.len(), q)?;
    data.select_nth_unstable_by(k, f64::total_cmp);
    data.get(k).copied()
}

/// The nearest rank's place (from 0) among `n` values; `None` when `n` is 0.
fn rank(n: usize, q: f64) -> Option<usize> {
    if n == 0 {
        return None;
    }
    #[allow(
        clippy::cast_precision_loss,
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss
    )]
    let rank = ((q * n as f64).ceil() as usize).clamp(1, n);
    Some(rank - 1)
}

#[cfg(test)]
mod tests {
    use super::nearest_rank;

    #[test]
    fn nearest_rank_picks_the_smallest_value_covering_the_fraction() {
        let v = [1.0, 2.0, 3.0, 4.0];
        assert_eq!(nearest_rank(&v, 0.5), Some(2.0));
        assert_eq!(nearest_rank(&v, 0.51), Some(3.0));
        assert_eq!(nearest_rank(&v, 0.0), Some(1.0));
        assert_eq!(nearest_rank(&v, 1.0), Some(4.0));
        assert_eq!(nearest_rank(&[], 0.5), None);
    }

    #[test]
    fn the_unsorted_nearest_rank_is_the_sorted_one() {
        // A shuffled sample with ties, every quantile of a fine grid.
        let mut sorted: Vec<f64> = (0..1000_u32).map(|i| f64::from(i / 3)).collect();
        let mut shuffled = sorted.clone();
        let mut state = 12_345_u64;
        for i in (1..shuffled.len()).rev() {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            #[allow(clippy::cast_possible_truncation)]
            let j = (state >> 33) as usize % (i + 1);
            shuffled.swap(i, j);
        }
        sorted.sort_by(f64::total_cmp);
        for k in 0..=200 {
            let q = f64::from(k) / 200.0;
            assert_eq!(
                super::nearest_rank_unsorted(&mut shuffled.clone(), q),
                nearest_rank(&sorted, q),
                "q = {q}"
            );
        }
        assert_eq!(super::nearest_rank_unsorted(&mut [], 0.5), None);
    }
}
