"""The participant side of a run: handshake, then answer the coupler until Stop.

Rollback for implicit schemes happens here, as in coupler/participant/run_participant.cpp:
the state is saved at the start of every window (iteration 1) and restored before the
window is repeated (iteration > 1), so a solver need not know which scheme runs.
"""

import sys
import time
import traceback

from .connection import Aborted, Connection
from .scene import Scene
from .solver import Inputs, Window
from .wire import FORCE_WIDTH, POSE_WIDTH, Array, ProtocolError, Tag, Type

# The bits of Hello's provides and needs. Fields (4) are not offered: their messages
# (docs/protocol.md) are not implemented here.
DATA = {"poses": 1, "forces": 2}


def run(solver, provides=(), needs=()):
    """Serves the coupler that started this process with `solver` (a Solver); `provides` and
    `needs` name what it can exchange ("poses", "forces"). Returns the exit code: 0 after
    Stop, 1 after a failure (reported to the coupler and on stderr), 2 when the process was
    not started by cosim run."""
    unknown = (set(provides) | set(needs)) - DATA.keys()
    if unknown:
        raise ValueError(f"cannot exchange {', '.join(sorted(unknown))}: only {', '.join(DATA)}")
    connection = Connection.from_environment()
    if connection is None:
        print(f"{sys.argv[0]}: a cosim participant: start it through cosim run", file=sys.stderr)
        return 2
    try:
        return _serve(connection, solver, set(provides), set(needs))
    except Aborted as e:
        print(f"{connection.name}: {e}", file=sys.stderr)
        return 1
    except Exception as e:
        traceback.print_exc()
        connection.error(f"{type(e).__name__}: {e}")
        return 1
    finally:
        connection.close()


def _serve(connection, solver, provides, needs):
    connection.send(Type.HELLO, provides=_bits(provides), needs=_bits(needs))
    init = connection.receive(Type.INIT)
    texts = init.all(Tag.TEXT)
    if len(texts) != 2:
        raise ProtocolError("Init must carry the scene file and text")
    scene = Scene.parse(texts[0].text.decode(), texts[1].text.decode())
    poses = init.find(Tag.POSES)
    state = init.find(Tag.STATE)
    bodies = poses.rows
    outputs, wall = _timed(solver.initialise, scene, connection.name, poses.row_list(),
                           state.values if state else None)
    connection.send(Type.READY, _output_arrays(outputs, provides, bodies, wall))

    saved = None
    while True:
        m = connection.receive(Type.ADVANCE, Type.COMMIT, Type.CHECKPOINT, Type.STOP)
        h = m.header
        if h.type == Type.ADVANCE:
            if h.iteration > 1:
                solver.restore(saved)
            else:
                saved = solver.state()
            outputs, wall = _timed(solver.advance, Window(h.window, h.iteration, h.t0, h.t1),
                                   _inputs(m))
            connection.send(Type.RESULT, _output_arrays(outputs, provides, bodies, wall),
                            window=h.window, iteration=h.iteration)
        elif h.type == Type.CHECKPOINT:
            values = [float(v) for v in solver.state()]
            connection.send(Type.STATE, [Array(Tag.STATE, 1, len(values), values)])
        elif h.type == Type.STOP:
            connection.send(Type.BYE)
            return 0


def _bits(names):
    return sum(DATA[n] for n in names)


def _timed(call, *args):
    start = time.perf_counter()
    result = call(*args)
    return result, time.perf_counter() - start


def _inputs(advance):
    poses = [a.row_list() for a in advance.all(Tag.POSES)]
    forces = [a.row_list() for a in advance.all(Tag.FORCES)]
    return Inputs(*(poses or [[], []]), *(forces or [[], []]))


def _output_arrays(outputs, provides, bodies, wall):
    arrays = []
    for name, tag, width in (("poses", Tag.POSES, POSE_WIDTH), ("forces", Tag.FORCES, FORCE_WIDTH)):
        if name not in provides:
            continue
        rows = getattr(outputs, name)
        if len(rows) != bodies or any(len(row) != width for row in rows):
            raise ValueError(f"the solver returned {len(rows)} rows of {name}; the scene has "
                             f"{bodies} bodies, each a row of {width} values")
        arrays.append(Array(tag, bodies, width, [float(v) for row in rows for v in row]))
    arrays.append(Array(Tag.STATS, 1, 2, [float(outputs.substeps), wall]))
    return arrays
