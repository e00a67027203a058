"""The tutorials in docs/tutorials/ run as a user follows them: each page's ```sh blocks, in
order, in a folder of its own, with the files its marked blocks write; every marked output
block must appear in what the command before it printed, its numbers within the block's
tolerance. The markers are described in docs/tutorials/README.md.

    test_docs_tutorials.py COSIM WORK [--show] [unittest arguments]

COSIM is the cosim program (its folder goes first on PATH, the checkout is $COSIM), WORK a
folder for the tutorials' folders. --show prints every command block with what it printed,
for updating a page's output blocks. One tutorial:
`test_docs_tutorials.py COSIM WORK Tutorials.test_rarefied_gas`.
"""

import math
import os
import re
import shutil
import subprocess
import sys
import unittest
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
TUTORIALS = REPO / "docs" / "tutorials"
COSIM, WORK = Path(sys.argv[1]).resolve(), Path(sys.argv[2])
SHOW = "--show" in sys.argv[3:]
BLOCK_TIMEOUT = 600  # seconds for one command block

MARKER = re.compile(r"<!--\s*tutorial:\s*(.*?)\s*-->")
FENCE = re.compile(r"^```(\S*)")
NUMBER = r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?"
TOKEN = re.compile(rf"(?P<skip>~{NUMBER})|(?P<ellipsis>\.\.\.)|(?P<number>(?<![\w.]){NUMBER}(?!\w))|(?P<space>\s+)")


@dataclass
class Expect:
    text: str
    rtol: float
    atol: float
    line: int


@dataclass
class Step:
    kind: str  # "file" or "run"
    text: str
    line: int
    name: str = ""
    expects: list = field(default_factory=list)


def parse(page):
    """The page's steps in order: files to write and command blocks with their output blocks."""
    lines = page.read_text().splitlines()
    steps, marker, i = [], None, 0
    while i < len(lines):
        line = lines[i]
        found = MARKER.fullmatch(line.strip())
        fence = FENCE.match(line)
        if found:
            marker = (found.group(1).split(), i + 1)
        elif fence:
            language, start = fence.group(1), i + 1
            i += 1
            body = []
            while i < len(lines) and not lines[i].startswith("```"):
                body.append(lines[i])
                i += 1
            text = "\n".join(body) + "\n"
            words = marker[0] if marker else []
            where = f"{page.name}:{start}"
            if words and words[0] == "file":
                if len(words) != 2:
                    raise ValueError(f"{where}: 'file' takes one name: {words}")
                steps.append(Step("file", text, start, name=words[1]))
            elif words and words[0] == "output":
                options = dict(w.split("=", 1) for w in words[1:])
                if set(options) - {"rtol", "atol"}:
                    raise ValueError(f"{where}: 'output' takes rtol= and atol=: {words}")
                runs = [s for s in steps if s.kind == "run"]
                if not runs:
                    raise ValueError(f"{where}: an output block before any command block")
                runs[-1].expects.append(Expect(text, float(options.get("rtol", 0)), float(options.get("atol", 0)),
                                               start))
            elif words and words != ["skip"]:
                raise ValueError(f"{where}: unknown marker {words}")
            elif not words and language in ("sh", "bash"):
                steps.append(Step("run", text, start))
            marker = None
        elif line.strip():
            marker = None  # a marker belongs to the block right after it
        i += 1
    return steps


def pattern(expected):
    """The regular expression of one expected line and the numbers it states."""
    parts, numbers, at = [], [], 0
    for m in TOKEN.finditer(expected):
        parts.append(re.escape(expected[at:m.start()]))
        if m.lastgroup == "skip":
            parts.append(NUMBER)
        elif m.lastgroup == "ellipsis":
            parts.append(".*?")
        elif m.lastgroup == "number":
            parts.append(f"({NUMBER})")
            numbers.append(m.group())
        else:
            parts.append(r"\s+")
        at = m.end()
    parts.append(re.escape(expected[at:]))
    return re.compile("".join(parts)), numbers


