#!/usr/bin/python3
"""Plots a PoroFrac cut mesh and its fractures from the files a run writes (mesh.vtu and
mesh_fractures.vtu, or mesh.vtk and mesh_fractures.vtk with `Output/Format = vtk`).

Usage: plot_mesh.py OUTPUT_DIR PICTURE.png [--zoom x0 x1 y0 y1] [--axes x,r]
  --axes: names of the two coordinates on the axis labels (default x,y; the radial section of an
          axisymmetric scene is (x, r)).

Also the readers of the other plotting scripts: read_fields(path) returns the points, cells and
cell data of a .vtk (legacy ASCII) or .vtu (XML, ASCII or deal.II's zlib-compressed binary) file.
"""
import base64
import os
import struct
import sys
import xml.etree.ElementTree as ElementTree
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def read_legacy_vtk(path):
    """Returns points, cells and cell scalars of an ASCII legacy VTK unstructured grid.

    POINT_DATA scalars (the displacement files, which DataOut writes with each cell as its own
    patch) are averaged over the points of each cell.
    """
    with open(path) as f:
        tokens = f.read().split()
    points, cells, data = [], [], {}
    location, count = "CELL_DATA", 0
    i = 0
    while i < len(tokens):
        t = tokens[i]
        if t == "POINTS":
            n = int(tokens[i + 1])
            values = list(map(float, tokens[i + 3:i + 3 + 3 * n]))
            points = [values[3 * k:3 * k + 2] for k in range(n)]
            i += 3 + 3 * n
        elif t == "CELLS":
            n = int(tokens[i + 1])
            i += 3
            for _ in range(n):
                m = int(tokens[i])
                cells.append(list(map(int, tokens[i + 1:i + 1 + m])))
                i += 1 + m
        elif t in ("CELL_DATA", "POINT_DATA"):
            location, count = t, int(tokens[i + 1])
            i += 2
        elif t == "SCALARS":
            name = tokens[i + 1]
            i += 3
            if tokens[i] == "1":
                i += 1
            if tokens[i] == "LOOKUP_TABLE":
                i += 2
            n = count if count > 0 else len(cells)
            values = list(map(float, tokens[i:i + n]))
            i += n
            if location == "POINT_DATA":
                values = [sum(values[p] for p in c) / len(c) for c in cells]
            data[name] = values
        else:
            i += 1
    return points, cells, data


_TYPES = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt32": "I", "Int64": "q",
          "UInt64": "Q", "UInt8": "B", "Int8": "b"}


