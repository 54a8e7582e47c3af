#pragma once
// The MPI calls of app/mpi_world.cpp, in a library of their own (librangesim_mpi.so, beside the
// rangesim executable) that mpi_world.cpp loads with dlopen only when the process was started by
// an MPI launcher with more than one process. Why: linking Open MPI into the executable loads
// and relocates seven more libraries (libmpi, libopen-rte, libopen-pal, hwloc, libevent, libudev,
// libz) before main in every rangesim process, MPI or not: about a quarter of a short command's
// start-up (docs/bench.md, numpy_peer_lockin_mc).
#include <string>
#include <vector>

namespace rangesim::app::mpi {

// One table of functions, returned by the library's one C symbol (kPluginEntry).
struct PluginApi {
  int abi;                             // kPluginAbi of the library's build
  void (*init)(int* rank, int* size);  // MPI_Init_thread (funneled), MPI_Finalize at exit
  void (*gather)(const std::string& mine, std::vector<std::string>* all);  // onto rank 0
  int (*max_all)(int value);                                               // MPI_Allreduce MAX
};

inline constexpr int kPluginAbi = 1;
inline constexpr const char* kPluginEntry = "rangesim_mpi_plugin";
using PluginEntry = const PluginApi* (*)();

}  // namespace rangesim::app::mpi
