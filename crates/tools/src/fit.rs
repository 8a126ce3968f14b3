//! Estimating a model's generics from measured waveforms (`vams fit`).
//!
//! Takes the free parameters ([`FreeParam`]: guess and bounds), the measured series
//! ([`Series`]: one column of one capture each) and a [`Simulate`] that runs the model of an
//! experiment with given parameter values and gives its simulated values at the series'
//! times; gives the fitted values with two 95 % intervals, the correlations, the directions the
//! captures do not determine, and the residual of each series ([`Fitted`]).
//!
//! The fit minimises the weighted residual of all series jointly ([`lm`]: Levenberg-Marquardt
//! with bounds, positive parameters in log space). Weights: each series is divided by its
//! noise (estimated from its own samples) for a first pass, then by its RMS residual after
//! that pass for a second, so that a series the model cannot follow to its noise (a ripple
//! the model lacks) weighs as much as it deserves and the residual per degree of freedom is
//! about one. Then [`uncertainty`] turns the residual into intervals. It never prints, never
//! reads files, and knows nothing of VHDL: the caller simulates.

pub mod drive;
pub mod lm;
pub mod param;
pub mod series;
pub mod uncertainty;

pub use lm::{Ending, Settings};
pub use param::{FreeParam, Scale};
pub use series::Series;
pub use uncertainty::{Uncertainty, Unidentified};

use std::ops::Range;
use std::sync::Mutex;

/// What runs the model: the caller's simulator.
pub trait Simulate: Sync {
    /// Why a simulation failed.
    type Error: Clone + std::fmt::Display + Send;
    /// Simulates each job (experiment, parameter values in the order of the free
    /// parameters), in parallel where it can; each result holds, per series of that
    /// experiment (in the order of [`Fit::series`]), the simulated values at its times.
    fn simulate(&self, jobs: &[(usize, Vec<f64>)]) -> Vec<Result<Simulated, Self::Error>>;
}

/// One experiment's simulated series (see [`Simulate::simulate`]). `None` at a point the
/// simulation cannot be compared at: a jump of the simulated trace (a switch) within a sample
/// interval of it. A sampled jump tells only which side of it each sample lies on; compared
/// there, a switching time's sensitivity would be the jump over the difference step whenever
/// the step crosses a sample, and its interval as narrow as that step.
pub type Simulated = Vec<Vec<Option<f64>>>;

/// A fit to set up.
pub struct Fit<'a, S: Simulate> {
    pub simulator: &'a S,
    pub params: &'a [FreeParam],
    pub series: &'a [Series],
    pub experiments: usize,
    pub settings: Settings,
    /// Seed of the bootstrap.
    pub seed: u64,
}

/// A parameter's result.
#[derive(Debug, Clone)]
pub struct Estimate {
    pub value: f64,
    /// The 95 % interval from the covariance (None where undetermined or at a bound).
    pub interval: Option<(f64, f64)>,
    /// The 95 % interval that also holds for correlated noise and model error: the block
    /// bootstrap's, widened to the covariance's where that is wider.
    pub robust: Option<(f64, f64)>,
    /// Ended at a bound.
    pub at_bound: bool,
    /// Per experiment, the size of the parameter's effect on the weighted residual (the
    /// norm of its Jacobian column over the experiment's rows): where it shows.
    pub influence: Vec<f64>,
}

/// A series' agreement.
#[derive(Debug, Clone)]
pub struct SeriesFit {
    /// RMS of simulated less measured at the start, in the series' unit.
    pub rms_start: f64,
    /// RMS at the end.
    pub rms: f64,
    /// The simulated values at the end.
    pub simulated: Vec<f64>,
}

/// The fit's result.
#[derive(Debug, Clone)]
pub struct Fitted {
    pub estimates: Vec<Estimate>,
    /// The fitted offsets ([`Series::offset`]), by number.
    pub offsets: Vec<Estimate>,
    pub series: Vec<SeriesFit>,
    pub uncertainty: Uncertainty,
    pub iterations: usize,
    /// Simulations run (each point evaluates every experiment).
    pub simulations: usize,
    pub ending: Ending,
    /// The experiments whose cost (the sum of their series' squared misfits, each weighed
    /// by its misfit) the fit's end made at least four times its start's. A fit that bends
    /// that far from one capture to follow the others has found an experiment the model
    /// does not reproduce: it is not reported, the start is ([`Fitted::start_reported`]).
    pub worse_than_start: Vec<usize>,
    /// The experiments the fit ended worse on than its start, but not far ([`Fitted::run`]'s
    /// rule), each with the ratio of its weighted RMS misfit at the end to the start's.
    pub traded: Vec<(usize, f64)>,
    /// The values, intervals (none) and series are the start's, not the fit's end.
    pub start_reported: bool,
}

