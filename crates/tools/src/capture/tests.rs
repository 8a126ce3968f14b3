use super::*;
use proptest::prelude::*;

fn sample(name: &str) -> Capture {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/captures")
        .join(name);
    match read(&path, &ReadOptions::default()) {
        Ok(c) => c,
        Err(e) => panic!("{name}: {:?}", miette::Report::new(e)),
    }
}

fn names(c: &Capture) -> Vec<&str> {
    c.channels.iter().map(|c| c.name.as_str()).collect()
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

fn render(e: &dyn miette::Diagnostic) -> String {
    let mut out = String::new();
    let handler =
        miette::GraphicalReportHandler::new_themed(miette::GraphicalTheme::unicode_nocolor())
            .with_width(100);
    handler.render_report(&mut out, e).unwrap();
    out
}

fn parse_str(text: &str) -> Result<Capture, CaptureError> {
    parse(Path::new("scope.csv"), text, &ReadOptions::default())
}

fn rows(n: usize) -> String {
    (0..n)
        .map(|k| format!("{},{},{}\n", k as f64 * 1e-3, (k as f64 * 0.3).sin(), 0.25))
        .collect()
}

#[test]
fn generic_with_a_units_row() {
    let c = sample("generic_units_row.csv");
    assert_eq!(names(&c), ["voltage", "current"]);
    assert_eq!(c.len(), 100);
    assert!(close(c.time[3], 3e-4));
    let i = c.channel("Current").unwrap();
    assert_eq!(i.unit.as_deref(), Some("A"));
    // Written in mA: 0.8 A at the start.
    assert!((i.values[0] - 0.8).abs() < 0.05, "{}", i.values[0]);
    assert!(c.warnings.is_empty(), "{:?}", c.warnings);
}

#[test]
fn generic_with_units_in_the_header() {
    let c = sample("generic_header_units.csv");
    assert_eq!(names(&c), ["vout", "iout"]);
    assert!(close(c.time[2], 5e-6));
    assert!((c.channel("VOUT").unwrap().values[99] - 5.0).abs() < 0.6);
    assert!((c.channel("iout (uA)").unwrap().values[0] - 0.8).abs() < 0.05);
    assert_eq!(c.header.names[0], "time (µs)");
}

#[test]
fn rigol_sample_index_start_and_increment() {
    let c = sample("rigol_ds1054z.csv");
    assert_eq!(names(&c), ["CH1", "CH2"]);
    assert!(close(c.time[0], -6e-3));
    assert!(close(c.time[10], -6e-3 + 10.0 * 2e-6));
    assert_eq!(c.channel("ch2").unwrap().unit.as_deref(), Some("V"));
}

#[test]
fn tektronix_tds_metadata_columns() {
    let c = sample("tektronix_tds2012.csv");
    assert_eq!(names(&c), ["CH2"]);
    assert_eq!(c.len(), 100);
    assert!(close(c.time[0], -2e-5));
    assert!(close(c.time[99], -2e-5 + 99.0 * 4e-7));
    assert_eq!(c.channels[0].unit.as_deref(), Some("V"));
}

#[test]
fn tektronix_mso_metadata_lines() {
    let c = sample("tektronix_mso44.csv");
    assert_eq!(names(&c), ["CH1", "CH2"]);
    assert_eq!(c.channel("ch2").unwrap().unit.as_deref(), Some("A"));
    assert!(close(c.time[1] - c.time[0], 4e-7));
}

#[test]
fn keysight_numbered_channels() {
    let c = sample("keysight_dsox2024a.csv");
    assert_eq!(names(&c), ["1", "2"]);
    assert!(c.channel("CH1").is_some() && c.channel("2").is_some());
    assert!(close(c.time[0], -1e-3));
}

#[test]
fn picoscope_units_row_bom_and_infinities() {
    let c = sample("picoscope_6.csv");
    assert_eq!(names(&c), ["Channel A", "Channel B"]);
    assert!(close(c.time[1] - c.time[0], 1e-5));
    let b = c.channel("channel b").unwrap();
    assert!(b.values.iter().all(|v| v.is_finite()));
    let clipped: Vec<usize> = (0..b.clipped.len()).filter(|&k| b.clipped[k]).collect();
    assert_eq!(clipped, [30, 31, 32, 33, 34, 35, 70]);
    let hi = (0..100)
        .filter(|k| !b.clipped[*k])
        .map(|k| b.values[k])
        .fold(f64::MIN, f64::max);
    assert_eq!(b.values[30], hi);
    assert_eq!(c.warnings.len(), 1);
    let w = c.warnings[0].to_string();
    assert!(w.contains("7 samples of `Channel B`"), "{w}");
    // mV to V.
    assert!(b.values[0].abs() < 1.0);
}

#[test]
fn european_semicolons_quotes_crlf_and_trailing_blank_lines() {
    let c = sample("european_semicolon.csv");
    assert_eq!(names(&c), ["Spannung", "Strom"]);
    assert_eq!(c.len(), 100);
    assert!(close(c.time[7], 7e-4));
    assert!((c.channel("strom").unwrap().values[0] - 0.8).abs() < 0.05);
}

#[test]
fn picoscope_tab_separated_with_decimal_commas() {
    let c = sample("picoscope_tab_comma.txt");
    assert_eq!(names(&c), ["Channel A"]);
    assert!(close(c.time[0], -500e-6));
    assert!(close(c.time[1] - c.time[0], 2e-6));
}

#[test]
fn clipping_is_marked_and_warned() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/captures/clipped_sine.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let c = parse(
        Path::new("clipped_sine.csv"),
        &text,
        &ReadOptions::default(),
    )
    .unwrap();
    let vin = c.channel("vin").unwrap();
    // The sine is cut at 2.9 V near its two crests.
    let at_rail: Vec<bool> = vin.values.iter().map(|v| *v == 2.9).collect();
    assert_eq!(vin.clipped, at_rail);
    assert_eq!(vin.clipped.iter().filter(|c| **c).count(), 9);
    assert!(!c.channel("vout").unwrap().clipped.iter().any(|c| *c));
    assert_eq!(c.warnings.len(), 1);
    insta::assert_snapshot!(render(&c.warnings[0]));
    // Off: only infinities count.
    let opts = ReadOptions {
        detect_clipping: false,
        ..ReadOptions::default()
    };
    let c = parse(&c.path, &text, &opts).unwrap();
    assert!(c.warnings.is_empty());
}

