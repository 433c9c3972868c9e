#!/usr/bin/env python3
"""The `use` graph between the modules of a Rust crate's src/ folder.

Prints one line per module, `module -> the modules it uses`, then every
cycle (strongly connected group of two or more modules) and every breach
of the layering: only `ffi` and its submodules may use `ffi`, and only
they may hold `extern "C"` or `#[no_mangle]` (the C ABI is one layer, on
top). Exits 1 when there is a cycle or a breach. Reads `use crate::...`, `use super::...` and `crate::a::b` paths
in the code as text (comments left out); tests (`#[cfg(test)] mod tests` blocks at the end of a
file) are left out, since a test may reach back up.

Usage: scripts/module_graph.py [SRC_DIR]   (default: rust-core/src)
"""
import os
import re
import sys


def module_of(path, src):
    rel = os.path.relpath(path, src)[:-3]
    parts = rel.split(os.sep)
    if parts[-1] in ("mod", "lib"):
        parts = parts[:-1]
    return "::".join(parts) or "crate"


def strip_tests(text):
    m = re.search(r"^#\[cfg\(test\)\]\s*\n\s*mod \w+", text, re.M)
    return text[: m.start()] if m else text


def resolve(current, path, modules):
    """The longest known module that `path` (a::b::c, relative to the crate) names."""
    parts = path.split("::")
    for n in range(len(parts), 0, -1):
        name = "::".join(parts[:n])
        if name in modules:
            return name
    return None


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "rust-core/src"
    files = {}
    for root, _, names in os.walk(src):
        for name in names:
            if name.endswith(".rs"):
                path = os.path.join(root, name)
                files[module_of(path, src)] = path
    modules = set(files)
    edges = {m: set() for m in modules}
    breaches = []
    for mod, path in files.items():
        text = strip_tests(open(path, encoding="utf-8").read())
        # comments name modules without using them
        text = re.sub(r"//.*", "", text)
        if not in_ffi(mod) and re.search(r'extern\s+"C"|#\[no_mangle\]|#\[unsafe\(no_mangle\)\]', text):
            breaches.append(f'{mod} holds extern "C" or no_mangle: the C ABI lives in ffi')
        # an inline `mod x {` inside the file counts as the file's module
        is_dir_module = os.path.basename(path) in ("mod.rs", "lib.rs")
        parent = mod if is_dir_module else "::".join(mod.split("::")[:-1])
        for m in re.finditer(r"\b(crate|super)((?:::\w+)+)", text):
            head, tail = m.group(1), m.group(2)[2:]
            if head == "crate":
                target = resolve(mod, tail, modules)
            else:
                base = parent.split("::") if parent else []
                rest = tail.split("::")
                # `super::super::x` climbs further
                while rest and rest[0] == "super":
                    base, rest = base[:-1], rest[1:]
                target = resolve(mod, "::".join(base + rest), modules)
            if target and target != mod and not mod.startswith(target + "::") and target != "crate":
                edges[mod].add(target)
    for mod in sorted(modules):
        if edges[mod]:
            print(f"{mod} -> {', '.join(sorted(edges[mod]))}")
    for mod in sorted(modules):
        for target in sorted(edges[mod]):
            if in_ffi(target) and not in_ffi(mod):
                breaches.append(f"{mod} uses {target}: only the C ABI layer (ffi) may")
    cycles = strongly_connected(edges)
    for group in cycles:
        print("cycle: " + " <-> ".join(sorted(group)))
    if not cycles:
        print("no cycles")
    for breach in sorted(breaches):
        print("layering: " + breach)
    if not breaches:
        print("layering kept")
    return 1 if cycles or breaches else 0


def in_ffi(mod):
    return mod == "ffi" or mod.startswith("ffi::")


def strongly_connected(edges):
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            group = []
            while True:
                w = stack.pop()
                on.discard(w)
                group.append(w)
                if w == v:
                    break
            if len(group) > 1:
                out.append(group)

    sys.setrecursionlimit(10000)
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return out


if __name__ == "__main__":
    sys.exit(main())