impl Fitted {
    /// Whether the result can be trusted as a least-squares estimate: the iteration ended
    /// by converging (or at a minimum to the simulations' precision), no parameter at a
    /// bound, and no capture worse than at the start. Otherwise the intervals are not
    /// reliable.
    pub fn converged(&self) -> bool {
        self.ending != Ending::IterationLimit
            && !self.estimates.iter().any(|e| e.at_bound)
            && self.worse_than_start.is_empty()
    }
}

/// The failure of a fit.
#[derive(Debug, Clone)]
pub enum FitError<E> {
    /// The simulation of an experiment failed at the first guess.
    Start(E),
    /// The first guess gives a non-finite residual.
    NotFinite,
    /// A difference simulation failed.
    Sensitivity { parameter: String, error: E },
}

impl<E: std::fmt::Display> std::fmt::Display for FitError<E> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FitError::Start(e) => write!(f, "the simulation at the first guess failed: {e}"),
            FitError::NotFinite => {
                f.write_str("the simulation at the first guess gives a non-finite value")
            }
            FitError::Sensitivity { parameter, error } => write!(
                f,
                "the simulation with `{parameter}` changed slightly failed: {error}"
            ),
        }
    }
}

/// The weighted residual of a fit: [`lm::Residuals`] over the caller's simulator. The
/// optimiser's vector holds the parameters' coordinates, then the offsets' (in units of their
/// series' magnitude, [`Fit::offset_units`]).
struct Weighted<'a, S: Simulate> {
    fit: &'a Fit<'a, S>,
    sigma: Vec<f64>,
    units: Vec<f64>,
    /// The last point simulated alone (a trial step, the start) with its series: the
    /// sensitivities to the offsets change no simulated value, and reuse it.
    last: Mutex<Option<(Vec<f64>, Simulated)>>,
}

impl<'a, S: Simulate> Weighted<'a, S> {
    fn new(fit: &'a Fit<'a, S>, sigma: Vec<f64>) -> Self {
        Weighted {
            fit,
            sigma,
            units: fit.offset_units(),
            last: Mutex::new(None),
        }
    }

    /// The simulated series at each point: each distinct set of parameter values simulated
    /// once (points that differ only in offsets share it).
    fn simulate(&self, points: &[Vec<f64>]) -> Vec<Result<Simulated, S::Error>> {
        let ne = self.fit.experiments;
        let np = self.fit.params.len();
        let key = |x: &Vec<f64>| x[..np.min(x.len())].to_vec();
        let cached = self
            .last
            .lock()
            .ok()
            .and_then(|last| last.as_ref().map(|(k, sims)| (k.clone(), sims.clone())));
        // Which distinct parameter vector each point simulates (None: the cached one).
        let mut distinct: Vec<Vec<f64>> = Vec::new();
        let slot: Vec<Option<usize>> = points
            .iter()
            .map(|x| {
                let k = key(x);
                if cached.as_ref().is_some_and(|(c, _)| *c == k) {
                    return None;
                }
                Some(distinct.iter().position(|d| *d == k).unwrap_or_else(|| {
                    distinct.push(k);
                    distinct.len() - 1
                }))
            })
            .collect();
        let jobs: Vec<(usize, Vec<f64>)> = distinct
            .iter()
            .flat_map(|x| {
                let values: Vec<f64> = self
                    .fit
                    .params
                    .iter()
                    .zip(x)
                    .map(|(p, x)| p.from_x(*x))
                    .collect();
                (0..ne).map(move |e| (e, values.clone()))
            })
            .collect();
        let mut results = self.fit.simulator.simulate(&jobs).into_iter();
        let simulated: Vec<Result<Simulated, S::Error>> = distinct
            .iter()
            .map(|_| {
                let per_experiment: Vec<_> = results.by_ref().take(ne).collect();
                let mut out = vec![Vec::new(); self.fit.series.len()];
                let mut next = vec![0usize; ne];
                let mut sims = Vec::with_capacity(ne);
                for r in per_experiment {
                    sims.push(r?);
                }
                for (k, s) in self.fit.series.iter().enumerate() {
                    let e = s.experiment;
                    out[k] = std::mem::take(sims[e].get_mut(next[e]).unwrap_or(&mut Vec::new()));
                    next[e] += 1;
                }
                Ok(out)
            })
            .collect();
        // A point simulated alone is where the iteration stands next (a start, a trial).
        if let ([only], [Ok(sims)]) = (distinct.as_slice(), simulated.as_slice())
            && let Ok(mut last) = self.last.lock()
        {
            *last = Some((only.clone(), sims.clone()));
        }
        slot.iter()
            .map(|s| match s {
                Some(k) => simulated[*k].clone(),
                // The cached vector exists whenever a point maps to it.
                None => Ok(cached
                    .as_ref()
                    .map(|(_, sims)| sims.clone())
                    .unwrap_or_default()),
            })
            .collect()
    }

