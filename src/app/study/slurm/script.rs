//! The text of a sweep's sbatch job-array script, and the quoting it needs.
//!
//! Two quoting rules meet in one file: the `#SBATCH` lines are read by sbatch itself, which
//! knows double quotes and backslash escapes but not single quotes (and takes an unquoted `#`
//! for a comment), while the command line is read by `/bin/sh`. `--output` is also a Slurm
//! filename pattern, where `%` is a replacement symbol unless doubled. Never runs anything.

use std::borrow::Cow;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// A sweep's shards as one Slurm job array: task `K` runs
/// `VAMS sweep SPEC --shard K/N --out OUT EXTRA...`.
///
/// Paths are written as given: the caller makes them absolute (the tasks run in whatever
/// directory sbatch was called from). Paths that are not UTF-8 are written lossily.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ArrayJob {
    /// The `vams` binary the tasks run (`std::env::current_exe()`).
    pub vams: PathBuf,
    /// The sweep's spec file.
    pub spec: PathBuf,
    /// Where the shards' CSV files go; the tasks' logs go to `OUT/logs/`.
    pub out: PathBuf,
    /// N, the number of shards and of array tasks; at least 1.
    pub shards: usize,
    /// `#SBATCH --partition`, when given (else the cluster's default partition).
    pub partition: Option<String>,
    /// `#SBATCH --time` in one of Slurm's formats (see `validate_time`), when given.
    pub time: Option<String>,
    /// `#SBATCH --job-name`, what `squeue` shows.
    pub job_name: String,
    /// Further arguments of each task's `vams sweep`, after `--out`.
    pub extra_args: Vec<String>,
}

impl ArrayJob {
    /// The file task `task`'s standard output and error go to: `OUT/logs/shard-K.out`.
    pub fn log_path(&self, task: usize) -> PathBuf {
        self.out.join("logs").join(format!("shard-{task}.out"))
    }

    /// The sbatch script. One CPU per task (a shard runs its points one after the other);
    /// the task runs `vams` by `exec`, so a cancelled task's signal reaches vams itself, which
    /// then closes its shard as partial.
    pub fn script(&self) -> String {
        let last = self.shards.saturating_sub(1);
        let mut s = String::from("#!/bin/sh\n");
        let _ = writeln!(
            s,
            "# Written by `vams sweep --slurm`: task K of this array runs shard K of {} of {}.",
            self.shards,
            self.spec.display()
        );
        let mut directive = |option: &str, value: &str| {
            let _ = writeln!(s, "#SBATCH --{option}={}", sbatch_quote(value));
        };
        directive("job-name", &self.job_name);
        directive("array", &format!("0-{last}"));
        directive(
            "output",
            &filename_pattern(&self.out.join("logs"), "shard-%a.out"),
        );
        directive("ntasks", "1");
        directive("cpus-per-task", "1");
        if let Some(partition) = &self.partition {
            directive("partition", partition);
        }
        if let Some(time) = &self.time {
            directive("time", time);
        }
        let mut command = format!(
            "exec {} sweep {} --shard \"$SLURM_ARRAY_TASK_ID/{}\" --out {}",
            shell_quote(&lossy(&self.vams)),
            shell_quote(&lossy(&self.spec)),
            self.shards,
            shell_quote(&lossy(&self.out)),
        );
        for arg in &self.extra_args {
            command.push(' ');
            command.push_str(&shell_quote(arg));
        }
        s.push_str(&command);
        s.push('\n');
        s
    }
}

fn lossy(path: &Path) -> Cow<'_, str> {
    path.to_string_lossy()
}

/// `text` as one word for `/bin/sh`: bare when it holds only characters no shell treats
/// specially, else in single quotes (inside which only `'` needs care: `'\''`).
pub fn shell_quote(text: &str) -> Cow<'_, str> {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-./,:=+@%".contains(c);
    if !text.is_empty() && text.chars().all(plain) {
        Cow::Borrowed(text)
    } else {
        Cow::Owned(format!("'{}'", text.replace('\'', r"'\''")))
    }
}

/// `text` as the argument of an `#SBATCH` line: sbatch reads the line itself (not a shell),
/// honouring double quotes and backslash escapes, and ends the argument at an unquoted `#`
/// or space.
fn sbatch_quote(text: &str) -> Cow<'_, str> {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-./,:=+@%".contains(c);
    if !text.is_empty() && text.chars().all(plain) {
        Cow::Borrowed(text)
    } else {
        let escaped = text.replace('\\', r"\\").replace('"', "\\\"");
        Cow::Owned(format!("\"{escaped}\""))
    }
}

/// A Slurm filename pattern for `dir/file`, where `file` holds the replacement symbols:
/// the directory's own `%` signs doubled so that Slurm keeps them. (A backslash anywhere
/// turns every replacement off in Slurm's patterns: such a directory gets one log file for
/// all tasks, named literally.)
fn filename_pattern(dir: &Path, file: &str) -> String {
    let dir = lossy(dir).replace('%', "%%");
    format!("{}/{file}", dir.trim_end_matches('/'))
}

