//! `vams run` writes its files as the run goes (issue 23): the streamed CSV and VCD are what
//! the in-memory waveforms give, a partial run's files end where the run says it stopped,
//! kernel times are written exactly, the VCD keeps events 1 fs apart, and the plot of a long
//! run, drawn from its bounded copy, keeps a spike of a single time point.

use std::path::{Path, PathBuf};

use assert_cmd::Command;

use vams::app::load::load;
use vams::app::time::format_time;
use vams::elaborate::{ElabOptions, elaborate};
use vams::kernel::{SimOptions, simulate};
use vams::output::csv::write_csv;
use vams::output::vcd::write_vcd;

#[cfg(unix)]
use crate::support::interrupt;

fn vams() -> Command {
    Command::cargo_bin("vams").expect("the vams binary is built for integration tests")
}

/// The data rows of a CSV: the time's text and the cells as numbers (comment lines left out).
fn rows(text: &str) -> Vec<(String, Vec<f64>)> {
    text.lines()
        .skip(1)
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let mut cells = l.split(',');
            let time = cells.next().unwrap().to_string();
            (time, cells.map(|c| c.parse().unwrap()).collect())
        })
        .collect()
}

/// The time stamps of a VCD, in file order.
fn stamps(text: &str) -> Vec<u64> {
    text.lines()
        .filter_map(|l| l.strip_prefix('#'))
        .map(|n| n.parse().unwrap())
        .collect()
}

/// The time after "wrote the waveforms up to t = " in `stderr`.
fn printed_end(stderr: &str) -> String {
    let start = stderr
        .find("wrote the waveforms up to t = ")
        .unwrap_or_else(|| panic!("no end printed: {stderr}"))
        + "wrote the waveforms up to t = ".len();
    let rest = &stderr[start..];
    rest[..rest.find(" to ").unwrap()].to_string()
}

#[test]
fn streamed_csv_and_vcd_are_what_the_in_memory_run_writes() {
    let dir = tempfile::tempdir().unwrap();
    let (csv, vcd) = (dir.path().join("t.csv"), dir.path().join("t.vcd"));
    vams()
        .args(["run", "models", "--top", "tb_tracking", "-o"])
        .arg(&csv)
        .arg("-o")
        .arg(&vcd)
        .assert()
        .success();

    let models = PathBuf::from(format!("{}/models", env!("CARGO_MANIFEST_DIR")));
    let loaded = load(&[models]).expect("models/ readable");
    let options = ElabOptions {
        top: "tb_tracking".into(),
        generics: Vec::new(),
    };
    let design = elaborate(&loaded.sources, &loaded.files, &options).expect("elaborates");
    let sim = SimOptions {
        stop: 6.0,
        ..SimOptions::default()
    };
    let result = simulate(&design, &sim, &mut |_| {}).expect("runs");
    let mut expected = Vec::new();
    write_csv(&mut expected, &result.waveforms).unwrap();
    assert!(std::fs::read(&csv).unwrap() == expected, "the CSVs differ");
    let mut expected = Vec::new();
    write_vcd(&mut expected, &result.waveforms, "tb_tracking", None).unwrap();
    assert!(std::fs::read(&vcd).unwrap() == expected, "the VCDs differ");
    // Only the targets: no temporary left behind.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
}

/// Checks that `csv` and `vcd` of a partial run end at `end` (as printed) and say why.
fn assert_partial(csv: &Path, vcd: &Path, end: &str, why: &str) {
    let text = std::fs::read_to_string(csv).unwrap();
    let data = rows(&text);
    assert!(data.len() > 2, "{text}");
    let times: Vec<f64> = data.iter().map(|(t, _)| t.parse().unwrap()).collect();
    assert!(times.windows(2).all(|w| w[0] <= w[1]), "times out of order");
    let last = *times.last().unwrap();
    assert_eq!(format_time(last), end);
    let note = format!("partial: {why} at t = {end}");
    assert_eq!(text.lines().last(), Some(format!("# {note}").as_str()));

    let dump = std::fs::read_to_string(vcd).unwrap();
    let lines: Vec<&str> = dump.lines().collect();
    assert!(lines[0].starts_with("$version"));
    assert_eq!(lines[1], format!("$comment {note} $end"));
    let unit = unit(&dump);
    let stamps = stamps(&dump);
    assert!(
        stamps.windows(2).all(|w| w[0] < w[1]),
        "stamps out of order"
    );
    let final_stamp = *stamps.last().unwrap();
    assert!(final_stamp <= (last / unit).round() as u64);
    // The dump's last change is at or before the last row (later rows may change nothing).
    assert!(final_stamp as f64 * unit > times[times.len() / 2]);
}

/// Seconds per time unit of a VCD: 1 fs unless the run is hours long.
fn unit(dump: &str) -> f64 {
    let line = dump.lines().find(|l| l.starts_with("$timescale")).unwrap();
    match line {
        "$timescale 1 fs $end" => 1e-15,
        "$timescale 1 ns $end" => 1e-9,
        other => panic!("{other}"),
    }
}

