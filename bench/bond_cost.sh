#!/usr/bin/env bash
# Cost of one bond step / contact step, per element.
#
# Runs the criterion benchmark rust-core/benches/kernels.rs and prints one
# row per variant: mean ns per element-step with the working set in cache
# (1e3 pairs) and memory bound (1e6 pairs), taken from criterion's
# target/criterion/<group>/<variant>/<n>/new/{benchmark,estimates}.json.
#
# Usage: bench/bond_cost.sh [--no-run-bench] [extra args for the bench binary]
#   --no-run-bench   only print the table of the last run's results
# Example: bench/bond_cost.sh full_6dof     (criterion filter)
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
target="${CARGO_TARGET_DIR:-$root/target}"
run=1
if [[ "${1:-}" == "--no-run-bench" ]]; then
    run=0
    shift
fi

stamp="$(mktemp)"
trap 'rm -f "$stamp"' EXIT
if [[ $run == 1 ]]; then
    # Only results written after this point are reported.
    touch "$stamp"
    sleep 1
    (cd "$root" && cargo bench --bench kernels --no-run)
    load_before="$(cut -d' ' -f1-3 /proc/loadavg)"
    (cd "$root" && cargo bench --bench kernels -- "$@")
    echo "load average before / after the run: $load_before / $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores)"
else
    touch -d '1970-01-01' "$stamp"
fi

python3 - "$target/criterion" "$stamp" <<'PY'
import json, os, sys

base, stamp = sys.argv[1], sys.argv[2]
since = os.path.getmtime(stamp)
rows = {}   # (kind, variant) -> {size: ns}
order = []
for dirpath, _, files in os.walk(base):
    if os.path.basename(dirpath) != "new" or "estimates.json" not in files:
        continue
    est = os.path.join(dirpath, "estimates.json")
    if os.path.getmtime(est) < since:
        continue
    with open(os.path.join(dirpath, "benchmark.json")) as f:
        bench = json.load(f)
    with open(est) as f:
        mean = json.load(f)["mean"]
    elements = (bench.get("throughput") or {}).get("Elements")
    if not elements:
        continue
    group = bench["group_id"]            # e.g. bond_1e3
    kind, _, size = group.rpartition("_")
    key = (kind, bench["function_id"])
    if key not in rows:
        rows[key] = {}
        order.append(key)
    rows[key][size] = (mean["point_estimate"] / elements,
                       (mean["confidence_interval"]["upper_bound"]
                        - mean["confidence_interval"]["lower_bound"]) / 2 / elements)

if not rows:
    sys.exit("no criterion results found under " + base)

kinds = {"bond": 0, "ffi": 1, "contact": 2}
variants = ["full_6dof", "no_twist", "no_bend", "normal_shear", "normal_only",
            "tension_only", "damping_off", "smooth_damping", "zeroed_twist_bend",
            "zeroed_shear_twist_bend", "full_6dof_ffi_single", "voigt_rolling",
            "voigt_no_rolling"]
def rank(key):
    kind, name = key
    return (kinds.get(kind, 9), variants.index(name) if name in variants else 99, name)

def cell(d, size):
    if size not in d:
        return "-"
    ns, half = d[size]
    return f"{ns:7.2f} ±{half:5.2f}"

print()
print(f"{'kernel':8} {'variant':26} {'1e3 (in cache) ns/step':>24} {'1e6 ns/step':>16}")
print("-" * 78)
for key in sorted(order, key=rank):
    kind, name = key
    print(f"{kind:8} {name:26} {cell(rows[key], '1e3'):>24} {cell(rows[key], '1e6'):>16}")
print()
print("mean over criterion samples per element-step; ± = half-width of the 95 % CI")
PY
