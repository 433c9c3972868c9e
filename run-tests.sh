#!/usr/bin/env bash
# Every test: the Rust core's unit, property, physics and C-ABI tests.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
cargo test --workspace
