#include "fluid/ibm/summed_rows.hpp"

#include <algorithm>
#include <cstddef>

#include "fluid/petsc_check.hpp"

namespace cosim::fluid::ibm {

namespace {

using Product = MarkerStencils::Product;

bool by_row(const Product& a, const Product& b) { return a.row < b.row; }

// Every rank's entries for the rows this rank owns, rank after rank, each rank's in the order
// it gave them (by ascending row); rank r's are from_rank[r] .. from_rank[r + 1] - 1, and
// `first` is this rank's first row.
std::vector<Product> gathered(MPI_Comm comm, PetscInt rows, const std::vector<Product>& entries,
                              std::vector<std::size_t>& from_rank, PetscInt& first) {
  int size = 1, rank = 0;
  MPI_Comm_size(comm, &size);
  MPI_Comm_rank(comm, &rank);
  std::vector<PetscInt> ends(static_cast<std::size_t>(size));
  MPI_Allgather(&rows, 1, MPIU_INT, ends.data(), 1, MPIU_INT, comm);
  for (std::size_t r = 1; r < ends.size(); ++r) ends[r] += ends[r - 1];
  first = ends[static_cast<std::size_t>(rank)] - rows;
  // The entries for rank r's rows are consecutive: the entries come by ascending row.
  std::vector<int> send(static_cast<std::size_t>(size), 0), receive(send.size()), sent_at(send.size()),
      received_at(send.size());
  auto from = entries.begin();
  for (std::size_t r = 0; r < ends.size(); ++r) {
    const auto to = std::lower_bound(from, entries.end(), Product{ends[r], 0, 0.0}, by_row);
    send[r] = static_cast<int>(to - from);
    from = to;
  }
  MPI_Alltoall(send.data(), 1, MPI_INT, receive.data(), 1, MPI_INT, comm);
  for (std::size_t r = 1; r < send.size(); ++r) {
    sent_at[r] = sent_at[r - 1] + send[r - 1];
    received_at[r] = received_at[r - 1] + receive[r - 1];
  }
  std::vector<Product> out(static_cast<std::size_t>(received_at.back() + receive.back()));
  MPI_Datatype type = MPI_DATATYPE_NULL;
  const int lengths[] = {2, 1};
  const MPI_Aint displacements[] = {offsetof(Product, row), offsetof(Product, value)};
  const MPI_Datatype types[] = {MPIU_INT, MPI_DOUBLE};
  MPI_Datatype packed = MPI_DATATYPE_NULL;
  MPI_Type_create_struct(2, lengths, displacements, types, &packed);
  MPI_Type_create_resized(packed, 0, sizeof(Product), &type);
  MPI_Type_commit(&type);
  MPI_Alltoallv(entries.data(), send.data(), sent_at.data(), type, out.data(), receive.data(), received_at.data(), type,
                comm);
  MPI_Type_free(&type);
  MPI_Type_free(&packed);
  from_rank.clear();
  for (std::size_t r = 0; r < receive.size(); ++r) from_rank.push_back(static_cast<std::size_t>(received_at[r]));
  from_rank.push_back(out.size());
  return out;
}

}  // namespace

Mat summed_rows(MPI_Comm comm, PetscInt rows, std::vector<Product> entries) {
  if (!std::is_sorted(entries.begin(), entries.end(), by_row)) std::stable_sort(entries.begin(), entries.end(), by_row);
  PetscInt first = 0;  // this rank's first row
  std::vector<std::size_t> from_rank;
  const std::vector<Product> mine = gathered(comm, rows, entries, from_rank, first);
  entries = {};
  std::vector<std::size_t> cursor(from_rank.begin(), from_rank.end() - 1);
  std::vector<PetscInt> starts{0}, columns;
  std::vector<PetscScalar> values;
  columns.reserve(mine.size() + static_cast<std::size_t>(rows));
  values.reserve(columns.capacity());
  std::vector<std::pair<PetscInt, double>> row;
  const auto by_column = [](const auto& a, const auto& b) { return a.first < b.first; };
  for (PetscInt r = first; r < first + rows; ++r) {
    row.clear();
    int sources = 0;
    for (std::size_t k = 0; k < cursor.size(); ++k) {
      const std::size_t before = row.size();
      for (; cursor[k] < from_rank[k + 1] && mine[cursor[k]].row == r; ++cursor[k])
        row.emplace_back(mine[cursor[k]].column, mine[cursor[k]].value);
      sources += row.size() > before ? 1 : 0;
    }
    // One rank's columns come ascending; the diagonal goes in its place among them.
    if (sources > 1) std::sort(row.begin(), row.end(), by_column);
    const std::pair<PetscInt, double> diagonal{r, 0.0};
    row.insert(std::lower_bound(row.begin(), row.end(), diagonal, by_column), diagonal);
    const std::size_t begin = columns.size();
    for (const auto& [column, value] : row)
      if (columns.size() > begin && columns.back() == column) {
        values.back() += value;
      } else {
        columns.push_back(column);
        values.push_back(value);
      }
    for (std::size_t k = begin; k < columns.size(); ++k)
      if (columns[k] == r && values[k] == 0) values[k] = 1.0;
    starts.push_back(static_cast<PetscInt>(columns.size()));
  }
  Mat B = nullptr;
  COSIM_PETSC(MatCreateMPIAIJWithArrays(comm, rows, rows, PETSC_DETERMINE, PETSC_DETERMINE, starts.data(),
                                        columns.data(), values.data(), &B));
  return B;
}

}  // namespace cosim::fluid::ibm
