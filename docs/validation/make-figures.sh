#!/usr/bin/env bash
# The figures of docs/validation.md: runs every mode of
# tests/validation/check_validation.py (the ctests validation_*) with --json,
# then draws the PNGs into docs/figures/validation/ (plot.py, matplotlib).
#   docs/validation/make-figures.sh [BUILD_DIR]     (default: build)
# VALIDATION_WORK=DIR keeps the runs, logs and JSON files in DIR.
# A failing check still writes its JSON; the script stops after drawing.
set -uo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "${1:-build}")
lig="$build/bin/liggghts-granbond"
lmp="$build/bin/lmp-granbond"
work=${VALIDATION_WORK:-$(mktemp -d)}
mkdir -p "$work"
out=docs/figures/validation
mkdir -p "$out"
status=0
for mode in normal oblique spinning tangential rolling spindown hertz cantilever beam-frequency chain-waves; do
  engines=(--liggghts "$lig" --lammps "$lmp")
  case $mode in
    rolling|hertz|cantilever) engines=(--liggghts "$lig") ;;
    chain-waves) engines=(--lammps "$lmp") ;;
  esac
  python3 tests/validation/check_validation.py --mode "$mode" --workdir "$work/$mode" \
      "${engines[@]}" --json "$work/$mode.json" > "$work/$mode.log" 2>&1 || status=1
  tail -n 1 "$work/$mode.log" | sed "s/^/$mode: /"
done
python3 docs/validation/plot.py "$work" "$out"
[ -n "${VALIDATION_WORK:-}" ] || rm -rf "$work"
exit $status
