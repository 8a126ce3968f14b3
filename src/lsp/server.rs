//! The main loop: reads the client's messages, keeps the [`Workspace`] up to date and answers.
//!
//! Changes are debounced: `didChange` only records the text, and the loop analyses it when
//! the client has been quiet for the debounce time (`recv_timeout` on the connection), or at
//! once when a request needs the analysis. Every handler runs under `catch_unwind`: a bug hit
//! by some text answers that request with an error and the server goes on.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use crossbeam_channel::RecvTimeoutError;
use lsp_server::{Connection, ErrorCode, Message, Notification, Request, Response};
use lsp_types::notification::{
    DidChangeTextDocument, DidCloseTextDocument, DidOpenTextDocument, DidSaveTextDocument,
    Notification as _, PublishDiagnostics,
};
use lsp_types::request::{
    CodeLensRequest, Completion, DocumentSymbolRequest, ExecuteCommand, GotoDefinition,
    HoverRequest, References, Request as _,
};
use lsp_types::{
    CodeLensParams, CompletionParams, DidChangeTextDocumentParams, DidCloseTextDocumentParams,
    DidOpenTextDocumentParams, DidSaveTextDocumentParams, DocumentSymbolParams,
    DocumentSymbolResponse, ExecuteCommandParams, GotoDefinitionParams, GotoDefinitionResponse,
    HoverParams, PublishDiagnosticsParams, ReferenceParams, TextDocumentPositionParams, Url,
};
use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::Value;

use crate::source::FileId;

use super::diagnostics::Published;
use super::lens::{RUN_TESTBENCH, code_lenses, run_testbench};
use super::position::LineIndex;
use super::workspace::Workspace;
use super::{LspError, completion, hover, navigation, symbols};

/// The state of one session.
pub struct Server {
    connection: Connection,
    workspace: Workspace,
    published: Published,
    /// The workspace's folders, where `vams test` looks for benches.
    roots: Vec<PathBuf>,
    debounce: Duration,
    /// When the last change arrived, while some are not analysed yet.
    last_change: Option<Instant>,
}

/// How a request went: its result, or an error code and message.
type Answer = Result<Value, (ErrorCode, String)>;

impl Server {
    pub fn new(connection: Connection, roots: Vec<PathBuf>, debounce: Duration) -> Server {
        let mut server = Server {
            connection,
            workspace: Workspace::new(),
            published: Published::default(),
            roots,
            debounce,
            last_change: None,
        };
        server.guarded("loading the workspace", |s| {
            for root in &s.roots {
                s.workspace.load_folder(root);
            }
            let updates = s.published.saved(&s.workspace, None);
            s.publish(updates);
        });
        server
    }

    /// Serves until `exit`; Ok when a `shutdown` came first (the protocol's clean end).
    pub fn run(mut self) -> Result<(), LspError> {
        loop {
            let message = match self.last_change {
                Some(at) => {
                    let wait = (at + self.debounce).saturating_duration_since(Instant::now());
                    match self.connection.receiver.recv_timeout(wait) {
                        Ok(m) => m,
                        Err(RecvTimeoutError::Timeout) => {
                            self.analyse_pending();
                            continue;
                        }
                        Err(RecvTimeoutError::Disconnected) => return Err(LspError::NoExit),
                    }
                }
                None => match self.connection.receiver.recv() {
                    Ok(m) => m,
                    Err(_) => return Err(LspError::NoExit),
                },
            };
            match message {
                Message::Request(request) => {
                    if self.connection.handle_shutdown(&request)? {
                        return Ok(());
                    }
                    self.analyse_pending();
                    let id = request.id.clone();
                    let answer = catch_unwind(AssertUnwindSafe(|| self.request(request)))
                        .unwrap_or_else(|panic| Err((ErrorCode::InternalError, panicked(&panic))));
                    let response = match answer {
                        Ok(result) => Response::new_ok(id, result),
                        Err((code, message)) => Response::new_err(id, code as i32, message),
                    };
                    self.send(Message::Response(response));
                }
                Message::Notification(note) if note.method == "exit" => {
                    return Err(LspError::NoShutdown);
                }
                Message::Notification(note) => {
                    let method = note.method.clone();
                    self.guarded(&method, |s| s.notification(note));
                }
                Message::Response(_) => {}
            }
        }
    }

