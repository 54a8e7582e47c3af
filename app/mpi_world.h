#pragma once
// The MPI world of a run started by `mpirun -n N rangesim sweep|evaluate --trials ...`: each rank
// computes its share (every N-th variant or grid point) and rank 0 gathers the results and writes
// the one output, byte-identical to a one-process run (counter-based random streams). Built with
// MPI when CMake finds it (RANGESIM_HAS_MPI); a build without MPI refuses a run under mpirun with
// N > 1, saying how to get MPI, instead of running N identical copies.
#include <string>
#include <vector>

namespace rangesim::app::mpi {

struct World {
  int rank = 0;  // this process
  int size = 1;  // processes in the run
};

// The world: MPI_Init (once) when started under an MPI launcher with more than one process,
// {0, 1} otherwise. Throws UserError (exit 2) under a launcher in a build without MPI.
World init();

// Every rank's `mine`, in rank order, on rank 0 (other ranks get an empty vector). Collective:
// every rank of the world must call it.
std::vector<std::string> gather(const World& w, const std::string& mine);

// The largest of every rank's `value` on every rank (collective).
int max_all(const World& w, int value);

}  // namespace rangesim::app::mpi
