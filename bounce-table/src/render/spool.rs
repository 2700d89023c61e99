//! The analyses of a long scene file, kept on disk instead of in memory: a table of a million
//! switches is laid out (its column widths need every row) and written only once every switch
//! is analysed, in memory that does not grow with the file.
//!
//! The file is private to the run: on Unix it is unlinked as soon as it is created (the open
//! handle keeps it), elsewhere it is removed when the spool is dropped. Where the temporary
//! directory refuses a file, the records stay in memory (compact: about 100 bytes a switch). Numbers are stored as
//! their bits, so every value, infinities included, reads back exactly.

use std::borrow::Cow;
use std::fs::File;
use std::io::{self, BufReader, BufWriter, Read, Seek, SeekFrom, Write};
use std::path::PathBuf;

use crate::stats::analysis::{Analysis, BounceEstimate, MonteCarlo, Sensitivity};

/// Analyses written once and read back any number of times, in order.
pub struct Spool {
    backing: Backing,
    /// The path to remove on drop where it could not be unlinked at once.
    path: Option<PathBuf>,
    len: usize,
    /// Whether any analysis has sensitivities.
    sensitivity: bool,
    /// The static names (regimes, tiers) met so far: a record holds their index, and reads
    /// them back without an allocation.
    names: Vec<&'static str>,
    /// The record being written.
    scratch: Vec<u8>,
}

/// Where the records are.
enum Backing {
    /// A private temporary file.
    File(BufWriter<File>),
    /// Memory, where the temporary directory refused a file (a run must not fail for that).
    Memory(Vec<u8>),
}

impl Spool {
    /// A new, empty spool: a private file in the system's temporary directory, else memory
    /// (always memory in a browser).
    #[must_use]
    pub fn new() -> Self {
        use std::sync::atomic::{AtomicU64, Ordering};
        // WebAssembly in a browser (the page in web/) has no files, and its `temp_dir` and
        // process id panic.
        if cfg!(all(target_arch = "wasm32", target_os = "unknown")) {
            return Self::in_memory();
        }
        static NEXT: AtomicU64 = AtomicU64::new(0);
        let path = std::env::temp_dir().join(format!(
            "bounce-table-spool-{}-{}",
            std::process::id(),
            NEXT.fetch_add(1, Ordering::Relaxed)
        ));
        let Ok(file) = std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .create_new(true)
            .open(&path)
        else {
            return Self::in_memory();
        };
        let path = if cfg!(unix) && std::fs::remove_file(&path).is_ok() {
            None
        } else {
            Some(path)
        };
        Self {
            backing: Backing::File(BufWriter::new(file)),
            path,
            len: 0,
            sensitivity: false,
            names: Vec::new(),
            scratch: Vec::new(),
        }
    }

    /// A new, empty spool in memory.
    #[must_use]
    pub fn in_memory() -> Self {
        Self {
            backing: Backing::Memory(Vec::new()),
            path: None,
            len: 0,
            sensitivity: false,
            names: Vec::new(),
            scratch: Vec::new(),
        }
    }

    /// How many analyses it holds.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when any analysis it holds has sensitivities.
    #[must_use]
    pub fn any_sensitivity(&self) -> bool {
        self.sensitivity
    }

