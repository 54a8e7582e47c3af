#include "app/mpi_world.h"

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/mpi_plugin.h"
#include "core/user_error.h"

namespace rangesim::app::mpi {

namespace {

// The process count an MPI launcher announces (Open MPI, MPICH/PMI), 1 without one.
int launcher_size() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
    if (const char* v = std::getenv(var)) return std::max(1, std::atoi(v));
  return 1;
}

const PluginApi* api = nullptr;  // loaded by init() under a launcher

#if RANGESIM_HAS_MPI
// The MPI library's candidate paths: beside the executable (the build tree), then where
// `cmake --install` puts it relative to the installed executable.
std::vector<std::string> plugin_paths() {
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  std::string dir = n > 0 ? std::string(exe, static_cast<std::size_t>(n)) : std::string();
  dir = dir.substr(0, dir.find_last_of('/') + 1);
  return {dir + RANGESIM_MPI_PLUGIN, dir + RANGESIM_MPI_PLUGIN_INSTALLED_DIR + "/" + RANGESIM_MPI_PLUGIN};
}

const PluginApi* load_plugin() {
  std::string tried;
  for (const std::string& path : plugin_paths()) {
    // Global: Open MPI loads its own components, which look for libmpi's symbols.
    void* lib = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!lib) {
      tried += std::string(tried.empty() ? "" : "; ") + dlerror();
      continue;
    }
    const auto entry = reinterpret_cast<PluginEntry>(dlsym(lib, kPluginEntry));
    const PluginApi* a = entry ? entry() : nullptr;
    if (a && a->abi == kPluginAbi) return a;
    tried += std::string(tried.empty() ? "" : "; ") + path + " is not this build's";
  }
  throw UserError("started under mpirun with more than one process, but the MPI library of this build (" +
                  std::string(RANGESIM_MPI_PLUGIN) + ") cannot be loaded: " + tried +
                  "; rebuild (cmake --build build --target rangesim) or reinstall, or split the run with --shard "
                  "K/N and `rangesim merge`");
}
#else
const PluginApi* load_plugin() {
  throw UserError(
      "started under mpirun with more than one process, but this rangesim was built without MPI; install "
      "Debian's openmpi-bin and libopenmpi-dev (scripts/install-deps.sh does) and rebuild, or split the run "
      "with --shard K/N and `rangesim merge`");
}
#endif

}  // namespace

World init() {
  static World world;
  static bool done = false;
  if (done || launcher_size() == 1) return world;
  done = true;
  api = load_plugin();
  api->init(&world.rank, &world.size);
  return world;
}

std::vector<std::string> gather(const World& w, const std::string& mine) {
  if (w.size == 1 || !api) return {mine};
  std::vector<std::string> parts;
  api->gather(mine, &parts);
  return parts;
}

int max_all(const World& w, int value) { return w.size == 1 || !api ? value : api->max_all(value); }

}  // namespace rangesim::app::mpi
