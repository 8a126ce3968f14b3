//! Elaboration diagnostics, golden: each `tests/elaborate/*.vhd` (top entity `t` unless the
//! first line says `-- top: NAME`) fails to elaborate with the diagnostics of its snapshot,
//! rendered as the CLI prints them.

use std::path::Path;

use vams::diagnostics::render_plain;
use vams::elaborate::{ElabOptions, elaborate};
use vams::parser::parse;
use vams::source::SourceMap;

#[test]
fn diagnostics_match_their_snapshots() {
    let dir = Path::new("tests/elaborate");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("tests/elaborate exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "vhd"))
        .collect();
    files.sort();
    assert!(files.len() >= 10);
    for path in files {
        let text = std::fs::read_to_string(&path).expect("readable test file");
        let name = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or_default()
            .to_string();
        let top = text
            .lines()
            .next()
            .and_then(|l| l.strip_prefix("-- top: "))
            .unwrap_or("t")
            .trim()
            .to_string();
        let mut sources = SourceMap::new();
        let mut ids = vams::stdlib::load(&mut sources);
        ids.push(sources.add(format!("{name}.vhd"), "work", text.clone()));
        let mut files = Vec::new();
        for id in ids {
            let file_text = sources.file(id).text.clone();
            let (ast, errors) = parse(id, &file_text);
            assert!(errors.is_empty(), "{name}: syntax errors {errors:?}");
            files.push((id, ast));
        }
        let options = ElabOptions {
            top,
            generics: Vec::new(),
        };
        let errors = match elaborate(&sources, &files, &options) {
            Ok(_) => panic!("{name} should not elaborate"),
            Err(e) => e,
        };
        let rendered: String = errors
            .iter()
            .map(|e| render_plain(e, &sources))
            .collect::<Vec<_>>()
            .join("\n");
        insta::assert_snapshot!(name, rendered);
    }
}
