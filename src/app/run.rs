//! `vams run`: elaborate, simulate to the stop time, print reports as they happen, stream the
//! waveform files and the plot's data as the run goes (`output::stream`), and close with a
//! summary line.

use crate::kernel::{Outcome, SimEnd, SimStats};

use super::time::format_time;

/// The probes to record: `--probe` names plus the `--panel` names, each once; empty (record
/// everything) when no `--probe` is given.
pub fn probe_list(probes: &[String], panels: &[Vec<String>]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    if probes.is_empty() {
        return out;
    }
    for name in probes
        .iter()
        .map(|p| p.trim().to_ascii_lowercase())
        .chain(panels.iter().flatten().cloned())
    {
        if !out.contains(&name) {
            out.push(name);
        }
    }
    out
}

/// The closing line: simulated and wall time, steps, Newton iterations, files written.
pub fn summary(top: &str, stop: f64, result: &SimEnd, wall: f64, written: &[String]) -> String {
    let ended = match result.outcome {
        Outcome::Finished => format!("simulated {top} to {}", format_time(stop)),
        Outcome::Stopped { time } => format!(
            "simulated {top} to {} (stopped by the design)",
            format_time(time)
        ),
        Outcome::Failed { time } => format!("simulated {top} to {} (FAILED)", format_time(time)),
    };
    let files = if written.is_empty() {
        String::new()
    } else {
        format!("; wrote {}", written.join(", "))
    };
    format!(
        "{ended} in {wall:.2} s wall time: {} accepted steps, {} Newton iterations{files}",
        result.stats.accepted_steps, result.stats.newton_iterations
    )
}

/// Every counter of [`SimStats`], one per line.
pub fn stats_table(stats: &SimStats) -> String {
    (stats.named().iter())
        .map(|&(name, n)| {
            // Newton failures are a part of the rejected steps above them.
            let name = match name {
                "Newton failures" => "  Newton failures",
                other => other,
            };
            format!("  {name:<18} {n:>10}\n")
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn summary_and_stats_name_every_figure() {
        let result = SimEnd {
            reports: vec![],
            outcome: Outcome::Finished,
            stats: SimStats {
                accepted_steps: 1234,
                newton_iterations: 5678,
                breaks: 3,
                ..SimStats::default()
            },
        };
        let line = summary("tb", 6.0, &result, 0.5, &["a.csv".into(), "p.svg".into()]);
        assert_eq!(
            line,
            "simulated tb to 6 s in 0.50 s wall time: 1234 accepted steps, 5678 Newton iterations; wrote a.csv, p.svg"
        );
        let table = stats_table(&result.stats);
        assert_eq!(table.lines().count(), 10);
        assert!(table.contains("breaks") && table.contains("5678"));
    }
}