#[test]
fn a_channel_clipped_everywhere_is_an_error() {
    let text = format!(
        "time,v,i\n{}",
        (0..40)
            .map(|k| format!("{k},{},1\n", if k < 2 { 0.5 } else { 4.0 }))
            .collect::<String>()
    );
    let e = parse_str(&text).unwrap_err();
    assert!(
        matches!(&e, CaptureError::AllClipped { channel, clipped: 38, .. } if channel == "v"),
        "{e:?}"
    );
    insta::assert_snapshot!(render(&e));
}

#[test]
fn scales_multiply_a_channel() {
    let opts = ReadOptions {
        scales: vec![("current".into(), 10.0), ("TIME".into(), 1e-3)],
        ..ReadOptions::default()
    };
    let text = format!("time,voltage,current\n{}", rows(40));
    let c = parse(Path::new("a.csv"), &text, &opts).unwrap();
    assert_eq!(c.channel("current").unwrap().values[0], 2.5);
    assert!(close(c.time[1], 1e-6));
    let opts = ReadOptions {
        scales: vec![("curent".into(), 10.0)],
        ..ReadOptions::default()
    };
    let e = parse(Path::new("a.csv"), &text, &opts).unwrap_err();
    assert!(
        matches!(&e, CaptureError::UnknownScale { suggestion: Some(s), .. } if s == "current"),
        "{e:?}"
    );
}

#[test]
fn missing_channel_lists_the_channels_and_suggests() {
    let c = sample("keysight_dsox2024a.csv");
    let e = c.channel_or_error("ch3").unwrap_err();
    let text = render(&e) + &e.to_string();
    assert!(text.contains("vams::capture::missing_channel"), "{text}");
    assert!(text.contains("it has: 1, 2"), "{text}");
    assert!(!text.contains("did you mean"), "{text}");
    assert!(text.contains("keysight_dsox2024a.csv"), "{text}");
    let c = sample("generic_units_row.csv");
    let e = c.channel_or_error("volatge").unwrap_err();
    assert!(render(&e).contains("did you mean `voltage`?"));
}

