#!/usr/bin/env python3
"""cosim-tracker on 1, 2 and 4 MPI ranks: setup time and peak memory per rank, and the time per step.

    bench/tracker_scaling/run.py [--tracker build/release/bin/cosim-tracker] [--cells 64] [--steps 20] [--ranks 1 2 4]

Each rank runs under /usr/bin/time, which reports its peak resident memory (the ranks'
peaks are printed in ascending order: /usr/bin/time does not say which rank is which);
cosim-tracker prints rank 0's setup time (mesh, locator, obstacles, partition, seeding,
the run file created; the scene was read before) and the run's wall time. The time per step is (wall - setup) / steps, the start and end writes
included. On a machine with fewer cores than ranks, the ranks share cores (oversubscribed):
then only setup and memory per rank mean anything.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def scene_text(cells, steps):
    text = (HERE / "scene.yaml").read_text()
    side, end = cells * 1.0e-5, steps * 1.0e-8
    for old, new in [("cells: [64, 64, 64]", f"cells: [{cells}, {cells}, {cells}]"),
                     ("max: [6.4e-4, 6.4e-4, 6.4e-4]", f"max: [{side:g}, {side:g}, {side:g}]"),
                     ("centre: [3.2e-4, 3.2e-4, 3.2e-4], radius: 1.0e-4",
                      f"centre: [{side / 2:g}, {side / 2:g}, {side / 2:g}], radius: {side / 6.4:g}"),
                     ("time: {end: 2.0e-7}", f"time: {{end: {end:g}}}"),
                     ("coupling: {window: 2.0e-7}", f"coupling: {{window: {end:g}}}")]:
        if old not in text:
            sys.exit(f"bench/tracker_scaling/scene.yaml no longer has '{old}': update run.py")
        text = text.replace(old, new)
    return text


def run(tracker, ranks, scene, out):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl="self,vader")
    command = ["mpirun", "-n", str(ranks), "/usr/bin/time", "-f", "peak %M KB", tracker, "--standalone", scene,
               "-o", out]
    done = subprocess.run(command, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed:\n{done.stderr}")
    peaks = [int(k) / 1024 for k in re.findall(r"peak (\d+) KB", done.stderr)]
    wall, setup = map(float, re.search(r"([\d.]+) s \(setup ([\d.]+) s\)", done.stderr).groups())
    particles = int(re.search(r"(\d+) particles seeded", done.stderr).group(1))
    return peaks, wall, setup, particles


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--tracker", default="build/release/bin/cosim-tracker")
    parser.add_argument("--cells", type=int, default=64, help="cells per side")
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--ranks", type=int, nargs="+", default=[1, 2, 4])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        scene = Path(scratch) / "scene.yaml"
        scene.write_text(scene_text(args.cells, args.steps))
        print(f"{args.cells}^3 cells, {args.steps} steps")
        print(f"{'ranks':>5} {'particles':>10} {'setup s':>8} {'s/step':>8} {'peak MB per rank, ascending':>30}")
        for ranks in args.ranks:
            peaks, wall, setup, particles = run(args.tracker, ranks, str(scene), str(Path(scratch) / "run.h5"))
            per_step = (wall - setup) / args.steps
            print(f"{ranks:>5} {particles:>10} {setup:>8.2f} {per_step:>8.3f} {' '.join(f'{p:.0f}' for p in sorted(peaks)):>30}")


if __name__ == "__main__":
    main()
