//! NumPy arrays and pandas data frames of columns.

use numpy::{Element, PyArray1};
use pyo3::exceptions::PyImportError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Named columns of one length as NumPy arrays, made once (each access gives the same array).
pub struct Columns<T: Element> {
    pub names: Vec<String>,
    pub arrays: Vec<Py<PyArray1<T>>>,
}

impl<T: Element> Columns<T> {
    pub fn new(py: Python<'_>, columns: Vec<(String, Vec<T>)>) -> Columns<T> {
        let (names, arrays) = columns
            .into_iter()
            .map(|(name, values)| (name, PyArray1::from_vec(py, values).unbind()))
            .unzip();
        Columns { names, arrays }
    }

    /// The column `name` (case-insensitive, as VHDL names are).
    pub fn get(&self, py: Python<'_>, name: &str) -> Option<Py<PyArray1<T>>> {
        let wanted = name.trim().to_ascii_lowercase();
        let k = self.names.iter().position(|n| *n == wanted)?;
        Some(self.arrays[k].clone_ref(py))
    }

    /// Adds the columns to `dict` in order.
    pub fn add_to(&self, py: Python<'_>, dict: &Bound<'_, PyDict>) -> PyResult<()> {
        for (name, array) in self.names.iter().zip(&self.arrays) {
            dict.set_item(name, array.clone_ref(py))?;
        }
        Ok(())
    }
}

/// A pandas DataFrame of `first` (a named index column such as time or frequency) and the
/// columns of each of `rest`, in order; an ImportError saying how to get pandas without it.
pub fn data_frame<'py>(
    py: Python<'py>,
    first: (&str, &Py<PyArray1<f64>>),
    add_rest: impl FnOnce(&Bound<'py, PyDict>) -> PyResult<()>,
) -> PyResult<Bound<'py, PyAny>> {
    let pandas = py
        .import("pandas")
        .map_err(|_| PyImportError::new_err("to_pandas() needs pandas: pip install pandas"))?;
    let dict = PyDict::new(py);
    dict.set_item(first.0, first.1.clone_ref(py))?;
    add_rest(&dict)?;
    pandas.call_method1("DataFrame", (dict,))
}
