#!/usr/bin/env python3
"""The bond network of a per-bond dump as VTK polydata, for ParaView.

usage: bonds_to_vtk.py BONDS_DUMP --columns "KEYWORDS" [--breaklog FILE] --out DIR

BONDS_DUMP is the `dump local` of LAMMPS `compute granbond/local` or
LIGGGHTS `compute pair/gran/local/bond`, with the compute's columns in order;
--columns repeats the compute's keywords (`id pos status sigma_ratio ...`;
`id` and `pos` are needed, `all` is not accepted: name the fields). Writes,
per dump step, DIR/bonds_STEP.vtp (one line per bond from centre i to centre
j, every other column as cell data named by its keyword, `id` as id_i and
id_j) and DIR/bonds.pvd, the series ParaView opens. With --breaklog (the
file of `fix bond/breaklog`), also DIR/breaks_STEP.vtp (one vertex per bond
broken up to that step, at its centre, with mode, sigma, tau and their limits
as point data) and DIR/breaks.pvd. Times in the .pvd files are steps.

Python 3 standard library only. `read_vtp`, `read_pvd`, `read_dump_local` and
`read_break_log` are strict readers used by the tests and the plots.
"""

import argparse
import os
import sys
import xml.etree.ElementTree as ET

MODES = {"distance": 1, "tension": 2, "compression": 3, "shear": 4}
BREAK_COLUMNS = ["step", "i", "j", "x", "y", "z", "mode", "sigma", "tau", "sigma_max", "tau_max"]


def expand_columns(keywords):
    """Column names of the compute's keywords (`id` and `pos` expand)."""
    names = []
    for word in keywords.split():
        if word == "id":
            names += ["id_i", "id_j"]
        elif word == "pos":
            names += ["x_i", "y_i", "z_i", "x_j", "y_j", "z_j"]
        elif word == "all":
            raise ValueError("--columns: name the fields instead of 'all' (the dump has no column names)")
        else:
            names.append(word)
    for needed in ("id_i", "x_i"):
        if needed not in names:
            raise ValueError(f"--columns: needs the keywords 'id' and 'pos' (no {needed})")
    return names


