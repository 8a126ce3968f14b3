//! `vams lsp` driven as an editor drives it: the built binary as a child process, JSON-RPC
//! over its standard input and output. Diagnostics with their ranges (and cleared once fixed),
//! elaboration errors of a testbench on save, hover, definition and references across two
//! files, completion after a tick, document symbols, the run-testbench lens, unknown methods
//! and bad parameters answered with errors, and a clean shutdown.

use crate::support::lsp_client;

use std::path::Path;
use std::time::Duration;

use lsp_client::{Client, at, open_params, position_of};
use lsp_types::Url;
use serde_json::{Value, json};

/// The cell of `tests/run/tb_rc.vhd`, in a file of its own.
const CELL: &str = r#"library ieee;
use ieee.electrical_systems.all;

entity rc_cell is
  generic (
    r : real := 1.0e3;
    c : real := 1.0e-6
  );
  port (terminal outp : electrical);
end entity rc_cell;

architecture behavioral of rc_cell is
  terminal inp : electrical;
  quantity vin across iin through inp to electrical_ref;
  quantity vr across ir through inp to outp;
  quantity vout across ic through outp to electrical_ref;
  signal drive : real := 0.0;
begin
  vin == drive;
  vr == r * ir;
  ic == c * vout'dot;
  drive <= 1.0 after 1 ms;
end architecture behavioral;
"#;

/// Its bench, which names the cell from the other file.
const BENCH: &str = r#"-- vams: stop 5 ms
library ieee;
use ieee.electrical_systems.all;

entity tb_rc is
end entity tb_rc;

architecture bench of tb_rc is
  terminal outp : electrical;
  quantity vout across outp to electrical_ref;
begin
  dut : entity work.rc_cell
    port map (outp => outp);

  check : process
  begin
    wait for 2 ms;
    assert abs(vout - 0.63212) < 5.0e-3
      report "vout(2 ms) = " & real'image(vout) & ", expected 0.63212"
      severity error;
    wait;
  end process check;
end architecture bench;
"#;

/// A resistor between two terminals nothing ties to the reference: analysis is content, the
/// analog system of the bench is not.
const FLOATING: &str = r#"library ieee;
use ieee.electrical_systems.all;
entity resistor is
  port (terminal p, n : electrical);
end entity resistor;
architecture a of resistor is
  quantity v across i through p to n;
begin
  v == 1.0e3 * i;
end architecture a;

library ieee;
use ieee.electrical_systems.all;
entity tb_float is
end entity tb_float;
architecture a of tb_float is
  terminal x, y : electrical;
begin
  u : entity work.resistor port map (p => x, n => y);
end architecture a;
"#;

const PATIENCE: Duration = lsp_client::PATIENCE;

/// A workspace folder holding the two files; the client started on it.
fn start() -> (tempfile::TempDir, Client, Url, Url) {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let cell = write(dir.path(), "rc_cell.vhd", CELL);
    let bench = write(dir.path(), "tb_rc.vhd", BENCH);
    let client = Client::start(dir.path(), 20);
    (dir, client, cell, bench)
}

/// A workspace folder holding `text` alone as `name`; the client started on it.
fn start_with(name: &str, text: &str) -> (tempfile::TempDir, Client, Url) {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let uri = write(dir.path(), name, text);
    let client = Client::start(dir.path(), 20);
    (dir, client, uri)
}

fn write(dir: &Path, name: &str, text: &str) -> Url {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the fixture is written");
    Url::from_file_path(path).expect("an absolute path")
}

fn position(text: &str, needle: &str, into: u32) -> (u32, u32) {
    let (line, column) = position_of(text, needle);
    (line, column + into)
}

