"""Bond bookkeeping in the engine: compute bond/counter, fix bond/breaklog,
per-bond dump local output, `bonded yes` clumps, restart continuity, the
time-step warning and the error for an unregistered model combination.

usage: check_bond_book.py --mode MODE --engine EXE [--mpiexec MPIEXEC] --workdir DIR
  events     decks/bond_events.in (distance mode): counter values, break log
             (steps against the kinematics, positions, modes), dump local
             columns; with --mpiexec the 2-rank files equal the 1-rank ones
  stress     the same deck in stress mode: pair bonds break in tension
  clumps     decks/clump_bonds.in: spheres of one clump bond, others never
  restart    decks/restart_chain.in: write_restart/read_restart mid-run, and
             a restart file written during a run (`restart N`) read back,
             end in the uninterrupted state (1 rank, and 2 with --mpiexec)
  timestep   the warning above the recommended / critical step, none below
  combination  an unregistered combination lists the registered ones
"""

import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from deck_runner import Failure, main, read_table, run_deck, run_ok  # noqa: E402

DIAMETER = 2e-3
RADIUS = DIAMETER / 2
DT = 1e-6
VX = 0.05
MAXDIST = 2.08e-3          # decks/bond_properties.in
LAMBDA = 0.5
EVENTS = {"nrun": 1500, "every": 50, "vx": VX, "dt": DT}


def mpi_prefix(mpiexec):
    prefix = [mpiexec, "-np", "2"]
    if os.geteuid() == 0:
        prefix += ["--allow-run-as-root"]
    return prefix + ["--oversubscribe"]


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def break_log(path):
    rows = []
    for line in read(path).splitlines():
        if line.startswith("#") or not line.strip():
            continue
        f = line.split()
        rows.append({"step": int(f[0]), "i": int(f[1]), "j": int(f[2]), "x": [float(v) for v in f[3:6]],
                     "mode": f[6], "sigma": float(f[7]), "tau": float(f[8])})
    return rows


def check_counter(rows, log, pair_bonds, wall_bonds, cumulative=False):
    """Per-interval created/broken add up to the events; intact = created - broken."""
    created = [0, 0]
    broken = [0, 0]
    for row in rows:
        step = int(row[0])
        for kind in (0, 1):
            c, b, intact = row[1 + 3 * kind: 4 + 3 * kind]
            if cumulative:
                created[kind], broken[kind] = c, b
            else:
                created[kind] += c
                broken[kind] += b
            if intact != created[kind] - broken[kind]:
                raise Failure(f"step {step}: {'wall' if kind else 'pair'} intact {intact} != created "
                              f"{created[kind]} - broken {broken[kind]}")
            logged = sum(1 for e in log if e["step"] <= step and (e["j"] == 0) == (kind == 1))
            if broken[kind] != logged:
                raise Failure(f"step {step}: {'wall' if kind else 'pair'} broken {broken[kind]} but {logged} "
                              "lines in the break log")
    if created != [pair_bonds, wall_bonds]:
        raise Failure(f"created pair/wall bonds {created}, expected {[pair_bonds, wall_bonds]}")
    return broken


def predicted_pair_breaks(nrun):
    """Bond between spheres k and k+1 (ids k+1, k+2) stretches at VX*(2k+1)."""
    out = {}
    for k in range(5):
        rate = VX * (2 * k + 1)
        step = math.floor((MAXDIST - DIAMETER) / (rate * DT)) + 1
        if step <= nrun:
            out[(k + 1, k + 2)] = step
    return out


# slots of the core's bond state (GRANBOND_BOND_STATE_LEN)
BOND_STATE_LEN = 18


def check_dump_columns(path):
    """id_i id_j periodic f(3) t(3) | state(BOND_STATE_LEN) output(12: f, T_1, T_2, side, sigma, tau) | shear(3)"""
    first_out = 9 + BOND_STATE_LEN
    rows = [r for r in read_table_loose(path) if len(r) == first_out + 15 and r[9] > 0.0]
    if not rows:
        raise Failure("no intact bond in the dump local output")
    area = math.pi * (LAMBDA * RADIUS) ** 2
    for r in rows:
        force, torque = r[3:6], r[6:9]
        out = r[first_out:first_out + 12]
        if any(abs(force[c] - out[c]) > 1e-12 * abs(force[0]) for c in range(3)):
            raise Failure(f"dumped force {force} differs from the bond output slots {out[0:3]}")
        if out[9] not in (1.0, -1.0):
            raise Failure(f"bond_side {out[9]} is neither +1 nor -1")
        t_i = out[3:6] if out[9] > 0 else out[6:9]
        if any(abs(torque[c] - t_i[c]) > 1e-12 * (abs(force[0]) + 1e-30) for c in range(3)):
            raise Failure(f"dumped torque {torque} differs from the bond output {t_i}")
        sigma = out[10]
        if abs(sigma - abs(force[0]) / area) > 1e-5 * sigma:   # dump local prints 6 digits
            raise Failure(f"sigma {sigma} != |F|/A = {abs(force[0]) / area} for pure tension")
    return len(rows)


