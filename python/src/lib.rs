//! `vams` for Python: check, simulate and analyse VHDL-AMS models from a notebook.
//!
//! One extension module over the `vams` crate (the same library as the CLI): each function
//! takes the CLI command's arguments, compiles the sources with the GIL released, and gives
//! back Python objects (NumPy arrays for waveforms and responses). Errors raise
//! [`error::VamsError`] with the diagnostics' text; nothing here aborts the interpreter.

mod analyses;
mod check;
mod design;
mod design_space;
mod diagnostic;
mod error;
mod frame;
mod interrupt;
mod run;
mod sweep;

use pyo3::prelude::*;

#[pymodule]
fn vams(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("VamsError", m.py().get_type::<error::VamsError>())?;
    m.add_function(wrap_pyfunction!(check::check, m)?)?;
    m.add_function(wrap_pyfunction!(run::run, m)?)?;
    m.add_function(wrap_pyfunction!(analyses::op, m)?)?;
    m.add_function(wrap_pyfunction!(analyses::dae, m)?)?;
    m.add_function(wrap_pyfunction!(analyses::ac, m)?)?;
    m.add_function(wrap_pyfunction!(analyses::noise, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::dc, m)?)?;
    m.add_function(wrap_pyfunction!(design_space::sweep, m)?)?;
    m.add_class::<diagnostic::Diagnostic>()?;
    m.add_class::<run::RunResult>()?;
    m.add_class::<run::Report>()?;
    m.add_class::<analyses::Dae>()?;
    m.add_class::<analyses::AcResult>()?;
    m.add_class::<analyses::NoiseResult>()?;
    m.add_class::<sweep::DcResult>()?;
    m.add_class::<design_space::SweepResult>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
