//! What a long operation tells its user as it goes: progress lines, diagnostics found before
//! it fails, a script it wrote. The application layer never prints: it hands such text to a
//! [`Notes`] the caller chooses. The CLI prints it on stderr and stdout; a library caller may
//! keep it or drop it ([`Quiet`]).

/// Where an operation's messages go.
pub trait Notes: Sync {
    /// A message, already rendered and ending with its newline (the CLI writes it to stderr).
    fn note(&self, text: &str);
    /// A result meant for standard output (the job script of a dry run).
    fn output(&self, text: &str);
    /// A progress bar over `total` steps; hidden unless the caller draws one.
    fn progress(&self, total: u64) -> indicatif::ProgressBar {
        let _ = total;
        indicatif::ProgressBar::hidden()
    }
}

/// Notes nobody reads.
#[derive(Debug, Clone, Copy, Default)]
pub struct Quiet;

impl Notes for Quiet {
    fn note(&self, _: &str) {}
    fn output(&self, _: &str) {}
}
