//! Assertions on a small-signal response, for `vams ac --assert` and for `-- vams: assert`
//! comments of testbenches run by `vams test`: `MEASURE(PROBE, FREQUENCY) OP BOUND`, with
//! MEASURE one of `gain_db`, `gain` (magnitude), `phase_deg`, and OP one of `<`, `<=`, `>`,
//! `>=`. Each is solved at exactly its frequency (no interpolation on a grid).

use faer::c64;

use crate::design::{Design, QuantityId};
use crate::solver::ac::{db, degrees};

use super::ac::{Linearised, parse_frequency, probes, respond};
use super::error::CliError;

/// What an assertion measures of a probe's phasor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Measure {
    GainDb,
    Gain,
    PhaseDeg,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Comparison {
    Less,
    LessOrEqual,
    Greater,
    GreaterOrEqual,
}

/// `gain_db(vout, 1kHz) > -3.1`.
#[derive(Clone, Debug, PartialEq)]
pub struct AcAssertion {
    pub measure: Measure,
    pub probe: String,
    pub frequency: f64,
    pub comparison: Comparison,
    pub bound: f64,
    /// As written, for the verdict line.
    pub text: String,
}

impl AcAssertion {
    /// Reads an assertion; the error says what is wrong with it.
    pub fn parse(text: &str) -> Result<AcAssertion, CliError> {
        let bad = |problem: &str| CliError::AcAssertion {
            text: text.trim().to_string(),
            problem: problem.to_string(),
        };
        let t = text.trim();
        let open = t
            .find('(')
            .ok_or_else(|| bad("expected MEASURE(PROBE, FREQUENCY)"))?;
        let measure = match t[..open].trim().to_ascii_lowercase().as_str() {
            "gain_db" => Measure::GainDb,
            "gain" => Measure::Gain,
            "phase_deg" => Measure::PhaseDeg,
            other => {
                return Err(bad(&format!(
                    "unknown measure `{other}`; use gain_db, gain or phase_deg"
                )));
            }
        };
        let close = t[open..]
            .find(')')
            .map(|k| open + k)
            .ok_or_else(|| bad("a `)` is missing"))?;
        let (probe, frequency) = t[open + 1..close]
            .split_once(',')
            .ok_or_else(|| bad("expected two arguments, a probe and a frequency"))?;
        let probe = probe.trim().to_ascii_lowercase();
        if probe.is_empty() {
            return Err(bad("the probe is missing"));
        }
        let frequency = parse_frequency(frequency).map_err(|e| bad(&e))?;
        let rest = t[close + 1..].trim();
        let (comparison, bound) = [
            ("<=", Comparison::LessOrEqual),
            (">=", Comparison::GreaterOrEqual),
            ("<", Comparison::Less),
            (">", Comparison::Greater),
        ]
        .into_iter()
        .find_map(|(op, c)| rest.strip_prefix(op).map(|b| (c, b)))
        .ok_or_else(|| bad("expected a comparison: <, <=, > or >= and a number"))?;
        let bound = bound
            .trim()
            .parse::<f64>()
            .ok()
            .filter(|b| b.is_finite())
            .ok_or_else(|| bad(&format!("`{}` is not a number", bound.trim())))?;
        Ok(AcAssertion {
            measure,
            probe,
            frequency,
            comparison,
            bound,
            text: t.to_string(),
        })
    }

    /// The measured value of phasor `z`.
    pub fn measure(&self, z: c64) -> f64 {
        match self.measure {
            Measure::GainDb => db(z),
            Measure::Gain => z.norm(),
            Measure::PhaseDeg => degrees(z),
        }
    }

    pub fn holds(&self, value: f64) -> bool {
        match self.comparison {
            Comparison::Less => value < self.bound,
            Comparison::LessOrEqual => value <= self.bound,
            Comparison::Greater => value > self.bound,
            Comparison::GreaterOrEqual => value >= self.bound,
        }
    }
}

/// An assertion checked: the value found and whether it holds.
#[derive(Clone, Debug, PartialEq)]
pub struct AcVerdict {
    pub text: String,
    pub value: f64,
    pub holds: bool,
}

