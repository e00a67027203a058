#!/usr/bin/python3
"""Stokes drag of random arrays of fixed spheres against van der Hoef, Beetstra & Kuipers
(J. Fluid Mech. 528, 2005, 233), whose fit to their lattice-Boltzmann simulations of random
arrays is
    F(phi) = 10 phi / (1 - phi)^2 + (1 - phi)^2 (1 + 1.5 phi^(1/2)),
F = F_d / (3 pi mu d U_s): F_d the drag on a sphere without the mean pressure gradient's
part, U_s the superficial velocity. N spheres are placed at random in the shipped Hasimoto
scene's periodic unit box (configs/hasimoto-sphere.yaml: its drive and viscosity, Stokes
flow) at solid fraction phi, reaching across its faces as they fall (a fixed body wraps
round periodic faces), and run by `cosim-fluid --standalone` for 4000 steps. In the
steady state the drive on the box, rho f L^3, is the total drag of the N spheres, of which
the mean pressure gradient's part is phi; so F_d = (1 - phi) rho f L^3 / N, and U_s is the
mean velocity over the box (spheres included). This is the drag a fluidized bed's beads
feel among their neighbours, where a single sphere or a simple cubic array (dense_arrays.py)
leaves out the near pairs a random bed has.

    bench/fluid_accuracy/random_arrays.py [--fractions 0.1 0.2 0.3] [--spheres N]
        [--d-over-h 6] [--seeds K] [--first-seed S] [--gap CELLS] [--csv FILE] [--check --within PERCENT]

The placement is random sequential addition followed by Monte Carlo sweeps of hard-sphere
moves (a hard-sphere fluid's structure, near pairs included, up to phi about 0.35), each
seed its own array; --gap keeps the spheres' surfaces that many cells apart (0 by default).
The grid has n = round(d/h / d) cells a side, so d/h is the one asked to within a cell in n.
--csv writes the rows (bench/fluid_accuracy/random_arrays.csv, rendered by scripts/results);
--check runs the first fraction over the seeds and exits 1 when the seeds' mean F is off van
der Hoef et al.'s by more than --within percent (the ctest).
"""
import argparse
import math
import os
import statistics
import sys
import tempfile
from pathlib import Path

import numpy as np

import periodic_box

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "bench"))
from results_table import upsert  # noqa: E402

# The immersed boundary's forcing and the projection settle together over steps, not time
# (fluid/ibm/README.md), the faster the smaller dt nu / h^2: at about 2 the mean velocity
# changes by about 1e-4 of itself over the last 500 of 4000 steps (the `change` column).
STEPS = 4000
COLUMNS = ["phi", "spheres", "cells", "d_over_h", "seed", "near", "F", "van_der_hoef", "error", "change", "steps", "wall_s",
           "command"]


def van_der_hoef(phi):
    return 10 * phi / (1 - phi) ** 2 + (1 - phi) ** 2 * (1 + 1.5 * math.sqrt(phi))


def apart(centres, i, x, least):
    """Whether x keeps `least` from every centre but the i-th, nearest images counted."""
    d = centres - x
    d -= np.round(d)
    far = np.einsum("ij,ij->i", d, d) >= least * least
    if 0 <= i < len(centres):
        far[i] = True
    return bool(far.all())


def place(n_spheres, radius, gap, seed, sweeps=200):
    """Centres in the unit box, no two nearer than 2 radius + gap (nearest images): random
    sequential addition, then Monte Carlo sweeps moving each sphere by up to a radius."""
    rng = np.random.default_rng(seed)
    least = 2 * radius + gap
    centres = np.empty((0, 3))
    tries = 0
    while len(centres) < n_spheres:
        x = rng.random(3)
        tries += 1
        if tries > 1000000:
            sys.exit(f"random_arrays.py: cannot place {n_spheres} spheres of radius {radius:.4f} at random")
        if apart(centres, -1, x, least):
            centres = np.vstack([centres, x])
    for _ in range(sweeps):
        for i in range(n_spheres):
            x = (centres[i] + radius * (2 * rng.random(3) - 1)) % 1.0
            if apart(centres, i, x, least):
                centres[i] = x
    return centres


def near_pairs(centres, radius, h):
    """Pairs of spheres whose surfaces come within a cell h of each other (nearest images),
    per sphere: where the immersed boundary's drag is too high at d/h 6 (dense_arrays.py)."""
    d = centres[:, None, :] - centres[None, :, :]
    d -= np.round(d)
    gap = np.sqrt(np.einsum("ijk,ijk->ij", d, d)) - 2 * radius
    upper = np.triu_indices(len(centres), 1)
    return float((gap[upper] < h).sum()) / len(centres)


