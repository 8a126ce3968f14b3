#!/usr/bin/env sh
# Installs the Debian/Ubuntu package $1 providing the command $2 (default: $1), with sudo
# where not root; exits 0 at once when the command is there already.
set -eu
package="$1"
command_name="${2:-$1}"
if command -v "$command_name" >/dev/null 2>&1; then
    echo "$command_name already installed: $(command -v "$command_name")"
    exit 0
fi
if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
elif command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
else
    echo "not root and no sudo: install $package by hand" >&2
    exit 1
fi
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "$package"
"$command_name" --version | head -n 2
