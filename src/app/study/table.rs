//! The result table of a sweep: one CSV row per run (run id, case, parameter values, metric
//! values, pass/fail, status, message), written row by row as runs finish so that an
//! interrupted sweep keeps what it computed and resumes from it.
//!
//! The file starts with a comment line naming the spec, its fingerprint and the plan's size
//! (and the shard, for a shard's file): a resumed or collected sweep checks it against its
//! spec. Numbers are written with the shortest text that reads back exactly, so that a run's
//! row is the same text whatever machine, shard or order computed it, and merging the shards
//! gives the local run's file byte for byte.

use std::fs::{File, OpenOptions};
use std::io::{self, BufRead, BufReader, Write};
use std::path::{Path, PathBuf};

use thiserror::Error;

use crate::output::csv::format_number;

/// How a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Reached its stop time (its metrics may still fail their limits).
    Ok,
    /// Did not: elaboration error, solver failure, run-time error, assertion of severity
    /// failure. Its metrics are those the waveforms up to the failure gave.
    Failed,
}

impl Status {
    pub fn name(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Failed => "failed",
        }
    }
}

/// One run's row.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub index: usize,
    pub case: String,
    /// Parameter values as written (numbers in shortest form, or the literal).
    pub values: Vec<String>,
    /// Metric values; `None` where a metric could not be evaluated (its reason joins the
    /// message).
    pub metrics: Vec<Option<f64>>,
    /// All limits met; `None` without limits.
    pub pass: Option<bool>,
    pub status: Status,
    pub message: String,
}

/// What the comment line of a result file says.
#[derive(Clone, Debug, PartialEq)]
pub struct Identity {
    pub spec: String,
    pub fingerprint: u64,
    pub runs: u64,
    /// `(k, n)` for a shard's file.
    pub shard: Option<(usize, usize)>,
}

impl Identity {
    fn line(&self) -> String {
        let mut line = format!(
            "# vams sweep {} fingerprint={:016x} runs={}",
            self.spec, self.fingerprint, self.runs
        );
        if let Some((k, n)) = self.shard {
            line.push_str(&format!(" shard={k}/{n}"));
        }
        line
    }

    fn parse(line: &str) -> Option<Identity> {
        let rest = line.strip_prefix("# vams sweep ")?;
        // The spec's name may hold spaces: the fields are read from the right.
        let mut words: Vec<&str> = rest.split(' ').collect();
        let mut shard = None;
        if let Some(s) = words.last()?.strip_prefix("shard=") {
            let (k, n) = s.split_once('/')?;
            shard = Some((k.parse().ok()?, n.parse().ok()?));
            words.pop();
        }
        let runs = words.pop()?.strip_prefix("runs=")?.parse().ok()?;
        let fingerprint =
            u64::from_str_radix(words.pop()?.strip_prefix("fingerprint=")?, 16).ok()?;
        Some(Identity {
            spec: words.join(" "),
            fingerprint,
            runs,
            shard,
        })
    }
}

/// The table's header row.
pub fn header(parameters: &[String], metrics: &[String]) -> Vec<String> {
    let mut h = vec!["run".to_string(), "case".to_string()];
    h.extend(parameters.iter().cloned());
    h.extend(metrics.iter().cloned());
    h.extend(["pass", "status", "message"].map(String::from));
    h
}

fn cells(row: &Row) -> Vec<String> {
    let mut c = vec![row.index.to_string(), row.case.clone()];
    c.extend(row.values.iter().cloned());
    c.extend(
        row.metrics
            .iter()
            .map(|m| m.map(format_number).unwrap_or_default()),
    );
    c.push(match row.pass {
        Some(true) => "pass".into(),
        Some(false) => "fail".into(),
        None => String::new(),
    });
    c.push(row.status.name().into());
    c.push(row.message.clone());
    c
}

/// Problems with a result file.
#[derive(Debug, Error)]
pub enum TableError {
    #[error("cannot write `{}`: {source}", path.display())]
    Write { path: PathBuf, source: io::Error },
    #[error("cannot read `{}`: {source}", path.display())]
    Read { path: PathBuf, source: io::Error },
    #[error("`{}` is not a result file of this sweep: {why}", path.display())]
    Foreign { path: PathBuf, why: String },
    #[error("`{}` line {line}: {why}", path.display())]
    Malformed {
        path: PathBuf,
        line: usize,
        why: String,
    },
}

