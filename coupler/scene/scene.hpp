// The scene: one YAML file describes a whole run. Every program reads it through
// load_scene(), so a key means the same thing everywhere and a typo is caught once.
// Units are SI throughout (m, kg, s, N, Pa).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "coupler/coupling/acceleration_kind.hpp"

namespace cosim::scene {

using Vec3 = std::array<double, 3>;
using Quat = std::array<double, 4>;  // w, x, y, z

enum class Scheme { SerialExplicit, ParallelExplicit, SerialImplicit, ParallelImplicit };
constexpr bool is_serial(Scheme s) { return s == Scheme::SerialExplicit || s == Scheme::SerialImplicit; }
constexpr bool is_implicit(Scheme s) { return s == Scheme::SerialImplicit || s == Scheme::ParallelImplicit; }
using coupling::Acceleration;
enum class Transport { Ipc, Tcp };

// What a participant puts on the wire or takes from it.
enum class Data : std::uint32_t { Poses = 1u << 0, Forces = 1u << 1, Fields = 1u << 2 };
using DataSet = std::uint32_t;  // bit set of Data
constexpr bool has(DataSet set, Data d) { return (set & static_cast<std::uint32_t>(d)) != 0; }

enum class Effect { Gravity, Buoyancy, Hydrodynamics, Contact, Friction, RarefiedGas, Tracers };

struct Time {
  double end = 0.0;
};

struct Coupling {
  double window = 0.0;  // coupling window length W [s]
  Scheme scheme = Scheme::SerialImplicit;
  Acceleration acceleration = Acceleration::IqnIls;
  double relaxation = 0.5;  // constant factor, or Aitken's first factor
  int max_iterations = 50;
  double tolerance =
      1e-6;  // change of the exchanged data per iteration, relative to the larger of their start and end values
  // [N and N m] converged too when the forces change by at most this much: bodies at rest
  // feel forces that fade towards the fluid solver's round-off. 0: the relative test only.
  double force_tolerance = 0.0;
  Transport transport = Transport::Ipc;
  // tcp: the network interface ("ib0") or local address the coupler listens on, so that
  // participants on other hosts reach it; empty: 127.0.0.1.
  std::string interface;
  double timeout = 60.0;  // seconds a participant may take to answer
  // Seconds without an answer to ZMTP heartbeats after which a participant's connection
  // counts as lost: a host that died leaves no process to watch.
  double heartbeat = 10.0;
};

struct Output {
  std::string file = "run.h5";  // relative to the working directory
  int every = 1;                // write body series every N windows
  int checkpoint_every = 10;    // checkpoint every N windows
  int fields_every = 10;        // grid fields at t = 0, every N windows and the last; 0: none
  // Whether the state after `done` of `windows` windows is written: every N-th and the last
  // (done = 0, the start, is a multiple of every N).
  bool row_at(std::uint64_t done, std::uint64_t windows) const { return at(every, done, windows); }
  bool checkpoint_at(std::uint64_t done, std::uint64_t windows) const { return at(checkpoint_every, done, windows); }
  bool fields_at(std::uint64_t done, std::uint64_t windows) const {
    return fields_every > 0 && at(fields_every, done, windows);
  }

