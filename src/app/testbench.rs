//! `vams test`: finds the testbenches under the given paths, runs each to its stop time on
//! N threads, prints one line per testbench in name order and a closing count, and optionally
//! writes JUnit XML. A testbench fails on any report of severity error or failure, and on any
//! error that keeps it from running to its end.

pub mod discover;
pub mod junit;

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::analysis::{Analysis, UnitKind, analyse};
use crate::ast::DesignFile;
use crate::elaborate::{ElabOptions, ElabWarning, elaborate_analysed};
use crate::kernel::{Severity, SimError, SimOptions, SimResult, simulate};
use crate::source::{FileId, SourceMap};

use super::ac::linearise;
use super::ac_assert::{AcAssertion, AcVerdict, assertion_probes, check_assertions};
use super::error::CliError;
use super::load::{LibrarySources, Loaded, load_with_libraries};
use super::notes::Notes;
use super::parallel::run_in_order;
use super::render::{format_report, render, render_located, render_sim_error};
use super::stop::{assert_comments, stop_comment};
use discover::Testbench;
use discover::discover;
use junit::{Case, Problem};

/// How one testbench went.
#[derive(Clone, Debug)]
pub struct Verdict {
    pub seconds: f64,
    /// `None` when it passed; else the kind and the text (report lines or diagnostics).
    pub problem: Option<(Problem, String)>,
    /// Elaboration warnings (an unbound component instance), shown under the verdict line.
    pub warnings: String,
}

/// The search paths: those given, or those of `tests/` and `models/` that exist.
pub fn default_paths(given: &[PathBuf], root: &Path) -> Vec<PathBuf> {
    if !given.is_empty() {
        return given.to_vec();
    }
    ["tests", "models"]
        .iter()
        .map(|d| root.join(d))
        .filter(|p| p.is_dir())
        .map(|p| p.strip_prefix(root).map(Path::to_path_buf).unwrap_or(p))
        .collect()
}

/// Runs one testbench to its end and judges it: `None` when it passed.
pub fn run_bench(
    loaded: &Loaded,
    (analysis, files): (&Analysis, &[(FileId, DesignFile)]),
    bench: &Testbench,
    default_stop: Option<f64>,
    warnings: &mut String,
) -> Option<(Problem, String)> {
    let sources = &loaded.sources;
    if let Some((_, errors)) = loaded.syntax_errors.iter().find(|(f, _)| *f == bench.file) {
        let text: String = errors.iter().map(|e| render_located(e, sources)).collect();
        return Some((Problem::Error, text));
    }
    // The analysis errors of every unit the bench reaches (not those of other benches).
    let entity = analysis
        .units
        .iter()
        .position(|u| u.kind == UnitKind::Entity && u.file == bench.file && u.name == bench.name);
    if let Some(entity) = entity {
        let text: String = analysis
            .reached_from(entity)
            .into_iter()
            .flat_map(|u| &analysis.units[u].errors)
            .map(|e| render_located(e, sources))
            .collect();
        if !text.is_empty() {
            return Some((Problem::Error, text));
        }
    }
    let assertions = match assert_comments(sources, bench.file) {
        Ok(a) => a,
        Err(e) => return Some((Problem::Error, render_located(&e, sources))),
    };
    // A testbench with assertions on its small-signal response and no stop time is an AC
    // test only.
    let stop = match (stop_comment(sources, bench.file), default_stop) {
        (Some(Ok(t)), _) | (None, Some(t)) => Some(t),
        (Some(Err(e)), _) => return Some((Problem::Error, render_located(&e, sources))),
        (None, None) if !assertions.is_empty() => None,
        (None, None) => {
            let e = CliError::NoStop {
                top: bench.name.clone(),
            };
            return Some((Problem::Error, render(&e)));
        }
    };
    let options = ElabOptions {
        top: bench.name.clone(),
        generics: Vec::new(),
    };
    let design = match elaborate_analysed(analysis, sources, files, &options) {
        Ok(d) => d,
        Err(errors) => {
            let text = errors.iter().map(|e| render_located(e, sources)).collect();
            return Some((Problem::Error, text));
        }
    };
    for u in &design.warnings {
        warnings.push_str(&render_located(&ElabWarning::from(u), sources));
    }
    if let Some(stop) = stop {
        let sim = SimOptions {
            stop,
            ..SimOptions::default()
        };
        // Reports from no process are the simulator's own warnings (an implicit through
        // quantity); the model's own reports judge the run.
        let mut own_warning = |r: &crate::kernel::Report| {
            if r.process.is_empty() && r.severity == Severity::Warning {
                warnings.push_str(&format_report(r, sources));
                warnings.push('\n');
            }
        };
        if let Some(problem) = judge(simulate(&design, &sim, &mut own_warning), sources) {
            return Some(problem);
        }
    }
    if assertions.is_empty() {
        return None;
    }
    judge_response(&design, sources, &assertions)
}

