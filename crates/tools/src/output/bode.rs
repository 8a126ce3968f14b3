//! Bode plots of a small-signal analysis: magnitude (dB) and phase (degrees) panels over a
//! logarithmic frequency axis, one trace per probe, as SVG or PNG (by the file's extension).
//!
//! Takes traces of `(frequency, dB, degrees)`; gives a picture file, written beside the
//! target and renamed over it when complete. Shares the fonts and colours of
//! [`super::plot`]; knows nothing of the analysis.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::plot::{COLORS, FONT, Picture, PlotError, draw_legend, draw_trace, write_picture};

/// One probe's response.
#[derive(Debug, Clone)]
pub struct BodeTrace {
    pub name: String,
    /// `(frequency in hertz, magnitude in dB, phase in degrees)`, frequency increasing.
    pub points: Vec<(f64, f64, f64)>,
}

/// The phases of `points` (frequency increasing) shifted by whole turns so that no step
/// between neighbours exceeds half a turn; non-finite phases are left as they are and do not
/// break the chain.
pub fn unwrap_phase(points: &[(f64, f64, f64)]) -> Vec<(f64, f64, f64)> {
    let mut shift = 0.0;
    let mut previous: Option<f64> = None;
    points
        .iter()
        .map(|&(f, db, degrees)| {
            if !degrees.is_finite() {
                return (f, db, degrees);
            }
            if let Some(p) = previous {
                shift += 360.0 * (-((degrees + shift - p) / 360.0).round());
            }
            let unwrapped = degrees + shift;
            previous = Some(unwrapped);
            (f, db, unwrapped)
        })
        .collect()
}

/// A point of a trace: `(frequency, dB, degrees)`.
type BodePoint = (f64, f64, f64);

/// What a panel plots of each point.
type Component = fn(&BodePoint) -> f64;

const WIDTH: u32 = 1100;
const HEIGHT: u32 = 640;

/// Draws the magnitude and phase of `traces` into `path` (`.svg` or `.png`).
pub fn plot_bode(path: &Path, title: &str, traces: &[BodeTrace]) -> Result<(), PlotError> {
    let finite = |p: &&(f64, f64, f64)| p.0 > 0.0 && p.0.is_finite();
    if !traces.iter().any(|t| t.points.iter().any(|p| finite(&p))) {
        return Err(PlotError::Empty {
            path: path.to_path_buf(),
        });
    }
    // The phase as a continuous curve: a lag past 180 degrees reads as such, not as a jump
    // to +180.
    let traces: Vec<BodeTrace> = traces
        .iter()
        .map(|t| BodeTrace {
            name: t.name.clone(),
            points: unwrap_phase(&t.points),
        })
        .collect();
    let traces = &traces[..];
    write_picture(path, (WIDTH, HEIGHT), &Bode { title, traces })
}

/// A Bode plot to draw.
struct Bode<'a> {
    title: &'a str,
    traces: &'a [BodeTrace],
}

impl Picture for Bode<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static,
    {
        draw(root, self.title, self.traces)
    }
}

/// The finite range of `values`, padded; `(0, 1)` when there is none.
fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = ((hi - lo) * 0.06).max(1e-9 + hi.abs() * 1e-6);
    (lo - pad, hi + pad)
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    traces: &[BodeTrace],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let root = root.titled(title, (FONT, 22))?;
    let points = || traces.iter().flat_map(|t| t.points.iter());
    let (mut f0, mut f1) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in points().filter(|p| p.0 > 0.0 && p.0.is_finite()) {
        f0 = f0.min(p.0);
        f1 = f1.max(p.0);
    }
    if f1 <= f0 {
        f1 = f0 * 10.0;
    }
    let areas = root.split_evenly((2, 1));
    let panels: [(&str, Component); 2] =
        [("magnitude (dB)", |p| p.1), ("phase (degrees)", |p| p.2)];
    for (k, (area, (label, value))) in areas.iter().zip(panels).enumerate() {
        let last = k == 1;
        let (y0, y1) = padded_range(points().map(value));
        let mut chart = ChartBuilder::on(area)
            .margin(6)
            .margin_right(20)
            .x_label_area_size(if last { 40 } else { 22 })
            .y_label_area_size(80)
            .build_cartesian_2d((f0..f1).log_scale(), y0..y1)?;
        let mut mesh = chart.configure_mesh();
        mesh.y_desc(label)
            .label_style((FONT, 13))
            .axis_desc_style((FONT, 14))
            .light_line_style(RGBColor(235, 235, 235))
            .x_label_formatter(&|f| crate::output::csv::format_number(*f));
        if last {
            mesh.x_desc("frequency (Hz)");
        }
        mesh.draw()?;
        for (n, trace) in traces.iter().enumerate() {
            let color = COLORS[n % COLORS.len()];
            let pts: Vec<(f64, f64)> = (trace.points.iter())
                .filter(|p| p.0 > 0.0 && value(p).is_finite())
                .map(|p| (p.0, value(p)))
                .collect();
            draw_trace(&mut chart, pts, &trace.name, color, 2)?;
        }
        if traces.len() > 1 && k == 0 {
            draw_legend(&mut chart)?;
        }
    }
    root.present()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn phases_unwrap_into_a_continuous_lag() {
        let wrapped = [
            (1.0, 0.0, -170.0),
            (2.0, 0.0, 179.0),
            (3.0, 0.0, f64::NAN),
            (4.0, 0.0, 100.0),
            (5.0, 0.0, -20.0),
        ];
        let phases: Vec<f64> = unwrap_phase(&wrapped).iter().map(|p| p.2).collect();
        assert_eq!(phases[..2], [-170.0, -181.0]);
        assert!(phases[2].is_nan());
        assert_eq!(phases[3..], [-260.0, -380.0]);
    }

    #[test]
    fn draws_both_panels_on_a_log_axis() {
        let dir = tempfile::tempdir().unwrap();
        let points: Vec<(f64, f64, f64)> = (0..=60)
            .map(|k| {
                let f = 10f64.powf(k as f64 / 10.0);
                let w = f / 1e3;
                (f, -10.0 * (1.0 + w * w).log10(), -w.atan().to_degrees())
            })
            .collect();
        let traces = [BodeTrace {
            name: "vout".into(),
            points,
        }];
        for name in ["b.svg", "b.png"] {
            let path = dir.path().join(name);
            plot_bode(&path, "rc", &traces).unwrap();
            let bytes = std::fs::read(&path).unwrap();
            assert!(bytes.len() > 3000, "{name}: {} bytes", bytes.len());
            if name.ends_with("svg") {
                let text = String::from_utf8(bytes).unwrap();
                assert!(text.contains("magnitude (dB)") && text.contains("frequency (Hz)"));
            }
        }
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
        assert!(matches!(
            plot_bode(&dir.path().join("b.pdf"), "rc", &traces),
            Err(PlotError::Format { .. })
        ));
        assert!(matches!(
            plot_bode(&dir.path().join("e.svg"), "rc", &[]),
            Err(PlotError::Empty { .. })
        ));
    }
}
