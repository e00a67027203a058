#!/usr/bin/python3
"""Viscosity error against wall time from dsmc_study's CSV: one line per sweep (particles
per cell, cell size, time step) with its standard errors, each point labelled with the
parameter it varies, and the Green-Kubo prediction of each point as an open marker.

    /usr/bin/python3 bench/dsmc_study/plot.py dsmc_study.csv dsmc_study.png
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

LABEL = {"ppc": ("particles_per_cell", "N={:g}"), "cell": ("cell_over_lambda", "dx={:.2g}"),
         "dt": ("dt_over_collision_time", "dt={:.2g}"), "ref": ("particles_per_cell", "N={:g}")}


def read(csv_path):
    """sweep -> [(wall, error %, sigma %, predicted %, label)]"""
    runs = defaultdict(list)
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            column, fmt = LABEL[row["sweep"]]
            runs[row["sweep"]].append((float(row["wall_seconds"]), 100 * float(row["error"]),
                                       100 * float(row["error_sigma"]), 100 * float(row["predicted"]),
                                       fmt.format(float(row[column]))))
    return runs


def draw(ax, runs):
    for sweep, points in sorted(runs.items()):
        points.sort()
        line = ax.errorbar([p[0] for p in points], [p[1] for p in points], yerr=[p[2] for p in points], fmt="o-",
                           capsize=3, label=sweep)
        ax.plot([p[0] for p in points], [p[3] for p in points], "o", mfc="none", color=line[0].get_color())
        for wall, error, _, _, label in points:
            ax.annotate(label, (wall, error), fontsize=7, xytext=(3, 3), textcoords="offset points")
    ax.axhline(0.0, color="gray", lw=0.8)
    ax.set_xscale("log")
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("mu / mu_CE - 1 [%]  (open: Green-Kubo prediction)")
    ax.set_title("DSMC Couette flow, hard-sphere argon, Kn = 0.05")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(title="sweep")


def main(csv_path, png_path):
    fig, ax = plt.subplots(figsize=(7, 4.5))
    draw(ax, read(csv_path))
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(*sys.argv[1:3]) if len(sys.argv) == 3 else sys.exit(__doc__)
