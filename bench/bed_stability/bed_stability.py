#!/usr/bin/python3
"""Explicit against implicit coupling of a bed of immersed spheres, density ratio by density
ratio: 32 spheres (radius 12.5 mm, a 4 x 4 x 2 lattice with 1 mm gaps, each given a random
velocity of up to 1 cm/s) in the middle of a closed 0.15 m box of liquid (rho_f 1 kg/m^3,
mu 1e-3 Pa s: the sedimenting bed's), d/h 6 with the immersed boundary, windows of 20 ms,
for 1 s, in which the spheres fall onto the floor (rho_p > rho_f) or rise to the lid. Each
ratio runs serial-explicit and serial-implicit (IQN-ILS, tolerance 1e-4, at most 30
iterations); neither has a virtual mass: cosim-fluid sends its response tensors.

For each ratio: stable (the explicit run's fastest sphere within twice the implicit one's,
and every value finite), the explicit run's error against the implicit one (the velocity
difference over the implicit run's fastest speed: its root mean square over spheres and
written rows, and its largest, which a landing one window apart sets), the
implicit iterations per window (mean and most), the deepest overlap in either run (of the
radius) and both wall times. Writes the Markdown table to stdout (README.md holds it).
--lattice and --gap spread the bed or shrink it to one sphere (what the neighbours cost
the implicit iterations).

    bench/bed_stability/bed_stability.py [--bin build/release/bin] [--ratios 2 1.2 ...] [--window 0.02]
                                         [--lattice 4 4 2] [--gap 1] [--out runs/bed_stability]
"""

import argparse
import os
import random
import subprocess
import sys
import time

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")

import h5py
import numpy as np

RADIUS = 0.0125
CELLS = 36  # 0.15 m / 36 = 4.17 mm: d/h 6


def scene(name, ratio, scheme, end, window, lattice, gap):
    rng = random.Random(7)
    bodies = []
    pitch = 2 * RADIUS + gap
    nx, ny, nz = lattice
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                # centred on the box across, the lowest layer 62 mm up
                x = 0.0765 + pitch * (i - (nx - 1) / 2) + 1e-4 * j
                y = 0.0765 + pitch * (j - (ny - 1) / 2) - 1e-4 * i
                z = 0.062 + pitch * k
                v = [rng.uniform(-0.01, 0.01) for _ in range(3)]
                bodies.append(f"  - {{name: s{len(bodies):02d}, shape: {{type: sphere, radius: {RADIUS}}}, "
                              f"material: {{density: {ratio}, friction: 0.3}}, position: [{x:.5f}, {y:.5f}, {z:.5f}], "
                              f"velocity: [{v[0]:.6f}, {v[1]:.6f}, {v[2]:.6f}]}}")
    implicit = ", acceleration: iqn-ils, relaxation: 0.5, max_iterations: 30, tolerance: 1.0e-4" if scheme == "serial-implicit" else ""
    return f"""time: {{end: {end}}}
coupling: {{window: {window}, scheme: {scheme}{implicit}}}
output: {{file: {name}.h5, checkpoint_every: 1000, fields_every: 0}}
gravity: [0, 0, -9.81]
domain: {{min: [0, 0, 0], max: [0.15, 0.15, 0.15]}}
effects: [gravity, buoyancy, hydrodynamics, contact, friction]
bodies:
{chr(10).join(bodies)}
participants:
  rigidbody: {{dt: 1.0e-3, options: {{fluid_density: 1.0, walls: [x_min, x_max, y_min, y_max, z_min, z_max]}}}}
  fluid:
    dt: {window}
    options: {{density: 1.0, viscosity: {{model: newtonian, mu: 1.0e-3}}, grid: {{cells: [{CELLS}, {CELLS}, {CELLS}]}}, dt_initial: {window}, bodies: {{method: ibm}}}}
"""


