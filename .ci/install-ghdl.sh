#!/usr/bin/env sh
# Installs GHDL (Debian/Ubuntu's `ghdl`, the mcode backend): the reference of
# `tests/it/ghdl_differential.rs` (`.ci/run` calls this; without GHDL that test prints a skip).
set -eu
exec sh "$(dirname "$0")/install-package.sh" ghdl
