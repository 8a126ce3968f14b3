//! What processes reach beyond their variables and signals: the heap of objects that access
//! values designate (`new`, `.all`, `deallocate`), and the file objects (`std.textio` and the
//! implicit operations of file types). Both sit behind `RefCell`s in [`Io`], since
//! expressions (`new`, `endfile`) evaluate against a shared environment.

use std::cell::RefCell;
use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Write};

use vams_design::{FileMode, FileObject, Value};

use super::ops::EvalError;

/// The heap and the files of one simulation.
#[derive(Default)]
pub(crate) struct Io {
    pub heap: RefCell<Heap>,
    pub files: RefCell<Files>,
    /// Reports of functions (`report` and failed assertions of severity below failure),
    /// made inside an expression and told by the process that evaluated it.
    pub function_reports: RefCell<Vec<FunctionReport>>,
    /// The run's cancel flag (Ctrl-C, SIGTERM): long loops in processes and functions look
    /// at it every [`CANCEL_CHECK`] instructions, so that a stop does not wait for them.
    pub cancel: Option<super::Cancel>,
}

/// How many interpreted instructions run between two looks at the cancel flag.
pub(crate) const CANCEL_CHECK: usize = 1 << 16;

impl Io {
    /// `Err` when the run was cancelled (checked every [`CANCEL_CHECK`]-th `step`).
    pub fn check_cancel(&self, step: usize) -> Result<(), EvalError> {
        if step % CANCEL_CHECK == CANCEL_CHECK - 1
            && self
                .cancel
                .as_ref()
                .is_some_and(super::Cancel::is_cancelled)
        {
            return Err(EvalError::interrupted());
        }
        Ok(())
    }
}

/// A report a function made: the process that called it emits it with its own name.
#[derive(Debug)]
pub(crate) struct FunctionReport {
    pub severity: super::Severity,
    pub message: String,
    pub span: vams_syntax::source::Span,
}

/// Objects designated by access values: `Value::Access(h)` is `cells[h - 1]` (0 is
/// `null`). Freed cells are reused.
#[derive(Default)]
pub(crate) struct Heap {
    cells: Vec<Option<Value>>,
    free: Vec<u32>,
}

/// More objects than this alive at once is a model that allocates without freeing in a loop.
const HEAP_LIMIT: usize = 10_000_000;

fn null_access() -> EvalError {
    EvalError::new(
        "dereference of a null access value",
        "test the access value against `null` before using what it designates (LRM 7.3.6)",
    )
}

impl Heap {
    /// A new object holding `v`.
    pub fn alloc(&mut self, v: Value) -> Result<Value, EvalError> {
        if let Some(h) = self.free.pop() {
            self.cells[h as usize - 1] = Some(v);
            return Ok(Value::Access(h));
        }
        if self.cells.len() >= HEAP_LIMIT {
            return Err(EvalError::new(
                format!("more than {HEAP_LIMIT} objects allocated with `new` and not freed"),
                "call `deallocate` on objects that are no longer needed",
            ));
        }
        self.cells.push(Some(v));
        Ok(Value::Access(self.cells.len() as u32))
    }

    fn cell(&mut self, p: &Value) -> Result<&mut Option<Value>, EvalError> {
        match p {
            Value::Access(h) if *h > 0 => self
                .cells
                .get_mut(*h as usize - 1)
                .filter(|c| c.is_some())
                .ok_or_else(|| {
                    EvalError::new(
                        "access to an object that was deallocated",
                        "another access value designated the same object and freed it",
                    )
                }),
            Value::Access(_) => Err(null_access()),
            _ => Err(EvalError::new(
                "dereference of a value that is not an access value",
                "this is a bug in elaboration",
            )),
        }
    }

    /// The object `p` designates.
    pub fn get(&mut self, p: &Value) -> Result<&mut Value, EvalError> {
        // Invariant: `cell` returns only occupied cells.
        self.cell(p).map(|c| c.as_mut().expect("occupied cell"))
    }

    /// `deallocate(p)`: frees the object (nothing for `null`).
    pub fn free(&mut self, p: &Value) -> Result<(), EvalError> {
        if matches!(p, Value::Access(0)) {
            return Ok(());
        }
        *self.cell(p)? = None;
        if let Value::Access(h) = p {
            self.free.push(*h);
        }
        Ok(())
    }
}

/// The design's file objects, open or closed.
#[derive(Default)]
pub(crate) struct Files {
    open: Vec<Option<OpenFile>>,
    names: Vec<String>,
}

enum OpenFile {
    /// Lines still to read; `None` at the end.
    Reader(Box<dyn BufRead>, Option<String>),
    Writer(Box<dyn Write>),
}

/// `file_open_status` by position.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum OpenStatus {
    Ok = 0,
    StatusError = 1,
    NameError = 2,
}

impl Files {
    /// The design's files, those declared with a name opened (LRM 4.3.1.4).
    pub fn new(files: &[FileObject]) -> Result<Files, (usize, EvalError)> {
        let mut out = Files {
            open: (0..files.len()).map(|_| None).collect(),
            names: files.iter().map(|f| f.name.clone()).collect(),
        };
        for (k, f) in files.iter().enumerate() {
            if let Some((name, mode)) = &f.open {
                let status = out.open(k as u32, name, *mode);
                if status != OpenStatus::Ok {
                    return Err((k, open_error(&f.name, name, *mode, status)));
                }
            }
        }
        Ok(out)
    }

