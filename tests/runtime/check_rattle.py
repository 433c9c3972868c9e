"""Engine-level checks of the time-step rule for bonds that break in
compression (docs/runtime-checks.md, docs/speed-accuracy.md), for LIGGGHTS
(liggghts-granbond) and LAMMPS (lmp-granbond). Decks: rattle_liggghts.in,
rattle_lammps.in (a bonded block falling freely: nothing loads a bond).

  free-fall   for blocks of several sizes, stiffnesses and strengths, the
              recommended step is read from the warning of a run far above
              it (run 0); then at 0.5, 0.8 and 0.95 of it no bond breaks
              and nothing warns; at 2.5 times it the run warns at its start,
              naming the rattle's remedies, before any bond breaks; with the
              linear regularisation (compressionLinearBelowBondnonlinear /
              compression_linear_below) the block stays intact at 0.95 of
              the limit the warning gives for a sphere with 6 bonds.
  restart     (LAMMPS) a bonded run continued by read_restart does not
              warn that its creation step has passed; a fresh run started
              after its creation step still does.
  units       (LAMMPS) the same deck in `units micro` warns in micrometres,
              picograms and microseconds, at the same step as in SI.
  unfix       (LIGGGHTS) `unfix` of a fix wall/gran holding wall bonds:
              compute bond/counter counts them as lost (column 8; created
              stays), and one warning names their number.

usage: check_rattle.py --mode MODE --engine BIN --kind lammps|liggghts --workdir DIR
"""

import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))

import deck_runner  # noqa: E402
from deck_runner import Failure, main, run_deck  # noqa: E402

deck_runner.DECKS = os.path.join(HERE, "decks")

# (spheres per edge, k_fn1 N/m^2.5 (the other stiffnesses scale with it), maxSigma Pa)
BLOCKS = [(5, 2.0e10, 1.0e6), (4, 8.0e10, 3.0e6), (6, 5.0e9, 3.0e5)]
RADIUS, LAMBDA = 1e-3, 0.7
NRUN = 2000
FAR_ABOVE = 1e-5   # s, above every estimate of these blocks
NUMBER = r"([0-9.]+(?:e[-+]?[0-9]+)?)"


def need_kind(a, kind, mode):
    if a.kind != kind:
        raise Failure(f"{mode}: {kind} only")


def judge(failed):
    if failed:
        raise Failure("; ".join(failed))


def deck(kind):
    return f"rattle_{kind}.in"


def log_of(engine, name, workdir, variables):
    """The log of deck `name` run in `workdir`; a failed run is a Failure."""
    rc, text = run_deck([engine], name, workdir, variables)
    if rc != 0:
        raise Failure(f"{name} {variables} exited with {rc}:\n{text[-3000:]}")
    with open(os.path.join(workdir, "log.lammps"), encoding="utf-8", errors="replace") as f:
        return f.read()


def run_ok(engine, kind, workdir, variables):
    return log_of(engine, deck(kind), workdir, dict({"nrun": NRUN}, **variables))


def bond_warnings(log):
    """The time-step warnings on bonds (LAMMPS also checks its contact)."""
    return [x for x in log.splitlines()
            if x.startswith("WARNING") and "time step" in x and "of the stiffest bond" in x]


def broken_column(kind):
    return "bc[2]" if kind == "liggghts" else "c_pb[2]"


def rows_with_lines(log, column):
    """(line number, value of `column`) of every thermo row."""
    out = [(k, row[header.index(column)]) for header, rows in deck_runner.thermo_blocks(log) if column in header
           for k, row in rows]
    if not out:
        raise Failure(f"no thermo rows with {column}")
    return out


def probe(engine, kind, workdir, variables):
    """The recommended step and the one-sphere-with-6-bonds limit, from the
    warning of a run far above them (run 0)."""
    log = run_ok(engine, kind, workdir, dict(variables, dt=FAR_ABOVE, nrun=0))
    ours = bond_warnings(log)
    if not ours:
        raise Failure(f"{variables}: no time-step warning at dt {FAR_ABOVE}")
    rec = re.search(r"Use timestep <= " + NUMBER, ours[0])
    z6 = re.search(r"stable below " + NUMBER + r" \S+ for z = 6", ours[0])
    if not (rec and z6):
        raise Failure(f"warning without the recommended step or the 6-bond limit: {ours[0]}")
    return float(rec.group(1)), float(z6.group(1)), ours[0]


