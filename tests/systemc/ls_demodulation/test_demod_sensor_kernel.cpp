// ls-demodulation sensor kernel: frame timing == golden schedule, decisions and positions against
// the golden decision, event skipping == ticking, decision probability under noise.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "core/preset.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/frame_timing.h"
#include "golden/ls_demodulation/decision.h"
#include "systemc/ls_demodulation/sensor_kernel.h"
#include "tests/systemc/ls_demodulation/demod_test_helpers.h"
#include "golden/ls_demodulation/model.h"

namespace rangesim::systemc {
namespace {

TEST(DemodSensorKernel, FrameTimingEqualsGoldenCycleForCycle) {
  const ParamSet params = load_preset_file(std::string(RANGESIM_PRESET_DIR) + "/ls-demodulation.toml");
  const auto c = ls_demodulation_from_params(params);
  const golden::FrameTiming g = golden::frame_timing_ls_demodulation(params);
  for (bool skip : {true, false}) {
    DemodKernelOptions o;
    o.event_skipping = skip;
    o.noise = DemodNoiseSwitches::none();
    const auto run = run_demod_kernel(c, o, test::spot_source(c, 1.11e-10, 1e-10, 40.0), 2);
    ASSERT_EQ(run.frames.size(), 2u);
    for (const auto& f : run.frames) {
      EXPECT_EQ(f.cycles, g.frame_cycles);
      ASSERT_EQ(f.phase_cycles.size(), g.phases.size());
      for (std::size_t i = 0; i < g.phases.size(); ++i)
        EXPECT_EQ(f.phase_cycles[i], g.phases[i].cycles) << g.phases[i].name;
    }
    EXPECT_EQ(run.cycles, 2 * g.frame_cycles);
    EXPECT_DOUBLE_EQ(run.simulated_time_s / 2, g.frame_time_s);
  }
  EXPECT_EQ(g.frame_cycles, 5011);
  EXPECT_NEAR(g.frame_access_rate_Hz, 2000.0, 0.01 * 2000.0);  // calibrated preset (thesis: 2000 fps)
  EXPECT_EQ(g.clock_Hz, 10e6);
}

// A modified preset (3 decisions, 7 rows, 30 cycles per row, 8 periods of 50 cycles at 200 kHz):
// golden frame timing and the kernel still agree cycle for cycle.
TEST(DemodSensorKernel, FrameTimingEqualsGoldenOnAModifiedPreset) {
  std::ifstream in(std::string(RANGESIM_PRESET_DIR) + "/ls-demodulation.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto sub = [&](const std::string& from, const std::string& to) {
    const auto pos = text.find(from);
    ASSERT_NE(pos, std::string::npos) << from;
    text.replace(pos, from.size(), to);
  };
  sub("detections = { value = 1,", "detections = { value = 3,");
  sub("rows = { value = 110,", "rows = { value = 7,");
  sub("row_cycles = { value = 41,", "row_cycles = { value = 30,");
  sub("frequency_Hz = { value = 100e3,", "frequency_Hz = { value = 200e3,");
  sub("cycles = { value = 5,", "cycles = { value = 8,");
  sub("integration_time_s = { value = 50e-6,", "integration_time_s = { value = 40e-6,");
  const ParamSet params = load_preset_text(text, "modified ls-demodulation");
  const auto c = ls_demodulation_from_params(params);
  const golden::FrameTiming g = golden::frame_timing_ls_demodulation(params);
  EXPECT_EQ(g.frame_cycles, 3 * (400 + 1 + 7 * 30));
  for (bool skip : {true, false}) {
    DemodKernelOptions o;
    o.event_skipping = skip;
    const auto run = run_demod_kernel(c, o, test::spot_source(c, 1.11e-10, 1e-10, 40.0), 1);
    EXPECT_EQ(run.frames[0].cycles, g.frame_cycles);
    for (std::size_t i = 0; i < g.phases.size(); ++i) EXPECT_EQ(run.frames[0].phase_cycles[i], g.phases[i].cycles);
    EXPECT_DOUBLE_EQ(run.simulated_time_s, g.frame_time_s);
  }
}

TEST(DemodSensorKernel, SeveralDecisionsPerFrameFollowTheSchedule) {
  auto c = test::small_config(2, 16);
  c.grid.detections = 3;
  DemodKernelOptions o;
  DemodSensorKernel k(c, o);
  const auto f = k.run_frame(0, [&] {
    DemodStimulus s;
    test::spot_source(c, 1.11e-10, 1e-10, 7.0)(0, s);
    return s;
  }());
  EXPECT_EQ(f.cycles, 3 * (500 + 1 + 2 * 41));
  EXPECT_EQ(f.phase_cycles[0], 1500);
  EXPECT_EQ(f.phase_cycles[1], 3);
  EXPECT_EQ(f.phase_cycles[2], 3 * 82);
  EXPECT_EQ(f.cycles, k.frame_cycles());
}

// Noise-free: each comparator decision equals golden's (D >= V_cmp on the golden correlator
// output), and the row position is the centre of the activated run.
TEST(DemodSensorKernel, NoiseFreeDecisionsAndCentresMatchGolden) {
  const auto c = test::small_config(4, 24);
  for (double sig : {7.4e-12, 3e-11, 1.11e-10, 1e-9})
    for (double bg : {1e-12, 1e-10, 1e-8}) {
      DemodKernelOptions o;
      o.noise = DemodNoiseSwitches::none();
      o.keep_analogue = true;
      DemodStimulus s;
      test::spot_source(c, sig, bg, 10.2)(0, s);
      DemodSensorKernel k(c, o);
      const auto f = k.run_frame(0, s);
      for (int r = 0; r < c.pixel.rows; ++r) {
        int first = -1, last = -1;
        for (int col = 0; col < c.pixel.columns; ++col) {
          const std::size_t i = static_cast<std::size_t>(r) * c.pixel.columns + col;
          const auto g = golden::correlate_periodic(c, golden::pixel_segments(c, s.beam_A[i], s.background_A[i]),
                                                    c.correlator.cycles);
          // Golden reuses the first period's integrals (periodic steady state); the kernel steps the
          // LPF through every period: equal to rounding (plus and minus nearly cancel in D).
          EXPECT_NEAR(f.diff_V[i], g.diff_V, 1e-10 + 1e-9 * std::fabs(g.plus_V));
          const bool act = g.diff_V >= c.comparator.threshold_V;
          EXPECT_EQ(f.activations[static_cast<std::size_t>(r)].test(col), act)
              << sig << " " << bg << " " << r << " " << col;
          if (act) last = col, first = first < 0 ? col : first;
        }
        const auto& rr = f.rows[static_cast<std::size_t>(r)];
        EXPECT_EQ(rr.valid(), first >= 0);
        if (first >= 0) {
          EXPECT_EQ(rr.left, first);
          EXPECT_EQ(rr.right, last);
          EXPECT_DOUBLE_EQ(rr.centre_px(), 0.5 * (first + last));
        }
      }
    }
}

TEST(DemodSensorKernel, EventSkippingEqualsTicking) {
  auto c = test::small_config(3, 20);
  c.grid.detections = 2;
  DemodKernelOptions a, b;
  a.event_skipping = true;
  a.aggregate = false;  // per period: the same draws as ticking (aggregation: tests/skipping)
  b.event_skipping = false;
  a.keep_analogue = b.keep_analogue = true;
  a.seed = b.seed = 42;
  const auto src = test::spot_source(c, 3e-11, 1e-9, 6.3, 0.41, 1.7);
  const auto ra = run_demod_kernel(c, a, src, 3);
  const auto rb = run_demod_kernel(c, b, src, 3);
  ASSERT_EQ(ra.frames.size(), rb.frames.size());
  EXPECT_EQ(ra.cycles, rb.cycles);
  for (std::size_t f = 0; f < ra.frames.size(); ++f) {
    EXPECT_EQ(ra.frames[f].cycles, rb.frames[f].cycles);
    EXPECT_EQ(ra.frames[f].phase_cycles, rb.frames[f].phase_cycles);
    EXPECT_EQ(ra.frames[f].rows, rb.frames[f].rows);
    EXPECT_EQ(ra.frames[f].activations, rb.frames[f].activations);
    EXPECT_EQ(ra.frames[f].read_offset_V, rb.frames[f].read_offset_V);
    ASSERT_EQ(ra.frames[f].diff_V.size(), rb.frames[f].diff_V.size());
    for (std::size_t i = 0; i < ra.frames[f].diff_V.size(); ++i)
      // Whole-segment vs per-cycle quadrature of the log stage (8-point Gauss-Legendre per piece):
      // equal to ~1e-10 V, five decades below the comparator threshold.
      EXPECT_NEAR(ra.frames[f].diff_V[i], rb.frames[f].diff_V[i], 1e-8);
  }
}

// Decision probability of one pixel under all noise (per-decision shot + kTC, frame-common read
// noise): P = Phi((mu - V_cmp) / sqrt(sigma_ind^2 + sigma_common^2)), the golden expectation over
// the common offset. 3000 independent frames; bound 5 binomial standard errors.
TEST(DemodSensorKernel, DecisionProbabilityMatchesGolden) {
  auto c = test::small_config(1, 1);
  const double bg = 1e-10;
  // Beam at which the golden mean sits just above / below V_cmp (bisection).
  for (double offset_V : {-0.4e-3, 0.0, 0.5e-3}) {
    double lo = 0, hi = 1e-9;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (golden::pixel_decision(c, mid, bg).out.diff_V < c.comparator.threshold_V + offset_V ? lo : hi) = mid;
    }
    const auto d = golden::pixel_decision(c, hi, bg);
    const double sigma = std::hypot(d.sigma_independent_V, d.sigma_common_V);
    const double p = golden::activation(d.out.diff_V, c.comparator.threshold_V, sigma).p;
    DemodKernelOptions o;
    o.seed = 9;
    const int n = 3000;
    const auto run = run_demod_kernel(
        c, o,
        [&](std::uint64_t, DemodStimulus& s) {
          s.beam_A = {hi};
          s.background_A = {bg};
        },
        n);
    int hits = 0;
    for (const auto& f : run.frames) hits += f.rows[0].valid() ? 1 : 0;
    EXPECT_NEAR(static_cast<double>(hits) / n, p, 5 * std::sqrt(p * (1 - p) / n) + 1e-3) << offset_V;
  }
}

TEST(DemodSensorKernel, RejectsRowCyclesTooShortForTheAddresses) {
  auto c = test::small_config();
  c.readout.row_cycles = 15;  // needs 1 + 2 x 7 + settle
  EXPECT_THROW(DemodSensorKernel(c, DemodKernelOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace rangesim::systemc
