#!/usr/bin/python3
"""Spheres in a box from a run file (configs/sedimenting-bed.yaml, fluidized-bed.yaml,
dkt-spheres.yaml): the deepest overlap of any two spheres and of a sphere with a wall of
cosim-rigidbody, over all written rows, as a fraction of the radius; with --bed, the bed
height h_b = 2 mean(z) (centres spread evenly over the bed), its solid fraction
alpha = N (4/3) pi R^3 / (A h_b) (A the box's section, or a container's: a round column's
or a basket's along z) averaged over the second half of the run (or from --since), with the
standard error of the mean from ten batch means (each batch far longer than the bed's
fluctuations last, so that the batches are about independent),
and Richardson-Zaki's alpha = 1 - (u0 / u_t)^(1/m) for the scene's inflow u0, also with
their wall correction log10 u_i = log10 u_t - d/D for a column of width D; with --lone RUN,
also with the settling velocity u_i of one bead in the same column on the same grid (a run
of the scene with that bead alone), which holds the walls' and the grid's effect on a lone
bead, so that what remains is the correlation itself, and the exponent n = ln(u0/u_i) /
ln(1 - alpha) the bed's own alpha implies; with --swap, for
the first two spheres (drafting, kissing and tumbling), the closest approach and the times
at which the higher one becomes the lower; with --settle, a settling cloud's mean fall speed
over a time window, how many spheres end on the floor, its fastest sphere and its largest
fluid force.

    bench/beds/beds.py run.h5 [--bed --terminal 0.226 --exponent 2.4 --since 1.0 --lone lone.h5
        --series bed.csv --plot bed.png] [--swap] [--settle 0.2 0.6]
        [--record bench/beds/results.csv fluidized-bed.yaml]

Reference: docs/references.md (Aguilar et al.; Richardson-Zaki, m = 2.4 at Re_p 500);
the wall correction is Richardson & Zaki's (Trans. Inst. Chem. Eng. 32, 1954).
"""

import argparse
import math
import os
import sys
from pathlib import Path

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")  # a run still being written

import h5py
import numpy as np
import yaml

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))  # bench/results_table.py
from results_table import add_option, overlap_text, record, run_figures
from scene_bodies import bodies_of


def settling_velocity(run):
    """The first sphere's mean speed over the lower half of its fall, stopping one diameter
    above where it lands: away from the start, and the staircase's oscillation, one cell
    crossing long, averaged out by taking distance over time."""
    with h5py.File(run, "r") as f:
        body = next(iter(f["bodies"].values()))
        radius = yaml.safe_load(f["run/scene_text"][()].decode())["bodies"][0]["shape"]["radius"]
        t, z = body["time"][:], body["position"][:, 2]
    lowest = z.min()
    rows = np.flatnonzero((z <= (z[0] + lowest) / 2) & (z >= lowest + 2 * radius))
    first, last = rows[0], rows[-1]
    return (z[first] - z[last]) / (t[last] - t[first]), t[first], t[last]


def column_of(scene, lo, hi):
    """The section A the bed fills, its narrowest width D, and a function giving each
    sphere's overlap with the column's side (as a fraction of its radius): a container (a
    cylinder or a box along z) if the scene has one, else the box of the domain."""
    for b in scene["bodies"]:
        shape = b.get("shape", {})
        if not shape.get("container", False):
            continue
        if "orientation" in b:
            raise SystemExit(f"beds.py: the container {b['name']} is turned; only one along z is read")
        centre = np.array(b.get("position", [0, 0, 0]), dtype=float)
        if shape["type"] == "cylinder":
            radius = shape["radius"]
            return (math.pi * radius**2, 2 * radius,
                    lambda row, r: (np.linalg.norm(row[:, :2] - centre[:2], axis=1) + r - radius) / r)
        if shape["type"] == "box":
            half = np.array(shape["half_extents"], dtype=float)
            return (4 * half[0] * half[1], 2 * min(half[0], half[1]),
                    lambda row, r: ((np.abs(row[:, :2] - centre[:2]) - half[:2]).max(axis=1) + r) / r)
        raise SystemExit(f"beds.py: the container {b['name']} is a {shape['type']}; only a cylinder or a box is read")
    return (hi[0] - lo[0]) * (hi[1] - lo[1]), min(hi[0] - lo[0], hi[1] - lo[1]), None


