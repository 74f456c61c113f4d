#!/usr/bin/python3
"""Energy history of a poromechanics run (the terms of the paper's estimate (19)).

Usage: plot_energy.py HISTORY_CSV PICTURE.png

Top: the stored energies E = capillary (matrix, fracture) + elastic + storage p_E^2/(2M) against
time. Bottom: per step, the left side E_{n+1} - E_n + flow dissipation + frictional work against
the supplied work (the inequality requires left <= right), and energy_inequality_violation.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

YEAR = 3.15576e7
STORED = ["energy_capillary_matrix", "energy_capillary_fracture", "energy_elastic",
          "energy_storage"]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time"]) / YEAR for r in rows]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    for name in STORED:
        top.plot(t, [abs(float(r[name])) for r in rows], label=name.replace("energy_", ""))
    top.set_yscale("log")
    top.set_ylabel("stored energy (J)")
    top.legend(fontsize=8)
    top.grid(True, which="both", alpha=0.3)

    energy = [sum(float(r[n]) for n in STORED) for r in rows]
    left, right = [], []
    for k, r in enumerate(rows):
        previous = energy[k - 1] if k > 0 else None
        if previous is None:
            continue
        left.append(energy[k] - previous + float(r["flow_dissipation"]) + float(r["friction_work"]))
        right.append(float(r["supplied_work"]))
    bottom.plot(t[1:], [abs(v) for v in right], label="|supplied work| per step")
    bottom.plot(t[1:], [abs(v) for v in left], "--",
                label="|ΔE + dissipation + friction work| per step")
    violation = max(float(r["energy_inequality_violation"]) for r in rows)
    bottom.set_title(f"largest relative violation of (19): {violation:.3g}", fontsize=10)
    bottom.set_yscale("log")
    bottom.set_xscale("log")
    bottom.set_xlabel("time (years)")
    bottom.set_ylabel("J per step")
    bottom.legend(fontsize=8)
    bottom.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)


if __name__ == "__main__":
    main()
