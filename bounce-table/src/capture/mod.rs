//! Real captures of a switch: import them (JSON Lines of the bouncy-button format, a CSV of
//! edges, a Value Change Dump), cut them into press and release events, and describe each
//! event's bounce: duration, transitions, resolved open intervals (flights) and closed intervals
//! (dwell), and the intervals too short for the instrument (chatter).
//!
//! Levels follow the usual wiring, a pull-up and a switch to ground: high = open, low = closed
//! (`Polarity::ActiveLow`); `Polarity::ActiveHigh` reads the other way.

mod csv;
mod event;
mod jsonl;
mod load;
pub mod scope;
mod vcd;

pub use csv::read_csv;
pub use event::{
    drop_several_presses, CaptureError, Description, Edge, EdgeName, Event, Hold, Polarity,
    Skipped, Stream,
};
pub use jsonl::read_jsonl;
pub use load::{load, load_text, Format, Loaded, Options};
pub use vcd::read_vcd;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stream_is_cut_at_quiet_gaps_and_kinds_alternate() {
        let s = Stream {
            closed_before: false,
            changes: vec![1.0, 1.001, 1.002, 2.0, 2.0005],
        };
        let e = s.segment("sw", 0.1);
        assert_eq!(e.len(), 2);
        assert_eq!(e[0].kind, Edge::Press);
        assert_eq!(e[0].changes, vec![1.0, 1.001, 1.002]);
        // Three changes leave it closed: the next event is a release.
        assert_eq!(e[1].kind, Edge::Release);
    }

    #[test]
    fn a_press_is_described_as_dwells_flights_and_chatter() {
        let e = Event {
            switch: "sw".into(),
            origin: String::new(),
            kind: Edge::Press,
            // closed 10 us, open 1 us (chatter), closed 20 us, open 30 us, closed.
            changes: vec![0.0, 10e-6, 11e-6, 31e-6, 61e-6],
            section: None,
        };
        let d = e.describe(3e-6, 1.0);
        assert_eq!(d.transitions, 5);
        assert_eq!(d.chatter, 1);
        assert_eq!(d.dwells.len(), 2);
        assert_eq!(d.flights.len(), 1);
        assert!((d.flights[0] - 30e-6).abs() < 1e-12);
        assert!((d.bounce - 61e-6).abs() < 1e-12);
        assert!((d.chatter_time - 1e-6).abs() < 1e-12);
        assert_eq!((d.bursts, d.first_burst_flights), (1, 1));
    }

    #[test]
    fn a_press_holds_for_its_longest_closed_dwell_inside_the_first_burst() {
        // closed 5, open 100, closed 2 (chatter), open 40, closed 300, open 20, closed; then,
        // after a quiet 10 ms (a late burst), a longer dwell that does not count.
        let mut e = Event {
            switch: "sw".into(),
            origin: String::new(),
            kind: Edge::Press,
            changes: vec![0.0, 5e-6, 105e-6, 107e-6, 147e-6, 447e-6, 467e-6],
            section: None,
        };
        let h = e.describe(3e-6, 5e-3).hold.unwrap();
        assert!((h.at - 147e-6).abs() < 1e-12 && (h.dwell - 300e-6).abs() < 1e-12);
        assert!((h.share - 3.0).abs() < 1e-9, "{h:?}");
        e.changes.extend([10.467e-3, 10.468e-3, 20.0e-3, 20.1e-3]);
        assert_eq!(e.describe(3e-6, 5e-3).hold, Some(h));
        // No resolved flight: nothing to compare a dwell with. A release has no hold.
        e.changes = vec![0.0, 300e-6, 301e-6];
        assert_eq!(e.describe(3e-6, 5e-3).hold, None);
        e.changes = vec![0.0, 5e-6, 105e-6, 405e-6, 406e-6];
        e.kind = Edge::Release;
        assert_eq!(e.describe(3e-6, 5e-3).hold, None);
    }

    #[test]
    fn a_quiet_interval_of_the_burst_gap_ends_a_burst() {
        let e = Event {
            switch: "sw".into(),
            origin: String::new(),
            kind: Edge::Release,
            // open 20 us, closed 10 us, open 5 ms (quiet), closed 30 us, open 2 ms (quiet),
            // closed 40 us, open.
            changes: vec![0.0, 20e-6, 30e-6, 5.03e-3, 5.06e-3, 7.06e-3, 7.1e-3],
            section: None,
        };
        let d = e.describe(3e-6, 1e-3);
        assert_eq!(d.bursts, 3);
        assert_eq!(d.first_burst_flights, 1);
        assert_eq!(d.flights.len(), 3);
        // A gap wider than every interval: one burst, all its flights.
        let d = e.describe(3e-6, 1.0);
        assert_eq!((d.bursts, d.first_burst_flights), (1, 3));
        let none = Event {
            changes: vec![],
            ..e.clone()
        };
        assert_eq!(none.describe(3e-6, 1e-3).bursts, 0);
    }

    #[test]
    fn csv_rejects_what_it_cannot_read_naming_the_line() {
        let bad = [
            ("time,level\n0,1\n0.5,2\n", 3, "level"),
            ("0,1\n0.5\n", 2, "expected"),
            ("0,1\n0.5,0\n0.4,1\n", 3, "back in time"),
            ("0,1\nabc,0\n", 2, "not a number"),
            ("0,1\nNaN,0\n", 2, "finite"),
        ];
        for (text, line, why) in bad {
            let e = read_csv("f.csv", text, Polarity::ActiveLow).unwrap_err();
            assert_eq!(e.line, line, "{text:?}: {e}");
            assert!(e.reason.contains(why), "{text:?}: {e}");
        }
        assert_eq!(
            read_csv("f.csv", "# nothing\n", Polarity::ActiveLow)
                .unwrap_err()
                .line,
            0
        );
    }

    #[test]
    fn vcd_rejects_what_it_cannot_read_naming_the_line() {
        let head = "$timescale 1ns $end\n$scope module top $end\n$var wire 1 ! sw $end\n$upscope $end\n$enddefinitions $end\n";
        let bad = [
            (format!("{head}#0\n1!\n#5\nx!\n"), 9, "unknown"),
            (format!("{head}#10\n1!\n#5\n0!\n"), 8, "back in time"),
            (format!("{head}1!\n"), 6, "before the first time stamp"),
            (format!("{head}#1.5\n"), 6, "whole number"),
            ("$timescale 3 ns $end\n".to_owned(), 1, "timescale"),
            ("#0\n1!\n".to_owned(), 1, "before `$enddefinitions`"),
            // sigrok-cli's META line is skipped only where sigrok-cli writes it: first.
            (
                format!("$comment x $end\nMETA samplerate: 1\n{head}"),
                2,
                "before `$enddefinitions`",
            ),
        ];
        for (text, line, why) in bad {
            let e = read_vcd("f.vcd", &text, None, Polarity::ActiveLow).unwrap_err();
            assert_eq!(e.line, line, "{text:?}: {e}");
            assert!(e.reason.contains(why), "{text:?}: {e}");
        }
        let e = read_vcd("f.vcd", head, Some("other"), Polarity::ActiveLow).unwrap_err();
        assert!(e.reason.contains("no signal named"), "{e}");
    }

    #[test]
    fn what_cannot_be_one_press_is_left_out_and_counted_per_reason() {
        let test = |dataset: &str, section: &str, invalid: bool, events: &str| {
            format!(
                "{{\"dataset\":\"{dataset}\",\"kind\":\"press\",\"section\":\"{section}\",\"section_invalid\":{invalid},\"events\":{events}}}\n"
            )
        };
        let one = "[[0,1],[10,0]]";
        let text = [
            test("a", "Slow", true, one),
            test("b", "Slow", false, one), // the same protocol, not flagged
            test("b", "Normal", false, one),
            test("b", "Odd", false, one),
            // closed, then open for 0.5 s, then closed again: two presses
            test("b", "Normal", false, "[[0,1],[10,0],[1e6,1],[5.01e8,0]]"),
        ]
        .concat();
        let (events, mut skipped) = read_jsonl("f.jsonl", &text, &["Odd".to_owned()]).unwrap();
        assert_eq!(events.len(), 2);
        let events = drop_several_presses(events, 0.2, &mut skipped);
        assert_eq!(events.len(), 1);
        assert_eq!(events[0].section.as_deref(), Some("Normal"));
        assert_eq!(
            (
                skipped.marked_invalid,
                skipped.marked_invalid_elsewhere,
                skipped.named,
                skipped.several_presses,
                skipped.total()
            ),
            (1, 1, 1, 1, 4)
        );
        let said = skipped.describe(0.2);
        for reason in [
            "(Slow)",
            "for another switch",
            "--skip-section",
            "several presses",
        ] {
            assert!(said.contains(reason), "{said}");
        }
        assert_eq!(Skipped::default().describe(0.2), "");
    }

    #[test]
    fn jsonl_rejects_a_kind_that_disagrees_with_the_starting_level() {
        let line = r#"{"dataset":"d","kind":"press","events":[[0,0],[10,1]]}"#;
        let e = read_jsonl("f.jsonl", line, &[]).unwrap_err();
        assert!(e.reason.contains("starts closed"), "{e}");
        // No `section`: the event has none.
        let line = r#"{"dataset":"d","kind":"press","events":[[0,1],[10,0]]}"#;
        assert_eq!(read_jsonl("f.jsonl", line, &[]).unwrap().0[0].section, None);
        let e = read_jsonl("f.jsonl", "{\n", &[]).unwrap_err();
        assert_eq!(e.line, 1);
    }
}
