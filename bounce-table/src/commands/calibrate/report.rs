//! The report: the description table, the fits, the held-out checks and the windows
//! (markdown).

use crate::capture;
use crate::capture::EdgeName;
use crate::render::output::time;
use crate::stats::{bounces, reopens, BounceModel, ImpactFit, LogNormal};
use crate::stats::{chronological_cover, earlier_count, window, Cover, FAR_BEYOND, MIN_EVENTS};
use crate::stats::{
    random_splits, ratio, validations, RatioSpread, RANDOM_SPLITS, VALIDATION_QUANTILES,
};
use crate::stats::{sorted, Groups};
use contact_bounce_reference::stats::nearest_rank;

fn q(v: &[f64], p: f64, show: impl Fn(f64) -> String) -> String {
    nearest_rank(v, p).map_or_else(|| "-".to_owned(), show)
}

/// The description table (markdown): per switch and kind, the events, the share of clean edges
/// (one change), the bounce's P50/P90/P99/max, transitions, resolved flights and dwells, and
/// unresolved intervals (chatter).
#[must_use]
pub fn describe(groups: &Groups<'_>, resolution: f64) -> String {
    let mut out = String::new();
    out.push_str(&format!(
        "Resolution {}: shorter intervals are counted as chatter, not timed.\n\n",
        time(resolution)
    ));
    out.push_str("| switch | kind | events | clean | bounce P50 | P90 | P99 | max | transitions P50 / P90 / max | flights per event (P50) | longest flight P50 / P90 | dwells per event (P50) | chatter per event P50 / P90 |\n");
    out.push_str("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for ((switch, kind), d) in groups {
        #[allow(clippy::cast_precision_loss)]
        let count = |f: &dyn Fn(&capture::Description) -> usize| {
            sorted(d.iter().map(|x| f(x) as f64).collect())
        };
        let bounce = sorted(d.iter().map(|x| x.bounce).collect());
        let transitions = count(&|x| x.transitions);
        let flights = count(&|x| x.flights.len());
        let dwells = count(&|x| x.dwells.len());
        let chatter = count(&|x| x.chatter);
        let longest = sorted(
            d.iter()
                .filter_map(|x| x.flights.iter().copied().reduce(f64::max))
                .collect(),
        );
        let clean = d.iter().filter(|x| x.transitions <= 1).count();
        let n = |x: f64| format!("{x:.0}");
        out.push_str(&format!(
            "| {switch} | {} | {} | {clean} | {} | {} | {} | {} | {} / {} / {} | {} | {} / {} | {} | {} / {} |\n",
            kind.name(),
            d.len(),
            q(&bounce, 0.5, time),
            q(&bounce, 0.9, time),
            q(&bounce, 0.99, time),
            q(&bounce, 1.0, time),
            q(&transitions, 0.5, n),
            q(&transitions, 0.9, n),
            q(&transitions, 1.0, n),
            q(&flights, 0.5, n),
            q(&longest, 0.5, time),
            q(&longest, 0.9, time),
            q(&dwells, 0.5, n),
            q(&chatter, 0.5, n),
            q(&chatter, 0.9, n),
        ));
    }
    out
}

fn ratio_text(r: Option<f64>) -> String {
    match r {
        None => "-".to_owned(),
        Some(r) if r >= 1000.0 => format!("{r:.1e}"),
        Some(r) => format!("{r:.2}"),
    }
}

fn three(r: &[Option<f64>; 3]) -> String {
    r.iter()
        .map(|x| ratio_text(*x))
        .collect::<Vec<_>>()
        .join(" / ")
}

fn lognormal_text(l: Option<LogNormal>) -> String {
    l.map_or_else(
        || "-".to_owned(),
        |l| {
            if l.floor > 0.0 {
                format!(
                    "{} + {} x/ {:.2}",
                    time(l.floor),
                    time(l.mu.exp()),
                    l.sigma.exp()
                )
            } else {
                format!("{} x/ {:.2}", time(l.median()), l.sigma.exp())
            }
        },
    )
}

