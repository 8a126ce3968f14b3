//! `vams lsp` latency (issue 19): a 5 000-line file, one character changed, the time until its
//! diagnostics arrive. The release binary runs as a child process with `--debounce 0` (an
//! editor's 150 ms of quiet come on top), driven over its standard input and output by the
//! tests' client; each change alternately breaks a name in the middle of the file and mends
//! it, so that every change publishes diagnostics. The file repeats an entity with generics,
//! terminals, branch quantities, simultaneous statements and a process; the goal is 100 ms.
//!
//! A plain program, not criterion: `cargo bench --bench lsp` (`LSP_BENCH_EDITS=N` edits,
//! default 40).

#[path = "../tests/it/support/lsp_client.rs"]
mod lsp_client;

use std::time::{Duration, Instant};

use lsp_client::{Client, open_params};
use lsp_types::Url;
use serde_json::json;

/// One block of the generated file (25 lines); `{n}` is its number.
const BLOCK: &str = "library ieee;
use ieee.electrical_systems.all;

entity cell_{n} is
  generic (r : real := 1.0e3; c : real := 1.0e-6);
  port (terminal p, n : electrical);
end entity cell_{n};

architecture behavioral of cell_{n} is
  terminal mid : electrical;
  quantity vr across ir through p to mid;
  quantity vc across ic through mid to n;
  signal level : real := 0.0;
begin
  vr == r * ir;
  ic == c * vc'dot;
  watch : process
  begin
    wait for 1 ms;
    level <= level + 1.0;
    assert level < 1.0e6 report \"cell_{n} overflows\" severity warning;
  end process watch;
end architecture behavioral;

";

const LINES: usize = 5_000;

fn main() {
    let blocks = LINES / BLOCK.lines().count();
    let text: String = (0..blocks)
        .map(|n| BLOCK.replace("{n}", &n.to_string()))
        .collect();
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("cells.vhd");
    std::fs::write(&path, &text).expect("written");
    let uri = Url::from_file_path(&path).expect("an absolute path");
    let edits: usize = std::env::var("LSP_BENCH_EDITS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(40);

    let started = Instant::now();
    let mut client = Client::start(dir.path(), 0);
    client.notify("textDocument/didOpen", open_params(&uri, &text));
    // The first analysis of the file (the workspace's load did it; the open finds it
    // unchanged), answered by a request that waits for it.
    client.call(
        "textDocument/documentSymbol",
        json!({ "textDocument": { "uri": uri } }),
    );
    let first = started.elapsed();

    // One character in the middle block: `r * ir` becomes `q * ir` (undeclared) and back.
    let middle = text
        .find(&format!("entity cell_{} is", blocks / 2))
        .expect("the block");
    let at = middle + text[middle..].find("vr == r").expect("the equation") + 6;
    let mut broken = text.clone();
    broken.replace_range(at..at + 1, "q");
    let mut times = Vec::new();
    for i in 0..edits {
        let now = if i % 2 == 0 { &broken } else { &text };
        let sent = Instant::now();
        client.notify(
            "textDocument/didChange",
            json!({
                "textDocument": { "uri": uri, "version": i + 2 },
                "contentChanges": [{ "text": now }],
            }),
        );
        let diags = client
            .diagnostics_for(&uri, Duration::from_secs(60))
            .expect("diagnostics after the change");
        times.push(sent.elapsed());
        assert_eq!(diags.len(), usize::from(i % 2 == 0), "{diags:?}");
    }
    assert!(client.shutdown().success());

    times.sort();
    let ms = |d: Duration| d.as_secs_f64() * 1e3;
    let median = times[times.len() / 2];
    let p90 = times[times.len() * 9 / 10];
    println!(
        "lsp: {} lines, {} units; start and first analysis {:.0} ms",
        text.lines().count(),
        blocks * 2,
        ms(first)
    );
    println!(
        "lsp: one-character change to its diagnostics, {} edits: median {:.1} ms, p90 {:.1} ms, max {:.1} ms (goal 100 ms)",
        times.len(),
        ms(median),
        ms(p90),
        ms(*times.last().expect("some edits"))
    );
}
