//! `vams sweep SPEC.toml`: design-space runs. The spec (`spec`) names the design, one plan
//! of runs (`plan`: a grid, corners, Monte Carlo samples from `sample`, or one-at-a-time
//! perturbations), the metrics evaluated on each run's waveforms (`metric`) and the plots.
//! The sources are parsed and analysed once; each run elaborates them with its generics and
//! simulates (`execute`) on every core, its row streamed to the result table (`table`) as it
//! finishes, so an interrupted sweep resumes where it stopped. The end prints a summary
//! (`summary`) and draws the envelope of chosen waveforms, the metrics' histograms and, for
//! sensitivities, a tornado per metric.
//!
//! A sweep splits into deterministic shards (`--shard K/N`: runs are numbered, each shard
//! a contiguous block) that a Slurm job array runs (`slurm`); `vams sweep collect DIR` merges
//! the shards' tables into the table a local run writes, byte for byte.

pub mod execute;
pub mod metric;
pub mod plan;
pub mod sample;
pub mod slurm;
pub mod spec;
pub mod summary;
pub mod table;

use std::path::{Path, PathBuf};
use std::time::Instant;

use miette::{Diagnostic, Report};
use thiserror::Error;

use crate::elaborate::ElabError;
use crate::kernel::Cancel;
use crate::output::sweep_plot::{EnvelopeBuilder, Histogram, TornadoBar};

use super::compile::{DesignOptions, Prepared, prepare, unknown_probe_help};
use super::error::CliError;
use super::load::LibrarySources;
use super::notes::Notes;
use super::render::{render, render_located};
use super::stop::{declaring_file, stop_comment};
use execute::Job;
use plan::Plan;
use spec::{Spec, read_spec};
use table::{Identity, Row, Status, TableError, TableWriter, header, read_table};

/// Plans larger than this need `--yes`.
const LARGE_PLAN: u64 = 100_000;
/// Time bins of an envelope plot.
const ENVELOPE_BINS: usize = 1000;

/// Errors of `vams sweep` itself.
#[derive(Debug, Error, Diagnostic)]
pub enum StudyError {
    #[error(transparent)]
    #[diagnostic(code(vams::sweep::table))]
    Table(#[from] TableError),
    #[error("`{}` already holds the table of a sweep", path.display())]
    #[diagnostic(
        code(vams::sweep::exists),
        help("--resume continues it, --overwrite starts afresh, or choose another --out")
    )]
    Exists { path: PathBuf },
    #[error("`{}` is the table of another spec or plan ({why})", path.display())]
    #[diagnostic(
        code(vams::sweep::other_spec),
        help("the spec changed since: --overwrite starts afresh, or choose another --out")
    )]
    OtherSpec { path: PathBuf, why: String },
    #[error("the sweep was interrupted after {done} of {total} runs")]
    #[diagnostic(
        code(vams::sweep::interrupted),
        help("the finished runs are in the table: run the same command with --resume to go on")
    )]
    Interrupted { done: usize, total: usize },
    #[error("{missing} of {shards} shards are missing or partial in `{}`", dir.display())]
    #[diagnostic(code(vams::sweep::missing_shards), help("{resubmit}"))]
    MissingShards {
        dir: PathBuf,
        missing: usize,
        shards: usize,
        resubmit: String,
    },
    #[error("no shard tables (shard-K-of-N.csv) in `{}`", dir.display())]
    #[diagnostic(
        code(vams::sweep::no_shards),
        help("give the --out folder of `vams sweep SPEC --shard K/N` or `--slurm`")
    )]
    NoShards { dir: PathBuf },
    #[error("cannot write `{}`: {reason}", path.display())]
    #[diagnostic(code(vams::sweep::write))]
    Write { path: PathBuf, reason: String },
    #[error(transparent)]
    #[diagnostic(transparent)]
    Slurm(#[from] slurm::SlurmError),
    #[error("cannot draw `{}`: {reason}", path.display())]
    #[diagnostic(code(vams::sweep::plot))]
    Plot { path: PathBuf, reason: String },
}

