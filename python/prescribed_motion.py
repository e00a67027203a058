#!/usr/bin/env python3
"""Bodies moved on a given trajectory, in place of cosim-rigidbody (python/README.md).

Options (participants.<name>.options):
  motion: {<body>: {amplitude: [x, y, z] m, frequency: Hz}}
A listed body's centre is x0 + A sin(2 pi f t), x0 its scene position, with its scene
orientation and no rotation; every other body stays at its start pose, at rest. The forces
the coupler sends do not change the motion.
"""

import math
import sys

from cosim_participant import Outputs, Solver, run

POSE_WIDTH = 13


class PrescribedMotion(Solver):
    OPTIONS = {"motion"}

    def initialise(self, scene, name, poses, state):
        options = scene.options(name)
        unknown = set(options) - self.OPTIONS
        if unknown:
            raise ValueError(f"participants.{name}.options: unknown keys {sorted(unknown)}, "
                             f"expected {sorted(self.OPTIONS)}")
        names = [body["name"] for body in scene.bodies]
        motion = options.get("motion") or {}
        for body in motion:
            if body not in names:
                raise ValueError(f"participants.{name}.options.motion.{body}: not a body of the scene")
        self.waves = [_wave(motion[n]) if n in motion else None for n in names]
        self.time = 0.0
        self.origin = poses
        if state is not None:
            self.restore(state)
        return Outputs(poses=self.poses_at(self.time))

    def advance(self, window, inputs):
        # A solver goes on from where its state is; run() must have put it at t0.
        if not math.isclose(self.time, window.t0, rel_tol=1e-12, abs_tol=1e-12):
            raise RuntimeError(f"asked to advance from t = {window.t0} s, but the state is at t = {self.time} s")
        self.time = window.t1
        return Outputs(poses=self.poses_at(self.time), substeps=1)

    def state(self):
        return [self.time] + [v for row in self.origin for v in row]

    def restore(self, state):
        if len(state) != 1 + POSE_WIDTH * len(self.origin):
            raise ValueError(f"a state of {len(state)} values, expected {1 + POSE_WIDTH * len(self.origin)}")
        self.time = state[0]
        self.origin = [state[1 + POSE_WIDTH * b:1 + POSE_WIDTH * (b + 1)] for b in range(len(self.origin))]

    def poses_at(self, t):
        return [_pose(start, wave, t) for start, wave in zip(self.origin, self.waves)]


def _wave(spec):
    amplitude = [float(a) for a in spec["amplitude"]]
    frequency = float(spec["frequency"])
    if len(amplitude) != 3 or not frequency > 0:
        raise ValueError(f"motion {spec}: amplitude needs 3 values and frequency must be positive")
    return amplitude, frequency


def _pose(start, wave, t):
    """position, orientation, velocity, angular velocity at t."""
    position, orientation = list(start[0:3]), list(start[3:7])
    velocity = [0.0, 0.0, 0.0]
    if wave is not None:
        amplitude, frequency = wave
        omega = 2 * math.pi * frequency
        position = [x + a * math.sin(omega * t) for x, a in zip(position, amplitude)]
        velocity = [a * omega * math.cos(omega * t) for a in amplitude]
    return position + orientation + velocity + [0.0, 0.0, 0.0]


if __name__ == "__main__":
    # Taking forces is part of the rigid-body role the scene plans for it (docs/protocol.md).
    sys.exit(run(PrescribedMotion(), provides=["poses"], needs=["forces"]))
