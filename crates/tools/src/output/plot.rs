//! Stacked waveform plots on a shared time axis, as SVG or PNG (by the file's extension).
//!
//! Takes panels of traces (name, unit, points); gives a picture file. Analog traces get a
//! y-axis labelled with their names and units; logic traces (values 0/1) are drawn as
//! digital steps on a 0/1 axis. Long traces are reduced to a min/max envelope per pixel
//! column, so ripple stays visible and files stay small. Text uses DejaVu Sans, embedded from
//! `assets/` (its license is in `assets/DejaVuSans.LICENSE`). Knows nothing of simulation or
//! extraction.

use miette::Diagnostic;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Once;
use thiserror::Error;

/// How a trace is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceKind {
    /// A continuous quantity, drawn as a polyline.
    Analog,
    /// A logic level (0 or 1), drawn as steps.
    Logic,
}

/// One named waveform.
#[derive(Debug, Clone)]
pub struct Trace {
    /// Legend name, e.g. `measured`.
    pub name: String,
    /// Unit, e.g. `A` (empty for logic).
    pub unit: String,
    /// (time, value) points, time increasing.
    pub points: Vec<(f64, f64)>,
    /// Analog or logic.
    pub kind: TraceKind,
}

impl Trace {
    /// An analog trace.
    pub fn analog(
        name: impl Into<String>,
        unit: impl Into<String>,
        points: Vec<(f64, f64)>,
    ) -> Self {
        Trace {
            name: name.into(),
            unit: unit.into(),
            points,
            kind: TraceKind::Analog,
        }
    }

    /// A logic trace (values 0 or 1).
    pub fn logic(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Trace {
            name: name.into(),
            unit: String::new(),
            points,
            kind: TraceKind::Logic,
        }
    }
}

/// One panel of the stack: its traces share a y-axis.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    /// Axis label; when empty, made from the trace names and units.
    pub label: String,
    /// The traces.
    pub traces: Vec<Trace>,
}

impl Panel {
    /// A panel with an axis label and traces.
    pub fn new(label: impl Into<String>, traces: Vec<Trace>) -> Self {
        Panel {
            label: label.into(),
            traces,
        }
    }

    fn is_logic(&self) -> bool {
        !self.traces.is_empty() && self.traces.iter().all(|t| t.kind == TraceKind::Logic)
    }

    fn axis_label(&self) -> String {
        let mut units: Vec<&str> = self
            .traces
            .iter()
            .map(|t| t.unit.as_str())
            .filter(|u| !u.is_empty())
            .collect();
        units.dedup();
        let unit = if units.is_empty() {
            String::new()
        } else {
            format!(" ({})", units.join(", "))
        };
        if self.label.is_empty() {
            let names: Vec<&str> = self.traces.iter().map(|t| t.name.as_str()).collect();
            format!("{}{unit}", names.join(", "))
        } else {
            format!("{}{unit}", self.label)
        }
    }
}

/// Why a plot could not be drawn.
#[derive(Debug, Error, Diagnostic)]
pub enum PlotError {
    /// The extension names no supported format.
    #[error("cannot plot to `{}`: unknown picture format", path.display())]
    #[diagnostic(
        code(vams::output::plot_format),
        help("name the file with .svg or .png")
    )]
    Format { path: PathBuf },
    /// Nothing to draw.
    #[error("cannot plot to `{}`: no panel has points", path.display())]
    #[diagnostic(
        code(vams::output::plot_empty),
        help("give at least one trace with points")
    )]
    Empty { path: PathBuf },
    /// The backend failed (e.g. the directory does not exist).
    #[error("cannot plot to `{}`: {what}", path.display())]
    #[diagnostic(
        code(vams::output::plot_draw),
        help("check that the directory exists and is writable")
    )]
    Draw { path: PathBuf, what: String },
}

const WIDTH: u32 = 1100;
const PANEL_HEIGHT: u32 = 240;
pub(super) const FONT: &str = "sans-serif";
pub(super) const COLORS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(23, 190, 207),
];

pub(super) fn register_font() {
    static REGISTER: Once = Once::new();
    REGISTER.call_once(|| {
        // The font is committed with the crate; a parse failure would only lose text.
        let _ = plotters::style::register_font(
            FONT,
            FontStyle::Normal,
            include_bytes!("../../../../assets/DejaVuSans.ttf"),
        );
    });
}

