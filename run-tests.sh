#!/usr/bin/env bash
# Every test: the habits (rustfmt, clippy without warnings, the core's
# rustdoc without warnings), the Rust core's unit, property, physics and
# C-ABI tests, then the engine adapters built with CMake and their
# engine-level tests (ctest).
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
cargo fmt --all -- --check
cargo clippy --workspace --all-targets -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps -p granbond
cargo test --workspace
cmake -S . -B build
cmake --build build -j2
ctest --test-dir build --output-on-failure
