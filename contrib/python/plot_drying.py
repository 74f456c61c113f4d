#!/usr/bin/python3
"""Reproduces the paper's Figs. 14-18 (Section 5.3) from PoroFrac runs of prm/drying_cylinder.prm
(VTU, the deck's format, also the .pvtu pieces of runs on several processes, or legacy VTK with
`Output/Format = vtk`).

Usage: plot_drying.py --fields FIELDS_DIR --out PICTURE_DIR
                      [--as AS_DIR --ssn SSN_DIR [--as-u AS_U_DIR] [--anderson ANDERSON_DIR]]
  FIELDS_DIR    the run whose fracture states, apertures and final fields are drawn: Figs. 14,
                16, 17 (drying_fig14_states.png, drying_fig16_aperture.png,
                drying_fig17_fields.png); default AS_DIR
  AS_DIR        active set + Newton-Krylov on p_E
  SSN_DIR       semi-smooth Newton (c = 1e9) + Newton-Krylov on p_E
  AS_U_DIR      active set + Newton-Krylov on u
  ANDERSON_DIR  active set + Anderson on p_E
  With --as and --ssn, also Figs. 15 and 18 (drying_fig15_width.png, drying_fig18_iterations.png).

       plot_drying.py --iterations-only PICTURE.png --as AS_DIR [--ssn SSN_DIR]
                      [--as-u AS_U_DIR] [--anderson ANDERSON_DIR] [--deck DECK_DIR] [--title TITLE]
  Fig. 18 alone, for whichever runs are given (their history.csv is enough).

       plot_drying.py --width-only PICTURE.png --as AS_DIR [--ssn SSN_DIR] [--anderson DIR]
  Fig. 15 alone (history.csv is enough).

The radial section is drawn with the axial coordinate x and the radius r.
"""
import argparse
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
from matplotlib.collections import LineCollection, PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(__file__))
from plot_mesh import read_fields  # noqa: E402

YEAR = 3.15576e7
STATE_NAMES = ["open", "stick", "slip"]
STATE_COLOURS = ["tab:red", "tab:blue", "tab:green"]


def read_history(directory):
    with open(os.path.join(directory, "history.csv")) as f:
        return list(csv.DictReader(f))


def read_pvd(directory):
    """(time, file) of every dataset of poromechanics.pvd."""
    with open(os.path.join(directory, "poromechanics.pvd")) as f:
        text = f.read()
    return [(float(t), name) for t, name in
            re.findall(r'timestep="([^"]+)" file="([^"]+)"', text)]


def snapshots(directory, times):
    """(time, base name, extension) of the datasets closest to the requested times (s)."""
    entries = read_pvd(directory)
    chosen = []
    for t in times:
        best = min(entries, key=lambda e: abs(e[0] - t))
        base, extension = os.path.splitext(best[1])
        chosen.append((best[0], os.path.join(directory, base), extension))
    return chosen


def fracture_segments(base, extension):
    # Runs on several processes list .pvtu records; their fracture files are whole .vtu files.
    if extension == ".pvtu":
        extension = ".vtu"
    points, cells, data = read_fields(base + "_fractures" + extension)
    segments = [[points[c[0]], points[c[1]]] for c in cells]
    return segments, data


def plot_fracture_field(directory, times, picture, field, title, states=False):
    shots = snapshots(directory, times)
    fig, axes = plt.subplots(len(shots), 1, figsize=(9, 2.6 * len(shots)), sharex=True)
    fields = [fracture_segments(base, extension) for _, base, extension in shots]
    # One colour scale for every panel, so that the panels can be compared; logarithmic, since
    # apertures range from d_0 = 1 mm on closed faces to about ten times that at the wall.
    if not states:
        values = [1e3 * v for _, data in fields for v in data[field]]
        norm = matplotlib.colors.LogNorm(vmin=min(values), vmax=max(values))
    for ax, (t, _, _), (segments, data) in zip(axes, shots, fields):
        if states:
            colours = [STATE_COLOURS[int(round(v))] for v in data["state"]]
            ax.add_collection(LineCollection(segments, colors=colours, linewidths=3))
            for name, colour in zip(STATE_NAMES, STATE_COLOURS):
                ax.plot([], [], color=colour, lw=3, label=name)
            ax.legend(loc="upper right", fontsize=8, ncol=3)
        else:
            lc = LineCollection(segments, array=[1e3 * v for v in data[field]], cmap="viridis",
                                norm=norm, linewidths=3)
            ax.add_collection(lc)
        ax.set_xlim(0, 10)
        ax.set_ylim(4.9, 6.6)
        ax.set_ylabel("r (m)")
        ax.set_title(f"{title}, t = {t / YEAR:.3g} years", fontsize=10)
    axes[-1].set_xlabel("x (m)")
    fig.tight_layout()
    if not states:
        fig.subplots_adjust(right=0.86)
        bar = fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap="viridis"),
                           cax=fig.add_axes([0.89, 0.1, 0.02, 0.8]), label="aperture (mm)")
        bar.set_ticks([v for v in (1, 1.5, 2, 3, 4, 6, 8, 10, 15, 20)
                       if norm.vmin <= v <= norm.vmax])
        bar.ax.yaxis.set_major_formatter(matplotlib.ticker.FormatStrFormatter("%g"))
        bar.ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    fig.savefig(picture, dpi=120)
    plt.close(fig)


