#include "coupler/participant/mpi_team.hpp"

#include <array>
#include <climits>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "coupler/protocol/field_message.hpp"

namespace cosim::participant {
namespace {

enum Call : int { kInitialise, kAdvance, kState, kRestore, kFields, kFinish };

int rank_of(MPI_Comm comm) {
  int r = 0;
  MPI_Comm_rank(comm, &r);
  return r;
}

int size_of(MPI_Comm comm) {
  int n = 0;
  MPI_Comm_size(comm, &n);
  return n;
}

int count(std::size_t n) {
  if (n > static_cast<std::size_t>(INT_MAX)) throw std::length_error("more values than MPI can count in one call");
  return static_cast<int>(n);
}

// Rank 0's value to every rank.
template <typename T>
void share(MPI_Comm comm, T& value) {
  MPI_Bcast(&value, sizeof(T), MPI_BYTE, 0, comm);
}

// A vector or string from rank 0 (send) to the others (receive). MPI_Bcast only reads the
// root's buffer, so the lead sends its callers' values as they are, without a copy.
template <typename Values>
void send(MPI_Comm comm, const Values& values) {
  unsigned long long n = values.size();
  share(comm, n);
  MPI_Bcast(const_cast<typename Values::value_type*>(values.data()), count(n * sizeof(values[0])), MPI_BYTE, 0, comm);
}

template <typename Values>
void receive(MPI_Comm comm, Values& values) {
  unsigned long long n = 0;
  share(comm, n);
  values.resize(n);
  MPI_Bcast(values.data(), count(n * sizeof(values[0])), MPI_BYTE, 0, comm);
}

// Forwarded fields cross as the arrays of the wire (field_message.hpp): none, no arrays.
void send(MPI_Comm comm, const std::optional<field::FieldFrame>& fields) {
  const std::vector<protocol::Array> arrays = fields ? protocol::field_arrays(*fields) : std::vector<protocol::Array>{};
  unsigned long long n = arrays.size();
  share(comm, n);
  for (const protocol::Array& a : arrays) {
    std::array<std::uint32_t, 3> shape{static_cast<std::uint32_t>(a.tag), a.rows, a.cols};
    share(comm, shape);
    send(comm, a.values);
    send(comm, a.bytes);
  }
}

std::optional<field::FieldFrame> receive_fields(MPI_Comm comm) {
  unsigned long long n = 0;
  share(comm, n);
  if (n == 0) return std::nullopt;
  std::vector<protocol::Array> arrays(n);
  for (protocol::Array& a : arrays) {
    std::array<std::uint32_t, 3> shape{};
    share(comm, shape);
    a.tag = static_cast<protocol::Tag>(shape[0]);
    a.rows = shape[1];
    a.cols = shape[2];
    receive(comm, a.values);
    receive(comm, a.bytes);
  }
  return protocol::field_frame(std::move(arrays), "the fields from rank 0");
}

// The per-rank sizes a gathered state announces, checked against this run's rank count
// before anything is announced, so a refusal leaves the followers waiting for the next call.
std::vector<int> state_sizes(const std::vector<double>& whole, int ranks) {
  if (whole.empty()) return std::vector<int>(static_cast<std::size_t>(ranks), 0);
  const auto written = static_cast<long long>(whole.front());
  if (written != ranks)
    throw std::runtime_error("the state was written by " + std::to_string(written) + " ranks, this run has " +
                             std::to_string(ranks) + ": resume on " + std::to_string(written));
  std::vector<int> sizes;
  std::size_t total = 1 + static_cast<std::size_t>(ranks);
  if (whole.size() < total) throw std::runtime_error("the state is shorter than its own header");
  for (int r = 0; r < ranks; ++r) {
    sizes.push_back(count(static_cast<std::size_t>(whole[1 + static_cast<std::size_t>(r)])));
    total += static_cast<std::size_t>(sizes.back());
  }
  if (whole.size() != total)
    throw std::runtime_error("the state holds " + std::to_string(whole.size()) + " values, its header says " +
                             std::to_string(total));
  return sizes;
}

// This rank's part of the state rank 0 holds whole (`sizes` from state_sizes(), rank 0 only).
std::vector<double> scattered(MPI_Comm comm, const std::vector<double>& whole, const std::vector<int>& sizes) {
  const int ranks = size_of(comm);
  std::vector<int> offsets;
  int at = 1 + ranks;
  for (int s : sizes) {
    offsets.push_back(at);
    at += s;
  }
  int mine = 0;
  MPI_Scatter(sizes.data(), 1, MPI_INT, &mine, 1, MPI_INT, 0, comm);
  std::vector<double> part(static_cast<std::size_t>(mine));
  MPI_Scatterv(whole.data(), sizes.data(), offsets.data(), MPI_DOUBLE, part.data(), mine, MPI_DOUBLE, 0, comm);
  return part;
}

// Every rank's state, whole on rank 0 (empty elsewhere).
std::vector<double> gathered(MPI_Comm comm, const std::vector<double>& part) {
  const int ranks = size_of(comm);
  const bool root = rank_of(comm) == 0;
  const int mine = count(part.size());
  std::vector<int> sizes(root ? static_cast<std::size_t>(ranks) : 0);
  MPI_Gather(&mine, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, comm);
  std::vector<double> whole;
  std::vector<int> offsets;
  if (root) {
    whole.push_back(ranks);
    int at = 1 + ranks;
    for (int s : sizes) {
      whole.push_back(s);
      offsets.push_back(at);
      at += s;
    }
    whole.resize(static_cast<std::size_t>(at));
  }
  MPI_Gatherv(part.data(), mine, MPI_DOUBLE, whole.data(), sizes.data(), offsets.data(), MPI_DOUBLE, 0, comm);
  return whole;
}

// Rows cross as their wire values.
template <class Row>
void send_rows(MPI_Comm comm, const std::vector<Row>& rows) {
  send(comm, values_of(rows));
}

template <class Row>
std::vector<Row> receive_rows(MPI_Comm comm, std::vector<Row> (*rows_of)(std::span<const double>)) {
  std::vector<double> values;
  receive(comm, values);
  return rows_of(values);
}

void initialise_follower(Solver& local, MPI_Comm comm) {
  std::string text, file, name;
  receive(comm, text);
  receive(comm, file);
  receive(comm, name);
  const std::vector<PoseRow> poses = receive_rows(comm, pose_rows);
  const std::vector<double> state = scattered(comm, {}, {});
  local.initialise(scene::load_scene_from_string(text, file), name, poses, state);
}

void advance_follower(Solver& local, MPI_Comm comm) {
  Window w;
  Inputs in;
  share(comm, w);
  in.poses_start = receive_rows(comm, pose_rows);
  in.poses_end = receive_rows(comm, pose_rows);
  in.forces_start = receive_rows(comm, force_rows);
  in.forces_end = receive_rows(comm, force_rows);
  in.fields = receive_fields(comm);
  local.advance(w, in);
}

}  // namespace

LeadSolver::LeadSolver(Solver& local, MPI_Comm comm) : local_(local), comm_(comm) {}

LeadSolver::~LeadSolver() {
  if (!finished_) finish(1);
}

void LeadSolver::announce(int call) const { MPI_Bcast(&call, 1, MPI_INT, 0, comm_); }

Outputs LeadSolver::initialise(const scene::Scene& scene, const std::string& name, const std::vector<PoseRow>& poses,
                               const std::vector<double>& state) {
  const std::vector<int> sizes = state_sizes(state, size_of(comm_));
  announce(kInitialise);
  send(comm_, scene.text);
  send(comm_, scene.file.string());
  send(comm_, name);
  send_rows(comm_, poses);
  return local_.initialise(scene, name, poses, scattered(comm_, state, sizes));
}

Outputs LeadSolver::advance(const Window& w, const Inputs& in) {
  announce(kAdvance);
  Window shared = w;
  share(comm_, shared);
  send_rows(comm_, in.poses_start);
  send_rows(comm_, in.poses_end);
  send_rows(comm_, in.forces_start);
  send_rows(comm_, in.forces_end);
  send(comm_, in.fields);
  return local_.advance(w, in);
}

std::vector<double> LeadSolver::state() const {
  announce(kState);
  return gathered(comm_, local_.state());
}

void LeadSolver::restore(const std::vector<double>& state) {
  const std::vector<int> sizes = state_sizes(state, size_of(comm_));
  announce(kRestore);
  local_.restore(scattered(comm_, state, sizes));
}

std::vector<std::string> LeadSolver::wanted_fields() const { return local_.wanted_fields(); }

field::FieldFrame LeadSolver::fields() const {
  announce(kFields);
  return local_.fields();
}

void LeadSolver::finish(int exit_code) {
  announce(kFinish);
  share(comm_, exit_code);
  finished_ = true;
}

int follow(Solver& local, MPI_Comm comm) {
  for (;;) {
    int call = kFinish;
    MPI_Bcast(&call, 1, MPI_INT, 0, comm);
    try {
      switch (call) {
        case kInitialise:
          initialise_follower(local, comm);
          break;
        case kAdvance:
          advance_follower(local, comm);
          break;
        case kState:
          gathered(comm, local.state());
          break;
        case kRestore:
          local.restore(scattered(comm, {}, {}));
          break;
        case kFields:
          local.fields();
          break;
        default: {
          int code = 1;
          share(comm, code);
          return code;
        }
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "rank %d: %s\n", rank_of(comm), e.what());
      MPI_Abort(comm, 1);
    }
  }
}

int run_on_ranks(Solver& local, MPI_Comm comm, const std::function<int(Solver&)>& lead) {
  if (rank_of(comm) != 0) return follow(local, comm);
  LeadSolver solver(local, comm);  // if `lead` throws, its destructor releases the followers
  const int code = lead(solver);
  solver.finish(code);
  return code;
}

}  // namespace cosim::participant
