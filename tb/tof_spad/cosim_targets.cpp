// The co-simulation targets of tof-spad (tb/common/cosim_target.h): its readout, and the shared
// TDC alone at high count rates.
#include "tb/common/cosim_target.h"
#include "tb/common/rtl_build.h"
#include "tb/tof_spad/cosim.h"
#include "tb/tof_spad/verilog_parameters.h"

namespace rangesim::tb {
namespace {
CosimReport tof_spad(const CosimOptions& o) { return run_tof_spad_cosim(o, false); }
CosimReport tdc(const CosimOptions& o) { return run_tof_spad_cosim(o, true); }

RtlBuildSpec preset_group(const ParamSet& preset) {
  return {"tof_spad",
          "tof_spad_sequencer",
          verilog_parameters(tof_spad_from_params(preset), preset.origin()),
          "tb/tof_spad/cosim_harness.h",
          "rangesim::tb::run_tof_spad_preset",
          {}};
}
}  // namespace

std::vector<CosimTarget> tof_spad_cosim_targets() {
  return {
      {"tof-spad",
       "tof-spad row sequencer + TDC + histogram vs the SPAD/TDC kernels: codes, bins, peaks, "
       "centroid sums; golden estimator on the RTL histograms",
       {"tdc_code_off_by_one", "dropped_histogram_count"},
       &tof_spad},
      {"tdc",
       "shared TDC at high count rates: arbitration, dead time, overflow, lost hits vs "
       "TdcGroupKernel",
       {"tdc_code_off_by_one"},
       &tdc},
  };
}

// `rangesim cosim <tof-spad preset>`: one TDC group of the preset's width (tdc.columns_per_tdc).
std::vector<PresetCosim> tof_spad_preset_cosims() {
  return {{"tof-spad", "tof-spad", "rtl/tof_spad/instances/tdc_group.toml", &preset_group}};
}

}  // namespace rangesim::tb
