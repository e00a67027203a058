#!/usr/bin/python3
"""Error against wall time from fluid_accuracy's CSV, one panel per case, one line per
alpha mode (point-sampled, sub-sampled) through the grid levels, labelled with the level.

    /usr/bin/python3 bench/fluid_accuracy/plot.py fluid_accuracy.csv fluid_accuracy.png
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(csv_path, png_path):
    runs = defaultdict(lambda: defaultdict(list))  # case -> alpha -> [(wall, |error|, level)]
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            runs[row["case"]][row["alpha"]].append(
                (float(row["wall_seconds"]), abs(float(row["error"])), row["level"]))
    cases = sorted(runs)
    fig, axes = plt.subplots(1, len(cases), figsize=(6 * len(cases), 4.5), squeeze=False)
    for ax, case in zip(axes[0], cases):
        for alpha, points in sorted(runs[case].items()):
            points.sort()
            ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label=alpha)
            for wall, error, level in points:
                ax.annotate(level, (wall, error), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time [s]")
        ax.set_title(case)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(title="alpha")
    axes[0][0].set_ylabel("|relative error|")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:3]) if len(sys.argv) == 3 else sys.exit(__doc__)
