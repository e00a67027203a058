#!/usr/bin/python3
# Debian's interpreter on purpose: a `python3` earlier on PATH may lack h5py.
"""What a coupled window costs as a suspension grows: N spheres at solid fraction 0.1 in a
closed cube whose side grows with N (cells in proportion to bodies), at d/h 6, the immersed
boundary, cosim-fluid on 1 or more ranks and cosim-rigidbody with contacts, serial-explicit
with the fluid's response tensors (as configs/sedimenting-bed.yaml). For each count and rank
count it runs `cosim run` for a few windows and reports, over the windows after the first:
the wall time per window and per body, the fluid's and the rigid bodies' shares and the
rest (the coupler and the wire), the fluid's stages per window from PETSc's event log
(`-log_view`), the immersed boundary's share of the fluid's step (body forcing and no-slip
stages), and the peak memory of each program (per fluid rank).

    bench/particulate/particulate.py [--counts 10 100 1000] [--ranks 1 2] [--windows 4]
        [--out DIR] [--bin DIR] [--table bench/particulate/results]

Writes DIR/<count>_<ranks>/ (scene, run file, logs) and, with --table, PREFIX.csv, from
which scripts/results renders the table of PREFIX.md that the README links to.
The programs come from build/release/bin (or --bin).
"""

import argparse
import csv
import math
import os
import re
import subprocess
import sys
import threading
import time

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DIAMETER = 0.006  # m: glass beads of 6 mm
CELLS_PER_DIAMETER = 6
FRACTION = 0.1
WINDOW = 2.0e-3  # s: one fluid step per window, nu dt / h^2 = 0.02
STAGES = ["FluidMomentumRHS", "FluidBodyForcing", "FluidViscousSolve", "FluidProjection", "FluidNoSlip"]


def scene_text(count, ranks, windows):
    """The suspension: a cube of n^3 cells holding `count` spheres at FRACTION."""
    h = DIAMETER / CELLS_PER_DIAMETER
    volume = count * math.pi / 6 * DIAMETER**3 / FRACTION
    n = math.ceil(volume ** (1 / 3) / h)
    side = n * h
    return n, f"""# bench/particulate: {count} spheres at solid fraction {FRACTION}, {n}^3 cells (d/h {CELLS_PER_DIAMETER})
time:
  end: {windows * WINDOW:.6g}
coupling:
  window: {WINDOW}
  scheme: serial-explicit
  timeout: 600  # the first window of ten thousand spheres takes over a minute
output:
  file: run.h5
  every: 1
  checkpoint_every: 1000
  fields_every: 0
gravity: [0, 0, -9.81]
domain:
  min: [0, 0, 0]
  max: [{side:.9g}, {side:.9g}, {side:.9g}]
effects: [gravity, buoyancy, hydrodynamics, contact]
bodies:
  - generate: random
    name: "s{{}}"
    shape: {{type: sphere, radius: {DIAMETER / 2}}}
    material: {{density: 2500}}
    region: {{min: [0, 0, 0], max: [{side:.9g}, {side:.9g}, {side:.9g}]}}
    count: {count}
    seed: 7
participants:
  rigidbody:
    dt: 2.0e-4
    options: {{fluid_density: 1000, lubrication: auto, walls: [x_min, x_max, y_min, y_max, z_min, z_max]}}
  fluid:
    dt: {WINDOW}
    ranks: {ranks}
    options:
      density: 1000
      viscosity: {{model: newtonian, mu: 1.0e-2}}
      grid: {{cells: [{n}, {n}, {n}]}}
      dt_initial: {WINDOW}
      petsc: "-log_view :fluid_log.txt"
"""


class PeakMemory:
    """The largest resident set (VmHWM) of each program among the descendants of process
    `root` while it lasts, read from /proc every 0.2 s: per program, the largest of its
    processes (its ranks)."""

    def __init__(self, root, names):
        self.root, self.peak, self.stop = root, {n: 0 for n in names}, threading.Event()
        self.thread = threading.Thread(target=self.poll, daemon=True)

    def poll(self):
        while not self.stop.wait(0.2):
            status = {}
            for pid in filter(str.isdigit, os.listdir("/proc")):
                try:
                    with open(f"/proc/{pid}/status") as f:
                        status[int(pid)] = f.read()
                except OSError:
                    continue
            parent = {p: int(re.search(r"^PPid:\s+(\d+)", s, re.M).group(1)) for p, s in status.items()}
            for pid, text in status.items():
                ancestor = pid
                while ancestor not in (self.root, 0, 1) and ancestor in parent:
                    ancestor = parent[ancestor]
                name = re.search(r"^Name:\s+(\S+)", text, re.M)
                hwm = re.search(r"^VmHWM:\s+(\d+) kB", text, re.M)
                if ancestor == self.root and name and hwm and name.group(1) in self.peak:
                    self.peak[name.group(1)] = max(self.peak[name.group(1)], int(hwm.group(1)) / 1024)

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join()