/// The fit, the held-out checks and the windows (markdown), after the description.
#[must_use]
pub fn assess(groups: &Groups<'_>, percentile: f64, seed: u64) -> String {
    let mut out = String::from(
        "\n## Impact-model fit\n\nR: the median ratio of successive resolved flights of the first burst (quartiles beside it); \
         the model holds when at least 5 pairs exist, 80 % of ratios are below 1 and the upper quartile too. \
         Scale v0 / (Omega^2 |Delta|) = first flight / (2 R); Omega, Delta and v0 apart need the closing \
         speed, the preload force or the resonance measured separately.\n\n\
         | switch | kind | flight pairs | R (median) | quartiles | ratios below 1 | first flight P50 | v0 / (Omega^2 \\|Delta\\|) | impact model holds |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut model = String::from(
        "\n## Fitted bounce model\n\nEach event is clean, one burst, or bounces again after a quiet interval of at \
         least the burst gap (a late burst); a bounce shorter than the resolution is not timed and counts as clean. Bursts are log-normal (median x/ geometric \
         spread); a late burst holds a quiet interval of at least the burst gap, so its bounce is the gap plus a \
         log-normal excess (gap + median x/ spread; the whole bounce's log-normal where a late burst lasts exactly the gap). The burst term is the impact model's (first flight / (1 - R), times 1 + the closed share: \
         the dwell and chatter a Newton impact does not have) where it holds, else the observed bursts'. \
         A press whose contact holds, inside its burst, for a dwell of at least a threshold share of its longest \
         flight and then opens again reopens: the stuck pair of two bodies with unequal partial frequencies, \
         whose swing turns the contact force tensile. Reopening presses are a part of their own where that \
         lowers the Bayesian information criterion (threshold and dwell median beside them). \
         Last column: the model's quantiles over the capture's, on every event.\n\n\
         | switch | kind | events | clean | one burst | burst bounce | closed share | reopens | reopening bounce | threshold / dwell | late burst | late bounce | burst term | model / observed P50 / P90 / P99 |\n\
         |---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|\n",
    );
    let mut checks = String::from(
        "\n## Held-out check\n\nFit on one half, predict the other half's bounce P50 / P90 / P99: \
         predicted / observed, by the empirical part alone (the fitted half's own quantiles), by the \
         impact model alone (each event's first flight / (1 - R); `-` where R >= 1 or nothing is observed), \
         and by the fitted bounce model (`-` where a part that occurs has fewer than 3 events to fit).\n\n\
         | switch | kind | split | events | observed P50 / P90 / P99 | empirical | impact model | fitted model |\n\
         |---|---|---|---:|---:|---:|---:|---:|\n",
    );
    let mut spread = format!(
        "\n## Held-out over {RANDOM_SPLITS} random halvings\n\nThe held-out ratio (predicted / observed) over \
         {RANDOM_SPLITS} seeded random halvings: median and, in brackets, the 10th to 90th percentile; \
         \"splits\": how many halvings the predictor could predict in.\n\n\
         | switch | kind | predictor | splits | P50 | P90 | P99 |\n|---|---|---|---:|---:|---:|---:|\n"
    );
    let mut windows = format!(
        "\n## Windows\n\nP{p} of the fitted model's posterior predictive: the bounce of the next event, with \
         the uncertainty of shares and log-normal spreads fitted to this many events (Student t parts, \
         shares (k + 1) / (n + parts + 1), a part with fewer than 3 events borrowing the others' spread); never \
         below the largest bounce observed. A window more than {FAR_BEYOND} times the largest observed says why.\n\n\
         | switch | kind | largest observed | predictive P{p} | window | note | explained by |\n|---|---|---:|---:|---:|---|---|\n",
        p = percentile * 100.0
    );
    let pct = |x: f64| format!("{:.0} %", x * 100.0);
    for ((switch, kind), d) in groups {
        let refs: Vec<&capture::Description> = d.iter().collect();
        let fit = ImpactFit::new(&refs);
        let scale = fit
            .first_flight
            .zip(fit.restitution)
            .map(|(f, r)| f / (2.0 * r));
        out.push_str(&format!(
            "| {switch} | {} | {} | {} | {} | {:.0} % | {} | {} | {} |\n",
            kind.name(),
            fit.pairs,
            ratio_text(fit.restitution),
            fit.quartiles
                .map_or_else(|| "-".to_owned(), |(a, b)| format!("{a:.2} - {b:.2}")),
            fit.shrinking * 100.0,
            fit.first_flight.map_or_else(|| "-".to_owned(), time),
            scale.map_or_else(|| "-".to_owned(), |s| format!("{s:.3e} s")),
            if fit.holds() { "yes" } else { "no" },
        ));
        let m = BounceModel::fit(&refs);
        let all = sorted(refs.iter().map(|x| x.bounce).collect());
        let in_sample = VALIDATION_QUANTILES.map(|q| ratio(m.quantile(q), nearest_rank(&all, q)));
        model.push_str(&format!(
            "| {switch} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            kind.name(),
            m.events,
            pct(m.clean),
            pct(m.single),
            lognormal_text(m.burst),
            m.closed_share
                .map_or_else(|| "-".to_owned(), |c| format!("{c:.2}")),
            pct(m.reopened),
            lognormal_text(m.reopened_bounce),
            m.reopening
                .zip(m.reopening_dwell)
                .map_or_else(|| "-".to_owned(), |(c, d)| format!("{c:.2} / {}", time(d))),
            pct(m.late),
            lognormal_text(m.late_bounce),
            if m.impact { "impact model" } else { "observed" },
            three(&in_sample),
        ));
        let v = validations(&refs, seed);
        for c in &v {
            let observed = c
                .observed
                .iter()
                .map(|x| x.map_or_else(|| "-".to_owned(), time))
                .collect::<Vec<_>>()
                .join(" / ");
            checks.push_str(&format!(
                "| {switch} | {} | {} | {} + {} | {observed} | {} | {} | {} |\n",
                kind.name(),
                c.split,
                c.sizes.0,
                c.sizes.1,
                three(&c.empirical),
                three(&c.model),
                three(&c.fitted),
            ));
        }
        for (name, r) in ["empirical", "impact model", "fitted model"]
            .iter()
            .zip(random_splits(&refs, seed, RANDOM_SPLITS))
        {
            let cell = |x: Option<RatioSpread>| {
                x.map_or_else(
                    || "-".to_owned(),
                    |x| {
                        format!(
                            "{} ({} - {})",
                            ratio_text(Some(x.p50)),
                            ratio_text(Some(x.p10)),
                            ratio_text(Some(x.p90))
                        )
                    },
                )
            };
            spread.push_str(&format!(
                "| {switch} | {} | {name} | {} | {} | {} | {} |\n",
                kind.name(),
                r.iter().flatten().map(|x| x.predicted).max().unwrap_or(0),
                cell(r[0]),
                cell(r[1]),
                cell(r[2]),
            ));
        }
        let explained = if fit.holds() {
            "impact model and empirical terms"
        } else {
            "empirical terms only"
        };
        let w = window(&refs, percentile);
        windows.push_str(&format!(
            "| {switch} | {} | {} | {} | {} | {} | {explained} |\n",
            kind.name(),
            time(w.observed),
            w.predictive
                .filter(|_| !w.too_few())
                .map_or_else(|| "-".to_owned(), time),
            if w.too_few() {
                "none".to_owned()
            } else {
                time(w.recommended())
            },
            if w.too_few() {
                format!("{} events are too few (at least {MIN_EVENTS})", w.events)
            } else {
                w.reason().unwrap_or_default()
            },
        ));
    }
    out + &model + &checks + &spread + &windows
}

