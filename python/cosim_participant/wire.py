"""The coupler's messages as bytes: docs/protocol.md, mirrored from coupler/protocol/.

Frame 0 is an 84-byte little-endian header plus a 12-byte descriptor per array; frames
1..n are the arrays' bytes. encode() and decode() apply the coupler's own checks, so a bad
message fails where it is made, with a message that says why.
"""

import math
import re
import struct
import sys
from array import array
from dataclasses import dataclass, field
from enum import IntEnum

MAGIC = 0x4D495343  # "CSIM"
VERSION = 4
NAME_SIZE = 32  # NUL-padded, so at most 31 characters
MAX_ARRAYS = 64
MAX_ELEMENTS = 1 << 31
POSE_WIDTH = 13  # position, quaternion w x y z, velocity, angular velocity
FORCE_WIDTH = 6  # force, torque
RESPONSE_WIDTH = 78  # added mass, added damping (6 x 6 each, row-major), hold (6)
STATS_WIDTH = 2  # substeps, wall seconds

_HEADER = struct.Struct("<IHH32sQIIIIddI")  # magic .. array count
_DESCRIPTOR = struct.Struct("<HHII")  # tag, dtype, rows, cols
_NAME = re.compile(r"[A-Za-z0-9_.-]{1,31}")


class ProtocolError(Exception):
    """A message that breaks the protocol, or one from a coupler that does."""


class Type(IntEnum):
    HELLO = 1
    INIT = 2
    READY = 3
    ADVANCE = 4
    RESULT = 5
    COMMIT = 6
    CHECKPOINT = 7
    STATE = 8
    FIELD = 9
    STOP = 10
    ABORT = 11
    ERROR = 12
    BYE = 13


class Tag(IntEnum):
    POSES = 1
    FORCES = 2
    STATS = 3
    STATE = 4
    TEXT = 5
    FIELD = 6
    POINTS = 7
    POINT_ATTRIBUTES = 8
    RESPONSES = 9


class DType(IntEnum):
    FLOAT64 = 1
    BYTES = 2


_COLUMNS = {Tag.POSES: POSE_WIDTH, Tag.FORCES: FORCE_WIDTH, Tag.RESPONSES: RESPONSE_WIDTH, Tag.STATS: STATS_WIDTH,
            Tag.POINTS: 3}
_FINITE = (Tag.POSES, Tag.FORCES, Tag.RESPONSES, Tag.STATS)


@dataclass
class Array:
    """rows x cols float64 values, row-major (a flat list), or the bytes of a Text array."""

    tag: Tag
    rows: int
    cols: int
    values: list = field(default_factory=list)
    text: bytes = b""

    @staticmethod
    def of_text(text):
        data = text.encode() if isinstance(text, str) else bytes(text)
        return Array(Tag.TEXT, 1, len(data), text=data)

    def row_list(self):
        """The values as a list of rows."""
        return [self.values[r * self.cols:(r + 1) * self.cols] for r in range(self.rows)]


@dataclass
class Header:
    type: Type
    participant: str
    window: int = 0
    iteration: int = 0
    provides: int = 0
    needs: int = 0
    ranks: int = 1
    t0: float = 0.0
    t1: float = 0.0


@dataclass
class Message:
    header: Header
    arrays: list = field(default_factory=list)

    def all(self, tag):
        return [a for a in self.arrays if a.tag == tag]

    def find(self, tag):
        """The first array with this tag, or None."""
        return next((a for a in self.arrays if a.tag == tag), None)


def check_name(name):
    if not _NAME.fullmatch(name):
        raise ProtocolError(f"participant name {name!r} must be 1 to {NAME_SIZE - 1} "
                            "letters, digits, '_', '.' or '-'")


def _check_header(h):
    if h.type not in Type.__members__.values():
        raise ProtocolError(f"unknown message type {int(h.type)}")
    check_name(h.participant)
    if not (math.isfinite(h.t0) and math.isfinite(h.t1) and h.t0 <= h.t1):
        raise ProtocolError(f"{Type(h.type).name} message has an invalid time span [{h.t0}, {h.t1}]")
    if h.type == Type.HELLO and h.ranks < 1:
        raise ProtocolError("Hello announces 0 ranks")


def _dtype(tag):
    if tag not in Tag.__members__.values():
        raise ProtocolError(f"unknown array tag {int(tag)}")
    return DType.BYTES if tag == Tag.TEXT else DType.FLOAT64


def _check_shape(index, tag, rows, cols):
    label = f"array {index} ({Tag(tag).name})"
    if tag in _COLUMNS and cols != _COLUMNS[tag]:
        raise ProtocolError(f"{label} has {cols} columns, expected {_COLUMNS[tag]}")
    if tag in (Tag.STATS, Tag.TEXT) and rows != 1:
        raise ProtocolError(f"{label} has {rows} rows, expected 1")
    if rows * cols > MAX_ELEMENTS:
        raise ProtocolError(f"{label} of {rows} x {cols} elements is larger than {MAX_ELEMENTS}")


