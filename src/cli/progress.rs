//! `vams run`'s progress bar: one line on stderr, redrawn in place with `\r`, shown only when
//! stderr is a terminal and only once the run has taken a second (short runs stay quiet).
//! Reports printed during the run clear the line first so they never share it.

use std::io::{IsTerminal, Write};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::kernel::ProgressHook;

/// How long a run goes before the bar appears.
const QUIET_FOR: Duration = Duration::from_secs(1);
/// Cells of the bar itself.
const WIDTH: usize = 30;

/// The bar of one run.
#[derive(Clone)]
pub struct ProgressBar {
    stop: f64,
    started: Instant,
    /// True while a bar is on the line (something to clear).
    drawn: Arc<AtomicBool>,
}

impl ProgressBar {
    /// A bar for a run to `stop`, or `None` when stderr is not a terminal.
    pub fn for_stderr(stop: f64) -> Option<ProgressBar> {
        std::io::stderr().is_terminal().then(|| ProgressBar {
            stop,
            started: Instant::now(),
            drawn: Arc::new(AtomicBool::new(false)),
        })
    }

    /// The kernel's hook: draws the bar once the run has taken [`QUIET_FOR`].
    pub fn hook(&self) -> ProgressHook {
        let bar = self.clone();
        ProgressHook::new(move |t| {
            if bar.started.elapsed() >= QUIET_FOR {
                eprint!("\r{}", bar_line(t, bar.stop, bar.started.elapsed()));
                let _ = std::io::stderr().flush();
                bar.drawn.store(true, Ordering::Relaxed);
            }
        })
    }

    /// Erases the bar, if one is drawn (before a report line, and at the end of the run).
    pub fn clear(&self) {
        if self.drawn.swap(false, Ordering::Relaxed) {
            eprint!("\r\x1b[2K");
            let _ = std::io::stderr().flush();
        }
    }
}

/// The unit both times are shown in, from the stop time: (seconds per unit, name).
fn unit_of(stop: f64) -> (f64, &'static str) {
    match stop {
        s if s >= 1.0 => (1.0, "s"),
        s if s >= 1e-3 => (1e-3, "ms"),
        s if s >= 1e-6 => (1e-6, "us"),
        _ => (1e-9, "ns"),
    }
}

/// `[#########.....................]  31%  1.860 of 6.000 s  (2.1 s)`: fixed decimals, so
/// that the line keeps its width as it is redrawn.
fn bar_line(t: f64, stop: f64, wall: Duration) -> String {
    let fraction = if stop > 0.0 {
        (t / stop).clamp(0.0, 1.0)
    } else {
        1.0
    };
    let (scale, unit) = unit_of(stop);
    let filled = (fraction * WIDTH as f64).round() as usize;
    format!(
        "[{}{}] {:>3.0}%  {:.3} of {:.3} {unit}  ({:.1} s)",
        "#".repeat(filled),
        ".".repeat(WIDTH - filled),
        fraction * 100.0,
        t / scale,
        stop / scale,
        wall.as_secs_f64()
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_line_shows_the_fraction_the_times_and_the_wall_clock() {
        let line = bar_line(1.5, 6.0, Duration::from_millis(2100));
        assert_eq!(
            line,
            "[########......................]  25%  1.500 of 6.000 s  (2.1 s)"
        );
        assert!(bar_line(2.5e-3, 1e-2, Duration::ZERO).contains("2.500 of 10.000 ms"));
        assert!(bar_line(7.0, 6.0, Duration::ZERO).starts_with(&format!("[{}]", "#".repeat(30))));
        assert!(bar_line(0.0, 0.0, Duration::ZERO).contains("100%"));
    }
}
