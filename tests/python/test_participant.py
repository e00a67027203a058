"""The Python participant module through `cosim run`: python/prescribed_motion.py moves the
cylinder of prescribed_cylinder.yaml through cosim-fluid in place of cosim-rigidbody.

    test_participant.py COSIM WORK [unittest arguments]

COSIM is the cosim program, WORK a folder for the run files.
"""

import math
import os
import shutil
import subprocess
import sys
import unittest
from pathlib import Path

import h5py
import numpy as np
import yaml

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
SCENE = HERE / "prescribed_cylinder.yaml"
COSIM, WORK = sys.argv[1], Path(sys.argv[2])
WINDOW, WINDOWS = 0.05, 10


def cosim(*args):
    """Runs cosim from the repository's root, where the scene's commands resolve."""
    env = dict(os.environ, PYTHONPATH=f"{REPO / 'python'}:{HERE}")
    return subprocess.run([COSIM, *map(str, args), "-q"], cwd=REPO, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=120)


def scratch(name):
    path = WORK / name
    shutil.rmtree(path, ignore_errors=True)
    path.mkdir(parents=True)
    return path


class PrescribedCylinder(unittest.TestCase):
    def assert_prescribed(self, run_file):
        """Every row of the run file holds the pose the scene prescribes at its time."""
        with h5py.File(run_file, "r") as f:
            body = f["bodies/cylinder"]
            t = body["time"][:]
            np.testing.assert_allclose(t, WINDOW * np.arange(WINDOWS + 1), rtol=0, atol=1e-12)
            phase = 2 * math.pi * t
            rows = len(t)
            expected = {
                "position": np.column_stack([0.55 + 0.1 * np.sin(phase), np.full(rows, 0.2), np.full(rows, 0.01)]),
                "orientation": np.tile([1.0, 0, 0, 0], (rows, 1)),
                "velocity": np.column_stack([0.1 * 2 * math.pi * np.cos(phase), np.zeros(rows), np.zeros(rows)]),
                "angular_velocity": np.zeros((rows, 3)),
            }
            for name, values in expected.items():
                np.testing.assert_allclose(body[name][:], values, rtol=0, atol=1e-12, err_msg=name)

    def test_the_cylinder_moves_as_prescribed_and_the_fluid_pushes_back(self):
        run_file = scratch("prescribed") / "run.h5"
        r = cosim("run", SCENE, "-o", run_file)
        self.assertEqual(r.returncode, 0, r.stdout)
        self.assert_prescribed(run_file)
        with h5py.File(run_file, "r") as f:
            self.assertEqual(f["run"].attrs["status"], "finished")
            # Implicit coupling repeats every window: the module rolled the example back.
            self.assertTrue((f["coupling/iterations"][1:] > 1).all(), f["coupling/iterations"][:])
            # The liquid resists the moving cylinder: the fluid got the poses.
            force = f["bodies/cylinder/force"][1:, 0]
            self.assertTrue((np.abs(force) > 1.0).all(), force)

    def test_an_error_is_reported_with_its_message_and_the_run_resumes(self):
        work = scratch("failing")
        scene = yaml.safe_load(SCENE.read_text())
        rigid = scene["participants"]["rigidbody"]
        rigid["command"] = ["/usr/bin/python3", str(HERE / "failing_motion.py")]
        rigid["options"].update(fail_in_window=5, fail_marker=str(work / "failed-once"))
        (work / "scene.yaml").write_text(yaml.safe_dump(scene))
        run_file = work / "run.h5"

        failed = cosim("run", work / "scene.yaml", "-o", run_file)
        self.assertEqual(failed.returncode, 1, failed.stdout)
        reported = ("participant 'rigidbody' reported an error: "
                    "RuntimeError: window 5 refused on purpose in window 5 (t = 0.25")
        self.assertIn("cosim: error: " + reported, failed.stdout)
        with h5py.File(run_file, "r") as f:
            self.assertTrue(f["run"].attrs["status"].startswith("failed: " + reported), f["run"].attrs["status"])

        # The checkpoint after window 3 (checkpoint_every: 4) holds the example's state.
        resumed = cosim("run", "--resume", run_file)
        self.assertEqual(resumed.returncode, 0, resumed.stdout)
        self.assertIn("from window 4 (t = 0.2 s)", resumed.stdout)
        self.assert_prescribed(run_file)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], *sys.argv[3:]])
