#!/usr/bin/python3
"""Plots the fracture faces of a 3D PoroFrac cut mesh, coloured by fracture, with the
intersection and boundary lines of the fractures and the outline of the box, from the files a
run writes: mesh_fractures.vtu and mesh_fracture_edges.vtu (ASCII XML).

Usage: plot_fractures_3d.py OUTPUT_DIR PICTURE.png [--box X0 Y0 Z0 X1 Y1 Z1]
                             [--views ELEV,AZIM ELEV,AZIM ...]
  --box: the domain (default: the bounding box of the fractures).
"""
import os
import sys
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402


def read_cells(path):
    """Points (x, y, z), cells (point index lists) and cell data of an ASCII VTU file."""
    piece = ElementTree.parse(path).getroot().find("UnstructuredGrid/Piece")
    xyz = [float(v) for v in piece.find("Points/DataArray").text.split()]
    points = [xyz[3 * k:3 * k + 3] for k in range(len(xyz) // 3)]
    arrays = {a.get("Name"): a for a in piece.find("Cells")}
    connectivity = [int(v) for v in arrays["connectivity"].text.split()]
    offsets = [int(v) for v in arrays["offsets"].text.split()]
    cells, start = [], 0
    for end in offsets:
        cells.append(connectivity[start:end])
        start = end
    data = {a.get("Name"): [float(v) for v in (a.text or "").split()]
            for a in piece.find("CellData")}
    return points, cells, data


def bounding_box(points):
    """Lower and upper corners of the bounding box of the points."""
    lo = [min(p[d] for p in points) for d in range(3)]
    hi = [max(p[d] for p in points) for d in range(3)]
    return lo, hi


def option(name, count):
    """The @p count values after --name on the command line, or None."""
    if "--" + name not in sys.argv:
        return None
    k = sys.argv.index("--" + name)
    return sys.argv[k + 1:k + 1 + count]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    directory, picture = sys.argv[1], sys.argv[2]
    views = [(25, -60), (60, -120)]
    if "--views" in sys.argv:
        k = sys.argv.index("--views")
        views = [tuple(map(float, v.split(","))) for v in sys.argv[k + 1:] if "," in v]
    box = option("box", 6)
    box = [float(v) for v in box] if box else None
    points, cells, data = read_cells(os.path.join(directory, "mesh_fractures.vtu"))
    epoints, ecells, edata = read_cells(os.path.join(directory, "mesh_fracture_edges.vtu"))
    ids = [int(v) for v in data["fracture_id"]]
    colours = plt.get_cmap("tab10")
    lo, hi = (box[:3], box[3:]) if box else bounding_box(points + epoints)

    fig = plt.figure(figsize=(6.5 * len(views), 6))
    for k, (elev, azim) in enumerate(views):
        ax = fig.add_subplot(1, len(views), k + 1, projection="3d")
        ax.computed_zorder = False  # draw in the order added: the lines over the faces
        ax.grid(False)
        triangles = [[points[i] for i in c] for c in cells]
        ax.add_collection3d(Poly3DCollection(
            triangles, facecolors=[colours(i % 10) for i in ids], edgecolors="0.25",
            linewidths=0.15, alpha=0.85))
        for kind, colour, width in ((1, "black", 1.8), (2, "red", 1.8)):
            lines = [[epoints[i] for i in c] for c, t in zip(ecells, edata["edge_type"])
                     if int(t) == kind]
            if lines:
                ax.add_collection3d(Line3DCollection(lines, colors=colour, linewidths=width))
        corners = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                   for z in (lo[2], hi[2])]
        outline = [(a, b) for a in corners for b in corners
                   if a < b and sum(u != v for u, v in zip(a, b)) == 1]
        ax.add_collection3d(Line3DCollection(outline, colors="0.5", linewidths=0.6))
        ax.set_xlim(lo[0], hi[0])
        ax.set_ylim(lo[1], hi[1])
        ax.set_zlim(lo[2], hi[2])
        ax.set_box_aspect([hi[d] - lo[d] for d in range(3)])
        ax.view_init(elev=elev, azim=azim)
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.set_zlabel("z (m)")
    for fid in sorted(set(ids)):
        fig.axes[0].plot([], [], color=colours(fid % 10), linewidth=6, label=f"fracture {fid}")
    fig.axes[0].plot([], [], color="black", label="intersection lines")
    fig.axes[0].plot([], [], color="red", label="lines on the boundary")
    fig.legend(loc="upper center", ncol=6, fontsize=8)
    fig.suptitle(f"{len(cells)} fracture faces", y=0.04)
    fig.savefig(picture, dpi=130, bbox_inches="tight")


if __name__ == "__main__":
    main()