    /// Offset `k`'s value at the optimiser's vector `x`.
    fn offset(&self, x: &[f64], k: usize) -> f64 {
        let np = self.fit.params.len();
        x.get(np + k).copied().unwrap_or(0.0) * self.units.get(k).copied().unwrap_or(1.0)
    }

    fn weigh(&self, x: &[f64], sims: &[Vec<Option<f64>>]) -> Vec<f64> {
        let mut r = Vec::new();
        for (k, s) in self.fit.series.iter().enumerate() {
            let w = 1.0 / self.sigma[k];
            let sim = &sims[k];
            // The probe reads the simulated value plus its offset.
            let m0 = s.offset.map_or(0.0, |o| self.offset(x, o));
            for (n, m) in s.measured.iter().enumerate() {
                let m = m - m0;
                // A simulation that gave fewer values than the series has (it cannot, but a
                // missing value must not shift the rows): NaN rejects the point. A point not
                // compared keeps its row with a residual of zero.
                r.push(match sim.get(n) {
                    Some(Some(v)) => (v - m) * w,
                    Some(None) => 0.0,
                    None => f64::NAN,
                });
            }
        }
        r
    }
}

impl<S: Simulate> Weighted<'_, S> {
    /// The simulated series behind a weighted residual (`measured + r sigma`): what a point
    /// the iteration evaluated gave, without simulating it again.
    fn unweigh(&self, residual: &[f64]) -> Vec<Vec<f64>> {
        let mut rows = residual.iter();
        self.fit
            .series
            .iter()
            .zip(&self.sigma)
            .map(|(s, sigma)| {
                s.measured
                    .iter()
                    .zip(rows.by_ref())
                    .map(|(m, r)| m + r * sigma)
                    .collect()
            })
            .collect()
    }
}

impl<S: Simulate> lm::Residuals for Weighted<'_, S> {
    type Error = S::Error;
    fn evaluate(&self, points: &[Vec<f64>]) -> Vec<Result<Vec<f64>, S::Error>> {
        self.simulate(points)
            .into_iter()
            .zip(points)
            .map(|(r, x)| r.map(|sims| self.weigh(x, &sims)))
            .collect()
    }
}

/// An interval's ends.
type Ends = (f64, f64);

/// The two 95 % intervals of coordinate `k` at `x` (see [`Estimate`]), as values (`value`
/// maps a coordinate to its value). The second is never narrower than the first (a bootstrap
/// of few blocks can come out narrow by chance, and an engineer designs with this one), and
/// holds the interval without any one series that does not alone determine the coordinate.
fn intervals(
    u: &Uncertainty,
    k: usize,
    x: f64,
    value: impl Fn(f64) -> f64,
) -> (Option<Ends>, Option<Ends>) {
    let ordered = |a: f64, b: f64| (a.min(b), a.max(b));
    let sd = u.sd[k];
    let interval = sd
        .is_finite()
        .then(|| ordered(value(x - u.t95 * sd), value(x + u.t95 * sd)));
    let robust = robust_range(u.bootstrap[k], u.leave_one_out[k]).map(|(lo, hi)| {
        let (a, b) = ordered(value(x + lo), value(x + hi));
        interval.map_or((a, b), |(c, d)| (a.min(c), b.max(d)))
    });
    (interval, robust)
}

