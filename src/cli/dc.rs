//! `vams dc`: DC transfer curves. A generic of the top is swept through a sequence of values;
//! at each the design is elaborated again from the analysed sources (not parsed again) and its
//! quiescent point found as `vams op` finds it, starting from the previous point's quantities
//! (continuation). Where a point fails from there, it is approached in halved steps, then
//! from the model's own initial guesses. The probed quantities and signals are written as CSV
//! (a row per point) and drawn against the swept value.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;
use miette::Report;
use rustc_hash::FxHashMap;

use crate::design::Design;
use crate::diagnostics::Finding;
use crate::kernel::{Cancel, SimError, SimOptions, operating_point};
use crate::output::atomic::{commit, temp_path};
use crate::output::csv::{format_number, push_number};
use crate::output::plot::{Panel, Trace, plot_panels_over};

use super::ac::csv_path;
use super::compile::{DesignArgs, NotCompiled, Prepared, discard_at_exit, prepare};
use super::error::CliError;
use super::interrupt::{cancel_on_ctrl_c, remove_on_exit};
use super::render::render_sim_error;
use super::run::plot_path;

/// Arguments of `vams dc`.
#[derive(Debug, Args)]
#[command(after_help = "Examples:
  vams dc diode.vhd --sweep vs -1 0.8 0.01 --probe id -o iv.csv --plot iv.svg
  vams dc models/ --top tb_bridge --sweep v_bat 9 16 0.5 --probe motor_v
  vams dc schmitt.vhd --sweep vin 0 5 0.05 --both-ways --probe vout --plot hyst.svg

NAME is a generic of the top entity (a source's level is usually one); an integer generic is
swept when FROM, TO and STEP are whole numbers. Each point starts from the last one's
quantities, so a model with two stable states (a Schmitt trigger) keeps its state along the
sweep and --both-ways shows its hysteresis. Signals keep the values their processes give them
at initialisation, as in `vams op`.")]
pub struct DcArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    /// The generic to sweep and its values: from FROM to TO (included) in steps of STEP.
    #[arg(long, num_args = 4, required = true, allow_negative_numbers = true,
          value_names = ["NAME", "FROM", "TO", "STEP"])]
    pub sweep: Vec<String>,
    /// Sweep to TO, then back to FROM (a `direction` column: 1 up, -1 down).
    #[arg(long)]
    pub both_ways: bool,
    /// Write the curves to FILE (.csv): the swept generic, then each probe. Default: standard
    /// output.
    #[arg(short = 'o', long = "out", value_name = "FILE", value_parser = csv_path)]
    pub output: Option<PathBuf>,
    /// Draw the curves to FILE (.svg or .png): a panel per probe over the swept value.
    #[arg(long, value_name = "FILE", value_parser = plot_path)]
    pub plot: Option<PathBuf>,
    /// Report this quantity or signal (hierarchical name, e.g. dut.vout); repeatable. Default:
    /// every quantity but the spectral sources.
    #[arg(long, value_name = "NAME")]
    pub probe: Vec<String>,
}

/// Most points one sweep computes (a typing slip in STEP should not run for hours).
const MAX_POINTS: usize = 1_000_000;

/// Halvings of a step that failed before the sweep gives up on its point.
const MAX_HALVINGS: u32 = 6;

/// The swept values: a whole-number sweep when FROM, TO and STEP all are whole (an integer
/// generic takes only those), else reals.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    pub name: String,
    pub values: Vec<f64>,
    pub whole: bool,
}