/// A result file being written, a row at a time (each row flushed, so a killed sweep keeps
/// every finished run).
pub struct TableWriter {
    path: PathBuf,
    out: csv::Writer<File>,
}

fn write_error(path: &Path) -> impl FnOnce(io::Error) -> TableError + '_ {
    move |source| TableError::Write {
        path: path.to_path_buf(),
        source,
    }
}

fn csv_error(path: &Path) -> impl Fn(csv::Error) -> TableError + '_ {
    move |e| TableError::Write {
        path: path.to_path_buf(),
        source: io::Error::other(e.to_string()),
    }
}

impl TableWriter {
    /// Starts `path` afresh with `rows` already done (a resumed sweep's), written through a
    /// temporary renamed over it, then kept open for appending.
    pub fn create(
        path: &Path,
        identity: &Identity,
        header: &[String],
        rows: &[Row],
    ) -> Result<TableWriter, TableError> {
        let temp = crate::output::atomic::temp_path(path);
        {
            let mut file = File::create(&temp).map_err(write_error(path))?;
            writeln!(file, "{}", identity.line()).map_err(write_error(path))?;
            let mut out = csv::Writer::from_writer(file);
            out.write_record(header).map_err(csv_error(path))?;
            for row in rows {
                out.write_record(cells(row)).map_err(csv_error(path))?;
            }
            out.flush().map_err(write_error(path))?;
        }
        crate::output::atomic::commit(&temp, path).map_err(write_error(path))?;
        let file = OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(write_error(path))?;
        Ok(TableWriter {
            path: path.to_path_buf(),
            out: csv::WriterBuilder::new()
                .has_headers(false)
                .from_writer(file),
        })
    }

    pub fn push(&mut self, row: &Row) -> Result<(), TableError> {
        self.out
            .write_record(cells(row))
            .map_err(csv_error(&self.path))?;
        self.out.flush().map_err(write_error(&self.path))
    }

    /// Ends the file with a comment saying why it is incomplete.
    pub fn finish_partial(mut self, why: &str) -> Result<(), TableError> {
        self.out.flush().map_err(write_error(&self.path))?;
        let mut file = self.out.into_inner().map_err(|e| TableError::Write {
            path: self.path.clone(),
            source: io::Error::other(e.to_string()),
        })?;
        writeln!(file, "# partial: {why}").map_err(write_error(&self.path))
    }
}

/// A result file read back.
#[derive(Debug)]
pub struct Table {
    pub identity: Identity,
    pub header: Vec<String>,
    pub rows: Vec<Row>,
    /// Its `# partial: ...` line, if any.
    pub partial: Option<String>,
}

