#!/usr/bin/python3
"""Stokes drag of dense simple cubic arrays of spheres against Zick & Homsy's (J. Fluid Mech.
115, 1982, table 2): the shipped Hasimoto scene (configs/hasimoto-sphere.yaml) with the
sphere's radius set for each solid fraction c and the box's cells for each d/h, run by
`cosim-fluid --standalone` to t = 6 (3000 steps; U then changes by less than 1e-4 of itself
per window). The drag is the drive on the whole cell, F = rho f L^3, and the mean velocity U
over the box (sphere included) gives K = F / (6 pi mu a U), the coefficient Zick & Homsy
tabulate (their K tends to Hasimoto's as c -> 0). In these arrays the kernels of a sphere
and of its images overlap across the gap between them (two cells at c = 0.216 and d/h 6),
which the dilute Hasimoto array, where the retraction is calibrated, does not test.

    bench/fluid_accuracy/dense_arrays.py [--cases 0.216:8 0.216:16 ...] [--positions K]
        [--csv FILE] [--check C:N --within PERCENT]

--cases takes c:n pairs (n cells a side; d/h = 2 a n with a = (3 c / (4 pi))^(1/3)), by
default four fractions of the table at about d/h 6 and 12; --positions runs each at the
first K of four places of the sphere's centre relative to the grid (on a grid point, then
three generic ones; a sphere reaching across the box's faces wraps round them), the spread
over them being the method's dependence on how the body meets the grid; --csv writes the rows
(bench/fluid_accuracy/dense_arrays.csv, rendered by scripts/results); --check runs the one
case (at each of the --positions) and exits 1 when K is off Zick & Homsy's by more than --within percent (the ctest).
"""
import argparse
import math
import os
import sys
import tempfile
from pathlib import Path

import periodic_box

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "bench"))
from results_table import upsert  # noqa: E402

# Zick & Homsy (1982), table 2, simple cubic arrays: solid fraction -> K.
ZICK_HOMSY = {0.027: 2.008, 0.064: 2.810, 0.125: 4.292, 0.216: 7.442, 0.343: 15.4, 0.45: 28.1, 0.5236: 42.1}
DEFAULT_CASES = ["0.125:10", "0.125:20", "0.216:8", "0.216:16", "0.343:7", "0.343:14", "0.45:8", "0.45:16"]
# The sphere's centre off the box's centre, in cells: on a grid point first, then generic.
OFFSETS = [(0, 0, 0), (0.37, 0.61, 0.19), (0.73, 0.11, 0.53), (0.23, 0.89, 0.71)]
COLUMNS = ["c", "cells", "d_over_h", "position", "K", "zick_homsy", "error", "steps", "wall_s", "command"]


def array_scene(c, n, offset):
    """The Hasimoto scene with the radius of fraction c, n^3 cells, the sphere `offset` cells
    off the box's centre, to t = 6; and the sphere's radius."""
    scene = periodic_box.hasimoto_scene()
    radius = (3 * c / (4 * math.pi)) ** (1 / 3)  # in a unit box
    sphere = scene["bodies"][0]
    sphere["shape"]["radius"] = radius
    sphere["position"] = [0.5 + o / n for o in offset]
    scene["participants"]["fluid"]["options"]["grid"]["cells"] = [n, n, n]
    scene["time"]["end"] = 6.0
    return scene, radius


def run_case(fluid, c, n, position, folder):
    scene, radius = array_scene(c, n, OFFSETS[position])
    result = periodic_box.run(fluid, scene, folder, f"c{c}_n{n}_p{position}")
    force, mu = periodic_box.drive(scene)
    k = force / (6 * math.pi * mu * radius * result["u"])
    reference = ZICK_HOMSY[c]
    return {"c": c, "cells": n, "d_over_h": f"{2 * radius * n:.2f}", "position": position, "K": f"{k:.4f}",
            "zick_homsy": reference, "error": f"{k / reference - 1:.4f}", "steps": result["steps"],
            "wall_s": f"{result['wall']:.0f}"}


def parse_case(text):
    c, n = text.split(":")
    if float(c) not in ZICK_HOMSY:
        sys.exit(f"dense_arrays.py: c = {c} is not in Zick & Homsy's table: {sorted(ZICK_HOMSY)}")
    return float(c), int(n)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cases", nargs="+", default=DEFAULT_CASES, help="c:n pairs")
    parser.add_argument("--positions", type=int, default=1, choices=range(1, len(OFFSETS) + 1),
                        help="places of the sphere per case")
    parser.add_argument("--csv", help="write the rows into this CSV")
    parser.add_argument("--check", help="run the one case c:n and compare")
    parser.add_argument("--within", type=float, default=5.0, help="--check's tolerance, per cent")
    parser.add_argument("--fluid", default=str(ROOT / "build/release/bin/cosim-fluid"))
    args = parser.parse_args()
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    cases = [parse_case(args.check)] if args.check else [parse_case(t) for t in args.cases]
    positions = args.positions
    command = "bench/fluid_accuracy/dense_arrays.py --cases " + " ".join(f"{c:g}:{n}" for c, n in cases)
    command += f" --positions {positions}" if positions > 1 else ""
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for c, n in cases:
            for position in range(positions):
                row = run_case(args.fluid, c, n, position, folder)
                row["command"] = command
                rows.append(row)
                if args.csv:  # row by row, so that a long study's rows outlive a failure
                    upsert(args.csv, COLUMNS, [{k: str(v) for k, v in row.items()}], ("c", "cells", "position"))
                print(f"c {c:g}, {n}^3 cells (d/h {row['d_over_h']}), position {position}: K {row['K']} against "
                      f"Zick & Homsy's {row['zick_homsy']}: {float(row['error']):+.2%}, {row['steps']} steps, {row['wall_s']} s")
    if args.check and any(abs(float(row["error"])) > args.within / 100 for row in rows):
        sys.exit(f"dense_arrays.py: K off Zick & Homsy's by more than {args.within} %")


if __name__ == "__main__":
    main()
