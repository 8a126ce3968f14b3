//! The runs of a sweep: what each one sets its parameters to. A [`Plan`] is the spec's
//! `[grid]`, `[corners]`, `[monte_carlo]` or `[sensitivity]` section, checked; [`Plan::run`]
//! gives run `i` on its own, computed from the plan alone (and the seed), so that any shard
//! of a sweep, on any machine and in any order, gives every run the same values.

use super::sample::{Sampler, Sampling};

/// A parameter's value in one run: a number, or the literal text of a grid's listed value
/// (`true`, `'1'`, `10 ms`).
#[derive(Clone, Debug, PartialEq)]
pub enum ParamValue {
    Number(f64),
    Text(String),
}

impl ParamValue {
    /// The VHDL literal the generic is set to: numbers with the shortest text that reads back
    /// exactly (so the run sees the sampled value to the last bit).
    pub fn literal(&self) -> String {
        match self {
            ParamValue::Number(x) => crate::output::csv::format_number(*x),
            ParamValue::Text(t) => t.clone(),
        }
    }

    pub fn as_number(&self) -> Option<f64> {
        match self {
            ParamValue::Number(x) => Some(*x),
            ParamValue::Text(_) => None,
        }
    }
}

/// `x` rounded to 12 significant digits: values derived from a percentage or a range
/// (`0.003 * 0.8`) read as the user would write them (`0.0024`, not
/// `0.0024000000000000002`), 1e-12 from the exact product.
pub fn tidy(x: f64) -> f64 {
    format!("{x:.11e}").parse().unwrap_or(x)
}

/// A `[corners]` parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Corner {
    pub name: String,
    pub min: f64,
    pub nominal: f64,
    pub max: f64,
}

/// A level of a corner parameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    Min,
    Nominal,
    Max,
}

impl Level {
    pub fn name(self) -> &'static str {
        match self {
            Level::Min => "min",
            Level::Nominal => "nominal",
            Level::Max => "max",
        }
    }
}

/// Which corners run (after the all-nominal run, which is always first).
#[derive(Clone, Debug, PartialEq)]
pub enum CornerSet {
    /// Every combination of min, nominal and max (3^n runs).
    All,
    /// Every combination of min and max (2^n runs, plus the nominal).
    Extremes,
    /// The named combinations; parameters a corner does not name stay nominal.
    Named(Vec<(String, Vec<Level>)>),
}

/// The spec's plan, checked.
#[derive(Clone, Debug)]
pub enum Plan {
    /// Every combination of the listed values, the last parameter varying fastest.
    Grid {
        names: Vec<String>,
        values: Vec<Vec<ParamValue>>,
    },
    Corners {
        corners: Vec<Corner>,
        set: CornerSet,
    },
    /// Run 0 is the nominal; runs 1..=N are the samples.
    MonteCarlo(Sampler),
    /// Run 0 is the nominal; then each parameter at (1 - delta) and (1 + delta) times its
    /// nominal, in turn.
    Sensitivity {
        names: Vec<String>,
        nominal: Vec<f64>,
        delta: f64,
    },
}

/// One run of the plan.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    pub index: usize,
    /// What kind of run it is, for the table: `nominal`, `grid`, `sample`, a corner's name
    /// (`r=max v_bat=min`) or a perturbation (`r-1%`).
    pub case: String,
    pub values: Vec<ParamValue>,
}

impl Run {
    /// The generics this run sets: `names` (the plan's parameters) with its values.
    pub fn generics(&self, names: &[String]) -> Vec<(String, String)> {
        names
            .iter()
            .cloned()
            .zip(self.values.iter().map(ParamValue::literal))
            .collect()
    }
}

impl Plan {
    /// The parameters, in the order of the table's columns.
    pub fn names(&self) -> Vec<String> {
        match self {
            Plan::Grid { names, .. } | Plan::Sensitivity { names, .. } => names.clone(),
            Plan::Corners { corners, .. } => corners.iter().map(|c| c.name.clone()).collect(),
            Plan::MonteCarlo(s) => s.names(),
        }
    }

    /// How many runs, or `None` beyond `u64` (a grid of many long lists).
    pub fn len(&self) -> Option<u64> {
        match self {
            Plan::Grid { values, .. } => values
                .iter()
                .try_fold(1u64, |n, v| n.checked_mul(v.len() as u64)),
            Plan::Corners { corners, set } => {
                let n = u32::try_from(corners.len()).ok()?;
                match set {
                    CornerSet::All => 3u64.checked_pow(n),
                    CornerSet::Extremes => 2u64.checked_pow(n)?.checked_add(1),
                    CornerSet::Named(named) => Some(named.len() as u64 + 1),
                }
            }
            Plan::MonteCarlo(s) => Some(s.runs() as u64 + 1),
            Plan::Sensitivity { names, .. } => Some(2 * names.len() as u64 + 1),
        }
    }

