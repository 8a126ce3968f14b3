//! The envelope of one waveform over many runs: its lowest and highest value in each time bin,
//! folded run by run, with the nominal run drawn over the band.
//!
//! Each bin takes the samples inside it and the run's values at both of its edges
//! (interpolated, or held for a signal), so that a spike between bin centres is kept and a
//! run with few samples still gives a band without holes. Memory is two numbers a bin (three
//! with the nominal run), whatever the number of runs.

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::{label, padded_range};
use crate::output::plot::{COLORS, FONT, Picture, PlotError, draw_legend, write_picture};

/// Folds runs into an [`Envelope`].
#[derive(Clone, Debug)]
pub struct EnvelopeBuilder {
    envelope: Envelope,
}

/// The lowest and highest value of a waveform in each time bin over a number of runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Envelope {
    pub name: String,
    pub unit: Option<String>,
    pub t_start: f64,
    pub t_stop: f64,
    /// Per bin, the lowest value (infinite where no run reached the bin).
    pub lo: Vec<f64>,
    /// Per bin, the highest value (minus infinity where no run reached the bin).
    pub hi: Vec<f64>,
    /// The nominal run at each bin's centre (NaN where it has no value).
    pub nominal: Option<Vec<f64>>,
    /// The number of runs folded in.
    pub runs: usize,
}

impl EnvelopeBuilder {
    /// An empty envelope of `columns_of_pixels` bins (at least one) over `[t_start, t_stop]`.
    pub fn new(
        name: impl Into<String>,
        unit: Option<String>,
        t_start: f64,
        t_stop: f64,
        columns_of_pixels: usize,
    ) -> Self {
        let bins = columns_of_pixels.max(1);
        EnvelopeBuilder {
            envelope: Envelope {
                name: name.into(),
                unit,
                t_start,
                t_stop,
                lo: vec![f64::INFINITY; bins],
                hi: vec![f64::NEG_INFINITY; bins],
                nominal: None,
                runs: 0,
            },
        }
    }

    /// Folds one run (`times` non-decreasing, one value each) into the band: linear between
    /// samples, or each value held until the next sample when `piecewise_constant`.
    /// Non-finite values and samples outside the envelope's time span are left out; a run
    /// that stops early leaves the later bins to the others.
    pub fn add_run(&mut self, times: &[f64], values: &[f64], piecewise_constant: bool) {
        let span = self.envelope_span();
        let env = &mut self.envelope;
        env.runs += 1;
        let n = times.len().min(values.len());
        let (times, values) = (&times[..n], &values[..n]);
        let bins = env.lo.len();
        let mut fold = |b: usize, v: f64| {
            if v.is_finite() {
                env.lo[b] = env.lo[b].min(v);
                env.hi[b] = env.hi[b].max(v);
            }
        };
        for (&t, &v) in times.iter().zip(values) {
            if let Some(b) = bin_of(t, span, bins) {
                fold(b, v);
            }
        }
        let mut at = Sampler::new(times, values, piecewise_constant);
        for k in 0..=bins {
            if let Some(v) = at.value(edge(span, bins, k as f64)) {
                if k > 0 {
                    fold(k - 1, v);
                }
                if k < bins {
                    fold(k, v);
                }
            }
        }
    }

    /// Keeps the nominal run, as its value at each bin's centre, to be drawn as a line (it
    /// is not folded into the band: add it with [`Self::add_run`] too when it is one of the
    /// runs).
    pub fn set_nominal(&mut self, times: &[f64], values: &[f64], piecewise_constant: bool) {
        let n = times.len().min(values.len());
        let bins = self.envelope.lo.len();
        let span = self.envelope_span();
        let mut at = Sampler::new(&times[..n], &values[..n], piecewise_constant);
        let line = (0..bins)
            .map(|k| {
                at.value(edge(span, bins, k as f64 + 0.5))
                    .unwrap_or(f64::NAN)
            })
            .collect();
        self.envelope.nominal = Some(line);
    }

    /// The envelope so far.
    pub fn finish(self) -> Envelope {
        self.envelope
    }

