// The bench settings of tof-spad: its rows of the run-time-against-error table (docs/bench.md).
#include <fmt/format.h>

#include "app/bench/bench_pareto.h"

namespace rangesim::app::bench {

std::vector<ParetoSetting> tof_spad_pareto_settings(bool quick) {
  std::vector<ParetoSetting> s = {
      {"tof-spad", "tof-spad-plane.toml", "kernel, 1 frame", "kernel", {"--kernel-only", "--frames", "1"}},
      {"tof-spad", "tof-spad-plane.toml", "kernel, 4 frames", "kernel", {"--kernel-only", "--frames", "4"}},
      {"tof-spad", "tof-spad-plane.toml", "SystemC module, 1 frame", "systemc", {"--frames", "1"}},
      // Beam spot: the window (512 pixels, 448 background-only) against the whole array one by one.
      {"tof-spad", "tof-spad-spot.toml", "kernel, beam spot, sparse", "kernel", {"--kernel-only"}},
  };
  if (!quick) {
    s.push_back(
        {"tof-spad", "tof-spad-plane.toml", "kernel, 16 frames", "kernel", {"--kernel-only", "--frames", "16"}});
    s.push_back({"tof-spad", "tof-spad-spot.toml", "kernel, beam spot, dense", "kernel", {"--kernel-only", "--dense"}});
  }
  return s;
}

}  // namespace rangesim::app::bench
