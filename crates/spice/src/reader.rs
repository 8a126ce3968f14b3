//! The reader: a deck's files to a [`Deck`].
//!
//! Takes the deck's file (registered in a [`SourceMap`]) and a [`Loader`] for what it
//! includes; gives the [`Deck`] and every error it found. Owns the deck's structure: which
//! body a line belongs to (`.subckt` nesting), `.include` and `.lib` (each loaded file
//! registered in the `SourceMap`, so spans point into it; paths relative to the including
//! file), include cycles, and duplicate definitions in one body. Line shapes are
//! `elements`' and `cards`'.
//!
//! Never fails and never panics: an unusable line is a diagnostic, and reading goes on at
//! the next line, so one run reports every error it can. An included file is spliced in
//! where the `.include` stands, as SPICE does, so it may open a `.subckt` the includer
//! closes. Inside a `.lib` file, `.lib name` ... `.endl` defines a section; `.lib file name`
//! reads only that section.

mod cards;
mod cursor;
mod elements;
#[cfg(test)]
mod tests;

use std::path::{Component, Path, PathBuf};

use vams_syntax::source::{FileId, SourceMap, Span};

use crate::deck::{Body, Deck, Name, Subckt};
use crate::error::SpiceError;
use crate::lines::{self, Line};
use crate::loader::Loader;
use crate::suggest::suggest;

use cards::Card;

/// Reads the deck in `file` and everything it includes (see the module doc). The file's name
/// in `sources` is its path: included paths are resolved against its folder, and each
/// included file is registered under its resolved path.
pub fn read_deck(
    sources: &mut SourceMap,
    file: FileId,
    loader: &mut dyn Loader,
) -> (Deck, Vec<SpiceError>) {
    let top = normalize(Path::new(&sources.file(file).name));
    let mut r = Reader {
        sources,
        loader,
        deck: Deck::default(),
        errors: Vec::new(),
        open: Vec::new(),
        chain: vec![(top, None)],
    };
    r.deck.files.push(file);
    r.read_file(file, true, None);
    while let Some(sub) = r.open.pop() {
        r.errors.push(SpiceError::UnclosedSubckt {
            span: sub.name.span,
            name: sub.name.text.clone(),
        });
        r.close(sub);
    }
    (r.deck, r.errors)
}

/// Lexical normalisation: `a/./b/../c` is `a/c` (no file system access).
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                let last_normal =
                    matches!(out.components().next_back(), Some(Component::Normal(_)));
                if last_normal {
                    out.pop();
                } else {
                    out.push("..");
                }
            }
            other => out.push(other.as_os_str()),
        }
    }
    out
}

struct Reader<'a> {
    sources: &'a mut SourceMap,
    loader: &'a mut dyn Loader,
    deck: Deck,
    errors: Vec<SpiceError>,
    /// Subcircuits being read, innermost last.
    open: Vec<Subckt>,
    /// The files being read, outermost first, with the library section read from each.
    chain: Vec<(PathBuf, Option<String>)>,
}

