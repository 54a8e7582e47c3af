#pragma once
// Monte Carlo trials of tof-lockin on its clock-level kernels (the interface:
// systemc/common/montecarlo.h). Built from the config struct so tests can edit a config before
// the run; runs the same kernels as `rangesim simulate --kernel-only`.
#include <memory>

#include "core/params.h"
#include "core/tof_lockin/config.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::mc {

// One pixel of the lock-in sensor kernel at evaluation.distance_m; a trial averages N_p range
// maps (each an LED frame and, with ambient subtraction, an ambient frame). Shot noise of the
// N_acc identical periods aggregated (exact: Poisson of the total mean). Each trial's frames are
// the sensor kernel's, or (simulation.direct_trials) the same draws without its sequencer; from
// trial code_tables_from_trial on (simulation.code_tables) each code comes from its own law.
class TofLockinMc : public McModel {
 public:
  // The code tables (~ms per point) pay for themselves over about this many trials.
  static constexpr long long kCodeTablesFromTrial = 65536;
  explicit TofLockinMc(TofLockinConfig cfg, bool aggregate = true,
                       long long code_tables_from_trial = kCodeTablesFromTrial);
  const char* unit() const override { return "m"; }
  double metres_per_unit() const override { return 1.0; }
  std::unique_ptr<McPointRunner> point(double signal_A, double background_A, std::uint64_t key) const override;

 private:
  TofLockinConfig cfg_;
  bool aggregate_;
  long long code_tables_from_;
};

// The registry's entry (systemc/common/montecarlo.cpp): the model of a validated preset.
std::unique_ptr<McModel> make_tof_lockin_mc(const ParamSet& params);

}  // namespace rangesim::mc
