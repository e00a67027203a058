#!/usr/bin/python3
"""The drag that holds a fluidized bed at its solid fraction, measured on fixed beads: the
beads of configs/fluidized-bed-round.yaml (6 mm Pyrex, 2230 kg/m^3, in KSCN solution, 1400
kg/m^3 and 3.8e-3 Pa s) placed at random (random_arrays.py's placement) in a periodic box
at solid fraction alpha, h = 1 mm as in the scene (d/h 6), and the fluid driven upwards by
the mean pressure gradient that carries their buoyant weight, rho f = alpha (rho_p - rho) g.
In the steady state the superficial velocity U_s (the mean velocity over the box, beads
included, over the run's second half) is the inflow at which a bed of solid fraction alpha
floats, with the beads held still: the drag law the method gives a bed, without the beads'
own motion. Richardson & Zaki's U_s = u_t (1 - alpha)^m (u_t = 0.226 m/s, m = 2.4, as
bench/beds/beds.py) is the reference; a power law through the measured points gives the
solid fraction at which fixed beads float at the scene's inflow u0, against Richardson-Zaki's
alpha = 1 - (u0 / u_t)^(1/m).

    bench/beds/bed_drag.py [--fractions 0.23 0.15] [--beads 40] [--seeds 3] [--end 1.2]
        [--record bench/beds/results.csv fluidized-bed-round.yaml]

Each seed is its own array; U_s is given as the mean over the seeds with its standard error,
and the power law runs through the two means.
"""
import argparse
import math
import os
import statistics
import sys
import tempfile
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parent.parent.parent
sys.path.insert(0, str(ROOT / "bench"))
sys.path.insert(0, str(ROOT / "bench/fluid_accuracy"))
import periodic_box  # noqa: E402
import random_arrays  # noqa: E402
from results_table import add_option, record  # noqa: E402

TERMINAL, EXPONENT = 0.226, 2.4  # Richardson-Zaki for Aguilar's beads, as bench/beds/beds.py


def bed_scene():
    return yaml.safe_load((ROOT / "configs/fluidized-bed-round.yaml").read_text())


def array_scene(alpha, beads, seed, end):
    """The periodic box of `beads` fixed beads at about `alpha`, driven along z; the scene,
    its solid fraction as placed (the box is a whole number of cells) and the cells."""
    bed = bed_scene()
    fluid = bed["participants"]["fluid"]
    sphere = next(b for b in bed["bodies"] if "generate" in b)
    radius = sphere["shape"]["radius"]
    h = (bed["domain"]["max"][0] - bed["domain"]["min"][0]) / fluid["options"]["grid"]["cells"][0]
    volume = 4 / 3 * math.pi * radius ** 3
    cells = round((beads * volume / alpha) ** (1 / 3) / h)
    side = cells * h
    alpha = beads * volume / side ** 3
    centres = random_arrays.place(beads, radius / side, 0.0, seed)
    rho, rho_p, g = fluid["options"]["density"], sphere["material"]["density"], -bed["gravity"][2]
    scene = periodic_box.hasimoto_scene()
    scene["domain"] = {"min": [0, 0, 0], "max": [side] * 3}
    scene["bodies"] = [{"name": f"b{k}", "shape": {"type": "sphere", "radius": radius}, "fixed": True,
                        "position": [float(v) * side for v in x]} for k, x in enumerate(centres)]
    scene["time"]["end"] = end
    scene["coupling"]["window"] = 0.01
    scene["output"]["fields_every"] = 5
    scene.pop("study", None)
    options = scene["participants"]["fluid"]["options"]
    options["density"] = rho
    options["viscosity"] = fluid["options"]["viscosity"]
    options["body_force"] = [0, 0, alpha * (rho_p - rho) * g / rho]
    options["grid"]["cells"] = [cells] * 3
    options["theta"] = 0.5
    scene["participants"]["fluid"]["dt"] = options["dt_initial"] = 0.002
    return scene, alpha, cells


def superficial_velocity(result, since):
    """The mean z velocity over the box (periodic_box.run's `means`), averaged over the
    fields from `since` on, and its standard deviation over them."""
    values = [m[2] for t, m in zip(result["times"], result["means"]) if t >= since]
    return statistics.fmean(values), statistics.stdev(values) if len(values) > 1 else 0.0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--fractions", type=float, nargs=2, default=[0.23, 0.15])
    parser.add_argument("--beads", type=int, default=40)
    parser.add_argument("--seeds", type=int, default=3, help="arrays per solid fraction")
    parser.add_argument("--end", type=float, default=1.2, help="simulated seconds; U_s is averaged over the second half")
    parser.add_argument("--fluid", default=str(ROOT / "build/release/bin/cosim-fluid"))
    add_option(parser)
    args = parser.parse_args()
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    points = []
    with tempfile.TemporaryDirectory() as folder:
        for asked in args.fractions:
            values = []
            for seed in range(1, args.seeds + 1):
                scene, alpha, cells = array_scene(asked, args.beads, seed, args.end)
                name = f"alpha{asked}_seed{seed}"
                result = periodic_box.run(args.fluid, scene, folder, name)
                u, spread = superficial_velocity(result, args.end / 2)
                values.append(u)
                print(f"alpha {alpha:.3f} ({args.beads} beads, {cells}^3 cells), seed {seed}: U_s {u:.4f} m/s "
                      f"(+- {spread:.4f} over the second half); {result['steps']} steps, {result['wall']:.0f} s",
                      flush=True)
            u = statistics.fmean(values)
            error = statistics.stdev(values) / math.sqrt(len(values)) if len(values) > 1 else 0.0
            reference = TERMINAL * (1 - alpha) ** EXPONENT
            points.append((alpha, u, error))
            print(f"alpha {alpha:.3f}: U_s {u:.4f} +- {error:.4f} m/s (standard error over {len(values)} arrays) "
                  f"against Richardson-Zaki's {reference:.4f}: {u / reference - 1:+.1%}", flush=True)
    (a1, u1, _), (a2, u2, _) = points
    m = math.log(u1 / u2) / math.log((1 - a1) / (1 - a2))
    terminal = u1 / (1 - a1) ** m
    u0 = bed_scene()["participants"]["fluid"]["options"]["boundaries"]["z_min"]["velocity"][2]
    floats = 1 - (u0 / terminal) ** (1 / m)
    reference = 1 - (u0 / TERMINAL) ** (1 / EXPONENT)
    print(f"through the two points U_s = {terminal:.3f} (1 - alpha)^{m:.2f}: fixed beads float at u0 = {u0} m/s at "
          f"alpha {floats:.3f}, against Richardson-Zaki's {reference:.3f}")
    record(args.record, None, [
        (f"fixed beads at random (d/h 6, periodic): alpha at u0 = {u0} m/s", f"{floats:.3f}",
         f"Richardson-Zaki {reference:.3f}"),
        *[(f"fixed beads at random: U_s at alpha {a:.3f}", f"{u:.4f} +- {e:.4f} m/s",
           f"Richardson-Zaki {TERMINAL * (1 - a) ** EXPONENT:.4f} m/s") for a, u, e in points]])


if __name__ == "__main__":
    main()