    /// `file_open`: the status as `file_open_status` has it.
    pub fn open(&mut self, f: u32, name: &str, mode: FileMode) -> OpenStatus {
        let Some(slot) = self.open.get_mut(f as usize) else {
            return OpenStatus::StatusError;
        };
        if slot.is_some() {
            return OpenStatus::StatusError;
        }
        let opened = match (name, mode) {
            ("STD_INPUT", FileMode::Read) => {
                Some(OpenFile::Reader(Box::new(std::io::stdin().lock()), None))
            }
            ("STD_OUTPUT", FileMode::Write | FileMode::Append) => {
                Some(OpenFile::Writer(Box::new(std::io::stdout())))
            }
            (_, FileMode::Read) => File::open(name)
                .ok()
                .map(|f| OpenFile::Reader(Box::new(BufReader::new(f)), None)),
            (_, FileMode::Write) => File::create(name)
                .ok()
                .map(|f| OpenFile::Writer(Box::new(BufWriter::new(f)))),
            (_, FileMode::Append) => std::fs::OpenOptions::new()
                .append(true)
                .create(true)
                .open(name)
                .ok()
                .map(|f| OpenFile::Writer(Box::new(BufWriter::new(f)))),
        };
        match opened {
            Some(o) => {
                *slot = Some(o);
                OpenStatus::Ok
            }
            None => OpenStatus::NameError,
        }
    }

    /// `file_close` (nothing for a file not open).
    pub fn close(&mut self, f: u32) -> Result<(), EvalError> {
        if let Some(slot) = self.open.get_mut(f as usize)
            && let Some(OpenFile::Writer(mut w)) = slot.take()
        {
            w.flush().map_err(|e| self.io_error(f, &e))?;
        }
        Ok(())
    }

    fn name(&self, f: u32) -> &str {
        self.names.get(f as usize).map_or("?", String::as_str)
    }

    fn io_error(&self, f: u32, e: &std::io::Error) -> EvalError {
        EvalError::new(
            format!("file `{}`: {e}", self.name(f)),
            "check the disk space and the file's permissions",
        )
    }

    fn not_open(&self, f: u32, mode: &str) -> EvalError {
        EvalError::new(
            format!("file `{}` is not open for {mode}", self.name(f)),
            "open it with `file_open` or in its declaration (`open read_mode is \"name\"`)",
        )
    }

    /// Whether a file open for reading has a next line (read ahead and kept until taken).
    fn peek(&mut self, f: u32) -> Result<bool, EvalError> {
        if !matches!(self.open.get(f as usize), Some(Some(OpenFile::Reader(..)))) {
            return Err(self.not_open(f, "reading"));
        }
        let Some(Some(OpenFile::Reader(r, next))) = self.open.get_mut(f as usize) else {
            return Ok(false);
        };
        if next.is_none() {
            let mut line = String::new();
            match r.read_line(&mut line) {
                Ok(0) => return Ok(false),
                Ok(_) => {
                    while line.ends_with(['\n', '\r']) {
                        line.pop();
                    }
                    *next = Some(line);
                }
                Err(e) => {
                    return Err(EvalError::new(
                        format!(
                            "file `{}`: {e}",
                            self.names.get(f as usize).map_or("?", String::as_str)
                        ),
                        "check that the file is text (UTF-8)",
                    ));
                }
            }
        }
        Ok(true)
    }

    /// `endfile(f)`.
    pub fn at_end(&mut self, f: u32) -> Result<bool, EvalError> {
        Ok(!self.peek(f)?)
    }

    /// The next line (`readline`); reading past the end is an error (LRM 14.3).
    pub fn read_line(&mut self, f: u32) -> Result<String, EvalError> {
        if !self.peek(f)? {
            return Err(EvalError::new(
                format!("read past the end of file `{}`", self.name(f)),
                "test `endfile(f)` before each read",
            ));
        }
        match self.open.get_mut(f as usize) {
            Some(Some(OpenFile::Reader(_, next))) => Ok(next.take().unwrap_or_default()),
            _ => Err(self.not_open(f, "reading")),
        }
    }

    /// One line out (`writeline`).
    pub fn write_line(&mut self, f: u32, line: &str) -> Result<(), EvalError> {
        let written = match self.open.get_mut(f as usize) {
            Some(Some(OpenFile::Writer(w))) => writeln!(w, "{line}"),
            _ => return Err(self.not_open(f, "writing")),
        };
        written.map_err(|e| self.io_error(f, &e))
    }

    /// Flushes every file open for writing (at the end of a run, whatever ended it).
    pub fn flush(&mut self) {
        for w in self.open.iter_mut().flatten() {
            if let OpenFile::Writer(w) = w {
                // A failed flush at the end has nowhere left to report to.
                let _ = w.flush();
            }
        }
    }
}

impl Drop for Files {
    fn drop(&mut self) {
        self.flush();
    }
}

fn open_error(object: &str, name: &str, mode: FileMode, status: OpenStatus) -> EvalError {
    let mode = match mode {
        FileMode::Read => "reading",
        FileMode::Write => "writing",
        FileMode::Append => "appending",
    };
    EvalError::new(
        format!("file `{object}` cannot open \"{name}\" for {mode} ({status:?})"),
        "check the path (relative paths start in the directory vams runs in) and its permissions",
    )
}