def fluid_events(log):
    """Each fluid event's count and time (the largest over the ranks) from PETSc's -log_view
    table: its main stage, without the response tensors' measurement (stage FluidResponse)."""
    out = {}
    with open(log) as f:
        for line in f:
            fields = line.split()
            if line.startswith("--- Event Stage") and "Main Stage" not in line:
                break
            if fields and fields[0].startswith("Fluid") and len(fields) > 3:
                out[fields[0]] = (int(fields[1]), float(fields[3]))
    return out


def run_case(count, ranks, windows, out, bin_dir):
    folder = os.path.join(out, f"{count}_{ranks}")
    os.makedirs(folder, exist_ok=True)
    n, text = scene_text(count, ranks, windows)
    with open(os.path.join(folder, "scene.yaml"), "w") as f:
        f.write(text)
    for stale in ("run.h5", "fluid_log.txt"):
        if os.path.exists(os.path.join(folder, stale)):
            os.remove(os.path.join(folder, stale))
    start = time.monotonic()
    with open(os.path.join(folder, "cosim.log"), "w") as log:
        run = subprocess.Popen([os.path.join(bin_dir, "cosim"), "run", "scene.yaml", "-q"], cwd=folder, stdout=log,
                               stderr=subprocess.STDOUT)
        with PeakMemory(run.pid, ["cosim", "cosim-fluid", "cosim-rigidbody"]) as memory:
            run.wait()
    total = time.monotonic() - start
    if run.returncode != 0:
        sys.exit(f"particulate: {count} spheres on {ranks} ranks failed (see {folder}/cosim.log)")
    with h5py.File(os.path.join(folder, "run.h5"), "r") as f:
        c = f["coupling"]
        every = c["wall_seconds"][:]
        wall = every[1:]
        fluid = c["participants/fluid/wall_seconds"][1:]
        rigid = c["participants/rigidbody/wall_seconds"][1:]
        bodies = len(f["bodies"])
    events = fluid_events(os.path.join(folder, "fluid_log.txt"))
    if "FluidBodyForcing" not in events:
        sys.exit(f"particulate: {folder}/fluid_log.txt holds no fluid events")
    stages = {s: events.get(s, (0, 0.0))[1] for s in STAGES}
    step = sum(stages.values()) / windows  # one fluid step per window
    forcing = (stages.get("FluidBodyForcing", 0) + stages.get("FluidNoSlip", 0)) / windows
    return {
        "bodies": bodies,
        "ranks": ranks,
        "cells": n**3,
        "window_s": float(np.mean(wall)),
        "per_body_ms": 1e3 * float(np.mean(wall)) / bodies,
        "fluid_s": float(np.mean(fluid)),
        "rigid_s": float(np.mean(rigid)),
        "rest_s": float(np.mean(wall - fluid - rigid)),
        **{f"{s}_ms": 1e3 * stages.get(s, 0) / windows for s in STAGES},
        "ibm_share": forcing / step if step > 0 else float("nan"),
        "iterations_per_step": events.get("FluidForcingIteration", (0, 0.0))[0] / windows,
        "start_s": total - float(np.sum(every)),  # the programs' start and set-up
        "fluid_MB": memory.peak["cosim-fluid"],
        "rigid_MB": memory.peak["cosim-rigidbody"],
        "cosim_MB": memory.peak["cosim"],
    }


def summary(row):
    """One line per case as it finishes."""
    return (f"{row['bodies']} bodies, {row['ranks']} ranks, {row['cells']:,} cells: window {row['window_s']:.3f} s, "
            f"per body {row['per_body_ms']:.2f} ms, IB share {100 * row['ibm_share']:.0f} %, "
            f"peak fluid {row['fluid_MB']:.0f} MB")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--counts", type=int, nargs="+", default=[10, 100, 1000])
    p.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    p.add_argument("--windows", type=int, default=4)
    p.add_argument("--out", default="runs/particulate")
    p.add_argument("--bin", default=os.path.join("build", os.environ.get("COSIM_PRESET", "release"), "bin"))
    p.add_argument("--table", help="write PREFIX.csv (scripts/results renders PREFIX.md from it)")
    a = p.parse_args()
    bin_dir = os.path.abspath(a.bin)
    rows = []
    for count in a.counts:
        for ranks in a.ranks:
            rows.append(run_case(count, ranks, a.windows, os.path.abspath(a.out), bin_dir))
            print(summary(rows[-1]), flush=True)
    if a.table:
        with open(a.table + ".csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "results")], check=True)

if __name__ == "__main__":
    main()
