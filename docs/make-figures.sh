#!/usr/bin/env bash
# Every figure of docs/speed-accuracy.md: builds the study (release), runs it
# (CSV files into docs/figures/data/), then draws the PNGs into docs/figures/.
#   docs/make-figures.sh            full grid (a few minutes on 2 cores)
#   docs/make-figures.sh --quick    coarse grid (seconds), for a smoke test
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/figures
mkdir -p "$out/data"
cargo build --release -p granbond-scene --example study
./target/release/examples/study "$out/data" "$@"
python3 docs/plots.py "$out/data" "$out"
