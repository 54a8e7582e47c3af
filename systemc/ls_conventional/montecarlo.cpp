// Monte Carlo trials of ls-conventional on the full sensor kernel (one row).
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "systemc/ls_conventional/montecarlo.h"
#include "core/user_error.h"
#include "golden/common/spot.h"
#include "golden/common/triangulation.h"
#include "systemc/ls_conventional/nonideal_pattern.h"
#include "systemc/ls_conventional/sensor_kernel.h"

namespace rangesim::mc {

namespace {

class Runner : public McPointRunner {
 public:
  Runner(const LsConventionalConfig& cfg, double signal_V, double background_V, std::uint64_t key, SpotPlacement spot)
      : cfg_(one_row(cfg)),
        key_(key),
        spot_(spot),
        signal_V_(signal_V),
        background_V_(background_V),
        kernel_(cfg_, options(key), [this](std::uint64_t frame, systemc::FrameStimulus& s) {
          s.rows.assign(1, systemc::RowIllumination{signal_V_, background_V_, x0(frame)});
          if (cfg_.fixed_pattern.any()) {
            // Every trial is a row of another chip (its fixed pattern keyed by the trial), so the
            // trials' spread holds the spread over chips that golden's accuracy does.
            pattern_ = systemc::make_pixel_pattern(cfg_, trial_key(key_, frame));
            s.pattern = &pattern_;
          }
        }) {
    kernel_.reset();
  }

  McTrial trial(long long t) override {
    if (t != next_trial_) throw std::logic_error("LsConventionalMc: trials out of order");
    ++next_trial_;
    // The kernel's own budget (2 frame accesses' worth) bounds the trial.
    const systemc::FrameResult r = kernel_.run_frames(1).front();
    kernel_.clear_results();  // memory stays bounded however many trials a point takes
    McTrial out;
    const auto& row = r.rows.front();
    const double x0_px = x0(static_cast<std::uint64_t>(t));
    out.detected = row.count > 0;
    if (out.detected) out.error = row.exact_centre_px() - x0_px;
    // An activation outside the spot's pixels: the extent of the last sampling holds every pixel
    // that fired (activations are latched).
    const systemc::ActivationExtent& e = r.extents.front();
    const golden::ColumnSpan spot = golden::spot_window(cfg_.spot, x0_px, cfg_.pixel.columns);
    out.outlier = e.first >= 0 && (e.first < spot.first || e.last > spot.last);
    return out;
  }

  // kTC and read noise (one normal pair, counted as two) and one Poisson per sampling, per simulated pixel.
  long long variates() const override {
    return kernel_.pixels().pixels_simulated() * (2 + cfg_.multisampling.samplings);
  }

 private:
  static LsConventionalConfig one_row(LsConventionalConfig c) {
    c.pixel.rows = 1;
    return c;
  }
  static systemc::SensorKernelOptions options(std::uint64_t key) {
    systemc::SensorKernelOptions o;
    o.pixel.seed = key;  // frame = trial: pixel streams keyed (key, trial, row, column)
    o.pixel.sparse = true;
    o.event_skipping = true;
    return o;
  }
  double x0(std::uint64_t trial) const {
    const double u = std::isnan(spot_.fixed_u) ? trial_uniform(key_, trial) : spot_.fixed_u;
    return cfg_.pixel.columns / 2 - 0.5 + u;
  }

  LsConventionalConfig cfg_;
  std::uint64_t key_;
  SpotPlacement spot_;
  double signal_V_, background_V_;
  systemc::PixelPattern pattern_;  // this trial's chip (fixed_pattern.* on)
  systemc::LsConventionalSensorKernel kernel_;
  long long next_trial_ = 0;  // = the kernel's frame counter: trial t is frame access t
};

}  // namespace

LsConventionalMc::LsConventionalMc(LsConventionalConfig cfg, SpotPlacement spot) : cfg_(std::move(cfg)), spot_(spot) {
  // The clock-level pixel array has the in-pixel comparator only (systemc/ls_conventional/pixel_array_kernel.h).
  if (cfg_.comparator.adc_bits != 1)
    throw UserError(
        fmt::format("--adc-bits {} (comparator.adc_bits): --trials runs the clock-level model, which has "
                    "the 1-bit in-pixel comparator only; allowed: 1",
                    cfg_.comparator.adc_bits));
}

double LsConventionalMc::metres_per_unit() const {
  return golden::range_per_px_m(cfg_.optics, cfg_.pixel.pitch_m, cfg_.optics.distance_m);
}

std::unique_ptr<McPointRunner> LsConventionalMc::point(double signal_V, double background_V, std::uint64_t key) const {
  return std::make_unique<Runner>(cfg_, signal_V, background_V, key, spot_);
}

std::unique_ptr<McModel> make_ls_conventional_mc(const ParamSet& params) {
  return std::make_unique<LsConventionalMc>(ls_conventional_from_params(params));
}

}  // namespace rangesim::mc