    /// Whether the plan has no runs (never, once checked: a grid has no empty list).
    pub fn is_empty(&self) -> bool {
        self.len() == Some(0)
    }

    /// Whether run `index` counts in the statistics: Monte Carlo's samples, not its nominal.
    pub fn is_sample(&self, index: usize) -> bool {
        !matches!(self, Plan::MonteCarlo(_)) || index > 0
    }

    /// Run `index` (below [`Plan::len`]).
    pub fn run(&self, index: usize) -> Run {
        match self {
            Plan::Grid { values, .. } => {
                // Mixed radix, the last parameter fastest.
                let mut rest = index;
                let mut picked = vec![ParamValue::Number(0.0); values.len()];
                for (k, list) in values.iter().enumerate().rev() {
                    picked[k] = list[rest % list.len()].clone();
                    rest /= list.len();
                }
                Run {
                    index,
                    case: "grid".into(),
                    values: picked,
                }
            }
            Plan::Corners { corners, set } => {
                let levels = corner_levels(corners.len(), set, index);
                let values = corners
                    .iter()
                    .zip(&levels)
                    .map(|(c, l)| {
                        ParamValue::Number(match l {
                            Level::Min => c.min,
                            Level::Nominal => c.nominal,
                            Level::Max => c.max,
                        })
                    })
                    .collect();
                let case = match set {
                    _ if index == 0 => "nominal".to_string(),
                    CornerSet::Named(named) => named[index - 1].0.clone(),
                    _ => corners
                        .iter()
                        .zip(&levels)
                        .filter(|(_, l)| **l != Level::Nominal)
                        .map(|(c, l)| format!("{}={}", c.name, l.name()))
                        .collect::<Vec<_>>()
                        .join(" "),
                };
                Run {
                    index,
                    case: if case.is_empty() {
                        "nominal".into()
                    } else {
                        case
                    },
                    values,
                }
            }
            Plan::MonteCarlo(sampler) => {
                let values = if index == 0 {
                    sampler.nominal()
                } else {
                    sampler.sample(index - 1)
                };
                Run {
                    index,
                    case: if index == 0 { "nominal" } else { "sample" }.into(),
                    values: values.into_iter().map(ParamValue::Number).collect(),
                }
            }
            Plan::Sensitivity {
                names,
                nominal,
                delta,
            } => {
                let mut values = nominal.clone();
                let case = if index == 0 {
                    "nominal".to_string()
                } else {
                    let (p, up) = ((index - 1) / 2, (index - 1) % 2 == 1);
                    let sign = if up { 1.0 } else { -1.0 };
                    values[p] = tidy(nominal[p] * (1.0 + sign * delta));
                    format!(
                        "{}{}{}%",
                        names[p],
                        if up { '+' } else { '-' },
                        crate::output::csv::format_number(delta * 100.0)
                    )
                };
                Run {
                    index,
                    case,
                    values: values.into_iter().map(ParamValue::Number).collect(),
                }
            }
        }
    }

    /// The sampling, for Monte Carlo plans.
    pub fn sampling(&self) -> Option<Sampling> {
        match self {
            Plan::MonteCarlo(s) => Some(s.sampling()),
            _ => None,
        }
    }
}

/// The levels of corner run `index`: run 0 all nominal, then the set's combinations in order
/// (the first parameter varying slowest), skipping the all-nominal one already run.
fn corner_levels(n: usize, set: &CornerSet, index: usize) -> Vec<Level> {
    if index == 0 {
        return vec![Level::Nominal; n];
    }
    match set {
        CornerSet::All => {
            // Combinations in base 3 (min, nominal, max), without the all-nominal one.
            let all_nominal = (0..n).fold(0usize, |acc, _| acc * 3 + 1);
            let code = if index <= all_nominal {
                index - 1
            } else {
                index
            };
            digits(code, 3, n)
                .into_iter()
                .map(|d| [Level::Min, Level::Nominal, Level::Max][d])
                .collect()
        }
        CornerSet::Extremes => digits(index - 1, 2, n)
            .into_iter()
            .map(|d| [Level::Min, Level::Max][d])
            .collect(),
        CornerSet::Named(named) => named[index - 1].1.clone(),
    }
}

