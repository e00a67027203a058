#!/usr/bin/env python3
"""cosim-tracker on 1, 2 and 4 MPI ranks: setup time and peak memory per rank, and the time per step.

    bench/tracker_scaling/run.py [--tracker build/release/bin/cosim-tracker] [--cells 64] [--steps 20] [--ranks 1 2 4]
                                 [--per-cell 10]

cosim-tracker prints each rank's setup time (mesh or its part, locator, obstacles,
partition, seeding, on rank 0 the run file created; the scene was read before) and peak
resident memory (getrusage), rank 0 first, and the run's wall time. The time per step is
(wall - setup of rank 0) / steps, the start and end writes included. On a machine with
fewer cores than ranks, the ranks share cores (oversubscribed): then only setup and memory
per rank mean anything.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def scene_text(cells, steps, per_cell):
    text = (HERE / "scene.yaml").read_text()
    side, end = cells * 1.0e-5, steps * 1.0e-8
    for old, new in [("cells: [64, 64, 64]", f"cells: [{cells}, {cells}, {cells}]"),
                     ("max: [6.4e-4, 6.4e-4, 6.4e-4]", f"max: [{side:g}, {side:g}, {side:g}]"),
                     ("centre: [3.2e-4, 3.2e-4, 3.2e-4], radius: 1.0e-4",
                      f"centre: [{side / 2:g}, {side / 2:g}, {side / 2:g}], radius: {side / 6.4:g}"),
                     ("time: {end: 2.0e-7}", f"time: {{end: {end:g}}}"),
                     ("coupling: {window: 2.0e-7}", f"coupling: {{window: {end:g}}}"),
                     ("per_cell: 10", f"per_cell: {per_cell}")]:
        if old not in text:
            sys.exit(f"bench/tracker_scaling/scene.yaml no longer has '{old}': update run.py")
        text = text.replace(old, new)
    return text


def run(tracker, ranks, scene, out):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl="self,vader")
    command = ["mpirun", "-n", str(ranks), tracker, "--standalone", scene, "-o", out]
    done = subprocess.run(command, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stderr}")
    by_rank = re.search(r"by rank: setup \[s\]([\d. ]+); peak memory \[MB\]([\d. ]+)", done.stderr)
    setups, peaks = ([float(x) for x in group.split()] for group in by_rank.groups())
    wall, setup = map(float, re.search(r"([\d.]+) s \(setup ([\d.]+) s\)", done.stderr).groups())
    particles = int(re.search(r"(\d+) particles seeded", done.stderr).group(1))
    return peaks, setups, wall, setup, particles


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tracker", default="build/release/bin/cosim-tracker")
    parser.add_argument("--cells", type=int, default=64, help="cells per side")
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    parser.add_argument("--per-cell", type=int, default=10, help="simulators per cell at the start")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        scene = Path(scratch) / "scene.yaml"
        scene.write_text(scene_text(args.cells, args.steps, args.per_cell))
        print(f"{args.cells}^3 cells, {args.per_cell} simulators per cell, {args.steps} steps")
        print(f"{'ranks':>5} {'particles':>10} {'s/step':>8}  {'setup s by rank (0 first)':<28} peak MB by rank")
        for ranks in args.ranks:
            peaks, setups, wall, setup, particles = run(args.tracker, ranks, str(scene), str(Path(scratch) / "run.h5"))
            per_step = (wall - setup) / args.steps
            print(f"{ranks:>5} {particles:>10} {per_step:>8.3f}  {' '.join(f'{t:.2f}' for t in setups):<28} "
                  f"{' '.join(f'{p:.0f}' for p in peaks)}")


if __name__ == "__main__":
    main()
