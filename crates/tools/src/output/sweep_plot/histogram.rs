//! Histograms of metrics over a sweep's runs, one panel each in a grid, with the limits as
//! vertical lines and the number of runs outside them in the panel's title.
//!
//! Bins follow the Freedman–Diaconis rule (width 2·IQR/∛n, robust to outliers), falling back
//! to Sturges' rule (⌈log₂ n⌉ + 1 bins) when the interquartile range is zero.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{label, tick};
use crate::output::plot::{COLORS, FONT, Picture, PlotError, draw_legend, write_picture};

/// One metric's values over the runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Histogram {
    pub name: String,
    pub unit: Option<String>,
    /// One value per run; non-finite values (runs where the metric failed) are counted
    /// apart, not binned.
    pub values: Vec<f64>,
    pub min_limit: Option<f64>,
    pub max_limit: Option<f64>,
}

impl Histogram {
    /// The finite values outside the limits.
    pub fn outside(&self) -> usize {
        self.finite()
            .filter(|&v| {
                self.min_limit.is_some_and(|m| v < m) || self.max_limit.is_some_and(|m| v > m)
            })
            .count()
    }

    fn finite(&self) -> impl Iterator<Item = f64> + '_ {
        self.values.iter().copied().filter(|v| v.is_finite())
    }

    /// The panel's title: name, unit, runs outside the limits, runs without a value.
    fn title(&self) -> String {
        let n = self.finite().count();
        let mut title = label(&self.name, self.unit.as_deref());
        if self.min_limit.is_some() || self.max_limit.is_some() {
            title += &format!(": {} of {n} outside limits", self.outside());
        }
        let missing = self.values.len() - n;
        if missing > 0 {
            title += &format!(" ({missing} without value)");
        }
        title
    }
}

/// The number of bins for `sorted` finite values: Freedman–Diaconis, or Sturges when the
/// interquartile range is zero; one for fewer than two distinct values; at most 100.
pub fn bin_count(sorted: &[f64]) -> usize {
    let n = sorted.len();
    if n < 2 || sorted[n - 1] <= sorted[0] {
        return 1;
    }
    let range = sorted[n - 1] - sorted[0];
    let iqr = quantile(sorted, 0.75) - quantile(sorted, 0.25);
    let bins = if iqr > 0.0 {
        (range / (2.0 * iqr / (n as f64).cbrt())).ceil()
    } else {
        (n as f64).log2().ceil() + 1.0
    };
    (bins as usize).clamp(1, 100)
}

/// The `q` quantile of `sorted`, linear between order statistics.
fn quantile(sorted: &[f64], q: f64) -> f64 {
    let x = q * (sorted.len() - 1) as f64;
    let i = x.floor() as usize;
    let j = (i + 1).min(sorted.len() - 1);
    sorted[i] + (sorted[j] - sorted[i]) * (x - i as f64)
}

/// The bins of `sorted` finite values (not empty): `(left edge, width, counts)`.
fn bins(sorted: &[f64]) -> (f64, f64, Vec<usize>) {
    let (lo, hi) = (sorted[0], sorted[sorted.len() - 1]);
    if hi <= lo {
        let width = if lo != 0.0 { lo.abs() * 0.1 } else { 1.0 };
        return (lo - width / 2.0, width, vec![sorted.len()]);
    }
    let k = bin_count(sorted);
    let width = (hi - lo) / k as f64;
    let mut counts = vec![0; k];
    for &v in sorted {
        counts[(((v - lo) / width).floor() as usize).min(k - 1)] += 1;
    }
    (lo, width, counts)
}

const PANEL_WIDTH: u32 = 440;
const PANEL_HEIGHT: u32 = 320;

/// Draws one histogram panel per metric in a grid into `path` (`.svg` or `.png`). A metric
/// without any finite value gets a panel saying so; none with one is [`PlotError::Empty`].
pub fn plot_histograms(
    path: &Path,
    title: &str,
    histograms: &[Histogram],
) -> Result<(), PlotError> {
    if !histograms.iter().any(|h| h.finite().next().is_some()) {
        return Err(PlotError::Empty {
            path: path.to_path_buf(),
        });
    }
    let cols = (histograms.len() as f64).sqrt().ceil() as usize;
    let rows = histograms.len().div_ceil(cols);
    let size = (PANEL_WIDTH * cols as u32, 50 + PANEL_HEIGHT * rows as u32);
    write_picture(
        path,
        size,
        &Histograms {
            title,
            histograms,
            grid: (rows, cols),
        },
    )
}

struct Histograms<'a> {
    title: &'a str,
    histograms: &'a [Histogram],
    grid: (usize, usize),
}

impl Picture for Histograms<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE)?;
        let root = root.titled(self.title, (FONT, 22))?;
        for (area, h) in root.split_evenly(self.grid).iter().zip(self.histograms) {
            draw_panel(area, h)?;
        }
        root.present()?;
        Ok(())
    }
}

fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    h: &Histogram,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    let mut sorted: Vec<f64> = h.finite().collect();
    if sorted.is_empty() {
        let text = format!("{}: no value in {} runs", h.name, h.values.len());
        area.titled(&text, (FONT, 15))?;
        return Ok(());
    }
    sorted.sort_by(f64::total_cmp);
    let (left, width, counts) = bins(&sorted);
    let right = left + width * counts.len() as f64;
    let (min_limit, max_limit) = (
        h.min_limit.filter(|m| m.is_finite()),
        h.max_limit.filter(|m| m.is_finite()),
    );
    let x_lo = min_limit.map_or(left, |m| m.min(left));
    let x_hi = max_limit.map_or(right, |m| m.max(right));
    let pad = (x_hi - x_lo) * 0.05;
    let top = counts.iter().copied().max().unwrap_or(1).max(1) as f64 * 1.12;
    let mut chart = ChartBuilder::on(area)
        .caption(h.title(), (FONT, 15))
        .margin(8)
        .margin_right(16)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(x_lo - pad..x_hi + pad, 0.0..top)?;
    let x_label = label(&h.name, h.unit.as_deref());
    chart
        .configure_mesh()
        .x_desc(x_label.as_str())
        .y_desc("runs")
        .x_labels(6)
        .label_style((FONT, 12))
        .axis_desc_style((FONT, 13))
        .light_line_style(RGBColor(235, 235, 235))
        .x_label_formatter(&|v| tick(*v, x_hi - x_lo))
        .y_label_formatter(&|v| format!("{v:.0}"))
        .draw()?;
    let color = COLORS[0];
    chart.draw_series(counts.iter().enumerate().map(|(k, &c)| {
        let a = left + width * k as f64;
        Rectangle::new([(a, 0.0), (a + width, c as f64)], color.mix(0.55).filled())
    }))?;
    chart.draw_series(counts.iter().enumerate().map(|(k, &c)| {
        let a = left + width * k as f64;
        Rectangle::new([(a, 0.0), (a + width, c as f64)], color.stroke_width(1))
    }))?;
    let limits = [("min limit", min_limit), ("max limit", max_limit)];
    let mut any = false;
    for (name, limit) in limits {
        if let Some(x) = limit {
            let red = COLORS[1];
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(x, 0.0), (x, top)],
                    red.stroke_width(2),
                )))?
                .label(name)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], red.stroke_width(2))
                });
            any = true;
        }
    }
    if any {
        draw_legend(&mut chart)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn histogram(name: &str, values: Vec<f64>) -> Histogram {
        Histogram {
            name: name.into(),
            unit: Some("s".into()),
            values,
            min_limit: None,
            max_limit: None,
        }
    }

    #[test]
    fn bins_follow_freedman_diaconis_then_sturges() {
        let uniform: Vec<f64> = (1..=100).map(f64::from).collect();
        // IQR 49.5, width 99/∛100 = 21.3, so ⌈99/21.3⌉ = 5 bins.
        assert_eq!(bin_count(&uniform), 5);
        // IQR zero: Sturges, ⌈log₂ 5⌉ + 1 = 4.
        assert_eq!(bin_count(&[0.0, 0.0, 0.0, 0.0, 1.0]), 4);
        assert_eq!(bin_count(&[2.0, 2.0]), 1);
        assert_eq!(bin_count(&[]), 1);
        let (left, width, counts) = bins(&uniform);
        assert_eq!((left, counts.iter().sum::<usize>()), (1.0, 100));
        assert!((width - 99.0 / 5.0).abs() < 1e-12);
        assert_eq!(bins(&[3.0, 3.0]).2, vec![2]);
    }

    #[test]
    fn counts_runs_outside_the_limits() {
        let mut h = histogram("settle", vec![0.5, 1.0, 1.6, 2.0, f64::NAN]);
        h.max_limit = Some(1.5);
        h.min_limit = Some(0.6);
        assert_eq!(h.outside(), 3);
        assert_eq!(
            h.title(),
            "settle (s): 3 of 4 outside limits (1 without value)"
        );
    }

    #[test]
    fn plots_a_grid_of_histograms_with_limits() {
        let dir = tempfile::tempdir().unwrap();
        let mut settle = histogram(
            "settle",
            (0..200)
                .map(|k| 1.0 + (k as f64 * 0.37).sin() * 0.3)
                .collect(),
        );
        settle.max_limit = Some(1.2);
        let constant = histogram("fails", vec![0.0; 10]);
        let failed = histogram("rise", vec![f64::NAN; 3]);
        let mut unbounded = histogram("i_peak", vec![1.0, 2.0, 2.5]);
        unbounded.min_limit = Some(f64::NEG_INFINITY);
        let all = [settle, constant, failed, unbounded];
        super::super::tests::assert_drawn(
            dir.path(),
            3000,
            &[
                "settle (s): ",
                "outside limits",
                "max limit",
                "fails (s)",
                "rise: no value in 3 runs",
                "runs",
            ],
            |path| plot_histograms(path, "sweep metrics", &all),
        );
        assert!(matches!(
            plot_histograms(
                &dir.path().join("x.svg"),
                "t",
                &[histogram("x", vec![f64::NAN])]
            ),
            Err(PlotError::Empty { .. })
        ));
        assert!(matches!(
            plot_histograms(&dir.path().join("x.svg"), "t", &[]),
            Err(PlotError::Empty { .. })
        ));
    }
}