#[test]
fn a_missing_time_column_points_at_the_header() {
    let opts = ReadOptions {
        time_column: Some("t".into()),
        ..ReadOptions::default()
    };
    let text = format!("Model,X\nseconds,voltage,current\n{}", rows(40));
    let e = parse(Path::new("scope.csv"), &text, &opts).unwrap_err();
    insta::assert_snapshot!(render(&e));
}

#[test]
fn required_channels_are_checked_before_the_samples() {
    let opts = ReadOptions {
        required: vec!["vout".into()],
        ..ReadOptions::default()
    };
    // Too few samples, but the missing channel is what is said.
    let text = format!("time,vin,vot\n{}", rows(5));
    let e = parse(Path::new("step.csv"), &text, &opts).unwrap_err();
    let CaptureError::MissingChannel(m) = &e else {
        panic!("{e:?}")
    };
    assert_eq!(m.suggestion.as_deref(), Some("vot"));
    assert_eq!(m.span.map(|s| (s.offset(), s.len())), Some((0, 12)));
}

#[test]
fn bad_rows_point_at_the_field() {
    let text = format!("time,voltage,current\n{}0.5,1.2,abc\n{}", rows(40), rows(0));
    let e = parse_str(&text).unwrap_err();
    insta::assert_snapshot!(render(&e));
    let CaptureError::BadRow(b) = e else {
        panic!("{e:?}")
    };
    assert_eq!(b.line, 42);
    assert_eq!(text[b.span.offset()..][..b.span.len()].to_string(), "abc");
}

#[test]
fn time_must_increase() {
    let mut text = format!("time,voltage,current\n{}", rows(40));
    text.push_str("0.01,1,1\n");
    let e = parse_str(&text).unwrap_err();
    insta::assert_snapshot!(render(&e));
    assert!(matches!(e, CaptureError::TimeNotIncreasing(ref n) if n.line == 42));
}

#[test]
fn empty_no_data_and_too_few_samples() {
    assert!(matches!(parse_str(""), Err(CaptureError::Empty { .. })));
    assert!(matches!(
        parse_str("\r\n , \n"),
        Err(CaptureError::Empty { .. })
    ));
    assert!(matches!(
        parse_str("Model,DS1054Z\nSerial,123\n"),
        Err(CaptureError::NoData {
            has_header: false,
            ..
        })
    ));
    assert!(matches!(
        parse_str("Time,CH1\ns,V\n"),
        Err(CaptureError::NoData {
            has_header: true,
            ..
        })
    ));
    let e = parse_str(&format!("time,voltage,current\n{}", rows(10))).unwrap_err();
    assert!(matches!(
        e,
        CaptureError::TooFewSamples {
            rows: 10,
            min: 32,
            ..
        }
    ));
    let e = read(Path::new("/nonexistent/scope.csv"), &ReadOptions::default()).unwrap_err();
    assert!(render(&e).contains("/nonexistent/scope.csv"));
}

#[test]
fn trigger_shift_window_and_decimate() {
    let text = format!("time,voltage,current\n{}", rows(100));
    let c = parse_str(&text).unwrap();
    // sin(0.3 k) crosses 0.5 upwards between k = 1 and 2.
    let t = c.trigger_time("voltage", 0.5, true).unwrap();
    let (a, b) = (0.3f64.sin(), 0.6f64.sin());
    assert!(close(t, 1e-3 + (0.5 - a) / (b - a) * 1e-3), "{t}");
    let down = c.trigger_time("voltage", 0.0, false).unwrap();
    assert!(down > 10e-3 && down < 10.6e-3, "{down}");
    assert!(c.trigger_time("voltage", 5.0, true).is_none());
    assert!(c.trigger_time("nope", 0.0, true).is_none());

    let s = c.shifted(-t);
    assert!(close(s.time[0], -t));
    let w = c.window(10e-3, 20e-3);
    assert_eq!(w.len(), 11);
    assert!(close(w.time[0], 10e-3));
    assert_eq!(w.channels[0].values.len(), 11);
    assert!(c.window(1.0, 2.0).is_empty());

    let mut c2 = c.clone();
    c2.channels[1].clipped[5] = true;
    let d = c2.decimated(30);
    // 100 samples in blocks of 4: 25 points.
    assert_eq!(d.len(), 25);
    assert!(close(d.time[0], 1.5e-3));
    assert!(d.channels[1].clipped[1] && !d.channels[1].clipped[0]);
    assert_eq!(d.channels[1].values[3], 0.25);
    assert_eq!(c.decimated(1000).len(), 100);
}