def run(cosim, out, name, text):
    path = os.path.join(out, name + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    start = time.monotonic()
    done = subprocess.run([cosim, "run", path, "-q"], cwd=out, capture_output=True, text=True)
    wall = time.monotonic() - start
    return done.returncode, wall, os.path.join(out, name + ".h5"), done.stderr


def read(path):
    with h5py.File(path, "r") as f:
        names = sorted(f["bodies"].keys())
        v = np.array([f["bodies"][n]["velocity"][:] for n in names])
        p = np.array([f["bodies"][n]["position"][:] for n in names])
        it = f["coupling/iterations"][1:]
    rows = min(v.shape[1], p.shape[1])
    return v[:, :rows], p[:, :rows], it


def overlap(p):
    worst = 0.0
    for k in range(p.shape[1]):
        x = p[:, k, :]
        d = np.linalg.norm(x[:, None, :] - x[None, :, :], axis=2) + np.eye(len(x))
        worst = max(worst, (2 * RADIUS - d.min()) / RADIUS, (RADIUS - x[:, 2].min()) / RADIUS,
                    (x[:, 2].max() + RADIUS - 0.15) / RADIUS)
    return max(worst, 0.0)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default=os.path.join(here, "..", "..", "build", "release", "bin"))
    parser.add_argument("--ratios", type=float, nargs="+", default=[2, 1.2, 1.0, 0.7, 0.5, 0.3, 0.2, 0.1])
    parser.add_argument("--end", type=float, default=1.0)
    parser.add_argument("--window", type=float, default=0.02, help="coupling window and fluid step [s]")
    parser.add_argument("--lattice", type=int, nargs=3, default=[4, 4, 2], metavar=("NX", "NY", "NZ"),
                        help="spheres along x, y, z")
    parser.add_argument("--gap", type=float, default=1.0, help="gap between neighbouring spheres [mm]")
    parser.add_argument("--out", default=os.path.join("runs", "bed_stability"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    cosim = os.path.abspath(os.path.join(args.bin, "cosim"))
    print("| rho_p/rho_f | stable | explicit error (rms, largest) | implicit iterations (mean, most) | deepest overlap (explicit, implicit) | wall time explicit, implicit |")
    print("|---|---|---|---|---|---|")
    for ratio in args.ratios:
        tag = f"{ratio:g}".replace(".", "_")
        runs = {}
        for scheme in ("serial-explicit", "serial-implicit"):
            name = f"bed_{tag}_w{args.window:g}_{'x'.join(map(str, args.lattice))}_g{args.gap:g}_{scheme.split('-')[1]}"
            text = scene(name, ratio, scheme, args.end, args.window, args.lattice, 1e-3 * args.gap)
            runs[scheme] = run(cosim, args.out, name, text)
        (ce, we, fe, ee), (ci, wi, fi, ei) = runs["serial-explicit"], runs["serial-implicit"]
        if ci != 0:
            print(f"| {ratio:g} | implicit run failed | | | | {we:.0f} s, {wi:.0f} s |")
            print(ei, file=sys.stderr)
            continue
        vi, pi, it = read(fi)
        fastest = np.linalg.norm(vi, axis=2).max()
        if ce != 0:
            print(f"| {ratio:g} | **no** (the run failed) | | {it.mean():.2f}, {it.max()} | -, {100 * overlap(pi):.2f} % | {we:.0f} s, {wi:.0f} s |")
            print(ee, file=sys.stderr)
            continue
        ve, pe, _ = read(fe)
        rows = min(ve.shape[1], vi.shape[1])
        stable = np.isfinite(ve).all() and np.linalg.norm(ve, axis=2).max() <= 2 * fastest
        difference = np.linalg.norm(ve[:, :rows] - vi[:, :rows], axis=2) / fastest
        rms, largest = np.sqrt((difference**2).mean()), difference.max()
        print(f"| {ratio:g} | {'yes' if stable else '**no**'} | {100 * rms:.1f} %, {100 * largest:.1f} % | {it.mean():.2f}, {it.max()} | "
              f"{100 * overlap(pe):.2f} %, {100 * overlap(pi):.2f} % | {we:.0f} s, {wi:.0f} s |", flush=True)


if __name__ == "__main__":
    main()
