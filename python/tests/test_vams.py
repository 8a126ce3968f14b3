"""The Python package against the CLI: check, run (generics, the arrays against the CSV of the
same run, reports, stats), op, dae, ac, noise, dc, the design-space sweep, and the errors."""

import csv
import math
import subprocess

import numpy as np
import pytest

import vams

BAD = """\
entity bad is
end entity bad;

architecture a of bad is
  signal s : bit;
begin
  s <= not_declared;
end architecture a;
"""


def test_check_clean_sources_give_no_diagnostics(root):
    assert vams.check(root / "tests" / "run" / "tb_rc.vhd") == []
    assert vams.check([str(root / "models")]) == []


def test_check_reports_an_error_with_its_place(tmp_path):
    path = tmp_path / "bad.vhd"
    path.write_text(BAD)
    found = vams.check(path)
    assert len(found) == 1
    d = found[0]
    assert d.severity == "error"
    assert d.file == str(path)
    assert (d.line, d.column) == (7, 8)
    assert "not_declared" in d.message
    assert d.code.startswith("vams::")
    assert f"{path}:7:8" in d.text
    assert d.text == str(d)


def test_run_gives_time_and_named_columns(root):
    r = vams.run(root / "tests" / "run" / "tb_rc.vhd", "tb_rc")
    assert r.time.dtype == np.float64 and r["vout"].dtype == np.float64
    assert r.time[0] == 0.0 and r.time[-1] == pytest.approx(5e-3)
    assert "vout" in r.columns and "dut.vout" in r.columns and "vout" in r
    assert r.units["vout"] == "V"
    # The closed form of the test bench: 1 - exp(-1) one time constant after the step.
    assert np.interp(2e-3, r.time, r["vout"]) == pytest.approx(1 - math.exp(-1), abs=5e-3)
    assert r.outcome == "finished" and not r.failed and r.reports == []
    assert r.stats["accepted_steps"] > 10
    assert r.stats["newton_iterations"] >= r.stats["accepted_steps"]
    with pytest.raises(KeyError, match="did you mean `vout`"):
        r["vuot"]


def test_generics_change_the_run(root):
    path = root / "tests" / "run" / "tb_rc.vhd"
    # vout(t) = 1 - exp(-(t - 1 ms) / RC): with r = 2 kOhm, one time constant is at 3 ms.
    fast = vams.run(path, "tb_rc", stop="4 ms")
    slow = vams.run(path, "tb_rc", stop=4e-3, generics={"dut.r": 2.0e3})
    assert np.interp(3e-3, slow.time, slow["vout"]) == pytest.approx(1 - math.exp(-1), abs=5e-3)
    assert np.interp(3e-3, fast.time, fast["vout"]) == pytest.approx(1 - math.exp(-2), abs=5e-3)
    # The bench's own checks now fail (severity error: reported, the run goes on).
    assert [rep.severity for rep in slow.reports] == ["error", "error"]
    assert slow.reports[0].time == pytest.approx(2e-3)
    assert "expected 0.63212" in slow.reports[0].message
    assert slow.reports[0].file.endswith("tb_rc.vhd") and slow.reports[0].line > 0


def test_generic_values_are_vhdl_literals(root):
    path = root / "tests" / "run" / "tb_rc.vhd"
    default = vams.run(path, "tb_rc")
    # 1e-06 is written 1.0e-6 (VHDL's reals need the point); an int and a string as given.
    same = vams.run(path, "tb_rc", generics={"dut.c": 1e-06, "dut.r": "1.0e3"})
    assert np.array_equal(same["vout"], default["vout"])
    with pytest.raises(ValueError, match="not a VHDL identifier"):
        vams.run(path, "tb_rc", generics={"no such": 1.0})
    with pytest.raises(ValueError, match="a bool, an int, a float or a string"):
        vams.run(path, "tb_rc", generics={"r": [1.0]})


def read_csv(path):
    with open(path, newline="") as f:
        rows = [row for row in csv.reader(f) if row and not row[0].startswith("#")]
    header, body = rows[0], rows[1:]
    return header, [[float(x) for x in row] for row in body]


@pytest.mark.parametrize(
    "source, top",
    [("tests/run/tb_rc.vhd", "tb_rc"), ("models", "tb_tracking")],
)
def test_arrays_equal_the_csv_of_the_same_run_bit_for_bit(root, tmp_path, vams_binary, source, top):
    out = tmp_path / "run.csv"
    subprocess.run(
        [vams_binary, "run", str(root / source), "--top", top, "-o", str(out)],
        check=True,
        capture_output=True,
    )
    header, rows = read_csv(out)
    r = vams.run(root / source, top)
    assert header == ["time"] + r.columns
    table = np.array(rows, dtype=np.float64)
    assert table.shape == (len(r.time), len(header))
    assert np.array_equal(table[:, 0], r.time)
    for k, name in enumerate(r.columns, start=1):
        # Bit for bit: the CSV holds the shortest text that reads back to the same double.
        assert np.array_equal(table[:, k].view(np.uint64), r[name].view(np.uint64)), name


