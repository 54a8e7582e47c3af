// Proof of the inversion draw (systemc/ls_conventional/activation_sampler.h, activation_table.h,
// preset key simulation.inversion_draw): an uncertain pixel's first firing sampling K drawn with one
// uniform u as the first k with u < f(lambda_k).
//  - the table's stated bound: at every node f within 1e-12 of golden::activation_probability, and
//    at 16 points in every interval within bound() of it, at five thresholds and three static-noise
//    configurations; bound() itself <= 1e-5 + 1e-11;
//  - the decision is golden's: u < f~ -+ bound decides, the rest is evaluated exactly, so for any u
//    (random, and within a few bounds of f) the answer equals u < golden f;
//  - statistically indistinguishable from the per-sampling draws and from the Gamma draw: the first
//    firing sampling of the representative pixels (4000 frames per path, different seeds) and the
//    plane scene's centre errors (100 frame accesses), means and variances within 5 standard errors
//    and a two-sample KS p >= 0.001 (app/bench/bench_stats.h; the alpha of test_exact_activation.cpp);
//  - power: the same battery rejects 3% more signal (worst |mean z| > 5; measured ~30);
//  - where it does not apply (no shot noise, no static noise, saturation that can matter) the Gamma
//    or per-sampling draws run: the switch changes no bit there.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "golden/common/activation_cdf.h"
#include "scene/scene.h"
#include "systemc/ls_conventional/activation_table.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "systemc/ls_conventional/sensor.h"
#include "tests/skipping/exact_activation_helpers.h"

using namespace exact_test;

namespace {

double golden_f(double lambda, double t, double s) { return rangesim::golden::activation_probability(lambda, t, s).p; }

struct NoiseCase {
  bool ktc, read;
};

LsConventionalConfig with_draw(LsConventionalConfig c, bool inversion) {
  c.simulation.inversion_draw = inversion;
  return c;
}

// The plane scene's centre errors over 100 frame accesses.
std::vector<double> plane_centre_errors(bool exact, bool inversion, std::uint64_t seed) {
  LsConventionalConfig c = with_draw(preset(), inversion);
  c.simulation.exact_activation_sampling = exact;
  const rangesim::scene::SceneOptics optics(
      c, rangesim::scene::load_scene(std::string(RANGESIM_SOURCE_DIR) + "/scenes/plane.toml", "ls-conventional"));
  rs::SensorKernelOptions o;
  o.pixel.seed = seed;
  rs::SensorRunOptions run;
  run.frames = 100;
  const auto res = rs::run_sensor_kernel(
      c, o, [&optics](std::uint64_t f, rs::FrameStimulus& s) { optics.stimulus(f, s); }, run);
  std::vector<double> err;
  for (const auto& fr : res.frames)
    for (int r = 0; r < optics.rows(); ++r) {
      const auto t = optics.truth(optics.beam_position(fr.frame), r);
      const auto& p = fr.rows[static_cast<std::size_t>(r)];
      if (t.visible && p.valid) err.push_back(p.exact_centre_px() - t.centre_px);
    }
  return err;
}

}  // namespace

TEST(InversionDraw, TableWithinStatedBound) {
  const LsConventionalConfig c = preset();
  const double e = rangesim::golden::electrons_per_volt(c.pixel);
  int tables = 0;
  double worst_ratio = 0;
  for (const NoiseCase& k : {NoiseCase{true, true}, NoiseCase{true, false}, NoiseCase{false, true}}) {
    rs::ExactActivation ex(model_of(c, true, k.ktc, k.read));
    const double s =
        std::hypot(k.ktc ? rangesim::golden::ktc_noise_V(c.pixel) : 0.0, k.read ? c.pixel.read_noise_V : 0.0) * e;
    for (double theta : {0.0011, 0.011, 0.0201, 0.0611, 0.251}) {
      const rs::ActivationBounds& b = ex.bounds(theta);
      ASSERT_TRUE(b.invertible) << theta;
      const double t = theta / c.pixel.source_follower_gain * e;
      const rs::ActivationTable table(t, s, std::max(b.never_upto_e, 0.0), b.always_from_e);
      ++tables;
      EXPECT_LE(table.bound(), rs::ActivationTable::kInterpolationTarget + rs::ActivationTable::kNodeAllowance);
      for (int j = 0; j < table.nodes(); ++j) {
        const double l = table.lo_e() + j * table.step_e();
        ASSERT_NEAR(table.node_value(j), golden_f(l, t, s), 1e-12) << "theta " << theta << " node " << j;
      }
      for (int j = 0; j + 1 < table.nodes(); ++j)
        for (int m = 1; m < 16; ++m) {
          const double l = table.lo_e() + (j + m / 16.0) * table.step_e();
          const double err = std::fabs(table.value(l) - golden_f(l, t, s));
          ASSERT_LE(err, table.bound()) << "theta " << theta << " lambda " << l;
          worst_ratio = std::max(worst_ratio, err / table.bound());
        }
    }
  }
  EXPECT_EQ(tables, 15);
  RecordProperty("worst_error_over_bound", std::to_string(worst_ratio));
}