/// A picture that draws itself on any plotters backend (the SVG and PNG ones).
pub(super) trait Picture {
    fn draw<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static;
}

/// Draws `picture` of `size` pixels into `path`, SVG or PNG by its extension, through a
/// temporary beside it that is renamed over it when complete (a failed drawing leaves the
/// previous file).
pub(super) fn write_picture(
    path: &Path,
    size: (u32, u32),
    picture: &impl Picture,
) -> Result<(), PlotError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    register_font();
    let temp = super::atomic::temp_path(path);
    let err = |e: Box<dyn std::error::Error>| PlotError::Draw {
        path: path.to_path_buf(),
        what: e.to_string(),
    };
    let drawn = match ext.as_deref() {
        Some("svg") => picture.draw(SVGBackend::new(&temp, size).into_drawing_area()),
        Some("png") => picture.draw(BitMapBackend::new(&temp, size).into_drawing_area()),
        _ => {
            return Err(PlotError::Format {
                path: path.to_path_buf(),
            });
        }
    };
    if let Err(e) = drawn {
        let _ = std::fs::remove_file(&temp);
        return Err(err(e));
    }
    super::atomic::commit(&temp, path).map_err(|e| err(Box::new(e)))
}

/// Draws `panels` stacked over a shared time axis into `path` (`.svg` or `.png`).
pub fn plot_panels(path: &Path, title: &str, panels: &[Panel]) -> Result<(), PlotError> {
    plot_panels_over(path, title, "time (s)", panels)
}

/// Draws `panels` stacked over a shared x axis labelled `x_label` (a DC sweep's parameter)
/// into `path` (`.svg` or `.png`).
pub fn plot_panels_over(
    path: &Path,
    title: &str,
    x_label: &str,
    panels: &[Panel],
) -> Result<(), PlotError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let drawn: Vec<&Panel> = panels
        .iter()
        .filter(|p| p.traces.iter().any(|t| !t.points.is_empty()))
        .collect();
    if drawn.is_empty() {
        return Err(PlotError::Empty {
            path: path.to_path_buf(),
        });
    }
    register_font();
    let size = (WIDTH, 60 + PANEL_HEIGHT * drawn.len() as u32);
    let err = |e: Box<dyn std::error::Error>| PlotError::Draw {
        path: path.to_path_buf(),
        what: e.to_string(),
    };
    match ext.as_deref() {
        Some("svg") => draw(
            SVGBackend::new(path, size).into_drawing_area(),
            title,
            x_label,
            &drawn,
        )
        .map_err(err),
        Some("png") => draw(
            BitMapBackend::new(path, size).into_drawing_area(),
            title,
            x_label,
            &drawn,
        )
        .map_err(err),
        _ => Err(PlotError::Format {
            path: path.to_path_buf(),
        }),
    }
}

/// A pixel column being reduced: its index, lowest and highest point.
type Bucket = Option<(usize, (f64, f64), (f64, f64))>;

/// Reduces a trace to at most two points (min, max) per pixel column.
fn envelope(points: &[(f64, f64)], x0: f64, x1: f64, columns: usize) -> Vec<(f64, f64)> {
    if points.len() <= 4 * columns || x1 <= x0 {
        return points.to_vec();
    }
    let mut out = Vec::with_capacity(2 * columns);
    let mut bucket: Bucket = None;
    let flush = |b: Bucket, out: &mut Vec<(f64, f64)>| {
        if let Some((_, lo, hi)) = b {
            if lo.0 <= hi.0 {
                out.extend([lo, hi]);
            } else {
                out.extend([hi, lo]);
            }
        }
    };
    for &p in points {
        let col = (((p.0 - x0) / (x1 - x0)) * columns as f64).floor().max(0.0) as usize;
        match bucket.as_mut() {
            Some((c, lo, hi)) if *c == col => {
                if p.1 < lo.1 {
                    *lo = p;
                }
                if p.1 > hi.1 {
                    *hi = p;
                }
            }
            _ => {
                flush(bucket.take(), &mut out);
                bucket = Some((col, p, p));
            }
        }
    }
    flush(bucket, &mut out);
    out
}

/// A logic trace as steps: the level holds until the next point.
fn steps(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * points.len());
    for (k, &(x, y)) in points.iter().enumerate() {
        if k > 0 {
            out.push((x, points[k - 1].1));
        }
        out.push((x, y));
    }
    out
}

