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