/// What a local sweep (or shard) leaves behind.
#[derive(Debug)]
pub struct StudyOutcome {
    /// The output folder (`--out` or its default).
    pub dir: PathBuf,
    /// The result table in it: `results.csv`, or the shard's table.
    pub table: PathBuf,
    /// The summary it printed (runs, failures, yield, metric statistics).
    pub summary: String,
}

/// What a design-space study runs: its spec, where its results go, how it is split.
#[derive(Debug, Clone, Default)]
pub struct StudyOptions {
    /// The spec (TOML).
    pub spec: PathBuf,
    /// Folder for the result table and plots; `None`: `SPEC-NAME.sweep` here.
    pub out: Option<PathBuf>,
    /// Runs at once; `None`: one per core.
    pub jobs: Option<u32>,
    /// Continue the study whose table is in `out`.
    pub resume: bool,
    /// Start afresh, replacing the table already in `out`.
    pub overwrite: bool,
    /// Run a plan of more than 100 000 runs.
    pub yes: bool,
    /// Run only shard K of N.
    pub shard: Option<(usize, usize)>,
    /// Run the study as a Slurm job array of shards.
    pub slurm: bool,
    /// Tasks of the job array; `None`: 100, or fewer when the plan has fewer runs.
    pub array_size: Option<u32>,
    /// Slurm partition of the tasks.
    pub partition: Option<String>,
    /// Time limit of each task (sbatch `--time`).
    pub time: Option<String>,
    /// Write the job script without submitting it.
    pub dry_run: bool,
    /// Wait for the job array to end, then collect its shards.
    pub wait: bool,
}

