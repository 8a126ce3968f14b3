#!/usr/bin/env sh
# Installs ngspice (Debian/Ubuntu): the reference of `tests/it/differential.rs` and of the benchmarks
# that compare vams with it (`.ci/run` calls this; without ngspice those print a skip).
set -eu
exec sh "$(dirname "$0")/../../.ci/install-package.sh" ngspice
