//! The files of a run written as the run goes: a [`WaveformSink`] that formats every row into
//! each requested CSV and VCD as it is accepted (through a 64 KiB buffer per file) and keeps
//! the plot's bounded copy ([`Decimator`]), so that memory does not grow with the run.
//!
//! Each file is written to a temporary beside its target ([`super::atomic::temp_path`]) and
//! renamed over it by [`Streams::finish`], as `atomic` does for a whole file: a target is
//! either the complete new file or the old one. A run that ends early is finished with a
//! note ("interrupted at t = 2.5 s"): a last `# partial: ...` line in CSV, a `$comment` in
//! the VCD's header (the dump is copied once behind it), the plot's title. A run that wrote
//! nothing is [abandoned](Streams::abandon), leaving the old files.
//!
//! Reads only the rows and columns handed to it; never the kernel's or the solver's state.

use std::fs::File;
use std::io::{self, BufReader, BufWriter};
use std::path::{Path, PathBuf};

use thiserror::Error;

use super::atomic::{commit, temp_path};
use super::csv::CsvWriter;
use super::decimate::Decimator;
use super::plot::{PlotError, plot_panels};
use super::vcd::{VcdWriter, copy_with_comment};
use super::waveplot::{layout, panels_of};
use vams_simulation::waveform::{Column, Header, SinkError, WaveformSink};

/// Bytes buffered per file between the run and the disk.
const BUFFER: usize = 1 << 16;

/// What to write.
#[derive(Clone, Debug, Default)]
pub struct Request {
    /// Waveform files, `.csv` or `.vcd` by extension.
    pub outputs: Vec<PathBuf>,
    /// The plot (`.svg` or `.png`) and its layout.
    pub plot: Option<PlotRequest>,
    /// The top entity: the VCD's outermost scope.
    pub top: String,
}

/// A plot and its panels, chosen when the columns are known ([`layout`]).
#[derive(Clone, Debug, Default)]
pub struct PlotRequest {
    pub path: PathBuf,
    /// `--panel` groups of names.
    pub panels: Vec<Vec<String>>,
    /// The testbench's `-- vams: panel` groups.
    pub file_panels: Vec<Vec<String>>,
}

/// Why the files of a run could not be written.
#[derive(Debug, Error)]
pub enum StreamError {
    #[error("cannot write `{}`: {source}", path.display())]
    Write { path: PathBuf, source: io::Error },
    /// A `--panel` name that is not a recorded column.
    #[error("no recorded quantity or signal named `{name}`")]
    UnknownPanel { name: String, recorded: String },
    #[error(transparent)]
    Plot(#[from] PlotError),
}

enum Writer {
    /// Created, waiting for the columns.
    Open(File),
    Csv(CsvWriter<BufWriter<File>>),
    Vcd(VcdWriter<BufWriter<File>>),
    /// Finished, or failed.
    Closed,
}

struct Stream {
    path: PathBuf,
    temp: PathBuf,
    writer: Writer,
}

struct PlotStream {
    path: PathBuf,
    temp: PathBuf,
    panels: Vec<Vec<String>>,
    file_panels: Vec<Vec<String>>,
    /// Panels as column indices, and the copy of the columns they draw.
    groups: Vec<Vec<usize>>,
    copy: Option<Decimator>,
}

/// The sink of `vams run`: see the module's header.
pub struct Streams {
    files: Vec<Stream>,
    plot: Option<PlotStream>,
    top: String,
    columns: Vec<Column>,
    rows: usize,
    last: Option<f64>,
    /// The first failure, kept for the owner (the kernel is only told to stop).
    failure: Option<StreamError>,
}

fn is_vcd(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("vcd"))
}

fn write_error(path: &Path) -> impl FnOnce(io::Error) -> StreamError + '_ {
    move |source| StreamError::Write {
        path: path.to_path_buf(),
        source,
    }
}