/// Runs a design-space study (`vams sweep`): `cancel` stops the runs. A local study gives
/// back its folder, table and summary; `slurm` gives `None`.
pub fn run_study(
    args: &StudyOptions,
    cancel: Cancel,
    notes: &dyn Notes,
) -> Result<Option<StudyOutcome>, Report> {
    let spec_path = &args.spec;
    let spec = read_spec(spec_path)?;
    let total = check_size(&spec, args.yes)?;
    let prepared = prepare_design(&spec, notes)?;
    check_parameters(&spec, &prepared, notes)?;
    let stop = stop_time(&spec, &prepared, notes)?;
    let out = args.out.clone().unwrap_or_else(|| default_out(spec_path));
    std::fs::create_dir_all(&out).map_err(|e| StudyError::Write {
        path: out.clone(),
        reason: e.to_string(),
    })?;
    if args.slurm {
        return submit(args, spec_path, &out, total, notes).map(|()| None);
    }
    let (range, table_path) = match args.shard {
        Some((k, n)) => (
            shard_range(total, k, n),
            out.join(format!("shard-{k}-of-{n}.csv")),
        ),
        None => (0..total, out.join("results.csv")),
    };
    let identity = Identity {
        spec: spec_name(spec_path),
        fingerprint: spec.fingerprint,
        runs: total as u64,
        shard: args.shard,
    };
    let names = spec.plan.names();
    let metric_names: Vec<String> = spec.metrics.iter().map(|m| m.name.clone()).collect();
    let head = header(&names, &metric_names);
    let kept = previous_rows(&table_path, &identity, &head, names.len(), args)?;
    let done: std::collections::HashSet<usize> = kept.iter().map(|r| r.index).collect();
    let todo: Vec<usize> = range.clone().filter(|i| !done.contains(i)).collect();
    let mut writer =
        TableWriter::create(&table_path, &identity, &head, &kept).map_err(StudyError::from)?;
    let job = Job {
        prepared: &prepared,
        parameters: names.clone(),
        metrics: &spec.metrics,
        envelope: &spec.envelope,
        stop,
        reltol: spec.design.reltol,
        abstol: spec.design.abstol,
        max_step: spec.design.max_step,
        cancel,
    };
    notes.note(&format!(
        "sweeping {} ({} runs{}, {} to do) into {}\n",
        spec_path.display(),
        range.len(),
        match args.shard {
            Some((k, n)) => format!(" of {total}: shard {k}/{n}"),
            None => String::new(),
        },
        todo.len(),
        table_path.display()
    ));
    let started = Instant::now();
    let mut envelopes: Vec<EnvelopeBuilder> = spec
        .envelope
        .iter()
        .map(|name| EnvelopeBuilder::new(name.clone(), None, 0.0, stop, ENVELOPE_BINS))
        .collect();
    let mut rows = kept;
    let mut write_failure = None;
    let bar = notes.progress(todo.len() as u64);
    let jobs = crate::app::parallel::threads(args.jobs);
    let plan = &spec.plan;
    let mut failures = 0;
    // Once a run is interrupted, later ones are not recorded either (a few may have finished
    // meanwhile): the table stays the runs in order, which a resumed sweep extends.
    let mut interrupted = false;
    super::parallel::run_in_order(
        &todo,
        jobs,
        |&index| job.run(&plan.run(index)),
        |k, result| {
            if interrupted {
                return;
            }
            let done = match result {
                Ok(Some(done)) => done,
                // Interrupted: not recorded, a resumed sweep runs it again.
                Ok(None) => {
                    interrupted = true;
                    return;
                }
                // An internal error in one run is that run's failure, not the sweep's.
                Err(panic) => job.failure(&plan.run(todo[k]), format!("internal error: {panic}")),
            };
            if done.row.status == Status::Failed {
                failures += 1;
            }
            for (env, trace) in envelopes.iter_mut().zip(&done.traces) {
                if let Some((t, v, held)) = trace {
                    if done.row.index == 0 {
                        env.set_nominal(t, v, *held);
                    }
                    env.add_run(t, v, *held);
                }
            }
            if write_failure.is_none()
                && let Err(e) = writer.push(&done.row)
            {
                write_failure = Some(e);
                job.cancel.cancel();
            }
            rows.push(done.row);
            bar.set_message(format!("{failures} failed"));
            bar.inc(1);
        },
    );
    bar.finish_and_clear();
    if let Some(e) = write_failure {
        return Err(StudyError::from(e).into());
    }
    rows.sort_by_key(|r| r.index);
    let finished = rows.iter().filter(|r| range.contains(&r.index)).count();
    if finished < range.len() {
        let why = format!("interrupted after {finished} of {} runs", range.len());
        writer.finish_partial(&why).map_err(StudyError::from)?;
        notes.note(&format!("{why}; the table is {}\n", table_path.display()));
        return Err(StudyError::Interrupted {
            done: finished,
            total: range.len(),
        }
        .into());
    }
    drop(writer);
    let summary = summary::summary(plan, &spec.metrics, &rows);
    notes.note(&summary);
    let mut written = vec![table_path.display().to_string()];
    if args.shard.is_none() {
        written.extend(draw(&spec, &rows, envelopes, &out)?);
    }
    notes.note(&format!(
        "swept {} runs in {:.2} s wall time ({} at once); wrote {}\n",
        todo.len(),
        started.elapsed().as_secs_f64(),
        jobs,
        written.join(", ")
    ));
    Ok(Some(StudyOutcome {
        dir: out,
        table: table_path,
        summary,
    }))
}