impl Sweep {
    /// Reads `NAME FROM TO STEP`.
    pub fn parse(words: &[String]) -> Result<Sweep, CliError> {
        let [name, from, to, step] = words else {
            return Err(CliError::SweepRange {
                name: words.first().cloned().unwrap_or_default(),
                problem: "expected NAME FROM TO STEP".into(),
            });
        };
        let name = name.trim().to_ascii_lowercase();
        let bad = |problem: String| CliError::SweepRange {
            name: name.clone(),
            problem,
        };
        let number = |what: &str, text: &str| {
            text.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| bad(format!("{what} `{text}` is not a number")))
        };
        let (from, to, step) = (
            number("FROM", from)?,
            number("TO", to)?,
            number("STEP", step)?,
        );
        if step == 0.0 {
            return Err(bad("STEP is zero".into()));
        }
        if (to - from) * step < 0.0 {
            return Err(bad(format!(
                "a step of {} never reaches {} from {}; give STEP the sign of TO - FROM",
                format_number(step),
                format_number(to),
                format_number(from)
            )));
        }
        // Points from + k*step (no accumulated rounding), TO included within a millionth of
        // a step.
        let span = (to - from) / step;
        if span + 1.0 > MAX_POINTS as f64 {
            return Err(bad(format!(
                "{} points; at most {MAX_POINTS}",
                format_number((span + 1.0).floor())
            )));
        }
        let count = (span + 1e-6).floor() as usize + 1;
        let values = (0..count)
            .map(|k| decimal(from + k as f64 * step, step))
            .collect();
        let whole = [from, to, step].iter().all(|v| v.fract() == 0.0);
        Ok(Sweep {
            name,
            values,
            whole,
        })
    }

    /// The generic's value as VHDL literal text.
    fn literal(&self, value: f64) -> String {
        if self.whole && value.fract() == 0.0 {
            format!("{}", value as i64)
        } else {
            format!("{value:?}")
        }
    }
}

/// `value` without the binary noise of `from + k step` (0.30000000000000004 is 0.3, and
/// -0.3 + 3 * 0.1 is 0): rounded to nine decimal digits below the step's own.
fn decimal(value: f64, step: f64) -> f64 {
    let digits = (9.0 - step.abs().log10().floor()).clamp(0.0, 300.0) as usize;
    format!("{value:.digits$}").parse().unwrap_or(value)
}

/// A quiescent point: quantities, then explicit signals, by name.
type Point = Vec<(String, f64)>;

/// A solved point and, per name, whether it is reported without `--probe`: a quantity that
/// is neither a spectral source nor generated by elaboration (named with a tick).
struct Solved {
    point: Point,
    listed: Vec<bool>,
}

/// Why one point could not be solved.
enum PointError {
    /// The design did not elaborate with that value: the sweep ends.
    Elaboration(NotCompiled),
    /// No quiescent point: worth approaching in smaller steps.
    Solve(SimError),
}

/// Solves points of the sweep: elaborates the design for a value, seeds its quantities'
/// initial guesses from a previous point, finds the quiescent point.
struct PointSolver<'a> {
    prepared: &'a Prepared,
    sweep: &'a Sweep,
    /// The elaboration warnings, once the first point is elaborated (not per point).
    warnings: Option<Vec<Finding>>,
    /// Print the warnings as they are found.
    echo: bool,
}

impl PointSolver<'_> {
    fn solve(&mut self, value: f64, guess: Option<&Point>) -> Result<Solved, PointError> {
        let extra = [(self.sweep.name.clone(), self.sweep.literal(value))];
        let mut design = self
            .prepared
            .elaborate_quietly(&extra)
            .map_err(PointError::Elaboration)?;
        if self.warnings.is_none() {
            if self.echo {
                self.prepared.print_warnings(&design);
            }
            self.warnings = Some(self.prepared.warnings(&design));
        }
        if let Some(guess) = guess {
            seed(&mut design, guess);
        }
        let point = operating_point(&design, &SimOptions::default()).map_err(PointError::Solve)?;
        // The design is dropped here, not left to the exiting process: a sweep elaborates
        // one per point, and its memory must not grow with the number of points.
        let listed = listed(&design, point.len());
        Ok(Solved { point, listed })
    }

    /// The point at `to`, walking from `from` (solved as `guess`): straight, or in halved
    /// steps where that fails (not for whole-number sweeps: an integer generic has no values
    /// between), or from the model's own guesses.
    fn approach(&mut self, from: Option<(f64, &Point)>, to: f64) -> Result<Solved, PointError> {
        let Some((from, guess)) = from else {
            return self.solve(to, None);
        };
        let depth = if self.sweep.whole { 0 } else { MAX_HALVINGS };
        match self.halving(from, guess, to, depth) {
            Err(PointError::Solve(first)) => self.solve(to, None).map_err(|e| match e {
                // The continuation's error says more (it started close by).
                PointError::Solve(_) => PointError::Solve(first),
                e => e,
            }),
            other => other,
        }
    }

    fn halving(
        &mut self,
        from: f64,
        guess: &Point,
        to: f64,
        depth: u32,
    ) -> Result<Solved, PointError> {
        match self.solve(to, Some(guess)) {
            Err(PointError::Solve(_)) if depth > 0 => {
                let mid = 0.5 * (from + to);
                let between = self.halving(from, guess, mid, depth - 1)?;
                self.halving(mid, &between.point, to, depth - 1)
            }
            other => other,
        }
    }
}