def _data_array(element, compressed):
    """The values of a VTU DataArray (ascii, or base64 binary, zlib-compressed or not)."""
    kind = _TYPES[element.get("type")]
    if element.get("format") == "ascii":
        values = (element.text or "").split()
        return [float(v) for v in values] if kind in "fd" else [int(float(v)) for v in values]
    text = "".join((element.text or "").split())
    size = struct.calcsize(kind)
    if not compressed:
        raw = base64.b64decode(text)
        n = struct.unpack("<I", raw[:4])[0]
        return list(struct.unpack("<%d%s" % (n // size, kind), raw[4:4 + n]))
    # Header (UInt32): number of blocks, block size, last block size, compressed block sizes;
    # base64-encoded on its own, followed by the base64 of the concatenated compressed blocks.
    n_blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    header_chars = ((4 * (3 + n_blocks) + 2) // 3) * 4
    header = struct.unpack("<%dI" % (3 + n_blocks), base64.b64decode(text[:header_chars]))
    data = base64.b64decode(text[header_chars:])
    raw, offset = b"", 0
    for k in range(n_blocks):
        raw += zlib.decompress(data[offset:offset + header[3 + k]])
        offset += header[3 + k]
    return list(struct.unpack("<%d%s" % (len(raw) // size, kind), raw))


def read_vtu(path):
    """Points (x, y), cells (lists of point indices) and cell data of a VTU unstructured grid.
    POINT_DATA arrays are averaged over the points of each cell, as in read_legacy_vtk."""
    root = ElementTree.parse(path).getroot()
    compressed = root.get("compressor") is not None
    piece = root.find("UnstructuredGrid/Piece")
    xyz = _data_array(piece.find("Points/DataArray"), compressed)
    points = [xyz[3 * k:3 * k + 2] for k in range(len(xyz) // 3)]
    arrays = {a.get("Name"): a for a in piece.find("Cells")}
    connectivity = _data_array(arrays["connectivity"], compressed)
    offsets = _data_array(arrays["offsets"], compressed)
    cells, start = [], 0
    for end in offsets:
        cells.append(connectivity[start:end])
        start = end
    data = {}
    for location in ("CellData", "PointData"):
        block = piece.find(location)
        if block is None:
            continue
        for a in block:
            if int(a.get("NumberOfComponents", "1")) != 1:
                continue
            values = _data_array(a, compressed)
            if location == "PointData":
                values = [sum(values[p] for p in c) / len(c) for c in cells]
            data[a.get("Name")] = values
    return points, cells, data


def read_pvtu(path):
    """The pieces a .pvtu record lists (runs on several processes), joined as one read_vtu."""
    root = ElementTree.parse(path).getroot()
    points, cells, data = [], [], {}
    for piece in root.iter("Piece"):
        p, c, d = read_vtu(os.path.join(os.path.dirname(path), piece.get("Source")))
        cells += [[k + len(points) for k in cell] for cell in c]
        points += p
        for name, values in d.items():
            data.setdefault(name, []).extend(values)
    return points, cells, data


def read_fields(path):
    """read_vtu, read_pvtu or read_legacy_vtk, by the file's extension."""
    if path.endswith(".pvtu"):
        return read_pvtu(path)
    return read_vtu(path) if path.endswith(".vtu") else read_legacy_vtk(path)


def mesh_file(directory, name):
    """DIRECTORY/NAME.vtu, .pvtu (one piece per process) or .vtk, the first that exists."""
    for extension in (".vtu", ".pvtu"):
        path = os.path.join(directory, name + extension)
        if os.path.exists(path):
            return path
    return os.path.join(directory, name + ".vtk")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    directory, picture = sys.argv[1], sys.argv[2]
    points, cells, _ = read_fields(mesh_file(directory, "mesh"))
    fpoints, fcells, fdata = read_fields(mesh_file(directory, "mesh_fractures"))
    names = ["x", "y"]
    if "--axes" in sys.argv:
        names = sys.argv[sys.argv.index("--axes") + 1].split(",")
    triangles = [c for c in cells if len(c) == 3]
    fig, ax = plt.subplots(figsize=(10, 5.5))
    segments = []
    for t in triangles:
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            segments.append((points[a], points[b]))
    ax.add_collection(LineCollection(segments, colors="0.55", linewidths=0.25))
    ids = fdata.get("fracture_id", [0] * len(fcells))
    colours = plt.get_cmap("tab10")
    for cell, fid in zip(fcells, ids):
        xs = [fpoints[k][0] for k in cell]
        ys = [fpoints[k][1] for k in cell]
        ax.plot(xs, ys, color=colours(int(fid) % 10), linewidth=2.2, solid_capstyle="butt")
    for fid in sorted(set(ids)):
        ax.plot([], [], color=colours(int(fid) % 10), linewidth=2.2, label=f"fracture {int(fid)}")
    ax.set_aspect("equal")
    ax.autoscale()
    if "--zoom" in sys.argv:
        k = sys.argv.index("--zoom")
        x0, x1, y0, y1 = map(float, sys.argv[k + 1:k + 5])
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    ax.set_xlabel(names[0] + " (m)")
    ax.set_ylabel(names[1] + " (m)")
    ax.set_title(f"Cut mesh: {len(triangles)} triangles, {len(fcells)} fracture faces")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    fig.tight_layout()
    fig.savefig(picture, dpi=150)


if __name__ == "__main__":
    main()
