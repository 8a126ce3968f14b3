//! The value of an independent source as an analog expression of time.
//!
//! Takes a source's numbers and the circuit's `.tran`; gives an [`Expr`] of [`Expr::Now`],
//! with ngspice's semantics (checked against ngspice 39's `vsrcload.c` and `ngspice -b`):
//! a transient function when the source has one and the circuit a `.tran`, else the DC value
//! (without a `.tran`: the function's value at time 0, as ngspice's operating point takes it).
//! Every corner of a waveform is the corner of a table of `now` (`vams.tables.pwl`), so the
//! integrator's step control lands on it: PULSE becomes the table of its periods up to TSTOP,
//! and the delays of SIN and EXP are ramps `max(now - td, 0)` written as tables.
//!
//! Defaults for missing (or zero) arguments, as ngspice's: PULSE `td` 0, `tr` and `tf`
//! TSTEP, `pw` and `per` TSTOP; SIN `freq` 1/TSTOP, `td` 0, `theta` 0, `phase` 0 (degrees);
//! EXP `td1` TSTEP, `tau1` TSTEP, `td2` `td1` + TSTEP, `tau2` TSTEP.

use vams_design::{Builtin, Expr, Value};

use super::{TranSpec, add, mul, sub};
use crate::circuit::FlatElement;
use crate::deck::{Source, Waveform};
use crate::error::SpiceError;

/// The most points a PULSE's table may have (a fast pulse over a long run is refused rather
/// than a table of millions of points built).
const MAX_POINTS: usize = 1_000_000;

/// The source's value (see the module doc).
pub(super) fn value(
    src: &Source<f64>,
    tran: Option<&TranSpec>,
    el: &FlatElement,
) -> Result<Expr, SpiceError> {
    match (&src.tran, tran) {
        (Some(w), Some(t)) => waveform(w, t, el),
        (Some(w), None) => Ok(Expr::real(src.dc.unwrap_or_else(|| at_zero(w)))),
        (None, _) => Ok(Expr::real(src.dc.unwrap_or(0.0))),
    }
}

/// A function's value at time 0, as ngspice's operating point without `.tran` takes it.
fn at_zero(w: &Waveform<f64>) -> f64 {
    match w {
        Waveform::Pulse { v1, .. } | Waveform::Exp { v1, .. } => *v1,
        Waveform::Sin { vo, va, phase, .. } => vo + va * phase.unwrap_or(0.0).to_radians().sin(),
        Waveform::Pwl { points, .. } => points.first().map_or(0.0, |p| p.1),
    }
}

/// An optional argument, with ngspice's default also for an explicit 0.
fn or_default(x: Option<f64>, default: f64) -> f64 {
    match x {
        Some(v) if v != 0.0 => v,
        _ => default,
    }
}

fn table(flat: Vec<f64>) -> Expr {
    Expr::Call(
        Builtin::Pwl,
        vec![
            Expr::Const(Value::Array(flat.into_iter().map(Value::Real).collect())),
            Expr::Now,
        ],
    )
}

/// `max(now - t0, 0)`: `now - t0` from `t0` on (as a table of `now` when `t0 > 0`, so the
/// corner is a breakpoint).
fn ramp(t0: f64, tstop: f64) -> Expr {
    if t0 <= 0.0 {
        return sub(Expr::Now, Expr::real(t0));
    }
    // Far past any run of this circuit; the table is constant beyond its last point.
    let end = t0 + 1e3 * tstop + 1.0;
    table(vec![t0, 0.0, end, end - t0])
}

fn waveform(w: &Waveform<f64>, t: &TranSpec, el: &FlatElement) -> Result<Expr, SpiceError> {
    let c = Expr::real;
    match *w {
        Waveform::Pulse {
            v1,
            v2,
            td,
            tr,
            tf,
            pw,
            per,
            np,
        } => {
            let td = td.unwrap_or(0.0);
            let tr = or_default(tr, t.tstep);
            let tf = or_default(tf, t.tstep);
            let pw = or_default(pw, t.tstop);
            let per = or_default(per, t.tstop);
            let mut flat = vec![td, v1];
            let mut k = 0u64;
            loop {
                let start = td + k as f64 * per;
                if start > t.tstop || np.is_some_and(|n| k as f64 >= n) {
                    break;
                }
                for (x, y) in [
                    (start, v1),
                    (start + tr, v2),
                    (start + tr + pw, v2),
                    (start + tr + pw + tf, v1),
                ] {
                    // Overlapping edges (tr + pw + tf > per) keep the earlier ones.
                    if flat.len() >= 2 && x <= flat[flat.len() - 2] {
                        continue;
                    }
                    flat.push(x);
                    flat.push(y);
                }
                if flat.len() / 2 > MAX_POINTS {
                    return Err(SpiceError::NotSupported {
                        span: el.span,
                        what: format!("a PULSE of more than {MAX_POINTS} corners"),
                        label: format!("`{}` repeats too often for its `.tran`", el.name),
                        help: "lengthen the period or shorten the `.tran` stop time".into(),
                    });
                }
                k += 1;
            }
            Ok(table(flat))
        }
        Waveform::Sin {
            vo,
            va,
            freq,
            td,
            theta,
            phase,
        } => {
            let freq = or_default(freq, 1.0 / t.tstop);
            let tau = ramp(td.unwrap_or(0.0), t.tstop);
            let phase = phase.unwrap_or(0.0).to_radians();
            let arg = add(
                mul(c(2.0 * std::f64::consts::PI * freq), tau.clone()),
                c(phase),
            );
            let mut wave = Expr::Call(Builtin::Sin, vec![arg]);
            let theta = theta.unwrap_or(0.0);
            if theta != 0.0 {
                wave = mul(wave, Expr::Call(Builtin::Exp, vec![mul(c(-theta), tau)]));
            }
            Ok(add(c(vo), mul(c(va), wave)))
        }
        Waveform::Exp {
            v1,
            v2,
            td1,
            tau1,
            td2,
            tau2,
        } => {
            let td1 = or_default(td1, t.tstep);
            let tau1 = or_default(tau1, t.tstep);
            let td2 = or_default(td2, td1 + t.tstep);
            let tau2 = or_default(tau2, t.tstep);
            // 1 - exp(-max(now - td, 0) / tau)
            let rise = |td: f64, tau: f64| {
                sub(
                    c(1.0),
                    Expr::Call(Builtin::Exp, vec![mul(c(-1.0 / tau), ramp(td, t.tstop))]),
                )
            };
            Ok(add(
                add(c(v1), mul(c(v2 - v1), rise(td1, tau1))),
                mul(c(v1 - v2), rise(td2, tau2)),
            ))
        }
        Waveform::Pwl {
            ref points,
            repeat,
            delay,
        } => {
            if repeat.is_some() {
                return Err(SpiceError::NotSupported {
                    span: el.span,
                    what: "a repeating PWL (`r=`)".into(),
                    label: format!("`{}` repeats its table", el.name),
                    help: "write the periods out in the table and remove `r=`".into(),
                });
            }
            let delay = delay.unwrap_or(0.0);
            let flat: Vec<f64> = points.iter().flat_map(|&(x, y)| [x + delay, y]).collect();
            match vams_design::pwl::Table::new(&flat) {
                Ok(_) => Ok(table(flat)),
                Err(e) => Err(SpiceError::syntax(
                    el.span,
                    format!("the PWL of `{}` is no table: {e}", el.name),
                    "not a table",
                    "write the PWL as time, value pairs with times increasing: `pwl(0 0 1u 5 2u 5)`; a jump is a steep segment",
                )),
            }
        }
    }
}