/// Sets each quantity's initial guess to its value at `point` (matched by name: the design
/// is elaborated again for each value).
fn seed(design: &mut Design, point: &Point) {
    let values: FxHashMap<&str, f64> = point.iter().map(|(n, v)| (n.as_str(), *v)).collect();
    for q in &mut design.quantities {
        if let Some(&v) = values.get(q.name.as_str())
            && v.is_finite()
        {
            q.initial_guess = Some(v);
        }
    }
}

/// Per entry of a point of `design` (quantities, then signals): reported without `--probe`?
fn listed(design: &Design, len: usize) -> Vec<bool> {
    let mut listed: Vec<bool> = (design.quantities.iter())
        .map(|q| !q.name.contains('\''))
        .collect();
    for s in &design.spectral_sources {
        listed[s.quantity.index()] = false;
    }
    listed.resize(len, false);
    listed
}

/// The names met so far in the sweep's points, in order of first appearance (a swept generic
/// may change the design's structure: a `for ... generate` count), and each point's values
/// by column.
#[derive(Debug, Default)]
struct Columns {
    names: Vec<String>,
    listed: Vec<bool>,
    index: FxHashMap<String, usize>,
    /// Per point: swept value, direction (1 up, -1 down), values by column (NaN where the
    /// point's design has no such name; shorter rows end before later columns).
    rows: Vec<(f64, f64, Vec<f64>)>,
}

impl Columns {
    fn push(&mut self, value: f64, direction: f64, solved: &Solved) {
        let mut row = vec![f64::NAN; self.names.len()];
        for ((name, v), &listed) in solved.point.iter().zip(&solved.listed) {
            let k = match self.index.get(name) {
                Some(&k) => k,
                None => {
                    self.index.insert(name.clone(), self.names.len());
                    self.names.push(name.clone());
                    self.listed.push(listed);
                    row.push(f64::NAN);
                    self.names.len() - 1
                }
            };
            row[k] = *v;
        }
        self.rows.push((value, direction, row));
    }

    /// The curves of the probed names: the given ones (quantities or explicit signals, met at
    /// some point of the sweep), or every listed one.
    fn curves(&self, probes: &[String]) -> Result<Curves, CliError> {
        let chosen: Vec<usize> = if probes.is_empty() {
            (0..self.names.len()).filter(|&k| self.listed[k]).collect()
        } else {
            probes
                .iter()
                .map(|p| self.column(p))
                .collect::<Result<_, _>>()?
        };
        let rows = (self.rows.iter())
            .map(|(value, direction, row)| {
                let cells = chosen
                    .iter()
                    .map(|&k| row.get(k).copied().unwrap_or(f64::NAN));
                (*value, *direction, cells.collect())
            })
            .collect();
        Ok(Curves {
            names: chosen.iter().map(|&k| self.names[k].clone()).collect(),
            rows,
        })
    }

    fn column(&self, probe: &str) -> Result<usize, CliError> {
        let wanted = probe.trim().to_ascii_lowercase();
        if let Some(&k) = self.index.get(&wanted) {
            return Ok(k);
        }
        let nearest = (self.names.iter())
            .map(|n| (strsim::levenshtein(&wanted, n), n.as_str()))
            .min_by_key(|&(d, _)| d);
        let help = match nearest {
            Some((d, n)) if d <= wanted.len().max(3) / 2 + 1 => format!("did you mean `{n}`?"),
            _ => "probe quantities and signals by hierarchical, lower-case name (dut.vout); \
                  without --probe every quantity is reported"
                .into(),
        };
        Err(CliError::DcProbe {
            name: probe.to_string(),
            help,
        })
    }
}

/// The computed curves: the probes' names and per point the swept value, the direction (1 up,
/// -1 down) and the probes' values.
#[derive(Debug, Default)]
pub struct Curves {
    pub names: Vec<String>,
    pub rows: Vec<(f64, f64, Vec<f64>)>,
}

