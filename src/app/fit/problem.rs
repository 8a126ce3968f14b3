//! A fit's problem: the command line's text (`FitSpec`) checked and parsed into free
//! parameters, experiments and matches, the captures loaded into series, the simulator of
//! the user's testbench, and the design checked at the guesses before the first simulation.

use miette::Report;

use crate::app::compile::{Prepared, unknown_probe_help};
use crate::app::fit::FitCliError;
use crate::app::fit::experiment::{self, Match, Measured};
use crate::app::fit::simulate::{DesignSimulator, Setup};
use crate::app::notes::Notes;
use crate::app::render::render_located;
use crate::capture::ReadOptions;
use crate::fit::{FreeParam, Series};

/// What `vams fit` is asked, each entry as the command line takes it.
#[derive(Debug, Clone, Default)]
pub struct FitSpec {
    /// `FILE` or `FILE:KEY=VALUE,...` per experiment.
    pub measured: Vec<String>,
    /// `NAME=GUESS[:MIN:MAX]`, one value for every experiment.
    pub free: Vec<String>,
    /// `NAME=GUESS[:MIN:MAX]`, estimated separately for each experiment.
    pub free_each: Vec<String>,
    /// `QUANTITY=COLUMN`.
    pub matches: Vec<String>,
    /// `GENERIC=COLUMN`: a `real_vector` generic driven by a column as a table of time.
    pub drive: Vec<String>,
    /// `COLUMN=FACTOR`.
    pub scale: Vec<String>,
    /// The captures' time column (default: found by name, else the first).
    pub time_col: Option<String>,
}

/// How the testbench's simulations run.
#[derive(Debug, Clone, Copy)]
pub struct SimulationSettings {
    pub reltol: f64,
    pub abstol: Option<f64>,
    pub max_step: Option<f64>,
    /// Simulations at once.
    pub jobs: usize,
}

/// The simulator of `prepared`'s testbench for `problem`: one setup per experiment (its
/// top, its generics and those of its `--drive` tables, the times its series need).
pub fn simulator<'a>(
    prepared: &'a Prepared,
    problem: &Problem,
    series: &[Series],
    driven: &[Vec<(String, String)>],
    settings: SimulationSettings,
) -> DesignSimulator<'a> {
    let setups = (problem.measured.iter().enumerate())
        .map(|(e, m)| {
            let mut generics = m.generics.clone();
            generics.extend(driven[e].iter().cloned());
            Setup::new(
                m.top.clone().unwrap_or_else(|| prepared.top.clone()),
                generics,
                e,
                series,
            )
        })
        .collect();
    DesignSimulator {
        prepared,
        setups,
        names: (problem.params.iter())
            .map(|p| (p.name.clone(), p.experiment))
            .collect(),
        reltol: settings.reltol,
        abstol: settings.abstol,
        max_step: settings.max_step,
        jobs: settings.jobs,
    }
}

/// A fit's inputs checked and parsed: the free parameters (one copy per experiment of each
/// `free_each`), the experiments, the driven generics, the matches and how captures are read.
pub struct Problem {
    pub params: Vec<FreeParam>,
    pub measured: Vec<Measured>,
    pub drives: Vec<(String, String)>,
    pub matches: Vec<Match>,
    pub read: ReadOptions,
}

