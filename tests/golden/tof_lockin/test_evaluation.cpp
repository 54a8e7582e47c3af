// Grid evaluation of the tof-lockin preset (evaluate_tof_lockin): speed, verdict layout, exact
// range edges, SBR' both ways, sweeps.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "golden/common/evaluate_sensor.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "lockin_test_util.h"
#include "golden/tof_lockin/model.h"

namespace rangesim::golden {

namespace {

const EvalResult& result() {
  static const EvalResult r = evaluate_tof_lockin(test::lockin_params(), nullptr);
  return r;
}

}  // namespace

TEST(LockinEvaluation, PresetGridIsFast) {
  const auto t0 = std::chrono::steady_clock::now();
  const EvalResult r = evaluate_sensor(test::lockin_params());
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(s, 1.0);  // measured ~0.01 s for 45 x 121 points, bisections and sweeps
  EXPECT_EQ(r.sensor, "tof-lockin");
  EXPECT_EQ(r.points.size(), 45u * 121u);
}

TEST(LockinEvaluation, AxesReasonsAndMetrics) {
  const EvalResult& r = result();
  EXPECT_EQ(r.signal.unit, "A");
  EXPECT_EQ(r.background.unit, "A");
  EXPECT_DOUBLE_EQ(r.signal.values.front(), 1e-11);
  EXPECT_DOUBLE_EQ(r.signal.values.back(), 1.5e-9);
  ASSERT_EQ(r.reasons.size(), 6u);
  EXPECT_EQ(r.reasons.front().first, "detectable");
  for (const auto& p : r.points) {
    bool known = false;
    for (const auto& [id, d] : r.reasons) known |= id == p.detect;
    EXPECT_TRUE(known) << p.detect;
    EXPECT_EQ(p.metrics.size(), r.metric_names.size());
    EXPECT_EQ(p.detect == "detectable", std::isfinite(p.accuracy_m));
  }
  EXPECT_EQ(r.metric_names[0], "std_m");
  EXPECT_EQ(r.metric_names[1], "bias_m");
  EXPECT_DOUBLE_EQ(r.distance_m, 1.0);
}

TEST(LockinEvaluation, DetectableSetIsAnIntervalAlongEachAxis) {
  const EvalResult& r = result();
  const size_t ns = r.signal.values.size(), nb = r.background.values.size();
  for (size_t ib = 0; ib < nb; ++ib) {
    int changes = 0;
    for (size_t is = 1; is < ns; ++is)
      changes += (r.at(ib, is).detect == "detectable") != (r.at(ib, is - 1).detect == "detectable");
    EXPECT_LE(changes, 2) << ib;
  }
  for (size_t is = 0; is < ns; ++is) {
    int changes = 0;
    for (size_t ib = 1; ib < nb; ++ib)
      changes += (r.at(ib, is).detect == "detectable") != (r.at(ib - 1, is).detect == "detectable");
    EXPECT_LE(changes, 2) << is;
  }
}

TEST(LockinEvaluation, RangeEdgesAreExact) {
  const EvalResult& r = result();
  const TofLockinConfig cfg = test::lockin_config();
  // Signal range at 10 fA background: from one range value's noise = 5 % of c T0 / 2
  // (readout.max_range_noise_fraction; not the 5 mV threshold nor SNR 3) to the grid top.
  const EvalRange& s = r.signal_range;
  EXPECT_FALSE(s.lo_limited_by_grid);
  EXPECT_TRUE(s.hi_limited_by_grid);
  const LockinPoint lo = evaluate_point(cfg, s.lo, s.at, 1.0, 1);
  EXPECT_EQ(lo.detect, LockinDetect::Detectable);
  EXPECT_NEAR(lo.std_first_m, cfg.readout.max_range_noise_fraction * max_range_m(cfg.source), 1e-9);
  EXPECT_EQ(evaluate_point(cfg, s.lo * (1 - 1e-9), s.at, 1.0, 1).detect, LockinDetect::RangeErrorUnbounded);
  EXPECT_NEAR(s.lo, 5.105e-11, 0.001e-11);
  EXPECT_NEAR(s.range_dB, 29.36, 0.01);
  // Background range at 1.5 nA: from the grid's 10 fA to saturation of FD1.
  const EvalRange& b = r.background_range;
  EXPECT_TRUE(b.lo_limited_by_grid);
  EXPECT_FALSE(b.hi_limited_by_grid);
  const FrameCharge c = frame_charge(cfg, b.at, b.hi, 2.0 / 299792458.0);
  EXPECT_NEAR(tap_sample(cfg, 0, c.total_e(0)).fd_swing_V, cfg.pixel.saturation_voltage_V, 1e-9);
  EXPECT_NEAR(b.hi, 1.560e-9, 0.001e-9);
  EXPECT_NEAR(b.range_dB, 103.86, 0.01);
}

TEST(LockinEvaluation, SbrBothWaysAndAccuracySummary) {
  const EvalResult& r = result();
  // Ratio style (eq. 3.23 / 4.11) goes negative: signal below background is still detectable.
  EXPECT_NEAR(r.sbr_ratio_max_dB, 20 * std::log10(1.5e-9 / 1e-14), 1e-9);
  EXPECT_NEAR(r.sbr_ratio_min_dB, -19.32, 0.01);
  EXPECT_NEAR(r.sbr_max_dB, 103.52, 0.01);
  EXPECT_NEAR(r.sbr_min_dB, 0.892, 0.001);
  EXPECT_NEAR(r.accuracy_min_m, 0.0306, 0.0001);  // 0.75 V at 1 m, lowest background
  // At the range-noise bound (0.75 m of noise) with the bias of the low-SNR ratio.
  EXPECT_NEAR(r.accuracy_max_m, 0.757, 0.001);
  EXPECT_EQ(r.points_detectable, 3008);
}

TEST(LockinEvaluation, SweepsOfThesisFigures) {
  const EvalResult& r = result();
  ASSERT_EQ(r.sweeps.size(), 5u);
  EXPECT_EQ(r.sweeps[0].id, "accuracy_vs_delay");
  EXPECT_EQ(r.sweeps[1].id, "accuracy_vs_frames");
  EXPECT_EQ(r.sweeps[2].id, "accuracy_vs_pulse_width");
  EXPECT_EQ(r.sweeps[3].id, "accuracy_vs_signal");
  EXPECT_EQ(r.sweeps[4].id, "accuracy_vs_distance");
  // Delay: symmetric about T0 / 2 with the ambient frame (the noise floor is the same in both taps).
  const EvalSeries& d = r.sweeps[0].series[0];
  ASSERT_EQ(d.x.size(), 101u);
  EXPECT_NEAR(d.y[1], d.y[99], 1e-3 * d.y[1]);
  EXPECT_GT(d.y[50], d.y[1]);
  // Frames: 1 / sqrt(N).
  const EvalSeries& f = r.sweeps[1].series[0];
  EXPECT_NEAR(f.y[0] / f.y[4], 5.0, 0.01);
  // Pulse width: accuracy grows with T0.
  const EvalSeries& w = r.sweeps[2].series[0];
  for (size_t i = 1; i < w.y.size(); ++i) EXPECT_GT(w.y[i], w.y[i - 1]);
  // Signal: more background, worse accuracy at the top signal.
  const auto& sig = r.sweeps[3].series;
  ASSERT_GE(sig.size(), 3u);
  EXPECT_LT(sig.front().y.back(), sig.back().y.back());
}

}  // namespace rangesim::golden
