//! The free parameters of a fit: a generic's name, a first guess, optional bounds, and the
//! coordinate the optimiser moves in.
//!
//! A parameter whose values are all positive (a positive guess and no bound at or below
//! zero) is fitted as its logarithm: a step is then a relative change, whatever the
//! parameter's magnitude (an inductance of 3e-3 H and a resistance of 8 ohm move alike), and
//! the fit can never make it zero or negative. Any other parameter moves linearly in units
//! of its guess's magnitude.

use std::fmt;

/// How a parameter is mapped to the optimiser's coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scale {
    /// `x = ln(value)`.
    Log,
    /// `x = value / unit`.
    Linear { unit: f64 },
}

/// A generic to estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct FreeParam {
    /// The generic, as `-g` takes it (`r`, or `dut.u_motor.r`).
    pub name: String,
    /// The first guess.
    pub guess: f64,
    /// The smallest value allowed.
    pub lower: Option<f64>,
    /// The largest value allowed.
    pub upper: Option<f64>,
    /// The one experiment it belongs to (a nuisance parameter such as the time a capture's
    /// switch closed), or `None`: every experiment's.
    pub experiment: Option<usize>,
}

/// A `--free` argument that does not parse, with why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BadFreeParam(pub String);

impl fmt::Display for BadFreeParam {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for BadFreeParam {}

fn number(text: &str, what: &str, arg: &str) -> Result<f64, BadFreeParam> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| {
            BadFreeParam(format!(
                "`{arg}`: the {what} `{text}` is not a finite number"
            ))
        })
}

impl FreeParam {
    /// Parses `NAME=GUESS`, `NAME=GUESS:MIN:MAX`, `NAME=GUESS:MIN:` or `NAME=GUESS::MAX`.
    pub fn parse(arg: &str) -> Result<FreeParam, BadFreeParam> {
        let Some((name, rest)) = arg.split_once('=') else {
            return Err(BadFreeParam(format!(
                "`{arg}`: expected NAME=GUESS or NAME=GUESS:MIN:MAX, e.g. `r=8` or `r=8:1:20`"
            )));
        };
        let name = name.trim();
        if name.is_empty() {
            return Err(BadFreeParam(format!(
                "`{arg}`: the generic's name is missing"
            )));
        }
        let parts: Vec<&str> = rest.split(':').collect();
        let bound = |k: usize, what: &str| -> Result<Option<f64>, BadFreeParam> {
            match parts.get(k).map(|s| s.trim()) {
                None | Some("") => Ok(None),
                Some(s) => number(s, what, arg).map(Some),
            }
        };
        if parts.len() == 2 || parts.len() > 3 {
            return Err(BadFreeParam(format!(
                "`{arg}`: expected GUESS or GUESS:MIN:MAX (leave MIN or MAX empty for no bound)"
            )));
        }
        let p = FreeParam {
            name: name.to_ascii_lowercase(),
            guess: number(parts[0], "guess", arg)?,
            lower: bound(1, "minimum")?,
            upper: bound(2, "maximum")?,
            experiment: None,
        };
        p.check()
            .map_err(|why| BadFreeParam(format!("`{arg}`: {why}")))?;
        Ok(p)
    }

    /// Whether the bounds hold the guess.
    pub fn check(&self) -> Result<(), String> {
        if let (Some(lo), Some(hi)) = (self.lower, self.upper)
            && lo >= hi
        {
            return Err(format!("the minimum {lo} is not below the maximum {hi}"));
        }
        if self.lower.is_some_and(|lo| self.guess < lo)
            || self.upper.is_some_and(|hi| self.guess > hi)
        {
            return Err(format!("the guess {} is outside its bounds", self.guess));
        }
        Ok(())
    }

    /// The coordinate the optimiser uses for this parameter.
    pub fn scale(&self) -> Scale {
        let positive = self.guess > 0.0 && self.lower.is_none_or(|lo| lo > 0.0);
        if positive {
            Scale::Log
        } else {
            let unit = if self.guess != 0.0 {
                self.guess.abs()
            } else {
                match (self.lower, self.upper) {
                    (Some(lo), Some(hi)) => (hi - lo).abs() / 10.0,
                    _ => 1.0,
                }
            };
            Scale::Linear { unit }
        }
    }

    /// The optimiser's coordinate of `value`.
    pub fn to_x(&self, value: f64) -> f64 {
        match self.scale() {
            Scale::Log => value.ln(),
            Scale::Linear { unit } => value / unit,
        }
    }

    /// The value at coordinate `x`.
    pub fn from_x(&self, x: f64) -> f64 {
        match self.scale() {
            Scale::Log => x.exp(),
            Scale::Linear { unit } => x * unit,
        }
    }

    /// The bounds in the optimiser's coordinate (infinite where there is none).
    pub fn x_bounds(&self) -> (f64, f64) {
        let lo = self.lower.map_or(f64::NEG_INFINITY, |v| self.to_x(v));
        let hi = self.upper.map_or(f64::INFINITY, |v| self.to_x(v));
        (lo, hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_guesses_and_bounds() {
        let p = FreeParam::parse("R=8:1:20").unwrap();
        assert_eq!(
            (p.name.as_str(), p.guess, p.lower, p.upper),
            ("r", 8.0, Some(1.0), Some(20.0))
        );
        let p = FreeParam::parse("dut.u_motor.j=1e-6").unwrap();
        assert_eq!((p.guess, p.lower, p.upper), (1e-6, None, None));
        let p = FreeParam::parse("v_off=-0.1::0.5").unwrap();
        assert_eq!((p.lower, p.upper), (None, Some(0.5)));
        for bad in [
            "r",
            "=3",
            "r=x",
            "r=1:2",
            "r=5:6:7",
            "r=1:3:2",
            "r=nan",
            "r=1:2:3:4",
        ] {
            assert!(FreeParam::parse(bad).is_err(), "{bad} was accepted");
        }
    }

    #[test]
    fn positive_parameters_move_in_log_space() {
        let p = FreeParam::parse("l=3e-3:1e-4:1").unwrap();
        assert_eq!(p.scale(), Scale::Log);
        assert!((p.from_x(p.to_x(3e-3)) - 3e-3).abs() < 1e-15);
        let (lo, hi) = p.x_bounds();
        assert!((lo - 1e-4f64.ln()).abs() < 1e-12 && hi.abs() < 1e-12);
        let q = FreeParam::parse("offset=-0.2").unwrap();
        assert_eq!(q.scale(), Scale::Linear { unit: 0.2 });
        let z = FreeParam::parse("offset=0:-1:1").unwrap();
        assert_eq!(z.scale(), Scale::Linear { unit: 0.2 });
        assert_eq!(
            FreeParam::parse("a=1:0:2").unwrap().scale(),
            Scale::Linear { unit: 1.0 }
        );
    }
}
