//! What a source file asks of `vams run` and `vams test` in `-- vams:` comments: the stop
//! time (`-- vams: stop 6 sec`, the first such comment counts), the plot's panels
//! (`-- vams: panel vref, vfb`, one comment per panel, in order) and assertions on the
//! small-signal response (`-- vams: assert gain_db(vout, 1kHz) > -3.1`, checked by `vams
//! test`).

use crate::ast::LibraryUnit;
use crate::diagnostics::{Finding, Level};
use crate::source::{FileId, SourceMap, Span};

use super::ac_assert::AcAssertion;
use super::compile::NotCompiled;
use super::error::{CliError, SourceError};
use super::load::Loaded;
use super::time::parse_positive_time;

/// The `-- vams: KEYWORD value` comments of a file, in order: each value (trimmed) with its
/// span (keyword matched without regard to case).
fn keyword_comments(sources: &SourceMap, file: FileId, keyword: &str) -> Vec<(String, Span)> {
    let text = &sources.file(file).text;
    let mut out = Vec::new();
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
        match after_tag.get(..keyword.len()) {
            Some(k) if k.eq_ignore_ascii_case(keyword) => {}
            _ => continue,
        }
        let rest = &after_tag[keyword.len()..];
        let value = rest.trim();
        let value_start = start + dashes + 2 + (comment.len() - rest.trim_start().len());
        out.push((
            value.to_string(),
            Span::new(file, value_start, value_start + value.len()),
        ));
    }
    out
}

/// The stop comment of a file: `None` without one, else its time or the diagnostic for a bad
/// one (pointing at the text after `stop`).
pub fn stop_comment(sources: &SourceMap, file: FileId) -> Option<Result<f64, SourceError>> {
    let (value, span) = keyword_comments(sources, file, "stop").into_iter().next()?;
    Some(
        parse_positive_time(&value)
            .map_err(|problem| SourceError::BadStopComment { span, problem }),
    )
}

/// The plot panels a file asks for: each `-- vams: panel a, b` comment is one panel of the
/// names listed (lower case), in file order.
pub fn panel_comments(sources: &SourceMap, file: FileId) -> Vec<Vec<String>> {
    let text = sources.file(file).text.clone();
    text.lines()
        .filter_map(|line| {
            let body = line[line.find("--")? + 2..].trim_start();
            let tag = body.get(..5)?;
            let rest = body[5..].trim_start();
            let keyword = rest.get(..5)?;
            if !tag.eq_ignore_ascii_case("vams:") || !keyword.eq_ignore_ascii_case("panel") {
                return None;
            }
            let names: Vec<String> = rest[5..]
                .split(',')
                .map(|n| n.trim().to_ascii_lowercase())
                .filter(|n| !n.is_empty())
                .collect();
            (!names.is_empty()).then_some(names)
        })
        .collect()
}

/// The small-signal assertions of a file, `-- vams: assert EXPR`, in order; a bad one is a
/// diagnostic pointing at its text.
pub fn assert_comments(sources: &SourceMap, file: FileId) -> Result<Vec<AcAssertion>, SourceError> {
    keyword_comments(sources, file, "assert")
        .into_iter()
        .map(|(value, span)| {
            AcAssertion::parse(&value).map_err(|e| SourceError::BadAssertComment {
                span,
                problem: match e {
                    CliError::AcAssertion { problem, .. } => problem,
                    e => e.to_string(),
                },
            })
        })
        .collect()
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

/// The stop time of a run of `top`: `given`, or else the stop comment of the file that
/// declares it; without either, or with a comment that does not read, why not.
pub fn stop_time(loaded: &Loaded, top: &str, given: Option<f64>) -> Result<f64, NotCompiled> {
    if let Some(t) = given {
        return Ok(t);
    }
    let no_stop = |findings| NotCompiled {
        findings,
        error: CliError::NoStop {
            top: top.to_string(),
        }
        .into(),
    };
    match declaring_file(loaded, top).and_then(|f| stop_comment(&loaded.sources, f)) {
        Some(Ok(t)) => Ok(t),
        Some(Err(e)) => Err(no_stop(vec![Finding::located(
            &e,
            &loaded.sources,
            Level::Error,
        )])),
        None => Err(no_stop(Vec::new())),
    }
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
    fn reads_panel_comments_in_order() {
        let (sources, id) = map(
            "-- vams: panel VREF, vfb\n-- vams: panel i_motor\n-- vams: panel\n-- vams: stop 1 s\n",
        );
        assert_eq!(
            panel_comments(&sources, id),
            vec![
                vec!["vref".to_string(), "vfb".into()],
                vec!["i_motor".into()]
            ]
        );
        let (sources, id) = map("-- vams: stop 1 s\n");
        assert!(panel_comments(&sources, id).is_empty());
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
    fn reads_assert_comments_and_points_at_a_bad_one() {
        let (sources, id) = map(
            "-- vams: assert gain_db(vout, 1kHz) > -3.1\n-- vams: stop 1 ms\n--vams: ASSERT phase_deg(vout, 10Hz) < 0\n",
        );
        let found = assert_comments(&sources, id).unwrap();
        assert_eq!(found.len(), 2);
        assert_eq!(found[1].text, "phase_deg(vout, 10Hz) < 0");
        let (sources, id) = map("\n-- vams: assert  gain_db(vout, 1kHz) = 3 \n");
        let Err(SourceError::BadAssertComment { span, problem }) = assert_comments(&sources, id)
        else {
            panic!("a bad assertion is refused");
        };
        assert_eq!(sources.snippet(span), "gain_db(vout, 1kHz) = 3");
        assert!(problem.contains("expected a comparison"), "{problem}");
    }

    #[test]
    fn bad_stop_comment_points_at_its_value() {
        let (sources, id) = map("\n-- vams: stop  soon \n");
        let err = stop_comment(&sources, id).unwrap().unwrap_err();
        let SourceError::BadStopComment { span, .. } = &err else {
            panic!("{err:?}");
        };
        assert_eq!(sources.snippet(*span), "soon");
        let rendered = crate::diagnostics::render_plain(&err, &sources);
        assert!(rendered.contains("vams::cli::bad_stop_comment") && rendered.contains("tb.vhd:2"));
    }
}