def test_a_failure_assertion_ends_the_run_without_an_exception(root):
    r = vams.run(root / "tests" / "run" / "failure.vhd")
    assert r.failed and r.outcome == "failed"
    assert r.end_time == pytest.approx(3e-3)
    assert [(x.severity, x.message) for x in r.reports] == [
        ("note", "starting"),
        ("error", "something is off"),
        ("failure", "giving up"),
    ]
    assert r.reports[-1].text.startswith("3 ms: failure: giving up")


def test_a_bad_model_raises_with_the_diagnostic_text(tmp_path):
    path = tmp_path / "bad.vhd"
    path.write_text(BAD)
    with pytest.raises(vams.VamsError) as caught:
        vams.run(path, "bad", stop=1e-3)
    message = str(caught.value)
    assert f"{path}:7:8" in message and "not_declared" in message
    assert "analysis error(s)" in message
    assert [d.line for d in caught.value.diagnostics] == [7]
    assert caught.value.result is None
    assert issubclass(vams.VamsError, Exception)


def test_argument_and_input_errors(root, tmp_path):
    with pytest.raises(vams.VamsError, match="cannot read"):
        vams.check(tmp_path / "missing.vhd")
    endless = tmp_path / "x.vhd"
    endless.write_text("entity x is end;\narchitecture a of x is begin end;\n")
    with pytest.raises(vams.VamsError, match="no stop time"):
        vams.run(endless)
    with pytest.raises(ValueError):
        vams.run(root / "tests" / "run" / "tb_rc.vhd", stop="soon")
    with pytest.raises(vams.VamsError, match="several entities could be the top"):
        vams.run(root / "models")


def test_op_is_the_quiescent_point(root):
    point = vams.op(root / "tests" / "ac" / "rc_lowpass.vhd")
    # The 2 V bias through the resistor into the capacitor: no current, vout = vin.
    assert point["vin"] == pytest.approx(2.0)
    assert point["vout"] == pytest.approx(2.0)
    assert point["ir"] == pytest.approx(0.0, abs=1e-12)


def test_dae_gives_text_and_data(root):
    d = vams.dae(root / "tests" / "ac" / "rc_lowpass.vhd")
    assert str(d) == d.text and d.text.startswith("unknowns (")
    names = [u["name"] for u in d.unknowns]
    assert "vout" in names
    assert any(u["differential"] for u in d.unknowns)
    assert all(e["residual"] for e in d.equations)
    assert any(e["origin"].endswith("rc_lowpass.vhd:17") for e in d.equations)
    assert d.eliminated and d.solver_unknowns
    for e in d.eliminated:
        assert f"= {e['formula']}   (equation {e['equation']})" in d.text


def test_ac_corner_of_the_rc_low_pass(root):
    r_ohm, c_farad = 1.0e3, 100.0e-9
    corner = 1 / (2 * math.pi * r_ohm * c_farad)  # 1591.55 Hz
    ac = vams.ac(
        root / "tests" / "ac" / "rc_lowpass.vhd",
        start="100Hz",
        stop=1e4,
        points_per_decade=400,
        probes=["vout"],
    )
    assert ac["vout"].dtype == np.complex128
    gain_db = 20 * np.log10(np.abs(ac["vout"]))
    # The -3.01 dB point, interpolated on the grid, within 0.5 % of 1 / (2 pi R C).
    measured = np.interp(-10 * math.log10(2), gain_db[::-1], ac.frequency[::-1])
    assert measured == pytest.approx(corner, rel=5e-3)
    # At the corner the phase is -45 degrees.
    k = np.argmin(np.abs(ac.frequency - corner))
    assert np.degrees(np.angle(ac["vout"][k])) == pytest.approx(-45, abs=1)


def test_ac_without_a_spectral_source_raises(root):
    with pytest.raises(vams.VamsError, match="no spectral source"):
        vams.ac(root / "tests" / "ac" / "no_source.vhd", start=1, stop=10)


def test_pandas_frames(root):
    pd = pytest.importorskip("pandas")
    r = vams.run(root / "tests" / "run" / "tb_rc.vhd", "tb_rc")
    frame = r.to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == ["time"] + r.columns
    assert np.array_equal(frame["vout"].to_numpy(), r["vout"])