TEST(InversionDraw, DecisionsAreGoldensComparison) {
  const LsConventionalConfig c = preset();
  rs::ExactActivation ex(model_of(c));
  const double e = rangesim::golden::electrons_per_volt(c.pixel);
  const double s = std::hypot(rangesim::golden::ktc_noise_V(c.pixel), c.pixel.read_noise_V) * e;
  const double theta = 0.0201, t = theta / c.pixel.source_follower_gain * e;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u01(0, 1);
  long long decisions = 0;
  for (int i = 0; i < 4000; ++i) {
    rs::ThresholdEntry& entry = ex.entry(theta);
    const double l = entry.b.never_upto_e + u01(rng) * (entry.b.always_from_e - entry.b.never_upto_e);
    const double p = golden_f(l, t, s);
    const double d = entry.table ? entry.table->bound() : 1e-5;
    for (double u : {u01(rng), p, p - d, p + d, p - 3 * d, p + 3 * d, std::nextafter(p, 0.0), std::nextafter(p, 1.0)}) {
      if (!(u > 0 && u < 1)) continue;
      ASSERT_EQ(ex.below(u, l, ex.entry(theta)), u < p) << "lambda " << l << " u " << u << " f " << p;
      ++decisions;
    }
  }
  EXPECT_TRUE(ex.entry(theta).table != nullptr);  // made after the first exact evaluations
  RecordProperty("decisions", std::to_string(decisions));
}

TEST(InversionDraw, FirstFiringIndistinguishableFromPerSamplingAndGamma) {
  const LsConventionalConfig c = stepped_rows();
  const auto per_sampling = first_firings(with_draw(c, true), false, 11, 4000, representative());
  const auto gamma = first_firings(with_draw(c, false), true, 13, 4000, representative());
  const auto inversion = first_firings(with_draw(c, true), true, 12, 4000, representative());
  int compared = 0;
  double worst = 0;
  EXPECT_TRUE(all_indistinguishable(per_sampling, inversion, compared, worst)) << "worst |mean z| " << worst;
  EXPECT_GE(compared, 12);
  RecordProperty("pixels_compared", std::to_string(compared));
  EXPECT_TRUE(all_indistinguishable(gamma, inversion, compared, worst)) << "worst |mean z| " << worst;
  EXPECT_GE(compared, 12);
}

TEST(InversionDraw, TestRejectsThreePercentMoreSignal) {
  const LsConventionalConfig c = stepped_rows();
  rs::RowIllumination more = representative();
  more.signal_V *= 1.03;
  const auto per_sampling = first_firings(with_draw(c, true), false, 11, 4000, representative());
  const auto inversion = first_firings(with_draw(c, true), true, 12, 4000, more);
  int compared = 0;
  double worst = 0;
  EXPECT_FALSE(all_indistinguishable(per_sampling, inversion, compared, worst));
  EXPECT_GT(worst, 5);
  RecordProperty("worst_mean_z", std::to_string(worst));
}

TEST(InversionDraw, PlaneCentresIndistinguishableFromPerSampling) {
  const auto per_sampling = plane_centre_errors(false, true, 21);
  const auto inversion = plane_centre_errors(true, true, 22);
  ASSERT_GT(per_sampling.size(), 20000u);
  const auto ce = compare_samples(per_sampling, inversion);
  EXPECT_TRUE(ce.indistinguishable()) << "mean z " << ce.mean_z << " var z " << ce.var_z << " KS p " << ce.ks_p;
}

TEST(InversionDraw, WhereItDoesNotApplyNoBitChanges) {
  // No shot noise (the normal pair decides), no static noise (no table: the Gamma draw) and a
  // saturation level near the threshold (f without saturation is not exact: the Gamma draw).
  struct Case {
    rs::PixelNoiseConfig noise;
    double saturation_V;
  };
  for (const Case& k :
       {Case{{false, true, true}, 1.741}, Case{{true, false, false}, 1.741}, Case{{true, true, true}, 0.0105}}) {
    std::vector<rs::FrameResult> runs[2];
    for (int inv = 0; inv < 2; ++inv) {
      LsConventionalConfig c = with_draw(rs::test::small_config(12, 64, 4), inv == 1);
      c.pixel.saturation_voltage_V = k.saturation_V;
      rs::SensorKernelOptions o;
      o.pixel.noise = k.noise;
      o.pixel.seed = 4;
      // Backgrounds 0.1 to 1 mV: thresholds 10.1 to 11 mV, within 1.7 read-noise sigma of V_sat = 10.5 mV.
      rs::LsConventionalSensorKernel kern(c, o, rs::test::RandomStimulus{5, 0.005, 1.5, 1e-4, 1e-3, 64});
      kern.reset();
      runs[inv] = kern.run_frames(30);
      EXPECT_EQ(kern.pixels().inversion_draw(), inv == 1);
    }
    for (std::size_t f = 0; f < runs[0].size(); ++f)
      ASSERT_EQ(runs[0][f], runs[1][f]) << "frame " << f << " shot " << k.noise.shot << " ktc " << k.noise.reset_ktc
                                        << " saturation " << k.saturation_V;
  }
  // Where it applies it does run: the same seed gives other bits.
  std::vector<rs::FrameResult> runs[2];
  for (int inv = 0; inv < 2; ++inv) {
    LsConventionalConfig c = with_draw(rs::test::small_config(12, 64, 4), inv == 1);
    rs::SensorKernelOptions o;
    o.pixel.seed = 4;
    rs::LsConventionalSensorKernel kern(c, o, rs::test::UniformStimulus{{0.03, 0.01, 30.3}});
    kern.reset();
    runs[inv] = kern.run_frames(30);
  }
  bool differ = false;
  for (std::size_t f = 0; f < runs[0].size(); ++f) differ = differ || !(runs[0][f] == runs[1][f]);
  EXPECT_TRUE(differ);
}