/// `--slurm`: the job array of the sweep's shards, written, then submitted (or printed).
fn submit(
    args: &StudyOptions,
    spec_path: &Path,
    out: &Path,
    total: usize,
    notes: &dyn Notes,
) -> Result<(), Report> {
    let absolute = |p: &Path| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
    let write_error = |path: &Path, e: std::io::Error| StudyError::Write {
        path: path.to_path_buf(),
        reason: e.to_string(),
    };
    let vams = std::env::current_exe().map_err(|e| write_error(Path::new("vams"), e))?;
    let shards = args
        .array_size
        .map_or(100, |n| n as usize)
        .min(total.max(1));
    let stem = spec_path
        .file_stem()
        .map_or("sweep".into(), |s| s.to_string_lossy().into_owned());
    let job = slurm::ArrayJob {
        vams,
        spec: absolute(spec_path),
        out: absolute(out),
        shards,
        partition: args.partition.clone(),
        time: args.time.clone(),
        job_name: format!("vams-{stem}"),
        // One CPU per task (the script asks for one): a shard runs its runs one at a time.
        extra_args: vec!["--jobs".into(), "1".into(), "--resume".into()],
    };
    let script = slurm::write_script(&job).map_err(StudyError::from)?;
    if args.dry_run {
        notes.output(&job.script());
        notes.note(&format!(
            "wrote {} ({shards} tasks for {total} runs); submit it with `sbatch {}`\n",
            script.display(),
            script.display()
        ));
        return Ok(());
    }
    let id = slurm::submit(&script, None).map_err(StudyError::from)?;
    notes.note(&format!(
        "submitted job {id}: {shards} tasks for {total} runs, script {}\n",
        script.display()
    ));
    if !args.wait {
        notes.note(&format!(
            "when it has ended: vams sweep collect {}\n",
            job.out.display()
        ));
        return Ok(());
    }
    // A sweep's tasks may queue for long on a busy cluster: wait up to a week.
    slurm::wait(&id, std::time::Duration::from_secs(7 * 24 * 3600)).map_err(StudyError::from)?;
    notes.note(&format!("job {id} has ended\n"));
    collect(&job.out, notes)
}

/// The plan's size, refused beyond [`LARGE_PLAN`] without `--yes`.
fn check_size(spec: &Spec, yes: bool) -> Result<usize, Report> {
    let too_large = |n: String| -> Report {
        spec::Locator::new(&spec.path.display().to_string(), spec.source.inner())
            .error(
                spec.plan_span,
                format!("this plan has {n} runs"),
                Some(format!(
                    "a plan of more than {LARGE_PLAN} runs needs --yes; check the spec's sizes"
                )),
            )
            .into()
    };
    match spec.plan.len() {
        None => Err(too_large("more than 2^64".into())),
        Some(n) if n > LARGE_PLAN && !yes => Err(too_large(n.to_string())),
        Some(n) => usize::try_from(n).map_err(|_| too_large(n.to_string())),
    }
}

/// Parses and analyses the spec's sources once.
fn prepare_design(spec: &Spec, notes: &dyn Notes) -> Result<Prepared, Report> {
    let options = DesignOptions {
        paths: spec.design.files.clone(),
        libraries: spec
            .design
            .libraries
            .iter()
            .map(|(name, path)| LibrarySources {
                name: name.clone(),
                path: path.clone(),
            })
            .collect(),
        top: spec.design.top.clone(),
        generics: spec.design.generics.clone(),
        params: None,
    };
    // The study's own diagnostics are printed as they are found (as a run of its shards
    // would print them in its log).
    prepare(&options).map_err(|not| {
        for f in &not.findings {
            notes.note(&render(f.report.as_ref()));
        }
        not.error
    })
}

/// The design must elaborate with the spec's fixed generics, and every parameter must name
/// a generic of it: a misspelt name is a spec error at its line, before any run.
fn check_parameters(spec: &Spec, prepared: &Prepared, notes: &dyn Notes) -> Result<(), Report> {
    // Run 0's values: a generic without a default that every run sets elaborates too.
    let errors = match prepared.try_elaborate(&spec.plan.run(0).generics(&spec.plan.names())) {
        Ok(design) => {
            for w in prepared.warnings(&design) {
                notes.note(&render(w.report.as_ref()));
            }
            return check_columns(spec, &design);
        }
        Err(errors) => errors,
    };
    let names = spec.plan.names();
    let loaded = &prepared.loaded;
    let at = spec::Locator::new(&spec.path.display().to_string(), spec.source.inner());
    let mut unknown_fixed = Vec::new();
    for e in &errors {
        let (name, help) = match e {
            ElabError::UnknownGeneric { name, help, .. }
            | ElabError::UnknownInstanceGeneric { name, help } => (name, help),
            _ => continue,
        };
        match names.iter().position(|n| n == name) {
            Some(k) => {
                return Err(at
                    .error(
                        spec.parameter_spans[k],
                        format!("the design has no generic `{name}`"),
                        help.clone(),
                    )
                    .into());
            }
            // One of `[design] generics`.
            None => unknown_fixed.push(e),
        }
    }
    if !unknown_fixed.is_empty() {
        for e in &unknown_fixed {
            notes.note(&render_located(*e, &loaded.sources));
        }
        return Err(CliError::Elaboration {
            count: unknown_fixed.len(),
        }
        .into());
    }
    // Other errors belong to the first run's values: each run reports its own.
    Ok(())
}

