#!/usr/bin/python3
"""Ten Cate's settling sphere from a run file of configs/tencate-e1.yaml or -e4.yaml: prints
u/u_inf and the gap h/d over time, u_max/u_inf next to the experiment's (also of the
velocity's running mean over --smooth seconds, which takes out the ripple of faces
switching between fluid and solid), the landing time and the implicit iterations, and
draws u/u_inf and h/d against t into a PNG.

    bench/tencate/tencate.py runs/tencate-e4.h5 [--case e4] [--png out.png] [--every 0.1] [--smooth 0.1]

Reference values: docs/references.md (ten Cate et al., Phys. Fluids 14, 2002).
"""

import argparse
import os

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")  # a run still being written

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

# case: (u_inf [m/s], measured u_max/u_inf, FEATFLOW's FEM-FBM, ten Cate's lattice Boltzmann)
CASES = {"e1": (0.038, 0.947, 0.945, 0.894), "e4": (0.128, 0.955, 0.951, 0.947)}
DIAMETER = 0.015


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--case", choices=sorted(CASES), help="default: from the file name")
    parser.add_argument("--png", help="default: <run>-tencate.png")
    parser.add_argument("--every", type=float, default=0.1, help="seconds between printed rows")
    parser.add_argument("--smooth", type=float, default=0.1, help="running mean's length [s]")
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
