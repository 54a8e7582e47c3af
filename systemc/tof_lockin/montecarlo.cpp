// Monte Carlo trials of tof-lockin on the sensor kernel (one pixel, one kernel run per trial).
#include <cmath>
#include <optional>

#include "systemc/tof_lockin/montecarlo.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "systemc/tof_lockin/nonideal_stimulus.h"
#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::mc {

namespace {

class Runner : public McPointRunner {
 public:
  Runner(const TofLockinConfig& cfg, bool aggregate, double signal_A, double background_A, std::uint64_t key)
      : cfg_(cfg),
        aggregate_(aggregate),
        key_(key),
        stim_{signal_A, background_A, golden::round_trip_delay_s(cfg.eval.distance_m)} {
    cfg_.pixel.rows = 1;
  }

  McTrial trial(long long t) override {
    using namespace systemc::lockin;
    // One kernel for all the point's trials, restarted with the trial's streams: (trial key,
    // frame, row 0, column 0), the same bits as a kernel built per trial.
    const std::uint64_t seed = trial_key(key_, static_cast<std::uint64_t>(t));
    // Every trial is a pixel of another chip (its fixed pattern keyed by the trial), so the
    // trials' spread holds the spread over pixels that golden's fpn_m is; one pixel of a uniform
    // plane: the point spread changes nothing there, the second return does.
    const bool fixed_pattern = cfg_.nonideal.fixed_pattern.any();
    if (fixed_pattern || !kernel_) {
      std::vector<LockinPixelStimulus> st{stim_};
      add_multipath(cfg_, st);
      apply_fixed_pattern(cfg_, seed, st, 1, 1);
      if (fixed_pattern) kernel_.reset();
      stim_now_ = st;
    }
    if (!kernel_) {
      const long long maps = std::max<long long>(1, cfg_.eval.frames_averaged);
      const long long per_map = cfg_.readout.ambient_subtraction ? 2 : 1;
      kernel_.emplace(cfg_, LockinSimOptions{true, true, aggregate_, seed}, 1, 1, stim_now_, maps * per_map);
    } else {
      kernel_->restart(seed);
    }
    TofLockinSensorKernel& k = *kernel_;
    k.run();  // bounded: the frames' schedule has a fixed number of events
    double sum = 0;
    McTrial out;
    for (long long m = 0; m < k.range_maps(); ++m) {
      const double L = k.range_m(m, 0, 0);
      if (!std::isfinite(L)) return out;  // a map without a range: the averaged value is missing
      sum += L;
    }
    out.detected = true;
    out.error = sum / static_cast<double>(k.range_maps()) - cfg_.eval.distance_m;
    return out;
  }

 private:
  TofLockinConfig cfg_;
  bool aggregate_;
  std::uint64_t key_;
  systemc::lockin::LockinPixelStimulus stim_;
  std::vector<systemc::lockin::LockinPixelStimulus> stim_now_;    // stim_ with the trial's chip
  std::optional<systemc::lockin::TofLockinSensorKernel> kernel_;  // built at the first trial
};

}  // namespace

TofLockinMc::TofLockinMc(TofLockinConfig cfg, bool aggregate) : cfg_(std::move(cfg)), aggregate_(aggregate) {}

std::unique_ptr<McPointRunner> TofLockinMc::point(double signal_A, double background_A, std::uint64_t key) const {
  return std::make_unique<Runner>(cfg_, aggregate_, signal_A, background_A, key);
}

std::unique_ptr<McModel> make_tof_lockin_mc(const ParamSet& params) {
  return std::make_unique<TofLockinMc>(tof_lockin_from_params(params));
}

}  // namespace rangesim::mc