    fn request(&mut self, request: Request) -> Answer {
        let ws = &self.workspace;
        match request.method.as_str() {
            HoverRequest::METHOD => {
                let p: HoverParams = params(request)?;
                at_position(ws, &p.text_document_position_params, |f, o| {
                    hover::hover(ws, f, o as u32)
                })
            }
            GotoDefinition::METHOD => {
                let p: GotoDefinitionParams = params(request)?;
                at_position(ws, &p.text_document_position_params, |f, o| {
                    navigation::definition(ws, f, o as u32).map(GotoDefinitionResponse::Scalar)
                })
            }
            References::METHOD => {
                let p: ReferenceParams = params(request)?;
                let include = p.context.include_declaration;
                at_position(ws, &p.text_document_position, |f, o| {
                    navigation::references(ws, f, o as u32, include)
                })
            }
            Completion::METHOD => {
                let p: CompletionParams = params(request)?;
                at_position(ws, &p.text_document_position, |f, o| {
                    completion::completion(ws, f, o)
                })
            }
            DocumentSymbolRequest::METHOD => {
                let p: DocumentSymbolParams = params(request)?;
                in_document(ws, &p.text_document.uri, |f| {
                    let index = LineIndex::new(ws.text(f));
                    let ast = ws.ast(f)?;
                    Some(DocumentSymbolResponse::Nested(symbols::document_symbols(
                        ast, &index,
                    )))
                })
            }
            CodeLensRequest::METHOD => {
                let p: CodeLensParams = params(request)?;
                in_document(ws, &p.text_document.uri, |f| {
                    let index = LineIndex::new(ws.text(f));
                    Some(code_lenses(ws.ast(f)?, &index))
                })
            }
            ExecuteCommand::METHOD => {
                let p: ExecuteCommandParams = params(request)?;
                let name = p.arguments.first().and_then(Value::as_str);
                match (p.command.as_str(), name) {
                    (RUN_TESTBENCH, Some(name)) => {
                        let sender = self.connection.sender.clone();
                        run_testbench(name.to_string(), self.bench_roots(), sender);
                        Ok(Value::Null)
                    }
                    (command, _) => Err((
                        ErrorCode::InvalidParams,
                        format!("unknown command `{command}` or missing testbench name"),
                    )),
                }
            }
            method => Err((
                ErrorCode::MethodNotFound,
                format!("vams lsp does not answer `{method}`"),
            )),
        }
    }

    fn notification(&mut self, note: Notification) {
        match note.method.as_str() {
            DidOpenTextDocument::METHOD => {
                let Ok(p) = note.extract::<DidOpenTextDocumentParams>(DidOpenTextDocument::METHOD)
                else {
                    return;
                };
                self.analyse_pending();
                self.workspace
                    .set_text(&p.text_document.uri, p.text_document.text);
                let updates = self.published.changed(&self.workspace);
                self.publish(updates);
            }
            DidChangeTextDocument::METHOD => {
                let Ok(mut p) =
                    note.extract::<DidChangeTextDocumentParams>(DidChangeTextDocument::METHOD)
                else {
                    return;
                };
                // Full sync: the last change holds the whole text.
                if let Some(change) = p.content_changes.pop() {
                    self.workspace.defer_text(&p.text_document.uri, change.text);
                    self.last_change = Some(Instant::now());
                }
            }
            DidSaveTextDocument::METHOD => {
                let Ok(p) = note.extract::<DidSaveTextDocumentParams>(DidSaveTextDocument::METHOD)
                else {
                    return;
                };
                self.workspace.flush();
                self.last_change = None;
                if let Some(text) = p.text {
                    self.workspace.set_text(&p.text_document.uri, text);
                }
                let saved = self.workspace.id(&p.text_document.uri);
                let updates = self.published.saved(&self.workspace, saved);
                self.publish(updates);
            }
            DidCloseTextDocument::METHOD => {
                let Ok(p) =
                    note.extract::<DidCloseTextDocumentParams>(DidCloseTextDocument::METHOD)
                else {
                    return;
                };
                self.analyse_pending();
                let uri = p.text_document.uri;
                let in_workspace = self.in_workspace(&uri);
                if self.workspace.close(&uri, in_workspace) {
                    let mut updates: Vec<_> = self.published.removed(&uri).into_iter().collect();
                    updates.extend(self.published.changed(&self.workspace));
                    self.publish(updates);
                } else {
                    let updates = self.published.changed(&self.workspace);
                    self.publish(updates);
                }
            }
            // Anything else ($/cancelRequest, $/setTrace, ...): nothing to do.
            _ => {}
        }
    }

