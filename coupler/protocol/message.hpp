// The wire format between the coupler and its participants.
//
// A message is a ZeroMQ multipart message: frame 0 is a fixed, versioned, little-endian
// header (Header, then one ArrayInfo per payload array); frames 1..n are the raw payload
// arrays, float64 little-endian (or bytes for text). decode() validates everything it is
// given and throws ProtocolError with a clear message; it never trusts a size it read.
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <zmq.hpp>

namespace cosim::protocol {

inline constexpr std::uint32_t kMagic = 0x4d495343;  // "CSIM" read as little-endian u32
// 2: Points arrays, for the point sets of a Field message (field_message.hpp).
// 3: PointAttributes arrays, for the values per point of those sets (point_set_arrays.hpp).
// 4: Responses arrays, the response tensors a force provider may send with its forces.
inline constexpr std::uint16_t kVersion = 4;
// Each version only added arrays, so every version from the first is still read: a message
// of version v carries only arrays v had (rules::first_version), and the coupler answers each
// participant in the version of its Hello (Server::send), so a participant built for an
// earlier version runs unchanged until the scene needs an array its version lacks.
inline constexpr std::uint16_t kOldestVersion = 1;
inline constexpr std::size_t kNameSize = 32;  // participant name, NUL padded
inline constexpr std::size_t kMaxArrays = 64;

// Columns of the per-body arrays and of the stats row.
inline constexpr std::uint32_t kPoseWidth = 13;      // position, quaternion w x y z, velocity, angular velocity
inline constexpr std::uint32_t kForceWidth = 6;      // force, torque
inline constexpr std::uint32_t kResponseWidth = 78;  // added mass, added damping (6 x 6 each), hold (6)
inline constexpr std::uint32_t kStatsWidth = 2;      // substeps, wall seconds

struct ProtocolError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Type : std::uint16_t {
  Hello = 1,   // participant -> coupler: version, provides/needs, MPI size
  Init,        // coupler -> participant: scene text, its name, initial poses, restart state
  Ready,       // participant -> coupler: initial outputs (values at t0)
  Advance,     // coupler -> participant: inputs at the window end; subcycle to t1
  Result,      // participant -> coupler: outputs at t1 and stats
  Commit,      // coupler -> participant: the window is accepted
  Checkpoint,  // coupler -> participant: send your state
  State,       // participant -> coupler: opaque state array
  Field,       // either way: named grid fields
  Stop,        // coupler -> participant: finish cleanly
  Abort,       // coupler -> participant: the run failed, exit now
  Error,       // participant -> coupler: text of what went wrong
  Bye,         // participant -> coupler: acknowledges Stop
};

// What a payload array holds. Checked (NaN/Inf) where physics is expected.
enum class Tag : std::uint16_t {
  Poses = 1,        // n_bodies x 13: position(3), quaternion w,x,y,z(4), velocity(3), omega(3)
  Forces,           // n_bodies x 6: force(3), torque(3)
  Stats,            // 1 x 2: substeps, wall seconds of the work for this message
  State,            // 1 x n: opaque restart state of a participant
  Text,             // bytes (rows = 1, cols = length): YAML or an error message
  Field,            // rows x cols float64 named field; name in a preceding Text array
  Points,           // n x 3 float64: x, y, z of points, the point sets of a Field message
  PointAttributes,  // 1 x n float64: the values per point of those point sets' attributes
  Responses,        // n_bodies x 78: added mass, added damping (6 x 6 each, row-major), hold (6)
};

enum class DType : std::uint16_t { Float64 = 1, Bytes = 2 };

struct ArrayInfo {
  Tag tag;
  DType dtype;
  std::uint32_t rows;
  std::uint32_t cols;
};

struct Header {
  Type type{};
  std::string participant;      // at most kNameSize - 1 bytes
  std::uint64_t window = 0;     // index of the coupling window [t0, t1]
  std::uint32_t iteration = 0;  // implicit-coupling iteration within the window, from 1
  double t0 = 0.0;
  double t1 = 0.0;
  std::uint32_t provides = 0;        // Hello: bit set of scene::Data
  std::uint32_t needs = 0;           // Hello: bit set of scene::Data
  std::uint32_t ranks = 1;           // Hello: MPI size of the participant
  std::uint16_t version = kVersion;  // the protocol version the message is written in
};

// A payload array: float64 values (row-major) or bytes.
struct Array {
  Tag tag;
  std::uint32_t rows = 0;
  std::uint32_t cols = 0;
  std::vector<double> values;  // Float64 arrays
  std::string bytes;           // Bytes arrays

  static Array of(Tag tag, std::uint32_t rows, std::uint32_t cols, std::vector<double> values);
  static Array text(std::string_view s);
};

struct Message {
  Header header;
  std::vector<Array> arrays;

  const Array* find(Tag tag) const;              // first array with this tag, or nullptr
  const Array& get(Tag tag) const;               // throws ProtocolError if missing
  std::vector<const Array*> all(Tag tag) const;  // every array with this tag, in order
};

// Header frame + one frame per array. The encoder copies once into each frame and applies
// the decoder's rules first, so an invalid message fails at its sender.
std::vector<zmq::message_t> encode(const Message& m);
// The same for a header and arrays kept apart (sending one payload under another name).
std::vector<zmq::message_t> encode(const Header& header, std::span<const Array> arrays);
// Validates magic, version (kOldestVersion to kVersion), type, name, frame count, sizes against the header, dtype,
// and finite values in Poses/Forces/Stats arrays.
Message decode(std::span<const zmq::message_t> frames);
// Same checks on raw buffers (used by the fuzz test and the decoder itself).
Message decode(std::span<const std::span<const std::byte>> frames);

// Throws ProtocolError unless name is 1 to kNameSize - 1 characters of [A-Za-z0-9_.-].
void check_participant_name(std::string_view name);

const char* to_string(Type);
const char* to_string(Tag);

}  // namespace cosim::protocol