def read_table_loose(path):
    rows = []
    for line in read(path).splitlines():
        f = line.split()
        try:
            rows.append([float(v) for v in f])
        except ValueError:
            continue
    return rows


def run_events(a, workdir, variables):
    run_ok([a.engine], "bond_events.in", workdir, variables)
    result = (read(os.path.join(workdir, "counter.txt")), read(os.path.join(workdir, "breaks.txt")))
    if a.mpiexec:
        wd2 = os.path.join(workdir, "np2")
        run_ok(mpi_prefix(a.mpiexec) + [a.engine], "bond_events.in", wd2, variables)
        result2 = (read(os.path.join(wd2, "counter.txt")), read(os.path.join(wd2, "breaks.txt")))
        if result2 != result:
            raise Failure("2 ranks: counter.txt or breaks.txt differ from 1 rank")
        print("2 ranks: counter and break log identical to 1 rank")
    return read_table(os.path.join(workdir, "counter.txt")), break_log(os.path.join(workdir, "breaks.txt"))


def check_events(a, workdir):
    counter, log = run_events(a, workdir, dict(EVENTS))
    broken = check_counter(counter, log, 5, 6)
    expected = predicted_pair_breaks(EVENTS["nrun"])
    pairs = {(e["i"], e["j"]): e for e in log if e["j"] != 0}
    if set(pairs) != set(expected) or len(pairs) != len([e for e in log if e["j"] != 0]):
        raise Failure(f"broken pairs {sorted(pairs)} (one line each), expected {sorted(expected)}")
    for key, step in expected.items():
        e = pairs[key]
        if abs(e["step"] - step) > 1 or e["mode"] != "distance":
            raise Failure(f"pair {key}: logged step {e['step']} mode {e['mode']}, kinematics give {step} distance")
        i, j = key
        xi = -2.5 * DIAMETER + (i - 1) * DIAMETER + VX * (i - 1) ** 2 * e["step"] * DT
        xj = -2.5 * DIAMETER + (j - 1) * DIAMETER + VX * (j - 1) ** 2 * e["step"] * DT
        want = [0.5 * (xi + xj), 0.0, RADIUS]
        if any(abs(e["x"][c] - want[c]) > 1e-8 for c in range(3)):
            raise Failure(f"pair {key}: logged position {e['x']}, the bond centre is {want}")
    walls = [e for e in log if e["j"] == 0]
    if any(e["mode"] != "distance" for e in walls):
        raise Failure(f"wall bonds broke in another mode: {walls}")
    ndump = check_dump_columns(os.path.join(workdir, "bonds.dump"))
    print(f"events: {len(pairs)} pair breaks at the predicted steps, {len(walls)} wall breaks, counter {broken} "
          f"broken; {ndump} dumped bonds match their output slots")


def check_stress(a, workdir):
    variables = dict(EVENTS, stress="on", cumulative="yes")
    counter, log = run_events(a, workdir, variables)
    check_counter(counter, log, 5, 6, cumulative=True)
    pairs = [e for e in log if e["j"] != 0]
    if len(pairs) != 5 or any(e["mode"] != "tension" for e in pairs):
        raise Failure(f"stress mode: expected 5 pair bonds broken in tension, log: {pairs}")
    print(f"stress: 5 tension breaks, wall modes {sorted(set(e['mode'] for e in log if e['j'] == 0))}")


def check_clumps_once(command, workdir):
    run_ok(command, "clump_bonds.in", workdir)
    counter = read_table(os.path.join(workdir, "counter.txt"))
    final = counter[-1]
    text = read(os.path.join(workdir, "log.lammps"))
    inserted = [line for line in text.splitlines() if "inserted" in line and "particle templates" in line]
    nclumps = int(inserted[0].split("inserted")[1].split()[0]) if inserted else 0
    if nclumps < 2:
        raise Failure(f"fewer than 2 clumps inserted ({inserted})")
    if final[1] != 2 * nclumps or final[3] != 2 * nclumps or final[2] != 0:
        raise Failure(f"{nclumps} clumps of 3: counter {final[1:]} (created, broken, intact), expected "
                      f"{2 * nclumps} created and intact")
    same = set()
    others = 0
    for r in read_table_loose(os.path.join(workdir, "clumps.dump")):
        if len(r) != 5:
            continue
        i, j, status = int(r[0]), int(r[1]), r[3]
        one_clump = (i - 1) // 3 == (j - 1) // 3
        if status == 1.0 and not one_clump:
            raise Failure(f"atoms {i} and {j} of different clumps are bonded")
        if one_clump and status == 1.0:
            same.add((min(i, j), max(i, j)))
    for r in read_table_loose(os.path.join(workdir, "contacts.dump")):
        if len(r) == 3 and (int(r[0]) - 1) // 3 != (int(r[1]) - 1) // 3:
            others += 1
    if len(same) != 2 * nclumps:
        raise Failure(f"bonded pairs within clumps {sorted(same)}, expected {2 * nclumps}")
    if others == 0:
        raise Failure("no contact between different clumps: the deck does not test 'not others'")
    return f"{nclumps} clumps, {len(same)} bonds within clumps, {others} unbonded contact rows between clumps"