impl Streams {
    /// Creates every temporary file (the plot's is created and removed again, since the
    /// plotting backend writes it at the end): a path that cannot be written fails here,
    /// before the run.
    pub fn create(request: &Request) -> Result<Streams, StreamError> {
        let mut streams = Streams {
            files: Vec::new(),
            plot: None,
            top: request.top.clone(),
            columns: Vec::new(),
            rows: 0,
            last: None,
            failure: None,
        };
        for (k, path) in request.outputs.iter().enumerate() {
            // A path given twice is written once (both would write one temporary).
            if request.outputs[..k].contains(path) {
                continue;
            }
            let temp = temp_path(path);
            let file = File::create(&temp).map_err(write_error(path))?;
            streams.files.push(Stream {
                path: path.clone(),
                temp,
                writer: Writer::Open(file),
            });
        }
        if let Some(plot) = &request.plot {
            let temp = temp_path(&plot.path);
            File::create(&temp).map_err(write_error(&plot.path))?;
            let _ = std::fs::remove_file(&temp);
            streams.plot = Some(PlotStream {
                path: plot.path.clone(),
                temp,
                panels: plot.panels.clone(),
                file_panels: plot.file_panels.clone(),
                groups: Vec::new(),
                copy: None,
            });
        }
        Ok(streams)
    }

    /// The temporary files, for removal by a process that exits at once (a second Ctrl-C).
    pub fn temporaries(&self) -> Vec<PathBuf> {
        let files = self.files.iter().map(|f| f.temp.clone());
        files
            .chain(self.plot.iter().map(|p| p.temp.clone()))
            .collect()
    }

    /// Rows received so far.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The time of the last row.
    pub fn last_time(&self) -> Option<f64> {
        self.last
    }

    /// Why the sink stopped taking rows, if it did.
    pub fn take_failure(&mut self) -> Option<StreamError> {
        self.failure.take()
    }

    fn fail(&mut self, error: StreamError) -> SinkError {
        let message = error.to_string();
        self.failure.get_or_insert(error);
        SinkError(message)
    }

    /// Closes every file and moves it over its target, then draws the plot: `partial` (why
    /// the run ended early, "interrupted at t = 2.5 s") marks each file as partial, `title`
    /// is the plot's. Returns the paths written. On an error the remaining temporaries are
    /// removed and the targets not yet written keep their old content.
    pub fn finish(
        &mut self,
        partial: Option<&str>,
        title: &str,
    ) -> Result<Vec<PathBuf>, StreamError> {
        let written = self.finish_files(partial, title);
        self.abandon();
        written
    }

    fn finish_files(
        &mut self,
        partial: Option<&str>,
        title: &str,
    ) -> Result<Vec<PathBuf>, StreamError> {
        let note = partial.map(|p| format!("partial: {p}"));
        let mut written = Vec::new();
        for stream in &mut self.files {
            let path = &stream.path;
            let out = match std::mem::replace(&mut stream.writer, Writer::Closed) {
                Writer::Csv(w) => w.finish(note.as_deref()),
                Writer::Vcd(w) => w.finish(),
                // Never started: the sink saw no columns (a run stopped before time 0).
                Writer::Open(_) | Writer::Closed => continue,
            };
            // The file is closed at the end of this: synced, then dropped.
            out.and_then(|w| w.into_inner().map_err(|e| e.into_error()))
                .and_then(|f| f.sync_all())
                .map_err(write_error(path))?;
            if let (Some(n), true) = (&note, is_vcd(path)) {
                // The comment belongs in the header, written before the run knew its end.
                let marked = temp_path(&path.with_extension("marked.vcd"));
                mark_vcd(&stream.temp, &marked, n).map_err(write_error(path))?;
                std::fs::rename(&marked, &stream.temp)
                    .inspect_err(|_| {
                        let _ = std::fs::remove_file(&marked);
                    })
                    .map_err(write_error(path))?;
            }
            commit(&stream.temp, path).map_err(write_error(path))?;
            written.push(path.clone());
        }
        if let Some(plot) = &self.plot
            && let Some(copy) = &plot.copy
        {
            // The copy keeps the plotted columns in the order of `keep`.
            let keep = plotted(&plot.groups);
            let points = |c: usize| match keep.iter().position(|&k| k == c) {
                Some(k) => copy.points(k),
                None => Vec::new(),
            };
            let panels = panels_of(&self.columns, &points, &plot.groups);
            plot_panels(&plot.temp, title, &panels)?;
            commit(&plot.temp, &plot.path).map_err(write_error(&plot.path))?;
            written.push(plot.path.clone());
        }
        Ok(written)
    }