impl AcVerdict {
    /// `assert gain_db(vout, 1kHz) > -3.1: -3.0103 ... ok`.
    pub fn line(&self) -> String {
        format!(
            "assert {}: {} ... {}",
            self.text,
            crate::output::csv::format_number(self.value),
            if self.holds { "ok" } else { "FAILED" }
        )
    }
}

/// The quantity each assertion probes (an unknown name is the `--probe` diagnostic).
pub fn assertion_probes(
    design: &Design,
    assertions: &[AcAssertion],
) -> Result<Vec<QuantityId>, CliError> {
    assertions
        .iter()
        .map(|a| match probes(design, std::slice::from_ref(&a.probe)) {
            Ok(found) => found.first().copied().ok_or_else(|| CliError::AcAssertion {
                text: a.text.clone(),
                problem: "no probe".into(),
            }),
            Err(CliError::AcProbe { problem, help, .. }) => Err(CliError::AcAssertion {
                text: a.text.clone(),
                problem: format!("`{}`: {problem}; {help}", a.probe),
            }),
            Err(e) => Err(e),
        })
        .collect()
}

/// Solves the linearised design at each assertion's frequency and judges it.
pub fn check_assertions(
    top: &str,
    linearised: &mut Linearised,
    assertions: &[AcAssertion],
    probes: &[QuantityId],
) -> Result<Vec<AcVerdict>, CliError> {
    assertions
        .iter()
        .zip(probes)
        .map(|(a, &q)| {
            let response = respond(top, linearised, &[q], vec![a.frequency])?;
            // One probe at one frequency: one value.
            let z = (response.values.first())
                .and_then(|column| column.first().copied())
                .unwrap_or(c64::new(f64::NAN, f64::NAN));
            let value = a.measure(z);
            Ok(AcVerdict {
                text: a.text.clone(),
                value,
                holds: a.holds(value),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn assertions_read_measure_probe_frequency_and_bound() {
        let a = AcAssertion::parse(" gain_db(Vout, 1kHz) > -3.1 ").unwrap();
        assert_eq!(a.measure, Measure::GainDb);
        assert_eq!(a.probe, "vout");
        assert_eq!(a.frequency, 1e3);
        assert_eq!(a.comparison, Comparison::Greater);
        assert_eq!(a.bound, -3.1);
        assert_eq!(a.text, "gain_db(Vout, 1kHz) > -3.1");
        let b = AcAssertion::parse("phase_deg(dut.vc, 2.5 MHz) <= -45").unwrap();
        assert_eq!((b.measure, b.frequency), (Measure::PhaseDeg, 2.5e6));
        assert_eq!(b.comparison, Comparison::LessOrEqual);
        assert!(b.holds(-45.0) && !b.holds(-44.9));
        let c = AcAssertion::parse("gain(x, 10) >= 0.99").unwrap();
        assert!((c.measure(c64::new(0.6, 0.8)) - 1.0).abs() < 1e-15);
    }

    #[test]
    fn bad_assertions_say_what_is_wrong() {
        let problem = |t: &str| match AcAssertion::parse(t) {
            Err(CliError::AcAssertion { problem, .. }) => problem,
            other => panic!("{other:?}"),
        };
        assert!(problem("gain_db vout > 1").contains("MEASURE(PROBE, FREQUENCY)"));
        assert!(problem("loudness(vout, 1kHz) > 1").contains("unknown measure `loudness`"));
        assert!(problem("gain_db(vout) > 1").contains("two arguments"));
        assert!(problem("gain_db(vout, fast) > 1").contains("not a positive frequency"));
        assert!(problem("gain_db(vout, 1kHz) = 1").contains("expected a comparison"));
        assert!(problem("gain_db(vout, 1kHz) > high").contains("`high` is not a number"));
        assert!(problem("gain_db(vout, 1kHz > 1").contains("`)` is missing"));
    }

    #[test]
    fn verdict_lines_say_the_value_and_the_outcome() {
        let v = AcVerdict {
            text: "gain_db(vout, 1kHz) > -3.1".into(),
            value: -3.0103,
            holds: true,
        };
        assert_eq!(
            v.line(),
            "assert gain_db(vout, 1kHz) > -3.1: -3.0103 ... ok"
        );
    }
}
