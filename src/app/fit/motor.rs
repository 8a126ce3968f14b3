//! The DC motor preset (`vams extract`): the paper's four captures fitted with the bundled
//! `dc_motor` and `constant_friction` models on their bench (`models/fit/tb_motor_bench.vhd`),
//! starting from the paper's estimates. There is no other copy of the motor's equations: the
//! simulations are the models the servo runs.
//!
//! Experiments: the inrush and the blocked rotor from the captured voltage step (the time the
//! switch closed is a nuisance parameter of each, fitted too: half a sample of error in it is
//! a percent of the electrical time constant), the constant speed and the coast after the
//! bench has run the motor up to speed (a settling time of 25 mechanical time constants at the
//! paper's values) and the coast's cut at its captured time. Each experiment has its own
//! supply `vs` and source resistance `rs`: labs take the blocked rotor at a few volts beside
//! runs at the full supply, each on its own bench supply, and one supply for all four bends
//! every motor parameter to fit them. The inrush and the blocked rotor draw a changing
//! current, so their sag makes `rs` identifiable; the constant-speed and coasting captures
//! draw a constant one before the cut, which only `vs - rs i` shows: there `rs` is 0 and `vs`
//! is the terminal voltage. Compared: the current and the terminal voltage of each capture
//! (the voltage makes the supply identifiable, which the current alone confuses with R), and
//! the speed read from the ripple of the constant-speed capture (a value with its standard
//! error: without a speed, scaling Ke, J, D and Tcst together leaves every current
//! unchanged).

use crate::app::compile::{Prepared, prepare_loaded};
use crate::app::load::load_texts;
use crate::capture::{Capture, Channel};
use crate::extract::MotorParams;
use crate::extract::paper::{PaperEstimates, Prepared as Captures};
use crate::extract::ripple::RippleModel;
use crate::fit::series::{block_widths, sample_interval};
use crate::fit::{Fit, FitError, Fitted, FreeParam, Series, Settings, Simulate, Simulated};

use super::simulate::{DesignSimulator, Setup, simulate_jobs};

/// The bundled models of the bench.
const SOURCES: [(&str, &str); 3] = [
    (
        "models/dc_motor.vhd",
        include_str!("../../../models/dc_motor.vhd"),
    ),
    (
        "models/constant_friction.vhd",
        include_str!("../../../models/constant_friction.vhd"),
    ),
    (
        "models/fit/tb_motor_bench.vhd",
        include_str!("../../../models/fit/tb_motor_bench.vhd"),
    ),
];

/// The roles of the captures, in the order of the experiments.
pub const ROLES: [&str; 4] = ["inrush", "blocked", "speed", "coast"];

/// The fitted generics of the motor, in the order of the fit's first parameters.
const MOTOR: [&str; 6] = ["r", "l", "ke", "j", "d", "tcst_motor"];

/// The bench with the commutation ripple of the inrush current ([`RippleModel`]): the
/// rotor starts from rest there, and its first commutation period is a swell of the current
/// that, without the ripple, reads as a lower resistance. The other captures average many
/// periods (or none: the blocked rotor), and their ripple's phase after the run-up would make
/// the residual hang on the whole run-up's angle.
struct MotorBench<'a> {
    bench: DesignSimulator<'a>,
    ripple: RippleModel,
    /// Per experiment, the series with a ripple: the index among the experiment's series and
    /// the measured values.
    rippled: Vec<Vec<(usize, Vec<f64>)>>,
}

impl MotorBench<'_> {
    /// The bench's quantity the ripple's phase is read from.
    const ANGLE: &'static str = "angle";

    fn sample(&self, e: usize, values: &[f64]) -> Result<Simulated, String> {
        let waves = self.bench.run(e, values)?;
        let mut simulated = self.bench.sample(e, &waves)?;
        for (k, measured) in &self.rippled[e] {
            let angle = self.bench.read(e, &waves, Self::ANGLE, *k)?;
            simulated[*k] = self.ripple.apply(&simulated[*k], &angle, measured);
        }
        Ok(simulated)
    }
}

