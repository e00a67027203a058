"""A cosim participant in Python: implement a Solver, then sys.exit(run(solver, ...)).

See python/README.md; the messages are those of docs/protocol.md.
"""

from .run import run
from .scene import Scene
from .solver import Inputs, Outputs, Solver, Window
from .wire import ProtocolError

__all__ = ["Inputs", "Outputs", "ProtocolError", "Scene", "Solver", "Window", "run"]