    /// Removes every temporary left: the targets keep their old content.
    pub fn abandon(&mut self) {
        for stream in &mut self.files {
            stream.writer = Writer::Closed;
            let _ = std::fs::remove_file(&stream.temp);
        }
        if let Some(plot) = &self.plot {
            let _ = std::fs::remove_file(&plot.temp);
        }
    }
}

impl Drop for Streams {
    fn drop(&mut self) {
        self.abandon();
    }
}

/// The columns the panels draw, each once, in first-seen order.
fn plotted(groups: &[Vec<usize>]) -> Vec<usize> {
    let mut keep: Vec<usize> = Vec::new();
    for &c in groups.iter().flatten() {
        if !keep.contains(&c) {
            keep.push(c);
        }
    }
    keep
}

/// `from` copied to `to` with the partial run's `$comment`.
fn mark_vcd(from: &Path, to: &Path, note: &str) -> io::Result<()> {
    let source = BufReader::with_capacity(BUFFER, File::open(from)?);
    let mut out = BufWriter::with_capacity(BUFFER, File::create(to)?);
    copy_with_comment(source, &mut out, note)?;
    out.into_inner().map_err(|e| e.into_error())?.sync_all()
}

impl WaveformSink for Streams {
    fn start(&mut self, header: &Header) -> Result<(), SinkError> {
        self.columns = header.columns.clone();
        let mut failed = None;
        for stream in &mut self.files {
            let Writer::Open(file) = std::mem::replace(&mut stream.writer, Writer::Closed) else {
                continue;
            };
            let out = BufWriter::with_capacity(BUFFER, file);
            let columns = &header.columns;
            let writer = if is_vcd(&stream.path) {
                VcdWriter::new(out, columns, &self.top, None, header.stop).map(Writer::Vcd)
            } else {
                CsvWriter::new(out, columns).map(Writer::Csv)
            };
            match writer {
                Ok(w) => stream.writer = w,
                Err(e) => {
                    failed = Some(write_error(&stream.path)(e));
                    break;
                }
            }
        }
        if let Some(e) = failed {
            return Err(self.fail(e));
        }
        if let Some(plot) = &mut self.plot {
            match layout(&header.columns, &plot.panels, &plot.file_panels) {
                Ok(groups) => {
                    plot.copy = Some(Decimator::new(plotted(&groups)));
                    plot.groups = groups;
                }
                Err(name) => {
                    let recorded: Vec<&str> =
                        header.columns.iter().map(|c| c.name.as_str()).collect();
                    let error = StreamError::UnknownPanel {
                        name,
                        recorded: recorded.join(", "),
                    };
                    return Err(self.fail(error));
                }
            }
        }
        Ok(())
    }

    fn wants_rows(&self) -> bool {
        !self.files.is_empty() || self.plot.is_some()
    }

