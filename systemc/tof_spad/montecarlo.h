#pragma once
// Monte Carlo trials of tof-spad on its clock-level kernels (the interface:
// systemc/common/montecarlo.h). Built from the config struct so tests can edit a config before
// the run; runs the same kernels as `rangesim simulate --kernel-only`.
#include <memory>

#include "core/params.h"
#include "core/tof_spad/config.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::mc {

// Column 0 of one TDC group (4 SPADs sharing a TDC, all seeing the point) at evaluation.distance_m;
// a trial is one histogram over N_p integrations and the preset's estimator.
class TofSpadMc : public McModel {
 public:
  explicit TofSpadMc(TofSpadConfig cfg, bool afterpulses = true);
  const char* unit() const override { return "m"; }
  double metres_per_unit() const override { return 1.0; }
  std::unique_ptr<McPointRunner> point(double signal_Hz, double background_Hz, std::uint64_t key) const override;
  double relative_cost(double signal_Hz, double background_Hz) const override;

 private:
  TofSpadConfig cfg_;
  bool afterpulses_;
};

// The registry's entry (systemc/common/montecarlo.cpp): the model of a validated preset.
std::unique_ptr<McModel> make_tof_spad_mc(const ParamSet& params);

}  // namespace rangesim::mc
