//! Recorded waveforms as stacked panels for [`super::plot`]: analog traces with their unit,
//! booleans, bits and `std_ulogic` as logic traces, integers and other enumerations as
//! unit-less analog traces (their positions).
//!
//! Default layout: one panel per column; with more than [`MAX_SEPARATE_PANELS`] columns,
//! only the top level's columns are drawn (when it has any: a testbench's own quantities and
//! signals), and columns of the same unit share a panel (logic signals one panel together).
//! Explicit groups
//! (`--panel vref,vfb`) replace the default layout.

use std::path::Path;

use super::levels::{Presentation, plot_level, presentation};
use super::plot::{Panel, PlotError, Trace, plot_panels};
use vams_simulation::waveform::{Column, ColumnKind, Waveforms};

/// Above this many columns, the default layout groups columns by unit.
pub const MAX_SEPARATE_PANELS: usize = 6;

/// What decides which panel a column joins in the grouped layout.
#[derive(Clone, Debug, PartialEq)]
enum GroupKey {
    Unit(String),
    Logic,
}

fn group_key(column: &Column) -> GroupKey {
    match presentation(column) {
        Presentation::Bit | Presentation::StdLogic => GroupKey::Logic,
        _ => match &column.kind {
            ColumnKind::Quantity { unit } => GroupKey::Unit(unit.clone().unwrap_or_default()),
            ColumnKind::Signal { .. } => GroupKey::Unit(String::new()),
        },
    }
}

/// Column indices per panel in the default layout.
pub fn default_groups(columns: &[Column]) -> Vec<Vec<usize>> {
    // A testbench exposes what matters at its top level (`vref`, `i_motor`, `ov`); with many
    // probes, the hierarchy below it would drown those in a plot.
    let top_level =
        columns.len() > MAX_SEPARATE_PANELS && columns.iter().any(|c| !c.name.contains('.'));
    let drawable = (0..columns.len()).filter(|&c| {
        presentation(&columns[c]) != Presentation::Other
            && !(top_level && columns[c].name.contains('.'))
    });
    if columns.len() <= MAX_SEPARATE_PANELS {
        return drawable.map(|c| vec![c]).collect();
    }
    let mut keys: Vec<GroupKey> = Vec::new();
    let mut groups: Vec<Vec<usize>> = Vec::new();
    for c in drawable {
        let key = group_key(&columns[c]);
        match keys.iter().position(|k| *k == key) {
            Some(g) => groups[g].push(c),
            None => {
                keys.push(key);
                groups.push(vec![c]);
            }
        }
    }
    groups
}

/// Column indices per panel for explicit groups of names; `Err(name)` for a name that is not
/// a column.
pub fn named_groups(columns: &[Column], groups: &[Vec<String>]) -> Result<Vec<Vec<usize>>, String> {
    groups
        .iter()
        .map(|names| {
            names
                .iter()
                .map(|name| {
                    columns
                        .iter()
                        .position(|c| c.name == *name)
                        .ok_or_else(|| name.clone())
                })
                .collect()
        })
        .collect()
}

/// The panels of a plot: the named `panels` (`--panel`) when there are some, else the
/// testbench's `-- vams: panel` comments (`file_panels`; names not recorded left out, and so
/// are panels left empty), else the default layout. `Err(name)` for a `--panel` name that is
/// not a column.
pub fn layout(
    columns: &[Column],
    panels: &[Vec<String>],
    file_panels: &[Vec<String>],
) -> Result<Vec<Vec<usize>>, String> {
    if !panels.is_empty() {
        return named_groups(columns, panels);
    }
    let from_file: Vec<Vec<usize>> = file_panels
        .iter()
        .map(|names| {
            names
                .iter()
                .filter_map(|n| columns.iter().position(|c| c.name == *n))
                .collect::<Vec<usize>>()
        })
        .filter(|g| !g.is_empty())
        .collect();
    if from_file.is_empty() {
        Ok(default_groups(columns))
    } else {
        Ok(from_file)
    }
}

/// A column's trace from its points `(time, value)`.
fn trace(column: &Column, points: Vec<(f64, f64)>) -> Trace {
    let kind = presentation(column);
    match kind {
        Presentation::Bit | Presentation::StdLogic => {
            let levels = points.into_iter().map(|(t, v)| (t, plot_level(kind, v)));
            Trace::logic(column.name.clone(), levels.collect())
        }
        _ => {
            let unit = match &column.kind {
                ColumnKind::Quantity { unit } => unit.clone().unwrap_or_default(),
                ColumnKind::Signal { .. } => String::new(),
            };
            Trace::analog(column.name.clone(), unit, points)
        }
    }
}

