//! A capture's events described and grouped per switch and kind: what every window from a
//! capture starts from.

use std::collections::BTreeMap;

use crate::capture::{self, Edge, EdgeName, Event};

pub(crate) fn sorted(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v
}

/// Every event described, one CSV row each, in capture order: where it is in the capture, its
/// bounce, transitions, resolved flights and dwells (count, longest), unresolved chatter
/// (count, time) and bursts.
#[must_use]
pub fn events_csv(events: &[Event], resolution: f64, burst_gap: f64) -> String {
    let mut out = String::from(
        "switch,origin,kind,bounce_s,transitions,flights,longest_flight_s,dwells,longest_dwell_s,chatter,chatter_time_s,bursts\n",
    );
    let quote = |s: &str| format!("\"{}\"", s.replace('"', "\"\""));
    let longest = |v: &[f64]| {
        v.iter()
            .copied()
            .reduce(f64::max)
            .map_or_else(String::new, |x| format!("{x:e}"))
    };
    for e in events {
        let d = e.describe(resolution, burst_gap);
        out.push_str(&format!(
            "{},{},{},{:e},{},{},{},{},{},{},{:e},{}\n",
            quote(&e.switch),
            quote(&e.origin),
            e.kind.name(),
            d.bounce,
            d.transitions,
            d.flights.len(),
            longest(&d.flights),
            d.dwells.len(),
            longest(&d.dwells),
            d.chatter,
            d.chatter_time,
            d.bursts,
        ));
    }
    out
}

/// The events described, per switch and kind, in capture order.
pub type Groups<'a> = BTreeMap<(&'a str, Edge), Vec<capture::Description>>;

/// Describes every event at `resolution` (a quiet interval of `burst_gap` ending a burst) and
/// groups them per switch and kind.
#[must_use]
pub fn group(events: &[Event], resolution: f64, burst_gap: f64) -> Groups<'_> {
    let mut groups: Groups<'_> = BTreeMap::new();
    for e in events {
        groups
            .entry((e.switch.as_str(), e.kind))
            .or_default()
            .push(e.describe(resolution, burst_gap));
    }
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_csv_has_one_row_per_event_quoted() {
        let events = [
            Event {
                switch: "a \"b\", c".into(),
                origin: "line 3".into(),
                kind: Edge::Press,
                // closed 10 us, open 1 us (chatter), closed 20 us, open 9 ms (quiet: a second
                // burst), closed 30 us.
                changes: vec![0.0, 10e-6, 11e-6, 31e-6, 9.031e-3, 9.061e-3],
                section: None,
            },
            Event {
                switch: "x".into(),
                origin: String::new(),
                kind: Edge::Release,
                changes: vec![1.0],
                section: None,
            },
        ];
        let csv = events_csv(&events, 3e-6, 5e-3);
        let lines: Vec<&str> = csv.lines().collect();
        assert_eq!(lines.len(), 3, "{csv}");
        let rest = lines[1]
            .strip_prefix("\"a \"\"b\"\", c\",\"line 3\",press,")
            .unwrap();
        let f: Vec<f64> = rest.split(',').map(|x| x.parse().unwrap()).collect();
        let want = [9.061e-3, 6.0, 1.0, 9e-3, 3.0, 3e-5, 1.0, 1e-6, 2.0];
        assert_eq!(f.len(), want.len(), "{rest}");
        for (got, want) in f.iter().zip(want) {
            assert!((got - want).abs() <= 1e-12, "{rest}");
        }
        assert_eq!(lines[2], "\"x\",\"\",release,0e0,1,0,,0,,0,0e0,1");
    }
}
