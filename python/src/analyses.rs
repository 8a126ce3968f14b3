//! The analyses besides a run: `op` (the quiescent point), `dae` (the equation system), `ac`
//! (small-signal frequency response) and `noise`, each as the CLI command of the same name
//! computes it.

use numpy::{Complex64, PyArray1};
use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use vams::analog::{AnalogSystem, DaeEquation};
use vams::app::ac::{FrequencyGrid, linearise, parse_frequency, probes, respond};
use vams::app::compile::Compiled;
use vams::app::error::CliError;
use vams::app::noise::{analyse, input_source};
use vams::app::render::render_sim_error;
use vams::diagnostics::{Finding, Level};
use vams::kernel::{SimOptions, operating_point};

use crate::design::DesignSpec;
use crate::error::{Failure, bad_argument};
use crate::frame::{Columns, data_frame};

/// Compiles `spec` and computes `then` of the design, without the GIL; a failure raises
/// VamsError.
fn with_design<T: Send>(
    py: Python<'_>,
    spec: &DesignSpec,
    then: impl FnOnce(&Compiled) -> Result<T, Failure> + Send,
) -> PyResult<T> {
    py.detach(|| {
        let (compiled, _warnings) = spec.compile()?;
        then(&compiled)
    })
    .map_err(|f| f.into_pyerr(py, None))
}

/// op(paths, top=None, *, generics=None, libraries=None) -> dict[str, float]
///
/// The quiescent operating point, as `vams op`: every quantity, then every explicit signal
/// (booleans and enumerations by position), by hierarchical name.
#[pyfunction]
#[pyo3(signature = (paths, top=None, *, generics=None, libraries=None))]
pub fn op<'py>(
    py: Python<'py>,
    paths: &Bound<'py, PyAny>,
    top: Option<String>,
    generics: Option<&Bound<'py, PyDict>>,
    libraries: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let spec = DesignSpec::new(paths, top, generics, libraries)?;
    let point = with_design(py, &spec, |c| {
        operating_point(&c.design, &SimOptions::default()).map_err(|e| Failure {
            findings: Vec::new(),
            rendered: render_sim_error(&e, &c.loaded.sources),
            summary: CliError::Simulation {
                top: c.design.top.clone(),
            }
            .into(),
        })
    })?;
    let dict = PyDict::new(py);
    for (name, value) in point {
        dict.set_item(name, value)?;
    }
    Ok(dict)
}

/// The equation system of a design: `text` (what `vams dae` prints) and the same as data:
/// `unknowns` (dicts of name and differential), `equations` (dicts of origin and residual:
/// each equation is residual = 0), `index_reduction` (None, or a dict of index, added
/// equations, dummies and states), `solver_unknowns` and `eliminated` (dicts of unknown,
/// name, formula and equation).
#[pyclass(frozen, module = "vams")]
pub struct Dae {
    #[pyo3(get)]
    text: String,
    dae: vams::analog::Dae,
}

/// Equations as dicts of origin and residual.
fn equations<'py>(py: Python<'py>, list: &[DaeEquation]) -> PyResult<Bound<'py, PyList>> {
    let dicts = list.iter().map(|e| {
        let d = PyDict::new(py);
        d.set_item("origin", &e.origin)?;
        d.set_item("residual", &e.residual)?;
        Ok::<_, PyErr>(d)
    });
    PyList::new(py, dicts.collect::<PyResult<Vec<_>>>()?)
}

#[pymethods]
impl Dae {
    #[getter]
    fn unknowns<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        (self.dae.unknowns.iter())
            .map(|u| {
                let d = PyDict::new(py);
                d.set_item("name", &u.name)?;
                d.set_item("differential", u.differential)?;
                Ok(d)
            })
            .collect()
    }

    #[getter]
    fn equations<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        equations(py, &self.dae.equations)
    }

    #[getter]
    fn index_reduction<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(r) = &self.dae.index_reduction else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        d.set_item("index", r.index)?;
        d.set_item("added", equations(py, &r.added)?)?;
        d.set_item("dummies", &r.dummies)?;
        d.set_item("states", &r.states)?;
        Ok(Some(d))
    }

    #[getter]
    fn solver_unknowns(&self) -> Vec<String> {
        self.dae.solver_unknowns.clone()
    }

    #[getter]
    fn eliminated<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        (self.dae.eliminated.iter())
            .map(|e| {
                let d = PyDict::new(py);
                d.set_item("unknown", e.unknown)?;
                d.set_item("name", &e.name)?;
                d.set_item("formula", &e.formula)?;
                d.set_item("equation", e.equation)?;
                Ok(d)
            })
            .collect()
    }

    fn __str__(&self) -> String {
        self.text.clone()
    }

    fn __repr__(&self) -> String {
        format!(
            "<Dae: {} unknowns, {} equations>",
            self.dae.unknowns.len(),
            self.dae.equations.len()
        )
    }
}

