#!/usr/bin/env bash
# Every granbond keyword of the base decks in tests/adapters/decks/mutation/
# given every bad value (tests/adapters/check_deck_mutations.py --all), both
# engines: prints each run that crashed, hung, gave nan or stopped without
# naming the input, then the table of outcomes. Takes a few minutes on two
# cores.
#
#   scripts/bad_input_campaign.sh [BUILD_DIR] [WORK_DIR]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
work="${2:-$(mktemp -d)}"
python3 "$root/tests/adapters/check_deck_mutations.py" --all --report \
  --liggghts "$build/bin/liggghts-granbond" --lammps "$build/bin/lmp-granbond" --workdir "$work"
