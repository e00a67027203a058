// The ranks one gas is spread over (tracker/parallel/README.md). A default Ranks is one
// rank and makes no MPI call, so the libraries and their tests run without MPI_Init.
#pragma once

#include <mpi.h>

#include <functional>
#include <span>
#include <vector>

namespace cosim::tracker::parallel {

class Ranks {
 public:
  Ranks() = default;
  explicit Ranks(MPI_Comm comm);

  MPI_Comm comm() const { return comm_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  bool lead() const { return rank_ == 0; }

  // Each value replaced by its sum over the ranks, on every rank (collective).
  void sum(std::span<double> values) const;
  void sum(std::span<long long> values) const;
  long long sum(long long value) const;
  // Each value replaced by its largest over the ranks, on every rank (collective).
  void max(std::span<double> values) const;
  // Rank 0's values on every rank (collective; the same count everywhere).
  void broadcast(std::span<int> values) const;
  // Every rank's values, rank after rank, on rank 0; nothing on the others (collective).
  std::vector<double> gather(std::span<const double> values) const;
  // On rank 0, take(values of rank r) for r = 0, 1, ... in turn: it holds one rank's values
  // at a time, sent in pieces that MPI's 32-bit counts hold (collective).
  void gather_each(std::span<const double> values, const std::function<void(std::span<const double>)>& take) const;

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0;
  int size_ = 1;
};

// The tags of the tracker's point-to-point messages: apart, so that no receive (the
// migration's probes take any source) takes another's message.
inline constexpr int kMigrationTags[2] = {7301, 7302};  // alternate rounds (migration.cpp)
inline constexpr int kGatherTag = 7303;                 // Ranks::gather_each

}  // namespace cosim::tracker::parallel
