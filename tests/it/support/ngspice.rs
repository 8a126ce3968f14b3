//! ngspice as the reference of the frequency-domain and DC tests: whether it is installed, and
//! the rows of numbers a deck's `.control` block writes with `wrdata`.

use std::path::Path;
use std::process::Command;

/// Whether `ngspice` runs here; the tests that need it print a skip otherwise.
pub fn available() -> bool {
    Command::new("ngspice").arg("--version").output().is_ok()
}

/// Runs `deck` in batch mode with the `.control` lines `control`, in which `{out}` stands for
/// the data file that `wrdata` writes; gives its rows of `columns` numbers (`None`, with
/// ngspice's output printed, when the file is missing).
pub fn run(deck: &str, control: &str, columns: usize, dir: &Path) -> Option<Vec<Vec<f64>>> {
    let cir = dir.join("deck.cir");
    let out = dir.join("ngspice.out");
    let control = control.replace("{out}", &out.display().to_string());
    let text = format!("{deck}\n.control\nset wr_singlescale\n{control}\n.endc\n.end\n");
    std::fs::write(&cir, text).ok()?;
    // ngspice exits with 1 after a `.control` run without `.print` lines; the data file
    // tells whether the analysis ran.
    let _ = std::fs::remove_file(&out);
    let run = Command::new("ngspice").arg("-b").arg(&cir).output().ok()?;
    let data = std::fs::read_to_string(&out).map_err(|e| {
        eprintln!(
            "{e}: {}{}",
            String::from_utf8_lossy(&run.stdout),
            String::from_utf8_lossy(&run.stderr)
        )
    });
    Some(
        data.ok()?
            .lines()
            .filter_map(|l| {
                let v: Vec<f64> = l
                    .split_whitespace()
                    .filter_map(|x| x.parse().ok())
                    .collect();
                (v.len() == columns).then_some(v)
            })
            .collect(),
    )
}
