"""docs/output.md's example reads a run file: its Python block, run on a short run of
prescribed_cylinder.yaml with fields, prints the status, the body, the iterations and the
last field frame.

    test_docs_output.py COSIM WORK

COSIM is the cosim program, WORK a folder for the run file and the example.
"""

import os
import re
import shutil
import subprocess
import sys
import unittest
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
COSIM, WORK = sys.argv[1], Path(sys.argv[2])


class OutputExample(unittest.TestCase):
    def test_the_example_reads_a_run_file(self):
        shutil.rmtree(WORK, ignore_errors=True)
        WORK.mkdir(parents=True)
        scene = yaml.safe_load((HERE / "prescribed_cylinder.yaml").read_text())
        scene["output"]["fields_every"] = 5
        (WORK / "scene.yaml").write_text(yaml.safe_dump(scene))
        run_file = WORK / "run.h5"
        env = dict(os.environ, PYTHONPATH=f"{REPO / 'python'}:{HERE}")
        run = subprocess.run([COSIM, "run", WORK / "scene.yaml", "-o", run_file, "-q"], cwd=REPO, env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
        self.assertEqual(run.returncode, 0, run.stdout)

        blocks = re.findall(r"```python\n(.*?)```", (REPO / "docs" / "output.md").read_text(), re.S)
        self.assertEqual(len(blocks), 1)
        (WORK / "read_run.py").write_text(blocks[0])
        read = subprocess.run([sys.executable, WORK / "read_run.py", run_file], stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, text=True, timeout=60)
        self.assertEqual(read.returncode, 0, read.stdout)
        lines = read.stdout.splitlines()
        self.assertEqual(lines[0], "status: finished")
        # The prescribed x = 0.55 + 0.1 sin(2 pi t) is back at 0.55 at t = 0.5 s.
        position = re.match(r"cylinder: t = 0\.5 s, position \[([^]]*)\] m, force \[([^]]*)\] N$", lines[1])
        self.assertIsNotNone(position, read.stdout)
        x, y, _ = map(float, position.group(1).split())
        self.assertAlmostEqual(x, 0.55, places=9)
        self.assertAlmostEqual(y, 0.2, places=9)
        # The liquid resists the moving cylinder along x.
        self.assertGreater(abs(float(position.group(2).split()[0])), 1.0, read.stdout)
        self.assertTrue(lines[2].startswith("coupling iterations per window: "), read.stdout)
        self.assertRegex(lines[3], r"^fluid window 000010 t = 0\.5 s: \[.*'alpha'.*'pressure'.*'velocity'\]$")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], *sys.argv[3:]])