    /// After a panic while the workspace changed: the same files analysed from scratch, or,
    /// should that fail too, the stdlib alone (the client's next edits bring files back).
    fn recover(&mut self) {
        let ws = &self.workspace;
        self.workspace = catch_unwind(AssertUnwindSafe(|| ws.rebuilt())).unwrap_or_default();
    }

    /// Runs `f`, which changes the workspace; a panic in it is logged and the workspace
    /// rebuilt, since its host may be half updated.
    fn guarded(&mut self, what: &str, f: impl FnOnce(&mut Server)) {
        if catch_unwind(AssertUnwindSafe(|| f(self))).is_err() {
            eprintln!("vams lsp: internal error in {what}; analysing the files again");
            self.recover();
        }
    }

    /// Analyses the changes not analysed yet and publishes what they changed.
    fn analyse_pending(&mut self) {
        self.last_change = None;
        self.guarded("an analysis", |s| {
            if s.workspace.flush() {
                let updates = s.published.changed(&s.workspace);
                s.publish(updates);
            }
        });
    }

    fn publish(&self, updates: Vec<PublishDiagnosticsParams>) {
        for p in updates {
            let note = Notification::new(PublishDiagnostics::METHOD.to_string(), p);
            self.send(Message::Notification(note));
        }
    }

    fn send(&self, message: Message) {
        // The client has gone when this fails; the loop ends at the next receive.
        let _ = self.connection.sender.send(message);
    }

    fn in_workspace(&self, uri: &Url) -> bool {
        uri.to_file_path()
            .is_ok_and(|p| self.roots.iter().any(|r| p.starts_with(r)))
    }

    /// Where `vams test` looks: the workspace's folders, or the open files' folders when
    /// the client gave none.
    fn bench_roots(&self) -> Vec<PathBuf> {
        if !self.roots.is_empty() {
            return self.roots.clone();
        }
        let mut dirs: Vec<PathBuf> = (self.workspace.user_files())
            .filter_map(|(_, uri, _)| uri.to_file_path().ok()?.parent().map(PathBuf::from))
            .collect();
        dirs.sort();
        dirs.dedup();
        dirs
    }
}

/// The request's parameters, or an InvalidParams answer.
fn params<P: DeserializeOwned>(request: Request) -> Result<P, (ErrorCode, String)> {
    serde_json::from_value(request.params).map_err(|e| (ErrorCode::InvalidParams, e.to_string()))
}

/// Runs `f` on the file and byte offset of a position; `null` for a document not in the
/// workspace or nothing there.
fn at_position<T: Serialize>(
    ws: &Workspace,
    at: &TextDocumentPositionParams,
    f: impl FnOnce(FileId, usize) -> T,
) -> Answer {
    in_document(ws, &at.text_document.uri, |file| {
        let offset = LineIndex::new(ws.text(file)).offset(at.position);
        Some(f(file, offset))
    })
}

fn in_document<T: Serialize>(
    ws: &Workspace,
    uri: &Url,
    f: impl FnOnce(FileId) -> Option<T>,
) -> Answer {
    let result = ws.id(uri).and_then(f);
    serde_json::to_value(result).map_err(|e| (ErrorCode::InternalError, e.to_string()))
}

/// The text of a caught panic.
fn panicked(panic: &Box<dyn std::any::Any + Send>) -> String {
    let what = (panic.downcast_ref::<&str>().map(|s| s.to_string()))
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_default();
    format!("internal error in vams lsp (the request was dropped): {what}")
}