def plot_width(runs, picture):
    fig, ax = plt.subplots(figsize=(6.5, 4))
    for directory, label, style in runs:
        h = read_history(directory)
        ax.plot([float(r["time"]) / YEAR for r in h],
                [float(r["mean_fracture_width"]) * 1e3 for r in h], style, label=label)
    ax.set_xlabel("time (years)")
    ax.set_ylabel("mean fracture width (mm)")
    ax.set_xscale("log")
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(picture, dpi=120)
    plt.close(fig)


def plot_fields(directory, picture):
    t, base = read_pvd(directory)[-1]
    points, cells, data = read_fields(os.path.join(directory, base))
    triangles = [[points[i] for i in c] for c in cells if len(c) == 3]
    fig, axes = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    for ax, (name, label, scale) in zip(axes, [("s_nw", "gas saturation", 1),
                                               ("p_E", "equivalent pressure (MPa)", 1e-6),
                                               ("porosity", "porosity", 1)]):
        pc = PolyCollection(triangles, array=[scale * v for v in data[name]], cmap="viridis",
                            edgecolors="face", linewidths=0.3)
        ax.add_collection(pc)
        fig.colorbar(pc, ax=ax, label=label)
        ax.set_xlim(0, 10)
        ax.set_ylim(5, 7)
        ax.set_ylabel("r (m)")
    axes[0].set_title(f"t = {t / YEAR:.3g} years", fontsize=10)
    axes[-1].set_xlabel("x (m)")
    fig.tight_layout()
    fig.savefig(picture, dpi=120)
    plt.close(fig)


def plot_iterations(runs, picture, title=None):
    fig, ax = plt.subplots(figsize=(6.5, 4))
    if title:
        ax.set_title(title, fontsize=9)
    for directory, label in runs:
        h = read_history(directory)
        total = sum(int(r["flow_newton_iterations"]) + int(r["mechanics_iterations"]) for r in h)
        ax.plot([float(r["time"]) / YEAR for r in h],
                [int(r["flow_newton_iterations"]) + int(r["mechanics_iterations"]) for r in h],
                label=f"{label} (total {total})")
    ax.set_xlabel("time (years)")
    ax.set_ylabel("flow + mechanics iterations per step")
    ax.set_xscale("log")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(picture, dpi=120)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--as", dest="as_dir")
    parser.add_argument("--ssn")
    parser.add_argument("--as-u", dest="as_u")
    parser.add_argument("--fields")
    parser.add_argument("--anderson")
    parser.add_argument("--deck", help="--iterations-only: the deck's run, for reference")
    parser.add_argument("--out")
    parser.add_argument("--iterations-only")
    parser.add_argument("--title")
    parser.add_argument("--width-only")
    a = parser.parse_args()
    if a.width_only:
        plot_width([(d, label, style) for d, label, style in
                    [(a.as_dir, "active set (c = 1e6) + NK(p_E)", "-"),
                     (a.ssn, "semi-smooth Newton (c = 1e9) + NK(p_E)", "--"),
                     (a.anderson, "active set + Anderson(p_E)", ":")] if d], a.width_only)
        return
    if a.iterations_only:
        runs = [(d, label) for d, label in [(a.as_dir, "active set + NK(p_E)"),
                                            (a.ssn, "semi-smooth Newton + NK(p_E)"),
                                            (a.as_u, "active set + NK(u)"),
                                            (a.anderson, "active set + Anderson(p_E)"),
                                            (a.deck, "deck: active set + Anderson(p_E), "
                                                     "extrapolated start")] if d]
        plot_iterations(runs, a.iterations_only, a.title)
        return
    fields = a.fields or a.as_dir
    if not (a.out and fields):
        parser.error("--out and --fields (or --as) are required")
    times = [0., 1 * YEAR, 50 * YEAR, 200 * YEAR]
    plot_fracture_field(fields, times, os.path.join(a.out, "drying_fig14_states.png"), "state",
                        "contact state", states=True)
    plot_fracture_field(fields, times, os.path.join(a.out, "drying_fig16_aperture.png"),
                        "aperture", "aperture")
    plot_fields(fields, os.path.join(a.out, "drying_fig17_fields.png"))
    if not (a.as_dir and a.ssn):
        return
    widths = [(a.as_dir, "active set (c = 1e6) + NK(p_E)", "-"),
              (a.ssn, "semi-smooth Newton (c = 1e9) + NK(p_E)", "--")]
    iterations = [(a.as_dir, "active set + NK(p_E)"), (a.ssn, "semi-smooth Newton + NK(p_E)")]
    if a.as_u:
        iterations.append((a.as_u, "active set + NK(u)"))
    if a.anderson:
        widths.append((a.anderson, "active set + Anderson(p_E)", ":"))
        iterations.append((a.anderson, "active set + Anderson(p_E)"))
    plot_width(widths, os.path.join(a.out, "drying_fig15_width.png"))
    plot_iterations(iterations, os.path.join(a.out, "drying_fig18_iterations.png"))


if __name__ == "__main__":
    main()