/// dae(paths, top=None, *, generics=None, libraries=None) -> Dae
///
/// The analog equation system of a design, as `vams dae`.
#[pyfunction]
#[pyo3(signature = (paths, top=None, *, generics=None, libraries=None))]
pub fn dae(
    py: Python<'_>,
    paths: &Bound<'_, PyAny>,
    top: Option<String>,
    generics: Option<&Bound<'_, PyDict>>,
    libraries: Option<&Bound<'_, PyDict>>,
) -> PyResult<Dae> {
    let spec = DesignSpec::new(paths, top, generics, libraries)?;
    with_design(py, &spec, |c| {
        let sources = &c.loaded.sources;
        let system = AnalogSystem::new(&c.design).map_err(|errors| Failure {
            findings: (errors.iter())
                .map(|e| Finding::located(e, sources, Level::Error))
                .collect(),
            rendered: String::new(),
            summary: CliError::Analog {
                count: errors.len(),
            }
            .into(),
        })?;
        let dae = system.dae(&c.design, sources).unwrap_or_default();
        Ok(Dae {
            text: dae.to_string(),
            dae,
        })
    })
}

/// The analysis frequencies of `ac` and `noise`, as `--from`, `--to`, `--points-per-decade`
/// and `--linear` give them.
fn grid(
    start: &Bound<'_, PyAny>,
    stop: &Bound<'_, PyAny>,
    points_per_decade: Option<u32>,
    linear: Option<u32>,
) -> PyResult<Vec<f64>> {
    let frequency = |f: &Bound<'_, PyAny>| match f.extract::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v),
        Ok(v) => Err(bad_argument(format!("{v} is not a positive frequency"))),
        Err(_) => parse_frequency(&f.extract::<String>()?).map_err(bad_argument),
    };
    if points_per_decade.is_some() && linear.is_some() {
        return Err(bad_argument("give points_per_decade or linear, not both"));
    }
    if points_per_decade == Some(0) || linear.is_some_and(|n| n < 2) {
        return Err(bad_argument(
            "points_per_decade is at least 1 and linear at least 2",
        ));
    }
    let sweep = FrequencyGrid {
        from: frequency(start)?,
        to: frequency(stop)?,
        points_per_decade,
        linear,
    };
    sweep.frequencies().map_err(|e| bad_argument(e.to_string()))
}

/// A small-signal response: `frequency` (Hz, float64) and each probe's complex response
/// (`result["vout"]`, complex128: the probe's phasor for the spectral sources' excitation),
/// `columns`, `to_pandas()`.
#[pyclass(frozen, module = "vams")]
pub struct AcResult {
    frequency: Py<PyArray1<f64>>,
    columns: Columns<Complex64>,
}

#[pymethods]
impl AcResult {
    #[getter]
    fn frequency(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.frequency.clone_ref(py)
    }

    #[getter]
    fn columns(&self) -> Vec<String> {
        self.columns.names.clone()
    }

    fn __getitem__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyArray1<Complex64>>> {
        (self.columns.get(py, name))
            .ok_or_else(|| PyKeyError::new_err(format!("`{name}` was not probed")))
    }

    /// A pandas DataFrame: a `frequency` column, then one complex column per probe.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        data_frame(py, ("frequency", &self.frequency), |d| {
            self.columns.add_to(py, d)
        })
    }
}

/// ac(paths, top=None, *, start, stop, points_per_decade=None, linear=None, probes=None,
///    generics=None, libraries=None) -> AcResult
///
/// The small-signal frequency response, as `vams ac`: the design linearised about its
/// quiescent point and excited by its spectral source quantities, at frequencies from
/// `start` to `stop` (hertz, or text such as "1kHz"), 20 per decade unless
/// `points_per_decade` or `linear` (a number of points) says otherwise. `probes` are the
/// quantities to report (default: every quantity but the sources).
#[pyfunction]
#[pyo3(signature = (paths, top=None, *, start, stop, points_per_decade=None, linear=None,
                    probes=None, generics=None, libraries=None))]
#[allow(clippy::too_many_arguments)] // Python's keyword arguments, as `vams ac`'s options.
pub fn ac(
    py: Python<'_>,
    paths: &Bound<'_, PyAny>,
    top: Option<String>,
    start: &Bound<'_, PyAny>,
    stop: &Bound<'_, PyAny>,
    points_per_decade: Option<u32>,
    linear: Option<u32>,
    probes: Option<Vec<String>>,
    generics: Option<&Bound<'_, PyDict>>,
    libraries: Option<&Bound<'_, PyDict>>,
) -> PyResult<AcResult> {
    let spec = DesignSpec::new(paths, top, generics, libraries)?;
    let frequencies = grid(start, stop, points_per_decade, linear)?;
    let names = probes.unwrap_or_default();
    let (frequency, columns) = with_design(py, &spec, |c| {
        let design = &c.design;
        if design.spectral_sources.is_empty() {
            let top = design.top.clone();
            return Err(CliError::NoSpectralSource { top }.into());
        }
        let probes = self::probes(design, &names)?;
        let mut linearised = linearise(design, &c.loaded.sources)?;
        let response = respond(&design.top, &mut linearised, &probes, frequencies)?;
        let columns: Vec<(String, Vec<Complex64>)> = (probes.iter().zip(response.values))
            .map(|(q, values)| {
                let name = design.quantities[q.index()].name.clone();
                (
                    name,
                    values.iter().map(|z| Complex64::new(z.re, z.im)).collect(),
                )
            })
            .collect();
        Ok((response.frequencies, columns))
    })?;
    Ok(AcResult {
        frequency: PyArray1::from_vec(py, frequency).unbind(),
        columns: Columns::new(py, columns),
    })
}

