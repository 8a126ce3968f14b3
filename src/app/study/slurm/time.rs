//! Slurm's time-limit formats, checked before a script is written, so that a typo in
//! `--time` is a usage error here rather than an sbatch rejection after the spec was read.

/// Checks `text` against the formats sbatch's `--time` takes: `MM`, `MM:SS`, `HH:MM:SS`,
/// `D-HH`, `D-HH:MM`, `D-HH:MM:SS`, and `INFINITE`/`UNLIMITED`. The leading field may be
/// as large as wanted (`90` minutes, `36:00:00`); the fields after it are minutes and seconds
/// below 60, and hours after a day below 24. The error says what was wrong, for a usage
/// message.
pub fn validate_time(text: &str) -> Result<(), String> {
    const FORMATS: &str = "MM, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS";
    if ["infinite", "unlimited"].contains(&text.to_ascii_lowercase().as_str()) {
        return Ok(());
    }
    let bad = |why: &str| {
        Err(format!(
            "`{text}` is not a Slurm time limit ({why}): use {FORMATS}"
        ))
    };
    let (days, clock) = match text.split_once('-') {
        Some((days, clock)) => (Some(days), clock),
        None => (None, text),
    };
    let fields: Vec<&str> = clock.split(':').collect();
    let numbers: Option<Vec<u64>> = days
        .into_iter()
        .chain(fields.iter().copied())
        .map(|f| {
            (!f.is_empty() && f.bytes().all(|b| b.is_ascii_digit()))
                .then(|| f.parse().ok())
                .flatten()
        })
        .collect();
    let Some(numbers) = numbers else {
        return bad("every field is a number");
    };
    // The fields that must stay below a bound: what follows the leading one.
    let bounds: &[u64] = match (days.is_some(), fields.len()) {
        (false, 1) => &[],
        (false, 2) => &[60],
        (false, 3) => &[60, 60],
        (true, 1) => &[24],
        (true, 2) => &[24, 60],
        (true, 3) => &[24, 60, 60],
        _ => return bad("too many fields"),
    };
    let tail = &numbers[numbers.len() - bounds.len()..];
    if tail.iter().zip(bounds).any(|(n, bound)| n >= bound) {
        return bad("hours below 24 after a day, minutes and seconds below 60");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::validate_time;

    #[test]
    fn slurm_formats_are_accepted() {
        for ok in [
            "30",
            "90",
            "0",
            "30:00",
            "1:00:00",
            "36:00:00",
            "2-0",
            "2-12",
            "1-12:30",
            "1-12:30:15",
            "INFINITE",
            "unlimited",
        ] {
            assert_eq!(validate_time(ok), Ok(()), "{ok}");
        }
    }

    #[test]
    fn malformed_times_are_refused() {
        for bad in [
            "",
            "1h",
            "1:2:3:4",
            "-5",
            "1-",
            "1-2:3:4:5",
            ":30",
            "10:",
            "1:60",
            "1:00:60",
            "1-24",
            "1-2:60",
            "+5",
            "1 0",
            "1--2",
        ] {
            let err = validate_time(bad).expect_err(bad);
            assert!(err.contains("HH:MM:SS"), "{err}");
        }
    }
}
