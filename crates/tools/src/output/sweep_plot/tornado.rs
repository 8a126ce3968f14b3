//! The tornado of a metric's sensitivities: one row per parameter, its normalised effect for
//! a step down and a step up as horizontal bars around zero, the largest effect at the top.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{padded_range, tick};
use crate::output::plot::{COLORS, FONT, Picture, PlotError, write_picture};

/// One parameter's effect on the metric: `(dM/M)/(dp/p)` for a step down (`low`) and up
/// (`high`).
#[derive(Clone, Debug, PartialEq)]
pub struct TornadoBar {
    pub parameter: String,
    pub low: f64,
    pub high: f64,
}

impl TornadoBar {
    /// The larger finite |effect| (0 when neither is finite).
    fn size(&self) -> f64 {
        [self.low, self.high]
            .into_iter()
            .filter(|v| v.is_finite())
            .fold(0.0, |m, v| m.max(v.abs()))
    }

    fn is_drawable(&self) -> bool {
        self.low.is_finite() || self.high.is_finite()
    }
}

/// The bars with a finite effect, the largest first (ties keep their order).
fn ranked(bars: &[TornadoBar]) -> Vec<&TornadoBar> {
    let mut ranked: Vec<&TornadoBar> = bars.iter().filter(|b| b.is_drawable()).collect();
    ranked.sort_by(|a, b| b.size().total_cmp(&a.size()));
    ranked
}

const WIDTH: u32 = 900;
const ROW_HEIGHT: u32 = 34;

/// Draws the tornado of `metric` into `path` (`.svg` or `.png`). A side whose effect is not
/// finite is left out; no bar with a finite effect is [`PlotError::Empty`].
pub fn plot_tornado(
    path: &Path,
    title: &str,
    metric: &str,
    bars: &[TornadoBar],
) -> Result<(), PlotError> {
    let ranked = ranked(bars);
    if ranked.is_empty() {
        return Err(PlotError::Empty {
            path: path.to_path_buf(),
        });
    }
    let height = (130 + ROW_HEIGHT * ranked.len() as u32).max(260);
    write_picture(
        path,
        (WIDTH, height),
        &Tornado {
            title,
            metric,
            ranked,
        },
    )
}

struct Tornado<'a> {
    title: &'a str,
    metric: &'a str,
    ranked: Vec<&'a TornadoBar>,
}

impl Picture for Tornado<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE)?;
        let root = root.titled(self.title, (FONT, 22))?;
        let n = self.ranked.len();
        let effects = self.ranked.iter().flat_map(|b| [b.low, b.high, 0.0]);
        let (x0, x1) = padded_range(effects).unwrap_or((-1.0, 1.0));
        // Row k (0 at the top) is centred on y = n - 1 - k.
        let row = |k: usize| (n - 1 - k) as f64;
        let names: Vec<String> = self
            .ranked
            .iter()
            .rev()
            .map(|b| b.parameter.clone())
            .collect();
        let longest = names.iter().map(|s| s.chars().count()).max().unwrap_or(0) as u32;
        let mut chart = ChartBuilder::on(&root)
            .caption(self.metric, (FONT, 16))
            .margin(8)
            .margin_right(24)
            .x_label_area_size(40)
            .y_label_area_size((16 + 8 * longest).clamp(60, 320))
            .build_cartesian_2d(x0..x1, -0.5..n as f64 - 0.5)?;
        let name_of = |y: &f64| {
            let k = y.round();
            if (y - k).abs() < 1e-6 && k >= 0.0 {
                names.get(k as usize).cloned().unwrap_or_default()
            } else {
                String::new()
            }
        };
        chart
            .configure_mesh()
            .x_desc("normalised sensitivity (%/%)")
            .disable_y_mesh()
            // At most `n` labels on a span of `n` is one per whole number: one per row.
            .y_labels(n)
            .label_style((FONT, 13))
            .axis_desc_style((FONT, 14))
            .light_line_style(RGBColor(235, 235, 235))
            .x_label_formatter(&|v| tick(*v, x1 - x0))
            .y_label_formatter(&name_of)
            .draw()?;
        // The step down in the upper half of a row, the step up in the lower half.
        for (label, down, offset, color) in [
            ("parameter −δ", true, 0.0, COLORS[0]),
            ("parameter +δ", false, -0.36, COLORS[3]),
        ] {
            let rects = self.ranked.iter().enumerate().filter_map(|(k, b)| {
                let v = if down { b.low } else { b.high };
                let y = row(k) + offset;
                v.is_finite()
                    .then(|| Rectangle::new([(0.0, y), (v, y + 0.36)], color.mix(0.8).filled()))
            });
            chart
                .draw_series(rects)?
                .label(label)
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 18, y + 5)], color.filled())
                });
        }
        chart.draw_series(std::iter::once(PathElement::new(
            vec![(0.0, -0.5), (0.0, n as f64 - 0.5)],
            BLACK.stroke_width(1),
        )))?;
        // Lower right: the bottom rows have the smallest effects.
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(180, 180, 180))
            .label_font((FONT, 13))
            .draw()?;
        root.present()?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bar(parameter: &str, low: f64, high: f64) -> TornadoBar {
        TornadoBar {
            parameter: parameter.into(),
            low,
            high,
        }
    }

    #[test]
    fn ranks_by_the_largest_effect() {
        let bars = [
            bar("r1", 0.1, -0.1),
            bar("kt", -0.9, 0.5),
            bar("gone", f64::NAN, f64::NAN),
            bar("j", 0.2, f64::INFINITY),
        ];
        let names: Vec<&str> = ranked(&bars).iter().map(|b| b.parameter.as_str()).collect();
        assert_eq!(names, ["kt", "j", "r1"]);
    }

    #[test]
    fn plots_labelled_bars() {
        let dir = tempfile::tempdir().unwrap();
        let bars = [
            bar("dut.r_winding", 0.1, -0.12),
            bar("kt", -0.9, 0.85),
            bar("j", 0.3, 0.25),
        ];
        super::super::tests::assert_drawn(
            dir.path(),
            2000,
            &[
                "dut.r_winding",
                "kt",
                "settle",
                "normalised sensitivity (%/%)",
                "+δ",
            ],
            |path| plot_tornado(path, "sensitivities", "settle", &bars),
        );
        assert!(matches!(
            plot_tornado(
                &dir.path().join("x.svg"),
                "t",
                "m",
                &[bar("p", f64::NAN, f64::NAN)]
            ),
            Err(PlotError::Empty { .. })
        ));
        assert!(matches!(
            plot_tornado(&dir.path().join("x.svg"), "t", "m", &[]),
            Err(PlotError::Empty { .. })
        ));
    }
}