    fn envelope_span(&self) -> (f64, f64) {
        (self.envelope.t_start, self.envelope.t_stop)
    }
}

impl Envelope {
    /// The number of time bins.
    pub fn bins(&self) -> usize {
        self.lo.len()
    }

    /// The time span of bin `k`.
    pub fn bin_span(&self, k: usize) -> (f64, f64) {
        let span = (self.t_start, self.t_stop);
        let bins = self.bins();
        (edge(span, bins, k as f64), edge(span, bins, k as f64 + 1.0))
    }

    /// True when some bin has a value.
    pub fn is_drawable(&self) -> bool {
        self.lo.iter().zip(&self.hi).any(|(l, h)| l <= h)
    }
}

/// The time of (fractional) bin edge `k`.
fn edge((t0, t1): (f64, f64), bins: usize, k: f64) -> f64 {
    t0 + (t1 - t0) * k / bins as f64
}

/// The bin holding time `t`, `None` outside the span.
fn bin_of(t: f64, (t0, t1): (f64, f64), bins: usize) -> Option<usize> {
    if t.is_nan() || t < t0 || t > t1 {
        return None;
    }
    if t1 <= t0 {
        return Some(0);
    }
    let b = ((t - t0) / (t1 - t0) * bins as f64).floor() as usize;
    Some(b.min(bins - 1))
}

/// Values of one run at increasing times, walking its samples once.
struct Sampler<'a> {
    times: &'a [f64],
    values: &'a [f64],
    piecewise_constant: bool,
    /// The first sample after the last time asked for.
    next: usize,
}

impl<'a> Sampler<'a> {
    fn new(times: &'a [f64], values: &'a [f64], piecewise_constant: bool) -> Self {
        Sampler {
            times,
            values,
            piecewise_constant,
            next: 0,
        }
    }

    /// The run's value at `t` (not below the previous `t`): after the jump at the time of
    /// one; `None` outside the run or where it is not finite.
    fn value(&mut self, t: f64) -> Option<f64> {
        let (times, values) = (self.times, self.values);
        if times.is_empty() || t < times[0] || t > times[times.len() - 1] {
            return None;
        }
        while self.next < times.len() && times[self.next] <= t {
            self.next += 1;
        }
        // times[0] <= t, so at least one sample is at or before t.
        let i = self.next - 1;
        let v = if self.piecewise_constant || self.next == times.len() || times[i] == t {
            values[i]
        } else {
            let (t0, t1) = (times[i], times[i + 1]);
            values[i] + (values[i + 1] - values[i]) * (t - t0) / (t1 - t0)
        };
        v.is_finite().then_some(v)
    }
}

const WIDTH: u32 = 1100;
const PANEL_HEIGHT: u32 = 240;

/// Draws `envelopes` stacked over a shared time axis into `path` (`.svg` or `.png`): each a
/// shaded min/max band and its nominal run as a line. Envelopes without any value are left
/// out; none with a value is [`PlotError::Empty`].
pub fn plot_envelopes(path: &Path, title: &str, envelopes: &[Envelope]) -> Result<(), PlotError> {
    let drawn: Vec<&Envelope> = envelopes.iter().filter(|e| e.is_drawable()).collect();
    if drawn.is_empty() {
        return Err(PlotError::Empty {
            path: path.to_path_buf(),
        });
    }
    let size = (WIDTH, 60 + PANEL_HEIGHT * drawn.len() as u32);
    write_picture(path, size, &Envelopes { title, drawn })
}

struct Envelopes<'a> {
    title: &'a str,
    drawn: Vec<&'a Envelope>,
}

