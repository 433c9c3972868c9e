#!/usr/bin/env python3
"""LIGGGHTS-INL's own bond/nonlinear examples through INL's build and
through liggghts-granbond, without and with `inlCompatible on`: prints, per
deck, the largest difference over the run of each column relative to its
range in INL's output (the metric of tests/validation/inl/check_inl.py).

    bench/inl_examples.py --inl <INL>/src/lmp_mpi_no_vtk --examples <INL>/examples/LIGGGHTS/INL \\
        --liggghts build/bin/liggghts-granbond --workdir /tmp/inl_examples [--mm-steps 50000000]

The tension decks' clump (`fix particletemplate/multiplespheres` +
`create_particles`, LIGGGHTS 4.x) becomes one `create_atoms` per sphere of
its template, centred on the template's mean position; INL centres the
9-sphere template on a Monte Carlo estimate of its centre, read here from
INL's output (sphere 1 is frozen). The `chain_bending_mm_*` decks (5e8
steps) run the first `--mm-steps` steps.
"""

import argparse
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "validation", "inl"))
import check_inl  # noqa: E402

PRIMES = os.path.join(HERE, "..", "tests", "validation", "inl", "tension_3_spheres", "prime_numbers.txt")
CASES = [
    ("cohesive_bond_nonlinear_compression/chain_bending_mm_1", "in.chain_bending.lmp", "output.csv"),
    ("cohesive_bond_nonlinear_compression/chain_bending_mm_2", "in.chain_bending.lmp", "output.csv"),
    ("cohesive_bond_nonlinear_compression/chain_bending_um_1", "in.chain_bending.lmp", "output.csv"),
    ("cohesive_bond_nonlinear_compression/chain_bending_um_2", "in.chain_bending.lmp", "output.csv"),
    ("cohesive_bond_nonlinear_tension/2_spheres", "in.particle_test", "out.loading.csv"),
    ("cohesive_bond_nonlinear_tension/3_spheres", "in.particle_test", "out.loading.csv"),
    ("cohesive_bond_nonlinear_tension/7_spheres", "in.particle_test", "out.loading.csv"),
    ("cohesive_bond_nonlinear_tension/9_spheres", "in.particle_test", "out.loading.csv"),
]


def without_clump(text, clump, inl_x1=None):
    """The deck with its clump placed by `create_atoms`; `inl_x1`: where
    INL put the template's first sphere along x, if not at the mean."""
    spheres = [[float(v) for v in line.split()] for line in open(clump, encoding="utf-8") if line.strip()]
    centre = [sum(s[k] for s in spheres) / len(spheres) for k in range(3)]
    if inl_x1 is not None:
        centre[0] = spheres[0][0] - inl_x1
    lines, out, k = text.splitlines(), [], 0
    while k < len(lines):
        line = lines[k]
        if line.startswith("fix") and "particletemplate/multiplespheres" in line:
            while lines[k].rstrip().endswith("&"):
                k += 1
        elif line.startswith("create_particles"):
            for s in spheres:
                out.append(f"create_atoms 1 single {s[0] - centre[0]!r} {s[1] - centre[1]!r} "
                           f"{s[2] - centre[2]!r} units box")
            out.append(f"set group all diameter {2 * spheres[0][3]!r} density ${{i_density}}")
        else:
            out.append(line)
        k += 1
    return "\n".join(out) + "\n"


def run(binary, folder, deck, text, work):
    if os.path.isdir(work):
        shutil.rmtree(work)
    shutil.copytree(folder, work, ignore=shutil.ignore_patterns("gold", "post", "*.vtk"))
    os.makedirs(os.path.join(work, "post"), exist_ok=True)
    shutil.copy(PRIMES, work)
    with open(os.path.join(work, deck), "w", encoding="utf-8") as f:
        f.write(text)
    proc = subprocess.run([binary, "-in", deck], cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          check=False)
    if proc.returncode != 0:
        raise SystemExit(f"{binary} failed in {work}:\n{proc.stdout.decode()[-2000:]}")


def differences(names, mine, theirs):
    out = {}
    for c, name in enumerate(names):
        if check_inl.SKIP.search(name):
            continue
        column = [row[c] for row in theirs]
        span = max(column) - min(column)
        if span > 0.0:
            out[name] = max(abs(a[c] - b[c]) / span for a, b in zip(mine, theirs))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--inl", required=True)
    ap.add_argument("--examples", required=True)
    ap.add_argument("--liggghts", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--mm-steps", type=int, default=50000000)
    a = ap.parse_args()
    a.inl, a.liggghts = os.path.abspath(a.inl), os.path.abspath(a.liggghts)
    for rel, deck, table in CASES:
        folder = os.path.join(a.examples, rel)
        name = rel.split("/")[-1]
        with open(os.path.join(folder, deck), encoding="utf-8") as f:
            text = f.read()
        text = text.replace("run\t\t500000000", f"run\t\t{a.mm_steps}")
        work = os.path.join(a.workdir, name)
        run(a.inl, folder, deck, text, os.path.join(work, "inl"))
        names, inl = check_inl.read_table(os.path.join(work, "inl", table))
        if "clump" in text:
            x1 = inl[0][names.index("1_disp")] if name == "9_spheres" else None
            text = without_clump(text, os.path.join(folder, "clump.txt"), x1)
        results = {}
        for variant, deck_text in (("without", text), ("with", check_inl.with_switch(text))):
            run(a.liggghts, folder, deck, deck_text, os.path.join(work, variant))
            _, mine = check_inl.read_table(os.path.join(work, variant, table))
            if len(mine) != len(inl):
                raise SystemExit(f"{name} {variant}: {len(mine)} rows against INL's {len(inl)}")
            results[variant] = differences(names, mine, inl)
        print(f"{name} ({len(inl)} rows): largest difference / range, without the switch -> with it")
        for column in results["with"]:
            print(f"  {column:>12} {results['without'][column]:10.3g} -> {results['with'][column]:10.3g}")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