#[test]
fn large_captures_parse_fast() {
    let n = 100_000;
    let mut text = String::from("Time,Channel A,Channel B\n(ms),(V),(mV)\n\n");
    for k in 0..n {
        use std::fmt::Write as _;
        let t = k as f64 * 1e-4;
        let _ = writeln!(text, "{t:.8},{:.8},{:.6}", (t * 7.0).sin(), (t * 3.0).cos());
    }
    let start = std::time::Instant::now();
    let c = parse_str(&text).unwrap();
    let elapsed = start.elapsed();
    eprintln!(
        "parsed {n} rows ({} bytes) in {:.1} ms",
        text.len(),
        elapsed.as_secs_f64() * 1e3
    );
    assert_eq!(c.len(), n);
    assert!(elapsed.as_secs_f64() < 2.0);
}

#[test]
fn scale_arguments() {
    assert_eq!(parse_scale("current=0.1"), Ok(("current".into(), 0.1)));
    assert_eq!(
        parse_scale(" Channel A = 10 "),
        Ok(("Channel A".into(), 10.0))
    );
    for bad in ["current", "=2", "current=0", "current=x", "current=inf"] {
        assert!(parse_scale(bad).is_err(), "{bad}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]
    /// Whatever the text, parsing gives a capture or a diagnostic, never a panic, and a
    /// capture holds only finite values on an increasing time base.
    #[test]
    fn never_panics_on_arbitrary_text(text in "(([a-zA-Z0-9.;,\t \"∞µ()\\[\\]+-]{0,24})(\r?\n)){0,70}") {
        if let Ok(c) = parse_str(&text) {
            prop_assert!(c.time.windows(2).all(|w| w[0] < w[1]));
            for ch in &c.channels {
                prop_assert!(ch.values.iter().all(|v| v.is_finite()));
                prop_assert_eq!(ch.values.len(), c.time.len());
            }
            let _ = c.decimated(7);
        }
    }

    /// Text after the opening lines of each layout never panics either.
    #[test]
    fn never_panics_after_a_layout_header(
        head in prop::sample::select(vec![
            "Record Length,2500,,-0.0005,0.02\n",
            "X,CH1,CH2,Start,Increment,\nSequence,Volt,Volt,-6e-03,2e-06,\n",
            "x-axis,1,2\nsecond,Volt,Volt\n",
            "Time,Channel A\n(ms),(V)\n\n",
            "\u{feff}\"Zeit\";\"U\"\r\n\"s\";\"V\"\r\n",
        ]),
        body in "(([0-9.;,\t ∞e+-]{0,16})(\r?\n)){0,60}",
    ) {
        let text = format!("{head}{body}");
        if let Ok(c) = parse_str(&text) {
            prop_assert!(c.time.windows(2).all(|w| w[0] < w[1]));
            prop_assert!(c.channels.iter().all(|ch| ch.values.iter().all(|v| v.is_finite())));
        }
    }

    /// Numeric rows with a header always read, whatever the numbers.
    #[test]
    fn numeric_rows_read(values in proptest::collection::vec(-1e6f64..1e6, 32..120)) {
        let text: String = std::iter::once("time,a,b\n".to_string())
            .chain(values.iter().enumerate().map(|(k, v)| format!("{k},{v},{}\n", -v)))
            .collect();
        let opts = ReadOptions { detect_clipping: false, ..ReadOptions::default() };
        let c = parse(Path::new("p.csv"), &text, &opts).unwrap();
        prop_assert_eq!(c.len(), values.len());
        prop_assert_eq!(&c.channels[0].values, &values);
    }
}
