#pragma once
// The four sensors' Monte Carlo models (mc_model.h), built from their config structs so tests can
// edit a config before the run. Each runs the same kernels as `rangesim simulate --kernel-only`.
#include <limits>

#include "app/montecarlo/mc_model.h"
#include "core/ls_conventional/config.h"
#include "core/ls_demodulation/config.h"
#include "core/tof_lockin/config.h"
#include "core/tof_spad/config.h"

namespace rangesim::app::mc {

// Where the spot sits in a light-section trial: centre pixel c = columns / 2 (as the golden row
// model), x0 = c - 0.5 + u with u uniform per trial (the golden accuracy's average over one
// pixel), or u fixed (tests comparing with the golden moments at one position).
struct SpotPlacement {
  double fixed_u = std::numeric_limits<double>::quiet_NaN();  // NaN: uniform per trial
};

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

// One pixel of the lock-in sensor kernel at evaluation.distance_m; a trial averages N_p range
// maps (each an LED frame and, with ambient subtraction, an ambient frame). Shot noise of the
// N_acc identical periods aggregated (exact: Poisson of the total mean).
class TofLockinMc : public McModel {
 public:
  explicit TofLockinMc(TofLockinConfig cfg, bool aggregate = true);
  const char* unit() const override { return "m"; }
  double metres_per_unit() const override { return 1.0; }
  std::unique_ptr<McPointRunner> point(double signal_A, double background_A, std::uint64_t key) const override;

 private:
  TofLockinConfig cfg_;
  bool aggregate_;
};

// Column 0 of one TDC group (4 SPADs sharing a TDC, all seeing the point) at evaluation.distance_m;
// a trial is one histogram over N_p integrations and the preset's estimator.
class TofSpadMc : public McModel {
 public:
  explicit TofSpadMc(TofSpadConfig cfg, bool afterpulses = true);
  const char* unit() const override { return "m"; }
  double metres_per_unit() const override { return 1.0; }
  std::unique_ptr<McPointRunner> point(double signal_Hz, double background_Hz, std::uint64_t key) const override;

 private:
  TofSpadConfig cfg_;
  bool afterpulses_;
};

}  // namespace rangesim::app::mc