impl Simulate for MotorBench<'_> {
    type Error = String;

    fn simulate(&self, jobs: &[(usize, Vec<f64>)]) -> Vec<Result<Simulated, String>> {
        simulate_jobs(jobs, self.bench.jobs, |e, values| self.sample(e, values))
    }
}

/// The preset's fit.
pub struct MotorFit {
    pub fitted: Fitted,
    pub params: Vec<FreeParam>,
    pub series: Vec<Series>,
    /// The capture file of each experiment.
    pub captures: Vec<String>,
    /// The fitted motor (kt = ke).
    pub motor: MotorParams,
    /// Per role, the index of its main series (current; the coast's voltage).
    pub main_series: [usize; 4],
}

impl MotorFit {
    /// Standard errors in the order of [`MotorParams::NAMES`] (from the covariance, in the
    /// parameters' units; NaN where undetermined).
    pub fn se(&self) -> [f64; 7] {
        let se = |k: usize| {
            let e = &self.fitted.estimates[k];
            e.interval.map_or(f64::NAN, |(lo, hi)| {
                (hi - lo) / 2.0 / self.fitted.uncertainty.t95
            })
        };
        [se(0), se(1), se(2), se(2), se(3), se(4), se(5)]
    }
}

/// The bench's models analysed, `tb_motor_bench` the top.
pub fn bench() -> Result<Prepared, miette::Report> {
    let texts = SOURCES
        .iter()
        .map(|(name, text)| (name.to_string(), text.to_string()))
        .collect();
    // The bundled models: a failure here is ours, its summary is enough.
    prepare_loaded(load_texts(texts), Some("tb_motor_bench"), Vec::new()).map_err(|n| n.error)
}

/// A capture of the extraction as a reduced general capture: block means down to `points`,
/// with the blocks' durations.
fn reduced(cap: &crate::extract::Capture, from: usize, points: usize) -> (Capture, Vec<f64>, f64) {
    let channel = |name: &str, unit: &str, values: &[f64]| Channel {
        name: name.into(),
        unit: Some(unit.into()),
        values: values[from..].to_vec(),
        clipped: vec![false; values.len() - from],
    };
    let widths = block_widths(&cap.t[from..], points);
    let reduced = Capture {
        path: cap.path.clone(),
        time: cap.t[from..].to_vec(),
        channels: vec![
            channel("voltage", "V", &cap.v),
            channel("current", "A", &cap.i),
        ],
        ..Capture::default()
    }
    .decimated(points);
    (reduced, widths, sample_interval(&cap.t[from..]))
}

/// The series of one capture (already shifted to simulation time): per quantity, the
/// capture's column and the number of its probe's offset.
fn series_of(
    e: usize,
    (cap, widths, dt): &(Capture, Vec<f64>, f64),
    role: &str,
    wanted: &[(&str, &str, usize)],
) -> Vec<Series> {
    wanted
        .iter()
        .filter_map(|(quantity, column, offset)| {
            let ch = cap.channel(column)?;
            let keep: Vec<usize> = (0..cap.time.len())
                .filter(|&k| cap.time[k] >= 0.0)
                .collect();
            Some(Series {
                experiment: e,
                simulated: quantity.to_string(),
                label: format!("{role}: {column}"),
                time: keep.iter().map(|&k| cap.time[k]).collect(),
                measured: keep.iter().map(|&k| ch.values[k]).collect(),
                width: if widths.is_empty() {
                    Vec::new()
                } else {
                    keep.iter().map(|&k| widths[k]).collect()
                },
                sample_interval: *dt,
                sigma: None,
                offset: Some(*offset),
            })
        })
        .collect()
}

fn positive(name: &str, guess: f64) -> FreeParam {
    let guess = guess.abs().max(1e-12);
    FreeParam {
        name: name.into(),
        guess,
        lower: Some(guess / 100.0),
        upper: Some(guess * 100.0),
        experiment: None,
    }
}