/// Every column a metric or the envelope reads must be a quantity or signal of the design
/// (of run 0's): a misspelt name is a spec error at its line, not a failure of every run.
fn check_columns(spec: &Spec, design: &crate::design::Design) -> Result<(), Report> {
    let wanted = spec
        .metrics
        .iter()
        .zip(&spec.metric_spans)
        .filter_map(|(m, span)| m.column().map(|c| (c.to_string(), *span)))
        .chain(
            spec.envelope
                .iter()
                .cloned()
                .zip(spec.envelope_spans.iter().copied()),
        );
    for (column, span) in wanted {
        let Some(help) = unknown_probe_help(design, &column) else {
            continue;
        };
        let at = spec::Locator::new(&spec.path.display().to_string(), spec.source.inner());
        return Err(at
            .error(
                span,
                format!("the design has no quantity or signal `{column}`"),
                Some(help),
            )
            .into());
    }
    Ok(())
}

/// The spec's stop time, or the testbench's `-- vams: stop` comment.
fn stop_time(spec: &Spec, prepared: &Prepared, notes: &dyn Notes) -> Result<f64, Report> {
    if let Some(t) = spec.design.stop {
        return Ok(t);
    }
    let loaded = &prepared.loaded;
    match declaring_file(loaded, &prepared.top).and_then(|f| stop_comment(&loaded.sources, f)) {
        Some(Ok(t)) => Ok(t),
        Some(Err(e)) => {
            notes.note(&render_located(&e, &loaded.sources));
            Err(CliError::NoStop {
                top: prepared.top.clone(),
            }
            .into())
        }
        None => Err(CliError::NoStop {
            top: prepared.top.clone(),
        }
        .into()),
    }
}

/// `SPEC-NAME.sweep` in the current folder.
fn default_out(spec: &Path) -> PathBuf {
    let stem = spec
        .file_stem()
        .map_or("sweep".into(), |s| s.to_string_lossy().into_owned());
    PathBuf::from(format!("{stem}.sweep"))
}

/// The spec as the tables name it: its absolute path (`collect` reads it from there).
fn spec_name(spec: &Path) -> String {
    std::fs::canonicalize(spec)
        .unwrap_or_else(|_| spec.to_path_buf())
        .display()
        .to_string()
}

/// Shard `k` of `n`: a contiguous block, the first `total % n` shards one run longer.
pub fn shard_range(total: usize, k: usize, n: usize) -> std::ops::Range<usize> {
    let (base, extra) = (total / n, total % n);
    let start = k * base + k.min(extra);
    start..start + base + usize::from(k < extra)
}

/// The rows a resumed sweep keeps (none for a fresh one); refuses to replace a table
/// without --overwrite, and to resume another spec's.
fn previous_rows(
    path: &Path,
    identity: &Identity,
    head: &[String],
    parameters: usize,
    args: &StudyOptions,
) -> Result<Vec<Row>, StudyError> {
    if !path.exists() || args.overwrite {
        return Ok(Vec::new());
    }
    if !args.resume {
        return Err(StudyError::Exists {
            path: path.to_path_buf(),
        });
    }
    let mut table = read_table(path)?;
    let other = |why: String| StudyError::OtherSpec {
        path: path.to_path_buf(),
        why,
    };
    if table.identity.fingerprint != identity.fingerprint {
        return Err(other("the spec's text differs".into()));
    }
    if table.identity.runs != identity.runs || table.identity.shard != identity.shard {
        return Err(other("the plan or shard differs".into()));
    }
    if table.header != head {
        return Err(other("the columns differ".into()));
    }
    table.resplit(parameters).map_err(other)?;
    Ok(table.rows)
}