/// The x axis's label and tick text: an axis in seconds (`... (s)`) of a short run scaled to
/// the SI prefix of its largest value, with as many decimals as its tick spacing needs.
struct XAxis {
    label: String,
    factor: f64,
    decimals: usize,
}

impl XAxis {
    fn for_range(label: &str, x0: f64, x1: f64) -> XAxis {
        const PREFIXES: [(f64, &str); 5] = [
            (1e-3, "m"),
            (1e-6, "\u{b5}"),
            (1e-9, "n"),
            (1e-12, "p"),
            (1e-15, "f"),
        ];
        let largest = x0.abs().max(x1.abs());
        let (factor, label) = match label.strip_suffix("(s)") {
            // Seconds down to 0.1 s; below, the prefix of the largest value (50 ms, 30 ns).
            Some(stem) if largest < 0.1 => PREFIXES
                .iter()
                .find(|(f, _)| largest >= *f)
                .map_or((1.0, label.to_string()), |&(f, p)| {
                    (f, format!("{stem}({p}s)"))
                }),
            _ => (1.0, label.to_string()),
        };
        // About ten ticks: their spacing's first significant digit needs these decimals.
        let step = (x1 - x0) / factor / 10.0;
        let decimals = if step > 0.0 && step.is_finite() {
            (-step.log10().floor()).clamp(0.0, 12.0) as usize
        } else {
            0
        };
        XAxis {
            label,
            factor,
            decimals,
        }
    }

    fn tick(&self, v: f64) -> String {
        format!("{:.*}", self.decimals, v / self.factor)
    }
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    x_label: &str,
    panels: &[&Panel],
) -> Result<(), Box<dyn std::error::Error>>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE)?;
    let root = root.titled(title, (FONT, 22))?;
    let all = panels
        .iter()
        .flat_map(|p| p.traces.iter())
        .flat_map(|t| t.points.iter());
    let (mut x0, mut x1) = (f64::INFINITY, f64::NEG_INFINITY);
    for &(x, _) in all {
        if x.is_finite() {
            x0 = x0.min(x);
            x1 = x1.max(x);
        }
    }
    if x1 <= x0 {
        x1 = x0 + 1.0;
    }
    // An axis in seconds is labelled in the unit its values read best in (`time (ns)` for a
    // run of 30 ns: plain seconds would print every tick as 0.0).
    let axis = XAxis::for_range(x_label, x0, x1);
    let areas = root.split_evenly((panels.len(), 1));
    for (k, (area, panel)) in areas.iter().zip(panels).enumerate() {
        let last = k + 1 == panels.len();
        let (y0, y1) = if panel.is_logic() {
            (-0.2, 1.2)
        } else {
            let ys = panel
                .traces
                .iter()
                .flat_map(|t| t.points.iter().map(|p| p.1))
                .filter(|y| y.is_finite());
            let (lo, hi) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
                (a.min(y), b.max(y))
            });
            let pad = ((hi - lo) * 0.06).max(1e-12 + hi.abs() * 1e-6);
            if lo.is_finite() {
                (lo - pad, hi + pad)
            } else {
                (0.0, 1.0)
            }
        };
        let mut chart = ChartBuilder::on(area)
            .margin(6)
            .margin_right(20)
            .x_label_area_size(if last { 40 } else { 22 })
            .y_label_area_size(80)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        let label = panel.axis_label();
        let tick = |v: &f64| axis.tick(*v);
        let mut mesh = chart.configure_mesh();
        mesh.y_desc(label.as_str())
            .label_style((FONT, 13))
            .axis_desc_style((FONT, 14))
            .light_line_style(RGBColor(235, 235, 235));
        if last {
            mesh.x_desc(axis.label.as_str());
        }
        mesh.x_label_formatter(&tick);
        if panel.is_logic() {
            mesh.y_labels(2).y_label_formatter(&|v| format!("{v:.0}"));
        }
        mesh.draw()?;
        for (n, trace) in panel.traces.iter().enumerate() {
            let color = COLORS[n % COLORS.len()];
            let pts = match trace.kind {
                TraceKind::Logic => steps(&trace.points),
                TraceKind::Analog => envelope(&trace.points, x0, x1, WIDTH as usize),
            };
            let width = if n == 0 { 1 } else { 2 };
            draw_trace(&mut chart, pts, &trace.name, color, width)?;
        }
        if panel.traces.len() > 1 {
            draw_legend(&mut chart)?;
        }
    }
    root.present()?;
    Ok(())
}

