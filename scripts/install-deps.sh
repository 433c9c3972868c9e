#!/usr/bin/env bash
# Installs what granbond needs on a fresh Debian machine and is a no-op when
# it is all there: the Rust toolchain must exist (rustup's cargo); Python
# plotting packages come from PyPI.
set -euo pipefail
if ! command -v cargo >/dev/null 2>&1; then
    echo "install-deps: cargo not found; install Rust (https://rustup.rs) first" >&2
    exit 1
fi
if ! command -v cc >/dev/null 2>&1; then
    echo "install-deps: installing a C compiler (apt)"
    apt-get update -qq && apt-get install -y -qq gcc g++ >/dev/null
fi
if ! python3 -c "import matplotlib, numpy" >/dev/null 2>&1; then
    echo "install-deps: installing matplotlib and numpy (pip)"
    python3 -m pip install --quiet --root-user-action=ignore matplotlib numpy
fi
