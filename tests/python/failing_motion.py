#!/usr/bin/env python3
"""Test double: python/prescribed_motion.py that fails once, in one window. Options, besides
motion: fail_in_window (its index) and fail_marker (a file: the window fails only while it
does not exist, and the failure creates it, so that a resumed run goes on)."""

import sys
from pathlib import Path

from cosim_participant import run
from prescribed_motion import PrescribedMotion


class FailingOnce(PrescribedMotion):
    OPTIONS = PrescribedMotion.OPTIONS | {"fail_in_window", "fail_marker"}

    def initialise(self, scene, name, poses, state):
        options = scene.options(name)
        self.fail_in_window = int(options["fail_in_window"])
        self.marker = Path(options["fail_marker"])
        return super().initialise(scene, name, poses, state)

    def advance(self, window, inputs):
        if window.index == self.fail_in_window and not self.marker.exists():
            self.marker.touch()
            raise RuntimeError(f"window {window.index} refused on purpose")
        return super().advance(window, inputs)


if __name__ == "__main__":
    sys.exit(run(FailingOnce(), provides=["poses"], needs=["forces"]))