    fn row(&mut self, time: f64, values: &[f64]) -> Result<(), SinkError> {
        self.rows += 1;
        self.last = Some(time);
        let mut failed = None;
        for stream in &mut self.files {
            let written = match &mut stream.writer {
                Writer::Csv(w) => w.row(time, values.iter().copied()),
                Writer::Vcd(w) => w.row(time, values.iter().copied()),
                Writer::Open(_) | Writer::Closed => Ok(()),
            };
            if let Err(e) = written {
                failed = Some(write_error(&stream.path)(e));
                break;
            }
        }
        if let Some(e) = failed {
            return Err(self.fail(e));
        }
        if let Some(copy) = self.plot.as_mut().and_then(|p| p.copy.as_mut()) {
            copy.push(time, values);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::csv::tests::synthetic;
    use crate::output::csv::write_csv;
    use crate::output::vcd::write_vcd;
    use vams_simulation::waveform::Waveforms;

    /// Streams `wf` through a sink created for `request`, then finishes it.
    fn stream(
        request: &Request,
        wf: &Waveforms,
        partial: Option<&str>,
    ) -> Result<Vec<PathBuf>, StreamError> {
        let mut sink = Streams::create(request)?;
        let header = Header {
            columns: wf
                .columns
                .iter()
                .map(|c| Column {
                    values: vec![],
                    ..c.clone()
                })
                .collect(),
            stop: *wf.times.last().unwrap(),
        };
        if sink.start(&header).is_err() {
            return Err(sink.take_failure().unwrap());
        }
        for (k, &t) in wf.times.iter().enumerate() {
            let row: Vec<f64> = wf.columns.iter().map(|c| c.values[k]).collect();
            sink.row(t, &row).unwrap();
        }
        sink.finish(partial, "tb (stop 1 s)")
    }

    #[test]
    fn streamed_files_are_what_the_whole_record_writes() {
        let dir = tempfile::tempdir().unwrap();
        let path = |name: &str| dir.path().join(name);
        let wf = synthetic();
        let request = Request {
            outputs: vec![path("w.csv"), path("w.vcd")],
            plot: Some(PlotRequest {
                path: path("w.svg"),
                ..PlotRequest::default()
            }),
            top: "tb".into(),
        };
        let written = stream(&request, &wf, None).unwrap();
        assert_eq!(written, [path("w.csv"), path("w.vcd"), path("w.svg")]);
        let mut csv = Vec::new();
        write_csv(&mut csv, &wf).unwrap();
        assert_eq!(std::fs::read(path("w.csv")).unwrap(), csv);
        let mut vcd = Vec::new();
        write_vcd(&mut vcd, &wf, "tb", None).unwrap();
        assert_eq!(std::fs::read(path("w.vcd")).unwrap(), vcd);
        assert!(
            std::fs::read_to_string(path("w.svg"))
                .unwrap()
                .contains("tb (stop 1 s)")
        );
        // Only the three targets: no temporary left behind.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3);

        // A partial run: the CSV's last line and the VCD's header comment say so.
        let note = "interrupted at t = 333.333 ms";
        stream(&request, &wf, Some(note)).unwrap();
        let text = std::fs::read_to_string(path("w.csv")).unwrap();
        assert_eq!(
            text.lines().last(),
            Some("# partial: interrupted at t = 333.333 ms")
        );
        let mut vcd = Vec::new();
        write_vcd(&mut vcd, &wf, "tb", Some(&format!("partial: {note}"))).unwrap();
        assert_eq!(std::fs::read(path("w.vcd")).unwrap(), vcd);
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 3);
    }

    #[test]
    fn an_unknown_panel_name_stops_at_the_start_and_keeps_the_old_files() {
        let dir = tempfile::tempdir().unwrap();
        let (csv, svg) = (dir.path().join("w.csv"), dir.path().join("w.svg"));
        std::fs::write(&csv, "old").unwrap();
        std::fs::write(&svg, "old").unwrap();
        let request = Request {
            outputs: vec![csv.clone()],
            plot: Some(PlotRequest {
                path: svg.clone(),
                panels: vec![vec!["vot".into()]],
                file_panels: vec![],
            }),
            top: "tb".into(),
        };
        let err = stream(&request, &synthetic(), None).unwrap_err();
        let StreamError::UnknownPanel { name, recorded } = err else {
            panic!("{err:?}");
        };
        assert_eq!(name, "vot");
        assert!(recorded.starts_with("vout, dut.u_ic.ov"), "{recorded}");
        assert_eq!(std::fs::read_to_string(&csv).unwrap(), "old");
        assert_eq!(std::fs::read_to_string(&svg).unwrap(), "old");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
    }

    #[test]
    fn a_path_that_cannot_be_written_fails_on_creation() {
        let dir = tempfile::tempdir().unwrap();
        let request = Request {
            outputs: vec![dir.path().join("no/dir/w.csv")],
            ..Request::default()
        };
        let err = Streams::create(&request).err().unwrap();
        assert!(err.to_string().contains("cannot write"), "{err}");
    }
}