impl Problem {
    /// Checks and parses `spec`: every argument's syntax, a parameter given twice, one both
    /// free and fixed.
    pub fn parse(spec: &FitSpec) -> Result<Problem, FitCliError> {
        let measured = spec
            .measured
            .iter()
            .map(|m| Measured::parse(m))
            .collect::<Result<Vec<_>, _>>()?;
        let mut params: Vec<FreeParam> = Vec::new();
        let each = spec.free_each.iter().map(|f| (f, true));
        for (f, each) in spec.free.iter().map(|f| (f, false)).chain(each) {
            let p = FreeParam::parse(f).map_err(|e| FitCliError::Free(e.to_string()))?;
            if params.iter().any(|q| q.name == p.name) {
                return Err(FitCliError::Free(format!("`{}` is given twice", p.name)));
            }
            if each {
                // One copy per experiment, each set only in its own simulations.
                params.extend((0..measured.len()).map(|e| FreeParam {
                    experiment: Some(e),
                    ..p.clone()
                }));
            } else {
                params.push(p);
            }
        }
        for m in &measured {
            if let Some((name, _)) = m
                .generics
                .iter()
                .find(|(g, _)| params.iter().any(|p| &p.name == g))
            {
                return Err(FitCliError::FreeAndFixed {
                    name: name.clone(),
                    capture: m.name(),
                });
            }
        }
        let matches = spec
            .matches
            .iter()
            .map(|m| experiment::parse_match(m))
            .collect::<Result<Vec<_>, _>>()?;
        let scales = spec
            .scale
            .iter()
            .map(|s| experiment::parse_scale(s))
            .collect::<Result<Vec<_>, _>>()?;
        let drives = spec
            .drive
            .iter()
            .map(|d| experiment::parse_drive(d))
            .collect::<Result<Vec<_>, _>>()?;
        if let Some((g, _)) = drives
            .iter()
            .find(|(g, _)| params.iter().any(|p| &p.name == g))
        {
            return Err(FitCliError::FreeAndFixed {
                name: g.clone(),
                capture: "--drive".into(),
            });
        }
        Ok(Problem {
            params,
            measured,
            drives,
            matches,
            read: ReadOptions {
                time_column: spec.time_col.clone(),
                scales,
                ..ReadOptions::default()
            },
        })
    }
}

/// The captures read (their warnings told to `notes`), their series, and per experiment the
/// generics of its `--drive` tables.
#[allow(clippy::type_complexity)]
pub fn load_series(
    p: &Problem,
    points: usize,
    notes: &dyn Notes,
) -> Result<(Vec<Series>, Vec<Vec<(String, String)>>), Report> {
    let mut series = Vec::new();
    let mut loaded = Vec::new();
    let mut driven = Vec::new();
    for (e, m) in p.measured.iter().enumerate() {
        let l = experiment::load(m, &p.read, points)?;
        for w in &l.capture.warnings {
            notes.note(&format!("{:?}\n", Report::new(w.clone())));
        }
        series.extend(experiment::series(e, m, &l, &p.matches)?);
        driven.push(
            (p.drives.iter())
                .map(|d| experiment::drive_generic(&l, d))
                .collect::<Result<Vec<_>, _>>()?,
        );
        loaded.push(l);
    }
    // Every matched column must be in some capture.
    for mt in &p.matches {
        if !series.iter().any(|s| {
            s.simulated == mt.quantity && loaded[s.experiment].capture.channel(&mt.column).is_some()
        }) {
            let available: Vec<String> = loaded
                .iter()
                .flat_map(|l| l.capture.channels.iter().map(|c| c.name.clone()))
                .collect();
            // Suggested by the rule that finds channels (`1` is `CH1`, `ch3` is not `ch1`).
            let help =
                match crate::capture::closest(&mt.column, available.iter().map(String::as_str)) {
                    Some(n) => format!("did you mean `{n}`?"),
                    None => format!("the captures' columns are {}", available.join(", ")),
                };
            return Err(FitCliError::NoColumn {
                quantity: mt.quantity.clone(),
                column: mt.column.clone(),
                help,
            }
            .into());
        }
    }
    Ok((series, driven))
}

/// Elaborates each experiment at the guesses: a generic the design lacks or a matched quantity
/// it does not have is reported here, at its source, not as a failure of every simulation.
/// The elaboration errors are told to `notes`, rendered.
pub fn check_design(sim: &DesignSimulator, p: &Problem, notes: &dyn Notes) -> Result<(), Report> {
    let guesses: Vec<f64> = p.params.iter().map(|q| q.guess).collect();
    for (e, setup) in sim.setups.iter().enumerate() {
        let design = match sim
            .prepared
            .try_elaborate_top(&setup.top, &sim.generics(e, &guesses))
        {
            Ok(d) => d,
            Err(errors) => {
                for err in &errors {
                    notes.note(&render_located(err, &sim.prepared.loaded.sources));
                }
                return Err(crate::app::error::CliError::Elaboration {
                    count: errors.len(),
                }
                .into());
            }
        };
        for probe in &setup.probes {
            let Some(help) = unknown_probe_help(&design, probe) else {
                continue;
            };
            return Err(FitCliError::NoQuantity {
                top: setup.top.clone(),
                name: probe.clone(),
                help,
            }
            .into());
        }
    }
    Ok(())
}