/// `code` in base `radix` with `n` digits, most significant first.
fn digits(mut code: usize, radix: usize, n: usize) -> Vec<usize> {
    let mut out = vec![0; n];
    for slot in out.iter_mut().rev() {
        *slot = code % radix;
        code /= radix;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numbers(run: &Run) -> Vec<f64> {
        run.values
            .iter()
            .filter_map(ParamValue::as_number)
            .collect()
    }

    #[test]
    fn a_grid_is_every_combination_last_parameter_fastest() {
        let plan = Plan::Grid {
            names: vec!["r".into(), "v".into()],
            values: vec![
                vec![ParamValue::Number(1.0), ParamValue::Number(2.0)],
                vec![
                    ParamValue::Number(10.0),
                    ParamValue::Number(20.0),
                    ParamValue::Text("30.0".into()),
                ],
            ],
        };
        assert_eq!(plan.len(), Some(6));
        let runs: Vec<Vec<String>> = (0..6)
            .map(|i| plan.run(i).values.iter().map(ParamValue::literal).collect())
            .collect();
        assert_eq!(
            runs,
            [
                ["1", "10"],
                ["1", "20"],
                ["1", "30.0"],
                ["2", "10"],
                ["2", "20"],
                ["2", "30.0"]
            ]
        );
    }

    fn corners() -> Vec<Corner> {
        vec![
            Corner {
                name: "r".into(),
                min: 1.0,
                nominal: 2.0,
                max: 3.0,
            },
            Corner {
                name: "v".into(),
                min: 9.0,
                nominal: 12.0,
                max: 16.0,
            },
        ]
    }

    #[test]
    fn all_corners_are_the_nominal_then_every_other_combination_once() {
        let plan = Plan::Corners {
            corners: corners(),
            set: CornerSet::All,
        };
        assert_eq!(plan.len(), Some(9));
        let runs: Vec<Vec<f64>> = (0..9).map(|i| numbers(&plan.run(i))).collect();
        assert_eq!(runs[0], [2.0, 12.0]);
        let mut sorted = runs.clone();
        sorted.sort_by(|a, b| a.partial_cmp(b).unwrap());
        sorted.dedup();
        assert_eq!(sorted.len(), 9, "{runs:?}");
        assert_eq!(plan.run(0).case, "nominal");
        assert_eq!(plan.run(1).case, "r=min v=min");
        assert_eq!(plan.run(8).case, "r=max v=max");
        assert!((1..9).all(|i| plan.run(i).case != "nominal"));
    }

    #[test]
    fn extreme_and_named_corners() {
        let plan = Plan::Corners {
            corners: corners(),
            set: CornerSet::Extremes,
        };
        assert_eq!(plan.len(), Some(5));
        let runs: Vec<Vec<f64>> = (0..5).map(|i| numbers(&plan.run(i))).collect();
        assert_eq!(
            runs,
            [
                [2.0, 12.0],
                [1.0, 9.0],
                [1.0, 16.0],
                [3.0, 9.0],
                [3.0, 16.0]
            ]
        );
        let named = Plan::Corners {
            corners: corners(),
            set: CornerSet::Named(vec![("hot".into(), vec![Level::Max, Level::Nominal])]),
        };
        assert_eq!(named.len(), Some(2));
        assert_eq!(numbers(&named.run(1)), [3.0, 12.0]);
        assert_eq!(named.run(1).case, "hot");
    }

    #[test]
    fn sensitivity_perturbs_one_parameter_each_way_in_turn() {
        let plan = Plan::Sensitivity {
            names: vec!["r".into(), "v".into()],
            nominal: vec![2.0, 10.0],
            delta: 0.01,
        };
        assert_eq!(plan.len(), Some(5));
        assert_eq!(numbers(&plan.run(0)), [2.0, 10.0]);
        assert_eq!(numbers(&plan.run(1)), [2.0 * 0.99, 10.0]);
        assert_eq!(numbers(&plan.run(2)), [2.0 * 1.01, 10.0]);
        assert_eq!(numbers(&plan.run(4)), [2.0, 10.0 * 1.01]);
        assert_eq!(plan.run(3).case, "v-1%");
        assert_eq!(plan.run(4).case, "v+1%");
    }

    #[test]
    fn huge_grids_count_without_overflow() {
        let list: Vec<ParamValue> = (0..1000).map(|k| ParamValue::Number(k as f64)).collect();
        let plan = Plan::Grid {
            names: (0..10).map(|k| format!("p{k}")).collect(),
            values: vec![list; 10],
        };
        assert_eq!(plan.len(), None);
    }
}
