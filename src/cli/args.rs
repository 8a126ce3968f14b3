//! The arguments several subcommands share, and their parsers: clap's side of the
//! application layer's option structs.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use crate::app::ac::{FrequencyGrid, parse_frequency};
use crate::app::compile::DesignOptions;
use crate::app::load::{LibrarySources, parse_library};
use crate::app::params::parse_generic;

/// Sources, top entity and generic overrides.
#[derive(Debug, Args)]
pub struct DesignArgs {
    /// Source files or directories (directories are searched for .vhd, .vhdl and .ams files).
    #[arg(required = true, value_name = "FILES|DIRS")]
    pub paths: Vec<PathBuf>,
    /// Analyse the sources under PATH into library NAME (repeatable): `--lib util=../util`
    /// for files that say `library util;`.
    #[arg(long = "lib", value_name = "NAME=PATH", value_parser = parse_library)]
    pub libraries: Vec<LibrarySources>,
    /// The entity to elaborate; default: the only entity that nothing instantiates.
    #[arg(long, value_name = "ENTITY")]
    pub top: Option<String>,
    /// Override a generic of the top entity, e.g. `-g r=8.0` or `-g t_step="10 ms"`
    /// (repeatable; wins over --params).
    #[arg(short = 'g', long = "generic", value_name = "NAME=VALUE", value_parser = parse_generic)]
    pub generics: Vec<(String, String)>,
    /// Read generic overrides from a file of `name=value` lines (`#` or `--` comments).
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
}

impl DesignArgs {
    /// The application layer's options for these arguments.
    pub fn options(&self) -> DesignOptions {
        DesignOptions {
            paths: self.paths.clone(),
            libraries: self.libraries.clone(),
            top: self.top.clone(),
            generics: self.generics.clone(),
            params: self.params.clone(),
        }
    }
}

/// Picture format of `--plot`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PlotFormat {
    /// Scalable vector graphics.
    Svg,
    /// Portable network graphics.
    Png,
}

/// Accepts `.csv` and `.vcd` paths.
pub fn output_path(text: &str) -> Result<PathBuf, String> {
    with_extension(text, &["csv", "vcd"])
}

/// Accepts `.svg` and `.png` paths.
pub fn plot_path(text: &str) -> Result<PathBuf, String> {
    with_extension(text, &["svg", "png"])
}

fn with_extension(text: &str, allowed: &[&str]) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext {
        Some(e) if allowed.contains(&e.as_str()) => Ok(path),
        _ => Err(format!(
            "`{text}` has an unknown extension; name the file with .{}",
            allowed.join(" or .")
        )),
    }
}

pub fn positive_number(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        _ => Err(format!("`{text}` is not a positive number (e.g. 1e-3)")),
    }
}

/// Accepts `.csv` paths.
pub fn csv_path(text: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("csv") => Ok(path),
        _ => Err(format!(
            "`{text}` has an unknown extension; name the file with .csv"
        )),
    }
}

/// The analysis frequencies of `vams ac` and `vams noise`.
#[derive(Debug, Args)]
pub struct FrequencyArgs {
    /// Lowest analysis frequency.
    #[arg(long, value_name = "FREQ", value_parser = parse_frequency)]
    pub from: f64,
    /// Highest analysis frequency.
    #[arg(long, value_name = "FREQ", value_parser = parse_frequency)]
    pub to: f64,
    /// Logarithmic sweep with N points per decade (the default, 20).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub points_per_decade: Option<u32>,
    /// Linear sweep of N points, both ends included.
    #[arg(long, value_name = "N", conflicts_with = "points_per_decade",
          value_parser = clap::value_parser!(u32).range(2..=10_000_000))]
    pub linear: Option<u32>,
}

impl FrequencyArgs {
    /// The application layer's grid.
    pub fn grid(&self) -> FrequencyGrid {
        FrequencyGrid {
            from: self.from,
            to: self.to,
            points_per_decade: self.points_per_decade,
            linear: self.linear,
        }
    }
}
