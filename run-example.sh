#!/usr/bin/env bash
# Flagship example, end to end: a bonded spherical agglomerate hits a wall
# and fragments (stress breakage). Installs what is missing, builds, runs
# with progress output, plots, and says where the results are.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
out=examples/agglomerate/out
echo "== building (release)"
cargo build --release --quiet --example scene
echo "== running the agglomerate impact (Rust scene runner)"
target/release/examples/scene agglomerate "$out" "$@"
echo "== plotting"
python3 examples/agglomerate/plot.py "$out"
echo "done: plots in $out/*.png, ParaView snapshots in $out/vtk/"