def test_noise_of_a_divider_is_4kt_times_the_parallel_resistance(root):
    n = vams.noise(root / "tests" / "noise" / "divider.vhd", "vout", start=1, stop=100)
    parallel = 3.0e3 * 1.0e3 / 4.0e3
    # Far below the corner 1 / (2 pi (r1 || r2) c), 212 kHz: the white thermal noise.
    assert n.total[0] == pytest.approx(4 * 1.380649e-23 * 300.0 * parallel, rel=1e-6)
    parts = n.contributions
    assert len(parts) == 2
    assert np.allclose(sum(parts.values()), n.total, rtol=1e-12)
    assert n.input_gain is None


def test_dc_sweep_of_an_integer_generic(root):
    # n + 1 equal resistors from 1 V: vout = 1 / (n + 1).
    d = vams.dc(root / "tests" / "dc" / "divider.vhd", ("n", 1, 5, 1), probes=["vout"])
    assert d.name == "n" and d.columns == ["vout"]
    assert list(d.values) == [1, 2, 3, 4, 5]
    assert np.allclose(d["vout"], 1 / (d.values + 1), rtol=1e-9)
    assert set(d.direction) == {1.0}


def test_dc_sweep_stops_where_there_is_no_quiescent_point(root):
    with pytest.raises(vams.VamsError, match="stopped at p = -0.25") as caught:
        vams.dc(root / "tests" / "dc" / "no_root.vhd", ("p", 1, -1, -0.25))
    assert "x * x == p" in str(caught.value)
    partial = caught.value.result
    assert list(partial.values) == [1.0, 0.75, 0.5, 0.25, 0.0]
    assert np.allclose(partial["x"] ** 2, partial.values, atol=1e-6)


# tests/sweep/decay.vhd over a 3 x 2 grid: x' = -x / tau, and an assertion of severity failure
# (a failed run) where tau exceeds tau_max.
SWEEP = """\
[design]
files = ["{model}"]
top = "tb_decay"

[grid.parameters]
tau = [0.5e-3, 1.0e-3, 2.0e-3]
tau_max = [1.0, 1.5e-3]

[metrics]
fall = {{ kind = "cross", of = "x", value = 0.36787944117144233, edge = "falling" }}
mean = {{ kind = "mean", of = "x" }}
"""


def sweep_spec(root, tmp_path):
    spec = tmp_path / "decay.toml"
    spec.write_text(SWEEP.format(model=(root / "tests" / "sweep" / "decay.vhd").as_posix()))
    return spec


def test_sweep_columns_equal_its_result_table(root, tmp_path):
    out = tmp_path / "out"
    result = vams.sweep(sweep_spec(root, tmp_path), out, jobs=2)
    assert result.dir == out
    assert len(result) == 6
    assert "6 runs: 5 ok, 1 failed" in result.summary
    with open(out / "results.csv", newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header, cells = rows[0], rows[1:]
    assert result.columns == header
    assert len(cells) == 6
    for k, name in enumerate(header):
        column = result[name]
        if name in ("run", "tau", "tau_max", "fall", "mean"):
            assert isinstance(column, np.ndarray) and column.dtype == np.float64
            expected = np.array([float(r[k]) if r[k] else math.nan for r in cells])
            assert np.array_equal(column, expected, equal_nan=True), name
        else:
            assert column == [r[k] for r in cells], name
    ok = np.array(result["status"]) == "ok"
    assert np.isfinite(result["mean"][ok]).all()
    assert np.isnan(result["fall"][~ok]).all()
    assert all("tau beyond tau_max" in m for m in np.array(result["message"])[~ok])
    frame = result.to_pandas()
    assert list(frame.columns) == header and len(frame) == 6
    # The finished table is kept: resuming runs nothing and gives the same columns.
    again = vams.sweep(sweep_spec(root, tmp_path), out, resume=True)
    assert np.array_equal(again["mean"], result["mean"], equal_nan=True)
    with pytest.raises(KeyError):
        result["no_such_column"]


def test_a_bad_sweep_spec_raises_with_the_diagnostic_text(root, tmp_path):
    with pytest.raises(vams.VamsError, match="cannot read the sweep spec"):
        vams.sweep(tmp_path / "missing.toml", tmp_path / "out")
    spec = sweep_spec(root, tmp_path)
    spec.write_text(spec.read_text().replace("tau_max = [", "tau_mux = ["))
    with pytest.raises(vams.VamsError, match="decay.toml:7: the design has no") as caught:
        vams.sweep(spec, tmp_path / "out")
    assert "tau_mux = [1.0, 1.5e-3]" in str(caught.value)
    assert "its generics are `tau`, `tau_max` and `steps`" in str(caught.value)
    spec.write_text("[design\n")
    with pytest.raises(vams.VamsError, match="unclosed table"):
        vams.sweep(spec, tmp_path / "out")
