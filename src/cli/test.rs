//! `vams test`: the command line of [`crate::app::testbench`]: its arguments, and the results
//! printed.

use crate::app::error::CliError;
use crate::app::testbench::*;
use crate::app::time::parse_positive_time;
use crate::cli::notes::Printed;
use crate::output::atomic::write_atomically;
use clap::Args;
use junit::junit_xml;
use miette::Report;
use std::path::PathBuf;

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
    let root = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("."));
    let options = TestOptions {
        paths: default_paths(&args.paths, &root),
        libraries: args.libraries.clone(),
        filter: args.filter.clone(),
        stop: args.stop,
        jobs: args.jobs,
    };
    let tested = run_testbenches(&options, &Printed, |name, verdict| {
        print!("{}", verdict_lines(name, verdict));
    })?;
    let (cases, total_seconds) = (tested.cases, tested.seconds);
    let failed = cases.iter().filter(|c| c.problem.is_some()).count();
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
