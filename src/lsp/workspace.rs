//! The workspace's files: every `*.vhd`/`*.vhdl` file under the client's folders, loaded into
//! one [`AnalysisHost`] (with the bundled stdlib), and the documents the client has open,
//! whose text replaces the file's on disk while they are open.
//!
//! Files are named in the host by their path (or by their URI when it is not a `file:` one,
//! an unsaved buffer), so that diagnostics and locations map back to the URIs the client knows.

use std::path::{Path, PathBuf};

use lsp_types::Url;
use rustc_hash::FxHashMap;

use crate::analysis::AnalysisHost;
use crate::ast::DesignFile;
use crate::source::FileId;

/// The files of the compilation and where each came from.
pub struct Workspace {
    host: AnalysisHost,
    uris: FxHashMap<FileId, Url>,
    /// Text received from the client and not yet analysed (the debounce's backlog).
    pending: FxHashMap<Url, String>,
}

impl Default for Workspace {
    fn default() -> Self {
        Self::new()
    }
}

impl Workspace {
    /// The stdlib alone.
    pub fn new() -> Workspace {
        Workspace {
            host: AnalysisHost::new(),
            uris: FxHashMap::default(),
            pending: FxHashMap::default(),
        }
    }

    /// The same files analysed from scratch: after a caught panic, when the host's tables
    /// may be half updated. Deferred text is kept as deferred.
    pub fn rebuilt(&self) -> Workspace {
        let mut fresh = Workspace::new();
        for (id, uri, _) in self.user_files() {
            fresh.set_text(uri, self.text(id).to_string());
        }
        fresh.pending = self.pending.clone();
        fresh
    }

    /// Loads every VHDL file under `root` (recursively; unreadable files are skipped, since
    /// the client names them again when it opens them).
    pub fn load_folder(&mut self, root: &Path) {
        let mut paths = Vec::new();
        collect_sources(root, &mut paths);
        paths.sort();
        for path in paths {
            let (Ok(text), Ok(uri)) = (std::fs::read_to_string(&path), Url::from_file_path(&path))
            else {
                continue;
            };
            self.set_text(&uri, text);
        }
    }

    /// Sets the text of `uri` now (adds the file when it is new).
    pub fn set_text(&mut self, uri: &Url, text: String) -> FileId {
        self.pending.remove(uri);
        let id = self.host.set_file(&file_name(uri), text);
        self.uris.insert(id, uri.clone());
        id
    }

    /// Records the text of `uri` for the next [`Workspace::flush`].
    pub fn defer_text(&mut self, uri: &Url, text: String) {
        self.pending.insert(uri.clone(), text);
    }

    /// Analyses the text deferred since the last flush; returns whether there was any.
    pub fn flush(&mut self) -> bool {
        let pending = std::mem::take(&mut self.pending);
        let any = !pending.is_empty();
        for (uri, text) in pending {
            self.set_text(&uri, text);
        }
        any
    }

    /// The client closed `uri`: the file on disk takes its place again, or, when there is
    /// none (an unsaved buffer, a file outside the workspace's folders that was deleted), the
    /// file leaves the compilation. Returns whether it left.
    pub fn close(&mut self, uri: &Url, in_workspace: bool) -> bool {
        self.pending.remove(uri);
        let on_disk = uri
            .to_file_path()
            .ok()
            .filter(|_| in_workspace)
            .and_then(|p| std::fs::read_to_string(p).ok());
        match on_disk {
            Some(text) => {
                self.set_text(uri, text);
                false
            }
            None => {
                if let Some(id) = self.id(uri) {
                    self.uris.remove(&id);
                }
                self.host.remove_file(&file_name(uri))
            }
        }
    }

    pub fn host(&self) -> &AnalysisHost {
        &self.host
    }

    /// The id of `uri` in the compilation.
    pub fn id(&self, uri: &Url) -> Option<FileId> {
        self.uris.iter().find(|(_, u)| *u == uri).map(|(id, _)| *id)
    }

    /// The URI of file `id`; `None` for the stdlib.
    pub fn uri(&self, id: FileId) -> Option<&Url> {
        self.uris.get(&id)
    }

    /// The user files with their URIs, in the order added.
    pub fn user_files(&self) -> impl Iterator<Item = (FileId, &Url, &DesignFile)> {
        self.host
            .files()
            .iter()
            .filter_map(|(id, ast)| Some((*id, self.uris.get(id)?, ast)))
    }

    /// The text of file `id`.
    pub fn text(&self, id: FileId) -> &str {
        &self.host.sources().file(id).text
    }

    /// The parsed file `id`.
    pub fn ast(&self, id: FileId) -> Option<&DesignFile> {
        self.host
            .files()
            .iter()
            .find(|(f, _)| *f == id)
            .map(|(_, ast)| ast)
    }
}

/// How the host names the file of `uri`.
fn file_name(uri: &Url) -> String {
    match uri.to_file_path() {
        Ok(path) => path.display().to_string(),
        Err(()) => uri.to_string(),
    }
}

/// True for the files a workspace folder contributes.
pub fn is_vhdl_path(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("vhd") || e.eq_ignore_ascii_case("vhdl"))
}

/// The VHDL files under `dir`, skipping hidden folders and build output (`target`,
/// `node_modules`), where copies of sources would shadow the real ones.
fn collect_sources(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name();
        let name = name.to_string_lossy();
        let Ok(kind) = entry.file_type() else {
            continue;
        };
        if kind.is_dir() {
            if !name.starts_with('.') && name != "target" && name != "node_modules" {
                collect_sources(&path, out);
            }
        } else if kind.is_file() && is_vhdl_path(&path) {
            out.push(path);
        }
    }
}
