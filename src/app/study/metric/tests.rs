//! Metrics on small waveforms with hand-computed values, written in the spec's own syntax.

use super::spec::parse_metrics;
use super::*;
use crate::design::Type;
use crate::kernel::Report;
use crate::source::Span;
use crate::waveform::Column;

/// The single metric of `[metrics]` with `m = { table }`.
fn metric(table: &str) -> Metric {
    let text = format!("[metrics]\nm = {table}\n");
    let mut all = parse_metrics(&text).unwrap_or_else(|e| panic!("{table}: {e:?}"));
    assert_eq!(all.len(), 1);
    all.remove(0)
}

/// The error of `m = { table }`, and the text its span covers.
fn spec_error(table: &str) -> (MetricSpecError, String) {
    let text = format!("[metrics]\nm = {table}\n");
    let mut errors = parse_metrics(&text).expect_err(table);
    let e = errors.remove(0);
    let covered = text[e.span.clone()].to_string();
    (e, covered)
}

fn quantity(name: &str, values: Vec<f64>) -> Column {
    Column {
        name: name.into(),
        kind: ColumnKind::Quantity {
            unit: Some("V".into()),
        },
        values,
    }
}

fn signal(name: &str, values: Vec<f64>) -> Column {
    Column {
        name: name.into(),
        kind: ColumnKind::Signal { ty: Type::Integer },
        values,
    }
}

fn waves(times: Vec<f64>, columns: Vec<Column>) -> Waveforms {
    Waveforms { times, columns }
}

/// `f` sampled every `dt` on `[0, stop]` as quantity `v`.
fn sampled(stop: f64, dt: f64, f: impl Fn(f64) -> f64) -> Waveforms {
    let n = (stop / dt).round() as usize;
    let times: Vec<f64> = (0..=n).map(|k| k as f64 * dt).collect();
    let values = times.iter().map(|&t| f(t)).collect();
    waves(times, vec![quantity("v", values)])
}

fn eval(table: &str, w: &Waveforms) -> Result<f64, MetricError> {
    metric(table).evaluate(w, &[])
}

fn value(table: &str, w: &Waveforms) -> f64 {
    eval(table, w).unwrap_or_else(|e| panic!("{table}: {e}"))
}

fn close(got: f64, want: f64, tol: f64) {
    assert!((got - want).abs() <= tol, "got {got}, want {want} ± {tol}");
}

/// v = t on 0..10 s, one sample a second.
fn ramp() -> Waveforms {
    sampled(10.0, 1.0, |t| t)
}

