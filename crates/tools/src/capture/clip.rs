//! Clipped samples: where a channel sits at the ADC's rails.

use super::{Capture, Channel};
use super::{CaptureError, CaptureWarning, MAX_CLIPPED_FRACTION, MIN_CLIP_RUN};

/// Marks the clipped samples of every channel of `cap` (infinities always; flat runs at the
/// extremes with `runs`), replaces infinities by the rail, and warns, or fails for a channel
/// clipped almost everywhere.
pub(super) fn mark(cap: &mut Capture, runs: bool) -> Result<(), CaptureError> {
    for ch in &mut cap.channels {
        mark_channel(ch, runs);
        let n = ch.clipped.iter().filter(|c| **c).count();
        if n == 0 {
            continue;
        }
        if n as f64 > MAX_CLIPPED_FRACTION * ch.values.len() as f64 {
            return Err(CaptureError::AllClipped {
                path: cap.path.clone(),
                channel: ch.name.clone(),
                clipped: n,
                samples: ch.values.len(),
            });
        }
        let first = ch.clipped.iter().position(|c| *c).unwrap_or(0);
        let last = ch.clipped.iter().rposition(|c| *c).unwrap_or(0);
        cap.warnings.push(CaptureWarning::Clipped {
            path: cap.path.clone(),
            channel: ch.name.clone(),
            samples: n,
            from: cap.time[first],
            to: cap.time[last],
        });
    }
    Ok(())
}

fn mark_channel(ch: &mut Channel, runs: bool) {
    let finite = ch.values.iter().copied().filter(|v| v.is_finite());
    let (lo, hi) = finite.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    let (lo, hi) = if lo <= hi { (lo, hi) } else { (0.0, 0.0) };
    for v in &mut ch.values {
        if *v == f64::INFINITY {
            *v = hi;
        } else if *v == f64::NEG_INFINITY {
            *v = lo;
        }
    }
    if !runs || lo == hi {
        return;
    }
    for rail in [lo, hi] {
        if !piles_up(&ch.values, rail) {
            continue;
        }
        let mut k = 0;
        let n = ch.values.len();
        while k < n {
            if ch.values[k] != rail {
                k += 1;
                continue;
            }
            let start = k;
            while k < n && ch.values[k] == rail {
                k += 1;
            }
            if k - start >= MIN_CLIP_RUN {
                ch.clipped[start..k].iter_mut().for_each(|c| *c = true);
            }
        }
    }
}

/// Whether samples pile up at `rail`: more of them sit exactly there than at the nearest value
/// the channel takes inside. A clipped signal spends its time at the rail; the peak of an
/// unclipped, noisy plateau (whose 8-bit codes also repeat in runs) is its rarest code.
fn piles_up(values: &[f64], rail: f64) -> bool {
    let at = values.iter().filter(|v| **v == rail).count();
    let nearest = values
        .iter()
        .copied()
        .filter(|v| *v != rail && v.is_finite())
        .min_by(|a, b| (a - rail).abs().total_cmp(&(b - rail).abs()));
    let Some(next) = nearest else {
        return true;
    };
    let beside = values.iter().filter(|v| **v == next).count();
    at > beside
}