def check_free_fall(a, workdir):
    failed = []
    for n, k, sigma in BLOCKS:
        v = {"n": n, "k": k, "sigma": sigma}
        tag = f"n{n}-k{k:g}-s{sigma:g}"
        recommended, z6, warning = probe(a.engine, a.kind, os.path.join(workdir, tag, "probe"), v)
        if "rattle" not in warning:
            failed.append(f"{tag}: the warning does not name the rattle: {warning}")
        print(f"{tag}: recommended {recommended:.4g} s, 6-bond limit {z6:.4g} s")
        for f in (0.5, 0.8, 0.95):
            log = run_ok(a.engine, a.kind, os.path.join(workdir, tag, f"at-{f}"), dict(v, dt=f * recommended))
            broken = rows_with_lines(log, broken_column(a.kind))[-1][1]
            warned = bond_warnings(log)
            print(f"  {f} x recommended: {broken:g} broken, {len(warned)} time-step warnings")
            if broken or warned:
                failed.append(f"{tag} at {f} x recommended: {broken:g} broken, warnings {warned}")
        log = run_ok(a.engine, a.kind, os.path.join(workdir, tag, "above"), dict(v, dt=2.5 * recommended))
        rows = rows_with_lines(log, broken_column(a.kind))
        first_break = next((line for line, b in rows if b > 0), None)
        warned_at = [k for k, x in enumerate(log.splitlines()) if x in bond_warnings(log)]
        remedies = [x for x in bond_warnings(log) if "Remedies: timestep <=" in x and "regularisation" in x]
        print(f"  2.5 x recommended: {rows[-1][1]:g} broken, warned on log line "
              f"{warned_at[:1]}, first break on line {first_break}")
        if not warned_at or not remedies:
            failed.append(f"{tag} at 2.5 x recommended: no warning naming the remedies")
        elif first_break is not None and first_break < warned_at[0]:
            failed.append(f"{tag} at 2.5 x recommended: a bond broke before the warning")
        eps = 1e-3 * LAMBDA * RADIUS
        vr = dict(v, eps=eps)
        rec_eps, z6_eps, _ = probe(a.engine, a.kind, os.path.join(workdir, tag, "probe-eps"), vr)
        log = run_ok(a.engine, a.kind, os.path.join(workdir, tag, "eps"), dict(vr, dt=0.95 * z6_eps))
        broken = rows_with_lines(log, broken_column(a.kind))[-1][1]
        print(f"  regularised: recommended {rec_eps:.4g} s; at 0.95 x the 6-bond limit {z6_eps:.4g} s: "
              f"{broken:g} broken")
        if broken:
            failed.append(f"{tag} regularised at 0.95 x {z6_eps:g} s: {broken:g} broken")
        if not rec_eps > recommended:
            failed.append(f"{tag}: the regularisation does not lengthen the recommended step")
    judge(failed)


def check_restart(a, workdir):
    need_kind(a, "lammps", "restart")
    failed = []
    passed = "is not after step"
    for case, bonds in (("bonded", True), ("no-bonds", False)):
        v = {"restart": "cont.restart", "half": 0.001 if bonds else 0.0015}
        log = log_of(a.engine, "rattle_restart_lammps.in", os.path.join(workdir, case), v)
        said = [x for x in log.splitlines() if x.startswith("WARNING") and passed in x]
        print(f"{case}: {len(said)} creation-step warning(s)" + "".join(f"\n    {x}" for x in said))
        if bonds and said:
            failed.append("a continuation with bonds warns that no bond forms")
        if not bonds and not said:
            failed.append("a run without bonds after its creation step does not warn")
    judge(failed)


def check_units(a, workdir):
    need_kind(a, "lammps", "units")
    n, k, sigma = BLOCKS[0]
    v = {"n": n, "k": k, "sigma": sigma}
    rec_si, _, si = probe(a.engine, a.kind, os.path.join(workdir, "si"), v)
    rec_micro, _, micro = probe(a.engine, a.kind, os.path.join(workdir, "micro"), dict(v, units="micro"))
    print(f"si: {si}\nmicro: {micro}")
    failed = []
    for unit in (" um", " pg", " us", " pg/(um us^2)"):
        if unit not in micro:
            failed.append(f"no '{unit}' in the micro warning")
    if re.search(r"[0-9] (m|kg|s|Pa)\b", micro):
        failed.append("SI unit names in the micro warning")
    # the same deck: micro's step is SI's in microseconds
    if abs(rec_micro / (rec_si * 1e6) - 1.0) > 1e-3:   # four printed digits
        failed.append(f"recommended {rec_micro} us in micro, {rec_si} s in SI")
    judge(failed)


def check_unfix(a, workdir):
    need_kind(a, "liggghts", "unfix")
    log = log_of(a.engine, "unfix_wall_liggghts.in", workdir, {})
    columns = ["bc[4]", "bc[5]", "bc[6]", "bc[8]"]
    last = {c: rows_with_lines(log, c)[-1][1] for c in columns}
    said = [x for x in log.splitlines() if x.startswith("WARNING") and "dropped" in x]
    print(f"after unfix: wall created {last['bc[4]']:g}, broken {last['bc[5]']:g}, "
          f"intact {last['bc[6]']:g}, lost {last['bc[8]']:g}; warnings: {said}")
    want = {"bc[4]": 3, "bc[5]": 0, "bc[6]": 0, "bc[8]": 3}
    failed = [f"{c} = {last[c]:g}, expected {v}" for c, v in want.items() if last[c] != v]
    if len(said) != 1 or " 3 intact bonds" not in said[0]:
        failed.append(f"expected one warning naming 3 bonds, got {said}")
    judge(failed)


def run(a):
    workdir = os.path.abspath(a.workdir)
    modes = {"free-fall": check_free_fall, "restart": check_restart, "units": check_units, "unfix": check_unfix}
    modes[a.mode](a, workdir)


if __name__ == "__main__":
    p = argparse.ArgumentParser()
    p.add_argument("--mode", required=True, choices=["free-fall", "restart", "units", "unfix"])
    p.add_argument("--kind", required=True, choices=["lammps", "liggghts"])
    p.add_argument("--engine", required=True)
    p.add_argument("--workdir", required=True)
    args = p.parse_args()
    main(lambda: run(args))
