//! The "run testbench" code lens on each `tb_*` / `test_*` entity without ports, and the
//! command it executes: `vams test` on the workspace's folders, filtered to that bench, in a
//! child process of this same executable, so that a long or failing simulation never holds
//! up or takes down the server. The bench's verdict line (`test tb_x ... ok (0.12 s)`) comes
//! back as a `window/showMessage`. It runs the files as saved on disk.

use std::path::PathBuf;
use std::process::Command;

use crossbeam_channel::Sender;
use lsp_server::{Message, Notification};
use lsp_types::notification::{Notification as _, ShowMessage};
use lsp_types::{CodeLens, Command as LspCommand, MessageType, ShowMessageParams};

use crate::app::testbench::discover::is_testbench_name;
use crate::ast::{DesignFile, LibraryUnit};

use super::position::LineIndex;

/// The command a lens runs; its one argument is the bench's name.
pub const RUN_TESTBENCH: &str = "vams.runTestbench";

pub fn code_lenses(file: &DesignFile, index: &LineIndex) -> Vec<CodeLens> {
    file.units
        .iter()
        .filter_map(|u| match &u.unit {
            LibraryUnit::Entity(e) if e.ports.is_empty() && is_testbench_name(&e.name.name) => {
                Some(CodeLens {
                    range: index.range(e.name.span),
                    command: Some(LspCommand {
                        title: "▶ run testbench".to_string(),
                        command: RUN_TESTBENCH.to_string(),
                        arguments: Some(vec![serde_json::Value::String(e.name.name.clone())]),
                    }),
                    data: None,
                })
            }
            _ => None,
        })
        .collect()
}

/// Runs bench `name` found under `roots` on a thread of its own; its verdict goes to the
/// client through `sender` when it ends.
pub fn run_testbench(name: String, roots: Vec<PathBuf>, sender: Sender<Message>) {
    std::thread::spawn(move || {
        let (kind, message) = match verdict(&name, &roots) {
            Ok(line) if line.contains("... ok") => (MessageType::INFO, line),
            Ok(line) => (MessageType::ERROR, line),
            Err(e) => (
                MessageType::ERROR,
                format!("{name}: cannot run `vams test`: {e}"),
            ),
        };
        let params = ShowMessageParams { typ: kind, message };
        let note = Notification::new(ShowMessage::METHOD.to_string(), params);
        // The client may have gone; nothing to tell then.
        let _ = sender.send(Message::Notification(note));
    });
}

/// The verdict line `vams test` prints for `name`, with the first lines of its reasons.
fn verdict(name: &str, roots: &[PathBuf]) -> std::io::Result<String> {
    let exe = std::env::current_exe()?;
    let output = Command::new(exe)
        .arg("test")
        .args(roots)
        .args(["--filter", name, "-j", "1"])
        .output()?;
    let stdout = String::from_utf8_lossy(&output.stdout);
    let prefix = format!("test {name} ... ");
    let line = stdout
        .lines()
        .find(|l| l.starts_with(&prefix))
        .map(str::to_string);
    Ok(match line {
        Some(l) if l.contains("... ok") => l,
        Some(l) => {
            let reasons: Vec<&str> = stdout
                .lines()
                .skip_while(|x| !x.starts_with(&prefix))
                .skip(1)
                .take_while(|x| !x.starts_with("test "))
                .filter(|x| !x.trim().is_empty())
                .take(6)
                .collect();
            format!("{l}\n{}", reasons.join("\n"))
        }
        None => {
            let stderr = String::from_utf8_lossy(&output.stderr);
            let first = stderr.lines().chain(stdout.lines()).take(6);
            format!(
                "test {name} did not run: {}",
                first.collect::<Vec<_>>().join("\n")
            )
        }
    })
}