#[test]
fn an_error_leaves_streamed_files_ending_at_the_printed_time() {
    let dir = tempfile::tempdir().unwrap();
    let (csv, vcd) = (dir.path().join("p.csv"), dir.path().join("p.vcd"));
    let out = vams()
        .args(["run", "tests/run/not_finite.vhd", "-o"])
        .arg(&csv)
        .arg("-o")
        .arg(&vcd)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8(out.stderr).unwrap();
    let end = printed_end(&stderr);
    assert_partial(&csv, &vcd, &end, "stopped by an error");
    // y = 1 - t changes at every row, so the dump's last stamp is the last row's.
    let dump = std::fs::read_to_string(&vcd).unwrap();
    let last_stamp = *stamps(&dump).last().unwrap();
    assert_eq!(unit(&dump), 1e-15);
    assert_eq!(format_time(last_stamp as f64 * 1e-15), end);
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
}

/// SIGINT mid-run: the streamed files are complete and end at the printed time.
#[cfg(unix)]
#[test]
fn sigint_leaves_streamed_files_ending_at_the_printed_time() {
    let dir = tempfile::tempdir().unwrap();
    let (csv, vcd) = (dir.path().join("e.csv"), dir.path().join("e.vcd"));
    let (status, stderr) = interrupt::run_interrupted(
        [
            "run",
            "tests/run/endless.vhd",
            "--stop",
            "1e9 sec",
            "--max-step",
            "0.05 sec",
        ]
        .map(std::ffi::OsString::from)
        .into_iter()
        .chain(["-o".into(), csv.clone().into_os_string()])
        .chain(["-o".into(), vcd.clone().into_os_string()]),
    );
    assert_eq!(status.code(), Some(130), "{stderr}");
    let end = printed_end(&stderr);
    assert_partial(&csv, &vcd, &end, "interrupted");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 2);
}

/// The counter of the streaming benchmark: every event time is a whole number of
/// nanoseconds, written as such (`0.000012345`, not `0.000012345000000001`).
#[test]
fn kernel_times_are_written_exactly() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("c.csv");
    vams()
        .args(["run", "benches/models/counter_rc.vhd", "--stop", "20 us"])
        .args(["--probe", "count", "-o"])
        .arg(&csv)
        .assert()
        .success();
    let text = std::fs::read_to_string(&csv).unwrap();
    let data = rows(&text);
    let mut changes = 0;
    for pair in data.windows(2) {
        if pair[0].1[0] == pair[1].1[0] {
            continue;
        }
        changes += 1;
        let (text, count) = (&pair[1].0, pair[1].1[0]);
        let digits = text
            .split('e')
            .next()
            .unwrap()
            .trim_start_matches(['0', '.'])
            .replace('.', "");
        assert!(digits.len() <= 5, "{text}");
        let ns = text.parse::<f64>().unwrap() * 1e9;
        assert_eq!(ns.round(), count, "{text}");
    }
    // The last change, at the stop time itself, may come after the last row.
    assert!(changes >= 19_999, "{changes}");
}

#[test]
fn vcd_events_one_femtosecond_apart_stay_apart_and_in_order() {
    let dir = tempfile::tempdir().unwrap();
    let model = dir.path().join("fs.vhd");
    std::fs::write(
        &model,
        "entity fs is end;\narchitecture a of fs is\n  signal s : integer := 0;\nbegin\n  \
         p : process begin\n    wait for 1 ns;\n    s <= 1;\n    wait for 1 fs;\n    \
         s <= 2;\n    wait for 1 fs;\n    s <= 3;\n    wait;\n  end process;\nend;\n",
    )
    .unwrap();
    let vcd = dir.path().join("fs.vcd");
    vams()
        .arg("run")
        .arg(&model)
        .args(["--stop", "2 ns", "-o"])
        .arg(&vcd)
        .assert()
        .success();
    let dump = std::fs::read_to_string(&vcd).unwrap();
    let changes: Vec<&str> = dump
        .split("$enddefinitions $end\n")
        .nth(1)
        .unwrap()
        .lines()
        .filter(|l| l.starts_with('#') || l.starts_with('b'))
        .collect();
    assert_eq!(
        changes,
        [
            "#0", "b0 !", "#1000000", "b1 !", "#1000001", "b10 !", "#1000002", "b11 !"
        ]
    );
}

/// A long run (200 000 rows, beyond what the plot keeps whole) with one value far above the
/// rest for a single femtosecond: the plot's y axis still reaches it.
#[test]
fn the_plot_of_a_long_run_keeps_a_single_sample_spike() {
    let dir = tempfile::tempdir().unwrap();
    let model = dir.path().join("spike.vhd");
    std::fs::write(
        &model,
        "entity spike is end;\narchitecture a of spike is\n  signal count : integer := 0;\n  \
         signal level : integer := 0;\nbegin\n  counter : process begin\n    wait for 1 ns;\n    \
         count <= count + 1;\n  end process;\n  pulse : process begin\n    wait for 61803 ns;\n    \
         level <= 7000;\n    wait for 1 fs;\n    level <= 0;\n    wait;\n  end process;\nend;\n",
    )
    .unwrap();
    let (svg, flat) = (dir.path().join("spike.svg"), dir.path().join("flat.svg"));
    let plot = |stop: &str, path: &Path| {
        vams()
            .arg("run")
            .arg(&model)
            .args(["--stop", stop, "--probe", "level", "--plot"])
            .arg(path)
            .assert()
            .success();
        std::fs::read_to_string(path).unwrap()
    };
    let spiked = plot("100 us", &svg);
    // Before the pulse the level is 0 throughout: its axis has no tick near 7000.
    let before = plot("60 us", &flat);
    assert!(spiked.contains("7000.0\n"), "no tick at 7000");
    assert!(!before.contains("7000.0\n"));
}
