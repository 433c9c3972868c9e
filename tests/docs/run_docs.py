#!/usr/bin/env python3
"""Runs every block of the README and docs/ that is marked runnable.

A block is marked by an HTML comment on the line before its opening fence:

    <!-- runnable: KIND [name=NAME] [needs=NAME] [expect="REGEX"] -->

KIND:
  sh                 bash -e, in a scratch copy of the checkout (`build/` is
                     the build tree, `examples/` a copy)
  liggghts           a whole deck, run by liggghts-granbond
  lammps             a whole deck, run by lmp-granbond
  liggghts-fragment  deck lines set into tests/docs/harness_liggghts.in (a
                     box, two touching spheres of type 1 drifting apart, 300
                     steps) at its FRAGMENT line
  lammps-fragment    the same with tests/docs/harness_lammps.in
  c                  a C program, compiled against granbond.h and the core
                     library and run
name=NAME marks a block that another one names with needs=NAME: that block
is put in front (fragments only). expect: a regular expression the output
must match. A deck passes when the engine exits with 0, prints no ERROR and
finishes its run; a marker without a fenced block after it fails.

Each failure prints a line starting with FAIL: (ctest's fail pattern).
"""
import argparse
import os
import re
import shlex
import shutil
import subprocess
import sys

MARKER = re.compile(r"^<!--\s*runnable:\s*(.*?)\s*-->\s*$")
HERE = os.path.dirname(os.path.abspath(__file__))
DECK_KINDS = ("liggghts", "lammps", "liggghts-fragment", "lammps-fragment")
KINDS = ("sh", "c") + DECK_KINDS


class Block:
    def __init__(self, path, line, kind, options, text):
        self.path, self.line, self.kind, self.options, self.text = path, line, kind, options, text

    def where(self):
        return f"{self.path}:{self.line}"


def parse_options(spec):
    words = shlex.split(spec)
    if not words:
        raise ValueError("no kind")
    options = {}
    for w in words[1:]:
        key, sep, value = w.partition("=")
        if not sep or key not in ("name", "needs", "expect"):
            raise ValueError(f"unknown option '{w}'")
        options[key] = value
    return words[0], options


def extract(path, shown):
    """Every marked block of one Markdown file, and the errors of its markers."""
    lines = open(path, encoding="utf-8").read().split("\n")
    blocks, errors = [], []
    i = 0
    while i < len(lines):
        m = MARKER.match(lines[i])
        if not m:
            i += 1
            continue
        where = f"{shown}:{i + 1}"
        try:
            kind, options = parse_options(m.group(1))
        except ValueError as e:
            errors.append(f"{where}: bad marker: {e}")
            i += 1
            continue
        if kind not in KINDS:
            errors.append(f"{where}: unknown kind '{kind}'")
        j = i + 1
        while j < len(lines) and not lines[j].strip():
            j += 1
        if j >= len(lines) or not lines[j].startswith("```"):
            errors.append(f"{where}: marker not followed by a fenced block")
            i = j
            continue
        k = j + 1
        while k < len(lines) and not lines[k].startswith("```"):
            k += 1
        if k >= len(lines):
            errors.append(f"{where}: fenced block not closed")
            break
        blocks.append(Block(shown, i + 1, kind, options, "\n".join(lines[j + 1:k]) + "\n"))
        i = k + 1
    return blocks, errors


def documents(source):
    paths = [os.path.join(source, "README.md")]
    for root, dirs, files in os.walk(os.path.join(source, "docs")):
        dirs.sort()
        paths += [os.path.join(root, f) for f in sorted(files) if f.endswith(".md")]
    return paths


def collect(source):
    blocks, errors = [], []
    for p in documents(source):
        shown = os.path.relpath(p, source)
        b, e = extract(p, shown)
        blocks += b
        errors += e
    return blocks, errors


def scratch_checkout(source, build, work):
    """A directory that looks like the checkout with its build tree, where
    commands may write (examples/ is copied, the rest linked)."""
    os.makedirs(work, exist_ok=True)
    for name in os.listdir(source):
        if name in (".git", "build", "target", "examples"):
            continue
        link = os.path.join(work, name)
        if not os.path.lexists(link):
            os.symlink(os.path.join(source, name), link)
    if not os.path.lexists(os.path.join(work, "build")):
        os.symlink(build, os.path.join(work, "build"))
    if not os.path.exists(os.path.join(work, "examples")):
        shutil.copytree(os.path.join(source, "examples"), os.path.join(work, "examples"),
                        ignore=shutil.ignore_patterns("out", "__pycache__"), symlinks=True)