/// The CSV text of the curves (an empty cell where a point's design lacks the probe);
/// `ending` becomes a last `# ...` line (a sweep cut short).
pub fn format_csv(sweep: &str, curves: &Curves, both_ways: bool, ending: Option<&str>) -> String {
    let mut out = String::from(sweep);
    if both_ways {
        out.push_str(",direction");
    }
    for name in &curves.names {
        out.push(',');
        out.push_str(name);
    }
    out.push('\n');
    for (value, direction, probes) in &curves.rows {
        push_number(&mut out, *value);
        if both_ways {
            out.push(',');
            push_number(&mut out, *direction);
        }
        for v in probes {
            out.push(',');
            // Empty where the point's design has no such name (see [`row`]).
            if !v.is_nan() {
                push_number(&mut out, *v);
            }
        }
        out.push('\n');
    }
    if let Some(e) = ending {
        out.push_str(&format!("# {e}\n"));
    }
    out
}

/// A panel per probe: one trace, or the upward and downward sweeps.
fn panels(curves: &Curves, both_ways: bool) -> Vec<Panel> {
    let trace = |k: usize, direction: f64, name: &str| {
        let mut points: Vec<(f64, f64)> = (curves.rows.iter())
            .filter(|r| r.1 == direction && !r.2[k].is_nan())
            .map(|r| (r.0, r.2[k]))
            .collect();
        // The plot reduces long traces by pixel column, over increasing x.
        points.sort_by(|a, b| a.0.total_cmp(&b.0));
        Trace::analog(name, "", points)
    };
    (curves.names.iter().enumerate())
        .map(|(k, name)| {
            let traces = if both_ways {
                vec![trace(k, 1.0, "up"), trace(k, -1.0, "down")]
            } else {
                vec![trace(k, 1.0, name)]
            };
            Panel::new(name, traces)
        })
        .collect()
}

/// An output file being made: its temporary is created before the sweep (an unwritable path
/// fails before any work) and renamed over the target when complete.
struct Pending {
    path: PathBuf,
    temp: PathBuf,
}

impl Pending {
    fn create(path: &Path) -> Result<Pending, CliError> {
        let temp = temp_path(path);
        std::fs::File::create(&temp).map_err(|e| write_error(path, &e))?;
        Ok(Pending {
            path: path.to_path_buf(),
            temp,
        })
    }

    fn commit(&self) -> Result<(), CliError> {
        commit(&self.temp, &self.path).map_err(|e| write_error(&self.path, &e))
    }

    fn abandon(&self) {
        let _ = std::fs::remove_file(&self.temp);
    }
}