/// Checks the small-signal assertions of a testbench: `None` when every one holds.
fn judge_response(
    design: &crate::design::Design,
    sources: &SourceMap,
    assertions: &[AcAssertion],
) -> Option<(Problem, String)> {
    if design.spectral_sources.is_empty() {
        let e = CliError::NoSpectralSource {
            top: design.top.clone(),
        };
        return Some((Problem::Error, render(&e)));
    }
    let probes = match assertion_probes(design, assertions) {
        Ok(p) => p,
        Err(e) => return Some((Problem::Error, render(&e))),
    };
    let mut linearised = match linearise(design, sources) {
        Ok(l) => l,
        Err(failure) => {
            let text = format!("{}{}", failure.diagnostics, render(&failure.error));
            return Some((Problem::Error, text));
        }
    };
    match check_assertions(&design.top, &mut linearised, assertions, &probes) {
        Err(e) => Some((Problem::Error, render(&e))),
        Ok(verdicts) if verdicts.iter().all(|v| v.holds) => None,
        Ok(verdicts) => {
            let lines: Vec<String> = (verdicts.iter())
                .filter(|v| !v.holds)
                .map(AcVerdict::line)
                .collect();
            Some((Problem::Failure, lines.join("\n")))
        }
    }
}

/// The verdict on a finished (or failed) run: reports of severity error or failure, or the
/// simulation error; `None` when it passed.
pub fn judge(run: Result<SimResult, SimError>, sources: &SourceMap) -> Option<(Problem, String)> {
    match run {
        Err(e) => Some((Problem::Error, render_sim_error(&e, sources))),
        Ok(result) => {
            let failing: Vec<String> = result
                .reports
                .iter()
                .filter(|r| r.severity >= Severity::Error)
                .map(|r| format_report(r, sources))
                .collect();
            (!failing.is_empty()).then(|| (Problem::Failure, failing.join("\n")))
        }
    }
}

/// The one-line gist of a failure text: the message of its first rendered diagnostic (the
/// line miette marks with `×`), else its first non-empty line.
pub fn headline(text: &str) -> String {
    let lines = || text.lines().map(str::trim).filter(|l| !l.is_empty());
    lines()
        .find_map(|l| l.strip_prefix('×'))
        .map(|l| l.trim().to_string())
        .or_else(|| lines().next().map(str::to_string))
        .unwrap_or_default()
}

/// The line for one testbench, its indented warnings, and its indented failure text.
pub fn verdict_lines(name: &str, verdict: &Verdict) -> String {
    let (mut out, text) = match &verdict.problem {
        None => (
            format!("test {name} ... ok ({:.2} s)\n", verdict.seconds),
            "",
        ),
        Some((_, text)) => (
            format!("test {name} ... FAILED ({:.2} s)\n", verdict.seconds),
            text.as_str(),
        ),
    };
    for line in verdict.warnings.lines().chain(text.lines()) {
        out.push_str("    ");
        out.push_str(line);
        out.push('\n');
    }
    out
}

/// What `vams test` runs: where its testbenches are, which, and how.
#[derive(Debug, Clone, Default)]
pub struct TestOptions {
    /// Files or directories searched ([`default_paths`] gives the command's default).
    pub paths: Vec<PathBuf>,
    pub libraries: Vec<LibrarySources>,
    /// Only the testbenches whose name contains this.
    pub filter: Option<String>,
    /// Stop time of testbenches whose file has no `-- vams: stop` comment.
    pub stop: Option<f64>,
    /// Testbenches run at once; `None`: the number of CPUs.
    pub jobs: Option<u32>,
}

/// The testbenches run: one case each (for a JUnit report), and the wall time.
#[derive(Debug)]
pub struct Tested {
    pub cases: Vec<junit::Case>,
    pub seconds: f64,
}

