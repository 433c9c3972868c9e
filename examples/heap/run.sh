#!/usr/bin/env bash
# The heap deck four times (two at a time on a 2-core machine), then plot.py:
#   voigt_rolling  model voigt tangential voigt rolling_friction voigt
#   voigt          model voigt tangential voigt            (no rolling resistance)
#   stock_epsd2    model hooke/stiffness tangential history rolling_friction epsd2
#   stock          model hooke/stiffness tangential history (no rolling resistance)
# Output in examples/heap/out/<case>/ and examples/heap/out/heap.png.
# Extra arguments go to every LIGGGHTS run (e.g. -var mur 0.3).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
engine="$here/../../build/bin/liggghts-granbond"
[ -x "$engine" ] || { echo "build first: cmake -S . -B build && cmake --build build -j2" >&2; exit 1; }
out="$here/out"
rm -rf "$out"
declare -A models=(
    [voigt_rolling]="model voigt tangential voigt rolling_friction voigt"
    [voigt]="model voigt tangential voigt"
    [stock_epsd2]="model hooke/stiffness tangential history rolling_friction epsd2"
    [stock]="model hooke/stiffness tangential history"
)
declare -A settings=(
    [voigt_rolling]="noAttraction on" [voigt]="noAttraction on"
    [stock_epsd2]="absolute_damping on" [stock]="absolute_damping on"
)
run() {
    mkdir -p "$out/$1"
    (cd "$out/$1" && "$engine" -in "$here/in.heap" -log log.liggghts \
        -var models "${models[$1]}" -var settings "${settings[$1]}" "${@:2}" > screen.txt 2>&1) ||
        { echo "heap: $1 failed, see $out/$1/screen.txt" >&2; return 1; }
    echo "heap: $1 done ($(awk '/^Loop time/ { t += $4 } END { printf "%.1f s", t }' "$out/$1/log.liggghts"))"
}
for pair in "voigt_rolling stock_epsd2" "voigt stock"; do
    set -- $pair "${@:1}"
    a=$1; b=$2; shift 2
    echo "heap: running $a and $b (thermo in $out/<case>/screen.txt)"
    run "$a" "$@" & pa=$!
    run "$b" "$@" & pb=$!
    wait $pa; wait $pb
done
python3 "$here/plot.py" "$out"
