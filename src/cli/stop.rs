//! The stop time a source file asks for: a comment `-- vams: stop 6 sec` in the file that
//! declares the entity (the first such comment counts).

use crate::ast::LibraryUnit;
use crate::source::{FileId, SourceMap, Span};

use super::error::SourceError;
use super::load::Loaded;
use super::time::parse_positive_time;

/// The stop comment of a file: `None` without one, else its time or the diagnostic for a bad
/// one (pointing at the text after `stop`).
pub fn stop_comment(sources: &SourceMap, file: FileId) -> Option<Result<f64, SourceError>> {
    let text = sources.file(file).text.clone();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let start = offset;
        offset += line.len();
        let Some(dashes) = line.find("--") else {
            continue;
        };
        let comment = &line[dashes + 2..];
        let body = comment.trim_start();
        if body.len() < 5 || !body[..5].eq_ignore_ascii_case("vams:") {
            continue;
        }
        let after_tag = body[5..].trim_start();
        if after_tag.len() < 4 || !after_tag[..4].eq_ignore_ascii_case("stop") {
            continue;
        }
        let value = after_tag[4..].trim();
        let value_start = start + dashes + 2 + (comment.len() - after_tag[4..].trim_start().len());
        let span = Span::new(file, value_start, value_start + value.len());
        return Some(
            parse_positive_time(value)
                .map_err(|problem| SourceError::BadStopComment { span, problem }),
        );
    }
    None
}

/// The user file (library `work`) that declares entity `name`.
pub fn declaring_file(loaded: &Loaded, name: &str) -> Option<FileId> {
    loaded
        .files
        .iter()
        .filter(|(id, _)| loaded.sources.file(*id).library == "work")
        .find(|(_, ast)| {
            ast.units.iter().any(
                |u| matches!(&u.unit, LibraryUnit::Entity(e) if e.name.name.eq_ignore_ascii_case(name)),
            )
        })
        .map(|(id, _)| *id)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(text: &str) -> (SourceMap, FileId) {
        let mut sources = SourceMap::new();
        let id = sources.add("tb.vhd", "work", text.into());
        (sources, id)
    }

    #[test]
    fn reads_the_first_stop_comment() {
        for (text, want) in [
            ("-- vams: stop 6 sec\nentity tb is end;", 6.0),
            ("entity tb is end;  --VAMS: STOP 10ms", 10e-3),
            ("-- other\n-- vams:stop 2.5 us\n-- vams: stop 1 s\n", 2.5e-6),
        ] {
            let (sources, id) = map(text);
            let got = stop_comment(&sources, id).unwrap().unwrap();
            assert!((got - want).abs() < 1e-15, "{text}: {got}");
        }
        let (sources, id) = map("-- vams is great\n-- stop 6 s\nentity tb is end;");
        assert!(stop_comment(&sources, id).is_none());
    }

    #[test]
    fn bad_stop_comment_points_at_its_value() {
        let (sources, id) = map("\n-- vams: stop  soon \n");
        let err = stop_comment(&sources, id).unwrap().unwrap_err();
        let SourceError::BadStopComment { span, .. } = &err;
        assert_eq!(sources.snippet(*span), "soon");
        let rendered = crate::diagnostics::render_plain(&err, &sources);
        assert!(rendered.contains("vams::cli::bad_stop_comment") && rendered.contains("tb.vhd:2"));
    }
}
