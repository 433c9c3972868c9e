"""Runs a LIGGGHTS or LAMMPS deck for the engine-level tests (Python 3 stdlib only)."""

import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# The decks of tests/adapters (bond_properties.in, plane.stl, ...); a check
# with decks of its own sets DECKS.
DECKS = os.path.join(HERE, "..", "adapters", "decks")

# A deck that hangs is a failure too; every deck here runs in well under this.
TIMEOUT_S = 120


class Failure(Exception):
    pass


def run_deck(command, deck, workdir, variables=None, env=None, log="log.lammps"):
    """Runs `command -in deck -log log -var k v ...` in `workdir`.

    Returns (exit code, screen output + log text). A run ended by a signal
    is always a failure, whatever the test expects."""
    os.makedirs(workdir, exist_ok=True)
    args = list(command) + ["-in", os.path.join(DECKS, deck), "-log", log]
    variables = dict({"decks": DECKS}, **(variables or {}))
    for key, value in variables.items():
        args += ["-var", key, str(value)]
    full_env = dict(os.environ)
    full_env.update(env or {})
    proc = subprocess.run(args, cwd=workdir, env=full_env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, timeout=TIMEOUT_S, check=False)
    screen = proc.stdout.decode("utf-8", "replace")
    log_path = os.path.join(workdir, log)
    log_text = ""
    if os.path.exists(log_path):
        with open(log_path, encoding="utf-8", errors="replace") as f:
            log_text = f.read()
    if proc.returncode < 0 or proc.returncode >= 128:
        raise Failure(f"{' '.join(args)} ended by a signal (exit {proc.returncode}):\n{screen[-3000:]}")
    return proc.returncode, screen + "\n" + log_text


def mpi_launcher(engine, mpiexec, ranks):
    """The command that runs `engine` on `ranks` ranks through Open MPI's
    `mpiexec` (as root, with its permission), or alone on 1 rank."""
    if ranks == 1:
        return [engine]
    if not mpiexec:
        raise Failure("--mpiexec is needed for several ranks")
    root = ["--allow-run-as-root"] if os.geteuid() == 0 else []
    return [mpiexec, "-np", str(ranks)] + root + ["--oversubscribe", engine]


def run_ok(command, deck, workdir, variables=None, env=None):
    rc, text = run_deck(command, deck, workdir, variables, env)
    if rc != 0:
        raise Failure(f"{deck} exited with {rc}:\n{text[-3000:]}")
    return text


def names_a_core_entry(line):
    """Whether an ERROR line names a C entry of the core (granbond_...),
    which no deck writes; the source location the engine appends is not
    the message."""
    message = line.rsplit(" (", 1)[0] if line.endswith(")") else line
    return re.search(r"\bgranbond_[a-z_]+", message) is not None


def judge_refusal(label, rc, text, name, failures, command=None):
    """A bad-input run must fail with an ERROR line naming `name` (and the
    deck's `command`, when given) and no C entry of the core; appends to
    `failures` what went wrong, or prints the error it gave."""
    errors = [line for line in text.splitlines() if line.startswith("ERROR")]
    if rc == 0:
        failures.append(f"{label}: the run succeeded")
    elif not any(name in line for line in errors):
        failures.append(f"{label}: no ERROR line names {name}; got {errors or text[-1500:]}")
    elif command and not any(name in line and command in line for line in errors):
        failures.append(f"{label}: the ERROR line naming {name} does not name the command {command!r}: {errors}")
    elif any(names_a_core_entry(line) for line in errors):
        failures.append(f"{label}: the ERROR line names a C entry of the core, not the deck's words: {errors}")
    else:
        print(f"ok: {label}: exit {rc}: {errors[0]}")


def read_table(path):
    """Rows of floats from a whitespace table, skipping '#' lines."""
    rows = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.strip() and not line.lstrip().startswith("#"):
                rows.append([float(v) for v in line.split()])
    return rows


def read_dump(path):
    """{step: rows of numbers} of a LAMMPS or LIGGGHTS dump, `custom` (the
    atoms) or `local` (the entries)."""
    frames = {}
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = int(lines[k + 1])
            count = int(lines[k + 3])
            start = next(n for n in range(k + 4, len(lines)) if lines[n].startswith(("ITEM: ATOMS", "ITEM: ENTRIES")))
            frames[step] = [[float(v) for v in line.split()] for line in lines[start + 1:start + 1 + count]]
            k = start + 1 + count
        else:
            k += 1
    return frames


def thermo_blocks(text):
    """The thermo blocks of an engine's output, in order, as (header, rows):
    the words of the block's `Step ...` line, and each row of the block as
    (line number, numbers), a row being a line of as many numbers as the
    header has words. LAMMPS and LIGGGHTS both end a block with `Loop time`."""
    blocks = []
    for k, line in enumerate(text.splitlines()):
        words = line.split()
        if words[:1] == ["Step"]:
            blocks.append((words, []))
        elif line.startswith("Loop time"):
            blocks.append((None, []))
        elif blocks and blocks[-1][0] and len(words) == len(blocks[-1][0]):
            try:
                blocks[-1][1].append((k, [float(w) for w in words]))
            except ValueError:
                pass
    return [b for b in blocks if b[0]]


def thermo_rows(text, first=("Step",)):
    """The rows of the thermo blocks whose header starts with the words
    `first`, as numbers."""
    return [row for header, rows in thermo_blocks(text) if header[:len(first)] == list(first) for _, row in rows]


def thermo_column(text, name):
    """Values of thermo column `name` in every block that has it (LIGGGHTS
    heads compute columns without the `c_`)."""
    names = {name, name[2:] if name.startswith("c_") else name}
    values = []
    for header, rows in thermo_blocks(text):
        found = [k for k, w in enumerate(header) if w in names]
        values += [row[found[0]] for _, row in rows] if found else []
    return values


def main(check):
    """Runs `check()`, printing the failure and exiting non-zero on Failure."""
    try:
        check()
    except Failure as e:
        print(f"FAIL: {e}")
        sys.exit(1)
    print("PASS")


def run_modes(doc, checks):
    """The command line of a check script that granbond_script_test runs
    (--mode, --kind, --engine, [--mpiexec], --workdir): runs
    `checks[mode](args, workdir)` as `main` does."""
    import argparse

    parser = argparse.ArgumentParser(description=doc.splitlines()[0])
    parser.add_argument("--mode", required=True, choices=sorted(checks))
    parser.add_argument("--kind", required=True)
    parser.add_argument("--engine", required=True)
    parser.add_argument("--mpiexec")
    parser.add_argument("--workdir", required=True)
    a = parser.parse_args()
    main(lambda: checks[a.mode](a, os.path.abspath(a.workdir)))
