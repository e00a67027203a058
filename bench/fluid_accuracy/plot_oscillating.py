#!/usr/bin/python3
"""Drag and lift coefficient histories of the oscillating cylinder from fluid_accuracy
--oscillating's CSV: one row of panels per coefficient, one line per grid level and body
method (thin: every step; the smooth part dashed; the axis limits leave out the impulsive
start, when the body sets off at full speed through fluid at rest), and on the right the
last period's spurious part (coefficient minus its smooth part).

    /usr/bin/python3 bench/fluid_accuracy/plot_oscillating.py oscillating.csv oscillating.png

An older CSV without the `method` column (the staircase alone) is read as well.
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

PERIOD = 4.0  # s, 1 / 0.25 Hz
SETTLED = PERIOD / 8  # the start's impulse has decayed by then


def level_number(level):
    """The cells per diameter of a level such as "D/h=10" (its order)."""
    try:
        return int(level.split("=")[1])
    except (IndexError, ValueError):
        return 0


def main(csv_path, png_path):
    runs = defaultdict(lambda: defaultdict(list))  # (method, level) -> column -> values
    methods = []  # in the order of the CSV
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            method = row.get("method") or ""
            if method not in methods:
                methods.append(method)
            for column in ("time", "drag", "lift", "drag_smooth", "lift_smooth"):
                runs[(method, row["level"])][column].append(float(row[column]))
    order = sorted(runs, key=lambda key: (methods.index(key[0]), level_number(key[1])))
    fig, axes = plt.subplots(2, 2, figsize=(14, 8), gridspec_kw={"width_ratios": [2, 1]})
    for name, (history, spurious) in zip(("drag", "lift"), axes):
        settled = []
        for key in order:
            h = runs[key]
            label = f"{key[1]}, {key[0]}" if key[0] else key[1]
            settled += [c for t, c in zip(h["time"], h[name]) if t > SETTLED]
            line, = history.plot(h["time"], h[name], lw=0.6, label=label)
            history.plot(h["time"], h[name + "_smooth"], "--", lw=1, color=line.get_color())
            start = h["time"][-1] - PERIOD
            last = [(t, c - s) for t, c, s in zip(h["time"], h[name], h[name + "_smooth"]) if t > start]
            spurious.plot([t for t, _ in last], [r for _, r in last], lw=0.6, color=line.get_color(),
                          label=label)
        if settled:
            margin = 0.05 * (max(settled) - min(settled))
            history.set_ylim(min(settled) - margin, max(settled) + margin)
        label = "C_D" if name == "drag" else "C_L"
        history.set_ylabel(label + " = 2F / (rho U^2 D T), U = 0.3927 m/s")
        spurious.set_ylabel(label + " - smooth part")
        for ax in (history, spurious):
            ax.grid(True, alpha=0.3)
            ax.legend(fontsize=7)
    axes[1][0].set_xlabel("t [s]")
    axes[1][1].set_xlabel("t [s] (last period)")
    fig.suptitle("Oscillating cylinder in the DFG channel: force histories per grid level and body method")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:3]) if len(sys.argv) == 3 else sys.exit(__doc__)
