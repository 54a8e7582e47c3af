// Proof of the ls-conventional exact activation sampling (systemc/ls_conventional/activation_sampler.h,
// preset key simulation.exact_activation_sampling) against the per-sampling draws it replaces, with
// the Gamma draw (simulation.inversion_draw = false; test_inversion_draw.cpp proves the inversion):
//  - the certain outcomes: at the classification bounds the true tail, summed independently in long
//    double over every electron count, is < 2^-56 per pixel and end; over the plane map's classified
//    pixels the total is < 1e-10;
//  - deterministic cases bit-identical (noise-free; no shot noise: the same two normals decide);
//  - statistically indistinguishable: the first firing sampling of representative pixels and the
//    reconstructed centres of the plane scene, means and variances within 5 standard errors and a
//    two-sample KS p >= 0.001 (app/bench/bench_stats.h; the two paths on different seeds). Stated
//    alpha: each statistic fails the battery by chance with probability ~1e-3 (the KS level, which
//    is conservative on discrete samples; the 5 SE limits add 1e-6), so a few percent over the
//    pixels of a test at most (the seeds are fixed: a pass is reproducible);
//  - power: the same battery rejects 3% more signal (the representative pixels' mean first firing
//    sampling moves by 32 standard errors at the most sensitive pixel, 4000 frames, measured, against a limit of 5).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "app/bench/bench_stats.h"
#include "core/ls_conventional/config.h"
#include "core/preset.h"
#include "golden/common/activation_cdf.h"
#include "golden/common/pixel.h"
#include "golden/common/quantiser.h"
#include "scene/scene.h"
#include "systemc/common/gamma_sampler.h"
#include "systemc/ls_conventional/activation_sampler.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "systemc/ls_conventional/sensor.h"
#include "tests/skipping/exact_activation_helpers.h"
#include "tests/systemc/sensor_test_helpers.h"

using namespace exact_test;

TEST(ExactActivation, CertainOutcomesBoundedByIndependentSum) {
  const LsConventionalConfig c = preset();
  struct Case {
    bool shot, ktc, read;
  };
  for (const Case& k :
       {Case{true, true, true}, Case{true, false, false}, Case{true, true, false}, Case{false, true, true}}) {
    rs::ExactActivation ex(model_of(c, k.shot, k.ktc, k.read));
    const double e = rangesim::golden::electrons_per_volt(c.pixel);
    const double s =
        std::hypot(k.ktc ? rangesim::golden::ktc_noise_V(c.pixel) : 0.0, k.read ? c.pixel.read_noise_V : 0.0) * e;
    for (double theta : {0.0011, 0.011, 0.0201, 0.0611, 0.251}) {
      const rs::ActivationBounds b = ex.bounds(theta);
      const double t = theta / c.pixel.source_follower_gain * e;
      // A threshold within a few sigma of the static noise is reachable with no electron: no pixel
      // is certain never to fire (never_upto_e = -1), and then rightly so.
      if (theta > 0.002) {
        ASSERT_GE(b.never_upto_e, 0) << theta;
      }
      ASSERT_LT(b.always_from_e, 1e300) << theta;
      long double p = 0, q;
      if (b.never_upto_e < 0) {
        EXPECT_GT(k.shot ? true_tail(0, t, s, true) : 0.5L * std::erfc(t / (s * std::sqrt(2.0L))), rs::kComputedTail);
      } else if (k.shot) {
        p = true_tail(b.never_upto_e, t, s, true);
      } else {
        p = 0.5L * std::erfc((t - b.never_upto_e) / (s * std::sqrt(2.0L)));
      }
      q = k.shot ? true_tail(b.always_from_e, t, s, false)
                 : 0.5L * std::erfc((b.always_from_e - t) / (s * std::sqrt(2.0L)));
      EXPECT_LT(p, rs::kCertainTail) << "shot " << k.shot << " theta " << theta;
      EXPECT_LT(q, rs::kCertainTail) << "shot " << k.shot << " theta " << theta;
      // Not needlessly wide: the uncertain band is within 25 transition widths.
      EXPECT_LT(b.always_from_e - b.never_upto_e, 25 * std::sqrt(t + s * s) + 25) << theta;
    }
  }
}