def _check_values(index, a):
    if a.tag in _FINITE:
        for i, v in enumerate(a.values):
            if not math.isfinite(v):
                raise ProtocolError(f"array {index} ({a.tag.name}) holds {v} at row "
                                    f"{i // a.cols}, column {i % a.cols}")


def _float64_bytes(values):
    a = array("d", values)
    if sys.byteorder == "big":
        a.byteswap()
    return a.tobytes()


def _float64_values(data):
    a = array("d")
    a.frombytes(data)
    if sys.byteorder == "big":
        a.byteswap()
    return a.tolist()


def encode(m):
    """The frames of m: the header, then one frame per array."""
    h = m.header
    _check_header(h)
    if len(m.arrays) > MAX_ARRAYS:
        raise ProtocolError(f"message has {len(m.arrays)} arrays, at most {MAX_ARRAYS} are allowed")
    head = [_HEADER.pack(MAGIC, VERSION, h.type, h.participant.encode(), h.window, h.iteration,
                         h.provides, h.needs, h.ranks, h.t0, h.t1, len(m.arrays))]
    payloads = []
    for i, a in enumerate(m.arrays):
        dtype = _dtype(a.tag)
        _check_shape(i, a.tag, a.rows, a.cols)
        held = len(a.text) if dtype == DType.BYTES else len(a.values)
        if held != a.rows * a.cols:
            raise ProtocolError(f"array {i} ({a.tag.name}) of {a.rows} x {a.cols} holds {held} elements")
        _check_values(i, a)
        head.append(_DESCRIPTOR.pack(a.tag, dtype, a.rows, a.cols))
        payloads.append(a.text if dtype == DType.BYTES else _float64_bytes(a.values))
    return [b"".join(head)] + payloads


def _read_name(raw):
    name, nul, padding = raw.partition(b"\0")
    if not nul:
        raise ProtocolError("participant name is not NUL-terminated")
    if padding.strip(b"\0"):
        raise ProtocolError("participant name is followed by bytes other than NUL")
    return name.decode("ascii", errors="replace")


def decode(frames):
    """A Message from its frames (bytes), after every check the coupler makes."""
    if not frames:
        raise ProtocolError("empty message: no header frame")
    head = bytes(frames[0])
    if len(head) < 8:
        raise ProtocolError(f"header frame of {len(head)} bytes is too short for a cosim message")
    magic, version = struct.unpack_from("<IH", head)
    if magic != MAGIC:
        raise ProtocolError(f"not a cosim message (magic {magic:#x}, expected {MAGIC:#x})")
    if version != VERSION:
        raise ProtocolError(f"protocol version {version}, this module speaks {VERSION}")
    if len(head) < _HEADER.size:
        raise ProtocolError(f"header frame of {len(head)} bytes is too short")
    (_, _, kind, name, window, iteration, provides, needs, ranks, t0, t1,
     n) = _HEADER.unpack_from(head)
    h = Header(kind, _read_name(name), window, iteration, provides, needs, ranks, t0, t1)
    _check_header(h)
    h.type = Type(kind)
    if n > MAX_ARRAYS:
        raise ProtocolError(f"header announces {n} arrays, at most {MAX_ARRAYS} are allowed")
    if len(head) != _HEADER.size + n * _DESCRIPTOR.size:
        raise ProtocolError(f"header frame of {len(head)} bytes does not fit its {n} arrays")
    if len(frames) != 1 + n:
        raise ProtocolError(f"message has {len(frames)} frames, its header announces {n} arrays")
    m = Message(h)
    for i in range(n):
        tag, dtype, rows, cols = _DESCRIPTOR.unpack_from(head, _HEADER.size + i * _DESCRIPTOR.size)
        if dtype != _dtype(tag):
            raise ProtocolError(f"array {i} ({Tag(tag).name}) has dtype {dtype}, which this tag never uses")
        tag = Tag(tag)
        _check_shape(i, tag, rows, cols)
        data = bytes(frames[1 + i])
        width = 1 if dtype == DType.BYTES else 8
        if len(data) != rows * cols * width:
            raise ProtocolError(f"array {i} ({tag.name}) of {rows} x {cols} needs "
                                f"{rows * cols * width} bytes, its frame has {len(data)}")
        if dtype == DType.BYTES:
            m.arrays.append(Array(tag, rows, cols, text=data))
        else:
            m.arrays.append(Array(tag, rows, cols, _float64_values(data)))
            _check_values(i, m.arrays[-1])
    return m
