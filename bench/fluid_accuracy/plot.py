#!/usr/bin/python3
"""Error against wall time from fluid_accuracy's CSV: one panel per case, one line per
body method (the immersed boundary, the staircase) through the grid levels, each point
labelled with its level. A level run at several body positions (Hasimoto) is one point: the
absolute mean error over the positions against the mean wall time per position, with a bar
over the range |error| takes at those positions.

    /usr/bin/python3 bench/fluid_accuracy/plot.py fluid_accuracy.csv fluid_accuracy.png

scripts/study uses summarise() for its table too. An older CSV with an `alpha` column in
place of `method` (point-sampled or sub-sampled staircase) is read as well.
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import error_plot  # noqa: E402  (bench/error_plot.py)


def summarise(csv_path):
    """One dict per (case, level, method) in the order of first appearance: the means over
    its rows (positions) of value, reference, error, check, steps and wall_seconds, the
    error's min and max, the number of rows as positions, and cells."""
    groups = {}
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            method = row["method"] if "method" in row else row["alpha"]
            groups.setdefault((row["case"], row["level"], method), []).append(row)
    summary = []
    for (case, level, method), rows in groups.items():
        def mean(column):
            present = [float(r[column]) for r in rows if r.get(column) not in (None, "")]
            return sum(present) / len(present) if present else None

        errors = [float(r["error"]) for r in rows]
        summary.append({"case": case, "level": level, "method": method, "cells": rows[0]["cells"],
                        "positions": len(rows), "steps": mean("steps"), "wall_seconds": mean("wall_seconds"),
                        "value": mean("value"), "reference": mean("reference"), "error": mean("error"),
                        "error_min": min(errors), "error_max": max(errors), "check": mean("check")})
    return summary


def absolute_range(low, high):
    """The range of |e| for e in [low, high]."""
    if low <= 0 <= high:
        return 0.0, max(-low, high)
    return min(abs(low), abs(high)), max(abs(low), abs(high))


def read(csv_path):
    """panel title (the case) -> method -> [(mean wall, |mean error|, level[, range of |error|])]"""
    summary = summarise(csv_path)
    several = {s["case"] for s in summary if s["positions"] > 1}
    runs = {}
    for s in summary:
        point = (s["wall_seconds"], abs(s["error"]), s["level"].replace("^3", "³"))
        if s["positions"] > 1:
            point += (absolute_range(s["error_min"], s["error_max"]),)
        title = s["case"] + (" (mean over positions, wall time per position)" if s["case"] in several else "")
        runs.setdefault(title, {}).setdefault(s["method"], []).append(point)
    return runs


def main(csv_path, png_path):
    error_plot.figure(read(csv_path), png_path,
                      ylabel="|relative error| (several positions: mean, bar: range)", legend_title="method")


if __name__ == "__main__":
    main(*sys.argv[1:3]) if len(sys.argv) == 3 else sys.exit(__doc__)