#[test]
fn an_undeclared_name_is_published_with_its_range_and_cleared_when_fixed() {
    let (_dir, mut client, _cell, bench) = start();
    client.notify("textDocument/didOpen", open_params(&bench, BENCH));
    let broken = BENCH.replace("abs(vout - 0.63212)", "abs(vuot - 0.63212)");
    client.notify(
        "textDocument/didChange",
        json!({
            "textDocument": { "uri": bench, "version": 2 },
            "contentChanges": [{ "text": broken }],
        }),
    );
    let diags = client
        .diagnostics_for(&bench, PATIENCE)
        .expect("diagnostics for the bench");
    assert_eq!(diags.len(), 1, "{diags:?}");
    let (line, column) = position_of(&broken, "vuot");
    assert_eq!(
        diags[0]["range"],
        json!({ "start": { "line": line, "character": column },
                "end": { "line": line, "character": column + 4 } })
    );
    let message = diags[0]["message"].as_str().unwrap_or_default();
    assert!(message.contains("vuot"), "{message}");
    assert_eq!(diags[0]["source"], "vams");
    // Fixed again: the file's diagnostics are cleared.
    client.notify(
        "textDocument/didChange",
        json!({
            "textDocument": { "uri": bench, "version": 3 },
            "contentChanges": [{ "text": BENCH }],
        }),
    );
    let diags = client.diagnostics_for(&bench, PATIENCE).expect("cleared");
    assert!(diags.is_empty(), "{diags:?}");
    assert!(client.shutdown().success());
}

#[test]
fn a_syntax_error_has_the_parse_message_and_help() {
    let (_dir, mut client, _cell, bench) = start();
    let broken = BENCH.replace("wait for 2 ms;", "wait for 2 ms");
    client.notify("textDocument/didOpen", open_params(&bench, &broken));
    let diags = client
        .diagnostics_for(&bench, PATIENCE)
        .expect("diagnostics");
    assert!(!diags.is_empty());
    let message = diags[0]["message"].as_str().unwrap_or_default();
    assert!(message.contains("syntax error"), "{message}");
    assert_eq!(diags[0]["code"], "vams::parse::unexpected");
    // The error is on the line after the missing `;`.
    let (line, _) = position_of(&broken, "assert abs");
    assert_eq!(diags[0]["range"]["start"]["line"], line);
}

#[test]
fn hover_shows_a_quantity_with_its_role() {
    let (_dir, mut client, cell, _bench) = start();
    client.notify("textDocument/didOpen", open_params(&cell, CELL));
    let (line, column) = position(CELL, "ic == c", 0);
    let hover = client.call("textDocument/hover", at(&cell, line, column));
    let text = hover["contents"]["value"].as_str().unwrap_or_default();
    assert!(text.contains("quantity `ic` : `real`"), "{text}");
    assert!(text.contains("**through** quantity"), "{text}");
    assert!(text.contains("from `outp` to `electrical_ref`"), "{text}");
    assert!(text.contains("quantity vout across ic through"), "{text}");
    assert!(text.contains("subtype `current`, unit `A`"), "{text}");
    // Nothing under the cursor: null.
    let hover = client.call("textDocument/hover", at(&cell, 0, 0));
    assert_eq!(hover, Value::Null);
}

#[test]
fn definition_and_references_cross_files() {
    let (_dir, mut client, cell, bench) = start();
    let (line, column) = position(BENCH, "work.rc_cell", 6);
    let found = client.call("textDocument/definition", at(&bench, line, column));
    assert_eq!(found["uri"], json!(cell));
    let (line, column) = position_of(CELL, "rc_cell is");
    assert_eq!(
        found["range"]["start"],
        json!({ "line": line, "character": column })
    );
    let mut params = at(&cell, line, column);
    params["context"] = json!({ "includeDeclaration": true });
    let refs = client.call("textDocument/references", params);
    let uris: Vec<&str> = (refs.as_array().expect("a list").iter())
        .filter_map(|l| l["uri"].as_str())
        .collect();
    assert!(uris.contains(&cell.as_str()), "{refs}");
    assert!(uris.contains(&bench.as_str()), "{refs}");
}