def last_digit(text):
    """Half a unit of the last digit a number is written with: 0.05 for 1.0, 0.5 for 20."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return 0.5 * 10.0 ** (int(exponent or 0) - decimals)


def close(actual, expected, rtol, atol):
    return abs(float(actual) - float(expected)) <= rtol * abs(float(expected)) + atol + last_digit(expected)


def compare(expect, output):
    """None if every line of the expected block appears in the output in order (each line
    matched by its text, numbers within the tolerance), else what is missing."""
    actual = [line.strip() for line in output.splitlines()]
    at = 0
    for wanted in (line.strip() for line in expect.text.splitlines()):
        if not wanted or wanted == "...":
            continue
        regex, numbers = pattern(wanted)
        near = None
        for k in range(at, len(actual)):
            m = regex.fullmatch(actual[k])
            if not m:
                continue
            if all(close(a, e, expect.rtol, expect.atol) for a, e in zip(m.groups(), numbers)):
                at = k + 1
                break
            near = near or actual[k]
        else:
            hint = f"\n  closest: {near!r} (numbers outside rtol {expect.rtol}, atol {expect.atol})" if near else ""
            return f"expected line {wanted!r} not found in order{hint}"
    return None


def environment():
    env = dict(os.environ, COSIM=str(REPO))
    env["PATH"] = f"{COSIM.parent}{os.pathsep}{env.get('PATH', '')}"
    return env


def command_text(text):
    """A page's commands name the build as $COSIM/build/release; a test of another build
    (another preset) runs them against that one."""
    build = COSIM.parent.parent
    if build != REPO / "build" / "release":
        text = text.replace("$COSIM/build/release", str(build)).replace("${COSIM}/build/release", str(build))
    return text


class Tutorials(unittest.TestCase):
    def follow(self, page):
        work = WORK / page.stem
        shutil.rmtree(work, ignore_errors=True)
        work.mkdir(parents=True)
        env = environment()
        for step in parse(page):
            where = f"{page.relative_to(REPO)}:{step.line}"
            if step.kind == "file":
                (work / step.name).parent.mkdir(parents=True, exist_ok=True)
                (work / step.name).write_text(step.text)
                continue
            r = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", command_text(step.text)], cwd=work, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=BLOCK_TIMEOUT)
            if SHOW:
                print(f"\n== {where} (exit {r.returncode})\n{step.text}--\n{r.stdout}", flush=True)
            self.assertEqual(r.returncode, 0, f"{where}: the block\n{step.text}exited with {r.returncode}:\n{r.stdout}")
            for expect in step.expects:
                problem = compare(expect, r.stdout)
                self.assertIsNone(problem, f"{page.relative_to(REPO)}:{expect.line}: {problem}\n"
                                           f"the block at {where} printed:\n{r.stdout}")


def _add_tests():
    pages = sorted(p for p in TUTORIALS.glob("*.md") if p.name != "README.md")
    for page in pages:
        name = "test_" + re.sub(r"\W", "_", page.stem)
        setattr(Tutorials, name, lambda self, page=page: self.follow(page))


class Harness(unittest.TestCase):
    """The parts of the harness the tutorials rely on."""

    def test_numbers_within_the_tolerance_and_the_last_digit(self):
        expect = Expect("u = 8.02 mm/s, +1.0 %, 20 windows\n", 0.01, 0, 1)
        self.assertIsNone(compare(expect, "u = 8.05 mm/s, +1.04 %, 20 windows\n"))
        self.assertIsNotNone(compare(expect, "u = 8.2 mm/s, +1.0 %, 20 windows\n"))
        self.assertIsNotNone(compare(expect, "u = 8.02 mm/s, +1.0 %, 21 windows\n"))

    def test_wildcards_and_order(self):
        expect = Expect("starts fluid: .../cosim-fluid\n...\nfinished in ~3.97 s\n", 0, 0, 1)
        self.assertIsNone(compare(expect, "x\nstarts fluid: /a/b/cosim-fluid\ny\nfinished in 12.5 s\n"))
        self.assertIsNotNone(compare(expect, "finished in 12.5 s\nstarts fluid: /a/b/cosim-fluid\n"))

    def test_words_next_to_digits_are_text(self):
        regex, numbers = pattern("level_1.h5 24x24 tencate-e4 1.65e16")
        self.assertEqual(numbers, ["1.65e16"])
        self.assertTrue(regex.fullmatch("level_1.h5 24x24 tencate-e4 1.65e16"))
        self.assertEqual(last_digit("1.65e16"), 0.5e14)
        self.assertTrue(math.isclose(last_digit("-0.00986"), 5e-6))

    def test_every_page_parses_and_runs_something(self):
        pages = sorted(p for p in TUTORIALS.glob("*.md") if p.name != "README.md")
        self.assertGreaterEqual(len(pages), 3)
        for page in pages:
            steps = parse(page)
            self.assertTrue(any(s.kind == "run" for s in steps), page)
            self.assertTrue(any(s.expects for s in steps), page)


_add_tests()

if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], *[a for a in sys.argv[3:] if a != "--show"]])