// The sampler's exact evaluations (the bounds' bisection, the draws between the table's cuts) look
// the band's Phi up in the entry's golden::ActivationTable: still golden::activation_probability
// bit for bit, at the threshold's own t and s, from below the never-bound to past the always-bound.
TEST(ExactActivation, ExactEvaluationsAreGoldensBitForBit) {
  const LsConventionalConfig c = preset();
  const double e = rangesim::golden::electrons_per_volt(c.pixel);
  struct Case {
    bool shot, ktc, read;
  };
  for (const Case& k : {Case{true, true, true}, Case{true, true, false}, Case{true, false, false}}) {
    rs::ExactActivation ex(model_of(c, k.shot, k.ktc, k.read));
    const double s =
        std::hypot(k.ktc ? rangesim::golden::ktc_noise_V(c.pixel) : 0.0, k.read ? c.pixel.read_noise_V : 0.0) * e;
    for (double theta : {0.0011, 0.011, 0.0201, 0.251}) {
      const rs::ThresholdEntry& entry = ex.entry(theta);
      EXPECT_EQ(entry.exact != nullptr, s > 0) << theta;  // no static noise: nothing to tabulate
      const double t = theta / c.pixel.source_follower_gain * e;
      const double hi = std::min(entry.b.always_from_e, 4 * t + 1000);
      for (int i = 0; i <= 400; ++i) {
        const double lambda = hi * 1.2 * i / 400;
        double p = 0, q = 0;
        ex.probability(lambda, entry, p, q);
        const rangesim::golden::ActivationProbability g = rangesim::golden::activation_probability(lambda, t, s);
        ASSERT_EQ(p, g.p) << "theta " << theta << " lambda " << lambda << " s " << s;
        ASSERT_EQ(q, g.q) << "theta " << theta << " lambda " << lambda << " s " << s;
      }
    }
  }
}

TEST(ExactActivation, PlaneMapCertainPixelsWithin1e10) {
  // The full plane map through the pixel array: every classified pixel contributes < 2 x 2^-56.
  const LsConventionalConfig c = preset();
  const rangesim::scene::SceneOptics optics(
      c, rangesim::scene::load_scene(std::string(RANGESIM_SOURCE_DIR) + "/scenes/plane.toml", "ls-conventional"));
  rs::PixelArrayKernel px(c, rs::PixelArrayOptions{},
                          [&optics](std::uint64_t f, rs::FrameStimulus& s) { optics.stimulus(f, s); });
  ASSERT_TRUE(px.exact_sampling());
  for (int f = 0; f < c.timing.beam_positions; ++f) {
    px.reset_frame(static_cast<std::uint64_t>(f));
    for (int k = 1; k <= c.multisampling.samplings; ++k) px.sample(k);
  }
  const long long certain = px.pixels_simulated() - px.pixels_drawn();
  EXPECT_GT(certain, 500000);
  EXPECT_LT(px.pixels_drawn(), px.pixels_simulated() / 3);
  EXPECT_LT(2 * rs::kCertainTail * static_cast<double>(px.pixels_simulated()), 1e-10);
  RecordProperty("pixels_simulated", std::to_string(px.pixels_simulated()));
  RecordProperty("pixels_drawn", std::to_string(px.pixels_drawn()));
}

TEST(ExactActivation, DeterministicCasesBitIdentical) {
  const LsConventionalConfig base = rs::test::small_config(12, 64, 4);
  for (const rs::PixelNoiseConfig noise : {rs::PixelNoiseConfig::none(), rs::PixelNoiseConfig{false, true, true},
                                           rs::PixelNoiseConfig{false, true, false}}) {
    std::vector<rs::FrameResult> runs[2];
    for (int exact = 0; exact < 2; ++exact) {
      LsConventionalConfig c = base;
      c.simulation.exact_activation_sampling = exact == 1;
      rs::SensorKernelOptions o;
      o.pixel.noise = noise;
      o.pixel.seed = 9;
      rs::LsConventionalSensorKernel k(c, o, rs::test::RandomStimulus{5, 0.005, 1.5, 1e-4, 0.05, 64});
      k.reset();
      runs[exact] = k.run_frames(300);
      if (exact == 1) {
        EXPECT_EQ(k.pixels().exact_sampling(), noise.any());
      }
    }
    ASSERT_EQ(runs[0].size(), runs[1].size());
    for (std::size_t f = 0; f < runs[0].size(); ++f) ASSERT_EQ(runs[0][f], runs[1][f]) << "frame " << f;
  }
}

