#pragma once
// Monte Carlo trials of ls-conventional on its clock-level kernels (the interface:
// systemc/common/montecarlo.h). Built from the config struct so tests can edit a config before
// the run; runs the same kernels as `rangesim simulate --kernel-only`.
#include <memory>

#include "core/params.h"
#include "core/ls_conventional/config.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::mc {

// One row (the rows are independent and identical at a grid point) of the full kernel: pixel
// array with shot, kTC and read noise, row search, centre processor, readout sequencer.
class LsConventionalMc : public McModel {
 public:
  explicit LsConventionalMc(LsConventionalConfig cfg, SpotPlacement spot = {});
  const char* unit() const override { return "px"; }
  double metres_per_unit() const override;
  std::unique_ptr<McPointRunner> point(double signal_V, double background_V, std::uint64_t key) const override;

 private:
  LsConventionalConfig cfg_;
  SpotPlacement spot_;
};

// The registry's entry (systemc/common/montecarlo.cpp): the model of a validated preset.
std::unique_ptr<McModel> make_ls_conventional_mc(const ParamSet& params);

}  // namespace rangesim::mc
