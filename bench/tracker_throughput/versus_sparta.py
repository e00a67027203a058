#!/usr/bin/env python3
"""SPARTA's free, collide and sphere decks and tracker_throughput's, side by side in one run.

SPARTA is the peer, built from its public source for this benchmark only (README.md,
"Against SPARTA"): this script runs its serial binary on its own bench inputs at the sizes
tracker_throughput uses (46^3 cells for free and collide, 22^3 for sphere, 10 particles per
cell), alternating with tracker_throughput round by round, so that both see the same
machine, and prints each round's particle-steps per second and the ratio cosim / SPARTA.
"""

import argparse
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

DECKS = {
    # deck: (SPARTA input, cells per side, tracker_throughput arguments, its row)
    "free": ("in.free", 46, ["--deck", "free", "--storage", "sorted"], "Swarm"),
    "collide": ("in.collide", 46, ["--deck", "free", "--storage", "collisions"], "Swarm + collisions"),
    "sphere": ("in.sphere", 22, ["--deck", "sphere"], None),
}
SPARTA_FILES = ["in.free", "in.collide", "in.sphere", "ar.species", "ar.vss", "data.sphere"]


def sparta_rate(binary, deck, scratch):
    """Particle moves per second of the deck's last (timed) run, from SPARTA's log."""
    deck_input, cells, _, _ = DECKS[deck]
    log = scratch / f"log.{deck}"
    command = [str(binary), "-in", deck_input, "-log", str(log), "-screen", "none"]
    for axis in "xyz":
        command += ["-var", axis, str(cells)]
    subprocess.run(command, cwd=scratch, check=True)
    text = log.read_text()
    loops = re.findall(r"Loop time of ([0-9.eE+-]+) on 1 procs for (\d+) steps with (\d+) particles", text)
    moves = re.findall(r"Particle moves\s+=\s+(\d+)", text)
    if not loops or not moves:
        sys.exit(f"versus_sparta: no 'Loop time' or 'Particle moves' in {log}")
    seconds = float(loops[-1][0])
    return int(moves[-1]) / seconds, int(loops[-1][2])


def cosim_rates(binary, decks):
    """M particle-steps/s per deck from one tracker_throughput run per distinct argument list."""
    rates = {}
    runs = {}
    for deck in decks:
        arguments = tuple(DECKS[deck][2])
        if arguments not in runs:
            runs[arguments] = subprocess.run([str(binary), *arguments], check=True, capture_output=True,
                                             text=True).stdout
        out = runs[arguments]
        row = DECKS[deck][3]
        if row is None:
            found = re.search(r"([0-9.]+) M particle-steps/s", out)
        else:
            found = re.search(r"^event-driven\s+" + re.escape(row) + r"\s+1\s+([0-9.]+)", out, re.M)
        if not found:
            sys.exit(f"versus_sparta: no row for the {deck} deck in tracker_throughput's output:\n{out}")
        rates[deck] = float(found.group(1)) * 1e6
    return rates


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sparta", required=True, type=pathlib.Path,
                        help="SPARTA's serial binary (src/spa_serial after `make serial`)")
    parser.add_argument("--sparta-bench", type=pathlib.Path,
                        help="SPARTA's bench directory with in.free, in.collide, in.sphere (default: next to src/)")
    parser.add_argument("--cosim", type=pathlib.Path, default=pathlib.Path("build/release/bin/tracker_throughput"),
                        help="tracker_throughput (default: build/release/bin/tracker_throughput)")
    parser.add_argument("--decks", nargs="+", choices=list(DECKS), default=list(DECKS))
    parser.add_argument("--rounds", type=int, default=2, help="alternations of the two programs (default 2)")
    args = parser.parse_args()
    bench = args.sparta_bench or args.sparta.resolve().parent.parent / "bench"
    for name in SPARTA_FILES:
        if not (bench / name).is_file():
            sys.exit(f"versus_sparta: {bench / name} not found (--sparta-bench)")

    results = {deck: {"sparta": [], "cosim": []} for deck in args.decks}
    with tempfile.TemporaryDirectory(prefix="versus_sparta_") as directory:
        scratch = pathlib.Path(directory)
        for name in SPARTA_FILES:
            shutil.copy(bench / name, scratch / name)
        for round_ in range(1, args.rounds + 1):
            for deck in args.decks:
                rate, particles = sparta_rate(args.sparta, deck, scratch)
                results[deck]["sparta"].append(rate)
                print(f"round {round_}: SPARTA {deck:8s} {rate / 1e6:7.2f} M particle-steps/s ({particles} particles)",
                      flush=True)
            for deck, rate in cosim_rates(args.cosim, args.decks).items():
                results[deck]["cosim"].append(rate)
                print(f"round {round_}: cosim  {deck:8s} {rate / 1e6:7.2f} M particle-steps/s", flush=True)

    # Per round, not pooled: a round whose two runs saw different loads shows in its ratio.
    print("\n| deck | SPARTA [M/s] per round | cosim [M/s] per round | cosim / SPARTA per round |")
    print("|---|---|---|---|")
    for deck, r in results.items():
        def row(values, scale=1e-6, suffix=""):
            return ", ".join(f"{x * scale:.2f}{suffix}" for x in values)
        ratios = [c / s for c, s in zip(r["cosim"], r["sparta"])]
        print(f"| {deck} | {row(r['sparta'])} | {row(r['cosim'])} | {row(ratios, 1, 'x')} |")


if __name__ == "__main__":
    main()