/// Runs every testbench under `options.paths` on `options.jobs` threads: `verdict` is told
/// each one's result in discovery order as it is known; notes say what was skipped and how
/// many run. The cases, for a JUnit report, come back with the wall time.
pub fn run_testbenches(
    options: &TestOptions,
    notes: &dyn Notes,
    mut verdict: impl FnMut(&str, &Verdict),
) -> Result<Tested, miette::Report> {
    let started = Instant::now();
    let paths = &options.paths;
    let loaded = load_with_libraries(paths, &options.libraries)?;
    let benches = discover(&loaded, options.filter.as_deref());
    // Files that do not parse are left out of the compilation; their testbenches fail.
    for (id, errors) in &loaded.syntax_errors {
        if !benches.iter().any(|b| b.file == *id) {
            let name = &loaded.sources.file(*id).name;
            notes.note(&format!(
                "warning: skipping {name}: {} syntax error(s) (`vams check {name}` shows them)\n",
                errors.len()
            ));
        }
    }
    if benches.is_empty() {
        let shown: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
        return Err(CliError::NoTestbench {
            paths: if shown.is_empty() {
                "the current directory".into()
            } else {
                shown.join(", ")
            },
            filter: match &options.filter {
                Some(f) => format!(" and, with --filter, contains `{f}`"),
                None => String::new(),
            },
        }
        .into());
    }
    let files: Vec<(FileId, DesignFile)> = loaded
        .files
        .iter()
        .filter(|(id, _)| !loaded.has_errors(*id))
        .cloned()
        .collect();
    let analysis = analyse(&loaded.sources, &files);
    let jobs = super::parallel::threads(options.jobs);
    notes.output(&format!(
        "running {} testbench(es) on {jobs} thread(s)\n",
        benches.len()
    ));
    let mut cases = Vec::with_capacity(benches.len());
    run_in_order(
        &benches,
        jobs,
        |bench| {
            let start = Instant::now();
            let mut warnings = String::new();
            let problem = run_bench(
                &loaded,
                (&analysis, &files),
                bench,
                options.stop,
                &mut warnings,
            );
            Verdict {
                seconds: start.elapsed().as_secs_f64(),
                problem,
                warnings,
            }
        },
        |k, result| {
            let bench = &benches[k];
            let result = result.unwrap_or_else(|panic| Verdict {
                seconds: 0.0,
                problem: Some((
                    Problem::Error,
                    format!("internal error: vams panicked: {panic}"),
                )),
                warnings: String::new(),
            });
            verdict(&bench.name, &result);
            cases.push(Case {
                name: bench.name.clone(),
                classname: loaded.sources.file(bench.file).name.clone(),
                seconds: result.seconds,
                problem: result
                    .problem
                    .map(|(kind, text)| (kind, headline(&text), text)),
            });
        },
    );
    Ok(Tested {
        cases,
        seconds: started.elapsed().as_secs_f64(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Outcome;

    #[test]
    fn lines_for_passing_and_failing_testbenches() {
        let ok = Verdict {
            seconds: 0.081,
            problem: None,
            warnings: String::new(),
        };
        assert_eq!(
            verdict_lines("tb_tracking", &ok),
            "test tb_tracking ... ok (0.08 s)\n"
        );
        let bad = Verdict {
            seconds: 0.1,
            problem: Some((Problem::Failure, "600 ms: error: a\n2 s: error: b".into())),
            warnings: String::new(),
        };
        assert_eq!(
            verdict_lines("tb_x", &bad),
            "test tb_x ... FAILED (0.10 s)\n    600 ms: error: a\n    2 s: error: b\n"
        );
    }

    fn result(severities: &[Severity], outcome: Outcome) -> SimResult {
        SimResult {
            waveforms: Default::default(),
            reports: severities
                .iter()
                .enumerate()
                .map(|(k, &severity)| crate::kernel::Report {
                    time: 1e-3 * (k + 1) as f64,
                    severity,
                    message: format!("report {k}"),
                    process: "check".into(),
                    span: Default::default(),
                })
                .collect(),
            outcome,
            stats: Default::default(),
        }
    }

    #[test]
    fn errors_and_failures_fail_notes_and_warnings_do_not() {
        let sources = SourceMap::new();
        let quiet = result(&[Severity::Note, Severity::Warning], Outcome::Finished);
        assert_eq!(judge(Ok(quiet), &sources), None);
        let noisy = result(
            &[Severity::Note, Severity::Error, Severity::Failure],
            Outcome::Failed { time: 3e-3 },
        );
        let (kind, text) = judge(Ok(noisy), &sources).unwrap();
        assert_eq!(kind, Problem::Failure);
        assert_eq!(
            text,
            "2 ms: error: report 1 (process check)\n3 ms: failure: report 2 (process check)"
        );
        let broken = Err(SimError::Analog { errors: vec![] });
        let (kind, text) = judge(broken, &sources).unwrap();
        assert_eq!(kind, Problem::Error);
        assert!(text.contains("vams::sim::analog"), "{text}");
    }

    #[test]
    fn headline_is_the_diagnostic_message_or_the_first_line() {
        assert_eq!(
            headline("vams::cli::no_stop\n\n  × no stop time for `tb`\n  help: pass --stop"),
            "no stop time for `tb`"
        );
        assert_eq!(
            headline("\n1 ms: error: a\n2 ms: error: b"),
            "1 ms: error: a"
        );
        assert_eq!(headline(""), "");
    }

    #[test]
    fn default_paths_are_the_existing_of_tests_and_models() {
        let dir = tempfile::tempdir().unwrap();
        assert!(default_paths(&[], dir.path()).is_empty());
        std::fs::create_dir(dir.path().join("models")).unwrap();
        assert_eq!(default_paths(&[], dir.path()), [PathBuf::from("models")]);
        std::fs::create_dir(dir.path().join("tests")).unwrap();
        assert_eq!(
            default_paths(&[], dir.path()),
            [PathBuf::from("tests"), PathBuf::from("models")]
        );
        let given = [PathBuf::from("x.vhd")];
        assert_eq!(default_paths(&given, dir.path()), given);
    }
}
