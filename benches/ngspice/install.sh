#!/usr/bin/env sh
# Installs ngspice (Debian/Ubuntu): the reference of `tests/differential.rs` and of the benchmarks
# that compare vams with it (`.ci/run` calls this; without ngspice those print a skip).
set -eu
if command -v ngspice >/dev/null 2>&1; then
    echo "ngspice already installed: $(command -v ngspice)"
    exit 0
fi
if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "not root and no sudo: install ngspice by hand" >&2
    exit 1
fi
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends ngspice
ngspice --version | head -n 2
