"""The participant SDK from a user's side: `cmake --install` of this build into a fresh
prefix, examples/participant configured and built out of tree against it with
find_package(cosim), then its scene run by the installed `cosim`: the ball falls at the
terminal velocity m g / c that the example's drag and gravity give.

    test_example_participant.py CMAKE BUILD GENERATOR CXX WORK [unittest arguments]

CMAKE is the cmake program, BUILD this build tree, GENERATOR and CXX its generator and C++
compiler (the example is built alike), WORK a folder for the prefix, the example's build
and the run file.
"""

import math
import shutil
import subprocess
import sys
import unittest
from pathlib import Path

import h5py
import yaml

REPO = Path(__file__).resolve().parents[2]
EXAMPLE = REPO / "examples" / "participant"
SCENE = EXAMPLE / "falling_ball.yaml"
CMAKE, BUILD, GENERATOR, CXX, WORK = sys.argv[1:6]
WORK = Path(WORK)


def run(*args, cwd=None):
    r = subprocess.run(list(map(str, args)), cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       timeout=100)
    if r.returncode != 0:
        raise AssertionError(f"{' '.join(map(str, args))} exited with {r.returncode}:\n{r.stdout}")
    return r.stdout


class ExampleParticipant(unittest.TestCase):
    def test_the_installed_sdk_builds_the_example_and_its_ball_falls_at_m_g_over_c(self):
        shutil.rmtree(WORK, ignore_errors=True)
        WORK.mkdir(parents=True)
        prefix = WORK / "prefix"
        run(CMAKE, "--install", BUILD, "--prefix", prefix)
        # In WORK/build, where the scene's command (build/cosim-drag) finds it from WORK.
        run(CMAKE, "-S", EXAMPLE, "-B", WORK / "build", "-G", GENERATOR, f"-DCMAKE_CXX_COMPILER={CXX}",
            f"-DCMAKE_PREFIX_PATH={prefix}")
        run(CMAKE, "--build", WORK / "build")
        run_file = WORK / "falling_ball.h5"
        run(prefix / "bin" / "cosim", "run", SCENE, "-o", run_file, "-q", cwd=WORK)

        scene = yaml.safe_load(SCENE.read_text())
        ball = scene["bodies"][0]
        mass = ball["material"]["density"] * 4 / 3 * math.pi * ball["shape"]["radius"] ** 3
        weight = -mass * scene["gravity"][2]
        terminal = -weight / scene["participants"]["drag"]["options"]["coefficient"]
        with h5py.File(run_file, "r") as f:
            self.assertEqual(f["run"].attrs["status"], "finished")
            body = f["bodies/ball"]
            self.assertAlmostEqual(body["time"][-1], scene["time"]["end"], places=9)
            velocity, force = body["velocity"][-1][2], body["force"][-1][2]
        print(f"terminal velocity {velocity:.6f} m/s, m g / c = {terminal:.6f} m/s; drag {force:.6f} N, "
              f"weight {weight:.6f} N")
        # After eight times m / c the ball is within e^-8 = 0.03 % of m g / c: a drag 2 % off fails.
        self.assertLess(abs(velocity / terminal - 1), 0.01)
        self.assertLess(abs(force / weight - 1), 0.01)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], *sys.argv[6:]])
