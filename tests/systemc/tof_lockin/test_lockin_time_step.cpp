// The time-step fidelity knob (LockinSimOptions::time_step_s, `simulate --time-step`): the
// pulse/gate overlap integrated numerically instead of in closed form. The noise-free ADC inputs
// approach golden's exact ones monotonically as the step shrinks and meet them for a small step;
// aggregated and per-period runs integrate the same way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "lockin_sc_test_util.h"

namespace rangesim::systemc::lockin {
namespace {

// Non-ideal pixel with 8 ns rise (10 ns ramps) on the 100 ns pulse; no ambient frame.
TofLockinConfig ramp_config() {
  return test::edited_config({{"pixel", "rows", "1"},
                              {"pixel", "drain_efficiency", "0.9"},
                              {"source", "rise_time_s", "8e-9"},
                              {"readout", "ambient_subtraction", "false"}});
}

const double kDistances[] = {0.3, 3.7, 7.5, 11.0, 14.2};

// Largest relative error of the noise-free ADC inputs against golden, over distances and taps.
double max_relative_error(const TofLockinConfig& cfg, double step_s, bool aggregate) {
  std::vector<LockinPixelStimulus> st;
  for (double L : kDistances) st.push_back({6e-10, 2e-11, golden::round_trip_delay_s(L)});
  LockinSimOptions o{false, true, aggregate, 1};
  o.time_step_s = step_s;
  TofLockinSensorKernel k(cfg, o, 1, static_cast<int>(st.size()), st, 1);
  k.run();
  double worst = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const golden::FrameCharge c = golden::frame_charge(cfg, st[i].signal_A, st[i].background_A, st[i].delay_s);
    for (int t = 0; t < 2; ++t) {
      const double exact = golden::tap_sample(cfg, t, c.total_e(t)).mean_V;
      const double v = k.adc_input_V(0, 0, static_cast<int>(i), t);
      worst = std::max(worst, std::fabs(v - exact) / exact);
    }
  }
  return worst;
}

TEST(LockinTimeStep, ErrorFallsMonotonicallyToTheExactInputs) {
  const TofLockinConfig cfg = ramp_config();
  EXPECT_LT(max_relative_error(cfg, 0.0, true), 1e-12);  // 0 = closed form
  double prev = INFINITY;
  for (double step : {50e-9, 10e-9, 2e-9, 0.4e-9, 0.08e-9}) {
    const double e = max_relative_error(cfg, step, true);
    EXPECT_LT(e, prev) << "step " << step;
    prev = e;
  }
  EXPECT_GT(max_relative_error(cfg, 50e-9, true), 1e-2);  // a coarse step is visibly wrong
  EXPECT_LT(prev, 1e-5);                                  // converges to the exact inputs
  EXPECT_LT(max_relative_error(cfg, 1e-12, true), 1e-9);  // the smallest allowed step (T0 / 1e5)
}

TEST(LockinTimeStep, PerPeriodAndAggregatedIntegrateAlike) {
  TofLockinConfig cfg = ramp_config();
  cfg.source.duty_cycle = 0.5;  // the ramp's tail reaches the next period
  cfg.gates.accumulations_per_frame = 7;
  // Same numerical light in both paths: their inputs agree to rounding at every step.
  for (double step : {10e-9, 0.5e-9}) {
    std::vector<LockinPixelStimulus> st = {{6e-10, 2e-11, golden::round_trip_delay_s(14.2)}};
    LockinSimOptions a{false, true, true, 1}, p{false, true, false, 1};
    a.time_step_s = p.time_step_s = step;
    TofLockinSensorKernel ka(cfg, a, 1, 1, st, 1), kp(cfg, p, 1, 1, st, 1);
    ka.run(), kp.run();
    for (int t = 0; t < 2; ++t)
      EXPECT_NEAR(ka.adc_input_V(0, 0, 0, t), kp.adc_input_V(0, 0, 0, t), 1e-12 * kp.adc_input_V(0, 0, 0, t))
          << "step " << step << " tap " << t;
  }
}

}  // namespace
}  // namespace rangesim::systemc::lockin
