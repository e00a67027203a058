#!/usr/bin/python3
"""What simulating only the scene's effects saves: the same bodies run by `cosim run` with
the scene's effects, then with those of a fluid (hydrodynamics, buoyancy) or a gas
(rarefied_gas) removed, which leaves the programs they need unstarted. Prints one row per
run: effects, programs started, windows, wall time, seconds per window.

    bench/effects_cost/effects_cost.py [scene.yaml] [--windows N] [--build build/release]

Default scene: configs/dkt-spheres.yaml (two spheres settling in a liquid).
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
REMOVED = {"hydrodynamics", "buoyancy", "rarefied_gas", "tracers"}


def run(cosim, scene, directory, name):
    path = os.path.join(directory, name + ".yaml")
    with open(path, "w") as f:
        yaml.safe_dump(scene, f, sort_keys=False)
    start = time.perf_counter()
    done = subprocess.run([cosim, "run", path, "-q", "-o", os.path.join(directory, name + ".h5")],
                          capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"effects_cost: {name} failed:\n{done.stdout}{done.stderr}")
    started = re.findall(r"started (\S+) \(pid", done.stdout + done.stderr)
    return started, wall


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scene", nargs="?", default=os.path.join(ROOT, "configs", "dkt-spheres.yaml"))
    parser.add_argument("--windows", type=int, default=20, help="windows to run (default 20)")
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "release"))
    args = parser.parse_args()

    with open(args.scene) as f:
        full = yaml.safe_load(f)
    full["time"]["end"] = args.windows * full["coupling"]["window"]
    full.setdefault("output", {})["fields_every"] = 0
    full["output"]["checkpoint_every"] = args.windows
    bare = dict(full, effects=[e for e in full["effects"] if e not in REMOVED])
    cosim = os.path.join(args.build, "bin", "cosim")

    print(f"{os.path.relpath(args.scene, ROOT)}, {len(full['bodies'])} bodies, {args.windows} windows")
    print(f"{'effects':<50} {'programs':<22} {'wall s':>8} {'s/window':>9}")
    with tempfile.TemporaryDirectory() as directory:
        for name, scene in (("with", full), ("without", bare)):
            started, wall = run(cosim, scene, directory, name)
            print(f"{', '.join(scene['effects']):<50} {' + '.join(started):<22} {wall:8.2f} {wall / args.windows:9.4f}")


if __name__ == "__main__":
    main()
