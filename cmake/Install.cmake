# Install rules and the exported CMake package `rangesim`:
#   find_package(rangesim REQUIRED)
#   target_link_libraries(app PRIVATE rangesim::golden rangesim::systemc rangesim::rtl)
# (rangesim::systemc links rangesim::scene, the scene reader its scene adapters use.)
# Headers install under include/rangesim/<folder>/ and are included as "core/...",
# "golden/...", "systemc/..." (install interface include dir: include/rangesim). Verilated
# headers go to include/rangesim/rtl/ (included by bare name, e.g. "Vaddress_search.h", since
# they include each other that way) plus "rtl/instance_presets.h" (the preset each was verilated from).
include(CMakePackageConfigHelpers)

set(RANGESIM_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/rangesim"
  CACHE STRING "Where rangesimConfig.cmake is installed, relative to the prefix")
set(RANGESIM_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/rangesim")

# Libraries: whichever of them this configuration builds (golden and rtl are optional here so
# a partial tree still installs).
set(_rangesim_export_targets)
foreach(_t rangesim_core rangesim_golden rangesim_scene rangesim_systemc rangesim_rtl rangesim_cosim_kit)
  if(TARGET ${_t})
    list(APPEND _rangesim_export_targets ${_t})
  endif()
endforeach()
install(TARGETS ${_rangesim_export_targets}
  EXPORT rangesimTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The command-line tool, if built.
if(TARGET rangesim)
  install(TARGETS rangesim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

# Public headers, folder by folder.
foreach(_dir core golden scene systemc)
  if(IS_DIRECTORY "${PROJECT_SOURCE_DIR}/${_dir}")
    install(DIRECTORY "${PROJECT_SOURCE_DIR}/${_dir}/"
      DESTINATION "${RANGESIM_INSTALL_INCLUDEDIR}/${_dir}"
      FILES_MATCHING PATTERN "*.h")
  endif()
endforeach()

# Generated headers (the sensor list).
install(FILES "${PROJECT_BINARY_DIR}/core/generated/core/sensor_list.h"
  DESTINATION "${RANGESIM_INSTALL_INCLUDEDIR}/core")

# Verilated model headers (generated at build time) and the instance presets.
if(TARGET rangesim_rtl)
  get_property(_rtl_dirs GLOBAL PROPERTY RANGESIM_RTL_INCLUDE_DIRS)
  foreach(_d ${_rtl_dirs})
    install(DIRECTORY "${_d}/" DESTINATION "${RANGESIM_INSTALL_INCLUDEDIR}/rtl"
      FILES_MATCHING PATTERN "*.h")
  endforeach()
endif()

# The verification kit (tb/CMakeLists.txt: rangesim_cosim_kit): its headers with the stimulus
# generators, and rangesim's
# Verilog with its Verilator flags and instance presets, for a user's testbench to verilate or
# to compare their own RTL with (docs/rtl-contract.md).
if(TARGET rangesim_cosim_kit)
  install(FILES
    "${PROJECT_SOURCE_DIR}/tb/common/cosim_scoreboard.h" "${PROJECT_SOURCE_DIR}/tb/common/cosim_run.h"
    "${PROJECT_SOURCE_DIR}/tb/common/cosim_ports.h" "${PROJECT_SOURCE_DIR}/tb/common/cosim_target.h"
    "${PROJECT_SOURCE_DIR}/tb/common/cosim_coverage.h" "${PROJECT_SOURCE_DIR}/tb/common/vcd_merge.h"
    "${PROJECT_SOURCE_DIR}/tb/common/cosim_save_file.h"
    "${PROJECT_SOURCE_DIR}/tb/common/address_search_stimulus.h"
    DESTINATION "${RANGESIM_INSTALL_INCLUDEDIR}/tb/common")
  # The stimulus generators (header-only, one per sensor: tb/<sensor>/stimulus.h), the random
  # scenes, rows and setups rangesim's own co-simulation draws.
  foreach(_sensor ${RANGESIM_SENSORS})
    if(EXISTS "${PROJECT_SOURCE_DIR}/tb/${_sensor}/stimulus.h")
      install(FILES "${PROJECT_SOURCE_DIR}/tb/${_sensor}/stimulus.h" DESTINATION "${RANGESIM_INSTALL_INCLUDEDIR}/tb/${_sensor}")
    endif()
  endforeach()
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/rtl/"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/rangesim/rtl"
    FILES_MATCHING PATTERN "*.sv" PATTERN "*.vlt" PATTERN "*.f" PATTERN "*.toml")
  install(FILES "${PROJECT_SOURCE_DIR}/docs/rtl-contract.md" DESTINATION "${CMAKE_INSTALL_DATADIR}/rangesim")
endif()

# Sensor presets (core looks here: RANGESIM_INSTALL_PRESET_DIR).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/presets/"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/rangesim/presets"
  FILES_MATCHING PATTERN "*.toml")

# The bench's NumPy peers (app/bench/bench_numpy_peers.cpp looks here).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/app/bench/peers/"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/rangesim/peers"
  FILES_MATCHING PATTERN "*.py")

# The package: targets file + config + version.
install(EXPORT rangesimTargets
  NAMESPACE rangesim::
  FILE rangesimTargets.cmake
  DESTINATION "${RANGESIM_INSTALL_CMAKEDIR}")
configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/rangesimConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/rangesimConfig.cmake"
  INSTALL_DESTINATION "${RANGESIM_INSTALL_CMAKEDIR}"
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/rangesimConfigVersion.cmake"
  VERSION ${PROJECT_VERSION}
  COMPATIBILITY SameMinorVersion)  # 0.x: minor versions may break the API
install(FILES
  "${PROJECT_BINARY_DIR}/rangesimConfig.cmake"
  "${PROJECT_BINARY_DIR}/rangesimConfigVersion.cmake"
  DESTINATION "${RANGESIM_INSTALL_CMAKEDIR}")
