#!/usr/bin/python3
"""Error against wall time from fluid_accuracy's CSV, one panel per case, one line per
alpha mode (point-sampled, sub-sampled) through the grid levels, labelled with the level.

    /usr/bin/python3 bench/fluid_accuracy/plot.py fluid_accuracy.csv fluid_accuracy.png
"""
import csv
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import error_plot  # noqa: E402  (bench/error_plot.py)


def read(csv_path):
    """case -> alpha -> [(wall, |error|, level)]"""
    runs = defaultdict(lambda: defaultdict(list))
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            runs[row["case"]][row["alpha"]].append(
                (float(row["wall_seconds"]), abs(float(row["error"])), row["level"]))
    return runs


def main(csv_path, png_path):
    error_plot.figure(read(csv_path), png_path, ylabel="|relative error|", legend_title="alpha")


if __name__ == "__main__":
    main(*sys.argv[1:3]) if len(sys.argv) == 3 else sys.exit(__doc__)
