#!/usr/bin/env sh
# Installs GHDL (Debian/Ubuntu's `ghdl`, the mcode backend): the reference of
# `tests/ghdl_differential.rs` (`.ci/run` calls this; without GHDL that test prints a skip).
set -eu
if command -v ghdl >/dev/null 2>&1; then
    echo "ghdl already installed: $(command -v ghdl)"
    exit 0
fi
if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "not root and no sudo: install ghdl by hand" >&2
    exit 1
fi
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends ghdl
ghdl --version | head -n 1