def run(cmd, cwd, timeout=300, env=None):
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                           universal_newlines=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return None, f"timed out after {timeout} s"
    return p.returncode, p.stdout


def deck_text(block, named):
    text = block.text
    needs = block.options.get("needs")
    if needs:
        if needs not in named:
            raise ValueError(f"needs={needs}: no block named {needs}")
        text = named[needs].text + text
    if block.kind.endswith("-fragment"):
        engine = block.kind.split("-")[0]
        harness = open(os.path.join(HERE, f"harness_{engine}.in"), encoding="utf-8").read()
        if "FRAGMENT\n" not in harness:
            raise ValueError(f"harness_{engine}.in has no FRAGMENT line")
        text = harness.replace("FRAGMENT\n", text, 1)
    return text


def check_deck_output(rc, out):
    if rc is None:
        return out
    if rc < 0:
        return f"the engine ended by signal {-rc}"
    if rc != 0:
        return f"the engine exited with {rc}"
    if re.search(r"^ERROR", out, re.M):
        return "the engine printed an ERROR"
    if "Loop time" not in out:
        return "the run did not finish (no 'Loop time')"
    return None


def compile_and_run_c(text, work, cflags, libs, env=None):
    """Compiles the C program `text` in `work` and runs it: (rc, output)."""
    os.makedirs(work, exist_ok=True)
    src = os.path.join(work, "prog.c")
    with open(src, "w") as f:
        f.write(text)
    exe = os.path.join(work, "prog")
    cc = os.environ.get("CC", "cc")
    rc, out = run([cc, "-std=gnu11", "-Wall", "-Werror", *cflags, src, "-o", exe, *libs], work)
    if rc != 0:
        return rc, "compile failed:\n" + (out or "")
    return run([exe], work, env=env)


def run_block(block, named, args, work):
    kind = block.kind
    if kind == "sh":
        scratch_checkout(args.source, args.build, work)
        rc, out = run(["bash", "-euo", "pipefail", "-c", block.text], work)
        problem = out if rc is None else (f"exited with {rc}" if rc != 0 else None)
    elif kind == "c":
        rc, out = compile_and_run_c(block.text, work, ["-I" + args.include],
                                    [args.core_library, "-lpthread", "-ldl", "-lm"])
        problem = out if rc is None else (f"exited with {rc}" if rc != 0 else None)
    else:
        os.makedirs(work, exist_ok=True)
        with open(os.path.join(work, "in.deck"), "w") as f:
            f.write(deck_text(block, named))
        engine = args.liggghts if kind.startswith("liggghts") else args.lammps
        if not engine:
            return "skipped", f"no {kind.split('-')[0]} launcher given"
        rc, out = run([engine, "-in", "in.deck", "-log", "log.txt"], work)
        problem = check_deck_output(rc, out)
    expect = block.options.get("expect")
    if problem is None and expect and not re.search(expect, out, re.S):
        problem = f"output does not match /{expect}/"
    return ("ok", "") if problem is None else ("fail", f"{problem}\n{out if out else ''}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--source", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--workdir", required=True)
    ap.add_argument("--liggghts")
    ap.add_argument("--lammps")
    ap.add_argument("--include", required=True, help="directory of granbond.h")
    ap.add_argument("--core-library", required=True, help="libgranbond.a")
    ap.add_argument("--list", action="store_true", help="list the blocks and stop")
    args = ap.parse_args()
    for key in ("source", "build", "liggghts", "lammps", "include", "core_library"):
        if getattr(args, key):
            setattr(args, key, os.path.abspath(getattr(args, key)))

    blocks, errors = collect(args.source)
    for e in errors:
        print("FAIL: " + e)
    named = {b.options["name"]: b for b in blocks if "name" in b.options}
    if args.list:
        for b in blocks:
            print(f"{b.where()} {b.kind} {b.options}")
        return 1 if errors else 0
    if not blocks:
        print("FAIL: no runnable block in README.md or docs/")
        return 1
    shutil.rmtree(args.workdir, ignore_errors=True)
    failed = len(errors)
    for n, b in enumerate(blocks):
        work = os.path.join(args.workdir, f"{n:02d}-" + re.sub(r"[^A-Za-z0-9]+", "_", b.path))
        try:
            status, detail = run_block(b, named, args, work)
        except ValueError as e:
            status, detail = "fail", str(e)
        if status == "fail":
            failed += 1
            print(f"FAIL: {b.where()} ({b.kind}): {detail.rstrip()[-3000:]}")
        else:
            print(f"{status}: {b.where()} ({b.kind}) {detail}".rstrip())
    print(f"{len(blocks)} runnable blocks, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