    /// True when it holds none.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends one analysis.
    ///
    /// # Errors
    /// The write fails (a full disk).
    pub fn push(&mut self, a: &Analysis) -> io::Result<()> {
        // The record is written whole behind its length, so that reading it back is one copy
        // and the decoding works on a slice.
        let mut w = std::mem::take(&mut self.scratch);
        w.clear();
        text(&mut w, &a.name)?;
        self.name(&mut w, &a.nominal.regime)?;
        self.name(&mut w, &a.nominal.tier)?;
        for x in [
            a.nominal.bounce,
            a.nominal.upper,
            a.nominal.expected_error,
            a.window,
        ] {
            number(&mut w, x)?;
        }
        optional(&mut w, a.nominal.impacts)?;
        w.write_all(&a.ticks.to_le_bytes())?;
        match &a.monte_carlo {
            None => w.write_all(&[0])?,
            Some(m) => {
                w.write_all(&[1])?;
                w.write_all(&m.samples.to_le_bytes())?;
                w.write_all(&m.exact.to_le_bytes())?;
                for x in [m.p50, m.window, m.max] {
                    number(&mut w, x)?;
                }
            }
        }
        w.write_all(
            &u64::try_from(a.sensitivity.len())
                .unwrap_or(u64::MAX)
                .to_le_bytes(),
        )?;
        for s in &a.sensitivity {
            text(&mut w, &s.parameter)?;
            number(&mut w, s.elasticity)?;
            number(&mut w, s.contribution)?;
        }
        match &a.warning {
            None => w.write_all(&[0])?,
            Some(t) => {
                w.write_all(&[1])?;
                text(&mut w, t)?;
            }
        }
        let length = u32::try_from(w.len())
            .map_err(|_| io::Error::new(io::ErrorKind::InvalidInput, "spool: a record too long"))?;
        let out: &mut dyn Write = match &mut self.backing {
            Backing::File(f) => f,
            Backing::Memory(v) => v,
        };
        out.write_all(&length.to_le_bytes())?;
        out.write_all(&w)?;
        self.scratch = w;
        self.len += 1;
        self.sensitivity |= !a.sensitivity.is_empty();
        Ok(())
    }

    /// A regime's or tier's name: its index among the static names met so far (at most 255),
    /// else its text.
    #[allow(clippy::ptr_arg)] // whether the name is static is the point
    fn name(&mut self, w: &mut Vec<u8>, name: &Cow<'static, str>) -> io::Result<()> {
        if let Cow::Borrowed(s) = name {
            let index = match self.names.iter().position(|n| n == s) {
                Some(i) => Some(i),
                None if self.names.len() < 255 => {
                    self.names.push(s);
                    Some(self.names.len() - 1)
                }
                None => None,
            };
            if let Some(i) = index.and_then(|i| u8::try_from(i).ok()) {
                return w.write_all(&[1, i]);
            }
        }
        w.write_all(&[0])?;
        text(w, name)
    }

    /// Every analysis, in the order pushed. The spool can be read again afterwards.
    ///
    /// # Errors
    /// The file cannot be flushed or rewound.
    pub fn rows(&mut self) -> io::Result<Rows<'_>> {
        let reader = match &mut self.backing {
            Backing::File(f) => {
                f.flush()?;
                let file = f.get_mut();
                file.seek(SeekFrom::Start(0))?;
                Reader::File(BufReader::new(file))
            }
            Backing::Memory(v) => Reader::Memory(v.as_slice()),
        };
        Ok(Rows {
            reader,
            left: self.len,
            record: Vec::new(),
            names: &self.names,
        })
    }
}

impl Default for Spool {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for Spool {
    fn drop(&mut self) {
        if let Some(path) = &self.path {
            let _ = std::fs::remove_file(path);
        }
    }
}

/// The analyses of a [`Spool`], read back.
pub struct Rows<'a> {
    reader: Reader<'a>,
    left: usize,
    /// The record being read (from a file).
    record: Vec<u8>,
    names: &'a [&'static str],
}

/// Where the records are read from: each its own type, so that a record's small reads are
/// copies from a buffer, not calls through a trait object (a million records are 20 million
/// reads).
enum Reader<'a> {
    File(BufReader<&'a mut File>),
    Memory(&'a [u8]),
}

/// Records read whole but not decoded: a block that threads decode (and render) in parallel,
/// while the next block is read.
pub struct Records<'a> {
    bytes: Vec<u8>,
    /// Where each record ends in `bytes`.
    ends: Vec<usize>,
    names: &'a [&'static str],
}

