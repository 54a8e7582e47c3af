// Monte Carlo trials of ls-demodulation on the sensor kernel (one row).
#include <cmath>

#include "systemc/ls_demodulation/montecarlo.h"
#include "golden/ls_demodulation/position.h"
#include "golden/common/spot.h"
#include "systemc/ls_demodulation/sensor_kernel.h"
#include "systemc/ls_demodulation/nonideal_stimulus.h"

namespace rangesim::mc {

namespace {

class Runner : public McPointRunner {
 public:
  Runner(const LsDemodulationConfig& cfg, double signal_A, double background_A, std::uint64_t key, SpotPlacement spot)
      : cfg_(one_row(cfg)),
        key_(key),
        spot_(spot),
        signal_A_(signal_A),
        background_A_(background_A),
        kernel_(cfg_, options(key)) {
    stim_.background_A.assign(static_cast<std::size_t>(cfg_.pixel.columns), background_A);
  }

  McTrial trial(long long t) override {
    const int frames = std::max(1, cfg_.grid.frames_averaged);
    const double u = std::isnan(spot_.fixed_u) ? trial_uniform(key_, static_cast<std::uint64_t>(t)) : spot_.fixed_u;
    const double x0 = cfg_.pixel.columns / 2 - 0.5 + u;
    stim_.beam_A.resize(stim_.background_A.size());
    for (std::size_t c = 0; c < stim_.beam_A.size(); ++c)
      stim_.beam_A[c] = signal_A_ * golden::spot_profile(cfg_.spot, static_cast<double>(c) - x0);
    if (cfg_.fixed_pattern.any()) {
      // Every trial is a row of another chip (its fixed pattern keyed by the trial), so the
      // trials' spread holds the spread over chips that golden's accuracy does.
      stim_.background_A.assign(stim_.background_A.size(), background_A_);
      systemc::apply_demod_fixed_pattern(cfg_, stim_, trial_key(key_, static_cast<std::uint64_t>(t)));
    }
    double sum = 0;
    int valid = 0;
    bool outlier = false;
    const golden::ColumnSpan spot = golden::spot_window(cfg_.spot, x0, cfg_.pixel.columns);
    for (int j = 0; j < frames; ++j) {
      // Frame index = trial x N_p + j: streams keyed (point key, frame, row, column).
      const auto r = kernel_.run_frame(static_cast<std::uint64_t>(t) * frames + j, stim_);
      const systemc::DemodRowResult& row = r.rows.front();
      if (row.valid()) sum += row.centre_px(), ++valid;
      outlier |= row.valid() && (row.min_left < spot.first || row.max_right > spot.last);
    }
    McTrial out;
    out.detected = valid > 0;
    if (out.detected) out.error = sum / valid - x0;
    out.outlier = outlier;
    return out;
  }

 private:
  static LsDemodulationConfig one_row(LsDemodulationConfig c) {
    c.pixel.rows = 1;
    return c;
  }
  static systemc::DemodKernelOptions options(std::uint64_t key) {
    systemc::DemodKernelOptions o;
    o.seed = key;
    return o;
  }

  LsDemodulationConfig cfg_;
  std::uint64_t key_;
  SpotPlacement spot_;
  double signal_A_;
  double background_A_;
  systemc::DemodSensorKernel kernel_;
  systemc::DemodStimulus stim_;
};

}  // namespace

LsDemodulationMc::LsDemodulationMc(LsDemodulationConfig cfg, SpotPlacement spot) : cfg_(std::move(cfg)), spot_(spot) {}

double LsDemodulationMc::metres_per_unit() const { return golden::demod_range_per_px_m(cfg_); }

std::unique_ptr<McPointRunner> LsDemodulationMc::point(double signal_A, double background_A, std::uint64_t key) const {
  return std::make_unique<Runner>(cfg_, signal_A, background_A, key, spot_);
}

std::unique_ptr<McModel> make_ls_demodulation_mc(const ParamSet& params) {
  return std::make_unique<LsDemodulationMc>(ls_demodulation_from_params(params));
}

}  // namespace rangesim::mc