def read_dump_local(path, columns):
    """{step: [row dict]} of a `dump local` file whose entries are `columns`."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    steps, k = {}, 0
    while k < len(lines):
        if lines[k] != "ITEM: TIMESTEP":
            raise ValueError(f"{path}:{k + 1}: expected 'ITEM: TIMESTEP', got {lines[k]!r}")
        step = int(lines[k + 1])
        if not lines[k + 2].startswith("ITEM: NUMBER OF"):
            raise ValueError(f"{path}:{k + 3}: expected the number of entries")
        n = int(lines[k + 3])
        if not lines[k + 4].startswith("ITEM: BOX BOUNDS") or not lines[k + 8].startswith("ITEM: ENTRIES"):
            raise ValueError(f"{path}:{k + 5}: expected the box bounds and the entries header")
        rows = []
        for r in range(n):
            values = [float(v) for v in lines[k + 9 + r].split()]
            if len(values) != len(columns):
                raise ValueError(f"{path}:{k + 10 + r}: {len(values)} columns, --columns gives {len(columns)}")
            row = dict(zip(columns, values))
            for c in ("id_i", "id_j"):
                if c in row:
                    row[c] = int(row[c])
            rows.append(row)
        steps[step] = rows
        k += 9 + n
    return steps


def read_break_log(path):
    """The lines of a `fix bond/breaklog` file as dicts."""
    events = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, start=1):
            if not line.strip() or line.startswith("#"):
                continue
            v = line.split()
            if len(v) != len(BREAK_COLUMNS) or v[6] not in MODES:
                raise ValueError(f"{path}:{number}: not a break log line: {line!r}")
            events.append({"step": int(v[0]), "i": int(v[1]), "j": int(v[2]), "x": [float(c) for c in v[3:6]],
                           "mode": v[6], "sigma": float(v[7]), "tau": float(v[8]), "sigma_max": float(v[9]),
                           "tau_max": float(v[10])})
    return events


def _array(name, values, components=1):
    text = " ".join(repr(float(v)) for v in values)
    return (f'<DataArray type="Float64" Name="{name}" NumberOfComponents="{components}" format="ascii">'
            f"{text}</DataArray>")


def _int_array(name, values):
    return f'<DataArray type="Int64" Name="{name}" format="ascii">{" ".join(str(v) for v in values)}</DataArray>'


def polydata(points, lines=(), verts=(), cell_data=None, point_data=None):
    """A VTK XML PolyData document: `lines` and `verts` index `points`."""
    n = len(points)
    flat = [c for p in points for c in p]
    parts = ['<?xml version="1.0"?>',
             '<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">',
             "<PolyData>",
             f'<Piece NumberOfPoints="{n}" NumberOfVerts="{len(verts)}" NumberOfLines="{len(lines)}" '
             'NumberOfStrips="0" NumberOfPolys="0">',
             "<Points>", _array("Points", flat, 3), "</Points>"]
    parts.append("<Verts>")
    parts.append(_int_array("connectivity", list(verts)))
    parts.append(_int_array("offsets", list(range(1, len(verts) + 1))))
    parts.append("</Verts>")
    parts.append("<Lines>")
    parts.append(_int_array("connectivity", [p for line in lines for p in line]))
    parts.append(_int_array("offsets", [2 * (k + 1) for k in range(len(lines))]))
    parts.append("</Lines>")
    for tag, data in (("PointData", point_data), ("CellData", cell_data)):
        parts.append(f"<{tag}>")
        for name, values in (data or {}).items():
            parts.append(_array(name, values))
        parts.append(f"</{tag}>")
    parts += ["</Piece>", "</PolyData>", "</VTKFile>"]
    return "\n".join(parts) + "\n"


def pvd(entries):
    rows = "\n".join(f'<DataSet timestep="{step}" part="0" file="{name}"/>' for step, name in entries)
    return ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="1.0" byte_order="LittleEndian">\n'
            f"<Collection>\n{rows}\n</Collection>\n</VTKFile>\n")


def _values(element, kind):
    text = (element.text or "").split()
    return [kind(v) for v in text]


def read_vtp(path):
    """A strict reader of the files `polydata` writes: checks the counts,
    that every array has one value per point or cell, that connectivity
    indexes existing points and that offsets match it. Returns points (as
    tuples), lines (pairs), verts, cells (cell data by name; verts come
    first in VTK's cell order, and files here hold verts or lines, not both)
    and points_data."""
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.get("type") != "PolyData":
        raise ValueError(f"{path}: not a VTK PolyData file")
    pieces = root.findall("./PolyData/Piece")
    if len(pieces) != 1:
        raise ValueError(f"{path}: {len(pieces)} pieces, expected 1")
    piece = pieces[0]
    n = int(piece.get("NumberOfPoints"))
    nlines, nverts = int(piece.get("NumberOfLines")), int(piece.get("NumberOfVerts"))
    coords = _values(piece.find("./Points/DataArray"), float)
    if len(coords) != 3 * n:
        raise ValueError(f"{path}: {len(coords)} coordinates for {n} points")
    points = [tuple(coords[3 * k:3 * k + 3]) for k in range(n)]

    def cells(tag, count, size):
        conn = _values(piece.find(f"./{tag}/DataArray[@Name='connectivity']"), int)
        offsets = _values(piece.find(f"./{tag}/DataArray[@Name='offsets']"), int)
        if len(offsets) != count or offsets != [size * (k + 1) for k in range(count)] or len(conn) != size * count:
            raise ValueError(f"{path}: {tag}: {count} cells of {size} points do not match the offsets/connectivity")
        if any(not 0 <= p < n for p in conn):
            raise ValueError(f"{path}: {tag}: connectivity outside the {n} points")
        return conn

    line_conn = cells("Lines", nlines, 2)
    verts = cells("Verts", nverts, 1)
    out = {"points": points, "lines": [(line_conn[2 * k], line_conn[2 * k + 1]) for k in range(nlines)],
           "verts": verts, "cells": {}, "points_data": {}}
    for tag, key, count in (("CellData", "cells", nlines + nverts), ("PointData", "points_data", n)):
        for a in piece.findall(f"./{tag}/DataArray"):
            values = _values(a, float)
            if len(values) != count:
                raise ValueError(f"{path}: {tag} {a.get('Name')}: {len(values)} values for {count}")
            out[key][a.get("Name")] = values
    return out


def read_pvd(path):
    """[(step, file)] of a .pvd series, each file present next to it."""
    root = ET.parse(path).getroot()
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        raise ValueError(f"{path}: not a VTK collection")
    entries = []
    for d in root.findall("./Collection/DataSet"):
        name = d.get("file")
        if not os.path.exists(os.path.join(os.path.dirname(path), name)):
            raise ValueError(f"{path}: lists {name}, which is missing")
        entries.append((int(float(d.get("timestep"))), name))
    return entries


def write(dump_path, keywords, out, breaklog=None):
    columns = expand_columns(keywords)
    steps = read_dump_local(dump_path, columns)
    events = read_break_log(breaklog) if breaklog else None
    os.makedirs(out, exist_ok=True)
    fields = [c for c in columns if c not in ("x_i", "y_i", "z_i", "x_j", "y_j", "z_j")]
    bonds, breaks = [], []
    for step, rows in sorted(steps.items()):
        points = []
        for r in rows:
            points += [(r["x_i"], r["y_i"], r["z_i"]), (r["x_j"], r["y_j"], r["z_j"])]
        lines = [(2 * k, 2 * k + 1) for k in range(len(rows))]
        name = f"bonds_{step}.vtp"
        with open(os.path.join(out, name), "w", encoding="utf-8") as f:
            f.write(polydata(points, lines=lines, cell_data={c: [r[c] for r in rows] for c in fields}))
        bonds.append((step, name))
        if events is None:
            continue
        gone = [e for e in events if e["step"] <= step]
        data = {"step": [e["step"] for e in gone], "id_i": [e["i"] for e in gone], "id_j": [e["j"] for e in gone],
                "mode": [MODES[e["mode"]] for e in gone]}
        for c in ("sigma", "tau", "sigma_max", "tau_max"):
            data[c] = [e[c] for e in gone]
        name = f"breaks_{step}.vtp"
        with open(os.path.join(out, name), "w", encoding="utf-8") as f:
            f.write(polydata([tuple(e["x"]) for e in gone], verts=range(len(gone)), point_data=data))
        breaks.append((step, name))
    with open(os.path.join(out, "bonds.pvd"), "w", encoding="utf-8") as f:
        f.write(pvd(bonds))
    if events is not None:
        with open(os.path.join(out, "breaks.pvd"), "w", encoding="utf-8") as f:
            f.write(pvd(breaks))
    return len(bonds)


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("dump", help="the dump local file of the per-bond compute")
    p.add_argument("--columns", required=True, help="the compute's keywords, in order (quoted)")
    p.add_argument("--breaklog", help="the file of fix bond/breaklog")
    p.add_argument("--out", required=True, help="directory for the .vtp and .pvd files")
    a = p.parse_args(argv)
    try:
        n = write(a.dump, a.columns, a.out, a.breaklog)
    except (OSError, ValueError) as e:
        print(f"bonds_to_vtk: {e}", file=sys.stderr)
        return 1
    print(f"bonds_to_vtk: {n} steps written to {a.out}/bonds.pvd" + (" and breaks.pvd" if a.breaklog else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
