// Socket plumbing shared by the two ends of the protocol.
#pragma once

#include <chrono>
#include <vector>

#include <zmq.hpp>

namespace cosim::protocol::socket {

// Queues are bounded by the request/answer protocol itself, so no high-water mark can
// drop or block a message; linger bounds how long closing waits for unsent messages.
void configure(zmq::socket_t& s, std::chrono::milliseconds linger);

// True when a message is waiting. False on timeout, and also when a signal interrupted
// the wait, so that a caller with a Ctrl-C handler gets to look at its flag.
bool readable(zmq::socket_t& s, std::chrono::milliseconds timeout);

// All frames of the next message; call after readable() returned true.
std::vector<zmq::message_t> receive(zmq::socket_t& s);

}  // namespace cosim::protocol::socket