impl Picture for Envelopes<'_> {
    fn draw<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, Shift>,
    ) -> Result<(), Box<dyn std::error::Error>>
    where
        DB::ErrorType: 'static,
    {
        root.fill(&WHITE)?;
        let root = root.titled(self.title, (FONT, 22))?;
        let x0 = self
            .drawn
            .iter()
            .map(|e| e.t_start)
            .fold(f64::INFINITY, f64::min);
        let mut x1 = self
            .drawn
            .iter()
            .map(|e| e.t_stop)
            .fold(f64::NEG_INFINITY, f64::max);
        if x1 <= x0 || x1.is_nan() {
            x1 = x0 + 1.0;
        }
        let areas = root.split_evenly((self.drawn.len(), 1));
        for (k, (area, env)) in areas.iter().zip(&self.drawn).enumerate() {
            let last = k + 1 == self.drawn.len();
            let values = env
                .lo
                .iter()
                .chain(&env.hi)
                .chain(env.nominal.iter().flatten())
                .copied();
            let (y0, y1) = padded_range(values).unwrap_or((0.0, 1.0));
            let mut chart = ChartBuilder::on(area)
                .margin(6)
                .margin_right(20)
                .x_label_area_size(if last { 40 } else { 22 })
                .y_label_area_size(80)
                .build_cartesian_2d(x0..x1, y0..y1)?;
            let y_label = label(&env.name, env.unit.as_deref());
            let mut mesh = chart.configure_mesh();
            mesh.y_desc(y_label.as_str())
                .label_style((FONT, 13))
                .axis_desc_style((FONT, 14))
                .light_line_style(RGBColor(235, 235, 235));
            if last {
                mesh.x_desc("time (s)");
            }
            mesh.draw()?;
            let band = COLORS[0].mix(0.3);
            chart
                .draw_series(
                    band_polygons(env)
                        .into_iter()
                        .map(|p| Polygon::new(p, band.filled())),
                )?
                .label(format!("{} runs: min/max", env.runs))
                .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 18, y + 5)], band.filled()));
            if let Some(nominal) = &env.nominal {
                let color = COLORS[1];
                let lines = nominal_lines(env, nominal);
                chart
                    .draw_series(
                        lines
                            .into_iter()
                            .map(|l| PathElement::new(l, color.stroke_width(2))),
                    )?
                    .label("nominal")
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 18, y)], color.stroke_width(2))
                    });
            }
            draw_legend(&mut chart)?;
        }
        root.present()?;
        Ok(())
    }
}

/// The outline of each run of consecutive bins with values: along the highs, back along the
/// lows, each bin as wide as its time span.
fn band_polygons(env: &Envelope) -> Vec<Vec<(f64, f64)>> {
    let mut polygons = Vec::new();
    let mut k = 0;
    while k < env.bins() {
        if env.lo[k] > env.hi[k] {
            k += 1;
            continue;
        }
        let first = k;
        while k < env.bins() && env.lo[k] <= env.hi[k] {
            k += 1;
        }
        let mut outline = Vec::with_capacity(4 * (k - first));
        for b in first..k {
            let (a, z) = env.bin_span(b);
            outline.extend([(a, env.hi[b]), (z, env.hi[b])]);
        }
        for b in (first..k).rev() {
            let (a, z) = env.bin_span(b);
            outline.extend([(z, env.lo[b]), (a, env.lo[b])]);
        }
        polygons.push(outline);
    }
    polygons
}

