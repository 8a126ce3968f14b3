"""Shared paths for the tests of the Python package: the repository's models and test
sources, and the `vams` binary the bit-for-bit comparison runs."""

import os
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def root():
    return ROOT


@pytest.fixture
def vams_binary():
    """The CLI built from the same checkout: $VAMS_BIN (CI sets it), else target/release or
    target/debug, else `vams` on PATH."""
    given = os.environ.get("VAMS_BIN")
    if given:
        return given
    for profile in ("release", "debug"):
        candidate = ROOT / "target" / profile / "vams"
        if candidate.exists():
            return str(candidate)
    found = shutil.which("vams")
    if found:
        return found
    pytest.skip("no vams binary: build it with `cargo build` or set VAMS_BIN")
