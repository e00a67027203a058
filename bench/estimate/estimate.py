#!/usr/bin/python3
"""The estimate before a run against the run: for each shipped scene, what `cosim check`
estimates (wall time, memory per program, run file) from a store holding only this host's
calibration, beside what `cosim run` then measured (its record in the store).

    bench/estimate/estimate.py [--calibrate] [--max-seconds 130] [--table bench/estimate/results]

--table writes TABLE.csv; scripts/results then renders it into TABLE.md.

--calibrate runs `cosim calibrate` first into the bench's own store; without it the store
must exist (--store). Scenes whose documented run time (configs/run_times.csv) is above
--max-seconds are estimated but not run.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]
UNITS = {"s": 1, "min": 60, "h": 3600, "kB": 1e3, "MB": 1e6, "GB": 1e9}


def number(value, unit):
    return float(value) * UNITS[unit]


def parse_estimate(line):
    """The wall seconds, {program: bytes} and run file bytes of an `estimate:` line."""
    wall = re.match(r"estimate: ([\d.]+) (s|min|h) here", line)
    memory = {}
    m = re.search(r"; memory ([^;]+);", line)
    if m:
        for part in m.group(1).split(", "):
            name, value, unit = part.rsplit(" ", 2)
            memory[name] = number(value, unit)
    disk = re.search(r"; run file ([\d.]+) (kB|MB|GB)", line)
    return number(*wall.groups()), memory, number(*disk.groups())


def environment(store):
    env = dict(os.environ, COSIM_COST_FILE=str(store), HDF5_USE_FILE_LOCKING="FALSE",
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return env


def scenes(max_seconds):
    with open(ROOT / "configs" / "run_times.csv") as f:
        for row in csv.DictReader(f):
            if row["command"] != "cosim run":
                continue  # prescribed motion runs standalone, without the coupler's estimate
            yield row["scene"], float(row["seconds"]) <= max_seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cosim", default=str(ROOT / "build" / "release" / "bin" / "cosim"))
    parser.add_argument("--store", default=str(ROOT / "runs" / "estimate" / "calibration.yaml"),
                        help="the calibrated store each scene's estimate starts from")
    parser.add_argument("--calibrate", action="store_true", help="run cosim calibrate into --store first")
    parser.add_argument("--max-seconds", type=float, default=130)
    parser.add_argument("--only", nargs="*", help="these scenes only")
    parser.add_argument("--table", help="write TABLE.csv (scripts/results renders TABLE.md from it)")
    args = parser.parse_args()

    store = Path(args.store)
    store.parent.mkdir(parents=True, exist_ok=True)
    if args.calibrate:
        store.unlink(missing_ok=True)
        subprocess.run([args.cosim, "calibrate"], env=environment(store), check=True)
    if not store.exists():
        sys.exit(f"{store} does not exist: run with --calibrate")

    rows = []
    stores = store.parent / "stores"
    stores.mkdir(exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        for name, run in scenes(args.max_seconds):
            if args.only and name not in args.only:
                continue
            own = stores / name  # the calibration and this scene's run, kept for a look
            shutil.copy(store, own)
            scene = ROOT / "configs" / name
            check = subprocess.run([args.cosim, "check", str(scene)], env=environment(own), cwd=ROOT,
                                   capture_output=True, text=True)
            line = next((l for l in check.stdout.splitlines() if l.startswith("estimate:")), None)
            if line is None:
                print(f"{name}: no estimate\n{check.stdout}{check.stderr}", file=sys.stderr)
                continue
            wall, memory, disk = parse_estimate(line)
            top = re.search(r"\((\S+) \d+ %: .*?([\d.]+)( k| M)? steps\)", line)
            row = {"scene": name, "estimate_s": wall, "estimate_disk": disk, "estimate_memory": memory,
                   "top": top.group(1) if top else "",
                   "estimate_steps": float(top.group(2)) * {None: 1, " k": 1e3, " M": 1e6}[top.group(3)] if top else 0}
            if run:
                out = Path(scratch) / f"{name}.h5"
                done = subprocess.run([args.cosim, "run", "-q", str(scene), "-o", str(out)], env=environment(own),
                                      cwd=ROOT, capture_output=True, text=True)
                if done.returncode == 0:
                    record = yaml.safe_load(own.read_text())["runs"][-1]
                    row["measured_s"] = record["wall_seconds"]
                    row["measured_disk"] = record["disk_bytes"]
                    row["measured_memory"] = {p: o["peak_bytes"] for p, o in record["programs"].items()
                                              if o.get("peak_bytes", 0) > 0}
                    if row["top"] in record["programs"]:
                        row["measured_steps"] = record["programs"][row["top"]]["steps"]
                    again = subprocess.run([args.cosim, "check", str(scene)], env=environment(own), cwd=ROOT,
                                           capture_output=True, text=True)
                    line_again = next((l for l in again.stdout.splitlines() if l.startswith("estimate:")), None)
                    if line_again:
                        row["again_s"] = parse_estimate(line_again)[0]
                else:
                    print(f"{name}: run failed\n{done.stderr[-2000:]}", file=sys.stderr)
            rows.append(row)
            print(f"{name}: {line}" + (f"  | measured {row['measured_s']:.1f} s" if "measured_s" in row else ""),
                  flush=True)
    if args.table:
        write_table(rows, Path(args.table))
        subprocess.run([sys.executable, str(ROOT / "scripts" / "results")], check=True)


def ratio(a, b):
    return f"{a / b:.2f}" if a and b else ""


def write_table(rows, table):
    """TABLE.csv, one row per scene; the Markdown table is scripts/results's, from this file."""
    fields = ["scene", "estimate_s", "measured_s", "wall_ratio", "again_ratio", "largest", "estimate_steps", "measured_steps",
              "memory", "estimate_disk_MB", "measured_disk_MB", "disk_ratio"]
    with open(table.with_suffix(".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows:
            measured_memory = r.get("measured_memory", {})
            memory = ", ".join(
                f"{p} {r['estimate_memory'][p] / 1e6:.0f} / " +
                (f"{measured_memory[p] / 1e6:.0f}" if p in measured_memory else "–")
                for p in r["estimate_memory"])
            measured = r.get("measured_s")
            w.writerow({"scene": r["scene"], "estimate_s": f"{r['estimate_s']:.1f}",
                        "measured_s": f"{measured:.1f}" if measured else "",
                        "wall_ratio": ratio(r["estimate_s"], measured),
                        "again_ratio": ratio(r.get("again_s"), measured), "largest": r["top"],
                        "estimate_steps": f"{r['estimate_steps']:.0f}" if r["top"] else "",
                        "measured_steps": f"{r['measured_steps']:.0f}" if "measured_steps" in r else "",
                        "memory": memory,
                        "estimate_disk_MB": f"{r['estimate_disk'] / 1e6:.3f}",
                        "measured_disk_MB": f"{r['measured_disk'] / 1e6:.3f}" if "measured_disk" in r else "",
                        "disk_ratio": ratio(r["estimate_disk"], r.get("measured_disk"))})

if __name__ == "__main__":
    main()
