//! The table mode's pass over a scene file: every entry parsed, checked and analysed, in
//! blocks spread over threads, into a [`Spool`] in file order. A scene file of a million lines
//! is read a block at a time (the next block is read, and the last one's results stored, while
//! the threads work on this one), so memory does not grow with the file.

use std::collections::HashMap;

use crate::render::output::{identifier, window_ns, Format, Layout};
use crate::render::spool::Spool;
use crate::scene::file::{check, Entries, FileError, Raw};
use crate::scene::input::FieldError;
use crate::stats::analysis::{analyse, Analysis, Settings};

/// Entries per block.
const BLOCK: usize = 4096;

/// What the pass learns of one entry, on any thread.
enum Outcome {
    /// It does not parse, or its scene is invalid.
    Invalid(FileError),
    /// Its analysis failed.
    Failed(FileError),
    /// Its analysis (named as the entry), and its cells' widths in the terminal table.
    Analysed(Analysis, Option<Layout>),
    /// Only checked: the file already has an invalid entry, so nothing is analysed.
    Valid,
}

fn outcome(raw: &Raw, settings: &Settings, analyse_it: bool, table: bool) -> Outcome {
    let entry = match raw.entry() {
        Ok(e) => e,
        Err(e) => return Outcome::Invalid(e),
    };
    let fault = |e: FieldError| FileError {
        file: raw.file().to_owned(),
        place: format!("entry {} ({})", raw.index() + 1, entry.name),
        field: e.field,
        message: e.message,
    };
    if !analyse_it {
        return check(&entry).map_or_else(|e| Outcome::Invalid(fault(e)), |()| Outcome::Valid);
    }
    match analyse(&entry.name, &entry.template, settings) {
        Ok(a) => {
            let layout = table.then(|| Layout::of(&a, settings));
            Outcome::Analysed(a, layout)
        }
        // The analysis checks the scene first: its fault is either kind.
        Err(e) => match check(&entry) {
            Err(invalid) => Outcome::Invalid(fault(invalid)),
            Ok(()) => Outcome::Failed(fault(e)),
        },
    }
}

/// The outcomes taken in file order: faults reported, analyses stored.
struct Store<'a> {
    spool: Spool,
    layout: Layout,
    /// Generated code: each identifier, and the first name that became it.
    identifiers: HashMap<String, String>,
    generated: bool,
    invalid: bool,
    failed: bool,
    source: &'a str,
    report: &'a mut dyn FnMut(String),
    /// Faults found so far.
    faults: usize,
}

/// Faults reported one by one; beyond these, only counted (a file of a million bad lines
/// should not print a million messages).
const REPORTED: usize = 100;

impl Store<'_> {
    /// Reports a fault, or counts it past [`REPORTED`].
    fn fault(&mut self, message: String) {
        self.faults += 1;
        if self.faults <= REPORTED {
            (self.report)(message);
        }
    }

    /// Takes a block's outcomes; `Err` if the spool cannot be written (reported).
    fn take(&mut self, outcomes: Vec<Outcome>) -> Result<(), ()> {
        for o in outcomes {
            match o {
                Outcome::Valid => {}
                Outcome::Invalid(e) => {
                    self.fault(e.to_string());
                    self.invalid = true;
                }
                Outcome::Failed(e) => {
                    self.fault(e.to_string());
                    self.failed = true;
                }
                Outcome::Analysed(a, cells) => {
                    if self.invalid {
                        continue;
                    }
                    if self.generated {
                        self.name_in_code(&a);
                    }
                    if let Some(w) = &a.warning {
                        // Not a fault: the window is written, with this beside it.
                        (self.report)(format!("{}: {}: warning: {w}", self.source, a.name));
                    }
                    if let Some(cells) = cells {
                        self.layout.fit(cells);
                    }
                    if !self.failed {
                        if let Err(e) = self.spool.push(&a) {
                            self.fault(format!("a temporary file for the results: {e}"));
                            return Err(());
                        }
                    }
                }
            }
        }
        Ok(())
    }

    /// Generated code: the window must have a nanosecond form, and the identifier be new.
    fn name_in_code(&mut self, a: &Analysis) {
        let source = self.source;
        if window_ns(a.window).is_none() {
            self.fault(format!(
                "{source}: {}: its window, {:e} s, is beyond a 64-bit count of nanoseconds: generated code cannot hold it",
                a.name, a.window
            ));
            self.failed = true;
        }
        let id = identifier(&a.name);
        if let Some(first) = self.identifiers.get(&id) {
            self.fault(format!(
                "{source}: switches '{first}' and '{}' both become {id} in generated code: rename one",
                a.name
            ));
            self.failed = true;
        } else {
            self.identifiers.insert(id, a.name.clone());
        }
    }
}

/// Analyses every entry into a spool, in file order, and fits the terminal table's layout.
/// Every fault goes to `report` (a message naming the file, the entry and the field; past 100,
/// only their count): a file
/// with an invalid entry is checked to its end but no more analysed; in generated code, a
/// window with no nanosecond form and two names with one identifier are faults. `None` if
/// there was any fault, or no entry at all.
pub fn analyse_all(
    mut entries: Entries,
    settings: &Settings,
    format: Format,
    source: &str,
    report: &mut dyn FnMut(String),
) -> Option<(Spool, Layout)> {
    let mut store = Store {
        spool: Spool::new(),
        layout: Layout::default(),
        identifiers: HashMap::new(),
        generated: matches!(format, Format::C | Format::Rust),
        invalid: false,
        failed: false,
        source,
        report,
        faults: 0,
    };
    let table = format == Format::Table;
    let mut read = || -> Vec<Raw> {
        std::iter::from_fn(|| entries.next_raw())
            .take(BLOCK)
            .collect()
    };
    let (mut block, mut pending, mut seen) = (read(), Vec::new(), 0_usize);
    while !block.is_empty() {
        seen += block.len();
        // Entries after an invalid one are only checked (known a block late: the previous
        // block is stored while this one is worked on).
        let analyse_them = !store.invalid;
        // Threads over entries where there are many (at least 64 a thread), else over each
        // entry's Monte Carlo samples: never both (the answer is the same either way).
        let workers = settings.threads.clamp(1, block.len().div_ceil(64));
        let inner = Settings {
            threads: if workers > 1 { 1 } else { settings.threads },
            // One progress bar per switch, from several threads at once, would be noise.
            progress: settings.progress && workers == 1,
            ..*settings
        };
        let share = block.len().div_ceil(workers);
        let part = |k: usize| -> Vec<Outcome> {
            block
                .iter()
                .skip(k * share)
                .take(share)
                .map(|raw| outcome(raw, &inner, analyse_them, table))
                .collect()
        };
        let (parts, (stored, next)) = crate::support::workers::each_while(workers, &part, || {
            (store.take(std::mem::take(&mut pending)), read())
        });
        stored.ok()?;
        pending = parts.into_iter().flatten().collect();
        block = next;
    }
    store.take(pending).ok()?;
    if store.faults > REPORTED {
        let more = store.faults - REPORTED;
        (store.report)(format!("{source}: {more} more faults not shown"));
    }
    if seen == 0 {
        (store.report)(format!("{source}: no switches in the file"));
        return None;
    }
    (!store.invalid && !store.failed).then_some((store.spool, store.layout))
}
