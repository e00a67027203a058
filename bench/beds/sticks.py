#!/usr/bin/python3
"""Capsules settling in a box from a run file (configs/sedimenting-sticks.yaml): the
deepest overlap over the written rows (all, or those from a time on), as a fraction of the
capsules' radius, of two capsules, of a capsule with a fixed sphere and of a capsule with a
wall of cosim-rigidbody; the cloud's mean fall speed over a time window; where the capsules
end; the capsules' jitter, the sign of an unstable coupling (the root mean square over the
capsules of each one's velocity less its running mean over five rows: a coupling that turns
a velocity over every few windows shows there first when the rows are windows,
`output.every: 1`); and what the run took (its wall time and seconds per window).

    bench/beds/sticks.py run.h5 [--settle 1 3] [--overlap-from T] [--plot cloud.png]
        [--record bench/beds/results.csv sedimenting-sticks.yaml]

A capsule is the segment of `height` along its body z axis, centred on its position, grown
by `radius`; two overlap by 2 radius - the distance of their segments.
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
from segments import segment_distances


def axis_of(q):
    """The body z axis of unit quaternions (w, x, y, z), one per row."""
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)], axis=-1)


def deepest_pair(a, b, radius, reach):
    """The deepest overlap of two capsules (segments a[i] to b[i], all of one radius) as a
    fraction of the radius; only pairs whose centres are closer than `reach` can touch."""
    centre = 0.5 * (a + b)
    gap = np.linalg.norm(centre[:, None, :] - centre[None, :, :], axis=2)
    i, j = np.nonzero(np.triu(gap < reach, 1))
    if len(i) == 0:
        return -math.inf
    return float(((2 * radius - segment_distances(a[i], b[i], a[j], b[j])) / radius).max())


def jitter(v):
    """Per row of velocities (rows, capsules, 3): the root mean square over the capsules of
    the velocity less its centred running mean over five rows (NaN on the first and last two)."""
    out = np.full(len(v), math.nan)
    if len(v) >= 5:
        mean = sum(v[k:len(v) - 4 + k] for k in range(5)) / 5
        out[2:-2] = np.sqrt((np.linalg.norm(v[2:-2] - mean, axis=2) ** 2).mean(axis=1))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--settle", type=float, nargs=2, metavar=("T0", "T1"),
                        help="the cloud's mean fall speed over [T0, T1]")
    parser.add_argument("--overlap-from", type=float, default=-math.inf, metavar="T",
                        help="the deepest overlaps over the rows from time T on (a run resumed from a checkpoint)")
    parser.add_argument("--plot", help="the cloud's mean height and fall speed over time into this PNG")
    add_option(parser)
    args = parser.parse_args()

    with h5py.File(args.run, "r") as f:
        scene = yaml.safe_load(f["run/scene_text"][()].decode())
        names = [n.decode() if isinstance(n, bytes) else n for n in f["run"].attrs["body_names"]]
        bodies = bodies_of(scene, names)
        sticks = [b for b in bodies if b["shape"]["type"] == "capsule" and not b.get("fixed", False)]
        spheres = [b for b in bodies if b["shape"]["type"] == "sphere" and b.get("fixed", False)]
        t = f[f"bodies/{sticks[0]['name']}/time"][:]
        x = np.stack([f[f"bodies/{b['name']}/position"][:] for b in sticks], axis=1)  # rows, sticks, 3
        q = np.stack([f[f"bodies/{b['name']}/orientation"][:] for b in sticks], axis=1)
        v = np.stack([f[f"bodies/{b['name']}/velocity"][:] for b in sticks], axis=1)
        wall_seconds = f["coupling/wall_seconds"][:]
        status = f["run"].attrs.get("status", b"unknown")
        status = status.decode() if isinstance(status, bytes) else str(status)
        run_seconds = float(f["run"].attrs.get("wall_seconds", math.nan))
        cost = run_figures(f)
    shapes = {(b["shape"]["radius"], b["shape"]["height"]) for b in sticks}
    if len(shapes) != 1:
        raise SystemExit("sticks.py: the capsules differ in size; one size is read")
    radius, height = shapes.pop()
    lo, hi = np.array(scene["domain"]["min"]), np.array(scene["domain"]["max"])
    walls = scene["participants"]["rigidbody"].get("options", {}).get("walls", [])

    half = 0.5 * height * axis_of(q)
    ends_a, ends_b = x - half, x + half
    stick_stick = stick_sphere = stick_wall = -math.inf
    rows = [row for row in range(len(t)) if t[row] >= args.overlap_from - 1e-9]
    if not rows:
        raise SystemExit(f"sticks.py: --overlap-from {args.overlap_from}: the run's rows end at t = {t[-1]:g} s")
    for row in rows:
        a, b = ends_a[row], ends_b[row]
        stick_stick = max(stick_stick, deepest_pair(a, b, radius, height + 2 * radius))
        for s in spheres:
            centre = np.array(s["position"], dtype=float)
            d = segment_distances(a, b, np.broadcast_to(centre, a.shape), np.broadcast_to(centre, a.shape))
            stick_sphere = max(stick_sphere, float(((radius + s["shape"]["radius"] - d) / radius).max()))
        for wall in walls:
            k = "xyz".index(wall[0])
            distance = (np.minimum(a[:, k], b[:, k]) - lo[k] if wall.endswith("min")
                        else hi[k] - np.maximum(a[:, k], b[:, k]))
            stick_wall = max(stick_wall, float(((radius - distance) / radius).max()))
    print(f"{len(sticks)} capsules (radius {radius}, {height + 2 * radius:g} long), {len(t)} rows to "
          f"t = {t[-1]:.3f} s ({status}); over {len(rows)} rows from t = {t[rows[0]]:.3f} s the "
          f"deepest overlap capsule-capsule {stick_stick:.2%} of the radius, "
          f"capsule-sphere {stick_sphere:.2%}, capsule-wall {stick_wall:.2%} (negative: never touched)")

    since = f" over the rows from t = {t[rows[0]]:g} s" if rows[0] else ""
    overlaps = [(f"deepest overlap capsule-{other}{since}", overlap_text(depth), "")
                for other, depth in (("capsule", stick_stick), ("sphere", stick_sphere), ("wall", stick_wall))]

    on_floor = np.minimum(ends_a[-1, :, 2], ends_b[-1, :, 2]) - lo[2] < 1.1 * radius
    speed = np.linalg.norm(v, axis=2)
    print(f"at t = {t[-1]:.3f} s {on_floor.sum()} of {len(sticks)} on the floor, the cloud's mean height "
          f"{x[-1, :, 2].mean() - lo[2]:.4f} m (from {x[0, :, 2].mean() - lo[2]:.4f}), the fastest capsule at "
          f"{speed[-1].max():.4f} m/s; the fastest ever {speed.max():.4f} m/s")
    figures = [
        ("the cloud's mean height", f"{x[-1, :, 2].mean() - lo[2]:.3f} m at t = {t[-1]:g} s (from "
         f"{x[0, :, 2].mean() - lo[2]:.3f} m)", ""),
        ("capsules on the floor", f"{on_floor.sum()} of {len(sticks)} at t = {t[-1]:g} s, the fastest then at "
         f"{speed[-1].max():.3f} m/s", ""),
        ("the fastest capsule", f"{speed.max():.3f} m/s at t = {t[speed.max(axis=1).argmax()]:g} s", "")]
    shaking = jitter(v)
    marks = [k for k in range(len(t)) if np.isfinite(shaking[k]) and abs(t[k] - round(t[k])) < 1e-9]
    print("jitter [m/s] at whole seconds: " + ", ".join(f"{t[k]:g} s {shaking[k]:.4f}" for k in marks))
    if marks:
        worst = max(marks, key=lambda k: shaking[k])
        figures.append(("the largest jitter at a whole second", f"{shaking[worst]:.4f} m/s at t = {t[worst]:g} s", ""))
    if args.settle:
        window = (t >= args.settle[0] - 1e-9) & (t <= args.settle[1] + 1e-9)
        fall = -v[window, :, 2].mean()
        print(f"falls at {fall:.4f} m/s on average over {args.settle[0]}-{args.settle[1]} s")
        figures.insert(0, (f"the cloud's mean fall speed over {args.settle[0]:g}-{args.settle[1]:g} s",
                           f"{fall:.4f} m/s", ""))
    done = wall_seconds[1:]  # the first row is the start
    print(f"wall time {run_seconds:.0f} s for the run; {done.mean():.2f} s per window on average "
          f"(rows of the run file: the last window of each)")
    record(args.record, args.run, figures + overlaps + cost)

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
        top.plot(t, x[:, :, 2].mean(axis=1) - lo[2], label="mean")
        top.fill_between(t, x[:, :, 2].min(axis=1) - lo[2], x[:, :, 2].max(axis=1) - lo[2], alpha=0.3,
                         label="lowest to highest")
        top.set_ylabel("capsules' height [m]")
        top.legend()
        bottom.plot(t, -v[:, :, 2].mean(axis=1))
        bottom.set_ylabel("mean fall speed [m/s]")
        bottom.set_xlabel("t [s]")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=120)


if __name__ == "__main__":
    main()
