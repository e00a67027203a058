"""What a Python program implements to take part in a run; run() does all the talking.

Poses are rows of 13 values (position, quaternion w x y z, velocity, angular velocity),
forces rows of 6 (force, torque about the body's position), one row per body of the scene,
fixed bodies included, in scene order.
"""

from abc import ABC, abstractmethod
from dataclasses import dataclass, field


@dataclass
class Window:
    index: int
    iteration: int  # > 1: an implicit scheme repeats the window, run() has restored the state
    t0: float
    t1: float


@dataclass
class Inputs:
    """The coupler's values at the window's start and end; empty lists for data the
    participant does not take in this run. Poses are instants; the forces of cosim-fluid
    and cosim-tracker are means over the window."""

    poses_start: list = field(default_factory=list)
    poses_end: list = field(default_factory=list)
    forces_start: list = field(default_factory=list)
    forces_end: list = field(default_factory=list)


@dataclass
class Outputs:
    poses: list = field(default_factory=list)   # if the participant provides poses
    forces: list = field(default_factory=list)  # if it provides forces
    substeps: float = 0  # reported in the run file's /coupling/participants/<name>/substeps


class Solver(ABC):
    @abstractmethod
    def initialise(self, scene, name, poses, state):
        """Set up as participant `name` of `scene` (a Scene); `poses` are the bodies' at the
        start, `state` a list of floats when resuming, else None. Returns the Outputs at
        the start time."""

    @abstractmethod
    def advance(self, window, inputs):
        """From the state at window.t0, advance to exactly window.t1; returns Outputs."""

    @abstractmethod
    def state(self):
        """A list of floats holding everything needed to continue from here."""

    @abstractmethod
    def restore(self, state):
        """Go back to a state that state() returned."""
