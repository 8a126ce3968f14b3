//! An analysis kept up to date under edits: the base of editor support. Files are added,
//! replaced or removed one at a time; each change re-parses that file and re-analyses only
//! from the first unit, in analysis order, that the change can affect ([`super::reanalyse`]),
//! so that the result is always what analysing every file from scratch gives.

use crate::stdlib;
use vams_syntax::ast::DesignFile;
use vams_syntax::diagnostics::SyntaxError;
use vams_syntax::parser;
use vams_syntax::source::{FileId, SourceMap};

use super::{Analysis, analyse, reanalyse};

/// The bundled stdlib plus the user's files (library `work`), parsed and analysed.
pub struct AnalysisHost {
    sources: SourceMap,
    files: Vec<(FileId, DesignFile)>,
    syntax: Vec<(FileId, Vec<SyntaxError>)>,
    analysis: Analysis,
    reused: usize,
}

impl Default for AnalysisHost {
    fn default() -> Self {
        Self::new()
    }
}

impl AnalysisHost {
    /// The stdlib alone, analysed.
    pub fn new() -> AnalysisHost {
        let mut sources = SourceMap::new();
        let ids = stdlib::load(&mut sources);
        let mut host = AnalysisHost {
            files: Vec::new(),
            syntax: Vec::new(),
            analysis: Analysis::default(),
            reused: 0,
            sources,
        };
        for id in ids {
            let (ast, errors) = host.parse(id);
            host.files.push((id, ast));
            host.record_syntax(id, errors);
        }
        host.analysis = analyse(&host.sources, &host.files);
        host
    }

    /// Adds the user file `name` with `text`, or replaces its text; returns its id.
    pub fn set_file(&mut self, name: &str, text: String) -> FileId {
        let id = match self.id_of(name) {
            // Saved without a change: nothing to do.
            Some(id) if *self.sources.file(id).text == text => {
                self.reused = self.analysis.units.len();
                return id;
            }
            Some(id) => {
                self.sources.set_text(id, text);
                let (ast, errors) = self.parse(id);
                if let Some(slot) = self.files.iter_mut().find(|(f, _)| *f == id) {
                    slot.1 = ast;
                }
                self.record_syntax(id, errors);
                id
            }
            None => {
                let id = self.sources.add(name, "work", text);
                let (ast, errors) = self.parse(id);
                self.files.push((id, ast));
                self.record_syntax(id, errors);
                id
            }
        };
        self.update(id);
        id
    }

    /// Removes the user file `name`; false when there is none.
    pub fn remove_file(&mut self, name: &str) -> bool {
        let Some(id) = self.id_of(name) else {
            return false;
        };
        self.files.retain(|(f, _)| *f != id);
        self.syntax.retain(|(f, _)| *f != id);
        self.update(id);
        true
    }

    pub fn analysis(&self) -> &Analysis {
        &self.analysis
    }

    pub fn sources(&self) -> &SourceMap {
        &self.sources
    }

    /// The files of the compilation, stdlib first, user files in the order added.
    pub fn files(&self) -> &[(FileId, DesignFile)] {
        &self.files
    }

    /// The syntax errors of each file that has some.
    pub fn syntax_errors(&self) -> &[(FileId, Vec<SyntaxError>)] {
        &self.syntax
    }

    /// How many units the last change took over without analysing them again.
    pub fn reused(&self) -> usize {
        self.reused
    }

    /// The id of the user file `name` in the compilation.
    fn id_of(&self, name: &str) -> Option<FileId> {
        self.files.iter().map(|(id, _)| *id).find(|&id| {
            self.sources.file(id).name == name && self.sources.file(id).library == "work"
        })
    }

    fn parse(&self, id: FileId) -> (DesignFile, Vec<SyntaxError>) {
        let text = self.sources.file(id).text.clone();
        parser::parse(id, &text)
    }

    fn record_syntax(&mut self, id: FileId, errors: Vec<SyntaxError>) {
        self.syntax.retain(|(f, _)| *f != id);
        if !errors.is_empty() {
            self.syntax.push((id, errors));
        }
    }

    fn update(&mut self, changed: FileId) {
        let previous = std::mem::take(&mut self.analysis);
        self.analysis = reanalyse(&self.sources, &self.files, previous, &[changed]);
        self.reused = self.analysis.reused;
    }
}