def check_clumps(a, workdir):
    print("1 rank: " + check_clumps_once([a.engine], workdir))
    if a.mpiexec:
        print("2 ranks: " + check_clumps_once(mpi_prefix(a.mpiexec) + [a.engine], os.path.join(workdir, "np2")))


def final_state(path):
    rows = read_table_loose(path)
    return [r for r in rows if len(r) == 10][-6:]


def check_restart_once(command, workdir, periodic=False):
    """write_restart after a run, or (periodic) the file `restart N` wrote
    during one, read back and run on."""
    full_dir, split_dir = os.path.join(workdir, "full"), os.path.join(workdir, "periodic" if periodic else "split")
    run_ok(command, "restart_chain.in", full_dir, {"phase": 0})
    if periodic:
        run_ok(command, "restart_chain.in", split_dir, {"phase": 3})
        run_ok(command, "restart_chain.in", split_dir, {"phase": 2, "rfile": "mid.1500.restart"})
    else:
        run_ok(command, "restart_chain.in", split_dir, {"phase": 1})
        run_ok(command, "restart_chain.in", split_dir, {"phase": 2})
    a = final_state(os.path.join(full_dir, "final.dump"))
    b = final_state(os.path.join(split_dir, "final.dump"))
    if len(a) != 6 or len(b) != 6:
        raise Failure("final dump incomplete")
    worst = 0.0
    for ra, rb in zip(a, b):
        for va, vb in zip(ra, rb):
            scale = max(abs(va), abs(vb), 1e-3)
            worst = max(worst, abs(va - vb) / scale)
    if worst > 1e-10:
        raise Failure(f"restarted run ends {worst:.3g} (relative) away from the uninterrupted one")
    ca = read_table(os.path.join(full_dir, "counter.txt"))[-1]
    cb = read_table(os.path.join(split_dir, "counter.txt"))[-1]
    if ca != cb or ca[1] < 1:
        raise Failure(f"bonds intact, created, broken or lost at the end (cumulative counts): uninterrupted {ca}, "
                      f"restarted {cb}")
    if cb[3] != cb[1] + cb[2] + cb[4]:
        raise Failure(f"restarted: created {cb[3]} != intact {cb[1] + cb[2]} + broken or lost {cb[4]}")
    return f"same final state (worst relative difference {worst:.1e}), intact bonds {ca[1:3]}, created {ca[3]}"


def check_restart(a, workdir):
    print("1 rank: " + check_restart_once([a.engine], workdir))
    print("1 rank, restart N: " + check_restart_once([a.engine], workdir, periodic=True))
    if a.mpiexec:
        np2 = os.path.join(workdir, "np2")
        print("2 ranks: " + check_restart_once(mpi_prefix(a.mpiexec) + [a.engine], np2))
        print("2 ranks, restart N: " + check_restart_once(mpi_prefix(a.mpiexec) + [a.engine], np2, periodic=True))


def check_timestep(a, workdir):
    # decks/bond_events.in: critical step about 4.3e-6 s, recommended 0.2 x that
    cases = [(5e-6, "EXCEEDS the critical step"), (1e-6, "exceeds the recommended step"), (5e-7, None)]
    for dt, text in cases:
        out = run_ok([a.engine], "bond_events.in", os.path.join(workdir, f"dt{dt:g}"),
                     dict(EVENTS, dt=dt, nrun=20, every=10))
        warnings = [line for line in out.splitlines() if "WARNING: cohesion bond/nonlinear" in line]
        if text is None and warnings:
            raise Failure(f"dt {dt:g}: unexpected warning {warnings[0]}")
        if text is not None and not any(text in w and "critical step" in w for w in warnings):
            raise Failure(f"dt {dt:g}: no warning '{text}' in the output")
        print(f"dt {dt:g}: {warnings[0][:110] if warnings else 'no warning'}")


def check_combination(a, workdir):
    rc, out = run_deck([a.engine], "bond_events.in", workdir,
                       dict(EVENTS, nrun=10, pairstyle_extra="rolling_friction epsd3"))
    if rc == 0:
        raise Failure("an unregistered combination ran")
    want = ["is not registered", "rolling_friction epsd3", "cohesion bond/nonlinear|bond rolling_friction off|cdt|epsd|epsd2"]
    for text in want:
        if text not in out:
            raise Failure(f"the error does not say '{text}':\n{out[-2000:]}")
    print("unregistered combination: error lists the registered ones")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mode", required=True,
                        choices=["events", "stress", "clumps", "restart", "timestep", "combination"])
    parser.add_argument("--engine", required=True)
    parser.add_argument("--mpiexec")
    parser.add_argument("--workdir", required=True)
    args = parser.parse_args()
    check = globals()["check_" + args.mode]
    main(lambda: check(args, args.workdir))