impl Reader<'_> {
    /// The body lines go to now.
    fn body(&mut self) -> &mut Body {
        match self.open.last_mut() {
            Some(sub) => &mut sub.body,
            None => &mut self.deck.body,
        }
    }

    fn read_file(&mut self, file: FileId, top: bool, section: Option<(&Name, Span)>) {
        let text = self.sources.file(file).text.clone();
        let lines = lines::split(&text, file, top);
        self.errors.extend(lines.errors);
        if let Some((title, span)) = lines.title {
            self.deck.title = title;
            self.deck.title_span = span;
        }
        for span in lines.controls {
            self.deck.warnings.push(SpiceError::ControlSkipped { span });
        }
        if top && lines.end.is_none() {
            self.deck
                .warnings
                .push(SpiceError::NoEnd { span: lines.eof });
        }
        let range = match section {
            None => 0..lines.lines.len(),
            Some((name, at)) => match find_section(&lines.lines, &name.key) {
                Ok(range) => range,
                Err(available) => {
                    let file_name = self.sources.file(file).name.clone();
                    self.errors.push(SpiceError::LibSection {
                        span: at,
                        file: file_name,
                        section: name.text.clone(),
                        suggestion: suggest(&name.key, available.iter().map(String::as_str)),
                        available: if available.is_empty() {
                            "none".into()
                        } else {
                            available.join(", ")
                        },
                    });
                    return;
                }
            },
        };
        self.read_lines(file, &text, &lines.lines[range]);
    }

    fn read_lines(&mut self, file: FileId, text: &str, lines: &[Line]) {
        let mut i = 0;
        while let Some(line) = lines.get(i) {
            i += 1;
            if !line.errors.is_empty() {
                self.errors.extend(line.errors.iter().cloned());
                continue;
            }
            let Some(head) = line.tokens.first() else {
                continue;
            };
            if !head.text.starts_with('.') {
                if let Some(el) = elements::element(line, &mut self.errors) {
                    self.body().elements.push(el);
                }
                continue;
            }
            let Some(card) = cards::card(line, text, &mut self.errors) else {
                continue;
            };
            match card {
                Card::LibSection => {
                    // A section definition met outside `.lib file name`: not read.
                    while let Some(l) = lines.get(i) {
                        i += 1;
                        if l.tokens.first().is_some_and(|t| t.is_keyword(".endl")) {
                            break;
                        }
                    }
                }
                card => self.apply(file, card),
            }
        }
    }

    fn apply(&mut self, file: FileId, card: Card) {
        match card {
            Card::Subckt {
                name,
                ports,
                params,
                span,
            } => self.open.push(Subckt {
                name,
                ports,
                params,
                body: Body::default(),
                span,
            }),
            Card::Ends(name, span) => match self.open.pop() {
                None => self.errors.push(SpiceError::StrayEnd {
                    span,
                    card: ".ends".into(),
                }),
                Some(sub) => {
                    if let Some(n) = name.filter(|n| n.key != sub.name.key) {
                        self.errors.push(SpiceError::EndsName {
                            span: n.span,
                            found: n.text,
                            expected: sub.name.text.clone(),
                        });
                    }
                    self.close(sub);
                }
            },
            Card::Model(model) => {
                let first = self
                    .body()
                    .models
                    .iter()
                    .find(|m| m.name.key == model.name.key)
                    .map(|m| m.name.span);
                match first {
                    Some(first) => {
                        let e = self.duplicate("model", &model.name, first);
                        self.errors.push(e);
                    }
                    None => self.body().models.push(model),
                }
            }
            Card::Params(params) => self.body().params.extend(params),
            Card::Include { path, span } => self.include(file, &path, None, span),
            Card::Lib {
                path,
                section,
                span,
            } => self.include(file, &path, Some(section), span),
            Card::LibSection => {}
            Card::Endl(span) => self.errors.push(SpiceError::StrayEnd {
                span,
                card: ".endl".into(),
            }),
            Card::Endc(span) => self.errors.push(SpiceError::StrayEnd {
                span,
                card: ".endc".into(),
            }),
            Card::Analysis(a) => self.deck.analyses.push(a),
            Card::Options(items) => self.deck.options.extend(items),
            Card::Temp(values) => self.deck.temps.extend(values),
            Card::Ic(values) => self.deck.initial.extend(values),
            Card::Nodeset(values) => self.deck.nodesets.extend(values),
            Card::Output(out) => self.deck.outputs.push(out),
            Card::Global(names) => self.deck.globals.extend(names),
            Card::Title(title) => self.deck.title = title,
            Card::Ignored(warning) => self.deck.warnings.push(warning),
        }
    }

    /// Adds a finished subcircuit to the body around it.
    fn close(&mut self, sub: Subckt) {
        let first = self
            .body()
            .subckts
            .iter()
            .find(|s| s.name.key == sub.name.key)
            .map(|s| s.name.span);
        match first {
            Some(first) => {
                let e = self.duplicate("subcircuit", &sub.name, first);
                self.errors.push(e);
            }
            None => self.body().subckts.push(sub),
        }
    }

    fn duplicate(&self, what: &'static str, name: &Name, first: Span) -> SpiceError {
        SpiceError::DuplicateDefinition {
            span: name.span,
            what,
            name: name.text.clone(),
            first_line: self.sources.line_col(first).0,
            first_file: self.sources.file(first.file).name.clone(),
        }
    }

    /// Reads `path` (relative to `from`'s folder) where the card at `span` stands: all of
    /// it, or one library section.
    fn include(&mut self, from: FileId, path: &str, section: Option<Name>, span: Span) {
        let base = Path::new(&self.sources.file(from).name)
            .parent()
            .map(Path::to_path_buf)
            .unwrap_or_default();
        let resolved = normalize(&base.join(path));
        let key = (resolved.clone(), section.as_ref().map(|s| s.key.clone()));
        if let Some(at) = self.chain.iter().position(|c| *c == key) {
            let mut names: Vec<String> = self.chain[at..]
                .iter()
                .map(|(p, s)| describe(p, s.as_deref()))
                .collect();
            names.push(describe(
                &resolved,
                section.as_ref().map(|s| s.key.as_str()),
            ));
            self.errors.push(SpiceError::IncludeCycle {
                span,
                path: resolved.display().to_string(),
                chain: names.join(" -> "),
            });
            return;
        }
        let text = match self.loader.load(&resolved) {
            Ok(text) => text,
            Err(e) => {
                self.errors.push(SpiceError::IncludeNotFound {
                    span,
                    path: resolved.display().to_string(),
                    reason: e.to_string(),
                });
                return;
            }
        };
        let id = self
            .sources
            .add(resolved.display().to_string(), "work", text);
        self.deck.files.push(id);
        self.chain.push(key);
        let at = section.as_ref().map(|s| s.span).unwrap_or(span);
        self.read_file(id, false, section.as_ref().map(|s| (s, at)));
        self.chain.pop();
    }
}

fn describe(path: &Path, section: Option<&str>) -> String {
    match section {
        Some(s) => format!("{} (section {s})", path.display()),
        None => path.display().to_string(),
    }
}

/// The lines of library section `name` (between `.lib name` and its `.endl`), or the names
/// of the sections there are.
fn find_section(lines: &[Line], name: &str) -> Result<std::ops::Range<usize>, Vec<String>> {
    let mut available = Vec::new();
    let mut i = 0;
    while let Some(line) = lines.get(i) {
        i += 1;
        let is_section =
            line.tokens.len() == 2 && line.tokens[0].is_keyword(".lib") && line.tokens[1].is_word();
        if !is_section {
            continue;
        }
        let this = line.tokens[1].key();
        let start = i;
        while lines
            .get(i)
            .is_some_and(|l| !l.tokens.first().is_some_and(|t| t.is_keyword(".endl")))
        {
            i += 1;
        }
        if this == name {
            return Ok(start..i);
        }
        available.push(this);
        i += 1;
    }
    Err(available)
}