/// The first stage of the fit: R and L from the blocked rotor alone (with its supply, source
/// resistance, switching time and probe offsets), where no mechanics enter. The joint fit
/// starts from there: from the paper's estimates at once, an inrush sampled coarsely (a
/// dozen samples per electrical time constant) with a ripple a little unlike the model's
/// could pull R and L away from the blocked rotor into a minimum that traded that capture's
/// agreement (one lab of 24: L 6 % off, a switching time at its bound). Gives the stage's
/// fit and, per its parameter, the index among `params`; `None` when it did not converge
/// (the joint fit then starts from the paper's estimates).
fn blocked_alone(
    prepared: &Prepared,
    params: &[FreeParam],
    series: &[Series],
    generics: &[(String, String)],
    jobs: usize,
    seed: u64,
) -> Option<(Fitted, Vec<usize>)> {
    const BLOCKED: usize = 1;
    let index: Vec<usize> = (0..params.len())
        .filter(|&k| {
            let p = &params[k];
            p.experiment == Some(BLOCKED)
                || (p.experiment.is_none() && (p.name == "r" || p.name == "l"))
        })
        .collect();
    let own: Vec<FreeParam> = index
        .iter()
        .map(|&k| FreeParam {
            experiment: None,
            ..params[k].clone()
        })
        .collect();
    // Its series alone, as experiment 0, its probes' offsets numbered from 0.
    let mut own_series: Vec<Series> = series
        .iter()
        .filter(|s| s.experiment == BLOCKED)
        .cloned()
        .collect();
    let first_offset = own_series
        .iter()
        .filter_map(|s| s.offset)
        .min()
        .unwrap_or(0);
    for s in &mut own_series {
        s.experiment = 0;
        s.offset = s.offset.map(|o| o - first_offset);
    }
    // The motor's other parameters at their guesses (the rotor is held: they hardly act).
    let mut generics = generics.to_vec();
    generics.extend(
        (params.iter())
            .filter(|p| p.experiment.is_none() && !own.iter().any(|o| o.name == p.name))
            .map(|p| (p.name.clone(), crate::output::csv::format_number(p.guess))),
    );
    let sim = DesignSimulator {
        prepared,
        setups: vec![Setup::new(
            "tb_motor_bench".into(),
            generics,
            0,
            &own_series,
        )],
        names: own.iter().map(|p| (p.name.clone(), None)).collect(),
        reltol: 1e-6,
        abstol: None,
        max_step: None,
        jobs,
    };
    let fit = Fit {
        simulator: &sim,
        params: &own,
        series: &own_series,
        experiments: 1,
        settings: Settings::default(),
        seed,
    };
    let fitted = fit.run().ok()?;
    fitted.converged().then_some((fitted, index))
}