#[test]
fn completion_after_a_tick_offers_the_attributes() {
    let (_dir, mut client, cell, _bench) = start();
    let typed = CELL.replace("ic == c * vout'dot;", "ic == c * vout'");
    client.notify("textDocument/didOpen", open_params(&cell, &typed));
    let (line, column) = position(&typed, "* vout'", 7);
    let items = client.call("textDocument/completion", at(&cell, line, column));
    let labels: Vec<&str> = (items.as_array().expect("a list").iter())
        .filter_map(|i| i["label"].as_str())
        .collect();
    for a in ["dot", "integ", "above", "delayed", "slew"] {
        assert!(labels.contains(&a), "{a} in {labels:?}");
    }
    // Without a tick: the names in scope.
    let (line, column) = position(&typed, "vr == r", 0);
    let items = client.call("textDocument/completion", at(&cell, line, column));
    let labels: Vec<&str> = (items.as_array().expect("a list").iter())
        .filter_map(|i| i["label"].as_str())
        .collect();
    for name in ["vr", "ir", "drive", "r", "electrical"] {
        assert!(labels.contains(&name), "{name} in {labels:?}");
    }
}

#[test]
fn document_symbols_nest_units_declarations_and_processes() {
    let (_dir, mut client, _cell, bench) = start();
    let symbols = client.call(
        "textDocument/documentSymbol",
        json!({ "textDocument": { "uri": bench } }),
    );
    let names = |v: &Value| -> Vec<String> {
        (v.as_array().into_iter().flatten())
            .filter_map(|s| s["name"].as_str().map(str::to_string))
            .collect()
    };
    assert_eq!(names(&symbols), ["tb_rc", "bench"]);
    let architecture = &symbols[1]["children"];
    assert_eq!(names(architecture), ["outp", "vout", "dut", "check"]);
    assert_eq!(architecture[1]["detail"], "across quantity");
    assert_eq!(architecture[3]["detail"], "process");
}

#[test]
fn a_testbench_is_elaborated_on_save() {
    let (_dir, mut client, uri) = start_with("tb_float.vhd", FLOATING);
    // Loading the workspace counts as a save: its benches are elaborated once at the start.
    let diags = client
        .diagnostics_for(&uri, PATIENCE)
        .expect("at the start");
    assert_eq!(diags.len(), 1, "{diags:?}");
    let (line, column) = position_of(FLOATING, "x, y");
    assert_eq!(
        diags[0]["range"]["start"],
        json!({ "line": line, "character": column })
    );
    assert_eq!(diags[0]["code"], "vams::analog::floating");
    assert!(
        diags[0]["message"]
            .as_str()
            .unwrap_or_default()
            .contains("help: connect")
    );
    // Fixed and saved: cleared.
    let fixed = FLOATING.replace("n => y", "n => electrical_ref");
    client.notify(
        "textDocument/didChange",
        json!({
            "textDocument": { "uri": uri, "version": 2 },
            "contentChanges": [{ "text": fixed }],
        }),
    );
    client.notify(
        "textDocument/didSave",
        json!({ "textDocument": { "uri": uri } }),
    );
    let diags = client
        .diagnostics_for(&uri, PATIENCE)
        .expect("after the save");
    assert!(diags.is_empty(), "{diags:?}");
}

#[test]
fn the_code_lens_runs_the_testbench() {
    let (_dir, mut client, _cell, bench) = start();
    let lenses = client.call(
        "textDocument/codeLens",
        json!({ "textDocument": { "uri": bench } }),
    );
    let lens = &lenses[0];
    assert_eq!(lens["command"]["arguments"], json!(["tb_rc"]));
    let command = lens["command"]["command"].clone();
    let result = client.call(
        "workspace/executeCommand",
        json!({ "command": command, "arguments": ["tb_rc"] }),
    );
    assert_eq!(result, Value::Null);
    let shown = client
        .wait_notification("window/showMessage", PATIENCE, |_| true)
        .expect("the verdict");
    let message = shown["message"].as_str().unwrap_or_default();
    assert!(message.starts_with("test tb_rc ... ok"), "{message}");
}

