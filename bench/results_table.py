"""Measured figures kept in one table, a CSV that scripts/results renders into the docs: a
bench script writes its rows, each with the command that measured it, and measuring a row
again (the same key) replaces it while the other rows stay.

The scene scripts (bench/beds/*.py) write one row per scene and figure (its value, what it
is compared with, the command):

    --record bench/beds/results.csv sedimenting-sticks.yaml
"""

import csv
import os
import shlex
import sys
from pathlib import Path

import yaml

COLUMNS = ["scene", "figure", "value", "against", "command"]
ROOT = Path(__file__).resolve().parent.parent


def add_option(parser):
    parser.add_argument("--record", nargs=2, metavar=("CSV", "SCENE"),
                        help="write the figures measured into CSV as the rows of SCENE "
                        "(e.g. bench/beds/results.csv sedimenting-sticks.yaml)")


def command_line(run, leave_out={"--record": 2}):
    """The command running now as a reader would type it: the script from the repository's
    root, the run file written <run>.h5, the options `leave_out` names (where the output
    goes) left out with as many values as it gives."""
    words, skip = [], 0
    for word in sys.argv[1:]:
        if skip:
            skip -= 1
        elif word in leave_out:
            skip = leave_out[word]
        else:
            words.append("<run>.h5" if word == run else word)
    script = os.path.relpath(Path(sys.argv[0]).resolve(), ROOT)
    return " ".join([script] + [shlex.quote(w) if w != "<run>.h5" else w for w in words])


def overlap_text(depth):
    """An overlap as a fraction of the radius, or that the bodies never touched."""
    return f"{depth:.2%} of the radius".replace("%", " %") if depth >= 0 else "never touched"


def run_figures(f):
    """What any run file tells of its cost and its coupling: the run's wall time over all its
    sessions and a written window's mean and, for an implicit scheme, the iterations per
    window (of the written windows, the last of each row)."""
    wall = float(f["run"].attrs["wall_seconds"])
    window = f["coupling/wall_seconds"][1:].mean()
    end = yaml.safe_load(f["run/scene_text"][()].decode())["time"]["end"]
    figures = [("simulated", f"to t = {f['coupling/time'][-1]:.3g} s of the scene's {end:g} s", ""),
               ("wall time", f"{wall:,.0f} s ({window:.2f} s a window)", "")]
    iterations = f["coupling/iterations"][1:]
    if iterations.size and iterations.max() > 1:
        figures.append(("coupling iterations per window", f"{iterations.mean():.2f} (at most {iterations.max():.0f})",
                        ""))
    return figures


def upsert(table, columns, rows, key):
    """Writes `rows` (dicts of `columns`) into the CSV `table`: a row whose `key` columns match
    an old row's takes its place, the others follow the last old row of the same first key."""
    path = Path(table)
    old = []
    if path.exists():
        with open(path, newline="", encoding="utf-8") as f:
            old = list(csv.DictReader(f))
    fresh = {tuple(row[k] for k in key): row for row in rows}
    kept = [fresh.pop(tuple(row[k] for k in key), row) for row in old]
    first = rows[0][key[0]] if rows else None
    last = max((k for k, row in enumerate(kept) if row[key[0]] == first), default=len(kept) - 1)
    kept[last + 1:last + 1] = fresh.values()
    with open(path, "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        writer.writeheader()
        writer.writerows(kept)


def record(option, run, figures):
    """Writes `figures` ((figure, value, against) triples) as the rows of the scene named in
    `option` ([csv, scene] from --record, or None to write nothing)."""
    if option is None:
        return
    table, scene = option
    command = command_line(run)
    upsert(table, COLUMNS, [{"scene": scene, "figure": name, "value": value, "against": against,
                             "command": command} for name, value, against in figures], ("scene", "figure"))
    print(f"{len(figures)} figures of {scene} in {table}")
