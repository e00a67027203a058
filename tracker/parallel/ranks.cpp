#include "tracker/parallel/ranks.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace cosim::tracker::parallel {
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

void Ranks::gather_each(std::span<const double> values,
                        const std::function<void(std::span<const double>)>& take) const {
  if (lead()) take(values);
  if (size_ == 1) return;
  // A rank's values in pieces of at most this many: their count is an int.
  constexpr std::size_t kPiece = std::size_t{1} << 28;
  if (!lead()) {
    const auto n = static_cast<long long>(values.size());
    MPI_Send(&n, 1, MPI_LONG_LONG, 0, kGatherTag, comm_);
    for (std::size_t at = 0; at < values.size(); at += kPiece)
      MPI_Send(values.data() + at, count(std::min(kPiece, values.size() - at)), MPI_DOUBLE, 0, kGatherTag, comm_);
    return;
  }
  std::vector<double> received;
  for (int from = 1; from < size_; ++from) {
    // Messages from one rank with one tag arrive in the order sent.
    long long n = 0;
    MPI_Recv(&n, 1, MPI_LONG_LONG, from, kGatherTag, comm_, MPI_STATUS_IGNORE);
    received.resize(static_cast<std::size_t>(n));
    for (std::size_t at = 0; at < received.size(); at += kPiece)
      MPI_Recv(received.data() + at, count(std::min(kPiece, received.size() - at)), MPI_DOUBLE, from, kGatherTag, comm_,
               MPI_STATUS_IGNORE);
    take(received);
  }
}

std::vector<double> Ranks::gather(std::span<const double> values) const {
  std::vector<double> all;
  gather_each(values, [&](std::span<const double> some) { all.insert(all.end(), some.begin(), some.end()); });
  return all;
}

}  // namespace cosim::tracker::parallel
