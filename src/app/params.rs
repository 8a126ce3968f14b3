//! Generic overrides: `-g NAME=VALUE` arguments and `--params FILE` (`name=value` lines, `#` and
//! `--` comments, blank lines). `-g` wins over the file; later lines win over earlier ones.

use std::path::Path;
use std::sync::Arc;

use miette::{Diagnostic, NamedSource, SourceSpan};
use thiserror::Error;

/// Problems with a `--params` file.
#[derive(Debug, Error, Diagnostic)]
pub enum ParamsError {
    #[error("cannot read the parameter file `{path}`: {reason}")]
    #[diagnostic(
        code(vams::params::unreadable),
        help("check the path given to --params")
    )]
    Unreadable { path: String, reason: String },
    /// `r 4.0` (no `=`), `=4.0` (no name), `r=` (no value).
    #[error("{path}:{line}: {problem}")]
    #[diagnostic(
        code(vams::params::bad_line),
        help("write one `name=value` per line, e.g. `r=4.0`; `#` or `--` starts a comment")
    )]
    BadLine {
        path: String,
        line: usize,
        problem: &'static str,
        #[source_code]
        src: Arc<NamedSource<String>>,
        #[label("here")]
        span: SourceSpan,
    },
}

/// Parses `NAME=VALUE` from the command line (`-g`): the name is lower-cased (VHDL names are
/// case-insensitive), the value kept as VHDL literal text.
pub fn parse_generic(text: &str) -> Result<(String, String), String> {
    match split_assignment(text) {
        Ok(pair) => Ok(pair),
        Err(problem) => Err(format!(
            "`{text}`: {problem}; write NAME=VALUE, e.g. -g r=4.0"
        )),
    }
}

fn split_assignment(text: &str) -> Result<(String, String), &'static str> {
    let (name, value) = text.split_once('=').ok_or("expected `name=value`")?;
    let (name, value) = (name.trim(), value.trim());
    if name.is_empty() {
        return Err("the name before `=` is missing");
    }
    if !is_generic_path(name) {
        return Err("the name is not a VHDL identifier or an instance path (`u_motor.r`)");
    }
    if value.is_empty() {
        return Err("the value after `=` is missing");
    }
    Ok((name.to_ascii_lowercase(), value.to_string()))
}

/// A generic's name: an identifier (`r`), or the path of an instance's generic from the top
/// (`dut.u_motor.r`, `u_cell(3).c`: a `for ... generate` iteration by its index).
pub fn is_generic_path(name: &str) -> bool {
    let identifier = |s: &str| {
        s.starts_with(|c: char| c.is_ascii_alphabetic())
            && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    };
    name.split('.')
        .all(|segment| match segment.split_once('(') {
            Some((label, index)) => {
                identifier(label)
                    && index
                        .strip_suffix(')')
                        .and_then(|i| i.strip_prefix('-').or(Some(i)))
                        .is_some_and(|i| !i.is_empty() && i.chars().all(|c| c.is_ascii_digit()))
            }
            None => identifier(segment),
        })
}

/// Parses the text of a parameter file named `path` (for messages).
pub fn parse_params(path: &str, text: &str) -> Result<Vec<(String, String)>, ParamsError> {
    let mut out = Vec::new();
    let mut offset = 0;
    for (k, raw) in text.split_inclusive('\n').enumerate() {
        let start = offset;
        offset += raw.len();
        let line = raw.trim_end_matches(['\n', '\r']);
        let content = match (line.find('#'), line.find("--")) {
            (Some(a), Some(b)) => &line[..a.min(b)],
            (Some(a), None) | (None, Some(a)) => &line[..a],
            (None, None) => line,
        };
        if content.trim().is_empty() {
            continue;
        }
        let pair = split_assignment(content).map_err(|problem| {
            let lead = content.len() - content.trim_start().len();
            ParamsError::BadLine {
                path: path.to_string(),
                line: k + 1,
                problem,
                src: Arc::new(NamedSource::new(path, text.to_string())),
                span: SourceSpan::new((start + lead).into(), content.trim().len()),
            }
        })?;
        out.push(pair);
    }
    Ok(out)
}

