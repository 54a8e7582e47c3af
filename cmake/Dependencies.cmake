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

# Optional: the Python module `rangesim` (python/, docs/python.md); on when pybind11, the Python
# headers and NumPy are found, built without it otherwise (-DRANGESIM_WITH_PYTHON=OFF switches it
# off). Never in the sanitizer or fuzzing builds: an instrumented module cannot be loaded into
# the uninstrumented interpreter.
option(RANGESIM_WITH_PYTHON "Build the Python module rangesim when pybind11 and NumPy are found" ON)
set(RANGESIM_PYTHON_MODULE OFF)
if(RANGESIM_WITH_PYTHON AND NOT RANGESIM_SANITIZE AND NOT RANGESIM_FUZZ)
  # Debian's pybind11-dev and python3-numpy serve /usr/bin/python3; a python3 earlier on PATH
  # (pyenv's, say) sees neither, so that one is the default (-DPython3_EXECUTABLE=... overrides).
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python3 COMPONENTS Interpreter Development.Module NumPy QUIET)
  if(Python3_FOUND)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(Python3_FOUND AND pybind11_FOUND)
    set(RANGESIM_PYTHON_MODULE ON)
    message(STATUS "Python module rangesim: pybind11 ${pybind11_VERSION}, ${Python3_EXECUTABLE} ${Python3_VERSION}")
  else()
    message(STATUS "Python module rangesim not built: pybind11 or NumPy not found "
                   "(Debian: apt-get install pybind11-dev python3-numpy)")
  endif()
endif()