/// Draws the envelope, the histograms and the tornados; returns the files written.
fn draw(
    spec: &Spec,
    rows: &[Row],
    envelopes: Vec<EnvelopeBuilder>,
    out: &Path,
) -> Result<Vec<String>, Report> {
    let mut written = Vec::new();
    let title = spec_title(spec);
    let plot_error = |path: &Path, e: &dyn std::fmt::Display| StudyError::Plot {
        path: path.to_path_buf(),
        reason: e.to_string(),
    };
    let built: Vec<_> = envelopes
        .into_iter()
        .map(EnvelopeBuilder::finish)
        .filter(|e| e.is_drawable())
        .collect();
    if !built.is_empty() {
        let path = out.join(format!("envelope.{}", spec.plot_format));
        crate::output::sweep_plot::plot_envelopes(&path, &title, &built)
            .map_err(|e| plot_error(&path, &e))?;
        written.push(path.display().to_string());
    }
    let counted: Vec<&Row> = rows
        .iter()
        .filter(|r| spec.plan.is_sample(r.index))
        .collect();
    if !spec.metrics.is_empty()
        && counted.len() > 1
        && !matches!(spec.plan, Plan::Sensitivity { .. })
    {
        let histograms: Vec<Histogram> = spec
            .metrics
            .iter()
            .enumerate()
            .map(|(m, metric)| {
                let (min_limit, max_limit) = (metric.limit.min, metric.limit.max);
                Histogram {
                    name: metric.name.clone(),
                    unit: None,
                    values: counted.iter().filter_map(|r| r.metrics[m]).collect(),
                    min_limit,
                    max_limit,
                }
            })
            .filter(|h| !h.values.is_empty())
            .collect();
        if !histograms.is_empty() {
            let path = out.join(format!("histograms.{}", spec.plot_format));
            crate::output::sweep_plot::plot_histograms(&path, &title, &histograms)
                .map_err(|e| plot_error(&path, &e))?;
            written.push(path.display().to_string());
        }
    }
    if let (Some(s), Plan::Sensitivity { names, .. }) = (
        summary::sensitivities(&spec.plan, rows, spec.metrics.len()),
        &spec.plan,
    ) {
        for (m, metric) in spec.metrics.iter().enumerate() {
            let bars: Vec<TornadoBar> = names
                .iter()
                .zip(&s[m])
                .filter_map(|(p, v)| {
                    v.map(|(low, high, _)| TornadoBar {
                        parameter: p.clone(),
                        low: -low,
                        high,
                    })
                })
                .collect();
            if bars.is_empty() {
                continue;
            }
            let path = out.join(format!("tornado-{}.{}", metric.name, spec.plot_format));
            crate::output::sweep_plot::plot_tornado(&path, &title, &metric.name, &bars)
                .map_err(|e| plot_error(&path, &e))?;
            written.push(path.display().to_string());
        }
    }
    Ok(written)
}

fn spec_title(spec: &Spec) -> String {
    let kind = match &spec.plan {
        Plan::Grid { .. } => "grid",
        Plan::Corners { .. } => "corners",
        Plan::MonteCarlo(_) => "Monte Carlo",
        Plan::Sensitivity { .. } => "sensitivity",
    };
    format!(
        "{} ({kind}, {} runs)",
        spec.path
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into_owned()),
        spec.plan.len().unwrap_or(0)
    )
}