/// Reads a parameter file.
pub fn read_params(path: &Path) -> Result<Vec<(String, String)>, ParamsError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| ParamsError::Unreadable {
        path: name.clone(),
        reason: e.to_string(),
    })?;
    parse_params(&name, &text)
}

/// The generics to elaborate with: the file's, then `-g`'s, a later one replacing an earlier
/// one of the same name (in its first position, so the order stays that of first mention).
pub fn merge_generics(
    file: Vec<(String, String)>,
    command_line: &[(String, String)],
) -> Vec<(String, String)> {
    let mut out: Vec<(String, String)> = Vec::new();
    for (name, value) in file.into_iter().chain(command_line.iter().cloned()) {
        match out.iter_mut().find(|(n, _)| *n == name) {
            Some(slot) => slot.1 = value,
            None => out.push((name, value)),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_lines_comments_and_blank_lines() {
        let text = "# motor\nr=4.0\n\n  L = 3.0e-3  -- henry\nkt=0.015 # N m/A\r\nv=10 ms\n";
        let got = parse_params("m.params", text).unwrap();
        let want = [
            ("r", "4.0"),
            ("l", "3.0e-3"),
            ("kt", "0.015"),
            ("v", "10 ms"),
        ];
        assert_eq!(got.len(), want.len());
        for ((n, v), (wn, wv)) in got.iter().zip(want) {
            assert_eq!((n.as_str(), v.as_str()), (wn, wv));
        }
    }

    #[test]
    fn bad_lines_name_the_file_and_line_and_point_at_the_text() {
        for (text, line, problem) in [
            ("r=4.0\nl 3.0e-3\n", 2, "expected `name=value`"),
            ("\n\n=4\n", 3, "the name before `=` is missing"),
            ("r=\n", 1, "the value after `=` is missing"),
            (
                "2r=1\n",
                1,
                "the name is not a VHDL identifier or an instance path (`u_motor.r`)",
            ),
        ] {
            let err = parse_params("m.params", text).unwrap_err();
            let ParamsError::BadLine { line: l, span, .. } = &err else {
                panic!("{err:?}");
            };
            assert_eq!(*l, line, "{text:?}");
            assert_eq!(err.to_string(), format!("m.params:{line}: {problem}"));
            let start = span.offset();
            let marked = &text[start..start + span.len()];
            assert!(!marked.is_empty() && text.lines().nth(line - 1) == Some(marked));
        }
    }

    #[test]
    fn command_line_generics_override_the_file() {
        let file = parse_params("p", "r=4.0\nl=3e-3\n").unwrap();
        let cli = [
            parse_generic("R=8.0").unwrap(),
            parse_generic("j=1e-6").unwrap(),
        ];
        let merged = merge_generics(file, &cli);
        let as_str: Vec<(&str, &str)> = merged
            .iter()
            .map(|(n, v)| (n.as_str(), v.as_str()))
            .collect();
        assert_eq!(as_str, [("r", "8.0"), ("l", "3e-3"), ("j", "1e-6")]);
        assert!(parse_generic("r").unwrap_err().contains("NAME=VALUE"));
        assert!(parse_generic("r=").is_err());
    }

    #[test]
    fn instance_paths_are_generic_names() {
        for good in ["r", "dut.u_motor.r", "u_cell(3).c", "a.b_2(10).x"] {
            assert!(is_generic_path(good), "{good}");
        }
        for bad in [
            "",
            "2r",
            "dut..r",
            "u_cell(x).c",
            "u_cell(3.c",
            "a.",
            ".a",
            "u()",
        ] {
            assert!(!is_generic_path(bad), "{bad}");
        }
        assert_eq!(
            parse_generic("DUT.U_Motor.R=5").unwrap(),
            ("dut.u_motor.r".into(), "5".into())
        );
    }

    #[test]
    fn unreadable_file_is_a_diagnostic() {
        let err = read_params(Path::new("/no/such/file.params")).unwrap_err();
        assert!(matches!(err, ParamsError::Unreadable { .. }));
    }
}