/// The panels for the given groups of column indices.
pub fn panels(waveforms: &Waveforms, groups: &[Vec<usize>]) -> Vec<Panel> {
    let points = |c: usize| -> Vec<(f64, f64)> {
        let values = waveforms.columns[c].values.iter().copied();
        waveforms.times.iter().copied().zip(values).collect()
    };
    panels_of(&waveforms.columns, &points, groups)
}

/// The panels for the given groups of column indices, the points of column `c` from
/// `points(c)`: whole waveforms, or the plot's bounded copy of a long run
/// ([`super::decimate::Decimator`]).
pub fn panels_of(
    columns: &[Column],
    points: &dyn Fn(usize) -> Vec<(f64, f64)>,
    groups: &[Vec<usize>],
) -> Vec<Panel> {
    groups
        .iter()
        .map(|group| {
            let traces: Vec<Trace> = group
                .iter()
                .filter(|&&c| c < columns.len())
                .map(|&c| trace(&columns[c], points(c)))
                .collect();
            // A long list of names makes an unreadable axis label; the legend names them.
            let label = if traces.len() > 3 {
                format!("{}, ... ({} traces)", traces[0].name, traces.len())
            } else {
                String::new()
            };
            Panel::new(label, traces)
        })
        .collect()
}

/// Draws the waveforms into `path` (`.svg` or `.png`).
pub fn plot_waveforms(
    path: &Path,
    title: &str,
    waveforms: &Waveforms,
    groups: &[Vec<usize>],
) -> Result<(), PlotError> {
    plot_panels(path, title, &panels(waveforms, groups))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::csv::tests::synthetic;
    use crate::output::plot::TraceKind;
    use vams_design::Type;

    fn quantity(name: &str, unit: &str) -> Column {
        Column {
            name: name.into(),
            kind: ColumnKind::Quantity {
                unit: Some(unit.into()),
            },
            values: vec![0.0, 1.0],
        }
    }

    fn many() -> Waveforms {
        let mut columns = vec![
            quantity("vref", "V"),
            quantity("i_motor", "A"),
            quantity("vfb", "V"),
            quantity("w", "rad/s"),
            quantity("v_motor", "V"),
            quantity("i_bat", "A"),
        ];
        columns.push(Column {
            name: "ov".into(),
            kind: ColumnKind::Signal { ty: Type::Boolean },
            values: vec![0.0, 1.0],
        });
        columns.push(Column {
            name: "msg".into(),
            kind: ColumnKind::Signal { ty: Type::String },
            values: vec![f64::NAN, f64::NAN],
        });
        Waveforms {
            times: vec![0.0, 1.0],
            columns,
        }
    }

    #[test]
    fn one_panel_per_probe_up_to_six() {
        let wf = synthetic();
        assert_eq!(default_groups(&wf.columns), [[0], [1], [2], [3], [4]]);
    }

    #[test]
    fn more_than_six_probes_group_by_unit_in_first_seen_order() {
        let wf = many();
        // Strings are not drawable and are left out.
        assert_eq!(
            default_groups(&wf.columns),
            [vec![0, 2, 4], vec![1, 5], vec![3], vec![6]]
        );
    }

    #[test]
    fn explicit_groups_by_name_and_unknown_names() {
        let wf = many();
        let groups = vec![
            vec!["vref".to_string(), "vfb".to_string()],
            vec!["ov".to_string()],
        ];
        assert_eq!(
            named_groups(&wf.columns, &groups).unwrap(),
            [vec![0, 2], vec![6]]
        );
        let bad = vec![vec!["vref".to_string(), "vbf".to_string()]];
        assert_eq!(named_groups(&wf.columns, &bad).unwrap_err(), "vbf");
    }

    #[test]
    fn logic_signals_become_logic_traces_and_quantities_keep_units() {
        let wf = synthetic();
        let panels = panels(&wf, &default_groups(&wf.columns));
        let kinds: Vec<(TraceKind, &str)> = panels
            .iter()
            .map(|p| (p.traces[0].kind, p.traces[0].unit.as_str()))
            .collect();
        assert_eq!(
            kinds,
            [
                (TraceKind::Analog, "V"),
                (TraceKind::Logic, ""),
                (TraceKind::Logic, ""),
                (TraceKind::Analog, ""),
                (TraceKind::Analog, "A"),
            ]
        );
        // std_ulogic U 0 1 Z H H -> 0.5 0 1 0.5 1 1
        let en: Vec<f64> = panels[2].traces[0].points.iter().map(|p| p.1).collect();
        assert_eq!(en, [0.5, 0.0, 1.0, 0.5, 1.0, 1.0]);
    }

    #[test]
    fn draws_an_svg_with_every_trace() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("run.svg");
        let wf = many();
        plot_waveforms(&path, "tb (stop 1 s)", &wf, &default_groups(&wf.columns)).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        for name in ["vref", "i_motor", "ov", "tb (stop 1 s)"] {
            assert!(svg.contains(name), "{name} missing");
        }
    }
}