/// `vams sweep collect DIR`.
pub fn collect(dir: &Path, notes: &dyn Notes) -> Result<(), Report> {
    let mut shards: Vec<(usize, usize, PathBuf)> = Vec::new();
    let entries = std::fs::read_dir(dir).map_err(|e| StudyError::Write {
        path: dir.to_path_buf(),
        reason: e.to_string(),
    })?;
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let parsed = name
            .strip_prefix("shard-")
            .and_then(|s| s.strip_suffix(".csv"))
            .and_then(|s| s.split_once("-of-"))
            .and_then(|(k, n)| Some((k.parse().ok()?, n.parse().ok()?)));
        if let Some((k, n)) = parsed {
            shards.push((k, n, entry.path()));
        }
    }
    let Some(&(_, n, _)) = shards.iter().max_by_key(|s| s.1) else {
        return Err(StudyError::NoShards {
            dir: dir.to_path_buf(),
        }
        .into());
    };
    shards.retain(|s| s.1 == n);
    let mut tables = Vec::new();
    let mut missing = Vec::new();
    for k in 0..n {
        match shards.iter().find(|s| s.0 == k) {
            Some((_, _, path)) => {
                let table = read_table(path).map_err(StudyError::from)?;
                tables.push((k, table));
            }
            None => missing.push(k),
        }
    }
    let Some((_, first)) = tables.first() else {
        return Err(StudyError::NoShards {
            dir: dir.to_path_buf(),
        }
        .into());
    };
    let spec_path = PathBuf::from(&first.identity.spec);
    let spec = read_spec(&spec_path)?;
    let identity = Identity {
        shard: None,
        ..first.identity.clone()
    };
    if identity.fingerprint != spec.fingerprint {
        return Err(StudyError::OtherSpec {
            path: spec_path,
            why: "the spec changed since the shards ran".into(),
        }
        .into());
    }
    let total = identity.runs as usize;
    let names = spec.plan.names();
    let metric_names: Vec<String> = spec.metrics.iter().map(|m| m.name.clone()).collect();
    let head = header(&names, &metric_names);
    let mut rows = Vec::new();
    for (k, mut table) in tables {
        let range = shard_range(total, k, n);
        let consistent = table.identity.fingerprint == identity.fingerprint
            && table.identity.runs == identity.runs
            && table.header == head;
        if !consistent {
            return Err(StudyError::OtherSpec {
                path: dir.join(format!("shard-{k}-of-{n}.csv")),
                why: "its spec, plan or columns differ from the other shards'".into(),
            }
            .into());
        }
        table
            .resplit(names.len())
            .map_err(|why| StudyError::OtherSpec {
                path: dir.join(format!("shard-{k}-of-{n}.csv")),
                why,
            })?;
        let complete = range
            .clone()
            .all(|i| table.rows.iter().any(|r| r.index == i));
        if !complete {
            missing.push(k);
            continue;
        }
        rows.extend(table.rows.into_iter().filter(|r| range.contains(&r.index)));
    }
    if !missing.is_empty() {
        missing.sort_unstable();
        let list: Vec<String> = missing.iter().map(usize::to_string).collect();
        let script = dir.join("sweep.sbatch");
        let resubmit = if script.exists() {
            format!(
                "run them again: sbatch --array={} {}",
                list.join(","),
                script.display()
            )
        } else {
            format!(
                "run them again: vams sweep {} --shard K/{n} --out {} for K in {}",
                spec_path.display(),
                dir.display(),
                list.join(", ")
            )
        };
        notes.note(&format!("missing or partial shards: {}\n", list.join(", ")));
        return Err(StudyError::MissingShards {
            dir: dir.to_path_buf(),
            missing: missing.len(),
            shards: n,
            resubmit,
        }
        .into());
    }
    rows.sort_by_key(|r| r.index);
    let path = dir.join("results.csv");
    drop(TableWriter::create(&path, &identity, &head, &rows).map_err(StudyError::from)?);
    notes.note(&summary::summary(&spec.plan, &spec.metrics, &rows));
    let mut written = vec![path.display().to_string()];
    written.extend(draw(&spec, &rows, Vec::new(), dir)?);
    notes.note(&format!(
        "collected {n} shards, {} runs; wrote {}\n",
        rows.len(),
        written.join(", ")
    ));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_cover_every_run_once() {
        for total in [0, 1, 7, 40, 1001] {
            for n in 1..12 {
                let mut next = 0;
                for k in 0..n {
                    let r = shard_range(total, k, n);
                    assert_eq!(r.start, next);
                    assert!(r.len() + 1 >= total / n && r.len() <= total / n + 1);
                    next = r.end;
                }
                assert_eq!(next, total);
            }
        }
    }
}