/// The array indices `only` as an `--array` list: sorted, duplicates dropped, runs of
/// consecutive indices as ranges (`[7, 3, 4, 5]` is `3-5,7`).
pub fn array_list(only: &[usize]) -> String {
    let mut indices = only.to_vec();
    indices.sort_unstable();
    indices.dedup();
    let mut list = String::new();
    let mut i = 0;
    while i < indices.len() {
        let start = indices[i];
        let mut end = start;
        while i + 1 < indices.len() && indices[i + 1] == end + 1 {
            i += 1;
            end = indices[i];
        }
        if !list.is_empty() {
            list.push(',');
        }
        let _ = match end - start {
            0 => write!(list, "{start}"),
            _ => write!(list, "{start}-{end}"),
        };
        i += 1;
    }
    list
}

/// The command that submits `script` again for the tasks `only` (what `vams sweep collect`
/// prints for missing or partial shards): `sbatch --array=3,7 DIR/sweep.sbatch`.
pub fn resubmit_command(script: &Path, only: &[usize]) -> String {
    format!(
        "sbatch --array={} {}",
        array_list(only),
        shell_quote(&lossy(script))
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn job() -> ArrayJob {
        ArrayJob {
            vams: PathBuf::from("/opt/vams/bin/vams"),
            spec: PathBuf::from("/home/ada/rc.toml"),
            out: PathBuf::from("/scratch/ada/rc"),
            shards: 8,
            partition: None,
            time: None,
            job_name: "vams-rc".into(),
            extra_args: vec![],
        }
    }

    #[test]
    fn plain_script() {
        assert_eq!(
            job().script(),
            r#"#!/bin/sh
# Written by `vams sweep --slurm`: task K of this array runs shard K of 8 of /home/ada/rc.toml.
#SBATCH --job-name=vams-rc
#SBATCH --array=0-7
#SBATCH --output=/scratch/ada/rc/logs/shard-%a.out
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
exec /opt/vams/bin/vams sweep /home/ada/rc.toml --shard "$SLURM_ARRAY_TASK_ID/8" --out /scratch/ada/rc
"#
        );
    }

    #[test]
    fn partition_time_and_extra_arguments() {
        let job = ArrayJob {
            partition: Some("short".into()),
            time: Some("0-00:30".into()),
            extra_args: vec!["--seed".into(), "42".into(), "a b".into()],
            ..job()
        };
        let script = job.script();
        assert!(script.contains("\n#SBATCH --partition=short\n#SBATCH --time=0-00:30\n"));
        assert!(script.ends_with("--out /scratch/ada/rc --seed 42 'a b'\n"));
    }

    #[test]
    fn awkward_paths_are_quoted_for_sbatch_and_for_the_shell() {
        let job = ArrayJob {
            vams: PathBuf::from("/opt/my vams/vams"),
            spec: PathBuf::from("/home/o'brien/spec $x.toml"),
            out: PathBuf::from("/tmp/a \"b\" 50%/c#d"),
            job_name: "rc #1 \"x\"".into(),
            ..job()
        };
        let script = job.script();
        assert!(script.contains("\n#SBATCH --job-name=\"rc #1 \\\"x\\\"\"\n"));
        assert!(
            script.contains("\n#SBATCH --output=\"/tmp/a \\\"b\\\" 50%%/c#d/logs/shard-%a.out\"\n")
        );
        assert!(script.ends_with(
            "exec '/opt/my vams/vams' sweep '/home/o'\\''brien/spec $x.toml' \
             --shard \"$SLURM_ARRAY_TASK_ID/8\" --out '/tmp/a \"b\" 50%/c#d'\n"
        ));
    }

    #[test]
    fn one_shard_is_an_array_of_one() {
        let job = ArrayJob { shards: 1, ..job() };
        assert!(job.script().contains("#SBATCH --array=0-0\n"));
    }

    #[test]
    fn shell_quoting() {
        assert_eq!(shell_quote("/a/b-c_1.csv"), "/a/b-c_1.csv");
        assert_eq!(shell_quote(""), "''");
        assert_eq!(shell_quote("a b"), "'a b'");
        assert_eq!(shell_quote("it's"), "'it'\\''s'");
        assert_eq!(shell_quote("$HOME"), "'$HOME'");
        assert_eq!(shell_quote("a*"), "'a*'");
    }

    #[test]
    fn array_lists() {
        assert_eq!(array_list(&[3, 7]), "3,7");
        assert_eq!(array_list(&[7, 3, 4, 5]), "3-5,7");
        assert_eq!(array_list(&[0, 1, 2, 3]), "0-3");
        assert_eq!(array_list(&[5, 5, 0]), "0,5");
        assert_eq!(array_list(&[]), "");
        assert_eq!(
            resubmit_command(Path::new("/s/out dir/sweep.sbatch"), &[3, 7]),
            "sbatch --array=3,7 '/s/out dir/sweep.sbatch'"
        );
    }
}
