#include "app/mpi_world.h"

#include <cstdlib>
#include <string>

#include "core/user_error.h"

#if RANGESIM_HAS_MPI
#include <mpi.h>
#endif

namespace rangesim::app::mpi {

namespace {

// The process count an MPI launcher announces (Open MPI, MPICH/PMI), 1 without one.
int launcher_size() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(var)) return std::max(1, std::atoi(v));
  return 1;
}

}  // namespace

#if RANGESIM_HAS_MPI

World init() {
  static World world;
  static bool done = false;
  if (done || launcher_size() == 1) return world;
  done = true;
  int provided = 0;
  // Funneled: only this thread calls MPI; the Monte Carlo workers never do.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  std::atexit([] { MPI_Finalize(); });
  MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  return world;
}

std::vector<std::string> gather(const World& w, const std::string& mine) {
  if (w.size == 1) return {mine};
  int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<std::size_t>(w.size)), offsets(static_cast<std::size_t>(w.size));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::string all;
  if (w.rank == 0) {
    long long total = 0;
    for (int r = 0; r < w.size; ++r)
      offsets[static_cast<std::size_t>(r)] = static_cast<int>(total), total += lengths[static_cast<std::size_t>(r)];
    all.resize(static_cast<std::size_t>(total));
  }
  MPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::string> parts;
  if (w.rank == 0)
    for (int r = 0; r < w.size; ++r)
      parts.push_back(all.substr(static_cast<std::size_t>(offsets[static_cast<std::size_t>(r)]),
                                 static_cast<std::size_t>(lengths[static_cast<std::size_t>(r)])));
  return parts;
}

int max_all(const World& w, int value) {
  if (w.size == 1) return value;
  int result = value;
  MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return result;
}

#else

World init() {
  if (launcher_size() > 1)
    throw UserError(
        "started under mpirun with more than one process, but this rangesim was built without MPI; install "
        "Debian's openmpi-bin and libopenmpi-dev (scripts/install-deps.sh does) and rebuild, or split the run "
        "with --shard K/N and `rangesim merge`");
  return {};
}

std::vector<std::string> gather(const World&, const std::string& mine) { return {mine}; }

int max_all(const World&, int value) { return value; }

#endif

}  // namespace rangesim::app::mpi
