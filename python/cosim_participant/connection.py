"""The participant's end of the coupler's socket: one DEALER whose identity is its name."""

import os

import zmq

from .wire import Array, Header, Message, ProtocolError, Tag, Type, check_name, decode, encode

ENDPOINT_ENV = "COSIM_ENDPOINT"
PARTICIPANT_ENV = "COSIM_PARTICIPANT"
# Seconds of the scene's coupling.heartbeat: how long to wait for an answer to the heartbeats
# before the coupler counts as gone.
HEARTBEAT_ENV = "COSIM_HEARTBEAT"
# Over tcp the coupler hands each participant CURVE keys made for the run (docs/security.md).
CURVE_ENV = ("COSIM_CURVE_SERVER_KEY", "COSIM_CURVE_PUBLIC_KEY", "COSIM_CURVE_SECRET_KEY")
LINGER_MS = 1000  # long enough for a last Bye or Error to leave, short enough that exit never hangs


class Aborted(Exception):
    """The coupler sent Abort: the run failed elsewhere, exit now."""


class Connection:
    def __init__(self, endpoint, name, curve_keys=None, heartbeat=0.0):
        """curve_keys: (the coupler's public key, own public key, own secret key), Z85 text.
        heartbeat: seconds; a ping every half of it, and the connection dropped when half of it
        passes without an answer, as the coupler does on its side."""
        check_name(name)
        self.name, self.endpoint, self.heartbeat = name, endpoint, heartbeat
        self._context = zmq.Context()
        self._socket = self._context.socket(zmq.DEALER)
        # The coupler checks that every header names the identity the message came from.
        self._socket.setsockopt(zmq.ROUTING_ID, name.encode())
        self._socket.setsockopt(zmq.LINGER, LINGER_MS)
        self._socket.setsockopt(zmq.SNDHWM, 0)
        self._socket.setsockopt(zmq.RCVHWM, 0)
        self._socket.setsockopt(zmq.IPV6, 1)
        if heartbeat > 0:
            half = max(1, int(heartbeat * 500))
            self._socket.setsockopt(zmq.HEARTBEAT_IVL, half)
            self._socket.setsockopt(zmq.HEARTBEAT_TIMEOUT, half)
        # Watched from before the first connection, so that no end of it goes unseen.
        self._events = self._socket.get_monitor_socket(zmq.EVENT_DISCONNECTED)
        self._poller = zmq.Poller()
        self._poller.register(self._socket, zmq.POLLIN)
        self._poller.register(self._events, zmq.POLLIN)
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
        heartbeat = os.environ.get(HEARTBEAT_ENV)
        try:
            seconds = float(heartbeat) if heartbeat is not None else 0.0
        except ValueError:
            seconds = -1.0
        if heartbeat is not None and not 0 < seconds <= 1e6:
            raise ProtocolError(f"{HEARTBEAT_ENV} = {heartbeat!r}: expected seconds > 0")
        return Connection(endpoint, name, keys if all(keys) else None, seconds)

    def send(self, kind, arrays=(), **fields):
        self._socket.send_multipart(encode(Message(Header(kind, self.name, **fields), list(arrays))))

    def receive(self, *kinds):
        """The coupler's next message, which must be of one of `kinds`; Abort raises Aborted; a
        connection to the coupler that ended (the coupler or its host gone) raises
        ProtocolError naming the coupler."""
        while True:
            ready = dict(self._poller.poll())
            if self._socket in ready:
                break
            if self._events in ready:
                self._events.recv_multipart()
                silent = (f", or it answered no heartbeat for {self.heartbeat / 2:g} s (coupling.heartbeat)"
                          if self.heartbeat > 0 else "")
                raise ProtocolError(f"participant '{self.name}' lost the coupler at {self.endpoint}: the connection "
                                    f"closed{silent}")
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
        self._socket.disable_monitor()
        self._events.close()
        self._socket.close()
        self._context.term()
