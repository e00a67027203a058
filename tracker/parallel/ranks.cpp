#include "tracker/parallel/ranks.hpp"

#include <climits>
#include <stdexcept>

namespace cosim::tracker {
namespace {

int count(std::size_t n) {
  if (n > static_cast<std::size_t>(INT_MAX)) throw std::length_error("more values than MPI can count in one call");
  return static_cast<int>(n);
}

}  // namespace

Ranks::Ranks(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm, &rank_);
  MPI_Comm_size(comm, &size_);
}

void Ranks::sum(std::span<double> values) const {
  if (size_ > 1 && !values.empty())
    MPI_Allreduce(MPI_IN_PLACE, values.data(), count(values.size()), MPI_DOUBLE, MPI_SUM, comm_);
}

void Ranks::sum(std::span<long long> values) const {
  if (size_ > 1 && !values.empty())
    MPI_Allreduce(MPI_IN_PLACE, values.data(), count(values.size()), MPI_LONG_LONG, MPI_SUM, comm_);
}

long long Ranks::sum(long long value) const {
  sum(std::span(&value, 1));
  return value;
}

void Ranks::max(std::span<double> values) const {
  if (size_ > 1) MPI_Allreduce(MPI_IN_PLACE, values.data(), count(values.size()), MPI_DOUBLE, MPI_MAX, comm_);
}

void Ranks::broadcast(std::span<int> values) const {
  if (size_ > 1) MPI_Bcast(values.data(), count(values.size()), MPI_INT, 0, comm_);
}

std::vector<double> Ranks::gather(std::span<const double> values) const {
  if (size_ == 1) return {values.begin(), values.end()};
  const int mine = count(values.size());
  std::vector<int> counts(lead() ? static_cast<std::size_t>(size_) : 0), offsets;
  MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_);
  std::size_t total = 0;
  for (const int n : counts) {
    offsets.push_back(count(total));
    total += static_cast<std::size_t>(n);
  }
  std::vector<double> all(total);
  MPI_Gatherv(values.data(), mine, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm_);
  return all;
}

}  // namespace cosim::tracker
