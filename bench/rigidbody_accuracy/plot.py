#!/usr/bin/python3
"""Error against wall time from rigidbody_accuracy's CSV, one panel per scene, one colour
per solver; the line joins each solver's runs that no cheaper run of it beats.

    /usr/bin/python3 bench/rigidbody_accuracy/plot.py accuracy.csv accuracy.png
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def front(points):
    """The points that are more accurate than every faster point (the cost-accuracy front)."""
    best, out = float("inf"), []
    for wall, error in sorted(points):
        if error < best:
            best = error
            out.append((wall, error))
    return out


def main(csv_path, png_path):
    runs = defaultdict(lambda: defaultdict(list))  # scene -> solver family -> [(wall, error)]
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            if row["error"] and float(row["error"]) > 0:
                family = row["solver"].split()[0]
                runs[row["scene"]][family].append((float(row["wall_seconds"]), float(row["error"])))
    scenes = sorted(runs)
    fig, axes = plt.subplots(1, len(scenes), figsize=(6 * len(scenes), 4.5), squeeze=False)
    for ax, scene in zip(axes[0], scenes):
        for family, points in sorted(runs[scene].items()):
            line = ax.plot(*zip(*front(points)), "-", label=family)[0]
            ax.plot(*zip(*points), "o", ms=3, alpha=0.4, color=line.get_color())
        ax.set(xscale="log", yscale="log", xlabel="wall time [s]", title=scene,
               ylabel="end-position error / size" if scene == scenes[0] else None)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
