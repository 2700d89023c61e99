//! Every tier of the core against the exact reference, on the grid of `host_tests::grid`
//! (every regime of physics.md sec. 4 and the switches of sec. 7) and on scenes off it: the
//! regime agrees, and wherever a tier states an expected error, the measured error is within
//! it. The expected errors are physics.md sec. 6, corrected where the reference showed them
//! wrong (see src/accuracy and docs/error-table.md); none is widened here.

use host_tests::grid::{compare, grid, off_grid, Row};

fn check(rows: &[Row]) -> Vec<String> {
    rows.iter()
        .filter_map(|r| {
            if !r.regime_agrees {
                return Some(format!("{} / {}: regime disagrees", r.scene, r.tier));
            }
            match r.expected {
                Some(e) if r.error > e => Some(format!(
                    "{} / {}: error {:.4} > expected {:.4} (reference {:?}, core {:?})",
                    r.scene, r.tier, r.error, e, r.truth, r.predicted
                )),
                _ => None,
            }
        })
        .collect()
}

#[test]
fn every_tier_keeps_its_expected_error_on_the_grid() {
    let mut problems = Vec::new();
    let mut compared = 0;
    for scene in grid() {
        match compare(&scene) {
            Ok(rows) => {
                compared += rows.len();
                problems.extend(check(&rows));
            }
            Err(e) => problems.push(e),
        }
    }
    assert!(compared > 1000);
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn every_tier_keeps_its_expected_error_off_the_grid() {
    let mut problems = Vec::new();
    let mut stated = 0;
    for scene in off_grid(300, 0x5eed_b0c3) {
        match compare(&scene) {
            Ok(rows) => {
                stated += rows.iter().filter(|r| r.expected.is_some()).count();
                problems.extend(check(&rows));
            }
            Err(e) => problems.push(e),
        }
    }
    assert!(stated > 500, "only {stated} stated errors");
    assert!(
        problems.is_empty(),
        "{} problems:\n{}",
        problems.len(),
        problems.join("\n")
    );
}

#[test]
fn exact_tiers_reproduce_the_reference_to_rounding() {
    // zeta = 0 (any Delta) and Delta = 0: the closed tier's sums and the reference agree.
    for scene in grid()
        .iter()
        .filter(|s| s.reference.zeta == 0.0 || s.reference.delta == 0.0)
    {
        let rows = compare(scene).unwrap();
        for row in rows.iter().filter(|r| {
            r.tier.starts_with("Closed(Undamped)") || r.tier.starts_with("Closed(Grazing)")
        }) {
            assert!(
                row.error < 1e-9,
                "{} / {}: {}",
                row.scene,
                row.tier,
                row.error
            );
        }
    }
}
