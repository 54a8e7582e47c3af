// librangesim_mpi.so: the MPI calls of `mpirun -n N rangesim sweep|evaluate --trials`
// (app/mpi_plugin.h says why they live apart; app/mpi_world.cpp loads this library).
#include "app/mpi_plugin.h"

#include <mpi.h>

#include <cstdlib>

namespace rangesim::app::mpi {
namespace {

void init(int* rank, int* size) {
  int provided = 0;
  // Funneled: only the main thread calls MPI; the Monte Carlo workers never do.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  std::atexit([] { MPI_Finalize(); });
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
}

void gather(const std::string& mine, std::vector<std::string>* parts) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int length = static_cast<int>(mine.size());
  const auto n = static_cast<std::size_t>(size);
  std::vector<int> lengths(n), offsets(n);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (rank == 0) {
    long long total = 0;
    for (std::size_t r = 0; r < n; ++r) offsets[r] = static_cast<int>(total), total += lengths[r];
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  if (rank == 0)
    for (std::size_t r = 0; r < n; ++r)
      parts->push_back(all.substr(static_cast<std::size_t>(offsets[r]), static_cast<std::size_t>(lengths[r])));
}

int max_all(int value) {
  int result = value;
  MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return result;
}

constexpr PluginApi kApi{kPluginAbi, &init, &gather, &max_all};

}  // namespace
}  // namespace rangesim::app::mpi

extern "C" __attribute__((visibility("default"))) const rangesim::app::mpi::PluginApi* rangesim_mpi_plugin() {
  return &rangesim::app::mpi::kApi;
}
