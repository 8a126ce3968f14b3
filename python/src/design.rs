//! The arguments every design-taking function shares (`paths`, `top`, `generics`,
//! `libraries`), read from Python, and the way from them to an elaborated design: the CLI's
//! `DesignArgs` and `compile`, with the diagnostics kept instead of printed.

use std::path::PathBuf;

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyString};
use vams::app::compile::{Compiled, Prepared, compile_loaded, prepare_loaded};
use vams::app::load::{LibrarySources, load_with_libraries, parse_library};
use vams::app::params::parse_generic;
use vams::app::time::parse_positive_time;
use vams::diagnostics::Finding;

use crate::error::{Failure, bad_argument};

/// Sources, top entity and generic overrides.
pub struct DesignSpec {
    pub paths: Vec<PathBuf>,
    pub libraries: Vec<LibrarySources>,
    pub top: Option<String>,
    pub generics: Vec<(String, String)>,
}

impl DesignSpec {
    /// Reads the Python arguments: `paths` a path or a list of paths (files or directories),
    /// `generics` a dict of name to value, `libraries` a dict of library name to path.
    pub fn new(
        paths: &Bound<'_, PyAny>,
        top: Option<String>,
        generics: Option<&Bound<'_, PyDict>>,
        libraries: Option<&Bound<'_, PyDict>>,
    ) -> PyResult<DesignSpec> {
        let mut spec = DesignSpec {
            paths: paths_of(paths)?,
            libraries: Vec::new(),
            top,
            generics: Vec::new(),
        };
        for (name, value) in generics.into_iter().flatten() {
            let text = format!("{}={}", name.extract::<String>()?, literal(&value)?);
            spec.generics
                .push(parse_generic(&text).map_err(bad_argument)?);
        }
        for (name, path) in libraries.into_iter().flatten() {
            let path: PathBuf = path.extract()?;
            let text = format!("{}={}", name.extract::<String>()?, path.display());
            spec.libraries
                .push(parse_library(&text).map_err(bad_argument)?);
        }
        Ok(spec)
    }

    /// Loads, parses, analyses and elaborates (call it with the GIL released): the design
    /// and its elaboration warnings.
    pub fn compile(&self) -> Result<(Compiled, Vec<Finding>), Failure> {
        let loaded = load_with_libraries(&self.paths, &self.libraries)?;
        let mut compiled = compile_loaded(loaded, self.top.as_deref(), self.generics.clone())?;
        let warnings = std::mem::take(&mut compiled.warnings);
        Ok((compiled, warnings))
    }

    /// Loads, parses and analyses, the top chosen, for elaborating several times (a sweep).
    pub fn prepare(&self) -> Result<Prepared, Failure> {
        let loaded = load_with_libraries(&self.paths, &self.libraries)?;
        Ok(prepare_loaded(
            loaded,
            self.top.as_deref(),
            self.generics.clone(),
        )?)
    }
}

/// A path or a list of paths.
pub fn paths_of(paths: &Bound<'_, PyAny>) -> PyResult<Vec<PathBuf>> {
    match paths.extract::<PathBuf>() {
        Ok(path) => Ok(vec![path]),
        Err(_) => paths.extract::<Vec<PathBuf>>(),
    }
}

/// A generic's value as VHDL literal text: a bool as `true`/`false`, an int as it is, a float
/// with a decimal point (`1e-05` is `1.0e-5`, as VHDL wants), a string as written (`"10 ms"`).
fn literal(value: &Bound<'_, PyAny>) -> PyResult<String> {
    if value.is_instance_of::<PyBool>() {
        return Ok(if value.extract::<bool>()? {
            "true"
        } else {
            "false"
        }
        .into());
    }
    if value.is_instance_of::<PyInt>() {
        return Ok(value.str()?.to_string());
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(real_literal(value.extract::<f64>()?));
    }
    if value.is_instance_of::<PyString>() {
        return value.extract::<String>();
    }
    Err(bad_argument(format!(
        "a generic's value is a bool, an int, a float or a string (VHDL text), not {}",
        value.get_type().name()?
    )))
}

/// The shortest text of `v` that reads back exactly, with the decimal point VHDL's real
/// literals need.
fn real_literal(v: f64) -> String {
    let text = format!("{v:?}");
    match text.split_once('e') {
        Some((mantissa, exponent)) if !mantissa.contains('.') => {
            format!("{mantissa}.0e{exponent}")
        }
        _ => text,
    }
}

/// A time in seconds: a number, or text with a unit (`"6 s"`, `"10 ms"`).
pub fn time_of(value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let text = match value.extract::<f64>() {
        Ok(v) => v.to_string(),
        Err(_) => value.extract::<String>()?,
    };
    parse_positive_time(&text).map_err(bad_argument)
}
