// Monte Carlo trials of tof-spad on the event-driven kernel (one TDC group, column 0).
#include <cmath>

#include "systemc/tof_spad/montecarlo.h"
#include "core/physics.h"
#include "systemc/tof_spad/sensor_kernel.h"
#include "systemc/tof_spad/nonideal_rates.h"

namespace rangesim::mc {

namespace {

class Runner : public McPointRunner {
 public:
  Runner(const TofSpadConfig& cfg, const systemc::spad::TofSpadKernelOptions& opt, double signal_Hz,
         double background_Hz)
      : cfg_(cfg),
        key_(opt.seed),
        kernel_(cfg, 1, cfg.tdc.columns_per_tdc, opt),
        distance_m_(cfg.evaluation.distance_m),
        rates_(systemc::spad::PixelRates{signal_Hz, background_Hz,
                                         2 * cfg.evaluation.distance_m / phys::kSpeedOfLight_m_per_s}) {}

  McTrial trial(long long t) override {
    // Frame = trial: the group's streams are keyed (point key, trial, row 0, column).
    // Every trial is a group of another chip (its fixed pattern keyed by the trial).
    const std::uint64_t chip = trial_key(key_, static_cast<std::uint64_t>(t));
    // A uniform scene: the point spread changes nothing; multipath adds its second return.
    const systemc::spad::RateSource rates = systemc::spad::chip_rates(
        cfg_, chip, [this](int, int) { return rates_; }, 1, cfg_.tdc.columns_per_tdc);
    const systemc::spad::GroupHistogram g = kernel_.simulate_group(static_cast<std::uint64_t>(t), 0, 0, rates);
    const std::optional<double> tof = kernel_.estimate(g.events[0], g.armed);
    McTrial out;
    out.detected = tof.has_value();
    if (out.detected) out.error = 0.5 * phys::kSpeedOfLight_m_per_s * *tof - distance_m_;
    return out;
  }

 private:
  TofSpadConfig cfg_;
  std::uint64_t key_;
  systemc::spad::TofSpadKernel kernel_;
  double distance_m_;
  systemc::spad::PixelRates rates_;
};

}  // namespace

TofSpadMc::TofSpadMc(TofSpadConfig cfg, bool afterpulses) : cfg_(std::move(cfg)), afterpulses_(afterpulses) {
  // N_p histograms accumulated = one histogram over N_p integration times (the golden model's
  // cycle count: integration x repetition rate x frames averaged).
  cfg_.histogram.integration_time_s *= std::max(1, cfg_.evaluation.frames_averaged);
}

std::unique_ptr<McPointRunner> TofSpadMc::point(double signal_Hz, double background_Hz, std::uint64_t key) const {
  systemc::spad::TofSpadKernelOptions opt;
  opt.seed = key;
  opt.noise.afterpulse = afterpulses_;
  return std::make_unique<Runner>(cfg_, opt, signal_Hz, background_Hz);
}

double TofSpadMc::relative_cost(double signal_Hz, double background_Hz) const {
  // The kernel draws every photon arrival of the histogram's integration: measured on the preset,
  // a trial takes about 0.2 us per arrival plus 15 ms (1e5 arrivals' worth) of fixed work, from
  // 15 ms at 1e5 counts/s to 10 s at 1e9 counts/s.
  return 1e5 + (signal_Hz + background_Hz) * cfg_.histogram.integration_time_s;
}

std::unique_ptr<McModel> make_tof_spad_mc(const ParamSet& params) {
  return std::make_unique<TofSpadMc>(tof_spad_from_params(params));
}

}  // namespace rangesim::mc
