//! The plots of a sweep: the envelope of waveforms over many runs, histograms of metrics, and
//! a tornado of sensitivities, as SVG or PNG (by the file's extension).
//!
//! Takes plain numbers (folded runs, metric values, normalised sensitivities); gives picture
//! files written beside the target and renamed over it when complete, in the look of
//! [`super::plot`] (its fonts, colours and legend). The envelope is folded run by run in
//! memory bounded by its number of time bins, not by the number of runs. Knows nothing of
//! the sweep's spec or of simulation.

mod envelope;
mod histogram;
mod tornado;

pub use envelope::{Envelope, EnvelopeBuilder, plot_envelopes};
pub use histogram::{Histogram, bin_count, plot_histograms};
pub use tornado::{TornadoBar, plot_tornado};

/// `name (unit)`, or the name alone.
fn label(name: &str, unit: Option<&str>) -> String {
    match unit {
        Some(u) if !u.is_empty() => format!("{name} ({u})"),
        _ => name.to_string(),
    }
}

/// `(lo, hi)` of the finite `values` padded by 6 % (a fixed pad when they are all equal),
/// `None` when there is none.
fn padded_range(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return None;
    }
    let pad = if hi > lo {
        (hi - lo) * 0.06
    } else if hi != 0.0 {
        hi.abs() * 0.1
    } else {
        1.0
    };
    Some((lo - pad, hi + pad))
}

/// A tick label on an axis `span` wide: six significant digits without rounding noise (`1.2`,
/// not `1.2000000000000002`; `0`, not `-5.551e-17`), in scientific notation when very small
/// or large.
fn tick(v: f64, span: f64) -> String {
    let v = if v.abs() <= 1e-9 * span { 0.0 } else { v };
    let m = v.abs();
    if m != 0.0 && !(1e-3..1e6).contains(&m) {
        return format!("{v:.3e}");
    }
    let rounded: f64 = format!("{v:.5e}").parse().unwrap_or(v);
    if rounded == 0.0 {
        "0".into()
    } else {
        rounded.to_string()
    }
}

#[cfg(test)]
mod tests {
    /// For the plots' tests: draws through `draw` into an SVG and a PNG in `dir`, checks each is
    /// at least `min_bytes` long and that the SVG's text holds every one of `wants`.
    pub(super) fn assert_drawn(
        dir: &std::path::Path,
        min_bytes: usize,
        wants: &[&str],
        draw: impl Fn(&std::path::Path) -> Result<(), crate::output::plot::PlotError>,
    ) {
        for name in ["picture.svg", "picture.png"] {
            let path = dir.join(name);
            draw(&path).unwrap();
            let bytes = std::fs::read(&path).unwrap();
            assert!(bytes.len() > min_bytes, "{name}: {} bytes", bytes.len());
            if name.ends_with("svg") {
                let text = String::from_utf8(bytes).unwrap();
                for want in wants {
                    assert!(text.contains(want), "{want}");
                }
            }
        }
    }

    use super::*;

    #[test]
    fn ticks_drop_rounding_noise() {
        assert_eq!(tick(1.2000000000000002, 1.0), "1.2");
        assert_eq!(tick(-0.1, 1.0), "-0.1");
        assert_eq!(tick(-5.551e-17, 1.0), "0");
        assert_eq!(tick(2.5e-6, 1e-5), "2.500e-6");
        assert_eq!(tick(150.0, 1.0), "150");
        assert_eq!(
            padded_range([1.0, f64::NAN, 3.0].into_iter()),
            Some((0.88, 3.12))
        );
        assert_eq!(padded_range([f64::NAN].into_iter()), None);
    }
}