/// Reads a result file; a last row cut short (a sweep killed while writing it) is dropped.
pub fn read_table(path: &Path) -> Result<Table, TableError> {
    let file = File::open(path).map_err(|source| TableError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let mut reader = BufReader::new(file);
    let mut first = String::new();
    reader
        .read_line(&mut first)
        .map_err(|source| TableError::Read {
            path: path.to_path_buf(),
            source,
        })?;
    let identity = Identity::parse(first.trim_end()).ok_or_else(|| TableError::Foreign {
        path: path.to_path_buf(),
        why: "its first line is not `# vams sweep ...`".into(),
    })?;
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut reader, &mut rest).map_err(|source| TableError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let partial = rest
        .lines()
        .rev()
        .find_map(|l| l.strip_prefix("# partial: "))
        .map(String::from);
    // A row cut short has no line end: drop it.
    let complete = match rest.rfind('\n') {
        Some(end) => &rest[..=end],
        None => "",
    };
    let mut csv = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .flexible(true)
        .from_reader(complete.as_bytes());
    let header: Vec<String> = csv
        .headers()
        .map_err(|e| malformed(path, 2, e.to_string()))?
        .iter()
        .map(String::from)
        .collect();
    if !is_result_header(&header) {
        return Err(TableError::Foreign {
            path: path.to_path_buf(),
            why: "its header is not `run,case,...,pass,status,message`".into(),
        });
    }
    let middle = header.len() - 5;
    let mut rows = Vec::new();
    for (k, record) in csv.records().enumerate() {
        let line = k + 3;
        let record = record.map_err(|e| malformed(path, line, e.to_string()))?;
        if record.len() != header.len() {
            return Err(malformed(
                path,
                line,
                format!("{} cells, the header has {}", record.len(), header.len()),
            ));
        }
        let cell = |i: usize| record.get(i).unwrap_or_default();
        let index = cell(0)
            .parse()
            .map_err(|_| malformed(path, line, "the run id is not a number".into()))?;
        let base = 2 + middle;
        rows.push(Row {
            index,
            case: cell(1).to_string(),
            // Parameters and metrics together until [`Table::resplit`].
            values: (0..middle).map(|p| cell(2 + p).to_string()).collect(),
            metrics: Vec::new(),
            pass: match cell(base) {
                "pass" => Some(true),
                "fail" => Some(false),
                _ => None,
            },
            status: if cell(base + 1) == "ok" {
                Status::Ok
            } else {
                Status::Failed
            },
            message: cell(base + 2).to_string(),
        });
    }
    Ok(Table {
        identity,
        header,
        rows,
        partial,
    })
}

fn malformed(path: &Path, line: usize, why: String) -> TableError {
    TableError::Malformed {
        path: path.to_path_buf(),
        line,
        why,
    }
}

/// `run,case,...,pass,status,message`.
fn is_result_header(header: &[String]) -> bool {
    let n = header.len();
    n >= 5
        && header[0] == "run"
        && header[1] == "case"
        && header[n - 3..] == ["pass", "status", "message"]
}

impl Table {
    /// Splits the cells between `case` and `pass` into `parameters` values and metrics,
    /// once the header is known to be the spec's (the file alone does not say where the
    /// parameters end).
    pub fn resplit(&mut self, parameters: usize) -> Result<(), String> {
        let middle = self.header.len() - 5;
        if parameters > middle {
            return Err("fewer columns than parameters".into());
        }
        for row in &mut self.rows {
            let all: Vec<String> = row.values.drain(..).collect();
            let (p, m) = all.split_at(parameters);
            row.values = p.to_vec();
            row.metrics = m
                .iter()
                .map(|t| {
                    if t.is_empty() {
                        Ok(None)
                    } else {
                        t.parse::<f64>()
                            .map(Some)
                            .map_err(|_| format!("`{t}` is not a number"))
                    }
                })
                .collect::<Result<_, _>>()?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(index: usize, m: Option<f64>) -> Row {
        Row {
            index,
            case: "sample".into(),
            values: vec!["4.5".into(), "1e-7".into()],
            metrics: vec![m, Some(0.1 + 0.2)],
            pass: m.map(|v| v < 1.0),
            status: if m.is_some() {
                Status::Ok
            } else {
                Status::Failed
            },
            message: if m.is_some() {
                String::new()
            } else {
                "no quiescent point, \"r\" too small\nsecond line".into()
            },
        }
    }

    #[test]
    fn rows_read_back_as_written_and_a_cut_row_is_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("results.csv");
        let id = Identity {
            spec: "my sweep.toml".into(),
            fingerprint: 0xdead_beef,
            runs: 10,
            shard: Some((2, 5)),
        };
        let head = header(&["r".into(), "l".into()], &["settle".into(), "peak".into()]);
        let mut w = TableWriter::create(&path, &id, &head, &[row(0, Some(0.5))]).unwrap();
        w.push(&row(1, None)).unwrap();
        w.push(&row(2, Some(2.0))).unwrap();
        w.finish_partial("interrupted after 3 runs").unwrap();
        let mut t = read_table(&path).unwrap();
        assert_eq!(t.identity, id);
        assert_eq!(t.header, head);
        t.resplit(2).unwrap();
        assert_eq!(t.rows, [row(0, Some(0.5)), row(1, None), row(2, Some(2.0))]);
        assert_eq!(t.partial.as_deref(), Some("interrupted after 3 runs"));
        // A row cut short by a kill is not read.
        let mut text = std::fs::read_to_string(&path).unwrap();
        text = text.replace("# partial: interrupted after 3 runs\n", "");
        text.push_str("3,sample,4.5,1e-7,0.");
        std::fs::write(&path, text).unwrap();
        let t = read_table(&path).unwrap();
        assert_eq!(t.rows.len(), 3);
        assert!(t.partial.is_none());
    }

    #[test]
    fn identity_lines_round_trip() {
        for id in [
            Identity {
                spec: "a.toml".into(),
                fingerprint: 1,
                runs: 1,
                shard: None,
            },
            Identity {
                spec: "dir with spaces/worst case.toml".into(),
                fingerprint: u64::MAX,
                runs: 123_456,
                shard: Some((11, 12)),
            },
        ] {
            assert_eq!(
                Identity::parse(&id.line()),
                Some(id.clone()),
                "{}",
                id.line()
            );
        }
        assert_eq!(Identity::parse("time,v"), None);
    }
}
