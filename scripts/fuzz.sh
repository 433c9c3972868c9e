#!/usr/bin/env bash
# Fuzzes the C ABI for MINUTES minutes, then runs the C harness under
# AddressSanitizer and UBSanitizer, and prints a summary (docs/fuzzing.md).
#
#   scripts/fuzz.sh MINUTES [--keep]
#
# The fuzzer starts from rust-core/fuzz/corpus/abi and works on a copy
# under target/fuzz-run/; --keep writes the minimised corpus back (the
# regression-* inputs are always kept). Needs the nightly toolchain and
# cargo-fuzz (installed from the crates registry if missing). Exits non-zero
# if anything crashed or a sanitizer reported.
set -euo pipefail

minutes=${1:-}
keep=${2:-}
if ! [[ "$minutes" =~ ^[0-9]+$ ]] || [ "$minutes" -lt 1 ]; then
    echo "usage: $0 MINUTES [--keep]" >&2
    exit 2
fi

root=$(cd "$(dirname "$0")/.." && pwd)
core="$root/rust-core"
run="$root/target/fuzz-run"
corpus="$core/fuzz/corpus/abi"
export CARGO_BUILD_JOBS=${CARGO_BUILD_JOBS:-2}

rustup toolchain list | grep -q '^nightly' || rustup toolchain install nightly --profile minimal
cargo +nightly fuzz --version >/dev/null 2>&1 || cargo install cargo-fuzz --locked

rm -rf "$run"
mkdir -p "$run/corpus" "$run/artifacts" "$run/minimised"
cp "$corpus"/* "$run/corpus/"

echo "== building the fuzz target (nightly, AddressSanitizer, debug assertions)"
cd "$core"
cargo +nightly fuzz build abi
target="$core/fuzz/target/x86_64-unknown-linux-gnu/release/abi"

echo "== fuzzing for $minutes minute(s)"
# one worker (-fork=1) that goes on after a crash, so the run lasts its time
# and every crashing input is kept
set +e
"$target" -fork=1 -ignore_crashes=1 -max_total_time=$((minutes * 60)) \
    -artifact_prefix="$run/artifacts/" "$run/corpus" >"$run/fuzz.log" 2>&1
fuzz_rc=$?
set -e
last=$(grep -E '^#[0-9]+: cov:' "$run/fuzz.log" | tail -1 || true)
executions=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")

# each crashing input once more, alone, to tell a panic from a sanitizer report
panics=0
asan=0
for a in "$run"/artifacts/*; do
    [ -e "$a" ] || continue
    log="$a.log"
    "$target" "$a" >"$log" 2>&1 || true
    if grep -q 'panicked at' "$log"; then panics=$((panics + 1)); fi
    if grep -qE 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' "$log"; then asan=$((asan + 1)); fi
done
crashes=$(find "$run/artifacts" -type f ! -name '*.log' | wc -l)

echo "== minimising the corpus"
"$target" -set_cover_merge=1 "$run/minimised" "$run/corpus" >"$run/merge.log" 2>&1
if [ "$keep" = "--keep" ]; then
    find "$corpus" -type f ! -name 'regression-*' -delete
    cp "$run/minimised"/* "$corpus/"
    echo "kept $(ls "$corpus" | wc -l) inputs ($(du -sh --apparent-size "$corpus" | cut -f1)) in rust-core/fuzz/corpus/abi"
fi

echo "== C harness with AddressSanitizer and UBSanitizer"
# the core itself instrumented too (nightly -Zsanitizer=address, debug
# assertions and overflow checks on), linked with the C harness
RUSTFLAGS="-Zsanitizer=address" cargo +nightly build --lib \
    --target x86_64-unknown-linux-gnu --target-dir "$run/asan-target" -q
lib="$run/asan-target/x86_64-unknown-linux-gnu/debug/libgranbond.a"
cc -std=c99 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
    -I "$core/include" "$core"/tests/c/*.c "$lib" -lpthread -ldl -lm -o "$run/abi_harness"
set +e
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "$run/abi_harness" >"$run/harness.log" 2>&1
harness_rc=$?
set -e
harness_reports=$(grep -cE 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:' "$run/harness.log" || true)

echo "== answers of the fuzzed corpus"
GRANBOND_FUZZ_CORPUS="$run/corpus" cargo test -q --test fuzz_corpus \
    every_corpus_input_is_answered_with_ok_or_an_error_code -- --nocapture >"$run/answers.log" 2>&1 || true
sed -n '/inputs; answers per entry point/,/all entries:/p' "$run/answers.log"

echo
echo "== summary"
echo "fuzzing:            $minutes min, ${executions:-?} executions, exit $fuzz_rc (log: $run/fuzz.log)"
echo "crashing inputs:    $crashes (panics $panics, sanitizer reports $asan; in $run/artifacts)"
echo "corpus:             $(ls "$run/corpus" | wc -l) inputs, minimised to $(ls "$run/minimised" | wc -l) ($(du -sh --apparent-size "$run/minimised" | cut -f1))"
echo "sanitized harness:  $(tail -1 "$run/harness.log"), exit $harness_rc, $harness_reports sanitizer reports (log: $run/harness.log)"
grep -E '^  all entries:' "$run/answers.log" | sed 's/^  all entries:/status codes seen: /' || true
if grep -q 'broke the ABI' "$run/answers.log"; then
    echo "corpus replay:      FAILED (see $run/answers.log)"
    exit 1
fi
[ "$crashes" -eq 0 ] && [ "$harness_rc" -eq 0 ] && [ "$harness_reports" -eq 0 ]
