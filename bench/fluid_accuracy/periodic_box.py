"""The shipped Hasimoto scene (configs/hasimoto-sphere.yaml) as a periodic box to put fixed
spheres in: a unit box, periodic on every face, the fluid driven through it by a uniform body
force. `run` runs a variant through `cosim-fluid --standalone` and reads the mean velocity
over the box (spheres included) from its last field: in the steady state the drive on the
whole box, rho f L^3, is the drag on all its spheres, and the mean velocity is the
superficial velocity through them. dense_arrays.py, random_arrays.py and
bench/beds/bed_drag.py use it.
"""
import math
import re
import subprocess
import sys
import time
from pathlib import Path

import h5py
import yaml

ROOT = Path(__file__).resolve().parent.parent.parent


def hasimoto_scene():
    return yaml.safe_load((ROOT / "configs/hasimoto-sphere.yaml").read_text())


def drive(scene):
    """rho f L^3, the drive on the whole box, and the viscosity."""
    options = scene["participants"]["fluid"]["options"]
    box = [hi - lo for lo, hi in zip(scene["domain"]["min"], scene["domain"]["max"])]
    return options["density"] * options["body_force"][0] * math.prod(box), options["viscosity"]["mu"]


def run(fluid, scene, folder, name):
    """Runs `scene` (its output into `folder`/`name`.h5); returns the mean velocity over the
    box at each field (`times`, `means`: a 3-vector each), the mean x velocity at the last
    field (`u`) and its relative change since the field before (`change`), the steps and
    the wall time."""
    run_file = Path(folder) / f"{name}.h5"
    scene["output"]["file"] = str(run_file)
    scene_file = Path(folder) / f"{name}.yaml"
    scene_file.write_text(yaml.safe_dump(scene))
    start = time.monotonic()
    done = subprocess.run([fluid, "--standalone", str(scene_file)], capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"{Path(sys.argv[0]).name}: {fluid} --standalone {scene_file} failed:\n{done.stdout}{done.stderr}")
    steps = re.search(r"(\d+) steps", done.stdout + done.stderr)
    with h5py.File(run_file, "r") as f:
        frames = sorted((g for g in f["fields/fluid"].values() if "velocity" in g), key=lambda g: g.attrs["time"])
        times = [float(g.attrs["time"]) for g in frames]
        means = [[float(g["velocity"][..., c].mean()) for c in range(3)] for g in frames]
    u, before = means[-1][0], means[-2][0]
    return {"times": times, "means": means, "u": u, "change": abs(u - before) / abs(u),
            "steps": steps.group(1) if steps else "", "wall": wall}
