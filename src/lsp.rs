//! `vams lsp`: a language server over standard input and output, for editors.
//!
//! **Takes** the client's JSON-RPC messages; **gives** diagnostics (syntax and analysis errors
//! of the edited files after each change, debounced; elaboration and analog-system errors of
//! the workspace's testbenches after each save; the messages and help lines of `vams check`),
//! hover, go to definition, find references, document symbols, completion (names in scope,
//! attributes after a tick) and a "run testbench" code lens. The workspace is every VHDL file
//! under the client's folders plus the bundled stdlib, kept analysed by one
//! [`AnalysisHost`](crate::analysis::AnalysisHost), which re-analyses only what an edit can
//! affect.
//!
//! Built on `lsp-server` and `lsp-types`, rust-analyzer's crates: a synchronous loop over
//! crossbeam channels with no async runtime, so the build stays lean on a small machine, and
//! requests are answered one at a time on the state as it is, which is all an analysis that
//! takes milliseconds needs. Like `cli`, a driver of the pipeline: it uses `analysis`,
//! `elaborate`, `analog` and `diagnostics` and holds no analysis of its own; it never panics on
//! a client's input (every handler is caught and answers an error) and never writes to
//! standard output but protocol messages.
//!
//! One job per module: `server` the loop and dispatch, `workspace` the files and open
//! documents, `position` byte offsets to UTF-16 positions, `diagnostics`, `hover`,
//! `navigation` (definition, references), `quantity` (a quantity's role and unit for hover), `symbols`, `completion`, `lens` (run a testbench),
//! `syntax` (finding a declaration's syntax for hover).

mod completion;
mod diagnostics;
mod hover;
mod lens;
mod navigation;
mod position;
mod quantity;
mod server;
mod symbols;
mod syntax;
mod workspace;

use std::path::PathBuf;
use std::time::Duration;

use lsp_server::{Connection, ProtocolError};
use lsp_types::{
    CodeLensOptions, CompletionOptions, ExecuteCommandOptions, InitializeParams, OneOf,
    SaveOptions, ServerCapabilities, ServerInfo, TextDocumentSyncCapability, TextDocumentSyncKind,
    TextDocumentSyncOptions, TextDocumentSyncSaveOptions,
};
use miette::Diagnostic;
use thiserror::Error;

/// Why a session ended badly.
#[derive(Debug, Error, Diagnostic)]
pub enum LspError {
    #[error("language server protocol error: {0}")]
    #[diagnostic(
        code(vams::lsp::protocol),
        help("`vams lsp` speaks LSP over standard input and output; start it from an editor")
    )]
    Protocol(#[from] ProtocolError),
    #[error("cannot read the initialize request's parameters: {0}")]
    #[diagnostic(
        code(vams::lsp::initialize),
        help("the client sent an invalid `initialize`")
    )]
    Initialize(#[from] serde_json::Error),
    #[error("the client closed the connection without `exit`")]
    #[diagnostic(code(vams::lsp::no_exit), help("the editor stopped or crashed"))]
    NoExit,
    #[error("the client sent `exit` before `shutdown`")]
    #[diagnostic(
        code(vams::lsp::no_shutdown),
        help("the protocol asks for `shutdown` first; the server exits with code 1")
    )]
    NoShutdown,
    #[error("the connection's threads failed: {0}")]
    #[diagnostic(code(vams::lsp::io), help("the editor closed the pipes"))]
    Io(#[from] std::io::Error),
}

/// Serves one client on standard input and output until it says `exit`.
pub fn serve_stdio(debounce: Duration) -> Result<(), LspError> {
    let (connection, io_threads) = Connection::stdio();
    let result = serve(connection, debounce);
    io_threads.join()?;
    result
}

/// Serves one client on `connection`: the initialize handshake, then the loop.
pub fn serve(connection: Connection, debounce: Duration) -> Result<(), LspError> {
    let capabilities = serde_json::to_value(capabilities())?;
    let (id, params) = connection.initialize_start()?;
    let params: InitializeParams = serde_json::from_value(params)?;
    let result = serde_json::json!({
        "capabilities": capabilities,
        "serverInfo": ServerInfo {
            name: "vams".to_string(),
            version: Some(env!("CARGO_PKG_VERSION").to_string()),
        },
    });
    connection.initialize_finish(id, result)?;
    server::Server::new(connection, roots(&params), debounce).run()
}

/// The folders of the workspace: the client's workspace folders, else its root.
fn roots(params: &InitializeParams) -> Vec<PathBuf> {
    let folders = params.workspace_folders.iter().flatten().map(|f| &f.uri);
    #[allow(deprecated)] // `root_uri` is the fallback of clients without workspace folders
    let root = params.root_uri.iter();
    let mut roots: Vec<PathBuf> = folders.filter_map(|u| u.to_file_path().ok()).collect();
    if roots.is_empty() {
        roots = root.filter_map(|u| u.to_file_path().ok()).collect();
    }
    roots
}

fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Options(
            TextDocumentSyncOptions {
                open_close: Some(true),
                change: Some(TextDocumentSyncKind::FULL),
                save: Some(TextDocumentSyncSaveOptions::SaveOptions(SaveOptions {
                    include_text: Some(false),
                })),
                ..TextDocumentSyncOptions::default()
            },
        )),
        hover_provider: Some(lsp_types::HoverProviderCapability::Simple(true)),
        definition_provider: Some(OneOf::Left(true)),
        references_provider: Some(OneOf::Left(true)),
        document_symbol_provider: Some(OneOf::Left(true)),
        completion_provider: Some(CompletionOptions {
            trigger_characters: Some(vec!["'".to_string()]),
            ..CompletionOptions::default()
        }),
        code_lens_provider: Some(CodeLensOptions {
            resolve_provider: Some(false),
        }),
        execute_command_provider: Some(ExecuteCommandOptions {
            commands: vec![lens::RUN_TESTBENCH.to_string()],
            ..ExecuteCommandOptions::default()
        }),
        ..ServerCapabilities::default()
    }
}