/// The second interval's reach around the estimate (optimiser's coordinates): the
/// bootstrap's, widened to the intervals without one series.
fn robust_range(
    bootstrap: Option<(f64, f64)>,
    leave_one_out: Option<(f64, f64)>,
) -> Option<(f64, f64)> {
    match (bootstrap, leave_one_out) {
        (Some((a, b)), Some((c, d))) => Some((a.min(c), b.max(d))),
        (b, None) => b,
        (None, l) => l,
    }
}

fn rms_per_series(series: &[Series], sims: &[Vec<f64>]) -> Vec<f64> {
    series
        .iter()
        .zip(sims)
        .map(|(s, sim)| {
            let n = s.measured.len().max(1) as f64;
            (s.measured
                .iter()
                .zip(sim)
                .map(|(m, v)| (v - m) * (v - m))
                .sum::<f64>()
                / n)
                .sqrt()
        })
        .collect()
}

impl<S: Simulate> Fit<'_, S> {
    /// The row ranges of each series in the residual.
    fn ranges(&self) -> Vec<Range<usize>> {
        let mut start = 0;
        self.series
            .iter()
            .map(|s| {
                let r = start..start + s.measured.len();
                start = r.end;
                r
            })
            .collect()
    }

    fn lm_error(&self, e: lm::LmError<S::Error>) -> FitError<S::Error> {
        match e {
            lm::LmError::Start(e) => FitError::Start(e),
            lm::LmError::NotFinite => FitError::NotFinite,
            lm::LmError::Jacobian { coordinate, error } => FitError::Sensitivity {
                parameter: self.params.get(coordinate).map_or_else(
                    || format!("offset {}", coordinate - self.params.len()),
                    |p| p.name.clone(),
                ),
                error,
            },
        }
    }

    /// How many offsets the series name ([`Series::offset`]).
    pub fn offset_count(&self) -> usize {
        (self.series.iter().filter_map(|s| s.offset).max()).map_or(0, |k| k + 1)
    }

    /// Each offset's unit in the optimiser's vector: the RMS of the measured values of the
    /// first series that names it, so that a step of the optimiser is of the signal's size.
    fn offset_units(&self) -> Vec<f64> {
        (0..self.offset_count())
            .map(|k| {
                self.series
                    .iter()
                    .find(|s| s.offset == Some(k))
                    .map(|s| {
                        let n = s.measured.len().max(1) as f64;
                        (s.measured.iter().map(|v| v * v).sum::<f64>() / n).sqrt()
                    })
                    .filter(|u| u.is_finite() && *u > 0.0)
                    .unwrap_or(1.0)
            })
            .collect()
    }

    /// Runs the fit.
    pub fn run(&self) -> Result<Fitted, FitError<S::Error>> {
        let offsets = self.offset_count();
        let np = self.params.len();
        // The offsets start at zero and are unbounded.
        let x0: Vec<f64> = (self.params.iter().map(|p| p.to_x(p.guess)))
            .chain(std::iter::repeat_n(0.0, offsets))
            .collect();
        let bounds: Vec<(f64, f64)> = (self.params.iter().map(FreeParam::x_bounds))
            .chain(std::iter::repeat_n(
                (f64::NEG_INFINITY, f64::INFINITY),
                offsets,
            ))
            .collect();
        let noise: Vec<f64> = self.series.iter().map(Series::noise).collect();
        let first = Weighted::new(self, noise);
        let pass1 =
            lm::minimise(&first, &x0, &bounds, &self.settings).map_err(|e| self.lm_error(e))?;
        // Reweigh by each series' own misfit.
        let rms_start = rms_per_series(self.series, &first.unweigh(&pass1.start_residual));
        let rms1 = rms_per_series(self.series, &first.unweigh(&pass1.residual));
        // Each series weighs by its own misfit (a series the model cannot follow to its noise,
        // a ripple the model lacks, weighs as much as it deserves). Weighing by the misfit's
        // correlation time as well was tried: on the motor's captures it let a capture with
        // a slow misfit pull R by 1 %, against 0.1 % without.
        let ranges = self.ranges();
        let sigma = rms1
            .iter()
            .zip(&first.sigma)
            .zip(self.series)
            .map(|((r, n), s)| match s.sigma {
                Some(known) => known,
                None => r.max(*n * 1e-3).max(f64::MIN_POSITIVE),
            })
            .collect();
        let second = Weighted::new(self, sigma);
        let pass2 = lm::minimise(&second, &pass1.x, &bounds, &self.settings)
            .map_err(|e| self.lm_error(e))?;
        let end_sims = second.unweigh(&pass2.residual);
        let rms = rms_per_series(self.series, &end_sims);
        // Each experiment's cost at the start and at the end, at the final weights (each
        // series' own misfit: about one per sample at the end), and its samples.
        let experiment_cost = |rms: &[f64]| -> Vec<f64> {
            let mut cost = vec![0.0; self.experiments];
            for ((s, r), w) in self.series.iter().zip(rms).zip(&second.sigma) {
                if let Some(c) = cost.get_mut(s.experiment) {
                    *c += s.measured.len() as f64 * (r / w).powi(2);
                }
            }
            cost
        };
        let (cost_start, cost_end) = (experiment_cost(&rms_start), experiment_cost(&rms));
        let mut samples = vec![0usize; self.experiments];
        for s in self.series {
            if let Some(n) = samples.get_mut(s.experiment) {
                *n += s.measured.len();
            }
        }
        // Worse: the capture's misfit at least doubled (its cost four times the start's),
        // beyond what the noise explains (three standard deviations of a chi-square of that
        // many samples). A start fitted to one capture alone (the paper's method reads the
        // motor's friction from the constant-speed capture) is better there than a joint fit
        // that must also follow the other captures with a model a little off: that trade is a
        // warning ([`Fitted::traded`]); a fit that bends the model far from one capture to
        // reach the others has found an experiment the model does not reproduce.
        let margin = |e: usize| 3.0 * (2.0 * samples[e] as f64).sqrt();
        let worse_than_start: Vec<usize> = (0..self.experiments)
            .filter(|&e| cost_end[e] > 4.0 * cost_start[e] + margin(e))
            .collect();
        let traded: Vec<(usize, f64)> = (0..self.experiments)
            .filter(|&e| !worse_than_start.contains(&e) && cost_end[e] > cost_start[e] + margin(e))
            .map(|e| {
                (
                    e,
                    (cost_end[e] / cost_start[e].max(f64::MIN_POSITIVE)).sqrt(),
                )
            })
            .collect();
        let start_reported = !worse_than_start.is_empty();
        let u = uncertainty::analyse(
            &pass2.jacobian,
            &pass2.residual,
            &ranges,
            &pass2.at_bound,
            self.seed,
            false,
        );
        let offsets = (0..offsets)
            .map(|k| {
                let (x, unit) = (pass2.x[np + k], second.units[k]);
                let (x, (interval, robust)) = if start_reported {
                    (0.0, (None, None))
                } else {
                    (x, intervals(&u, np + k, x, |x| x * unit))
                };
                Estimate {
                    value: x * unit,
                    interval,
                    robust,
                    at_bound: false,
                    influence: Vec::new(),
                }
            })
            .collect();
        let estimates = self
            .params
            .iter()
            .enumerate()
            .map(|(k, p)| {
                let x = pass2.x[k];
                let (interval, robust) = if pass2.at_bound[k] || start_reported {
                    (None, None)
                } else {
                    intervals(&u, k, x, |x| p.from_x(x))
                };
                let influence = (0..self.experiments)
                    .map(|e| {
                        self.series
                            .iter()
                            .zip(&ranges)
                            .filter(|(s, _)| s.experiment == e)
                            .flat_map(|(_, r)| r.clone())
                            .map(|row| pass2.jacobian[(row, k)].powi(2))
                            .sum::<f64>()
                            .sqrt()
                    })
                    .collect();
                // At a bound the value is the bound as given, not its round trip through
                // the logarithm.
                let (lo, hi) = bounds[k];
                let value = match (p.lower, p.upper) {
                    _ if start_reported => p.guess,
                    (Some(b), _) if x <= lo => b,
                    (_, Some(b)) if x >= hi => b,
                    _ => p.from_x(x),
                };
                Estimate {
                    value,
                    interval,
                    robust,
                    at_bound: pass2.at_bound[k],
                    influence,
                }
            })
            .collect();
        let reported_sims = if start_reported {
            first.unweigh(&pass1.start_residual)
        } else {
            end_sims
        };
        let series = reported_sims
            .into_iter()
            .zip(if start_reported { &rms_start } else { &rms })
            .zip(&rms_start)
            .map(|((simulated, rms), rms_start)| SeriesFit {
                rms_start: *rms_start,
                rms: *rms,
                simulated,
            })
            .collect();
        Ok(Fitted {
            estimates,
            offsets,
            series,
            uncertainty: u,
            iterations: pass1.iterations + pass2.iterations,
            simulations: (pass1.evaluations + pass2.evaluations) * self.experiments,
            ending: pass2.ending,
            worse_than_start,
            traded,
            start_reported,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A first-order step response `k (1 - exp(-t/tau))` per experiment, with the step's
    /// height the experiment's own: the "simulator" is the closed form.
    struct FirstOrder;

    impl Simulate for FirstOrder {
        type Error = String;
        fn simulate(&self, jobs: &[(usize, Vec<f64>)]) -> Vec<Result<Simulated, String>> {
            jobs.iter()
                .map(|(e, p)| {
                    let (k, tau) = (p[0], p[1]);
                    let height = [1.0, 2.0][*e];
                    Ok(vec![
                        (0..300)
                            .map(|n| Some(height * k * (1.0 - (-(n as f64) * 1e-3 / tau).exp())))
                            .collect(),
                    ])
                })
                .collect()
        }
    }

    fn series(k: f64, tau: f64, noise: f64) -> Vec<Series> {
        (0..2)
            .map(|e| {
                let height = [1.0, 2.0][e];
                Series {
                    experiment: e,
                    simulated: "y".into(),
                    label: format!("capture {e}: y"),
                    time: (0..300).map(|n| n as f64 * 1e-3).collect(),
                    measured: (0..300)
                        .map(|n| {
                            let wobble = noise * (((n * 7919 + e * 31) % 17) as f64 / 8.0 - 1.0);
                            height * k * (1.0 - (-(n as f64) * 1e-3 / tau).exp()) + wobble
                        })
                        .collect(),
                    width: Vec::new(),
                    sample_interval: 0.0,
                    sigma: None,
                    offset: None,
                }
            })
            .collect()
    }

    /// `k` and `tau` of [`FirstOrder`] fitted to `series`.
    fn fit_first_order(series: &[Series]) -> Fitted {
        let params = [
            FreeParam::parse("k=1:0.1:10").unwrap(),
            FreeParam::parse("tau=0.01").unwrap(),
        ];
        let fit = Fit {
            simulator: &FirstOrder,
            params: &params,
            series,
            experiments: 2,
            settings: Settings::default(),
            seed: 1,
        };
        fit.run().unwrap()
    }

    #[test]
    fn fits_two_experiments_jointly_and_covers_the_truth() {
        let f = fit_first_order(&series(2.5, 0.04, 0.01));
        for (e, truth) in f.estimates.iter().zip([2.5, 0.04]) {
            assert!((e.value - truth).abs() / truth < 0.01, "{e:?}");
            let (lo, hi) = e.interval.unwrap();
            assert!(lo < truth && truth < hi, "{e:?}");
            let (lo, hi) = e.robust.unwrap();
            assert!(lo < truth && truth < hi, "{e:?}");
        }
        assert!(f.series[0].rms < 0.02 && f.series[0].rms_start > 0.5);
        assert!(f.uncertainty.unidentified.is_empty());
    }

    #[test]
    fn a_probe_offset_is_fitted_and_counted() {
        // Both captures read 0.3 high through one probe (offset 0); the step starts at
        // zero, so the offset is told apart from the height.
        let mut series = series(2.5, 0.04, 0.01);
        for s in &mut series {
            s.offset = Some(0);
            s.measured.iter_mut().for_each(|v| *v += 0.3);
        }
        let f = fit_first_order(&series);
        for (e, truth) in f.estimates.iter().zip([2.5, 0.04]) {
            assert!((e.value - truth).abs() / truth < 0.01, "{e:?}");
            let (lo, hi) = e.interval.unwrap();
            assert!(lo < truth && truth < hi, "{e:?}");
        }
        let o = &f.offsets[0];
        assert!((o.value - 0.3).abs() < 0.01, "{o:?}");
        let (lo, hi) = o.interval.unwrap();
        assert!(lo < 0.3 && 0.3 < hi, "{o:?}");
        // The simulated series as the probe reads them: the offset included.
        assert!(f.series[0].rms < 0.02, "{}", f.series[0].rms);
    }
}
