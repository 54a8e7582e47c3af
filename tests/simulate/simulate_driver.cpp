// A stand-in for `rangesim simulate` while app/main.cpp is being refactored: the same CLI11
// subcommand and options that docs/simulate.md asks main.cpp to add, calling run_simulate().
// Used by the end-to-end tests in this folder only.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "core/user_error.h"

using namespace rangesim::app;

int main(int argc, char** argv) {
  CLI::App app{"simulate_driver: rangesim simulate for tests", "rangesim"};
  app.require_subcommand(1);
  // ---- the lines for app/main.cpp ----
  SimulateOptions sim_opt;
  auto* sim = app.add_subcommand(
      "simulate",
      "Clock-level model of the sensor (SystemC, or the bare cycle kernels) on a scene: range map with its\n"
      "error against the scene's ground truth, per-frame cycle counts by phase and the frame rate measured\n"
      "from simulated time beside the clock schedule. Writes range_map.csv/.png, points.csv, frames.csv and\n"
      "summary.json into --out.");
  sim->add_option("sensor", sim_opt.sensor, "Preset id or path to a .toml file (clock-level model: ls-conventional)")->required();
  sim->add_option("--scene", sim_opt.scene, "Scene file (TOML), e.g. scenes/plane.toml")->required();
  sim->add_option("--frames", sim_opt.frames, "Frame accesses to simulate (default: one range map = timing.beam_positions)");
  sim->add_option("--seed", sim_opt.seed, "Seed of the noise streams (default: 1)");
  sim->add_option("--trace", sim_opt.trace, "Write a VCD waveform (SystemC run only) to this .vcd file");
  sim->add_option("--out", sim_opt.out, "Output directory (default: rangesim-out/simulate/<scene name>)");
  sim->add_flag("--json", sim_opt.json, "Print summary.json to stdout instead of the table");
  sim->add_flag("--kernel-only", sim_opt.kernel_only, "Run the bare C++ cycle kernels, no SystemC elaboration");
  sim->add_flag("--tick", sim_opt.tick, "With --kernel-only: evaluate every clock cycle (no event skipping)");
  sim->add_flag("--noise-free", sim_opt.noise_free, "Switch all noise sources off");
  sim->add_flag("--dense", sim_opt.dense, "Simulate every pixel (no sparse window around the beam)");
  sim->add_flag("--no-plots", sim_opt.no_plots, "Skip range_map.png");
  // ---- end ----
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    fmt::print(stderr, "rangesim: {}\n", e.what());
    return kExitBadInput;
  }
  try {
    if (*sim) return run_simulate(sim_opt);
  } catch (const rangesim::UserError& e) {
    fmt::print(stderr, "rangesim: error: {}\n", e.what());
    return kExitBadInput;
  } catch (const NotModelled& e) {
    fmt::print(stderr, "{}\n", e.message);
    return kExitNotModelled;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rangesim: internal error: {}\n", e.what());
    return kExitInternal;
  }
  return kExitInternal;
}