#[test]
fn unknown_methods_and_bad_parameters_answer_errors() {
    let (_dir, mut client, cell, _bench) = start();
    let response = client.request("textDocument/semanticTokens/full", json!({}));
    assert_eq!(response.error.expect("an error").code, -32601);
    let response = client.request("textDocument/hover", json!({ "nonsense": 1 }));
    assert_eq!(response.error.expect("an error").code, -32602);
    // A position far outside the text, in a document the server knows.
    let hover = client.call("textDocument/hover", at(&cell, 9999, 9999));
    assert_eq!(hover, Value::Null);
    // A document it does not know.
    let unknown = Url::parse("untitled:Untitled-1").expect("a URI");
    assert_eq!(
        client.call("textDocument/hover", at(&unknown, 0, 0)),
        Value::Null
    );
    assert!(client.alive());
    assert!(client.shutdown().success());
}

#[test]
fn an_unsaved_buffer_with_crlf_and_multi_byte_text_is_cleared_when_closed() {
    let (_dir, mut client, _cell, _bench) = start();
    // A comment with characters of 2 and 4 bytes (1 and 2 UTF-16 units) before the error,
    // CRLF line ends.
    let text = "-- é𝄞\r\nentity e is\r\nend entity e;\r\narchitecture a of e is\r\n\
                begin\r\n  é𝄞 : assert undeclared_name;\r\nend architecture a;\r\n";
    let uri = Url::parse("untitled:Untitled-1").expect("a URI");
    client.notify("textDocument/didOpen", open_params(&uri, text));
    let diags = client.diagnostics_for(&uri, PATIENCE).expect("diagnostics");
    assert!(!diags.is_empty(), "{diags:?}");
    // The lexer's complaint about the label's first character: line 5, column 2 in UTF-16.
    assert_eq!(
        diags[0]["range"]["start"],
        json!({ "line": 5, "character": 2 }),
        "{diags:?}"
    );
    client.notify(
        "textDocument/didClose",
        json!({ "textDocument": { "uri": uri } }),
    );
    let diags = client.diagnostics_for(&uri, PATIENCE).expect("cleared");
    assert!(diags.is_empty(), "{diags:?}");
}

#[test]
fn saving_a_cell_elaborates_the_bench_that_uses_it() {
    let (_dir, mut client, cell, bench) = start();
    // The cell loses an equation: analysis is content, the bench's analog system is not.
    let short = CELL.replace("  vin == drive;\n", "");
    client.notify("textDocument/didOpen", open_params(&cell, &short));
    client.notify(
        "textDocument/didSave",
        json!({ "textDocument": { "uri": cell } }),
    );
    let diags = client
        .diagnostics_for(&cell, PATIENCE)
        .expect("after the save");
    assert_eq!(diags.len(), 1, "{diags:?}");
    assert_eq!(diags[0]["code"], "vams::analog::count");
    let (line, column) = position_of(&short, "vr == r");
    assert_eq!(
        diags[0]["range"]["start"],
        json!({ "line": line, "character": column })
    );
    // Saving the bench's own file keeps it (the cell is as it was).
    client.notify(
        "textDocument/didSave",
        json!({ "textDocument": { "uri": bench } }),
    );
    let sym = client.call(
        "textDocument/documentSymbol",
        json!({ "textDocument": { "uri": cell } }),
    );
    assert!(sym.is_array());
    assert!(client.notes.iter().all(|n| n.params["uri"] != json!(cell)));
    // Mended and saved: cleared.
    client.notify(
        "textDocument/didChange",
        json!({
            "textDocument": { "uri": cell, "version": 2 },
            "contentChanges": [{ "text": CELL }],
        }),
    );
    client.notify(
        "textDocument/didSave",
        json!({ "textDocument": { "uri": cell } }),
    );
    let diags = client.diagnostics_for(&cell, PATIENCE).expect("cleared");
    assert!(diags.is_empty(), "{diags:?}");
}