/// One trace as a line of `width` pixels, labelled `name` in the legend.
pub(super) fn draw_trace<'a, DB, CT>(
    chart: &mut ChartContext<'a, DB, CT>,
    points: Vec<(f64, f64)>,
    name: &str,
    color: RGBColor,
    width: u32,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB: DrawingBackend + 'a,
    DB::ErrorType: 'static,
    CT: CoordTranslate<From = (f64, f64)>,
{
    chart
        .draw_series(std::iter::once(PathElement::new(
            points,
            color.stroke_width(width),
        )))?
        .label(name)
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2)));
    Ok(())
}

/// The legend of a panel's traces, in its upper right corner.
pub(super) fn draw_legend<'a, DB, CT>(
    chart: &mut ChartContext<'a, DB, CT>,
) -> Result<(), Box<dyn std::error::Error>>
where
    DB: DrawingBackend + 'a,
    DB::ErrorType: 'static,
    CT: CoordTranslate<From = (f64, f64)>,
{
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(RGBColor(180, 180, 180))
        .label_font((FONT, 13))
        .draw()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn panels() -> Vec<Panel> {
        let sine: Vec<(f64, f64)> = (0..5000)
            .map(|k| (k as f64 * 1e-4, (k as f64 * 0.05).sin()))
            .collect();
        let cosine: Vec<(f64, f64)> = (0..50)
            .map(|k| (k as f64 * 1e-2, (k as f64 * 0.5).cos()))
            .collect();
        let logic: Vec<(f64, f64)> = (0..10).map(|k| (k as f64 * 0.05, (k % 2) as f64)).collect();
        vec![
            Panel::new(
                "current",
                vec![
                    Trace::analog("measured", "A", sine),
                    Trace::analog("simulated", "A", cosine),
                ],
            ),
            Panel::new("", vec![Trace::logic("enable", logic)]),
        ]
    }

    #[test]
    fn a_short_time_axis_reads_in_its_own_unit() {
        let axis = XAxis::for_range("time (s)", 0.0, 30e-9);
        assert_eq!(axis.label, "time (ns)");
        assert_eq!(axis.tick(15e-9), "15");
        let axis = XAxis::for_range("time (s)", 0.0, 6.0);
        assert_eq!(
            (axis.label.as_str(), axis.tick(2.5).as_str()),
            ("time (s)", "2.5")
        );
        let axis = XAxis::for_range("time (s)", 0.0, 5e-3);
        assert_eq!(
            (axis.label.as_str(), axis.tick(2.5e-3).as_str()),
            ("time (ms)", "2.5")
        );
        let axis = XAxis::for_range("frequency (Hz)", 10.0, 1e6);
        assert_eq!(axis.label, "frequency (Hz)");
    }

    #[test]
    fn writes_svg_and_png() {
        let dir = tempfile::tempdir().unwrap();
        for name in ["w.svg", "w.png"] {
            let path = dir.path().join(name);
            plot_panels(&path, "test waveforms", &panels()).unwrap();
            let bytes = std::fs::read(&path).unwrap();
            assert!(bytes.len() > 5000, "{name}: {} bytes", bytes.len());
            if name.ends_with("svg") {
                let text = String::from_utf8(bytes).unwrap();
                assert!(
                    text.contains("time (s)")
                        && text.contains("current (A)")
                        && text.contains("enable")
                );
                assert!(text.matches("<polyline").count() >= 3);
            } else {
                assert_eq!(&bytes[1..4], b"PNG");
            }
        }
    }

    #[test]
    fn rejects_unknown_formats_and_empty_plots() {
        let dir = tempfile::tempdir().unwrap();
        assert!(matches!(
            plot_panels(&dir.path().join("w.pdf"), "t", &panels()),
            Err(PlotError::Format { .. })
        ));
        assert!(matches!(
            plot_panels(&dir.path().join("w.svg"), "t", &[]),
            Err(PlotError::Empty { .. })
        ));
    }

    #[test]
    fn envelope_keeps_extremes_and_steps_hold_levels() {
        let pts: Vec<(f64, f64)> = (0..10_000)
            .map(|k| (k as f64, if k == 5000 { 9.0 } else { 0.0 }))
            .collect();
        let env = envelope(&pts, 0.0, 10_000.0, 100);
        assert!(env.len() <= 200 && env.iter().any(|p| p.1 == 9.0));
        assert_eq!(
            steps(&[(0.0, 0.0), (1.0, 1.0)]),
            vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]
        );
    }
}
