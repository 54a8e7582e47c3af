# All dependencies are Debian packages (scripts/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(fmt REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json REQUIRED)

# libsystemc-dev ships only a pkg-config file: wrap it in an imported target.
pkg_check_modules(SYSTEMC REQUIRED IMPORTED_TARGET systemc)
# An INTERFACE IMPORTED target (not an ALIAS) so exported targets refer to SystemC::systemc.
if(NOT TARGET SystemC::systemc)
  add_library(SystemC::systemc INTERFACE IMPORTED)
  target_link_libraries(SystemC::systemc INTERFACE PkgConfig::SYSTEMC)
endif()

# pcg-cpp is header-only without a CMake package.
find_path(PCG_INCLUDE_DIR pcg_random.hpp REQUIRED)

if(RANGESIM_WITH_RTL)
  find_package(verilator REQUIRED HINTS $ENV{VERILATOR_ROOT} /usr/share/verilator)
endif()
if(RANGESIM_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

# Optional: MPI for `mpirun -n N rangesim sweep|evaluate --trials` (app/mpi_world.h); on when
# found, built without it otherwise (-DRANGESIM_WITH_MPI=OFF switches it off).
option(RANGESIM_WITH_MPI "Build with MPI when it is found (mpirun -n N rangesim sweep|evaluate --trials)" ON)
if(RANGESIM_WITH_MPI)
  find_package(MPI COMPONENTS CXX QUIET)
endif()