def array_scene(phi, n_spheres, d_over_h, gap_cells, seed):
    """The Hasimoto scene holding the random array, its time step dt nu / h^2 about 2, to
    4000 steps in windows of 50; its radius, cells and near pairs per sphere."""
    radius = (3 * phi / (4 * math.pi * n_spheres)) ** (1 / 3)  # in a unit box
    cells = round(d_over_h / (2 * radius))
    centres = place(n_spheres, radius, gap_cells / cells, seed)
    scene = periodic_box.hasimoto_scene()
    scene["bodies"] = [{"name": f"s{k}", "shape": {"type": "sphere", "radius": float(radius)}, "fixed": True,
                        "position": [float(v) for v in x]} for k, x in enumerate(centres)]
    fluid = scene["participants"]["fluid"]
    fluid["options"]["grid"]["cells"] = [cells, cells, cells]
    nu = fluid["options"]["viscosity"]["mu"] / fluid["options"]["density"]
    dt = float(f"{2 / (cells * cells * nu):.1e}")
    fluid["dt"] = fluid["options"]["dt_initial"] = dt
    scene["coupling"]["window"] = 50 * dt
    scene["time"]["end"] = STEPS * dt
    return scene, radius, cells, near_pairs(centres, radius, 1 / cells)


def run_case(fluid, phi, n_spheres, d_over_h, gap, seed, folder):
    scene, radius, cells, near = array_scene(phi, n_spheres, d_over_h, gap, seed)
    result = periodic_box.run(fluid, scene, folder, f"phi{phi}_n{n_spheres}_s{seed}")
    drive, mu = periodic_box.drive(scene)
    f = (1 - phi) * drive / n_spheres / (3 * math.pi * mu * 2 * radius * result["u"])
    reference = van_der_hoef(phi)
    return {"phi": phi, "spheres": n_spheres, "cells": cells, "d_over_h": f"{2 * radius * cells:.2f}", "seed": seed,
            "near": f"{near:.2f}", "F": f"{f:.4f}", "van_der_hoef": f"{reference:.4f}", "error": f"{f / reference - 1:.4f}",
            "change": f"{result['change']:.1e}", "steps": result["steps"], "wall_s": f"{result['wall']:.0f}"}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fractions", type=float, nargs="+", default=[0.1, 0.2, 0.3])
    parser.add_argument("--spheres", type=int, default=32, help="spheres in the box")
    parser.add_argument("--d-over-h", type=float, default=6.0, help="cells per diameter")
    parser.add_argument("--seeds", type=int, default=3, help="arrays per fraction")
    parser.add_argument("--first-seed", type=int, default=1, help="the first array's seed")
    parser.add_argument("--gap", type=float, default=0.0, help="least gap between surfaces, in cells")
    parser.add_argument("--csv", help="write the rows into this CSV")
    parser.add_argument("--check", action="store_true", help="compare the first fraction's mean and exit 1 if off")
    parser.add_argument("--within", type=float, default=10.0, help="--check's tolerance, per cent")
    parser.add_argument("--fluid", default=str(ROOT / "build/release/bin/cosim-fluid"))
    args = parser.parse_args()
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    fractions = args.fractions[:1] if args.check else args.fractions
    command = (f"bench/fluid_accuracy/random_arrays.py --fractions {' '.join(f'{p:g}' for p in fractions)} "
               f"--spheres {args.spheres} --d-over-h {args.d_over_h:g} --seeds {args.seeds}")
    command += f" --first-seed {args.first_seed}" if args.first_seed != 1 else ""
    command += f" --gap {args.gap:g}" if args.gap else ""
    means = {}
    with tempfile.TemporaryDirectory() as folder:
        for phi in fractions:
            values = []
            for seed in range(args.first_seed, args.first_seed + args.seeds):
                row = run_case(args.fluid, phi, args.spheres, args.d_over_h, args.gap, seed, folder)
                row["command"] = command
                values.append(float(row["F"]))
                if args.csv:  # row by row, so that a long study's rows outlive a failure
                    upsert(args.csv, COLUMNS, [{k: str(v) for k, v in row.items()}],
                           ("phi", "spheres", "cells", "seed"))
                print(f"phi {phi:g}, {args.spheres} spheres, {row['cells']}^3 cells (d/h {row['d_over_h']}), seed "
                      f"{seed} ({row['near']} pairs a cell apart per sphere): F {row['F']} against van der Hoef et al.'s {row['van_der_hoef']}: "
                      f"{float(row['error']):+.2%}; U changed by {row['change']} over the last 500 steps; "
                      f"{row['steps']} steps, {row['wall_s']} s", flush=True)
            mean = statistics.fmean(values)
            spread = statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else 0.0
            means[phi] = mean
            print(f"phi {phi:g}: mean F {mean:.4f} +- {spread:.4f} (standard error over {len(values)} arrays) "
                  f"against {van_der_hoef(phi):.4f}: {mean / van_der_hoef(phi) - 1:+.2%}")
    if args.check:
        phi = fractions[0]
        if abs(means[phi] / van_der_hoef(phi) - 1) > args.within / 100:
            sys.exit(f"random_arrays.py: the mean F at phi {phi:g} is off van der Hoef et al.'s by more than "
                     f"{args.within} %")


if __name__ == "__main__":
    main()
