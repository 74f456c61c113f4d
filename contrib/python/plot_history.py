#!/usr/bin/python3
"""Time-step and iteration history of PoroFrac runs (history.csv of the output contract).

Usage: plot_history.py OUTPUT.png LABEL=RUN_DIR [LABEL=RUN_DIR ...]

Plots, against time in years (log scale): the time step, the nonlinear iterations per step
(flow Newton, and coupling/mechanics iterations when present) and the cumulative time-step cuts.
Prints a one-line summary per run (steps, iterations, cuts, largest mass-balance error).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

YEAR = 3.15576e7


def read(run_dir):
    with open(f"{run_dir}/history.csv") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    out = sys.argv[1]
    fig, ax = plt.subplots(3, 1, figsize=(7, 9), sharex=True)
    for spec in sys.argv[2:]:
        label, run_dir = spec.split("=", 1)
        h = read(run_dir)
        t = [x / YEAR for x in h["time"]]
        ax[0].loglog(t, [x / YEAR for x in h["dt"]], label=label)
        ax[1].semilogx(t, h["flow_newton_iterations"], label=f"{label}: flow Newton")
        if max(h.get("mechanics_iterations", [0])) > 0:
            ax[1].semilogx(t, h["mechanics_iterations"], "--", label=f"{label}: mechanics")
        if max(h.get("coupling_iterations", [0])) > 0:
            ax[1].semilogx(t, h["coupling_iterations"], ":", label=f"{label}: coupling")
        cuts, c = [], 0
        for x in h["time_step_cuts"]:
            c += x
            cuts.append(c)
        ax[2].semilogx(t, cuts, label=label)
        print(
            f"{label}: {len(t)} steps to t = {t[-1]:.4g} y, "
            f"{int(sum(h['flow_newton_iterations']))} flow Newton iterations "
            f"(max {int(max(h['flow_newton_iterations']))} per step), {int(c)} cuts, "
            f"mass balance error max {max(h['mass_balance_error']):.3g}"
        )
    ax[0].set_ylabel("time step (years)")
    ax[1].set_ylabel("iterations per step")
    ax[2].set_ylabel("cumulative time-step cuts")
    ax[2].set_xlabel("time (years)")
    for a in ax:
        a.grid(True, which="both", alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    main()
