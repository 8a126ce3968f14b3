//! `vams test`: the command line of [`crate::app::testbench`]: its arguments, and the results
//! printed.

use crate::analysis::analyse;
use crate::app::error::CliError;
use crate::app::load::load_with_libraries;
use crate::app::parallel::run_in_order;
use crate::app::testbench::*;
use crate::app::time::parse_positive_time;
use crate::ast::DesignFile;
use crate::output::atomic::write_atomically;
use crate::source::FileId;
use clap::Args;
use discover::discover;
use junit::{Case, Problem, junit_xml};
use miette::Report;
use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `vams test`.
#[derive(Debug, Args)]
#[command(
    after_help = "A testbench is an entity without ports whose name starts with tb_ or test_. It runs
to the time of the comment `-- vams: stop TIME` in its file, else to --stop.

Examples:
  vams test
  vams test models/ --filter tracking --junit results.xml -j 2"
)]
pub struct TestArgs {
    /// Files or directories to search; default: tests/ and models/ (those that exist).
    #[arg(value_name = "PATHS")]
    pub paths: Vec<PathBuf>,
    /// Analyse the sources under PATH into library NAME (repeatable): `--lib util=../util`
    /// for files that say `library util;`.
    #[arg(long = "lib", value_name = "NAME=PATH", value_parser = crate::app::load::parse_library)]
    pub libraries: Vec<crate::app::load::LibrarySources>,
    /// Run only the testbenches whose name contains TEXT.
    #[arg(long, value_name = "TEXT")]
    pub filter: Option<String>,
    /// Write the results as JUnit XML to FILE.
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Stop time for testbenches whose file has no `-- vams: stop` comment.
    #[arg(long, value_name = "TIME", value_parser = parse_positive_time)]
    pub stop: Option<f64>,
    /// Testbenches run at once; default: the number of CPUs.
    #[arg(short = 'j', long = "jobs", value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub jobs: Option<u32>,
}

/// Runs `vams test`.
pub fn run(args: &TestArgs) -> Result<(), Report> {
    let started = Instant::now();
    let root = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    let paths = default_paths(&args.paths, &root);
    let loaded = load_with_libraries(&paths, &args.libraries)?;
    let benches = discover(&loaded, args.filter.as_deref());
    // Files that do not parse are left out of the compilation; their testbenches fail.
    for (id, errors) in &loaded.syntax_errors {
        if !benches.iter().any(|b| b.file == *id) {
            let name = &loaded.sources.file(*id).name;
            eprintln!(
                "warning: skipping {name}: {} syntax error(s) (`vams check {name}` shows them)",
                errors.len()
            );
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
            filter: match &args.filter {
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
    let jobs = crate::app::parallel::threads(args.jobs);
    println!(
        "running {} testbench(es) on {jobs} thread(s)",
        benches.len()
    );
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
                args.stop,
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
            let verdict = result.unwrap_or_else(|panic| Verdict {
                seconds: 0.0,
                problem: Some((
                    Problem::Error,
                    format!("internal error: vams panicked: {panic}"),
                )),
                warnings: String::new(),
            });
            print!("{}", verdict_lines(&bench.name, &verdict));
            cases.push(Case {
                name: bench.name.clone(),
                classname: loaded.sources.file(bench.file).name.clone(),
                seconds: verdict.seconds,
                problem: verdict
                    .problem
                    .map(|(kind, text)| (kind, headline(&text), text)),
            });
        },
    );
    let failed = cases.iter().filter(|c| c.problem.is_some()).count();
    let total_seconds = started.elapsed().as_secs_f64();
    println!(
        "\n{} passed, {failed} failed ({total_seconds:.2} s)",
        cases.len() - failed
    );
    if let Some(path) = &args.junit {
        let xml = junit_xml(&cases, total_seconds);
        write_atomically(path, |w| std::io::Write::write_all(w, xml.as_bytes())).map_err(|e| {
            CliError::Write {
                path: path.display().to_string(),
                reason: e.to_string(),
            }
        })?;
    }
    if failed > 0 {
        return Err(CliError::TestsFailed {
            failed,
            total: cases.len(),
        }
        .into());
    }
    Ok(())
}
