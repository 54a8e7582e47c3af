#pragma once
// Co-simulation of the ls-conventional readout: the verilated rtl/ls_conventional/ls_conventional_readout.sv
// (frame sequencer, per-row comparator latches, address searches and centre processors) beside
// the clock-level ls-conventional model (systemc::LsConventionalSensorKernel ticked every clock
// under SystemC, the kernel the sc_module LsConventionalSensor runs), on the same stimulus: the
// model's pixel array (random scenes, signal and background levels, noise on or off) drives
// both the model's readout and the RTL's comparator inputs cmp_i.
//
// Scoreboard, cycle by cycle: the sequencer pins and every row's busy_o; per (frame, sampling,
// row) the streamed left and right addresses with the cycles of their first and last bit; per
// (frame, row) at frame_done the centre (valid, Q.8 centre, sum, n). With noise off, the centre
// of every row is also checked against golden::direct_estimate (exact: sum / 2n equals it).
// The harness is tb/ls_conventional/cosim_harness.h. Elaborates SystemC: once per process.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/ls_conventional/config.h"
#include "golden/ls_conventional/frame_timing.h"
#include "tb/common/cosim_target.h"

namespace rangesim::tb {

struct LsConventionalCosimOptions {
  bool full_size = false;    // Vls_conventional_readout (375 x 365) instead of the small instance
  long long frames = 10;     // frame accesses
  std::uint64_t seed = 1;    // scenes, noise on (even seeds) or off (odd), Verilator's initial state
  std::string inject_fault;  // "", "address_bit_flip", "dropped_row", "centre_off_by_one"
  std::string trace_path;    // RTL VCD ("" = none)
  // Icarus replay (tb/ls_conventional/ls_conventional_readout_tb.sv): the inputs of every clock period as
  // $readmemh lines {rst, cmp_i}, and the outputs from the reset edge on as %h fields.
  std::string record_stimulus_path, record_outputs_path;
  std::function<void(long long frames_done)> progress;  // after each frame access
};

struct LsConventionalCosimResult {
  CosimReport report;
  long long frames = 0;     // frame accesses compared
  double wall_time_s = 0;   // elaboration + run
  int recorded_cycles = 0;  // lines of the stimulus record
};

inline const std::vector<std::string>& ls_conventional_faults() {
  static const std::vector<std::string> f{"address_bit_flip", "dropped_row", "centre_off_by_one"};
  return f;
}

// Whole frame accesses covering `cycles` (at least one), for a CosimOptions run.
inline LsConventionalCosimOptions ls_conventional_options(const CosimOptions& o, const LsConventionalConfig& cfg) {
  LsConventionalCosimOptions lo;
  const long long fc = rangesim::frame_cycles(cfg.timing, cfg.multisampling.samplings);
  lo.frames = std::max<long long>(1, (static_cast<long long>(o.cycles) + fc - 1) / fc);
  lo.seed = o.seed;
  lo.inject_fault = o.inject_fault;
  lo.trace_path = o.trace_path;
  return lo;
}

// The built-in instances: Vls_conventional_readout_small, or with full_size Vls_conventional_readout.
LsConventionalCosimResult run_ls_conventional_cosim(const LsConventionalCosimOptions& options);

// The configs of the built-in instances, from the instance presets they were verilated from
// (rtl/ls_conventional/instances/): the small one, or the full-size 375 x 365 one.
LsConventionalConfig ls_conventional_instance_config(bool full_size);

}  // namespace rangesim::tb