#[test]
fn statistics_of_a_ramp_interpolate_the_window_edges() {
    let w = ramp();
    close(
        value(
            r#"{ kind = "max", of = "v", from = "2.5 s", to = 7.5 }"#,
            &w,
        ),
        7.5,
        1e-12,
    );
    close(
        value(r#"{ kind = "min", of = "v", from = 2.5, to = "7.5s" }"#, &w),
        2.5,
        1e-12,
    );
    close(
        value(r#"{ kind = "mean", of = "v", from = 2.5, to = 7.5 }"#, &w),
        5.0,
        1e-12,
    );
    close(
        value(
            r#"{ kind = "peak_to_peak", of = "v", from = 2.5, to = 7.5 }"#,
            &w,
        ),
        5.0,
        1e-12,
    );
    // RMS of t over [0, 3]: sqrt(∫t² dt / 3) = sqrt(3), exact on linear pieces.
    close(
        value(r#"{ kind = "rms", of = "v", to = "3 s" }"#, &w),
        3f64.sqrt(),
        1e-12,
    );
    close(value(r#"{ kind = "final", of = "v" }"#, &w), 10.0, 0.0);
    close(
        value(r#"{ kind = "at", of = "v", time = "2.9 s" }"#, &w),
        2.9,
        1e-12,
    );
    let centred = sampled(10.0, 1.0, |t| t - 7.0);
    close(
        value(r#"{ kind = "max_abs", of = "v" }"#, &centred),
        7.0,
        0.0,
    );
    close(
        value(r#"{ kind = "max_abs", of = "v", from = 5 }"#, &centred),
        3.0,
        0.0,
    );
}

#[test]
fn the_mean_weighs_time_not_samples() {
    // Zero for 9 s, then a ramp to 10 in the last second: the mean is 0.5, not 10/3.
    let w = waves(
        vec![0.0, 9.0, 10.0],
        vec![quantity("v", vec![0.0, 0.0, 10.0])],
    );
    close(value(r#"{ kind = "mean", of = "v" }"#, &w), 0.5, 1e-12);
}

#[test]
fn a_sine_has_rms_amplitude_over_root_two_and_mean_zero() {
    let w = sampled(3.0, 1e-3, |t| 2.0 * (std::f64::consts::TAU * t).sin());
    let rms = value(
        r#"{ kind = "rms", of = "v", from = 0.25, to = "2.25 s" }"#,
        &w,
    );
    close(rms, 2.0 / 2f64.sqrt(), 1e-5);
    close(
        value(r#"{ kind = "mean", of = "v", from = 0.1, to = 2.1 }"#, &w),
        0.0,
        1e-6,
    );
    close(value(r#"{ kind = "max", of = "v" }"#, &w), 2.0, 1e-5);
}

#[test]
fn crossings_are_interpolated_and_counted_by_edge() {
    let w = waves(
        vec![0.0, 1.0, 2.0, 3.0],
        vec![quantity("v", vec![0.0, 2.0, 0.0, 2.0])],
    );
    let cross = |rest: &str| {
        value(
            &format!(r#"{{ kind = "cross", of = "v", value = 1, {rest} }}"#),
            &w,
        )
    };
    close(cross(r#"edge = "rising""#), 0.5, 1e-12);
    close(cross(r#"edge = "falling""#), 1.5, 1e-12);
    close(cross(r#"edge = "rising", nth = 2"#), 2.5, 1e-12);
    close(cross(r#"edge = "either", nth = 3"#), 2.5, 1e-12);
    close(cross("nth = 2"), 1.5, 1e-12);
    close(cross(r#"from = "1 s""#), 1.5, 1e-12);
    let err = eval(
        r#"{ kind = "cross", of = "v", value = 1, edge = "rising", nth = 3 }"#,
        &w,
    );
    assert!(
        matches!(
            err,
            Err(MetricError::NoCrossing {
                found: 2,
                nth: 3,
                ..
            })
        ),
        "{err:?}"
    );
    // A sine of amplitude 2 crosses 1 rising at 1/12 + k and falling at 5/12 + k.
    let s = sampled(3.0, 1e-3, |t| 2.0 * (std::f64::consts::TAU * t).sin());
    let at = |rest: &str| {
        value(
            &format!(r#"{{ kind = "cross", of = "v", value = 1.0, {rest} }}"#),
            &s,
        )
    };
    close(at(r#"edge = "rising", nth = 2"#), 13.0 / 12.0, 1e-5);
    close(at(r#"edge = "falling""#), 5.0 / 12.0, 1e-5);
    close(at("nth = 3"), 13.0 / 12.0, 1e-5);
}

#[test]
fn touching_the_level_is_no_crossing_and_resting_on_it_counts_once() {
    let touch = waves(
        vec![0.0, 1.0, 2.0],
        vec![quantity("v", vec![0.0, 1.0, 0.0])],
    );
    assert!(eval(r#"{ kind = "cross", of = "v", value = 1 }"#, &touch).is_err());
    let rest = waves(
        vec![0.0, 1.0, 2.0, 3.0],
        vec![quantity("v", vec![0.0, 1.0, 1.0, 2.0])],
    );
    close(
        value(r#"{ kind = "cross", of = "v", value = 1 }"#, &rest),
        1.0,
        0.0,
    );
    assert!(eval(r#"{ kind = "cross", of = "v", value = 1, nth = 2 }"#, &rest).is_err());
}

#[test]
fn equal_times_are_jumps_and_the_value_at_one_is_the_value_after() {
    let w = waves(
        vec![0.0, 1.0, 1.0, 2.0],
        vec![quantity("v", vec![0.0, 1.0, 3.0, 3.0])],
    );
    close(value(r#"{ kind = "mean", of = "v" }"#, &w), 1.75, 1e-12);
    close(value(r#"{ kind = "max", of = "v", to = 1 }"#, &w), 3.0, 0.0);
    close(
        value(r#"{ kind = "max", of = "v", to = 0.5 }"#, &w),
        0.5,
        1e-12,
    );
    close(
        value(r#"{ kind = "at", of = "v", time = 1 }"#, &w),
        3.0,
        0.0,
    );
    close(
        value(r#"{ kind = "cross", of = "v", value = 2 }"#, &w),
        1.0,
        0.0,
    );
}

#[test]
fn signals_hold_their_value_until_the_next_sample() {
    let w = waves(
        vec![0.0, 1.0, 2.0, 3.0],
        vec![signal("s", vec![0.0, 1.0, 1.0, 0.0])],
    );
    close(
        value(r#"{ kind = "mean", of = "s" }"#, &w),
        2.0 / 3.0,
        1e-12,
    );
    close(
        value(r#"{ kind = "rms", of = "s" }"#, &w),
        (2.0f64 / 3.0).sqrt(),
        1e-12,
    );
    close(
        value(r#"{ kind = "at", of = "s", time = 0.99 }"#, &w),
        0.0,
        0.0,
    );
    close(
        value(r#"{ kind = "at", of = "s", time = 2.5 }"#, &w),
        1.0,
        0.0,
    );
    let cross = r#"{ kind = "cross", of = "s", value = 0.5, edge = "falling" }"#;
    close(value(cross, &w), 3.0, 0.0);
    close(
        value(r#"{ kind = "cross", of = "s", value = 0.5 }"#, &w),
        1.0,
        0.0,
    );
    close(
        value(r#"{ kind = "max", of = "s", to = 0.5 }"#, &w),
        0.0,
        0.0,
    );
}

#[test]
fn a_first_order_step_settles_into_two_percent_after_tau_ln_50() {
    let tau = 0.5;
    let w = sampled(12.0, 1e-3, |t| 1.0 - (-t / tau).exp());
    let want = tau * 50f64.ln();
    close(
        value(r#"{ kind = "settling_time", of = "v", band = "2%" }"#, &w),
        want,
        1e-5,
    );
    let target = r#"{ kind = "settling_time", of = "v", band = 0.02, target = 1.0 }"#;
    close(value(target, &w), want, 1e-6);
    // Counted from `from`; zero when already in the band there.
    let later = r#"{ kind = "settling_time", of = "v", band = 0.02, target = 1.0, from = 1 }"#;
    close(value(later, &w), want - 1.0, 1e-6);
    close(
        value(
            r#"{ kind = "settling_time", of = "v", from = "5 s", band = 0.02 }"#,
            &w,
        ),
        0.0,
        0.0,
    );
    let never = r#"{ kind = "settling_time", of = "v", band = 0.1, target = 2 }"#;
    assert!(matches!(
        eval(never, &w),
        Err(MetricError::NeverSettles { .. })
    ));
    assert!(metric(never).check(1.0).is_none());
    let limited = metric(r#"{ kind = "settling_time", of = "v", band = "2%", max = "1.5 s" }"#);
    assert_eq!(limited.limit.max, Some(1.5));
    assert_eq!(
        limited.check(value(r#"{ kind = "settling_time", of = "v" }"#, &w)),
        Some(false)
    );
}

#[test]
fn overshoot_is_the_peak_beyond_the_final_value_in_percent_of_the_step() {
    let up = waves(
        vec![0.0, 1.0, 2.0, 3.0, 4.0, 10.0],
        vec![quantity("v", vec![0.0, 0.0, 1.2, 0.9, 1.0, 1.0])],
    );
    close(
        value(r#"{ kind = "overshoot", of = "v" }"#, &up),
        20.0,
        1e-9,
    );
    let down = waves(
        up.times.clone(),
        vec![quantity("v", vec![5.0, 5.0, 2.6, 3.2, 3.0, 3.0])],
    );
    close(
        value(r#"{ kind = "overshoot", of = "v", from = "1 s" }"#, &down),
        20.0,
        1e-9,
    );
    close(
        value(r#"{ kind = "overshoot", of = "v" }"#, &ramp()),
        0.0,
        0.0,
    );
    // Second order, ζ = 0.5, ωn = 1: 100 exp(-πζ/√(1-ζ²)) ≈ 16.303 %.
    let (z, wd) = (0.5f64, (0.75f64).sqrt());
    let w = sampled(40.0, 1e-3, |t| {
        1.0 - (-z * t).exp() * ((wd * t).cos() + z / wd * (wd * t).sin())
    });
    let want = 100.0 * (-std::f64::consts::PI * z / wd).exp();
    close(value(r#"{ kind = "overshoot", of = "v" }"#, &w), want, 1e-4);
    let flat = sampled(1.0, 0.1, |_| 2.0);
    let e = eval(r#"{ kind = "overshoot", of = "v" }"#, &flat);
    assert!(matches!(e, Err(MetricError::ZeroStep { .. })), "{e:?}");
    let e = eval(
        r#"{ kind = "settling_time", of = "v", band = "2%" }"#,
        &flat,
    );
    assert!(matches!(e, Err(MetricError::ZeroStep { .. })), "{e:?}");
    close(
        value(r#"{ kind = "settling_time", of = "v", band = 0.1 }"#, &flat),
        0.0,
        0.0,
    );
}

#[test]
fn assertion_failures_count_errors_and_failures() {
    let report = |severity| Report {
        time: 1.0,
        severity,
        message: "m".into(),
        process: "p".into(),
        span: Span::default(),
    };
    let reports = [
        report(Severity::Note),
        report(Severity::Warning),
        report(Severity::Error),
        report(Severity::Failure),
    ];
    let m = metric(r#"{ kind = "assertion_failures", max = 0 }"#);
    assert!(m.probes().is_empty());
    let n = m.evaluate(&Waveforms::default(), &reports).unwrap();
    assert_eq!((n, m.check(n)), (2.0, Some(false)));
    assert_eq!(m.check(0.0), Some(true));
}

#[test]
fn evaluation_errors_say_why() {
    let w = waves(
        vec![0.0, 1.0],
        vec![
            quantity("vout", vec![0.0, 1.0]),
            quantity("vfb", vec![0.0, 1.0]),
            quantity("err", vec![0.0, f64::NAN]),
        ],
    );
    match eval(r#"{ kind = "final", of = "vfbb" }"#, &w) {
        Err(MetricError::UnknownColumn { known, .. }) => {
            assert!(known.starts_with("vfb,"), "{known}")
        }
        other => panic!("{other:?}"),
    }
    let many = waves(
        vec![0.0],
        (0..20)
            .map(|k| quantity(&format!("n{k}"), vec![0.0]))
            .collect(),
    );
    match eval(r#"{ kind = "final", of = "n7x" }"#, &many) {
        Err(MetricError::UnknownColumn { known, .. }) => {
            assert!(
                known.starts_with("n7,") && known.ends_with(" and 12 more"),
                "{known}"
            )
        }
        other => panic!("{other:?}"),
    }
    let e = eval(r#"{ kind = "max", of = "vfb", to = "20 s" }"#, &w).unwrap_err();
    assert!(matches!(e, MetricError::OutsideRun { .. }));
    assert!(
        e.to_string().contains("20 s") && e.to_string().contains("1 s"),
        "{e}"
    );
    assert!(eval(r#"{ kind = "at", of = "vfb", time = 3 }"#, &w).is_err());
    // A time a rounding error past the end is the end.
    close(
        value(r#"{ kind = "at", of = "vfb", time = 1.0000000001 }"#, &w),
        1.0,
        0.0,
    );
    assert!(matches!(
        eval(r#"{ kind = "final", of = "err" }"#, &w),
        Err(MetricError::NotFinite { .. })
    ));
    let empty = waves(vec![], vec![quantity("v", vec![])]);
    assert!(matches!(
        eval(r#"{ kind = "final", of = "v" }"#, &empty),
        Err(MetricError::EmptyRun { .. })
    ));
}

#[test]
fn metrics_know_their_probes_units_and_limits() {
    let w = ramp();
    let m = metric(r#"{ kind = "final", of = "v", min = -0.01, max = 0.01 }"#);
    assert_eq!(m.probes(), vec!["v".to_string()]);
    assert_eq!(
        (m.check(0.0), m.check(0.02), m.check(-0.01)),
        (Some(true), Some(false), Some(true))
    );
    assert_eq!(m.unit_hint(&w).as_deref(), Some("V"));
    let cross = metric(r#"{ kind = "cross", of = "v", value = 2, max = "3 ms" }"#);
    assert_eq!(cross.limit.max, Some(3e-3));
    assert_eq!(cross.unit_hint(&w).as_deref(), Some("s"));
    assert_eq!(
        metric(r#"{ kind = "overshoot", of = "v" }"#)
            .unit_hint(&w)
            .as_deref(),
        Some("%")
    );
}

#[test]
fn the_whole_example_of_the_spec_parses_in_order() {
    let text = r#"
[metrics]
settle    = { kind = "settling_time", of = "vfb", from = "3 s", band = "2%", max = "1.5 s" }
i_peak    = { kind = "max", of = "dut.i_motor", from = "0 s", to = "6 s", max = 2.0 }
i_abs     = { kind = "max_abs", of = "dut.i_motor" }
err_final = { kind = "final", of = "err", min = -0.01, max = 0.01 }
v_at      = { kind = "at", of = "vfb", time = "2.9 s" }
v_mean    = { kind = "mean", of = "vfb", from = "4 s", to = "6 s" }
rise      = { kind = "cross", of = "vfb", value = 2.5, edge = "rising", nth = 1 }
over      = { kind = "overshoot", of = "vfb", from = "3 s" }
fails     = { kind = "assertion_failures", max = 0 }
"#;
    let metrics = parse_metrics(text).unwrap();
    let names: Vec<&str> = metrics.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "settle",
            "i_peak",
            "i_abs",
            "err_final",
            "v_at",
            "v_mean",
            "rise",
            "over",
            "fails"
        ]
    );
    assert_eq!(
        metrics[0].kind,
        MetricKind::SettlingTime {
            of: "vfb".into(),
            from: Some(3.0),
            band: Band::Percent(2.0),
            target: None
        }
    );
    assert_eq!(
        metrics[1].limit,
        Limit {
            min: None,
            max: Some(2.0)
        }
    );
}

#[test]
fn spec_errors_point_at_the_value_at_fault() {
    let cases = [
        (
            r#"{ kind = "max", of = "v", from = "5 s", to = "2 s" }"#,
            "\"5 s\"",
            "not before",
        ),
        (
            r#"{ kind = "cross", of = "v", value = 1, nth = 0 }"#,
            "0",
            "counts no crossing",
        ),
        (r#"{ kind = "maxx", of = "v" }"#, "\"maxx\"", "unknown kind"),
        (
            r#"{ kind = "cross", of = "v", value = 1, edge = "up" }"#,
            "\"up\"",
            "unknown edge",
        ),
        (
            r#"{ kind = "settling_time", of = "v", band = -0.1 }"#,
            "-0.1",
            "negative",
        ),
        (
            r#"{ kind = "settling_time", of = "v", band = "two%" }"#,
            "\"two%\"",
            "percentage",
        ),
        (
            r#"{ kind = "final", of = "v", min = 2, max = 1 }"#,
            "2",
            "limits are empty",
        ),
        (
            r#"{ kind = "max", of = "v", band = 1 }"#,
            "1",
            "does not apply",
        ),
        (
            r#"{ kind = "final", of = "v", max = "1 s" }"#,
            "\"1 s\"",
            "not a time",
        ),
        (
            r#"{ kind = "max", of = "v", from = "3 parsecs" }"#,
            "\"3 parsecs\"",
            "not a time",
        ),
        (
            r#"{ kind = "max", of = "v", to = -1 }"#,
            "-1",
            "not negative",
        ),
        (
            r#"{ kind = "cross", of = "v", value = nan }"#,
            "nan",
            "finite",
        ),
        (
            r#"{ kind = "at", of = "v" }"#,
            r#"{ kind = "at", of = "v" }"#,
            "needs `time`",
        ),
        (r#"{ kind = "mean" }"#, r#"{ kind = "mean" }"#, "needs `of`"),
        (
            r#"{ kind = "assertion_failures", of = "v" }"#,
            "\"v\"",
            "does not apply",
        ),
    ];
    for (table, covered, says) in cases {
        let (e, got) = spec_error(table);
        assert_eq!(got, covered, "{table}: {e:?}");
        assert!(e.message.contains(says), "{table}: {}", e.message);
        assert!(!e.help.is_empty(), "{table}");
        assert!(e.to_string().starts_with("metric `m`"), "{e}");
    }
    let (e, _) = spec_error(r#"{ kind = "maxx", of = "v" }"#);
    assert!(e.help.starts_with("the kinds are max,"), "{}", e.help);
    // Unknown keys are refused by serde, with toml's span on the key.
    let (e, covered) = spec_error(r#"{ kind = "max", of = "v", form = 1 }"#);
    assert!(
        e.message.contains("form") && covered.contains("form"),
        "{e:?} {covered}"
    );
}

#[test]
fn spec_errors_render_as_diagnostics_at_their_value() {
    let text = "[metrics]\nrise = { kind = \"cross\", of = \"v\", value = 1, nth = 0 }\n";
    let e = parse_metrics(text).unwrap_err().remove(0);
    let report = miette::Report::new(e).with_source_code(text.to_string());
    let shown = crate::app::render::render(report.as_ref());
    for want in ["metric `rise`", "nth = 0", "here", "counted from 1"] {
        assert!(shown.contains(want), "{want}: {shown}");
    }
}
