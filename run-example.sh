#!/usr/bin/env bash
# Flagship example, end to end, in the real engine: a bonded spherical
# agglomerate (about 3,600 spheres, 10,000 cohesion bond/nonlinear bonds)
# hits a wall and fragments (stress breakage), run by the stock Debian
# LIGGGHTS 3.8 through build/bin/liggghts-granbond. Installs what is missing,
# builds, runs with progress output (thermo), plots, and says where the
# results are. Extra arguments go to LIGGGHTS (e.g. -var speed 5).
# NP=2 ./run-example.sh runs on two MPI ranks.
set -euo pipefail
cd "$(dirname "$0")"
scripts/install-deps.sh
echo "== building (cmake: Rust core + LIGGGHTS adapter)"
cmake -S . -B build >/dev/null
cmake --build build -j2
ex=examples/agglomerate_liggghts
out=$ex/out
echo "== running the agglomerate impact in LIGGGHTS ($ex/in.agglomerate_liggghts; thermo every 100 of 5000 steps)"
examples/run-liggghts.sh agglomerate_liggghts "$@"
echo "done: plots in $out/broken_bonds.png, $out/fragment_sizes.png, $out/fragments.png;"
echo "      ParaView: $out/post/agglomerate_*.vtk (time series) and $out/fragments.vtk (final fragments);"
echo "      glyph the points by 'radius'"