/// The nominal run as lines through the bin centres, broken where it has no value.
fn nominal_lines(env: &Envelope, nominal: &[f64]) -> Vec<Vec<(f64, f64)>> {
    let mut lines: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for (k, &v) in nominal.iter().enumerate() {
        if v.is_finite() {
            let (a, z) = env.bin_span(k);
            if let Some(line) = lines.last_mut() {
                line.push((0.5 * (a + z), v));
            }
        } else if lines.last().is_some_and(|l| !l.is_empty()) {
            lines.push(Vec::new());
        }
    }
    lines.retain(|l| !l.is_empty());
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    fn built(runs: &[(&[f64], &[f64], bool)], bins: usize) -> Envelope {
        let mut b = EnvelopeBuilder::new("v", Some("V".into()), 0.0, 4.0, bins);
        for (t, v, pc) in runs {
            b.add_run(t, v, *pc);
        }
        b.finish()
    }

    #[test]
    fn a_spike_between_bin_centres_is_kept() {
        // Four bins of 1 s; a spike to 5 at 1.4 s in a run that is 0 elsewhere.
        let env = built(
            &[(
                &[0.0, 1.3, 1.4, 1.5, 4.0],
                &[0.0, 0.0, 5.0, 0.0, 0.0],
                false,
            )],
            4,
        );
        assert_eq!(env.hi, vec![0.0, 5.0, 0.0, 0.0]);
        assert_eq!(env.lo, vec![0.0; 4]);
    }

    #[test]
    fn bins_take_the_interpolated_values_at_their_edges() {
        // A ramp from 0 to 4 with samples only at its ends: each bin spans its own slice.
        let env = built(&[(&[0.0, 4.0], &[0.0, 4.0], false)], 4);
        assert_eq!(env.lo, vec![0.0, 1.0, 2.0, 3.0]);
        assert_eq!(env.hi, vec![1.0, 2.0, 3.0, 4.0]);
        // Held instead: 0 until the last sample.
        let held = built(&[(&[0.0, 4.0], &[0.0, 4.0], true)], 4);
        assert_eq!(held.lo, vec![0.0; 4]);
        assert_eq!(held.hi, vec![0.0, 0.0, 0.0, 4.0]);
    }

    #[test]
    fn runs_on_different_grids_fold_together() {
        let env = built(
            &[
                (&[0.0, 2.0, 4.0], &[1.0, 1.0, 1.0], false),
                (
                    &[0.0, 0.5, 1.0, 1.5, 2.5, 3.5],
                    &[2.0, 2.0, -1.0, 2.0, 2.0, 2.0],
                    false,
                ),
                (&[0.0, 4.0], &[f64::NAN, f64::NAN], false),
            ],
            4,
        );
        assert_eq!(env.runs, 3);
        assert_eq!(env.lo, vec![-1.0, -1.0, 1.0, 1.0]);
        assert_eq!(env.hi, vec![2.0; 4]);
        assert!(env.is_drawable());
        assert!(!built(&[], 4).is_drawable());
    }

    #[test]
    fn the_nominal_run_is_its_value_at_bin_centres() {
        let mut b = EnvelopeBuilder::new("v", None, 0.0, 4.0, 4);
        b.set_nominal(&[0.0, 3.0], &[0.0, 3.0], false);
        let env = b.finish();
        let nominal = env.nominal.unwrap();
        assert_eq!(&nominal[..3], &[0.5, 1.5, 2.5]);
        assert!(nominal[3].is_nan());
    }

    #[test]
    fn plots_the_band_and_the_nominal_run() {
        let dir = tempfile::tempdir().unwrap();
        let mut b = EnvelopeBuilder::new("vfb", Some("V".into()), 0.0, 1.0, 200);
        let times: Vec<f64> = (0..=500).map(|k| k as f64 / 500.0).collect();
        for r in 0..20 {
            let gain = 1.0 + 0.01 * r as f64;
            let v: Vec<f64> = times
                .iter()
                .map(|t| gain * (1.0 - (-t * 5.0).exp()))
                .collect();
            b.add_run(&times, &v, false);
        }
        let v: Vec<f64> = times
            .iter()
            .map(|t| 1.1 * (1.0 - (-t * 5.0).exp()))
            .collect();
        b.set_nominal(&times, &v, false);
        let env = b.finish();
        let empty = EnvelopeBuilder::new("none", None, 0.0, 1.0, 10).finish();
        super::super::tests::assert_drawn(
            dir.path(),
            3000,
            &["20 runs: min/max", "nominal", "vfb (V)", "time (s)"],
            |path| plot_envelopes(path, "sweep", &[env.clone(), empty.clone()]),
        );
        assert!(matches!(
            plot_envelopes(&dir.path().join("x.svg"), "t", &[empty]),
            Err(PlotError::Empty { .. })
        ));
        assert!(matches!(
            plot_envelopes(&dir.path().join("x.svg"), "t", &[]),
            Err(PlotError::Empty { .. })
        ));
    }
}
