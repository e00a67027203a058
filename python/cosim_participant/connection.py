"""The participant's end of the coupler's socket: one DEALER whose identity is its name."""

import os

import zmq

from .wire import Array, Header, Message, ProtocolError, Tag, Type, check_name, decode, encode

ENDPOINT_ENV = "COSIM_ENDPOINT"
PARTICIPANT_ENV = "COSIM_PARTICIPANT"
# Over tcp the coupler hands each participant CURVE keys made for the run (docs/security.md).
CURVE_ENV = ("COSIM_CURVE_SERVER_KEY", "COSIM_CURVE_PUBLIC_KEY", "COSIM_CURVE_SECRET_KEY")
LINGER_MS = 1000  # long enough for a last Bye or Error to leave, short enough that exit never hangs


class Aborted(Exception):
    """The coupler sent Abort: the run failed elsewhere, exit now."""


class Connection:
    def __init__(self, endpoint, name, curve_keys=None):
        """curve_keys: (the coupler's public key, own public key, own secret key), Z85 text."""
        check_name(name)
        self.name = name
        self._context = zmq.Context()
        self._socket = self._context.socket(zmq.DEALER)
        # The coupler checks that every header names the identity the message came from.
        self._socket.setsockopt(zmq.ROUTING_ID, name.encode())
        self._socket.setsockopt(zmq.LINGER, LINGER_MS)
        self._socket.setsockopt(zmq.SNDHWM, 0)
        self._socket.setsockopt(zmq.RCVHWM, 0)
        self._socket.setsockopt(zmq.IPV6, 1)
        if curve_keys:
            server, public, secret = (key.encode() for key in curve_keys)
            self._socket.curve_serverkey = server
            self._socket.curve_publickey = public
            self._socket.curve_secretkey = secret
        self._socket.connect(endpoint)

    @staticmethod
    def from_environment():
        """The connection `cosim run` set up for this process, or None if it did not start it."""
        endpoint, name = os.environ.get(ENDPOINT_ENV), os.environ.get(PARTICIPANT_ENV)
        if endpoint is None and name is None:
            return None
        if endpoint is None or name is None:
            raise ProtocolError(f"{ENDPOINT_ENV} and {PARTICIPANT_ENV} must be set together")
        keys = [os.environ.get(k) for k in CURVE_ENV]
        if any(keys) and not all(keys):
            raise ProtocolError(f"{', '.join(CURVE_ENV)} must be set together")
        return Connection(endpoint, name, keys if all(keys) else None)

    def send(self, kind, arrays=(), **fields):
        self._socket.send_multipart(encode(Message(Header(kind, self.name, **fields), list(arrays))))

    def receive(self, *kinds):
        """The coupler's next message, which must be of one of `kinds`; Abort raises Aborted."""
        m = decode(self._socket.recv_multipart())
        if m.header.type in kinds:
            return m
        if m.header.type == Type.ABORT:
            why = m.find(Tag.TEXT)
            raise Aborted("the coupler aborted the run" + (": " + why.text.decode() if why else ""))
        raise ProtocolError(f"expected {' or '.join(k.name for k in kinds)} from the coupler "
                            f"and received {m.header.type.name}")

    def error(self, text):
        """Reports a failure; the coupler shows it to the user with this participant's name."""
        self.send(Type.ERROR, [Array.of_text(text)])

    def close(self):
        self._socket.close()
        self._context.term()