def batch_error(values, batches=10):
    """The standard error of the mean of a correlated series from `batches` batch means (nan
    for a series too short to split)."""
    if len(values) < 2 * batches:
        return math.nan
    means = np.array([chunk.mean() for chunk in np.array_split(values, batches)])
    return means.std(ddof=1) / math.sqrt(batches)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--bed", action="store_true", help="bed height and solid fraction against Richardson-Zaki")
    parser.add_argument("--terminal", type=float, default=0.226, help="u_t [m/s] (Aguilar's beads)")
    parser.add_argument("--exponent", type=float, default=2.4, help="Richardson-Zaki m (2.4 for Re_p >= 500)")
    parser.add_argument("--since", type=float, help="average the bed over t >= this (default: the run's second half)")
    parser.add_argument("--lone", help="a run of one bead settling in the same column: its u_i for Richardson-Zaki")
    parser.add_argument("--series", help="with --bed: write t, h_b and alpha per written row to this CSV")
    parser.add_argument("--plot", help="with --bed: plot h_b and alpha over time into this PNG")
    parser.add_argument("--swap", action="store_true", help="closest approach and order swaps of the first two spheres")
    parser.add_argument("--settle", type=float, nargs=2, metavar=("T0", "T1"),
                        help="a settling cloud: its mean fall speed over [T0, T1], how it ends on the floor, its "
                        "fastest sphere and largest fluid force")
    add_option(parser)
    args = parser.parse_args()

    with h5py.File(args.run, "r") as f:
        scene = yaml.safe_load(f["run/scene_text"][()].decode())
        names = [n.decode() if isinstance(n, bytes) else n for n in f["run"].attrs["body_names"]]
        spheres = [b for b in bodies_of(scene, names) if b["shape"]["type"] == "sphere" and not b.get("fixed", False)]
        t = f[f"bodies/{spheres[0]['name']}/time"][:]
        x = np.stack([f[f"bodies/{b['name']}/position"][:] for b in spheres], axis=1)  # rows, bodies, 3
        v = np.stack([f[f"bodies/{b['name']}/velocity"][:] for b in spheres], axis=1)
        force = np.stack([f[f"bodies/{b['name']}/force"][:] for b in spheres], axis=1)
        cost = run_figures(f)
    r = np.array([b["shape"]["radius"] for b in spheres])
    lo, hi = np.array(scene["domain"]["min"]), np.array(scene["domain"]["max"])
    walls = scene["participants"]["rigidbody"].get("options", {}).get("walls", [])

    area, width, side = column_of(scene, lo, hi)

    pair = np.triu(np.ones((len(r), len(r)), dtype=bool), 1)
    deepest_pair = deepest_wall = 0.0
    deepest_side = -math.inf
    for row in x:
        if side is not None:
            deepest_side = max(deepest_side, float(side(row, r).max()))
        gap = np.linalg.norm(row[:, None, :] - row[None, :, :], axis=2) - (r[:, None] + r[None, :])
        deepest_pair = max(deepest_pair, float(-(gap[pair] / np.minimum.outer(r, r)[pair]).min()))
        for wall in walls:
            axis = "xyz".index(wall[0])
            distance = row[:, axis] - lo[axis] if wall.endswith("min") else hi[axis] - row[:, axis]
            deepest_wall = max(deepest_wall, float(((r - distance) / r).max()))
    print(f"{len(r)} spheres, {len(t)} rows to t = {t[-1]:.3f} s: deepest overlap sphere-sphere "
          f"{deepest_pair:.2%} of the radius, sphere-wall {deepest_wall:.2%}"
          + (f", sphere-container {deepest_side:.2%}" if side is not None else "") + " (negative: never touched)")
    speed = np.linalg.norm(v, axis=2)
    figures = [("the fastest sphere", f"{speed.max():.3f} m/s at t = {t[speed.max(axis=1).argmax()]:g} s", "")]
    overlaps = [("deepest overlap sphere-sphere", overlap_text(deepest_pair), ""),
                ("deepest overlap sphere-wall", overlap_text(deepest_wall), "")]
    if side is not None:
        overlaps.append(("deepest overlap sphere-container", overlap_text(deepest_side), ""))

    if args.swap:
        distance = np.linalg.norm(x[:, 0] - x[:, 1], axis=1) / (r[0] + r[1])
        above = x[:, 1, 2] > x[:, 0, 2]
        swaps = [f"{t[k]:.3f}" for k in range(1, len(t)) if above[k] != above[k - 1]]
        k = distance.argmin()
        print(f"{spheres[0]['name']} and {spheres[1]['name']}: closest centre distance {distance[k]:.3f} d at "
              f"t = {t[k]:.3f} s; order swapped at t = {', '.join(swaps) or 'never'} s")
        figures += [("the first two spheres' closest approach", f"{distance[k]:.3f} d at t = {t[k]:.3f} s", ""),
                    ("the first two spheres' order swaps", f"at t = {', '.join(swaps)} s" if swaps else "never", "")]

    if args.settle:
        window = (t >= args.settle[0] - 1e-9) & (t <= args.settle[1] + 1e-9)
        on_floor = x[-1, :, 2] - lo[2] - r < 0.1 * r  # the centre within a tenth of a radius of resting on it
        rho_f = scene["participants"]["fluid"]["options"]["density"]
        rho_p = np.array([b["material"]["density"] for b in spheres])
        weight = (rho_p - rho_f) * 4 / 3 * math.pi * r**3 * np.linalg.norm(scene["gravity"])  # in the fluid
        print(f"falls at {-v[window, :, 2].mean():.4f} m/s on average over {args.settle[0]}-{args.settle[1]} s; at "
              f"t = {t[-1]:.3f} s {on_floor.sum()} of {len(r)} on the floor, the highest centre at "
              f"z = {x[-1, :, 2].max() - lo[2]:.4f} m, the fastest sphere at {speed[-1].max():.4f} m/s; the fastest "
              f"ever {speed.max():.4f} m/s, the largest fluid force {(np.linalg.norm(force, axis=2) / weight).max():.2f} "
              f"times a sphere's weight in the fluid")
        figures += [
            (f"the mean fall speed over {args.settle[0]:g}-{args.settle[1]:g} s", f"{-v[window, :, 2].mean():.4f} m/s",
             ""),
            ("spheres on the floor", f"{on_floor.sum()} of {len(r)} at t = {t[-1]:g} s, the highest centre at "
             f"z = {x[-1, :, 2].max() - lo[2]:.3f} m, the fastest then at {speed[-1].max():.3f} m/s", ""),
            ("the largest fluid force", f"{(np.linalg.norm(force, axis=2) / weight).max():.2f} times a sphere's weight "
             "in the fluid", "")]

    if args.bed:
        since = t[-1] / 2 if args.since is None else args.since
        half = t >= since
        heights = 2 * (x[:, :, 2].mean(axis=1) - lo[2])
        volume = sum(4 / 3 * math.pi * ri**3 for ri in r)
        alphas = volume / (area * heights)
        height, alpha = heights[half], alphas[half]
        u0 = scene["participants"]["fluid"]["options"]["boundaries"]["z_min"]["velocity"][2]
        rz = 1 - (u0 / args.terminal) ** (1 / args.exponent)
        # Richardson and Zaki's own wall correction, log10 u_i = log10 u_t - d/D, with D the
        # column's diameter or narrower side.
        d_over_d = 2 * max(r) / width
        rz_wall = 1 - (u0 / (args.terminal * 10 ** -d_over_d)) ** (1 / args.exponent)
        print(f"bed over t >= {since:.2f} s: h_b {height.mean() * 1e3:.1f} mm (from {height.min() * 1e3:.1f} to "
              f"{height.max() * 1e3:.1f}), alpha {alpha.mean():.4f} +- {batch_error(alpha):.4f} (standard error, "
              f"10 batch means of {(t[-1] - since) / 10:.2f} s); Richardson-Zaki with u0 = {u0} m/s, "
              f"u_t = {args.terminal} m/s, m = {args.exponent}: alpha {rz:.3f} ({alpha.mean() / rz - 1:+.1%}); "
              f"with the wall correction for d/D = {d_over_d:.3f}: alpha {rz_wall:.3f} "
              f"({alpha.mean() / rz_wall - 1:+.1%})")
        figures += [
            (f"bed height h_b over t >= {since:.2f} s", f"{height.mean() * 1e3:.1f} mm ({height.min() * 1e3:.1f} to "
             f"{height.max() * 1e3:.1f})", ""),
            (f"solid fraction alpha over t >= {since:.2f} s", f"{alpha.mean():.4f}" + (
                f" ± {batch_error(alpha):.4f} (standard error)" if math.isfinite(batch_error(alpha)) else ""),
             f"Richardson–Zaki {rz:.3f} ({alpha.mean() / rz - 1:+.1%}); with their wall correction {rz_wall:.3f} "
             f"({alpha.mean() / rz_wall - 1:+.1%})".replace("-", "−").replace("%", " %"))]
        if args.series:
            np.savetxt(args.series, np.column_stack([t, heights, alphas]), delimiter=",", fmt="%.6g",
                       header="t [s],h_b [m],alpha", comments="")
        if args.plot:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
            fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
            top.plot(t, heights * 1e3)
            top.set_ylabel("bed height h_b [mm]")
            bottom.plot(t, alphas, label="the bed")
            bottom.axhline(rz, color="k", linestyle="--", label=f"Richardson-Zaki, m = {args.exponent}")
            bottom.axvspan(since, t[-1], color="0.9", label="averaged")
            bottom.set_ylabel("solid fraction alpha")
            bottom.set_xlabel("t [s]")
            bottom.legend()
            fig.tight_layout()
            fig.savefig(args.plot, dpi=120)
        if args.lone:
            u_i, start, end = settling_velocity(args.lone)
            rz_lone = 1 - (u0 / u_i) ** (1 / args.exponent)
            print(f"a lone bead settles at u_i = {u_i:.4f} m/s ({start:.2f} to {end:.2f} s in {args.lone}): "
                  f"Richardson-Zaki alpha {rz_lone:.3f} ({alpha.mean() / rz_lone - 1:+.1%}); the bed's alpha "
                  f"implies n = {math.log(u0 / u_i) / math.log(1 - alpha.mean()):.2f} against m = {args.exponent}")
            figures += [
                ("a lone bead's settling velocity u_i in the same column", f"{u_i:.3f} m/s",
                 f"Richardson–Zaki with it: alpha {rz_lone:.3f}"),
                ("the exponent n the bed's alpha implies", f"{math.log(u0 / u_i) / math.log(1 - alpha.mean()):.2f}",
                 f"m = {args.exponent}")]
    record(args.record, args.run, figures + overlaps + cost)


if __name__ == "__main__":
    main()