fn write_error(path: &Path, e: &dyn std::fmt::Display) -> CliError {
    CliError::Write {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}

/// The points of a sweep, solved in order, each from the last one's quantities.
pub struct Swept {
    columns: Columns,
    /// Why the sweep stopped before its last point: the note for the CSV and the error.
    pub ending: Option<(String, CliError)>,
    /// The solver's diagnostic of the point that failed, rendered.
    pub failure: String,
    /// The elaboration warnings (of the first point).
    pub warnings: Vec<Finding>,
    /// How many points the sweep has (both ways counted).
    pub planned: usize,
}

impl Swept {
    /// The probed curves (every quantity but the spectral sources without `probes`).
    pub fn curves(&self, probes: &[String]) -> Result<Curves, CliError> {
        self.columns.curves(probes)
    }
}

/// Sweeps `sweep` over the design of `prepared` (up to TO and back with `both_ways`) until
/// the end, a point without a quiescent point or `cancel`; with `echo`, the warnings and the
/// failed point's diagnostic are printed as they are found. An elaboration error ends it.
pub fn sweep_points(
    prepared: &Prepared,
    sweep: &Sweep,
    both_ways: bool,
    cancel: &Cancel,
    echo: bool,
) -> Result<Swept, NotCompiled> {
    let mut values: Vec<(f64, f64)> = sweep.values.iter().map(|&v| (v, 1.0)).collect();
    if both_ways {
        // Back from the turning point, which is not solved twice.
        let back = sweep.values.iter().rev().skip(1).map(|&v| (v, -1.0));
        values.extend(back);
    }
    let mut solver = PointSolver {
        prepared,
        sweep,
        warnings: None,
        echo,
    };
    let mut columns = Columns::default();
    let mut last: Option<(f64, Point)> = None;
    let mut ending: Option<(String, CliError)> = None;
    let mut failure = String::new();
    for &(value, direction) in &values {
        if cancel.is_cancelled() {
            ending = Some((
                format!(
                    "interrupted before {} = {}",
                    sweep.name,
                    format_number(value)
                ),
                CliError::Interrupted {
                    top: prepared.top.clone(),
                },
            ));
            break;
        }
        let from = last.as_ref().map(|(v, p)| (*v, p));
        let solved = match solver.approach(from, value) {
            Ok(solved) => solved,
            Err(PointError::Elaboration(errors)) => return Err(errors),
            Err(PointError::Solve(error)) => {
                failure = render_sim_error(&error, &prepared.loaded.sources);
                if echo {
                    eprint!("{failure}");
                }
                ending = Some((
                    format!(
                        "stopped at {} = {}: no quiescent point",
                        sweep.name,
                        format_number(value)
                    ),
                    CliError::SweepFailed {
                        top: prepared.top.clone(),
                        name: sweep.name.clone(),
                        value: format_number(value),
                    },
                ));
                break;
            }
        };
        columns.push(value, direction, &solved);
        last = Some((value, solved.point));
    }
    Ok(Swept {
        columns,
        ending,
        failure,
        warnings: solver.warnings.unwrap_or_default(),
        planned: values.len(),
    })
}

/// Runs `vams dc`.
pub fn run(args: &DcArgs) -> Result<(), Report> {
    let started = Instant::now();
    let sweep = Sweep::parse(&args.sweep)?;
    let prepared = prepare(&args.design)?;
    let csv = args.output.as_deref().map(Pending::create).transpose()?;
    let plot = match args.plot.as_deref().map(Pending::create).transpose() {
        Ok(p) => p,
        Err(e) => {
            if let Some(c) = &csv {
                c.abandon();
            }
            return Err(e.into());
        }
    };
    let pending: Vec<&Pending> = csv.iter().chain(plot.iter()).collect();
    remove_on_exit(pending.iter().map(|p| p.temp.clone()).collect());
    let abandon = || pending.iter().for_each(|p| p.abandon());

    let cancel = cancel_on_ctrl_c();
    let swept = sweep_points(&prepared, &sweep, args.both_ways, &cancel, true).map_err(|e| {
        abandon();
        e.print()
    })?;
    let ending = &swept.ending;
    // What was computed is written, whole or cut short.
    let curves = swept.curves(&args.probe).inspect_err(|_| abandon())?;
    let note = ending.as_ref().map(|(text, _)| text.as_str());
    let mut written = Vec::new();
    if curves.rows.is_empty() {
        abandon();
    } else {
        let text = format_csv(&sweep.name, &curves, args.both_ways, note);
        match &csv {
            Some(pending) => {
                std::fs::write(&pending.temp, text.as_bytes())
                    .map_err(|e| write_error(&pending.path, &e))
                    .and_then(|()| pending.commit())
                    .inspect_err(|_| abandon())?;
                written.push(pending.path.display().to_string());
            }
            None => {
                let mut stdout = std::io::stdout().lock();
                stdout
                    .write_all(text.as_bytes())
                    .and_then(|()| stdout.flush())
                    .map_err(|e| write_error(Path::new("<stdout>"), &e))?;
            }
        }
        if let Some(pending) = &plot {
            let title = match note {
                Some(n) => format!("{} (DC sweep, {n})", prepared.top),
                None => format!("{} (DC sweep)", prepared.top),
            };
            plot_panels_over(
                &pending.temp,
                &title,
                &sweep.name,
                &panels(&curves, args.both_ways),
            )
            .map_err(Report::from)
            .and_then(|()| pending.commit().map_err(Report::from))
            .inspect_err(|_| pending.abandon())?;
            written.push(pending.path.display().to_string());
        }
    }
    remove_on_exit(Vec::new());
    let files = if written.is_empty() {
        String::new()
    } else {
        format!("; wrote {}", written.join(", "))
    };
    eprintln!(
        "swept {} over {} of {} point(s) in {:.2} s{files}",
        sweep.name,
        curves.rows.len(),
        swept.planned,
        started.elapsed().as_secs_f64()
    );
    discard_at_exit(prepared);
    match swept.ending {
        Some((_, error)) => Err(error.into()),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(s: &str) -> Vec<String> {
        s.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn sweeps_include_their_end_without_drift() {
        let s = Sweep::parse(&words("Vin 0 1 0.1")).unwrap();
        assert_eq!(s.name, "vin");
        assert_eq!(s.values.len(), 11);
        assert_eq!(s.values[3], 0.3); // 0 + 3 * 0.1, rounded to the step's decimals
        let across = Sweep::parse(&words("x -0.3 0.3 0.1")).unwrap();
        assert_eq!(across.values[3], 0.0);
        let fine = Sweep::parse(&words("x 0 3e-12 1e-12")).unwrap();
        assert_eq!(fine.values, vec![0.0, 1e-12, 2e-12, 3e-12]);
        assert!(!s.whole);
        let down = Sweep::parse(&words("n 10 0 -5")).unwrap();
        assert_eq!(down.values, vec![10.0, 5.0, 0.0]);
        assert!(down.whole);
        assert_eq!(down.literal(5.0), "5");
        assert_eq!(s.literal(0.5), "0.5");
        assert_eq!(s.literal(1e-7), "1e-7");
        // A step that does not divide the range stops before TO.
        assert_eq!(Sweep::parse(&words("x 0 1 0.4")).unwrap().values.len(), 3);
    }

    #[test]
    fn bad_sweeps_say_why() {
        let problem = |s: &str| match Sweep::parse(&words(s)) {
            Err(CliError::SweepRange { problem, .. }) => problem,
            other => panic!("{other:?}"),
        };
        assert_eq!(problem("x 0 1 0"), "STEP is zero");
        assert!(problem("x 0 1 -0.1").contains("give STEP the sign"));
        assert!(problem("x 0 1e9 1e-3").contains("at most"));
        assert!(problem("x 0 one 1").contains("`one` is not a number"));
    }

    #[test]
    fn csv_has_a_row_per_point_and_says_where_it_stopped() {
        let curves = Curves {
            names: vec!["vout".into(), "i".into()],
            rows: vec![(0.0, 1.0, vec![0.0, 1.5]), (1.0, 1.0, vec![0.25, f64::NAN])],
        };
        assert_eq!(
            format_csv("vin", &curves, false, None),
            "vin,vout,i\n0,0,1.5\n1,0.25,\n"
        );
        let curves = Curves {
            names: vec!["vout".into()],
            rows: vec![(0.0, 1.0, vec![0.0]), (1.0, -1.0, vec![5.0])],
        };
        let both = format_csv("vin", &curves, true, Some("interrupted before vin = 2"));
        assert_eq!(
            both,
            "vin,direction,vout\n0,1,0\n1,-1,5\n# interrupted before vin = 2\n"
        );
    }

    #[test]
    fn columns_follow_a_structure_that_changes_along_the_sweep() {
        let solved = |names: &[&str], listed: &[bool]| Solved {
            point: names
                .iter()
                .enumerate()
                .map(|(k, n)| (n.to_string(), k as f64))
                .collect(),
            listed: listed.to_vec(),
        };
        let mut columns = Columns::default();
        columns.push(
            1.0,
            1.0,
            &solved(&["vout", "chain(0).v", "clk"], &[true, true, false]),
        );
        columns.push(
            2.0,
            1.0,
            &solved(
                &["vout", "chain(0).v", "chain(1).v", "clk"],
                &[true, true, true, false],
            ),
        );
        let all = columns.curves(&[]).unwrap();
        assert_eq!(all.names, ["vout", "chain(0).v", "chain(1).v"]);
        assert!(all.rows[0].2[2].is_nan());
        assert_eq!(all.rows[1].2, vec![0.0, 1.0, 2.0]);
        // A signal is reported when asked for; a probe met at no point is an error.
        let asked = columns.curves(&["CLK".into()]).unwrap();
        assert_eq!(asked.rows[1].2, vec![3.0]);
        match columns.curves(&["chain(2).v".into()]) {
            Err(CliError::DcProbe { help, .. }) => assert!(help.contains("did you mean")),
            other => panic!("{other:?}"),
        }
    }
}