/// The bounce per section of the test protocol (markdown), where a switch and kind holds more
/// than one: how the switch was operated (a normal press, a fast one) can change how it bounces,
/// and a window fitted on one way of operating it holds on another only if they bounce alike.
/// Per section, in the order the capture first shows it: its tests in the earlier and the later
/// half (the chronological split of the held-out checks), the clean ones, those that bounce
/// again after the burst gap (a late burst), those that reopen (where the fitted model has a
/// reopening part: its threshold over the whole switch and kind), and the bounce's P50 / P90 /
/// max. Empty when no switch and kind has two sections.
#[must_use]
pub fn by_section(groups: &Groups<'_>) -> String {
    let mut rows = String::new();
    for ((switch, kind), d) in groups {
        let mut names: Vec<&str> = Vec::new();
        for x in d {
            if let Some(name) = x.section.as_deref() {
                if !names.contains(&name) {
                    names.push(name);
                }
            }
        }
        if names.len() < 2 {
            continue;
        }
        let refs: Vec<&capture::Description> = d.iter().collect();
        let reopening = BounceModel::fit(&refs).reopening;
        let earlier = earlier_count(d.len(), 0.5);
        for name in names {
            let (mut halves, mut clean, mut late, mut reopened) = ([0, 0], 0, 0, 0);
            let mut bounce = Vec::new();
            for (i, x) in d.iter().enumerate() {
                if x.section.as_deref() != Some(name) {
                    continue;
                }
                halves[usize::from(i >= earlier)] += 1;
                bounce.push(x.bounce);
                if !bounces(x) {
                    clean += 1;
                } else if x.bursts > 1 {
                    late += 1;
                } else if reopens(x, reopening) {
                    reopened += 1;
                }
            }
            let bounce = sorted(bounce);
            rows.push_str(&format!(
                "| {switch} | {} | {name} | {} / {} | {clean} | {late} | {} | {} | {} | {} |\n",
                kind.name(),
                halves[0],
                halves[1],
                if reopening.is_some() {
                    reopened.to_string()
                } else {
                    "-".to_owned()
                },
                q(&bounce, 0.5, time),
                q(&bounce, 0.9, time),
                q(&bounce, 1.0, time),
            ));
        }
    }
    if rows.is_empty() {
        return rows;
    }
    format!(
        "\n## By section\n\nThe capture's sections are parts of its test protocol: the same switch operated another way \
         (a normal press, a fast one). Per section: its tests in the earlier / later half (the chronological split \
         of the held-out checks), the clean ones, those that bounce again after the burst gap (late burst), those \
         that reopen (`-` where the fitted model has no reopening part), and the bounce's P50 / P90 / max. A window \
         fitted on one way of operating a switch holds on another only if they bounce alike.\n\n\
         | switch | kind | section | tests (earlier / later half) | clean | late burst | reopens | bounce P50 | P90 | max |\n\
         |---|---|---|---:|---:|---:|---:|---:|---:|---:|\n{rows}"
    )
}