/// Fits the motor to the prepared captures from the paper's estimates.
pub fn fit(
    caps: &Captures,
    paper: &PaperEstimates,
    points: usize,
    jobs: usize,
    seed: u64,
    commutations: u32,
) -> Result<MotorFit, miette::Report> {
    let prepared = bench()?;
    let [inrush, blocked, speed, coast] = &caps.caps;
    let guess = [
        paper.r.value,
        paper.l.value,
        paper.ke.value,
        paper.j.value,
        paper.d.value,
        paper.tcst_motor.value,
    ];
    // The run-up before the speed and coast captures: 25 mechanical time constants.
    let tau_m = paper.j.value * paper.r.value / (paper.ke.value * paper.ke.value);
    let settle = (25.0 * tau_m).clamp(0.05, 100.0);
    let first = |c: &crate::extract::Capture| c.t.first().copied().unwrap_or(0.0);

    let mut series = Vec::new();
    let mut setups_generics: Vec<Vec<(String, String)>> = Vec::new();
    let mut params: Vec<FreeParam> = MOTOR
        .iter()
        .zip(guess)
        .map(|(n, g)| positive(n, g))
        .collect();
    // Each probe's offset is fitted (a zero estimated from a capture's pre-trigger and
    // subtracted would be exact to the fit, and its error, common to a whole capture, would
    // escape the intervals: it made R's interval half its scatter). Inrush and blocked each
    // have their own, read against their pre-trigger; the constant-speed capture has no zero
    // of its own and shares the coast's, read against its standstill (the paper's procedure).
    let offsets = |e: usize| if e < 2 { [2 * e, 2 * e + 1] } else { [4, 5] };
    let both = |e: usize| {
        let [i, v] = offsets(e);
        [("motor.i", "current", i), ("motor.v", "voltage", v)]
    };

    // Inrush and blocked: the first sample at time 0, the switch at the step (fitted).
    for (e, (cap, step, extra)) in [
        (inrush, caps.inrush_step, "false"),
        (blocked, caps.blocked_step, "true"),
    ]
    .into_iter()
    .enumerate()
    {
        let shift = -first(cap);
        let mut generics = vec![("blocked".to_string(), extra.to_string())];
        let dt = cap.dt();
        if step >= 1 {
            let t_step = 0.5 * (cap.t[step - 1] + cap.t[step]) + shift;
            params.push(FreeParam {
                name: "t_on".into(),
                guess: t_step,
                lower: Some((t_step - 3.0 * dt).max(0.0)),
                upper: Some(t_step + 3.0 * dt),
                experiment: Some(e),
            });
        } else {
            // No pre-trigger: the switch closed long before; the capture starts settled.
            generics.push(("t_on".into(), "0.0".into()));
        }
        let (reduced, widths, dt) = reduced(cap, 0, points);
        let reduced = (reduced.shifted(shift), widths, dt);
        series.extend(series_of(e, &reduced, ROLES[e], &both(e)));
        setups_generics.push(generics);
    }

    // Constant speed: after the run-up; the speed from the ripple at its middle.
    let shift = settle - first(speed);
    let (reduced_speed, widths, dt) = reduced(speed, 0, points);
    let reduced_speed = (reduced_speed.shifted(shift), widths, dt);
    series.extend(series_of(2, &reduced_speed, ROLES[2], &both(2)));
    let t_mid = settle + 0.5 * (speed.t.last().copied().unwrap_or(0.0) - first(speed));
    series.push(Series {
        experiment: 2,
        simulated: "motor.w".into(),
        label: "speed: speed from the ripple".into(),
        time: vec![t_mid],
        measured: vec![caps.w_cst.value],
        width: Vec::new(),
        sample_interval: 0.0,
        sigma: Some(caps.w_cst.se.max(1e-6 * caps.w_cst.value.abs()).max(1e-12)),
        offset: None,
    });
    setups_generics.push(vec![("t_on".into(), "0.0".into())]);

    // Coast: after the run-up, cut where the current falls.
    let shift = settle - first(coast);
    let running = {
        let mut pre: Vec<f64> = coast.i[..caps.coast_start.max(1).min(coast.len())].to_vec();
        pre.sort_by(f64::total_cmp);
        pre.get(pre.len() / 2).copied().unwrap_or(0.0)
    };
    let cut = (0..coast.len())
        .find(|&k| coast.i[k].abs() < 0.5 * running.abs())
        .unwrap_or(caps.coast_start);
    let t_cut = 0.5 * (coast.t[cut.saturating_sub(1)] + coast.t[cut]) + shift;
    let (reduced_coast, widths, dt) = reduced(coast, 0, points);
    let reduced_coast = (reduced_coast.shifted(shift), widths, dt);
    // The current too: at standstill it is the zero of the current probe that the
    // constant-speed capture shares.
    let mut coast_series = series_of(3, &reduced_coast, ROLES[3], &both(3));
    // Without the cut and its inductive kick (what a scope shows of it depends on the switch
    // and the probe, not on the motor): from a sample before the cut to the coast proper.
    let kick = (
        coast.t[cut.saturating_sub(1)] + shift - coast.dt(),
        coast.t[caps.coast_start.max(cut).min(coast.len() - 1)] + shift,
    );
    for s in &mut coast_series {
        let keep: Vec<usize> = (0..s.time.len())
            .filter(|&k| {
                let h = 0.5 * s.width.get(k).copied().unwrap_or(0.0);
                s.time[k] + h < kick.0 || s.time[k] - h > kick.1
            })
            .collect();
        s.time = keep.iter().map(|&k| s.time[k]).collect();
        s.measured = keep.iter().map(|&k| s.measured[k]).collect();
        if !s.width.is_empty() {
            s.width = keep.iter().map(|&k| s.width[k]).collect();
        }
    }
    series.extend(coast_series);
    setups_generics.push(vec![
        ("t_on".into(), "0.0".into()),
        ("t_off".into(), crate::output::csv::format_number(t_cut)),
    ]);

    // Each experiment's supply, from its capture's voltage while the switch is closed (the
    // samples after the step; the coast's before the cut), and the source resistance of the
    // two whose current changes.
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len().max(1) as f64;
    let closed = [
        (inrush, caps.inrush_step, inrush.len()),
        (blocked, caps.blocked_step, blocked.len()),
        (speed, 0, speed.len()),
        (coast, 0, cut.saturating_sub(1).max(1)),
    ];
    for (e, (cap, from, to)) in closed.into_iter().enumerate() {
        let to = to.clamp(1, cap.len());
        let from = from.min(to - 1);
        let (v, i) = (mean(&cap.v[from..to]), mean(&cap.i[from..to]));
        let rs_guess = 0.1;
        params.push(FreeParam {
            experiment: Some(e),
            ..positive("vs", v + rs_guess * i)
        });
        if e < 2 {
            params.push(FreeParam {
                name: "rs".into(),
                guess: rs_guess,
                lower: Some(0.0),
                upper: Some(10.0),
                experiment: Some(e),
            });
        } else {
            setups_generics[e].push(("rs".into(), "0.0".into()));
        }
    }

    for g in &mut setups_generics {
        // The bench's own check of the no-load speed is for `vams test`, not for the fit's
        // trial values.
        g.push(("self_check".into(), "false".into()));
    }
    let staged = blocked_alone(&prepared, &params, &series, &setups_generics[1], jobs, seed);
    let (stage_iterations, stage_simulations) = match &staged {
        Some((fitted, index)) => {
            for (k, &i) in index.iter().enumerate() {
                params[i].guess = fitted.estimates[k].value;
            }
            (fitted.iterations, fitted.simulations)
        }
        None => (0, 0),
    };
    let mut setups: Vec<Setup> = setups_generics
        .into_iter()
        .enumerate()
        .map(|(e, g)| Setup::new("tb_motor_bench".into(), g, e, &series))
        .collect();
    // The inrush current's ripple, by the rotor's angle.
    setups[0].record.push(MotorBench::ANGLE.into());
    let mut rippled = vec![Vec::new(); 4];
    rippled[0] = series
        .iter()
        .filter(|s| s.experiment == 0)
        .enumerate()
        .filter(|(_, s)| s.simulated == "motor.i")
        .map(|(k, s)| (k, s.measured.clone()))
        .collect();
    let sim = MotorBench {
        bench: DesignSimulator {
            prepared: &prepared,
            setups,
            names: params
                .iter()
                .map(|p| (p.name.clone(), p.experiment))
                .collect(),
            reltol: 1e-6,
            abstol: None,
            max_step: None,
            jobs,
        },
        ripple: RippleModel::commutation(commutations),
        rippled,
    };
    let fit = Fit {
        simulator: &sim,
        params: &params,
        series: &series,
        experiments: 4,
        settings: Settings::default(),
        seed,
    };
    let mut fitted = fit
        .run()
        .map_err(|e: FitError<String>| super::FitCliError::Failed {
            message: format!("the joint fit of the motor: {e}"),
        })?;
    fitted.iterations += stage_iterations;
    fitted.simulations += stage_simulations;
    let v = |k: usize| fitted.estimates[k].value;
    let motor = MotorParams {
        r: v(0),
        l: v(1),
        ke: v(2),
        kt: v(2),
        j: v(3),
        d: v(4),
        tcst_motor: v(5),
    };
    let main = |role: usize, quantity: &str| {
        series
            .iter()
            .position(|s| s.experiment == role && s.simulated == quantity)
            .unwrap_or(0)
    };
    let main_series = [
        main(0, "motor.i"),
        main(1, "motor.i"),
        main(2, "motor.i"),
        main(3, "motor.v"),
    ];
    Ok(MotorFit {
        fitted,
        params,
        series,
        captures: caps
            .caps
            .iter()
            .map(|c| c.path.display().to_string())
            .collect(),
        motor,
        main_series,
    })
}