impl Records<'_> {
    /// How many records it holds.
    #[must_use]
    pub fn len(&self) -> usize {
        self.ends.len()
    }

    /// True when it holds none.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }

    /// Record `i`, decoded.
    ///
    /// # Errors
    /// `i` is beyond the block, or the record is malformed.
    pub fn get(&self, i: usize) -> io::Result<Analysis> {
        let start = match i.checked_sub(1) {
            Some(before) => self.ends.get(before).copied(),
            None => Some(0),
        };
        let record = start
            .zip(self.ends.get(i).copied())
            .and_then(|(start, end)| self.bytes.get(start..end))
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "spool: no such record"))?;
        read_analysis(&mut &record[..], self.names)
    }
}

impl<'a> Rows<'a> {
    /// The next `n` records (fewer at the end), read but not decoded.
    ///
    /// # Errors
    /// The spool cannot be read.
    pub fn next_records(&mut self, n: usize) -> io::Result<Records<'a>> {
        let mut block = Records {
            bytes: Vec::new(),
            ends: Vec::new(),
            names: self.names,
        };
        while block.ends.len() < n && self.left > 0 {
            self.left -= 1;
            match &mut self.reader {
                Reader::File(r) => read_record(r, &mut self.record)?,
                Reader::Memory(r) => read_record(r, &mut self.record)?,
            }
            block.bytes.extend_from_slice(&self.record);
            block.ends.push(block.bytes.len());
        }
        Ok(block)
    }
}

impl Iterator for Rows<'_> {
    type Item = io::Result<Analysis>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let names = self.names;
        Some(match &mut self.reader {
            Reader::File(r) => read_record(r, &mut self.record)
                .and_then(|()| read_analysis(&mut self.record.as_slice(), names)),
            Reader::Memory(r) => read_record(r, &mut self.record)
                .and_then(|()| read_analysis(&mut self.record.as_slice(), names)),
        })
    }
}

fn text(w: &mut (impl Write + ?Sized), s: &str) -> io::Result<()> {
    w.write_all(&u64::try_from(s.len()).unwrap_or(u64::MAX).to_le_bytes())?;
    w.write_all(s.as_bytes())
}

fn number(w: &mut (impl Write + ?Sized), x: f64) -> io::Result<()> {
    w.write_all(&x.to_bits().to_le_bytes())
}

fn optional(w: &mut (impl Write + ?Sized), x: Option<f64>) -> io::Result<()> {
    match x {
        None => w.write_all(&[0]),
        Some(x) => {
            w.write_all(&[1])?;
            number(w, x)
        }
    }
}

fn bytes<const N: usize>(r: &mut impl Read) -> io::Result<[u8; N]> {
    let mut b = [0; N];
    r.read_exact(&mut b)?;
    Ok(b)
}

fn read_u64(r: &mut impl Read) -> io::Result<u64> {
    Ok(u64::from_le_bytes(bytes(r)?))
}

fn read_number(r: &mut impl Read) -> io::Result<f64> {
    Ok(f64::from_bits(read_u64(r)?))
}

fn read_flag(r: &mut impl Read) -> io::Result<bool> {
    Ok(bytes::<1>(r)? != [0])
}

fn read_text(r: &mut impl Read) -> io::Result<String> {
    let len = usize::try_from(read_u64(r)?)
        .map_err(|_| io::Error::new(io::ErrorKind::InvalidData, "spool: a text too long"))?;
    let mut v = vec![0; len];
    r.read_exact(&mut v)?;
    String::from_utf8(v).map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))
}

/// The next record's bytes, behind their length, into `record`.
fn read_record(r: &mut impl Read, record: &mut Vec<u8>) -> io::Result<()> {
    let length = usize::try_from(u32::from_le_bytes(bytes(r)?))
        .map_err(|_| io::Error::new(io::ErrorKind::InvalidData, "spool: a record too long"))?;
    record.resize(length, 0);
    r.read_exact(record)
}

/// A name written by [`Spool::name`].
fn read_name(r: &mut impl Read, names: &[&'static str]) -> io::Result<Cow<'static, str>> {
    if read_flag(r)? {
        let [i] = bytes(r)?;
        names
            .get(usize::from(i))
            .map(|n| Cow::Borrowed(*n))
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidData, "spool: an unknown name"))
    } else {
        read_text(r).map(Cow::Owned)
    }
}

