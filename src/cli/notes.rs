//! The application layer's notes ([`crate::app::notes::Notes`]) as the command line shows them:
//! messages on stderr, results on stdout, a progress bar on stderr (indicatif draws it only
//! on a terminal).

use crate::app::notes::Notes;

/// Notes printed where a shell user reads them.
#[derive(Debug, Clone, Copy, Default)]
pub struct Printed;

impl Notes for Printed {
    fn note(&self, text: &str) {
        eprint!("{text}");
    }

    fn output(&self, text: &str) {
        print!("{text}");
    }

    fn progress(&self, total: u64) -> indicatif::ProgressBar {
        let bar = indicatif::ProgressBar::new(total);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{bar:30} {pos}/{len} runs, {msg}, {elapsed} elapsed, ETA {eta}",
        ) {
            bar.set_style(style);
        }
        bar
    }
}