 private:
  static bool at(int every_n, std::uint64_t done, std::uint64_t windows) {
    return done % static_cast<std::uint64_t>(every_n) == 0 || done == windows;
  }
};

struct Domain {
  Vec3 min{};
  Vec3 max{};
};

enum class ShapeType { Sphere, Ellipsoid, Box, Cylinder, Capsule, Plane, Mesh };

struct Shape {
  ShapeType type = ShapeType::Sphere;
  double radius = 0.0;         // sphere, cylinder, capsule
  Vec3 radii{};                // ellipsoid semi-axes
  Vec3 half_extents{};         // box
  double height = 0.0;         // cylinder, capsule: length of the axis (body z)
  Vec3 normal{0, 0, 1};        // plane: outward normal, through the body position
  std::filesystem::path file;  // mesh: STL or OBJ, resolved against the scene dir
  // The body is the solid outside the shape, whose inside holds the fluid and the other
  // bodies (a round column, a pipe); convex shapes of a fixed body only.
  bool container = false;
  bool operator==(const Shape&) const = default;
};

struct Material {
  double density = 0.0;  // kg/m^3
  double restitution = 0.0;
  double friction = 0.0;  // Coulomb coefficient
};

struct Body {
  std::string name;
  Shape shape;
  Material material;
  bool fixed = false;
  Vec3 position{};
  Quat orientation{1, 0, 0, 0};
  Vec3 velocity{};
  Vec3 angular_velocity{};
  int material_line = 0;  // 1-based line of `material` (of the entry if absent), for warnings
};

enum class Generator { Lattice, Random, File };

// An entry of `bodies` that made its bodies by a rule (`generate:`) instead of naming one,
// for reports such as `cosim check`.
struct BodyGenerator {
  std::size_t entry = 0;  // index in the scene file's `bodies` list
  Generator kind = Generator::Lattice;
  std::size_t first = 0;  // its bodies: bodies[first] to bodies[first + count - 1]
  std::size_t count = 0;
};

// Where a participant's ranks run. None given: on the coupler's host. Any of them starts
// the ranks with mpirun or, inside a Slurm allocation, srun (launcher/placement.hpp).
struct Placement {
  std::vector<std::string> hosts;  // on these hosts
  std::filesystem::path hostfile;  // on the hosts this file lists (resolved against the scene dir)
  int het_group = -1;              // in this component of a Slurm heterogeneous job
  bool scheduler = false;          // wherever the batch scheduler puts them (hosts: scheduler)
  bool local() const { return hosts.empty() && hostfile.empty() && het_group < 0 && !scheduler; }
};

// One section per participant. The built-in programs are `rigidbody`, `fluid` and
// `tracker`; any other name is an external program that speaks the protocol and must say
// what it provides and needs. `options` is passed verbatim to the program, which validates
// it through the same Reader (so its errors name file, line and key too).
struct Participant {
  std::string name;
  std::vector<std::string> command;  // empty: the built-in program of that name
  int ranks = 1;                     // > 1: started under mpirun -n ranks
  Placement placement;
  double dt = 0.0;  // its own time step; subcycles to the window end
  DataSet provides = 0;
  DataSet needs = 0;
  YAML::Node options;  // program-specific keys
  int line = 0;        // 1-based line of the section in the scene file
};

// A quantity `cosim study` measures on every level (docs/study.md), as written: the
// expression is coupler/study's to parse, so every program accepts a scene that carries one.
struct StudyMeasure {
  std::string name;
  std::string expression;
  int line = 0;  // 1-based line of the name, for errors about the expression
};

// `study:`, read by `cosim study` only.
struct Study {
  std::vector<StudyMeasure> measures;  // in file order
  std::optional<double> order;         // the order the scene's resolution is expected to converge with
};

struct Scene {
  std::filesystem::path file;  // where it was read from ("<string>" if not a file)
  // Where relative file names in the scene (meshes, balls, tracer fields, hostfiles) are
  // found: the key `folder` (relative to the scene file's folder), or the scene file's
  // folder. `cosim study` sets it in the levels it writes elsewhere.
  std::filesystem::path folder;
  std::string text;  // the YAML exactly as read, stored in every run file
  Time time;
  Coupling coupling;
  Output output;
  Vec3 gravity{0, 0, -9.81};
  Domain domain;
  std::vector<Body> bodies;
  std::vector<BodyGenerator> generators;  // in file order
  std::vector<Effect> effects;
  int effects_line = 0;                   // 1-based line of `effects`: plan errors about effects point here
  std::vector<Participant> participants;  // in file order
  Study study;

  bool has_effect(Effect e) const;
  const Participant* participant(const std::string& name) const;
  std::size_t windows() const;                  // time.end / coupling.window, exact by validation
  std::vector<std::string> body_names() const;  // in body order, as the run file's rows
};

// Reads and validates. Throws SceneError (see error.hpp) naming file, line, key and value.
Scene load_scene(const std::filesystem::path& file);
Scene load_scene_from_string(const std::string& text, const std::filesystem::path& file = "<string>");

const char* to_string(Scheme);
const char* to_string(Acceleration);
const char* to_string(Effect);
const char* to_string(Generator);
std::string describe(DataSet set);  // "poses, forces", or "nothing"

}  // namespace cosim::scene
