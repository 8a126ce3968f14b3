//! JUnit XML for CI systems: one `<testsuite>` named `vams` with one `<testcase>` per
//! testbench (class name: the file that declares it), times in seconds, and a `<failure>`
//! (reports of severity error or failure) or `<error>` (the testbench could not run: no stop
//! time, elaboration or simulation error) holding the full text.

use std::fmt::Write as _;

/// Why a testbench did not pass.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// It ran, and reported errors or failures.
    Failure,
    /// It could not run to its end.
    Error,
}

/// One testbench's result, as JUnit sees it.
#[derive(Clone, Debug)]
pub struct Case {
    pub name: String,
    pub classname: String,
    pub seconds: f64,
    /// `None` when it passed; else the kind, a one-line message and the full text.
    pub problem: Option<(Problem, String, String)>,
}

/// Escapes text for XML attributes and content; drops characters XML 1.0 cannot hold.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' | '\r' => out.push(c),
            c if (c as u32) < 0x20 => {}
            c => out.push(c),
        }
    }
    out
}

/// The JUnit document.
pub fn junit_xml(cases: &[Case], total_seconds: f64) -> String {
    let count = |p: Problem| {
        cases
            .iter()
            .filter(|c| c.problem.as_ref().is_some_and(|(k, _, _)| *k == p))
            .count()
    };
    let (failures, errors) = (count(Problem::Failure), count(Problem::Error));
    let mut xml = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    // Writing into a String cannot fail.
    let _ = writeln!(
        xml,
        "<testsuites name=\"vams\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" time=\"{total_seconds:.3}\">",
        cases.len()
    );
    let _ = writeln!(
        xml,
        "  <testsuite name=\"vams\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\" skipped=\"0\" time=\"{total_seconds:.3}\">",
        cases.len()
    );
    for case in cases {
        let head = format!(
            "    <testcase name=\"{}\" classname=\"{}\" time=\"{:.3}\"",
            escape(&case.name),
            escape(&case.classname),
            case.seconds
        );
        match &case.problem {
            None => {
                let _ = writeln!(xml, "{head}/>");
            }
            Some((kind, message, text)) => {
                let tag = match kind {
                    Problem::Failure => "failure",
                    Problem::Error => "error",
                };
                let _ = writeln!(xml, "{head}>");
                let _ = writeln!(
                    xml,
                    "      <{tag} message=\"{}\">{}</{tag}>",
                    escape(message),
                    escape(text)
                );
                let _ = writeln!(xml, "    </testcase>");
            }
        }
    }
    xml.push_str("  </testsuite>\n</testsuites>\n");
    xml
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cases() -> Vec<Case> {
        vec![
            Case {
                name: "tb_ok".into(),
                classname: "models/tb_ok.vhd".into(),
                seconds: 0.08,
                problem: None,
            },
            Case {
                name: "tb_bad".into(),
                classname: "models/tb_bad.vhd".into(),
                seconds: 0.1,
                problem: Some((
                    Problem::Failure,
                    "0.6 s: error: vfb < 1 & \"low\"".into(),
                    "0.6 s: error: vfb < 1 & \"low\"\n2 s: failure: stuck".into(),
                )),
            },
            Case {
                name: "tb_nostop".into(),
                classname: "t.vhd".into(),
                seconds: 0.0,
                problem: Some((
                    Problem::Error,
                    "no stop time".into(),
                    "no stop time\u{1}".into(),
                )),
            },
        ]
    }

    #[test]
    fn one_testcase_per_testbench_with_counts_and_times() {
        let xml = junit_xml(&cases(), 0.18);
        assert!(xml.starts_with("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites"));
        assert!(xml.contains(
            "<testsuite name=\"vams\" tests=\"3\" failures=\"1\" errors=\"1\" skipped=\"0\" time=\"0.180\">"
        ));
        assert_eq!(xml.matches("<testcase ").count(), 3);
        assert!(
            xml.contains(
                "<testcase name=\"tb_ok\" classname=\"models/tb_ok.vhd\" time=\"0.080\"/>"
            )
        );
        assert!(xml.contains(
            "<failure message=\"0.6 s: error: vfb &lt; 1 &amp; &quot;low&quot;\">0.6 s: error: vfb &lt; 1 &amp; &quot;low&quot;\n2 s: failure: stuck</failure>"
        ));
        assert!(xml.contains("<error message=\"no stop time\">no stop time</error>"));
        // Balanced elements.
        for tag in ["testsuites", "testsuite", "testcase"] {
            let open = xml.matches(&format!("<{tag} ")).count();
            let closed =
                xml.matches(&format!("</{tag}>")).count() + if tag == "testcase" { 1 } else { 0 };
            assert_eq!(open, closed, "{tag}");
        }
    }
}
