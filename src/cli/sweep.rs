//! `vams sweep`: the command line of [`crate::app::study`]: its arguments, and the results
//! printed.

use crate::app::study::slurm;
use crate::app::study::*;
use crate::cli::interrupt::cancel_on_ctrl_c;
use crate::cli::notes::Printed;
use clap::{Args, Subcommand};
use miette::Report;
use std::path::PathBuf;

/// Arguments of `vams sweep`.
#[derive(Debug, Args)]
#[command(
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    after_help = "Examples:
  vams sweep models/sweeps/worst_case.toml                  # on every core, into worst_case.sweep/
  vams sweep spec.toml --out runs --resume                    # continue an interrupted sweep
  vams sweep spec.toml --shard 3/10 --out runs                # the 4th of 10 shards
  vams sweep spec.toml --slurm --array-size 10 --out runs     # a Slurm job array of 10 shards
  vams sweep collect runs                                     # merge the shards

The spec is a TOML file: see models/sweeps/worst_case.toml and the README's \"Design-space
runs\" section for every key."
)]
pub struct SweepArgs {
    #[command(subcommand)]
    pub action: Option<SweepAction>,
    /// The sweep spec (TOML).
    #[arg(required = true, value_name = "SPEC.toml")]
    pub spec: Option<PathBuf>,
    /// Folder for the result table and plots; default: `SPEC-NAME.sweep` here.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Runs at once; default: one per core.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub jobs: Option<u32>,
    /// Continue the sweep whose table is in --out: runs already there are kept, the rest run.
    #[arg(long, conflicts_with = "overwrite")]
    pub resume: bool,
    /// Start afresh, replacing the table already in --out.
    #[arg(long)]
    pub overwrite: bool,
    /// Run a plan of more than 100 000 runs.
    #[arg(long)]
    pub yes: bool,
    /// Run only shard K of N (K from 0): a contiguous block of the runs, into
    /// DIR/shard-K-of-N.csv.
    #[arg(long, value_name = "K/N", value_parser = parse_shard, conflicts_with = "slurm")]
    pub shard: Option<(usize, usize)>,
    /// Run the sweep as a Slurm job array: write DIR/sweep.sbatch, whose task K runs
    /// `--shard K/N`, and submit it with sbatch; then `vams sweep collect DIR`.
    #[arg(long)]
    pub slurm: bool,
    /// Tasks of the job array (shards); default: 100, or fewer when the plan has fewer runs.
    #[arg(long, value_name = "N", requires = "slurm", value_parser = clap::value_parser!(u32).range(1..))]
    pub array_size: Option<u32>,
    /// Slurm partition of the tasks (sbatch --partition); default: the cluster's.
    #[arg(long, value_name = "P", requires = "slurm")]
    pub partition: Option<String>,
    /// Time limit of each task (sbatch --time: MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM, D-HH:MM:SS).
    #[arg(long, value_name = "TIME", requires = "slurm", value_parser = parse_slurm_time)]
    pub time: Option<String>,
    /// Write and print the job script without submitting it.
    #[arg(long, requires = "slurm")]
    pub dry_run: bool,
    /// Wait for the job array to end, then collect its shards.
    #[arg(long, requires = "slurm", conflicts_with = "dry_run")]
    pub wait: bool,
}

fn parse_slurm_time(text: &str) -> Result<String, String> {
    slurm::validate_time(text).map(|()| text.to_string())
}

/// `vams sweep collect DIR`.
#[derive(Debug, Subcommand)]
pub enum SweepAction {
    /// Merge the shards' tables in DIR into DIR/results.csv (the table a local run writes),
    /// print the summary and draw the histograms; list missing or partial shards.
    Collect {
        /// The folder the shards wrote to.
        #[arg(value_name = "DIR")]
        dir: PathBuf,
    },
}

/// Parses `K/N`.
fn parse_shard(text: &str) -> Result<(usize, usize), String> {
    let parsed = text
        .split_once('/')
        .and_then(|(k, n)| Some((k.trim().parse().ok()?, n.trim().parse().ok()?)));
    match parsed {
        Some((k, n)) if n >= 1 && k < n => Ok((k, n)),
        _ => Err(format!(
            "`{text}` is not a shard K/N with 0 <= K < N (e.g. 3/10)"
        )),
    }
}

/// Runs `vams sweep`.
pub fn run(args: &SweepArgs) -> Result<(), Report> {
    if let Some(SweepAction::Collect { dir }) = &args.action {
        return collect(dir, &Printed);
    }
    run_study(&args.options(), cancel_on_ctrl_c(), &Printed).map(drop)
}

impl SweepArgs {
    /// The application layer's options (the spec is required by clap unless a subcommand
    /// is given).
    pub fn options(&self) -> StudyOptions {
        StudyOptions {
            spec: self.spec.clone().unwrap_or_default(),
            out: self.out.clone(),
            jobs: self.jobs,
            resume: self.resume,
            overwrite: self.overwrite,
            yes: self.yes,
            shard: self.shard,
            slurm: self.slurm,
            array_size: self.array_size,
            partition: self.partition.clone(),
            time: self.time.clone(),
            dry_run: self.dry_run,
            wait: self.wait,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_are_k_of_n() {
        assert_eq!(parse_shard("3/10"), Ok((3, 10)));
        assert!(parse_shard("10/10").is_err() && parse_shard("1/0").is_err());
        assert!(parse_shard("a/b").unwrap_err().contains("K/N"));
    }
}
