//! A minimal LSP client for the tests and the benchmark: starts `vams lsp` as a child process
//! and speaks JSON-RPC to it over its standard input and output (Content-Length framing, by
//! `lsp_server::Message`). Notifications that arrive while waiting for a response are kept
//! for `wait_notification`.

#![allow(dead_code)] // each user takes what it needs

use std::collections::VecDeque;
use std::io::BufReader;
use std::path::Path;
use std::process::{Child, ChildStdin, Command, ExitStatus, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

use lsp_server::{Message, Notification, Request, RequestId, Response};
use lsp_types::Url;
use serde_json::{Value, json};

/// How long any one answer may take before the test fails.
pub const PATIENCE: Duration = Duration::from_secs(60);

pub struct Client {
    child: Child,
    stdin: Option<ChildStdin>,
    incoming: Receiver<Message>,
    /// Notifications received and not yet asked for.
    pub notes: VecDeque<Notification>,
    next_id: i32,
}

impl Client {
    /// Starts `vams lsp` on the workspace folder `root` and completes the handshake.
    pub fn start(root: &Path, debounce_ms: u64) -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_vams"))
            .args(["lsp", "--debounce", &debounce_ms.to_string()])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("vams lsp starts");
        let stdout = child.stdout.take().expect("piped stdout");
        let (tx, incoming) = channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(stdout);
            while let Ok(Some(message)) = Message::read(&mut reader) {
                if tx.send(message).is_err() {
                    break;
                }
            }
        });
        let stdin = child.stdin.take();
        let mut client = Client {
            child,
            stdin,
            incoming,
            notes: VecDeque::new(),
            next_id: 0,
        };
        let uri = Url::from_directory_path(root).expect("an absolute folder");
        let response = client.request(
            "initialize",
            json!({
                "processId": null,
                "rootUri": uri,
                "capabilities": {},
                "workspaceFolders": [{ "uri": uri, "name": "test" }],
            }),
        );
        assert!(response.error.is_none(), "{response:?}");
        client.notify("initialized", json!({}));
        client
    }

    pub fn send(&mut self, message: Message) {
        let stdin = self.stdin.as_mut().expect("stdin open");
        message.write(stdin).expect("the server reads its input");
    }

    pub fn notify(&mut self, method: &str, params: Value) {
        self.send(Message::Notification(Notification::new(
            method.to_string(),
            params,
        )));
    }

    /// Sends a request and waits for its response.
    pub fn request(&mut self, method: &str, params: Value) -> Response {
        self.next_id += 1;
        let id = RequestId::from(self.next_id);
        self.send(Message::Request(Request::new(
            id.clone(),
            method.to_string(),
            params,
        )));
        let deadline = Instant::now() + PATIENCE;
        loop {
            match self.next_message(deadline) {
                Some(Message::Response(r)) if r.id == id => return r,
                Some(Message::Notification(n)) => self.notes.push_back(n),
                Some(_) => {}
                None => panic!("no response to {method} within {PATIENCE:?}"),
            }
        }
    }

    /// The result of a request that must succeed.
    pub fn call(&mut self, method: &str, params: Value) -> Value {
        let response = self.request(method, params);
        assert!(response.error.is_none(), "{method}: {:?}", response.error);
        response.result.unwrap_or(Value::Null)
    }

    /// The first notification `method` (already received or coming within `wait`) whose
    /// parameters satisfy `keep`; the ones before it that do not are dropped.
    pub fn wait_notification(
        &mut self,
        method: &str,
        wait: Duration,
        keep: impl Fn(&Value) -> bool,
    ) -> Option<Value> {
        while let Some(n) = self.notes.pop_front() {
            if n.method == method && keep(&n.params) {
                return Some(n.params);
            }
        }
        let deadline = Instant::now() + wait;
        loop {
            match self.next_message(deadline)? {
                Message::Notification(n) if n.method == method && keep(&n.params) => {
                    return Some(n.params);
                }
                _ => {}
            }
        }
    }

    /// The diagnostics next published for `uri`.
    pub fn diagnostics_for(&mut self, uri: &Url, wait: Duration) -> Option<Vec<Value>> {
        let uri = uri.to_string();
        let params = self.wait_notification("textDocument/publishDiagnostics", wait, |p| {
            p["uri"].as_str() == Some(uri.as_str())
        })?;
        params["diagnostics"].as_array().cloned()
    }

    fn next_message(&mut self, deadline: Instant) -> Option<Message> {
        let wait = deadline.saturating_duration_since(Instant::now());
        self.incoming.recv_timeout(wait).ok()
    }

    /// True while the server process runs.
    pub fn alive(&mut self) -> bool {
        matches!(self.child.try_wait(), Ok(None))
    }

    /// `shutdown` then `exit`; the server's exit status.
    pub fn shutdown(mut self) -> ExitStatus {
        let response = self.request("shutdown", Value::Null);
        assert!(response.error.is_none(), "{response:?}");
        self.notify("exit", Value::Null);
        drop(self.stdin.take());
        self.child.wait().expect("the server exits")
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        // A test that failed half-way leaves no server behind.
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// `textDocument/didOpen` parameters.
pub fn open_params(uri: &Url, text: &str) -> Value {
    json!({ "textDocument": { "uri": uri, "languageId": "vhdl", "version": 1, "text": text } })
}

/// Parameters naming a position in `uri`.
pub fn at(uri: &Url, line: u32, character: u32) -> Value {
    json!({ "textDocument": { "uri": uri }, "position": { "line": line, "character": character } })
}

/// The 0-based line and UTF-16 column of the first `needle` in `text` (ASCII text).
pub fn position_of(text: &str, needle: &str) -> (u32, u32) {
    let offset = text.find(needle).expect("the needle is in the text");
    let before = &text[..offset];
    let line = before.matches('\n').count() as u32;
    let column = (offset - before.rfind('\n').map_or(0, |p| p + 1)) as u32;
    (line, column)
}
