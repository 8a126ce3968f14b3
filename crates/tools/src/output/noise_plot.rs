//! The plot of a noise analysis: noise spectral densities (units per root hertz) over
//! frequency on log-log axes, the total first (thicker) and each source's contribution, as
//! SVG or PNG (by the file's extension).
//!
//! Takes traces of `(frequency, density)`; gives a picture file, written beside the target
//! and renamed over it when complete. Shares the fonts, colours, traces and legend of
//! [`super::plot`] as [`super::bode`] does; knows nothing of the analysis.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::plot::{COLORS, FONT, Picture, PlotError, draw_legend, draw_trace, write_picture};

/// One density curve.
#[derive(Debug, Clone)]
pub struct NoiseTrace {
    pub name: String,
    /// `(frequency in hertz, density)`, frequency increasing.
    pub points: Vec<(f64, f64)>,
}

const WIDTH: u32 = 1100;
const HEIGHT: u32 = 560;

/// Draws `traces` (the first is the total) into `path` (`.svg` or `.png`); `unit` labels
/// the density axis (e.g. `V/√Hz`). Points that are not positive and finite are left out
/// (a source that does not reach the output has none on a log axis).
pub fn plot_noise(
    path: &Path,
    title: &str,
    unit: &str,
    traces: &[NoiseTrace],
) -> Result<(), PlotError> {
    if !traces.iter().any(|t| t.points.iter().any(drawable)) {
        return Err(PlotError::Empty {
            path: path.to_path_buf(),
        });
    }
    write_picture(
        path,
        (WIDTH, HEIGHT),
        &NoisePlot {
            title,
            unit,
            traces,
        },
    )
}

/// A noise plot to draw.
struct NoisePlot<'a> {
    title: &'a str,
    unit: &'a str,
    traces: &'a [NoiseTrace],
}

impl Picture for NoisePlot<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static,
    {
        draw(root, self.title, self.unit, self.traces)
    }
}

fn drawable(p: &(f64, f64)) -> bool {
    p.0 > 0.0 && p.0.is_finite() && p.1 > 0.0 && p.1.is_finite()
}

/// `(lo, hi)` of the positive finite values, widened to at least a factor of 10 and padded
/// by a tenth of a decade either side.
fn log_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| *v > 0.0 && v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (1.0, 10.0);
    }
    let hi = hi.max(lo * 10.0);
    (lo / 10f64.powf(0.1), hi * 10f64.powf(0.1))
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    unit: &str,
    traces: &[NoiseTrace],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let root = root.titled(title, (FONT, 22))?;
    let points = || {
        traces
            .iter()
            .flat_map(|t| t.points.iter().filter(|p| drawable(p)))
    };
    let (mut f0, mut f1) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in points() {
        f0 = f0.min(p.0);
        f1 = f1.max(p.0);
    }
    if f1 <= f0 {
        f1 = f0 * 10.0;
    }
    let (y0, y1) = log_range(points().map(|p| p.1));
    let mut chart = ChartBuilder::on(&root)
        .margin(6)
        .margin_right(20)
        .x_label_area_size(40)
        .y_label_area_size(90)
        .build_cartesian_2d((f0..f1).log_scale(), (y0..y1).log_scale())?;
    chart
        .configure_mesh()
        .y_desc(format!("noise density ({unit})"))
        .x_desc("frequency (Hz)")
        .label_style((FONT, 13))
        .axis_desc_style((FONT, 14))
        .light_line_style(RGBColor(235, 235, 235))
        .x_label_formatter(&|f| crate::output::csv::format_number(*f))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    for (n, trace) in traces.iter().enumerate() {
        let color = COLORS[n % COLORS.len()];
        let pts: Vec<(f64, f64)> = trace.points.iter().copied().filter(drawable).collect();
        draw_trace(
            &mut chart,
            pts,
            &trace.name,
            color,
            if n == 0 { 3 } else { 2 },
        )?;
    }
    if traces.len() > 1 {
        draw_legend(&mut chart)?;
    }
    root.present()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_densities_on_log_log_axes() {
        let dir = tempfile::tempdir().unwrap();
        let rc: Vec<(f64, f64)> = (0..=60)
            .map(|k| {
                let f = 10f64.powf(k as f64 / 10.0);
                (f, 4e-9 / (1.0 + (f / 1e3).powi(2)).sqrt())
            })
            .collect();
        let flicker: Vec<(f64, f64)> = rc.iter().map(|&(f, _)| (f, 1e-8 / f.sqrt())).collect();
        let traces = [
            NoiseTrace {
                name: "total".into(),
                points: rc.clone(),
            },
            NoiseTrace {
                name: "flicker".into(),
                points: flicker,
            },
        ];
        for name in ["n.svg", "n.png"] {
            let path = dir.path().join(name);
            plot_noise(&path, "rc", "V/√Hz", &traces).unwrap();
            let bytes = std::fs::read(&path).unwrap();
            assert!(bytes.len() > 3000, "{name}: {} bytes", bytes.len());
            if name.ends_with("svg") {
                let text = String::from_utf8(bytes).unwrap();
                assert!(text.contains("frequency (Hz)") && text.contains("flicker"));
            }
        }
        assert!(matches!(
            plot_noise(&dir.path().join("n.pdf"), "rc", "V", &traces),
            Err(PlotError::Format { .. })
        ));
        let silent = [NoiseTrace {
            name: "zero".into(),
            points: vec![(1.0, 0.0)],
        }];
        assert!(matches!(
            plot_noise(&dir.path().join("e.svg"), "rc", "V", &silent),
            Err(PlotError::Empty { .. })
        ));
    }
}
