"""docs/notebooks/headlight.ipynb runs top to bottom (it asserts what it shows), so that it
cannot rot. CI installs nbclient, ipykernel and matplotlib; elsewhere the test skips without
them."""

import time

import pytest


def test_the_headlight_notebook_runs(root):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("matplotlib")
    pytest.importorskip("ipykernel")
    path = root / "docs" / "notebooks" / "headlight.ipynb"
    notebook = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(
        notebook,
        timeout=300,
        kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
    )
    started = time.monotonic()
    client.execute()
    print(f"executed {path.name} in {time.monotonic() - started:.1f} s")
    images = [
        output
        for cell in notebook.cells
        if cell.cell_type == "code"
        for output in cell.get("outputs", [])
        if "image/png" in output.get("data", {})
    ]
    assert len(images) == 2
