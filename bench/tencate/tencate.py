#!/usr/bin/python3
"""Ten Cate's settling sphere from a run file of configs/tencate-e1.yaml or -e4.yaml: prints
u/u_inf and the gap h/d over time, u_max/u_inf next to the experiment's (also of the
velocity's running mean over --smooth seconds, which takes out the ripple of faces
switching between fluid and solid), the landing time and the implicit iterations, and
draws u/u_inf and h/d against t into a PNG.

    bench/tencate/tencate.py runs/tencate-e4.h5 [--case e4] [--png out.png] [--every 0.1] [--smooth 0.1]
        [--record bench/tencate/results.csv]

--record writes the run's row (case, grid, alignment, body method, window) into a results
table that scripts/results renders, replacing the row of a run with the same settings.

Reference values: docs/references.md (ten Cate et al., Phys. Fluids 14, 2002).
"""

import argparse
import math
import os
import sys
from pathlib import Path

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")  # a run still being written

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))  # bench/results_table.py
from results_table import command_line, upsert

# case: (u_inf [m/s], measured u_max/u_inf, FEATFLOW's FEM-FBM, ten Cate's lattice Boltzmann)
CASES = {"e1": (0.038, 0.947, 0.945, 0.894), "e4": (0.128, 0.955, 0.951, 0.947)}
DIAMETER = 0.015
COLUMNS = ["case", "cells", "d_over_h", "axis", "method", "film", "window_ms", "t_end", "u_max", "error", "landed",
           "before_contact", "at_contact", "landing_iterations", "iterations", "max_iterations", "wall_s", "command"]


def settings(scene):
    """The grid, d/h, where the sphere's axis runs (along cell edges or through cell
    centres), the body method and the window of a ten Cate scene."""
    fluid = scene["participants"]["fluid"]["options"]
    cells = fluid["grid"]["cells"]
    lo, hi = scene["domain"]["min"], scene["domain"]["max"]
    h = (hi[0] - lo[0]) / cells[0]
    sphere = next(b for b in scene["bodies"] if b["name"] == "sphere")
    offset = (sphere["position"][0] - lo[0]) / h % 1
    axis = "edges" if min(offset, 1 - offset) < 0.25 else "centres"
    bodies = fluid.get("bodies", {})
    method = bodies.get("method", "ibm")
    if "corrections" in bodies:
        method += f", {bodies['corrections']} no-slip corrections"
    steps = round(scene["coupling"]["window"] / scene["participants"]["fluid"]["dt"])
    if steps > 1:
        method += f", {steps} fluid steps a window"
    film = "lubrication" in scene["participants"]["rigidbody"].get("options", {})
    return {"cells": " x ".join(str(c) for c in cells), "d_over_h": f"{DIAMETER / h:.3g}", "axis": axis,
            "method": method, "film": "yes" if film else "no", "window_ms": f"{scene['coupling']['window'] * 1e3:g}"}


def landing(t, u, gap, iterations, u_inf):
    """The sphere's speed [m/s] one written row before contact (h/d < 0.001) and at it, and
    the iterations of the landing windows (that row, the contact's and the two after it;
    windows when every window is written), or blanks if it never touched."""
    if not (gap < 0.001).any():
        return {"before_contact": "", "at_contact": "", "landing_iterations": ""}
    contact = int(np.argmax(gap < 0.001))
    rows = range(max(contact - 1, 1), min(contact + 3, len(t)))
    return {"before_contact": f"{u[contact - 1] * u_inf:.2g}", "at_contact": f"{u[contact] * u_inf:.2g}",
            "landing_iterations": ", ".join(f"{iterations[k - 1]:.0f}" for k in rows)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--case", choices=sorted(CASES), help="default: from the file name")
    parser.add_argument("--png", help="default: <run>-tencate.png")
    parser.add_argument("--every", type=float, default=0.1, help="seconds between printed rows")
    parser.add_argument("--smooth", type=float, default=0.1, help="running mean's length [s]")
    parser.add_argument("--record", metavar="CSV", help="write the run's row into this results table")
    args = parser.parse_args()
    case = args.case or next((c for c in CASES if c in os.path.basename(args.run)), None)
    if case is None:
        parser.error("cannot tell the case from the file name: give --case")
    u_inf, measured, featflow, lbm = CASES[case]

    with h5py.File(args.run, "r") as f:
        t = f["bodies/sphere/time"][:]
        u = -f["bodies/sphere/velocity"][:, 2] / u_inf
        gap = (f["bodies/sphere/position"][:, 2] - DIAMETER / 2) / DIAMETER
        iterations = f["coupling/iterations"][1:]
        wall = f["coupling/wall_seconds"][:].sum()
        scene = yaml.safe_load(f["run/scene_text"][()].decode())

    print(f"{'t [s]':>7} {'u/u_inf':>8} {'h/d':>7}")
    next_row = 0.0
    for ti, ui, hi in zip(t, u, gap):
        if ti >= next_row - 1e-9:
            print(f"{ti:7.3f} {ui:8.4f} {hi:7.3f}")
            next_row += args.every
    landed = t[np.argmax(gap < 0.01)] if (gap < 0.01).any() else float("nan")
    rows = max(1, int(round(args.smooth / np.median(np.diff(t)))))
    mean = np.convolve(u, np.ones(rows) / rows, mode="valid")
    print(f"ten Cate {case.upper()}: u_max/u_inf {u.max():.4f} at t = {t[u.argmax()]:.3f} s, experiment {measured} "
          f"({u.max() / measured - 1:+.1%}; FEATFLOW {featflow}, lattice Boltzmann {lbm}); of the "
          f"{args.smooth:g} s running mean {mean.max():.4f} ({mean.max() / measured - 1:+.1%}); h/d < 0.01 from "
          f"t = {landed:.3f} s; implicit iterations per window mean {iterations.mean():.2f}, max {iterations.max():.0f}; "
          f"{wall:.0f} s of windows")

    if args.record:
        row = dict(settings(scene), **landing(t, u, gap, iterations, u_inf), case=case.upper(), t_end=f"{t[-1]:.3f}", u_max=f"{u.max():.4f}",
                   error=f"{u.max() / measured - 1:.5f}",
                   landed="" if math.isnan(landed) else f"{landed:.3f}", iterations=f"{iterations.mean():.2f}",
                   max_iterations=f"{iterations.max():.0f}", wall_s=f"{wall:.0f}",
                   command=command_line(args.run, {"--record": 1, "--png": 1}))
        upsert(args.record, COLUMNS, [row], ("case", "cells", "axis", "method", "film", "window_ms", "t_end"))
        print(f"{row['case']} on {row['cells']} ({row['axis']}, {row['method']}) in {args.record}")

    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    ax[0].plot(t, u, label="cosim")
    ax[0].axhline(measured, color="k", ls="--", lw=0.8, label=f"experiment u_max/u_inf = {measured}")
    ax[0].set(xlabel="t [s]", ylabel="u / u_inf", title=f"ten Cate {case.upper()}: sphere velocity")
    ax[0].legend()
    ax[1].plot(t, gap)
    ax[1].set(xlabel="t [s]", ylabel="h / d", title="gap to the bottom")
    fig.tight_layout()
    png = args.png or os.path.splitext(args.run)[0] + "-tencate.png"
    fig.savefig(png, dpi=110)
    print(png)


if __name__ == "__main__":
    main()