TEST(ExactActivation, FirstFiringIndistinguishableFromPerSampling) {
  LsConventionalConfig c = stepped_rows();
  c.simulation.inversion_draw = false;  // the Gamma draw (test_inversion_draw.cpp proves the inversion)
  for (const rs::PixelNoiseConfig noise : {rs::PixelNoiseConfig{}, rs::PixelNoiseConfig{true, false, false}}) {
    const auto old_k = first_firings(c, false, 11, 4000, representative(), noise);
    const auto new_k = first_firings(c, true, 12, 4000, representative(), noise);
    int compared = 0;
    double worst = 0;
    EXPECT_TRUE(all_indistinguishable(old_k, new_k, compared, worst)) << "worst |mean z| " << worst;
    EXPECT_GE(compared, 12);  // the representative pixels do have random outcomes
    RecordProperty("pixels_compared", std::to_string(compared));
  }
}

TEST(ExactActivation, TestRejectsThreePercentMoreSignal) {
  LsConventionalConfig c = stepped_rows();
  c.simulation.inversion_draw = false;  // the Gamma draw (test_inversion_draw.cpp proves the inversion)
  rs::RowIllumination more = representative();
  more.signal_V *= 1.03;
  const auto old_k = first_firings(c, false, 11, 4000, representative());
  const auto new_k = first_firings(c, true, 12, 4000, more);
  int compared = 0;
  double worst = 0;
  EXPECT_FALSE(all_indistinguishable(old_k, new_k, compared, worst));
  EXPECT_GT(worst, 5);
  RecordProperty("worst_mean_z", std::to_string(worst));
}

TEST(ExactActivation, PlaneCentresIndistinguishableFromPerSampling) {
  // Reconstructed centres (their error against the exact ground truth) and the number of
  // samplings that found the spot, over 100 frame accesses x 365 rows of the plane scene.
  const LsConventionalConfig base = preset();
  const rangesim::scene::SceneOptics optics(
      base, rangesim::scene::load_scene(std::string(RANGESIM_SOURCE_DIR) + "/scenes/plane.toml", "ls-conventional"));
  std::vector<double> err[2], count[2];
  for (int exact = 0; exact < 2; ++exact) {
    LsConventionalConfig c = base;
    c.simulation.exact_activation_sampling = exact == 1;
    c.simulation.inversion_draw = false;  // the Gamma draw
    rs::SensorKernelOptions o;
    o.pixel.seed = 21 + exact;
    rs::SensorRunOptions run;
    run.frames = 100;
    const auto res = rs::run_sensor_kernel(
        c, o, [&optics](std::uint64_t f, rs::FrameStimulus& s) { optics.stimulus(f, s); }, run);
    for (const auto& fr : res.frames)
      for (int r = 0; r < optics.rows(); ++r) {
        const auto t = optics.truth(optics.beam_position(fr.frame), r);
        const auto& p = fr.rows[static_cast<std::size_t>(r)];
        if (!t.visible || !p.valid) continue;
        err[exact].push_back(p.exact_centre_px() - t.centre_px);
        count[exact].push_back(p.count);
      }
  }
  ASSERT_GT(err[0].size(), 20000u);
  const auto ce = compare_samples(err[0], err[1]);
  EXPECT_TRUE(ce.indistinguishable()) << "mean z " << ce.mean_z << " var z " << ce.var_z << " KS p " << ce.ks_p;
  if (!(constant(count[0]) && constant(count[1]))) {
    const auto cc = compare_samples(count[0], count[1]);
    EXPECT_LT(std::fabs(cc.mean_z), 5);
  }
}

TEST(GammaSampler, EqualsSumOfExponentials) {
  // Gamma(n, 1) is the n-th arrival of a unit-rate Poisson process: the sum of n exponentials.
  for (int n : {1, 3, 40}) {
    pcg32 rng(7, 11);
    std::mt19937_64 g(n);
    std::exponential_distribution<double> e(1.0);
    std::vector<double> a, b;
    for (int i = 0; i < 20000; ++i) {
      a.push_back(rs::gamma_variate(rng, n));
      double s = 0;
      for (int j = 0; j < n; ++j) s += e(g);
      b.push_back(s);
    }
    const auto c = compare_samples(a, b);
    EXPECT_TRUE(c.indistinguishable()) << n << ": mean z " << c.mean_z << " var z " << c.var_z << " KS p " << c.ks_p;
  }
}
