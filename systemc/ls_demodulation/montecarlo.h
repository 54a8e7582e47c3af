#pragma once
// Monte Carlo trials of ls-demodulation on its clock-level kernels (the interface:
// systemc/common/montecarlo.h). Built from the config struct so tests can edit a config before
// the run; runs the same kernels as `rangesim simulate --kernel-only`.
#include <memory>

#include "core/params.h"
#include "core/ls_demodulation/config.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::mc {

// One row of the demodulating sensor kernel; a trial averages the centres of N_p frames
// (evaluation.frames_averaged) of K decisions each.
class LsDemodulationMc : public McModel {
 public:
  explicit LsDemodulationMc(LsDemodulationConfig cfg, SpotPlacement spot = {});
  const char* unit() const override { return "px"; }
  double metres_per_unit() const override;
  std::unique_ptr<McPointRunner> point(double signal_A, double background_A, std::uint64_t key) const override;

 private:
  LsDemodulationConfig cfg_;
  SpotPlacement spot_;
};

// The registry's entry (systemc/common/montecarlo.cpp): the model of a validated preset.
std::unique_ptr<McModel> make_ls_demodulation_mc(const ParamSet& params);

}  // namespace rangesim::mc