fn read_analysis(r: &mut impl Read, names: &[&'static str]) -> io::Result<Analysis> {
    let name = read_text(r)?;
    let regime = read_name(r, names)?;
    let tier = read_name(r, names)?;
    let [bounce, upper, expected_error, window] = [
        read_number(r)?,
        read_number(r)?,
        read_number(r)?,
        read_number(r)?,
    ];
    let impacts = if read_flag(r)? {
        Some(read_number(r)?)
    } else {
        None
    };
    let ticks = u32::from_le_bytes(bytes(r)?);
    let monte_carlo = if read_flag(r)? {
        let samples = read_u64(r)?;
        let exact = read_u64(r)?;
        Some(MonteCarlo {
            samples,
            exact,
            p50: read_number(r)?,
            window: read_number(r)?,
            max: read_number(r)?,
        })
    } else {
        None
    };
    let n = read_u64(r)?;
    let mut sensitivity = Vec::new();
    for _ in 0..n {
        sensitivity.push(Sensitivity {
            parameter: read_text(r)?,
            elasticity: read_number(r)?,
            contribution: read_number(r)?,
        });
    }
    let warning = if read_flag(r)? {
        Some(read_text(r)?)
    } else {
        None
    };
    Ok(Analysis {
        name,
        nominal: BounceEstimate {
            bounce,
            upper,
            regime,
            impacts,
            tier,
            expected_error,
        },
        window,
        ticks,
        monte_carlo,
        sensitivity,
        warning,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn analysis(name: &str, with_spread: bool) -> Analysis {
        Analysis {
            name: name.to_owned(),
            nominal: BounceEstimate {
                bounce: 1.5e-4,
                upper: f64::INFINITY,
                regime: "zeno_accumulation".into(),
                impacts: with_spread.then_some(13.0),
                // A static name is kept as its index, any other as its text.
                tier: if with_spread {
                    "map".into()
                } else {
                    Cow::Owned("a tier by name".to_owned())
                },
                expected_error: 0.004,
            },
            window: -0.0,
            ticks: u32::MAX,
            monte_carlo: with_spread.then_some(MonteCarlo {
                samples: 10_000,
                p50: 1e-4,
                window: 2e-4,
                max: f64::NAN,
                exact: 7,
            }),
            sensitivity: if with_spread {
                vec![Sensitivity {
                    parameter: "kernel.tau".to_owned(),
                    elasticity: -0.5,
                    contribution: 0.25,
                }]
            } else {
                Vec::new()
            },
            warning: with_spread.then(|| "the contacts do not stay closed".to_owned()),
        }
    }

    #[test]
    fn every_field_reads_back_bit_for_bit_and_twice() {
        let rows = [
            analysis("a\nswitch \u{0}with a \"name\"", true),
            analysis("", false),
        ];
        for mut spool in [Spool::new(), Spool::in_memory()] {
            for a in &rows {
                spool.push(a).expect("push");
            }
            assert_eq!(spool.len(), 2);
            for _ in 0..2 {
                let back: Vec<Analysis> = spool
                    .rows()
                    .expect("rows")
                    .map(|r| r.expect("row"))
                    .collect();
                assert_eq!(back.len(), 2);
                for (b, a) in back.iter().zip(&rows) {
                    // NaN != NaN: compare the debug form, which shows every field.
                    assert_eq!(format!("{b:?}"), format!("{a:?}"));
                    assert_eq!(b.window.to_bits(), a.window.to_bits());
                }
            }
            // The same records in blocks, decoded one by one (as the rendering threads do).
            let mut reader = spool.rows().expect("rows");
            let block = reader.next_records(5).expect("records");
            assert_eq!(block.len(), 2);
            for (i, a) in rows.iter().enumerate() {
                let b = block.get(i).expect("a record");
                assert_eq!(format!("{b:?}"), format!("{a:?}"));
            }
            assert!(block.get(2).is_err());
            assert!(reader.next_records(5).expect("the end").is_empty());
        }
    }
}
