#!/usr/bin/python3
"""ten Cate E4 by both body treatments, error against wall time, from a table of runs:

    bench/tencate/methods_plot.py runs.csv out.png

runs.csv columns: method, alignment (edges or centres), cells (e.g. 40x40x64), d_over_h,
wall_seconds, u_max_over_u_inf (of the run, as bench/tencate/tencate.py prints it). One line
per method and alignment through its grids, each point labelled with its d/h; the error is
against the experiment's 0.955 (ten Cate et al. 2002, docs/references.md).
"""
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import error_plot  # noqa: E402  (bench/error_plot.py)

EXPERIMENT = 0.955


def read(path):
    series = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            name = f"{row['method']}, axis along cell {row['alignment']}"
            error = abs(float(row["u_max_over_u_inf"]) / EXPERIMENT - 1)
            series.setdefault(name, []).append((float(row["wall_seconds"]), error, f"d/h {row['d_over_h']}"))
    return {"ten Cate E4, u_max/u_inf": series}


def main(csv_path, png_path):
    error_plot.figure(read(csv_path), png_path, ylabel="|u_max/u_inf / 0.955 - 1|", legend_title="method")


if __name__ == "__main__":
    main(*sys.argv[1:3]) if len(sys.argv) == 3 else sys.exit(__doc__)
