//! `vams.dc(...)`: a DC transfer sweep as `vams dc` computes it (a generic of the top swept,
//! each point's quiescent point found from the last one's).

use numpy::PyArray1;
use pyo3::exceptions::PyKeyError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vams::app::dc::{GenericSweep, sweep_points};
use vams::kernel::Cancel;

use crate::design::DesignSpec;
use crate::error::{Failure, bad_argument};
use crate::frame::{Columns, data_frame};

/// The curves of a DC sweep: `name` (the swept generic), `values` (its value at each point),
/// `direction` (1 up, -1 on the way back of `both_ways`), each probe by name
/// (`result["vout"]`, float64), `columns`, `to_pandas()`.
#[pyclass(frozen, module = "vams")]
pub struct DcResult {
    #[pyo3(get)]
    name: String,
    values: Py<PyArray1<f64>>,
    direction: Py<PyArray1<f64>>,
    columns: Columns<f64>,
}

#[pymethods]
impl DcResult {
    #[getter]
    fn values(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.values.clone_ref(py)
    }

    #[getter]
    fn direction(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.direction.clone_ref(py)
    }

    #[getter]
    fn columns(&self) -> Vec<String> {
        self.columns.names.clone()
    }

    fn __getitem__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyArray1<f64>>> {
        (self.columns.get(py, name))
            .ok_or_else(|| PyKeyError::new_err(format!("`{name}` was not probed")))
    }

    /// A pandas DataFrame: the swept value (named as the generic), `direction`, then each
    /// probe.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        data_frame(py, (&self.name, &self.values), |d| {
            d.set_item("direction", self.direction.clone_ref(py))?;
            self.columns.add_to(py, d)
        })
    }
}

/// dc(paths, sweep, top=None, *, both_ways=False, probes=None, generics=None,
///    libraries=None) -> DcResult
///
/// Sweeps the top's generic `sweep = (name, from, to, step)` as `vams dc --sweep NAME FROM TO
/// STEP` (whole numbers sweep an integer generic), to TO and back with `both_ways`. `probes`
/// are the quantities and signals to report (default: every quantity but the spectral
/// sources). A point without a quiescent point raises VamsError, whose `result` holds the
/// points before it.
#[pyfunction]
#[pyo3(signature = (paths, sweep, top=None, *, both_ways=false, probes=None, generics=None,
                    libraries=None))]
#[allow(clippy::too_many_arguments)] // Python's keyword arguments, as `vams dc`'s options.
pub fn dc(
    py: Python<'_>,
    paths: &Bound<'_, PyAny>,
    sweep: (String, f64, f64, f64),
    top: Option<String>,
    both_ways: bool,
    probes: Option<Vec<String>>,
    generics: Option<&Bound<'_, PyDict>>,
    libraries: Option<&Bound<'_, PyDict>>,
) -> PyResult<DcResult> {
    let spec = DesignSpec::new(paths, top, generics, libraries)?;
    let (name, from, to, step) = sweep;
    let words = [
        name,
        format!("{from:?}"),
        format!("{to:?}"),
        format!("{step:?}"),
    ];
    let sweep = GenericSweep::parse(&words).map_err(|e| bad_argument(e.to_string()))?;
    let probes = probes.unwrap_or_default();
    let computed = py.detach(|| {
        let prepared = spec.prepare()?;
        let swept = sweep_points(&prepared, &sweep, both_ways, &Cancel::new(), None)?;
        let curves = swept.curves(&probes)?;
        let failure = (swept.ending).map(|(_, error)| Failure {
            findings: Vec::new(),
            rendered: swept.failure,
            summary: error.into(),
        });
        Ok::<_, Failure>((curves, failure))
    });
    let (curves, failure) = computed.map_err(|f| f.into_pyerr(py, None))?;
    let (values, direction): (Vec<f64>, Vec<f64>) = curves.rows.iter().map(|r| (r.0, r.1)).unzip();
    let columns = (curves.names.iter().enumerate())
        .map(|(k, name)| (name.clone(), curves.rows.iter().map(|r| r.2[k]).collect()))
        .collect();
    let result = DcResult {
        name: sweep.name,
        values: PyArray1::from_vec(py, values).unbind(),
        direction: PyArray1::from_vec(py, direction).unbind(),
        columns: Columns::new(py, columns),
    };
    match failure {
        None => Ok(result),
        Some(f) => Err(f.into_pyerr(py, Some(Py::new(py, result)?.into_any()))),
    }
}
