//! `vams lsp` under random edits: insertions and deletions of VHDL-ish fragments (keywords,
//! half statements, unbalanced parentheses and quotes, ticks, multi-byte characters, CRLF)
//! anywhere in a real model, each followed by requests at random positions. Every response
//! must be well formed (a result of the method's type or an error, never silence), every
//! published diagnostic must lie within its document, and the server must stay alive to
//! shut down cleanly.

use crate::support::fixed_seed;
use crate::support::lsp_client;

use std::cell::RefCell;

use lsp_client::{Client, at, open_params};
use lsp_types::{
    CodeLens, CompletionResponse, DocumentSymbolResponse, GotoDefinitionResponse, Hover, Location,
    PublishDiagnosticsParams, Url,
};
use proptest::prelude::*;
use proptest::test_runner::TestRunner;
use serde::de::DeserializeOwned;
use serde_json::{Value, json};

/// The edited model.
const MODEL: &str = "models/dc_motor.vhd";

const FRAGMENTS: &[&str] = &[
    "quantity ",
    "terminal t : electrical;",
    " across ",
    " through ",
    "'dot",
    "'",
    "\"",
    " == ",
    "(",
    ")",
    ";",
    "--",
    "begin",
    "end architecture;",
    "entity x is end;",
    "process begin wait; end process;",
    "if q > 0.0 use q == 1.0; else q == 0.0; end use;",
    "break on s;",
    "use ieee.",
    "library ieee;",
    "tb_",
    "é",
    "𝄞",
    "\r\n",
    "\n",
    "x\"ff\"",
    "1.0e3",
    "'above(0.5)",
    "procedural is begin end procedural;",
    "v'integ",
];

/// One edit: where (a fraction of the text), how much to delete there, what to insert.
#[derive(Clone, Debug)]
struct Edit {
    at: f64,
    delete: usize,
    insert: &'static str,
}

fn edit() -> impl Strategy<Value = Edit> {
    (0.0..1.0f64, 0usize..24, prop::sample::select(FRAGMENTS))
        .prop_map(|(at, delete, insert)| Edit { at, delete, insert })
}

fn apply(text: &mut String, e: &Edit) {
    let mut start = (e.at * text.len() as f64) as usize;
    while !text.is_char_boundary(start) {
        start -= 1;
    }
    let mut end = (start + e.delete).min(text.len());
    while !text.is_char_boundary(end) {
        end += 1;
    }
    text.replace_range(start..end, e.insert);
}

/// The response's result parsed as `T`, or its error: either way well formed.
fn well_formed<T: DeserializeOwned>(client: &mut Client, method: &str, params: Value) {
    let response = client.request(method, params);
    // `lsp_server` reads `"result": null` as no result: the null of "nothing here".
    match (response.result, response.error) {
        (None, None) => {}
        (Some(result), None) => {
            if let Err(e) = serde_json::from_value::<Option<T>>(result.clone()) {
                panic!(
                    "{method}: a result that is no {}: {e}: {result}",
                    std::any::type_name::<T>()
                );
            }
        }
        (None, Some(error)) => {
            // A caught internal error is an answer; say it so that it can be fixed.
            eprintln!("{method}: error {}: {}", error.code, error.message);
        }
        (Some(result), Some(error)) => panic!("{method}: both {result} and {error:?}"),
    }
}

/// Every diagnostic published for `uri` lies within `text`.
fn diagnostics_within(client: &mut Client, uri: &Url, text: &str) {
    let lines = text.split('\n').count() as u32;
    while let Some(note) = client.notes.pop_front() {
        if note.method != "textDocument/publishDiagnostics" {
            continue;
        }
        let params: PublishDiagnosticsParams =
            serde_json::from_value(note.params).expect("well-formed diagnostics");
        if &params.uri != uri {
            continue;
        }
        for d in params.diagnostics {
            let (s, e) = (d.range.start, d.range.end);
            assert!((s.line, s.character) <= (e.line, e.character), "{d:?}");
            assert!(e.line < lines, "{d:?} beyond {lines} lines");
        }
    }
}

#[test]
fn random_edits_get_well_formed_answers() {
    let original = std::fs::read_to_string(MODEL).expect("the model");
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("dc_motor.vhd");
    std::fs::write(&path, &original).expect("written");
    let uri = Url::from_file_path(&path).expect("an absolute path");
    let client = RefCell::new(Client::start(dir.path(), 0));
    client
        .borrow_mut()
        .notify("textDocument/didOpen", open_params(&uri, &original));
    let version = RefCell::new(1);
    // Cases are run by hand (one server for all of them), so no regression file is kept.
    let mut config = fixed_seed::config(40);
    config.failure_persistence = None;
    let mut runner = TestRunner::new(config);
    let case = (
        prop::collection::vec(edit(), 1..6),
        prop::collection::vec((0u32..60, 0u32..90), 3),
    );
    runner
        .run(&case, |(edits, positions)| {
            let mut client = client.borrow_mut();
            let mut text = original.clone();
            for e in &edits {
                apply(&mut text, e);
                *version.borrow_mut() += 1;
                client.notify(
                    "textDocument/didChange",
                    json!({
                        "textDocument": { "uri": uri, "version": *version.borrow() },
                        "contentChanges": [{ "text": text }],
                    }),
                );
                for &(line, column) in &positions {
                    let p = at(&uri, line, column);
                    well_formed::<Hover>(&mut client, "textDocument/hover", p.clone());
                    well_formed::<GotoDefinitionResponse>(
                        &mut client,
                        "textDocument/definition",
                        p.clone(),
                    );
                    well_formed::<CompletionResponse>(
                        &mut client,
                        "textDocument/completion",
                        p.clone(),
                    );
                    let mut r = p;
                    r["context"] = json!({ "includeDeclaration": true });
                    well_formed::<Vec<Location>>(&mut client, "textDocument/references", r);
                }
                let doc = json!({ "textDocument": { "uri": uri } });
                well_formed::<DocumentSymbolResponse>(
                    &mut client,
                    "textDocument/documentSymbol",
                    doc.clone(),
                );
                well_formed::<Vec<CodeLens>>(&mut client, "textDocument/codeLens", doc);
                diagnostics_within(&mut client, &uri, &text);
                prop_assert!(client.alive(), "the server died after {edits:?}");
            }
            // Back to the model for the next case; a save elaborates its benches (none).
            client.notify(
                "textDocument/didChange",
                json!({
                    "textDocument": { "uri": uri, "version": *version.borrow() + 1 },
                    "contentChanges": [{ "text": original }],
                }),
            );
            *version.borrow_mut() += 1;
            client.notify(
                "textDocument/didSave",
                json!({ "textDocument": { "uri": uri } }),
            );
            Ok(())
        })
        .expect("every response well formed");
    let client = client.into_inner();
    assert!(client.shutdown().success());
}