/// One plain line per switch and kind, for the top of the report: the window to use and what
/// it rests on, how the same rule held on the capture's later half when fitted on its earlier
/// half, and the share of late bursts.
#[must_use]
pub fn summary(groups: &Groups<'_>, percentile: f64, burst_gap: f64, cap: Option<f64>) -> String {
    let mut out = String::new();
    for ((switch, kind), d) in groups {
        let refs: Vec<&capture::Description> = d.iter().collect();
        let w = window(&refs, percentile);
        let capped = |x: f64| cap.map_or(x, |c| x.min(c));
        let Cover {
            window: half,
            covered,
            later,
            later_max,
        } = chronological_cover(&refs, percentile, 0.5);
        let late: Vec<f64> = d
            .iter()
            .filter(|x| x.bursts > 1)
            .map(|x| x.bounce)
            .collect();
        if w.too_few() {
            out.push_str(&format!(
                "- {switch} {}: no window: {} events are too few (at least {MIN_EVENTS}; below that the fit's own uncertainty sets its tail); the largest bounce observed is {}. Capture more.\n",
                kind.name(),
                d.len(),
                time(w.observed)
            ));
            continue;
        }
        let what = if w.predictive.is_some_and(|p| p >= w.observed) {
            format!("P{} of the fitted model's predictive", percentile * 100.0)
        } else {
            "the largest bounce observed".to_owned()
        };
        #[allow(clippy::cast_precision_loss)]
        let late_text = if late.is_empty() {
            format!("none bounces again after a quiet {}", time(burst_gap))
        } else {
            format!(
                "{:.0} % bounce again after a quiet {}, up to {} after the first change",
                late.len() as f64 * 100.0 / d.len() as f64,
                time(burst_gap),
                time(late.iter().copied().fold(0.0, f64::max))
            )
        };
        let kinds = match kind {
            capture::Edge::Press => "presses",
            capture::Edge::Release => "releases",
        };
        // Capped: the later events the capped earlier-half window still covers.
        let covered = match cap {
            Some(c) if half.recommended() > c => refs
                .get(earlier_count(refs.len(), 0.5)..)
                .unwrap_or(&[])
                .iter()
                .filter(|x| x.bounce <= c)
                .count(),
            _ => covered,
        };
        // A later half that never bounced has no largest bounce to compare with.
        let held = if later_max > 0.0 {
            format!(
                "covers {covered} of the {later} later {kinds} and is {:.2} times the largest of them, {}",
                capped(half.recommended()) / later_max,
                time(later_max)
            )
        } else {
            format!("covers {covered} of the {later} later {kinds}, none of which bounced")
        };
        let cap_text = match cap {
            Some(c) if w.recommended() > c => {
                let longer: Vec<f64> = d.iter().map(|x| x.bounce).filter(|&b| b > c).collect();
                format!(
                    " Capped at {} (--min-tap: the fit asks {}): {} of the {} {kinds} bounce longer, up to {}, and a window a tap long lets the rest of their bounce through as false edges.",
                    time(c),
                    time(w.recommended()),
                    longer.len(),
                    d.len(),
                    time(longer.iter().copied().fold(0.0, f64::max))
                )
            }
            _ => String::new(),
        };
        out.push_str(&format!(
            "- {switch} {}: use {} ({what}, {} events); the same rule fitted on the earlier half ({}) {held}; {late_text}.{}{cap_text}\n",
            kind.name(),
            time(capped(w.recommended())),
            d.len(),
            time(capped(half.recommended())),
            w.reason().map_or_else(String::new, |r| format!(" Far beyond the capture: {r}.")),
        ));
    }
    out
}