/// A noise analysis: `frequency` (Hz), `total` (the output's power spectral density, the
/// probe's units squared per hertz), `contributions` (a dict of each noise source's part of
/// it), `input_gain` (the complex transfer from `input`, or None), `probe`, `to_pandas()`.
#[pyclass(frozen, module = "vams")]
pub struct NoiseResult {
    #[pyo3(get)]
    probe: String,
    frequency: Py<PyArray1<f64>>,
    total: Py<PyArray1<f64>>,
    contributions: Columns<f64>,
    input_gain: Option<Py<PyArray1<Complex64>>>,
}

#[pymethods]
impl NoiseResult {
    #[getter]
    fn frequency(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.frequency.clone_ref(py)
    }

    #[getter]
    fn total(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.total.clone_ref(py)
    }

    #[getter]
    fn contributions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        self.contributions.add_to(py, &dict)?;
        Ok(dict)
    }

    #[getter]
    fn input_gain(&self, py: Python<'_>) -> Option<Py<PyArray1<Complex64>>> {
        self.input_gain.as_ref().map(|g| g.clone_ref(py))
    }

    /// A pandas DataFrame: `frequency`, `total`, then each source's contribution.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        data_frame(py, ("frequency", &self.frequency), |d| {
            d.set_item("total", self.total.clone_ref(py))?;
            self.contributions.add_to(py, d)
        })
    }
}

/// noise(paths, probe, top=None, *, start, stop, input=None, points_per_decade=None,
///       linear=None, generics=None, libraries=None) -> NoiseResult
///
/// The noise at the quantity `probe`, as `vams noise`: each noise source quantity's power
/// spectral density carried to the probe through the small-signal model, at frequencies
/// from `start` to `stop`; with `input` (a spectral source quantity) also the gain from it.
#[pyfunction]
#[pyo3(signature = (paths, probe, top=None, *, start, stop, input=None, points_per_decade=None,
                    linear=None, generics=None, libraries=None))]
#[allow(clippy::too_many_arguments)] // Python's keyword arguments, as `vams noise`'s options.
pub fn noise(
    py: Python<'_>,
    paths: &Bound<'_, PyAny>,
    probe: String,
    top: Option<String>,
    start: &Bound<'_, PyAny>,
    stop: &Bound<'_, PyAny>,
    input: Option<String>,
    points_per_decade: Option<u32>,
    linear: Option<u32>,
    generics: Option<&Bound<'_, PyDict>>,
    libraries: Option<&Bound<'_, PyDict>>,
) -> PyResult<NoiseResult> {
    let spec = DesignSpec::new(paths, top, generics, libraries)?;
    let frequencies = grid(start, stop, points_per_decade, linear)?;
    let (probe, table, sources) = with_design(py, &spec, |c| {
        let design = &c.design;
        if design.noise_sources.is_empty() {
            let top = design.top.clone();
            return Err(CliError::NoNoiseSource { top }.into());
        }
        // One name gives one quantity or an error.
        let q = probes(design, std::slice::from_ref(&probe))?[0];
        let input = (input.as_deref())
            .map(|name| input_source(design, name))
            .transpose()?;
        let table = analyse(design, &c.loaded.sources, q, input, frequencies)?;
        let name = |q: vams::design::QuantityId| design.quantities[q.index()].name.clone();
        let sources: Vec<String> = design
            .noise_sources
            .iter()
            .map(|s| name(s.quantity))
            .collect();
        Ok((name(q), table, sources))
    })?;
    let contributions = (sources.into_iter().enumerate())
        .map(|(k, name)| (name, table.contributions.iter().map(|c| c[k]).collect()))
        .collect();
    Ok(NoiseResult {
        probe,
        frequency: PyArray1::from_vec(py, table.frequencies).unbind(),
        total: PyArray1::from_vec(py, table.total).unbind(),
        contributions: Columns::new(py, contributions),
        input_gain: table.input_gain.map(|g| {
            let g: Vec<Complex64> = g.iter().map(|z| Complex64::new(z.re, z.im)).collect();
            PyArray1::from_vec(py, g).unbind()
        }),
    })
}
