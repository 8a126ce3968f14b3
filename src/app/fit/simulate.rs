//! The simulator behind `vams fit`: each job elaborates an experiment's testbench with its
//! generics and the free parameters' values (the sources were analysed once), simulates it to
//! the end of its capture recording only the matched quantities, and reads them at the
//! capture's sample times. Jobs run on every core, in order, each with the deep stack that
//! VHDL recursion needs ([`crate::app::parallel`]).

use crate::app::compile::Prepared;
use crate::app::parallel::run_in_order;
use crate::app::render::{located_line, sim_error_line};
use crate::fit::series::{block_mean, near_jump};
use crate::fit::{Series, Simulate, Simulated};
use crate::kernel::{Outcome, SimOptions, simulate_into};
use crate::output::csv::format_number;
use crate::waveform::{ColumnKind, Waveforms};

/// One experiment as the simulator runs it.
pub struct Setup {
    pub top: String,
    /// Its fixed generics (the `--measured` settings).
    pub generics: Vec<(String, String)>,
    /// The quantities recorded, one per series of the experiment, in series order.
    pub probes: Vec<String>,
    /// Per series, the sample times and the durations they average over.
    pub times: Vec<Vec<f64>>,
    pub widths: Vec<Vec<f64>>,
    /// Per series, the interval of the samples its blocks were made of.
    pub sample_intervals: Vec<f64>,
    /// Its end: the last sample time.
    pub stop: f64,
    /// Quantities recorded beside the probes, for a caller that reads more of the run
    /// ([`DesignSimulator::read`]).
    pub record: Vec<String>,
}

impl Setup {
    /// The setup of experiment `e` from its series.
    pub fn new(top: String, generics: Vec<(String, String)>, e: usize, series: &[Series]) -> Setup {
        let mine: Vec<&Series> = series.iter().filter(|s| s.experiment == e).collect();
        // The end of the last block.
        let stop = mine
            .iter()
            .filter_map(|s| {
                let t = s.time.last()?;
                Some(t + 0.5 * s.width.last().copied().unwrap_or(0.0))
            })
            .fold(0.0, f64::max);
        Setup {
            top,
            generics,
            probes: mine.iter().map(|s| s.simulated.clone()).collect(),
            times: mine.iter().map(|s| s.time.clone()).collect(),
            widths: mine.iter().map(|s| s.width.clone()).collect(),
            sample_intervals: mine.iter().map(|s| s.sample_interval).collect(),
            stop,
            record: Vec::new(),
        }
    }
}

/// How every simulation of the fit runs.
pub struct DesignSimulator<'a> {
    pub prepared: &'a Prepared,
    pub setups: Vec<Setup>,
    /// The free parameters' names, and the experiment each belongs to (`None`: all), in the
    /// fit's order.
    pub names: Vec<(String, Option<usize>)>,
    pub reltol: f64,
    pub abstol: Option<f64>,
    pub max_step: Option<f64>,
    pub jobs: usize,
}

impl DesignSimulator<'_> {
    /// The generics of a job: the experiment's, then the free values (which win).
    pub fn generics(&self, e: usize, values: &[f64]) -> Vec<(String, String)> {
        let mut g = self.setups[e].generics.clone();
        g.extend(
            self.names
                .iter()
                .zip(values)
                .filter(|((_, only), _)| only.is_none_or(|k| k == e))
                .map(|((n, _), v)| (n.clone(), format_number(*v))),
        );
        g
    }

    /// Simulates experiment `e` with the free values `values`.
    pub fn run(&self, e: usize, values: &[f64]) -> Result<Waveforms, String> {
        let setup = &self.setups[e];
        let sources = &self.prepared.loaded.sources;
        let design = self
            .prepared
            .try_elaborate_top(&setup.top, &self.generics(e, values))
            .map_err(|errors| {
                errors
                    .first()
                    .map(|err| format!("elaboration: {}", located_line(err, sources)))
                    .unwrap_or_default()
            })?;
        let sim = SimOptions {
            stop: setup.stop,
            reltol: self.reltol,
            abstol: self.abstol,
            max_step: self.max_step,
            max_order: 5,
            probes: setup.probes.iter().chain(&setup.record).cloned().collect(),
            progress: None,
            keep_unknowns: false,
            cancel: None,
        };
        let mut waves = Waveforms::default();
        let end = simulate_into(&design, &sim, &mut waves, &mut |_| {})
            .map_err(|err| sim_error_line(&err, waves.times.last().copied(), sources))?;
        if let Outcome::Failed { time } = end.outcome {
            return Err(format!(
                "an assertion of severity failure at t = {}",
                crate::app::time::format_time(time)
            ));
        }
        Ok(waves)
    }

    /// The simulated values of experiment `e` at its series' times.
    pub fn sample(&self, e: usize, waves: &Waveforms) -> Result<Simulated, String> {
        let setup = &self.setups[e];
        (0..setup.probes.len())
            .map(|k| self.read(e, waves, &setup.probes[k], k))
            .collect()
    }

    /// Quantity `name` of a run of experiment `e` at the times of its series `k`: a signal
    /// as held at each time, a quantity as the mean over each block, `None` within a sample
    /// interval of a jump.
    pub fn read(
        &self,
        e: usize,
        waves: &Waveforms,
        name: &str,
        k: usize,
    ) -> Result<Vec<Option<f64>>, String> {
        let setup = &self.setups[e];
        let (times, widths, dt) = (&setup.times[k], &setup.widths[k], setup.sample_intervals[k]);
        let col = waves
            .column(name)
            .ok_or_else(|| format!("the run recorded no `{name}`"))?;
        let held = matches!(col.kind, ColumnKind::Signal { .. });
        let mut hint = 0;
        Ok(times
            .iter()
            .enumerate()
            .map(|(n, &t)| {
                if held {
                    let k = waves.times.partition_point(|x| *x <= t);
                    Some(col.values[k.saturating_sub(1).min(col.values.len() - 1)])
                } else {
                    let w = widths.get(n).copied().unwrap_or(0.0);
                    (!near_jump(&waves.times, &col.values, t, w, dt))
                        .then(|| block_mean(&waves.times, &col.values, t, w, &mut hint))
                }
            })
            .collect())
    }
}

impl Simulate for DesignSimulator<'_> {
    type Error = String;

    fn simulate(&self, jobs: &[(usize, Vec<f64>)]) -> Vec<Result<Simulated, String>> {
        simulate_jobs(jobs, self.jobs, |e, values| {
            self.run(e, values).and_then(|w| self.sample(e, &w))
        })
    }
}

/// Runs `job` (experiment, free values) for each job on `threads` cores, the results in the
/// jobs' order; a job that panics is an error of its own.
pub fn simulate_jobs(
    jobs: &[(usize, Vec<f64>)],
    threads: usize,
    job: impl Fn(usize, &[f64]) -> Result<Simulated, String> + Sync,
) -> Vec<Result<Simulated, String>> {
    let mut out: Vec<Result<Simulated, String>> = Vec::with_capacity(jobs.len());
    run_in_order(
        jobs,
        threads,
        |(e, values)| job(*e, values),
        |_, result| {
            out.push(match result {
                Ok(r) => r,
                Err(panic) => Err(format!("internal error: {panic}")),
            })
        },
    );
    out
}
