#!/usr/bin/python3
"""Plots a PoroFrac cut mesh and its fractures from the legacy VTK files that
`porofrac DECK --set Output/Format=vtk` writes (mesh.vtk, mesh_fractures.vtk).

Usage: plot_mesh.py OUTPUT_DIR PICTURE.png [--zoom x0 x1 y0 y1]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def read_legacy_vtk(path):
    """Returns points, cells and cell scalars of an ASCII legacy VTK unstructured grid.

    POINT_DATA scalars (DataOut writes each simplex as its own patch, so a cell's points carry
    its values) are averaged over the points of each cell.
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


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    directory, picture = sys.argv[1], sys.argv[2]
    points, cells, _ = read_legacy_vtk(directory + "/mesh.vtk")
    fpoints, fcells, fdata = read_legacy_vtk(directory + "/mesh_fractures.vtk")
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
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"Cut mesh: {len(triangles)} triangles, {len(fcells)} fracture faces")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8)
    fig.tight_layout()
    fig.savefig(picture, dpi=150)


if __name__ == "__main__":
    main()
